"""The buildings stage: classified points in, footprints, roof planes, LoD1.2/LoD2.2 models and
solar potential out (:func:`reconstruct_buildings`)."""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.errors import InvalidInputError, StageError

from .footprints import (Component, Footprint, FootprintParams, component_footprint, district_components,
                         no_footprint_error, nominal_spacing, points_by_label)
from .models import ModelParams, build_building
from .planes import PlaneParams, segment_planes
from .solar import SolarParams

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class BuildingsParams:
    """Parameters of :func:`reconstruct_buildings`.

    Attributes
    ----------
    building_class, ground_class : int
        ASPRS classes of roof points and ground points.
    planes, footprints, models : PlaneParams, FootprintParams, ModelParams
        Stage parameters (see each).
    solar : SolarParams or None
        Solar potential parameters; None skips the solar computation.
    dtm_cell : float
        Cell of the DTM gridded from the ground points (m).
    dsm_cell : float or None
        Cell of the DSM used for shading (m); None uses the nominal point spacing (at least 0.5 m).
    solar_map_cell : float or None
        Cell of the roof solar map (m, :func:`solar_map`); None skips the map.
    """

    building_class: int = int(ASPRSClass.BUILDING)
    ground_class: int = int(ASPRSClass.GROUND)
    planes: PlaneParams = field(default_factory=PlaneParams)
    footprints: FootprintParams = field(default_factory=FootprintParams)
    models: ModelParams = field(default_factory=ModelParams)
    solar: SolarParams | None = field(default_factory=SolarParams)
    dtm_cell: float = 1.0
    dsm_cell: float | None = None
    solar_map_cell: float | None = 0.5


@dataclass(frozen=True)
class BuildingsResult:
    """Everything :func:`reconstruct_buildings` made.

    Attributes
    ----------
    models : list of BuildingModel
    solar_kwh_m2_year : list of (r,) arrays
        Annual irradiation of each roof face of each building (kWh/m^2/year; NaN when skipped).
    footprint_source : str
        ``points`` or ``given``.
    timings : dict
        Seconds per step. Wall time of the stage: ``cluster_s`` (starting or reaching the Dask
        cluster, only with one), ``district_s`` (point spacing, district density raster and its
        regions; with a cluster, made while it starts), ``district_wait_s`` (with a cluster: the
        wait for the district pass once the cluster is up), ``solar_s``, ``solar_map_s`` and
        ``total_s``. Summed over the buildings, each
        timed where it ran (on a cluster the workers' time, not the wall time, which is less
        with several workers): ``outlines_sum_s`` (each building's footprint traced from its
        region), ``planes_sum_s`` (roof planes), ``models_sum_s`` (LoD1.2/LoD2.2 models), and
        ``buildings_cpu_s``, the CPU seconds of all three.
    spacing : float
        Nominal point spacing of the building points (m).
    coverage : dict
        How footprints and points agree: ``building_points_outside`` (share of building points
        in no footprint, 0-1) and ``footprints_without_points`` (count), given footprints
        checked against the cloud.
    solar_map : (array (rows, cols) float32, transform tuple) or None
        Roof solar map of :func:`solar_map` (NaN off the roofs), None when solar or the map is skipped.
    """

    models: list
    solar_kwh_m2_year: list
    footprint_source: str
    timings: dict
    spacing: float
    coverage: dict = field(default_factory=dict)
    solar_map: tuple | None = None


def ground_dtm(xyz: np.ndarray, cell: float):
    """DTM (m) of ground points: mean height per cell, empty cells (under buildings) from the
    nearest ground cell. Returns (z (rows, cols), origin (2,))."""
    from scipy import ndimage

    origin = xyz[:, :2].min(axis=0)
    ij = np.floor((xyz[:, :2] - origin) / cell).astype(np.int64)
    shape = (int(ij[:, 1].max()) + 1, int(ij[:, 0].max()) + 1)
    flat = ij[:, 1] * shape[1] + ij[:, 0]
    n = np.bincount(flat, minlength=shape[0] * shape[1])
    s = np.bincount(flat, weights=xyz[:, 2], minlength=shape[0] * shape[1])
    z = np.where(n > 0, s / np.maximum(n, 1), np.nan).reshape(shape)
    empty = np.isnan(z)
    if empty.any():
        _, (ii, jj) = ndimage.distance_transform_edt(empty, return_indices=True)
        z = z[ii, jj]
    return z, origin


