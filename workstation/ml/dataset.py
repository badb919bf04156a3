"""Simulated, domain-randomised training data for the point classifier.

Scenes come from the shared scene model (:func:`workstation.lidar.scene.build_scene`, recipes
in ``datasets_synth/``) and are scanned here by a compact airborne simulator on Open3D ray
casting (:class:`workstation.interop.open3d_raycast.RaycastScene`): parallel flight lines
over the tile, a beam per pulse from the aircraft, multiple returns where the beam passes a
porous target (leaf clouds, wires, towers) with the remaining energy, range noise along the
beam, per-strip height offsets, specular water that answers only near nadir, Lambertian
intensity with range and incidence, and isolated high / low outliers labelled noise.

**Domain randomisation** (Tobin et al. 2017), drawn per tile from the recipe's ranges: point
density (log-uniform), flying height and field of view (so scan angles), number of returns
recorded (or none kept at all), range noise, strip offsets, intensity gain and offset or no
intensity at all, noise rate, tile size and terrain type (the scene recipe). The model never
sees one scanner, so it cannot learn it.

Every draw comes from ``numpy.random.default_rng`` seeded by the dataset seed and the tile
index, so a recipe and a seed give the same dataset on every machine.

References
----------
J. Tobin et al. (2017). Domain randomization for transferring deep neural networks from
simulation to the real world. IROS 2017, 23-30.
A. M. Esmorís et al. (2024). Virtual LiDAR for point cloud semantic segmentation: training
with HELIOS++ and the sim-to-real gap (on simulated training data for ALS segmentation).
"""

from __future__ import annotations

import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.io.textfile import read_text

log = get_logger(__name__)

#: The model's classes (index -> name) and how ASPRS codes map onto them.
MODEL_CLASSES: tuple[str, ...] = ("ground", "vegetation", "building", "water", "other", "noise")
_ASPRS_TO_MODEL = np.full(256, 4, np.int64)
for _code, _k in ((C.GROUND, 0), (C.ROAD_SURFACE, 0), (C.LOW_VEGETATION, 1), (C.MEDIUM_VEGETATION, 1),
                  (C.HIGH_VEGETATION, 1), (C.BUILDING, 2), (C.WATER, 3), (C.LOW_POINT, 5), (C.HIGH_NOISE, 5)):
    _ASPRS_TO_MODEL[int(_code)] = _k

_POROUS = np.zeros(256, bool)
for _code in (C.LOW_VEGETATION, C.MEDIUM_VEGETATION, C.HIGH_VEGETATION, C.WIRE_CONDUCTOR, C.TRANSMISSION_TOWER):
    _POROUS[int(_code)] = True


def asprs_to_model(codes: np.ndarray) -> np.ndarray:
    """Model class index (see :data:`MODEL_CLASSES`) of ASPRS codes; unknown codes -> other."""
    return _ASPRS_TO_MODEL[np.asarray(codes, np.uint8)]


@dataclass(frozen=True)
class Randomisation:
    """Ranges the simulator draws from per tile (uniform unless stated).

    Attributes
    ----------
    density : (float, float)
        Pulses per m² (log-uniform).
    altitude : (float, float)
        Flying height above the terrain (m).
    half_fov_deg : (float, float)
        Half field of view (degrees).
    max_returns : (int, int)
        Returns recorded per pulse (inclusive range).
    p_no_returns : float
        Probability the tile keeps no return numbers at all.
    range_sigma : (float, float)
        Range noise, 1 sigma (m).
    strip_offset : float
        Per-flight-line height offset, uniform in ±this (m).
    p_no_intensity : float
        Probability the tile has no intensity.
    intensity_gain : (float, float)
        Multiplier of the intensity (log-uniform).
    noise_rate : (float, float)
        Fraction of outlier points added.
    tile_size : (float, float)
        Square tile side (m).
    max_points : int
        Upper bound on points per tile (shrinks the tile at high density).
    p_physical : float
        Probability a tile is scanned by the full physical simulator of
        :mod:`workstation.lidar.simulate` (beam footprint, range equation, navigation errors,
        scan patterns) instead of the compact scanner here; both get the same randomised
        post-processing (returns, intensity, outliers).
    """

    density: tuple = (0.15, 20.0)
    altitude: tuple = (300.0, 1500.0)
    half_fov_deg: tuple = (10.0, 30.0)
    max_returns: tuple = (1, 5)
    p_no_returns: float = 0.25
    range_sigma: tuple = (0.02, 0.10)
    strip_offset: float = 0.08
    p_no_intensity: float = 0.3
    intensity_gain: tuple = (0.1, 10.0)
    noise_rate: tuple = (0.0, 0.003)
    tile_size: tuple = (80.0, 300.0)
    max_points: int = 250_000
    p_physical: float = 0.0


