"""Contour lines of a DEM (contourpy marching squares) written as GeoJSON.

Lines are traced by contourpy's serial algorithm (marching squares with saddle
disambiguation; Lorensen & Cline 1987 in 2-D) on the cell centres, so closed loops come back
closed and open lines end on the raster edge or at nodata. Every line carries its elevation,
whether it is an index contour (every 5th level: multiples of 5 × interval) and whether it is
closed. Optional smoothing is Chaikin's corner cutting (Chaikin 1974), which keeps open-line
end points. The default interval follows the map-accuracy rule that the contour interval is
about three times the vertical RMSE of the surface (ASPRS 1990 class 1: RMSEz = CI / 3; the
"3σ" rule of the photogrammetric products lecture).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Raster

log = get_logger(__name__)

NICE_INTERVALS = (0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0)


@dataclass(frozen=True)
class ContourParams:
    """Parameters of :func:`contour_lines`.

    Attributes
    ----------
    interval : float or None
        Vertical distance between contours in metres, whatever the DEM's height unit (1 m
        on a DEM in feet gives levels 3.2808... ft apart). None: 3 × the DEM's
        ``vertical_rmse`` (from ``Raster.meta``) rounded up to a round value, or about 20
        levels over the height range when the accuracy is unknown.
    base : float
        Contours are at ``base + k · interval`` (metres).
    index_every : int
        Every n-th level (multiples of n · interval from ``base``) is an index contour.
    smooth : int
        Chaikin corner-cutting iterations (0 = none).
    min_points : int
        Lines with fewer vertices are dropped (specks).
    """

    interval: float | None = None
    base: float = 0.0
    index_every: int = 5
    smooth: int = 0
    min_points: int = 2


@dataclass
class ContourSet:
    """Contour lines in world coordinates.

    Attributes
    ----------
    lines : list of (n, 2) float64 arrays
    levels : (m,) float64, the elevation of each line in the DEM's height unit
    closed : (m,) bool
    index : (m,) bool, index contours
    interval : float
        Spacing of the levels in the DEM's height unit.
    crs : str or None
    reason : str
        How the interval was chosen.
    interval_m : float
        The same spacing in metres.
    z_unit : str
        The DEM's height unit ("metre", "US survey foot").
    """

    lines: list
    levels: np.ndarray
    closed: np.ndarray
    index: np.ndarray
    interval: float
    crs: str | None = None
    reason: str = ""
    meta: dict = field(default_factory=dict)
    interval_m: float | None = None
    z_unit: str = "metre"

    def __len__(self) -> int:
        return len(self.lines)

    def to_geojson(self, decimals: int = 3) -> dict:
        """A GeoJSON FeatureCollection of LineStrings (coordinates in the raster's CRS)."""
        feats = []
        for pts, lev, closed, idx in zip(self.lines, self.levels, self.closed, self.index):
            feats.append({
                "type": "Feature",
                "properties": {"elevation": float(lev), "index": bool(idx), "closed": bool(closed)},
                "geometry": {"type": "LineString", "coordinates": np.round(pts, decimals).tolist()},
            })
        fc = {"type": "FeatureCollection", "features": feats,
              "properties": {"interval": self.interval, "interval_m": self.interval_m, "z_unit": self.z_unit,
                             "interval_reason": self.reason}}
        if self.crs:
            # RFC 7946 drops the crs member; GDAL/QGIS still read it, so coordinates stay usable
            name = self.crs if self.crs.upper().startswith("EPSG:") else None
            if name:
                fc["crs"] = {"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{name.split(':')[1]}"}}
        return fc


def _nice_interval(value: float) -> float:
    for v in NICE_INTERVALS:
        if v >= value - 1e-9:
            return v
    return float(math.ceil(value))


def choose_interval(raster: Raster, interval: float | None) -> tuple[float, str]:
    """The contour interval in metres and why it was chosen (``interval`` is metres too)."""
    if interval is not None:
        if not interval > 0:
            raise InvalidInputError("interval must be positive", field="interval")
        return float(interval), "given"
    rmse = raster.meta.get("vertical_rmse") if raster.meta else None
    if rmse:
        iv = _nice_interval(3.0 * float(rmse))
        return iv, f"3 × vertical RMSE {float(rmse):g} m = {3 * float(rmse):.2f} m, rounded up to {iv:g} m"
    from workstation.io.crs import raster_units

    a = np.asarray(raster.array, float)
    if raster.nodata is not None and not np.isnan(raster.nodata):
        a = np.where(a == raster.nodata, np.nan, a)
    rng = float(np.nanmax(a) - np.nanmin(a)) if np.isfinite(a).any() else 0.0
    rng = raster_units(raster).v_to_m(rng)
    iv = _nice_interval(max(rng / 20.0, 0.1))
    return iv, f"vertical accuracy unknown: about 20 levels over the {rng:.1f} m height range -> {iv:g} m"


