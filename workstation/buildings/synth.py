"""Analytic buildings with known roofs for tests and benchmarks (numpy only).

Each :class:`SynthBuilding` is a rectangle, an L or a T in a local frame (u along the length, v
along the width) rotated by ``yaw`` about its centre, with a roof given in closed form, so
footprints, roof planes (tilt, azimuth) and roof heights are known exactly. The roofs of
:data:`COMPLEX_KINDS` are unions of gabled wings (:class:`Wing`): each wing is a gabled prism over
its own rectangle and the roof is their upper envelope, so where two wings cross their slopes meet
in valleys, and a small wing standing on a slope is a dormer with vertical front and cheek walls. :func:`district`
lays out a grid of them on a gently sloping ground and samples airborne-like points (uniform
positions at a given density, Gaussian noise along z), classified ground (2) and building (6).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

KINDS = ("flat", "shed", "gabled", "hipped", "multilevel", "lshape")
COMPLEX_KINDS = ("cross_l", "cross_t", "dormer")


@dataclass(frozen=True)
class Wing:
    """A gabled prism of a composite roof, in the building's local frame (metres).

    Attributes
    ----------
    u0, u1, v0, v1 : float
        Its rectangle.
    along_u : bool
        Ridge parallel to u (else parallel to v).
    ridge : float
        Ridge position across it (v when ``along_u``, else u).
    half_width : float
        Horizontal distance from the ridge to its eaves.
    eave : float
        Eave height above the building's eaves.
    slope : float
        Rise per metre of both its roof planes.
    """

    u0: float
    u1: float
    v0: float
    v1: float
    along_u: bool
    ridge: float
    half_width: float
    eave: float
    slope: float

    def z(self, u: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Height above the building's eaves at (u, v); -inf outside its rectangle."""
        across = v if self.along_u else u
        z = self.eave + self.slope * (self.half_width - np.abs(across - self.ridge))
        inside = (u >= self.u0) & (u <= self.u1) & (v >= self.v0) & (v <= self.v1)
        return np.where(inside, z, -np.inf)

    def gradients(self) -> list:
        """Local gradients (dz/du, dz/dv) of its two planes."""
        return [(0.0, self.slope), (0.0, -self.slope)] if self.along_u else [(self.slope, 0.0), (-self.slope, 0.0)]