@dataclass(frozen=True)
class DatasetRecipe:
    """A simulated dataset: which scenes, how many tiles, and the randomisation.

    Attributes
    ----------
    seed : int
    recipes : tuple of str
        Scene recipe names in ``datasets_synth/`` (terrain types).
    scenes_per_recipe : int
    tiles_per_scene : int
    val_fraction : float
        Fraction of scenes held out for validation (whole scenes, never tiles of a training scene).
    samples_per_tile : int
        Training points drawn per tile, class-balanced (square-root of class frequency).
    randomisation : Randomisation
    train : dict
        Training settings (``epochs``, ``batch``, ``lr``, ``patience``, ``hidden``, ``time_budget_s``).
    """

    seed: int = 0
    recipes: tuple = ("urban", "rural", "forest", "mountain", "mixed")
    scenes_per_recipe: int = 2
    tiles_per_scene: int = 2
    val_fraction: float = 0.2
    samples_per_tile: int = 20_000
    randomisation: Randomisation = field(default_factory=Randomisation)
    train: dict = field(default_factory=dict)


def load_dataset_recipe(path) -> DatasetRecipe:
    """Read a training recipe TOML (``[dataset]``, ``[randomisation]``, ``[train]`` tables)."""
    p = Path(path)
    if not p.exists():
        raise InvalidInputError("recipe not found", "give a TOML file such as datasets_synth/ml_train.toml", path=p)
    try:
        data = tomllib.loads(read_text(p))
    except tomllib.TOMLDecodeError as e:
        raise InvalidInputError(f"not valid TOML: {e}", path=p) from None
    ds = dict(data.get("dataset", {}))
    rnd = dict(data.get("randomisation", {}))
    known = set(Randomisation.__dataclass_fields__)
    bad = set(rnd) - known
    if bad:
        raise InvalidInputError(f"unknown randomisation keys {sorted(bad)}", f"known: {sorted(known)}", path=p)
    rnd = {k: tuple(v) if isinstance(v, list) else v for k, v in rnd.items()}
    known_ds = set(DatasetRecipe.__dataclass_fields__) - {"randomisation", "train"}
    bad = set(ds) - known_ds
    if bad:
        raise InvalidInputError(f"unknown dataset keys {sorted(bad)}", f"known: {sorted(known_ds)}", path=p)
    if "recipes" in ds:
        ds["recipes"] = tuple(ds["recipes"])
    return DatasetRecipe(**ds, randomisation=Randomisation(**rnd), train=dict(data.get("train", {})))


# -- the scanner ---------------------------------------------------------------------------
def _face_normals(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    return n / np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-12)


def _loguniform(rng, lo, hi):
    return float(np.exp(rng.uniform(np.log(lo), np.log(hi))))