def sample_grid(z: np.ndarray, origin: np.ndarray, cell: float, xy: np.ndarray) -> np.ndarray:
    """Nearest-cell values of a raster at ``xy`` (m, 2), clamped to the raster."""
    ij = np.floor((xy - origin) / cell).astype(np.int64)
    return z[np.clip(ij[:, 1], 0, z.shape[0] - 1), np.clip(ij[:, 0], 0, z.shape[1] - 1)]


def assign_to_footprints(xy: np.ndarray, polygons: list) -> np.ndarray:
    """Footprint index (n,) of each point (-1 outside every footprint), via an STR-tree."""
    import shapely

    tree = shapely.STRtree([shapely.Polygon(p) for p in polygons])
    pi, gi = tree.query(shapely.points(xy), predicate="intersects")
    out = np.full(len(xy), -1, np.int64)
    out[pi] = gi
    return out


def reconstruct_buildings(xyz: np.ndarray, classification: np.ndarray, params: BuildingsParams = BuildingsParams(),
                          footprints: list | None = None, workers: int = 1,
                          scheduler: str | None = None) -> BuildingsResult:
    """Footprints, roof planes, LoD1.2/LoD2.2 models and solar potential of the buildings in a
    classified cloud (``xyz`` (n, 3) in metres, ``classification`` (n,) ASPRS codes).

    ``footprints`` (list of (k, 2) polygons, metres) are used instead of traced ones when given.
    The district-wide raster of the footprints is made here; each building's outline, roof
    planes and model (:func:`build_unit`) follow one after the other, or, with ``workers`` > 1
    or a ``scheduler`` address, in batches on a Dask cluster (a local one of ``workers``
    single-threaded processes, started while the district raster is made, or the running one
    at ``scheduler``): the same models, in the same order, either way. Spawned worker processes
    need the ``if __name__ == "__main__":`` guard in a script that asks for them.
    """
    if workers < 1:
        raise InvalidInputError(f"workers {workers} is below 1", "use 1 or more processes", field="workers")
    t0 = time.perf_counter()
    cls = np.asarray(classification)
    bmask = cls == params.building_class
    if bmask.sum() < 10:
        raise StageError("buildings", f"only {int(bmask.sum())} points of class {params.building_class}",
                         "classify the cloud first (ws classify) or pass --classify")
    bxyz = np.asarray(xyz, float)[bmask]
    t: dict = {}
    if workers == 1 and not scheduler:
        d = _district_pass(xyz, cls, bxyz, params, footprints, 1, t)
        done = [r for i in range(len(d.shapes)) for r in build_unit(d.items(i, i + 1), d.setup, d.dtm)]
    else:
        d, done = _on_cluster(xyz, cls, bxyz, params, footprints, workers, scheduler, t, t0)
    models, spacing, coverage = _collect(done, t), d.setup.spacing, d.coverage
    source = "points" if footprints is None else "given"
    solar = _solar(models, xyz, params, spacing, t)
    smap = None
    if params.solar is not None and params.solar_map_cell and any(m.roofs for m in models):
        t2 = time.perf_counter()
        smap = solar_map(models, xyz, params.solar, spacing, params.solar_map_cell, params.dsm_cell)
        t["solar_map_s"] = time.perf_counter() - t2
    t["total_s"] = time.perf_counter() - t0
    return BuildingsResult(models, solar, source, t, spacing, coverage, smap)


@dataclass(frozen=True)
class UnitSetup:
    """What every building of :func:`build_unit` shares: the stage parameters, the point
    spacing (m), and the traced raster's roof density and cell (m)."""

    params: BuildingsParams
    spacing: float
    ref: float
    cell: float


@dataclass(frozen=True)
class DistrictPass:
    """What :func:`_district_pass` hands the buildings: each building's shape (a traced
    :class:`Component` or a given :class:`Footprint`), the building points with their order by
    building and each building's start in it (building i: ``order[starts[i + 1]:starts[i + 2]]``),
    the shared :class:`UnitSetup`, the ground DTM of :func:`ground_dtm` (or None) and the
    coverage figures of :class:`BuildingsResult`."""

    shapes: list
    points: np.ndarray
    order: np.ndarray
    starts: np.ndarray
    setup: UnitSetup
    dtm: tuple | None
    coverage: dict

    def items(self, a: int, b: int) -> list:
        """Buildings ``a`` to ``b`` - 1 as (shape, points (m, 3)) pairs, the points copied now."""
        return [(self.shapes[i], self.points[self.order[self.starts[i + 1]:self.starts[i + 2]]])
                for i in range(a, min(b, len(self.shapes)))]