@dataclass(frozen=True)
class SynthBuilding:
    """A building with an analytic roof.

    Attributes
    ----------
    kind : str
        One of ``flat``, ``shed``, ``gabled``, ``hipped``, ``multilevel`` (two flat parts, the
        part u > 0.1 length is 3 m higher), ``lshape`` (flat roof, quadrant u > 0, v > 0 cut),
        or one of the wing roofs of :meth:`wings`: ``cross_l`` (the L of ``lshape`` with a gabled
        wing along each leg, crossing in the corner), ``cross_t`` (a T: a gabled bar with a lower
        gabled stem whose ridge ends on the bar's slope) and ``dormer`` (a gabled roof with a
        gabled dormer on its v < 0 slope).
    center : (float, float)
        Centre (m, absolute).
    length, width : float
        Sides along u and v (m), length >= width.
    yaw : float
        Rotation of the u axis from +x, counter-clockwise (radians).
    eave : float
        Eave height above ``ground`` (m).
    rise : float
        Ridge height above the eaves (m) for sloped roofs; for the wing roofs, the pitch is that
        of a ``gabled`` roof of the same width (slope ``rise / (width / 2)``).
    ground : float
        Ground height at the centre (m).
    """

    kind: str
    center: tuple
    length: float
    width: float
    yaw: float
    eave: float
    rise: float
    ground: float

    def to_local(self, xy: np.ndarray) -> np.ndarray:
        c, s = np.cos(self.yaw), np.sin(self.yaw)
        d = np.asarray(xy, float) - np.asarray(self.center, float)
        return np.column_stack([d[:, 0] * c + d[:, 1] * s, -d[:, 0] * s + d[:, 1] * c])

    def to_world(self, uv: np.ndarray) -> np.ndarray:
        c, s = np.cos(self.yaw), np.sin(self.yaw)
        return np.column_stack([uv[:, 0] * c - uv[:, 1] * s, uv[:, 0] * s + uv[:, 1] * c]) + np.asarray(self.center, float)

    def wings(self) -> list:
        """The gabled wings of a ``cross_l``, ``cross_t`` or ``dormer`` roof (empty otherwise).

        ``cross_l``: a wing along u over v < 0 and one along v over u < 0, each with its ridge
        on its centre line; they cross in the corner square. ``cross_t``: a bar along u over the
        v > b - 0.6 w strip (w the width) and a stem along v, 0.9 times as wide, from v = -b to the
        bar's ridge line (never above it). ``dormer``: the whole-rectangle gable and, on its
        v < 0 slope at u = -a / 4, a wing along v as wide as a quarter of the length (2.5-4 m),
        its front 0.2 b from the eave, eaves 0.45 and ridge 0.8 of the main rise up."""
        a, b = self.length / 2, self.width / 2
        s = self.rise / b
        if self.kind == "cross_l":
            return [Wing(-a, a, -b, 0.0, True, -b / 2, b / 2, 0.0, s),
                    Wing(-a, 0.0, -b, b, False, -a / 2, a / 2, 0.0, s)]
        if self.kind == "cross_t":
            wb = 0.6 * self.width
            c = 0.45 * wb
            return [Wing(-a, a, b - wb, b, True, b - wb / 2, wb / 2, 0.0, s),
                    Wing(-c, c, -b, b - wb / 2, False, 0.0, c, 0.0, s)]
        if self.kind == "dormer":
            wd = float(np.clip(self.length / 4, 2.5, 4.0))
            ud = -a / 4
            return [Wing(-a, a, -b, b, True, 0.0, b, 0.0, s),
                    Wing(ud - wd / 2, ud + wd / 2, -0.8 * b, 0.0, False, ud, wd / 2, 0.45 * self.rise,
                         0.35 * self.rise / (wd / 2))]
        return []

    def footprint(self) -> np.ndarray:
        """(k, 2) counter-clockwise outline (m, absolute)."""
        a, b = self.length / 2, self.width / 2
        if self.kind in ("lshape", "cross_l"):
            uv = np.array([[-a, -b], [a, -b], [a, 0], [0, 0], [0, b], [-a, b]])
        elif self.kind == "cross_t":
            yb, c = b - 0.6 * self.width, 0.27 * self.width
            uv = np.array([[-c, -b], [c, -b], [c, yb], [a, yb], [a, b], [-a, b], [-a, yb], [-c, yb]])
        else:
            uv = np.array([[-a, -b], [a, -b], [a, b], [-a, b]])
        return self.to_world(uv)

    def inside(self, xy: np.ndarray) -> np.ndarray:
        uv = self.to_local(xy)
        a, b = self.length / 2, self.width / 2
        m = (np.abs(uv[:, 0]) <= a) & (np.abs(uv[:, 1]) <= b)
        if self.kind in ("lshape", "cross_l"):
            m &= ~((uv[:, 0] > 0) & (uv[:, 1] > 0))
        elif self.kind == "cross_t":
            m &= (uv[:, 1] >= b - 0.6 * self.width) | (np.abs(uv[:, 0]) <= 0.27 * self.width)
        return m

    def roof_z(self, xy: np.ndarray) -> np.ndarray:
        """Roof height (m, absolute) at ``xy`` (m, 2); NaN outside the footprint."""
        uv = self.to_local(xy)
        u, v = uv[:, 0], uv[:, 1]
        a, b = self.length / 2, self.width / 2
        base = self.ground + self.eave
        if self.kind in ("flat", "lshape"):
            z = np.full(len(u), base)
        elif self.kind == "shed":
            z = base + self.rise * (v + b) / (2 * b)
        elif self.kind == "gabled":
            z = base + self.rise * (1 - np.abs(v) / b)
        elif self.kind == "hipped":
            slope = self.rise / b
            z = base + np.minimum(self.rise * (1 - np.abs(v) / b), slope * (a - np.abs(u)))
        elif self.kind == "multilevel":
            z = base + np.where(u > 0.1 * self.length, 3.0, 0.0)
        elif self.kind in COMPLEX_KINDS:
            z = base + np.max([w.z(u, v) for w in self.wings()], axis=0)
        else:
            raise ValueError(f"unknown kind {self.kind}")
        return np.where(self.inside(xy), z, np.nan)

    def roof_gradients(self) -> np.ndarray:
        """(p, 2) world gradients (dz/dx, dz/dy) of the true roof planes."""
        a, b = self.length / 2, self.width / 2
        if self.kind in COMPLEX_KINDS:
            g = list(dict.fromkeys(gr for w in self.wings() for gr in w.gradients()))
        else:
            g = {"flat": [(0, 0)], "lshape": [(0, 0)], "multilevel": [(0, 0)], "shed": [(0, self.rise / (2 * b))],
                 "gabled": [(0, -self.rise / b), (0, self.rise / b)],
                 "hipped": [(0, -self.rise / b), (0, self.rise / b), (-self.rise / b, 0), (self.rise / b, 0)]}[self.kind]
        c, s = np.cos(self.yaw), np.sin(self.yaw)
        gl = np.array(g, float)  # (du, dv) -> world
        return np.column_stack([gl[:, 0] * c - gl[:, 1] * s, gl[:, 0] * s + gl[:, 1] * c])

    def true_tilt_azimuth(self) -> np.ndarray:
        """(p, 2) tilt and azimuth (degrees) of the true roof planes (azimuth of flat = 0)."""
        g = self.roof_gradients()
        tilt = np.degrees(np.arctan(np.hypot(g[:, 0], g[:, 1])))
        az = np.degrees(np.arctan2(-g[:, 0], -g[:, 1])) % 360.0
        return np.column_stack([tilt, np.where(tilt > 0, az, 0.0)])