def simulate_tile(scene, rng: np.random.Generator, rnd: Randomisation, raycaster=None) -> Cloud:
    """Scan a random square tile of a scene with randomised airborne scanner settings.

    Parameters
    ----------
    scene : workstation.lidar.scene.Scene
    rng : numpy Generator
    rnd : Randomisation
    raycaster : RaycastScene, optional
        Reused across tiles of the same scene.

    Returns
    -------
    Cloud
        Map coordinates; ``classification`` (true ASPRS class, vegetation split 3/4/5 by height
        above the true ground), ``return_number``/``number_of_returns`` (unless dropped),
        ``intensity`` (unless dropped), ``scan_angle`` (degrees); ``meta["sim"]`` the draws.
    """
    from workstation.interop.open3d_raycast import RaycastScene

    rc = raycaster or RaycastScene(scene.vertices, scene.faces)
    fl = _draw_flight(scene, rng, rnd)
    origin, d, strip_dz = _fire_pulses(fl, rng, rnd)
    xyz, cls, ret, pid, inten = _trace_returns(rc, scene, rng, fl, origin, d, strip_dz)
    if len(xyz) < 50:
        raise InvalidInputError("simulated tile has too few points", "enlarge the tile or density")
    order, rn, nr = _renumber_returns(ret, pid)
    xyz, cls, pid, inten = xyz[order], cls[order], pid[order], inten[order]
    scan_angle = np.degrees(np.arctan2(d[pid, 0], -d[pid, 2])).astype(np.float32)
    return _finish_tile(xyz + scene.origin, cls, rn, nr, inten, scan_angle, rng, rnd, scene.crs,
                        {"simulator": "compact", "density": fl.density, "size": fl.size, "altitude": fl.altitude,
                         "half_fov_deg": float(np.degrees(fl.fov)), "max_returns": fl.max_returns,
                         "range_sigma": fl.range_sigma})


@dataclass(frozen=True)
class _Flight:
    """The randomised survey of one tile (scene-local coordinates, metres).

    ``density`` pulses per m², tile ``size`` (m) with south-west corner ``x0, y0``, flying
    ``altitude`` above the scene's median height ``zref``, half field of view ``fov``
    (radians), ``max_returns`` recorded per pulse, range noise ``range_sigma`` (m), and the
    x positions of the flight lines (along y) ``lines``, ``spacing`` apart.
    """

    density: float
    size: float
    x0: float
    y0: float
    altitude: float
    fov: float
    max_returns: int
    range_sigma: float
    zref: float
    spacing: float
    lines: np.ndarray


def _draw_flight(scene, rng: np.random.Generator, rnd: Randomisation) -> _Flight:
    """Draw the tile and the scanner settings from the recipe's ranges (in this order, so a seed
    gives the same tile): density (log-uniform), tile size (capped by ``max_points`` and the
    scene), tile corner, altitude, FOV, returns, range noise, then flight lines spaced for
    20-50 % side overlap."""
    lo, hi = scene.bounds_local()
    density = _loguniform(rng, *rnd.density)
    size = float(rng.uniform(*rnd.tile_size))
    size = min(size, np.sqrt(rnd.max_points / (density * 1.3)), hi[0] - lo[0] - 2, hi[1] - lo[1] - 2)
    x0 = rng.uniform(lo[0] + 1, hi[0] - 1 - size)
    y0 = rng.uniform(lo[1] + 1, hi[1] - 1 - size)
    H = float(rng.uniform(*rnd.altitude))
    fov = np.radians(rng.uniform(*rnd.half_fov_deg))
    max_ret = int(rng.integers(rnd.max_returns[0], rnd.max_returns[1] + 1))
    sigma = float(rng.uniform(*rnd.range_sigma))
    zref = float(np.median(scene.vertices[:, 2]))
    # flight lines along y, spaced for 20-50 % side overlap
    swath = 2 * H * np.tan(fov)
    spacing = swath * rng.uniform(0.5, 0.8)
    lines = np.arange(x0 - rng.uniform(0, spacing), x0 + size + spacing, spacing)
    return _Flight(density, size, x0, y0, H, fov, max_ret, sigma, zref, spacing, lines)