def _district_pass(xyz, cls, bxyz, params, footprints, threads, t) -> DistrictPass:
    """The district-wide work before the buildings (:class:`DistrictPass`): the point spacing
    and the district raster of the building points ``bxyz`` on ``threads`` threads, and the
    ground DTM (with more than one thread, in a thread of its own beside the raster; an error
    of the raster returns at once, without waiting for it). Seconds into ``t``."""
    from workstation.core.dasktasks import alongside

    t0 = time.perf_counter()
    dtm_f = alongside(_ground, xyz, cls, params) if threads > 1 else None
    spacing = params.footprints.spacing or nominal_spacing(bxyz[:, :2], threads)
    if not spacing > 0:  # fewer than two distinct building points: nothing to model
        raise StageError("buildings", f"the {len(bxyz)} building points hold fewer than two distinct positions",
                         "check that building points are classified (class 6)")
    shapes, owner, ref, cell = _district(bxyz, footprints, replace(params.footprints, spacing=spacing), threads)
    t["district_s"] = time.perf_counter() - t0
    dtm = dtm_f.result() if dtm_f is not None else _ground(xyz, cls, params)
    coverage = {"building_points_outside": float(np.mean(owner < 0)),
                "footprints_without_points": int(len(shapes) - len(np.unique(owner[owner >= 0])))}
    if footprints is not None and coverage["building_points_outside"] > 0.2:
        log.warning("%.0f %% of the building points lie outside the given footprints",
                    100 * coverage["building_points_outside"])
    order, starts = points_by_label(owner + 1, len(shapes))  # building i: label i + 1
    return DistrictPass(shapes, bxyz, order, starts, UnitSetup(params, spacing, ref, cell), dtm, coverage)


def _on_cluster(xyz, cls, bxyz, params, footprints, workers: int, scheduler: str | None, t: dict, t0: float):
    """:func:`_district_pass` in a thread (:func:`workstation.core.dasktasks.alongside`), then
    its buildings on the Dask cluster: (district pass, :func:`build_unit` results in building
    order). With a local cluster the pass, on ``workers`` threads, overlaps the workers' start
    here; a running ``scheduler`` is reached first (an address that fails costs no pass, and
    the overlap would gain nothing), the pass on one thread beside the workers' imports. The
    cluster is closed on the way out, an error or Ctrl-C included; a Ctrl-C while the workers
    start is lost (:func:`workstation.core.signals.workers_starting`), one after is raised at
    once. On an error or Ctrl-C the pass's thread still runs to its end, its CPU not reclaimed."""
    from workstation.core.dasktasks import alongside, connect, local_client, wait_for
    from workstation.core.signals import caught_signals

    td: dict = {}  # the district pass's seconds, taken into t once it is done

    def district():
        return alongside(_district_pass, xyz, cls, bxyz, params, footprints, 1 if scheduler else workers, td)

    pending = None if scheduler else district()
    with (connect(scheduler) if scheduler else local_client(workers)) as client, caught_signals() as latch:
        t["cluster_s"] = time.perf_counter() - t0
        if pending is None:
            pending = district()
        # the workers import while the district pass ends (futures held till the end)
        warm = [client.submit(_warm_up, pure=False, workers=[w]) for w in client.scheduler_info()["workers"]]
        t1 = time.perf_counter()
        d = wait_for(pending, latch)
        t.update(td, district_wait_s=time.perf_counter() - t1)
        done = _on_dask(client, d, latch)
        del warm
    return d, done


def _ground(xyz, cls, params):
    """:func:`ground_dtm` of the points of ``params.ground_class``, or None (with a warning) when
    there are fewer than three."""
    gmask = cls == params.ground_class
    if gmask.sum() < 3:
        log.warning("no ground points (class %d): walls reach down to each building's lowest point",
                    params.ground_class)
        return None
    return ground_dtm(np.asarray(xyz, float)[gmask], params.dtm_cell)