def ground_z(xy: np.ndarray, origin=(500000.0, 5300000.0), slope=(0.01, 0.005), base: float = 100.0) -> np.ndarray:
    """The district's planar ground (m), ``base`` at ``origin``."""
    return base + slope[0] * (xy[:, 0] - origin[0]) + slope[1] * (xy[:, 1] - origin[1])


def sample_building(b: SynthBuilding, density: float, noise: float, rng: np.random.Generator) -> np.ndarray:
    """(m, 3) roof points of one building: uniform positions at ``density`` (points/m^2), z noise
    sigma ``noise`` (m)."""
    fp = b.footprint()
    lo, hi = fp.min(axis=0), fp.max(axis=0)
    n = rng.poisson(density * np.prod(hi - lo))
    xy = rng.uniform(lo, hi, (n, 2))
    xy = xy[b.inside(xy)]
    return np.column_stack([xy, b.roof_z(xy) + rng.normal(0.0, noise, len(xy))])


def district(n_buildings: int, seed: int = 0, density: float = 10.0, noise: float = 0.03, pitch: float = 30.0,
             kinds=KINDS, origin=(500000.0, 5300000.0)):
    """A grid district of ``n_buildings`` analytic buildings and its sampled points.

    Returns ``(xyz (n, 3), classification (n,) uint8, buildings list)``; positions are absolute
    (m) around ``origin``; ground points at the same density cover the free space.
    """
    rng = np.random.default_rng(seed)
    cols = int(np.ceil(np.sqrt(n_buildings)))
    blds = []
    for i in range(n_buildings):
        r, c = divmod(i, cols)
        center = (origin[0] + (c + 0.5) * pitch, origin[1] + (r + 0.5) * pitch)
        length = rng.uniform(10.0, 18.0)
        width = rng.uniform(7.0, min(length, 12.0))
        g = float(ground_z(np.array([center]), origin)[0])
        blds.append(SynthBuilding(kinds[i % len(kinds)], center, length, width, rng.uniform(0, np.pi),
                                  rng.uniform(4.0, 9.0), rng.uniform(2.5, 5.0), g))
    pts = [sample_building(b, density, noise, rng) for b in blds]
    ext = np.array([cols * pitch, (int(np.ceil(n_buildings / cols))) * pitch])
    ng = rng.poisson(density * np.prod(ext))
    gxy = np.asarray(origin) + rng.uniform(0, 1, (ng, 2)) * ext
    keep = np.ones(ng, bool)
    cell = np.floor((gxy - np.asarray(origin)) / pitch).astype(np.int64)  # each building owns its grid cell
    owner = cell[:, 1] * cols + cell[:, 0]
    order = np.argsort(owner, kind="stable")
    bounds = np.searchsorted(owner[order], np.arange(len(blds) + 1))
    for i, b in enumerate(blds):
        idx = order[bounds[i]:bounds[i + 1]]
        keep[idx[b.inside(gxy[idx])]] = False
    gxy = gxy[keep]
    ground = np.column_stack([gxy, ground_z(gxy, origin) + rng.normal(0, noise, len(gxy))])
    xyz = np.vstack([ground, *pts])
    cls = np.concatenate([np.full(len(ground), 2, np.uint8), np.full(len(xyz) - len(ground), 6, np.uint8)])
    return xyz, cls, blds