def _fire_pulses(fl: _Flight, rng: np.random.Generator, rnd: Randomisation):
    """Pulse targets uniform over the tile, each fired from a flight line that sees it within the
    FOV (random among those). Returns the beam origins (n, 3), unit directions (n, 3) and the
    height offset of each pulse's strip (n,)."""
    H, fov, lines, spacing = fl.altitude, fl.fov, fl.lines, fl.spacing
    n_p = max(int(fl.density * fl.size * fl.size), 100)
    tx = rng.uniform(fl.x0, fl.x0 + fl.size, n_p)
    ty = rng.uniform(fl.y0, fl.y0 + fl.size, n_p)
    li = np.clip(np.round((tx - lines[0]) / spacing + rng.uniform(-0.5, 0.5, n_p)).astype(np.int64), 0, len(lines) - 1)
    lx = lines[li]
    off = np.clip(tx - lx, -H * np.tan(fov), H * np.tan(fov))
    lx = tx - off
    origin = np.column_stack([lx, ty, np.full(n_p, fl.zref + H)])
    d = np.column_stack([tx - lx, np.zeros(n_p), np.full(n_p, -H)])
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    strip_dz = rng.uniform(-rnd.strip_offset, rnd.strip_offset, len(lines))[li]
    return origin, d, strip_dz


def _trace_returns(rc, scene, rng: np.random.Generator, fl: _Flight, origin, d, strip_dz):
    """Cast every pulse, return by return: each hit is recorded (water only near nadir, a
    Gaussian in incidence), with Lambertian intensity falling with range², range noise along
    the beam and the strip offset; a pulse continues through porous targets with part of its
    energy. Returns ``(xyz, classification, return index, pulse id, intensity)`` per echo."""
    from workstation.lidar.materials import material_arrays

    normals = _face_normals(scene.vertices, scene.faces)
    refl = material_arrays(1064.0)["reflectance"]
    H = fl.altitude
    pulse = np.arange(len(d))
    energy = np.ones(len(d))
    o = origin.copy()
    out_xyz, out_cls, out_ret, out_pulse, out_int = [], [], [], [], []
    p_through = rng.uniform(0.4, 0.8)
    water_w = np.radians(rng.uniform(1.5, 6.0))
    for ret in range(1, fl.max_returns + 1):
        if len(pulse) == 0:
            break
        t, prim = rc.cast(o, d[pulse])
        hit = prim >= 0
        pulse, t, prim, o_h = pulse[hit], t[hit].astype(np.float64), prim[hit], o[hit]
        dirs = d[pulse]
        p = o_h + dirs * t[:, None]
        cls = scene.classification[prim]
        cos_i = np.abs((normals[prim] * dirs).sum(1))
        keep = np.ones(len(p), bool)
        water = cls == C.WATER
        if water.any():
            inc = np.arccos(np.clip(cos_i[water], 0, 1))
            keep[water] = rng.uniform(size=water.sum()) < 0.03 + 0.97 * np.exp(-0.5 * (inc / water_w) ** 2)
        rng_m = np.linalg.norm(p - origin[pulse], axis=1)
        inten = refl[scene.material[prim]] * np.maximum(cos_i, 0.05) * energy[pulse] * (H / rng_m) ** 2
        pn = p + dirs * rng.normal(0, fl.range_sigma, len(p))[:, None]
        pn[:, 2] += strip_dz[pulse]
        out_xyz.append(pn[keep])
        out_cls.append(cls[keep])
        out_ret.append(np.full(keep.sum(), ret, np.uint8))
        out_pulse.append(pulse[keep])
        out_int.append(inten[keep])
        # continue through porous targets
        go = _POROUS[cls] & (rng.uniform(size=len(p)) < p_through)
        energy[pulse[go]] *= rng.uniform(0.3, 0.7, go.sum())
        sep = rng.uniform(0.8, 1.6)
        o = p[go] + dirs[go] * sep
        pulse = pulse[go]
    return (np.concatenate(out_xyz), np.concatenate(out_cls).astype(np.uint8), np.concatenate(out_ret),
            np.concatenate(out_pulse), np.concatenate(out_int))