def _district(bxyz, footprints, fparams, threads):
    """What each building is made from: a :class:`Component` of the traced district raster (on
    ``threads`` threads) or a given :class:`Footprint` per building, the building of every point
    (-1: none), and the raster's roof density and cell (NaN with given footprints)."""
    if footprints is not None:
        if not footprints:
            raise InvalidInputError("no footprint polygons given", field="footprints")
        fps = [Footprint(np.asarray(p, float), "given") for p in footprints]
        return fps, assign_to_footprints(bxyz[:, :2], [f.polygon for f in fps]), float("nan"), float("nan")
    d = district_components(bxyz[:, :2], fparams, threads)
    if not d.components:
        raise no_footprint_error(fparams, len(bxyz))
    return d.components, d.point_component(), d.ref, d.cell


def build_unit(items: list, setup: UnitSetup, dtm) -> list:
    """Footprint, roof planes and model of each building of ``items`` ((shape, points (m, 3))
    pairs, the shape a traced :class:`Component` or a given :class:`Footprint`), the ground
    height from ``dtm`` ((z, origin) of :func:`ground_dtm`, or None: the lowest point).

    Returns per building (footprint, model with id -1 or None when it has too few points,
    seconds of the footprint, of the planes and of the model, CPU seconds of all three). Module
    level, on plain data: a worker process receives it pickled."""
    p = setup.params
    fparams = replace(p.footprints, spacing=setup.spacing)
    cell = p.models.cell or setup.spacing
    out = []
    for shape, pts in items:
        t0, c0 = time.perf_counter(), time.thread_time()
        fp = component_footprint(shape, pts[:, :2], setup.spacing, setup.ref, setup.cell, fparams) \
            if isinstance(shape, Component) else shape
        t1 = time.perf_counter()
        if len(pts) < max(3, p.planes.min_points):
            out.append((fp, None, t1 - t0, 0.0, 0.0, time.thread_time() - c0))
            continue
        planes = segment_planes(pts, p.planes)
        t2 = time.perf_counter()
        ground = float(sample_grid(dtm[0], dtm[1], p.dtm_cell, fp.polygon).min()) if dtm is not None \
            else float(pts[:, 2].min())
        model = build_building(-1, fp.polygon, pts, planes.labels, planes, ground, p.models, cell)
        out.append((fp, model, t1 - t0, t2 - t1, time.perf_counter() - t2, time.thread_time() - c0))
    return out


def _collect(done: list, t: dict) -> list:
    """The models of :func:`build_unit`'s results in building order, numbered from 0; the
    seconds per step summed over the buildings into ``t`` (``*_sum_s``, over all workers: work,
    not wall time), and their CPU seconds (``buildings_cpu_s``; see :class:`BuildingsResult`)."""
    models = [replace(m, id=i) for i, m in enumerate(r[1] for r in done if r[1] is not None)]
    if not models:
        raise StageError("buildings", "no footprint holds building points", "check the footprints' CRS and extent")
    for k, key in ((2, "outlines_sum_s"), (3, "planes_sum_s"), (4, "models_sum_s"), (5, "buildings_cpu_s")):
        t[key] = float(sum(r[k] for r in done))
    return models


def _warm_up() -> None:
    """Import what :func:`build_unit` needs (run on each worker before the first batch)."""
    import contourpy  # noqa: F401
    import scipy.ndimage  # noqa: F401
    import scipy.sparse.csgraph  # noqa: F401
    import scipy.spatial  # noqa: F401
    import scipy.stats  # noqa: F401
    import shapely  # noqa: F401


def _on_dask(client, d: DistrictPass, latch) -> list:
    """:func:`build_unit` on batches of consecutive buildings of ``d`` on a Dask cluster, at
    most two batches per worker in flight (a batch's points are copied only when a worker is
    nearly free for it), a Ctrl-C caught into ``latch`` raised between them; the results in
    building order. Batches (:func:`batch_ranges`) hold a quarter of a worker's share of the
    buildings left (at most 32), so they shrink towards the end and the workers finish within
    about one building's time."""
    from workstation.core.dasktasks import run_bounded

    n = max(1, sum(client.nthreads().values()))
    dtm_f = client.scatter(d.dtm, broadcast=True) if d.dtm is not None else None
    results: dict = {}
    calls = ((k, lambda a=a, b=b: (build_unit, d.items(a, b), d.setup, dtm_f))
             for k, (a, b) in enumerate(batch_ranges(len(d.shapes), n)))
    run_bounded(client, calls, 2 * n, results.__setitem__, latch, pause=0.02)
    return [r for k in sorted(results) for r in results[k]]