def model_roof_z(model, xy: np.ndarray) -> np.ndarray:
    """Height (m) of a building model's LoD2.2 roof at ``xy`` (m, 2); NaN off the roof."""
    import shapely

    z = np.full(len(xy), np.nan)
    for f in model.roofs:
        inside = shapely.contains_xy(shapely.Polygon(f.polygon), xy[:, 0], xy[:, 1])
        z[inside] = f.z(xy[inside])
    return z


def best_model(polys: list, tree, building: SynthBuilding) -> int | None:
    """Index of the model footprint among ``polys`` (shapely polygons, in the STRtree ``tree``)
    overlapping ``building``'s footprint most; None where none intersects it."""
    import shapely

    T = shapely.Polygon(building.footprint())
    cand = tree.query(T, predicate="intersects")
    return int(max(cand, key=lambda k: polys[k].intersection(T).area)) if len(cand) else None


def matched_faces(model, building: SynthBuilding) -> list:
    """Per true sloped roof plane of ``building``: (its index q into
    :meth:`SynthBuilding.roof_gradients`, tilt, azimuth (degrees), the face of ``model`` whose
    normal is nearest to its normal)."""
    normals = np.array([f.normal for f in model.roofs])
    out = []
    for q, (tilt, az) in enumerate(building.true_tilt_azimuth()):
        if tilt <= 0:
            continue
        t, a = np.radians(tilt), np.radians(az)
        n = np.array([np.sin(t) * np.sin(a), np.sin(t) * np.cos(a), np.cos(t)])
        out.append((q, tilt, az, model.roofs[int(np.argmax(normals @ n))]))
    return out


def evaluate(models: list, buildings: list, grid: float = 0.25) -> list[dict]:
    """Compare models with the analytic buildings: per true building, the best-overlapping
    model's (:func:`best_model`) footprint IoU, roof-plane tilt and azimuth errors (degrees; each
    true sloped plane against the model face with the nearest normal, :func:`matched_faces`), the
    roof RMS (m) over a ``grid`` (m) inside both footprints and whether all of that model's
    LoD2.2 solids are watertight."""
    import shapely

    from .models import is_watertight

    polys = [shapely.Polygon(m.footprint) for m in models]
    tree = shapely.STRtree(polys)
    out = []
    for b in buildings:
        j = best_model(polys, tree, b)
        if j is None:
            out.append({"kind": b.kind, "iou": 0.0, "found": False})
            continue
        T = shapely.Polygon(b.footprint())
        m, P = models[j], polys[j]
        row = {"kind": b.kind, "found": True, "iou": P.intersection(T).area / P.union(T).area, "roof_type": m.roof_type,
               "watertight": all(is_watertight(s) for s in m.lod2)}
        faces = matched_faces(m, b)
        row["tilt_err_deg"] = max((abs(f.tilt_deg - t) for _, t, _, f in faces), default=0.0)
        row["azimuth_err_deg"] = max((abs((f.azimuth_deg - a + 180) % 360 - 180) for _, _, a, f in faces), default=0.0)
        inter = P.intersection(T)
        x0, y0, x1, y1 = inter.bounds
        gx, gy = np.meshgrid(np.arange(x0, x1, grid), np.arange(y0, y1, grid))
        xy = np.column_stack([gx.ravel(), gy.ravel()])
        xy = xy[shapely.contains_xy(inter, xy[:, 0], xy[:, 1])]
        dz = model_roof_z(m, xy) - b.roof_z(xy)
        row["roof_rms_m"] = float(np.sqrt(np.nanmean(dz ** 2))) if np.isfinite(dz).any() else float("nan")
        out.append(row)
    return out