def _renumber_returns(ret: np.ndarray, pid: np.ndarray):
    """Order echoes by pulse then return, and number them again after dropped (water) returns.
    Returns ``(order, return_number, number_of_returns)``, the last two in that order (uint8)."""
    order = np.lexsort((ret, pid))
    pid = pid[order]
    start = np.r_[True, pid[1:] != pid[:-1]]
    grp = np.cumsum(start) - 1
    counts = np.bincount(grp)
    first_idx = np.flatnonzero(start)
    rn = (np.arange(len(pid)) - first_idx[grp] + 1).astype(np.uint8)
    nr = counts[grp].astype(np.uint8)
    return order, rn, nr


def simulate_tile_physical(scene, rng: np.random.Generator, rnd: Randomisation) -> Cloud:
    """Scan a random square tile with the full simulator (:func:`workstation.lidar.survey.run_survey`)
    under randomised flight and scanner settings, then apply the same randomised returns,
    intensity and outlier treatment as :func:`simulate_tile`."""
    import dataclasses

    from workstation.lidar.survey import default_survey, run_survey

    lo, hi = scene.bounds_local()
    density = _loguniform(rng, *rnd.density)
    size = float(rng.uniform(*rnd.tile_size))
    size = min(size, np.sqrt(rnd.max_points / (density * 1.5)), hi[0] - lo[0] - 2, hi[1] - lo[1] - 2)
    x0 = rng.uniform(lo[0] + 1, hi[0] - 1 - size)
    y0 = rng.uniform(lo[1] + 1, hi[1] - 1 - size)
    H = float(rng.uniform(*rnd.altitude))
    fov = float(2 * rng.uniform(*rnd.half_fov_deg))
    kind = str(rng.choice(["zigzag", "polygon", "palmer"]))
    cfg = default_survey("als")
    swath = 2 * H * np.tan(np.radians(fov / 2))
    speed = float(rng.uniform(40, 80))
    overlap = float(rng.uniform(0.2, 0.5))
    # pulses per second for the wanted density: density * swath * speed / (1 - overlap) ... per line
    prf = float(np.clip(density * swath * speed, 5_000, 2_000_000))
    scan_f = float(np.clip(np.sqrt(prf * speed / max(swath, 1.0)) / 2, 10, 400))
    cfg = dataclasses.replace(
        cfg, area=(x0, x0 + size, y0, y0 + size),
        scanner=dataclasses.replace(cfg.scanner, kind=kind, prf=prf, scan_frequency=scan_f, fov_deg=fov),
        sensor=dataclasses.replace(cfg.sensor, max_returns=int(rng.integers(rnd.max_returns[0], rnd.max_returns[1] + 1)),
                                   subrays=3),
        errors=dataclasses.replace(cfg.errors, range_noise_m=float(rng.uniform(*rnd.range_sigma))),
        flight=dataclasses.replace(cfg.flight, altitude=H, speed=speed, overlap=overlap,
                                   heading_deg=float(rng.uniform(0, 180))))
    res = run_survey(scene, cfg, seed=int(rng.integers(0, 2**31 - 1)))
    c = res.cloud
    xyz = np.asarray(c.xyz)
    loc = xyz[:, :2] - scene.origin[:2]
    inside = (loc[:, 0] >= x0) & (loc[:, 0] < x0 + size) & (loc[:, 1] >= y0) & (loc[:, 1] < y0 + size)
    c = c[inside]
    if c.n < 50:
        raise InvalidInputError("physically simulated tile has too few points", "enlarge the tile or density")
    xyz = np.asarray(c.xyz)
    cls = np.asarray(c.attrs["classification"]).astype(np.uint8)
    rn = np.asarray(c.attrs["return_number"])
    nr = np.asarray(c.attrs["number_of_returns"])
    inten = np.asarray(c.attrs["intensity"], np.float64) / 2000.0
    scan_angle = np.asarray(c.attrs["scan_angle"], np.float32)
    return _finish_tile(xyz, cls, rn, nr, inten, scan_angle, rng, rnd, scene.crs,
                        {"simulator": "physical", "density": density, "size": size, "altitude": H, "half_fov_deg": fov / 2,
                         "pattern": kind, "prf": prf, "max_returns": cfg.sensor.max_returns,
                         "range_sigma": cfg.errors.range_noise_m})