def _chaikin(p: np.ndarray, closed: bool, iterations: int) -> np.ndarray:
    for _ in range(iterations):
        if len(p) < 3:
            return p
        if closed:
            q = p[:-1]
            nxt = np.roll(q, -1, axis=0)
            new = np.empty((2 * len(q), 2))
            new[0::2] = 0.75 * q + 0.25 * nxt
            new[1::2] = 0.25 * q + 0.75 * nxt
            p = np.vstack([new, new[:1]])
        else:
            a, b = p[:-1], p[1:]
            new = np.empty((2 * len(a), 2))
            new[0::2] = 0.75 * a + 0.25 * b
            new[1::2] = 0.25 * a + 0.75 * b
            p = np.vstack([p[:1], new[1:-1], p[-1:]])
    return p


def contour_lines(raster: Raster, params: ContourParams = ContourParams()) -> ContourSet:
    """Trace contour lines of a single-band DEM.

    Parameters
    ----------
    raster : Raster
        North-up DEM; NaN or ``nodata`` cells are masked.
    params : ContourParams

    Returns
    -------
    ContourSet

    Raises
    ------
    StageError
        When no level crosses the surface.
    """
    import contourpy

    a = np.asarray(raster.array, dtype=np.float64)
    if a.ndim == 3:
        a = a[0]
    if raster.nodata is not None and not np.isnan(raster.nodata):
        a = np.where(a == raster.nodata, np.nan, a)
    if not np.isfinite(a).any():
        raise InvalidInputError("the DEM has no valid cell", field="array")
    if min(a.shape) < 2:
        raise InvalidInputError(f"a {a.shape[0]} x {a.shape[1]} DEM has no contours (2 x 2 cells at least)",
                                "grid the cloud with a finer --resolution", field="shape")
    from workstation.io.crs import raster_units

    units = raster_units(raster)
    interval_m, reason = choose_interval(raster, params.interval)
    interval, base = units.v_from_m(interval_m), units.v_from_m(params.base)  # metres -> the DEM's heights
    zmin, zmax = float(np.nanmin(a)), float(np.nanmax(a))
    k0 = math.ceil((zmin - base) / interval)
    k1 = math.floor((zmax - base) / interval)
    if k1 - k0 > 10_000:
        raise InvalidInputError(f"{k1 - k0 + 1} contour levels: the interval is too small", field="interval")
    ks = np.arange(k0, k1 + 1)
    t = raster.transform
    gen = contourpy.contour_generator(z=np.ma.masked_invalid(a), name="serial", line_type="SeparateCode", corner_mask=True)
    lines, levels, closed, index = [], [], [], []
    for k in ks:
        level = base + k * interval
        segs, codes = gen.lines(level)
        for p, c in zip(segs, codes):
            if len(p) < params.min_points:
                continue
            is_closed = bool(c[-1] == 79) or (len(p) > 2 and np.array_equal(p[0], p[-1]))
            if is_closed and not np.array_equal(p[0], p[-1]):
                p = np.vstack([p, p[:1]])
            # grid index (col, row) of cell centres -> world
            w = np.empty_like(p)
            w[:, 0] = t[2] + (p[:, 0] + 0.5) * t[0] + (p[:, 1] + 0.5) * t[1]
            w[:, 1] = t[5] + (p[:, 0] + 0.5) * t[3] + (p[:, 1] + 0.5) * t[4]
            if params.smooth:
                w = _chaikin(w, is_closed, params.smooth)
            lines.append(w)
            levels.append(level)
            closed.append(is_closed)
            index.append(params.index_every > 0 and k % params.index_every == 0)
    if not lines:
        zu = units.v_abbrev
        raise StageError("contours", f"no {units.describe_v(interval_m)} level crosses the surface "
                                     f"({zmin:.2f}-{zmax:.2f} {zu})", "use a smaller --interval")
    return ContourSet(lines, np.array(levels), np.array(closed, bool), np.array(index, bool), interval, raster.crs, reason,
                      interval_m=interval_m, z_unit=units.v_name)


def write_geojson(cs: ContourSet, path, *, overwrite: bool = False, inputs=(), decimals: int = 3) -> Path:
    """Write a :class:`ContourSet` as GeoJSON atomically."""
    from workstation.io import atomic_path

    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        with open(tmp, "w") as f:
            json.dump(cs.to_geojson(decimals), f, separators=(",", ":"))
    return Path(path)