def batch_ranges(n_items: int, workers: int, largest: int = 32) -> list:
    """(start, end) index pairs, end excluded, of consecutive batches that cover ``n_items``
    once, for ``workers``: each a quarter of a worker's share of the items not yet in a batch,
    between 1 and ``largest`` items."""
    out, a = [], 0
    while a < n_items:
        b = a + max(1, min(largest, -(-(n_items - a) // (4 * workers))))
        out.append((a, min(b, n_items)))
        a = b
    return out


def _solar(models, xyz, params, spacing, t):
    """Annual irradiation per roof face, shaded by the DSM of all points."""
    from .solar import build_dsm, horizon_angles, plane_irradiation

    if params.solar is None:
        return [np.full(len(m.roofs), np.nan) for m in models]
    t1 = time.perf_counter()
    cell = params.dsm_cell or max(spacing, 0.5)
    dsm, origin = build_dsm(np.asarray(xyz, float), cell)
    faces = [f for m in models for f in m.roofs]
    pts, owner = _face_samples(faces, cell)
    hor = horizon_angles(dsm, origin, cell, pts, params.solar.sectors, params.solar.max_distance)
    normals = np.array([f.normal for f in faces])[owner]
    per_sample = plane_irradiation(normals, hor, params.solar)
    per_face = np.bincount(owner, per_sample, minlength=len(faces)) / np.maximum(np.bincount(owner, minlength=len(faces)), 1)
    out, k = [], 0
    for m in models:
        out.append(per_face[k:k + len(m.roofs)])
        k += len(m.roofs)
    t["solar_s"] = time.perf_counter() - t1
    return out


def _face_samples(faces, cell):
    """Up to about nine points on each roof face (a grid inside it, else its representative
    point), lifted by the DSM's own roughness over one cell diagonal so a face does not shade
    itself: (points (s, 3), face index (s,))."""
    import shapely

    from .solar import self_shading_lift

    pts, owner = [], []
    for i, f in enumerate(faces):
        poly = shapely.Polygon(f.polygon)
        step = max(np.sqrt(poly.area / 9.0), cell)
        x0, y0, x1, y1 = poly.bounds
        gx, gy = np.meshgrid(np.arange(x0 + step / 2, x1, step), np.arange(y0 + step / 2, y1, step))
        xy = np.column_stack([gx.ravel(), gy.ravel()])
        xy = xy[shapely.contains_xy(poly, xy[:, 0], xy[:, 1])]
        if not len(xy):
            rp = poly.representative_point()
            xy = np.array([[rp.x, rp.y]])
        pts.append(np.column_stack([xy, f.z(xy) + self_shading_lift(f.normal, cell)]))
        owner.append(np.full(len(xy), i))
    return np.vstack(pts), np.concatenate(owner)


def solar_map(models: list, xyz: np.ndarray, solar: SolarParams, spacing: float, cell: float = 0.5,
              dsm_cell: float | None = None):
    """Raster of the annual clear-sky irradiation (kWh/m^2/year) of every roof cell seen from
    above, each cell shaded by its own DSM horizon (the per-face computation of
    :func:`reconstruct_buildings` run at each cell centre), NaN off the roofs.

    Returns (array (rows, cols) float32, transform (a, b, c, d, e, f) of its upper-left corner)."""
    from .solar import build_dsm, horizon_angles, plane_irradiation, roof_cells, self_shading_lift

    if not cell > 0:
        raise InvalidInputError(f"solar map cell must be positive, got {cell}", field="solar_cell")
    faces = [f for m in models for f in m.roofs]
    if not faces:
        raise StageError("buildings", "no roof faces for the solar map")
    dcell = dsm_cell or max(spacing, 0.5)
    rows, cols, pts, owner, shape, (x0, y1) = roof_cells([f.polygon for f in faces], [f.z for f in faces], cell)
    normals = np.array([f.normal for f in faces])
    lift = np.array([self_shading_lift(n, dcell) for n in normals])
    pts = pts + np.column_stack([np.zeros((len(pts), 2)), lift[owner]])
    dsm, origin = build_dsm(np.asarray(xyz, float), dcell)
    hor = horizon_angles(dsm, origin, dcell, pts, solar.sectors, solar.max_distance)
    out = np.full(shape, np.nan, np.float32)
    out[rows, cols] = plane_irradiation(normals[owner], hor, solar)
    return out, (cell, 0.0, x0, 0.0, -cell, y1)