def _finish_tile(xyz, cls, rn, nr, inten, scan_angle, rng, rnd: Randomisation, crs, meta) -> Cloud:
    """Outliers, vegetation split, randomly dropped returns / intensity, intensity gain."""
    n_noise = int(len(xyz) * rng.uniform(*rnd.noise_rate))
    if n_noise:
        src = rng.integers(0, len(xyz), n_noise)
        high = rng.uniform(size=n_noise) < 0.5
        nz = xyz[src].copy()
        nz[:, :2] += rng.normal(0, 2.0, (n_noise, 2))
        nz[:, 2] += np.where(high, rng.uniform(15, 150, n_noise), -rng.uniform(1.5, 20, n_noise))
        xyz = np.vstack([xyz, nz])
        cls = np.r_[cls, np.where(high, C.HIGH_NOISE, C.LOW_POINT).astype(np.uint8)]
        rn = np.r_[rn, np.ones(n_noise, np.uint8)]
        nr = np.r_[nr, np.ones(n_noise, np.uint8)]
        inten = np.r_[inten, rng.uniform(0.0, 0.3, n_noise)]
        scan_angle = np.r_[scan_angle, rng.uniform(-30, 30, n_noise).astype(np.float32)]
    cls = _split_vegetation(xyz, cls)
    attrs = {"classification": cls, "scan_angle": scan_angle}
    no_ret = rng.uniform() < rnd.p_no_returns
    if not no_ret:
        attrs["return_number"] = rn
        attrs["number_of_returns"] = nr
    no_int = rng.uniform() < rnd.p_no_intensity
    if not no_int:
        gain = _loguniform(rng, *rnd.intensity_gain)
        i = inten * gain * 2000 * rng.lognormal(0, 0.15, len(inten)) + rng.uniform(0, 500)
        attrs["intensity"] = np.clip(i, 0, 65535).astype(np.uint16)
    meta = {"sim": {**meta, "returns_kept": not no_ret, "intensity_kept": not no_int, "noise_points": n_noise}}
    return Cloud(xyz, attrs, crs=crs, meta=meta)


def _split_vegetation(xyz: np.ndarray, cls: np.ndarray, low_max: float = 0.5, medium_max: float = 2.0) -> np.ndarray:
    """Relabel vegetation 3/4/5 by height above the true ground (TIN of the ground points)."""
    veg = np.isin(cls, (C.LOW_VEGETATION, C.MEDIUM_VEGETATION, C.HIGH_VEGETATION))
    g = np.isin(cls, (C.GROUND, C.ROAD_SURFACE))
    if not veg.any() or g.sum() < 3:
        return cls
    from workstation.ground.common import fill_nearest

    from .features import grid_bilinear, grid_reduce

    lo = xyz[:, :2].min(axis=0)
    xy = xyz[:, :2] - lo
    cell = 2.0
    c = np.floor(xy[:, 0] / cell).astype(np.int64)
    r = np.floor(xy[:, 1] / cell).astype(np.int64)
    shape = (int(r.max()) + 1, int(c.max()) + 1)
    gz = grid_reduce(xyz[g, 2], r[g], c[g], shape, np.minimum, np.inf)
    gz = fill_nearest(gz, ~np.isfinite(gz))
    h = xyz[veg, 2] - grid_bilinear(gz, xy[veg], cell)
    out = cls.copy()
    out[veg] = np.where(h < low_max, C.LOW_VEGETATION, np.where(h < medium_max, C.MEDIUM_VEGETATION, C.HIGH_VEGETATION))
    return out


# -- dataset assembly ------------------------------------------------------------------------
@dataclass
class TileSet:
    """Features and labels of simulated tiles (training samples drawn per tile).

    Attributes
    ----------
    X : (m, f) float32
    y : (m,) int64
        Model class indices.
    tile : (m,) int64
        Tile index of each sample.
    val : (t,) bool
        Whether each tile belongs to the validation split.
    info : list of dict
        Per-tile draws.
    seconds : float
    """

    X: np.ndarray
    y: np.ndarray
    tile: np.ndarray
    val: np.ndarray
    info: list
    seconds: float


def tile_plan(recipe: DatasetRecipe) -> list[tuple[str, int, int, bool]]:
    """(scene recipe, scene seed, tile index, is_validation) for every tile, deterministic."""
    rng = np.random.default_rng(recipe.seed)
    plan = []
    t = 0
    for name in recipe.recipes:
        for s in range(recipe.scenes_per_recipe):
            seed = int(rng.integers(0, 2**31 - 1))
            val = bool(s == recipe.scenes_per_recipe - 1 and recipe.val_fraction > 0 and recipe.scenes_per_recipe > 1) \
                if recipe.val_fraction < 0.5 else bool(s % 2)
            for _ in range(recipe.tiles_per_scene):
                plan.append((name, seed, t, val))
                t += 1
    return plan


def sample_balanced(y: np.ndarray, n: int, rng: np.random.Generator) -> np.ndarray:
    """Indices of ``n`` samples, each class weighted by the square root of its frequency."""
    if len(y) <= n:
        return np.arange(len(y))
    cls, inv, cnt = np.unique(y, return_inverse=True, return_counts=True)
    w = (1.0 / np.sqrt(cnt))[inv]
    w /= w.sum()
    return np.sort(rng.choice(len(y), n, replace=False, p=w))


def simulated_tiles(recipe: DatasetRecipe, validation_only: bool = False, progress: bool = False):
    """Simulate the recipe's tiles in plan order, deterministically.

    Yields
    ------
    name, scene_seed, tile, is_validation, cloud, rng
        ``rng`` is the tile's generator after the simulation (:func:`build_tileset` goes on
        drawing the training samples from it).
    """
    from workstation.core.progress import track
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.lidar.scene import build_scene

    plan = tile_plan(recipe)
    items = track(plan, "simulating tiles", unit="tiles") if progress else plan
    cache: dict = {}
    for name, seed, t, val in items:
        if validation_only and not val:
            continue
        key = (name, seed)
        if key not in cache:
            cache.clear()
            sc = build_scene(name, seed=seed)
            cache[key] = (sc, RaycastScene(sc.vertices, sc.faces))
        sc, rc = cache[key]
        rng = np.random.default_rng([recipe.seed, t])
        if rng.uniform() < recipe.randomisation.p_physical:
            cloud = simulate_tile_physical(sc, rng, recipe.randomisation)
        else:
            cloud = simulate_tile(sc, rng, recipe.randomisation, rc)
        yield name, seed, t, val, cloud, rng


def build_tileset(recipe: DatasetRecipe, feature_params=None, progress: bool = True) -> TileSet:
    """Simulate every tile of the recipe, compute features and draw training samples."""
    from .features import FeatureParams, compute_features

    fp = feature_params or FeatureParams()
    t0 = time.perf_counter()
    val = np.array([p[3] for p in tile_plan(recipe)], bool)
    Xs, ys, ts, info = [], [], [], []
    for name, seed, t, _v, cloud, rng in simulated_tiles(recipe, progress=progress):
        F = compute_features(cloud, fp)
        y = asprs_to_model(cloud.attrs["classification"])
        idx = sample_balanced(y, recipe.samples_per_tile, rng)
        Xs.append(F[idx])
        ys.append(y[idx])
        ts.append(np.full(len(idx), t))
        info.append({"recipe": name, "scene_seed": seed, "tile": t, "points": cloud.n, **cloud.meta["sim"]})
    return TileSet(np.concatenate(Xs), np.concatenate(ys), np.concatenate(ts), val, info, time.perf_counter() - t0)
