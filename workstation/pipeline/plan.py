"""The task graph of a project run: one task per (stage, chunk), keyed by content.

Stages, in the order data flows: ``index`` (each plain LAS/LAZ input binned by chunk once),
``points`` (the point stages on a chunk and its buffer), ``rasters`` (DEM and density tiles
of a chunk), ``mosaic`` (one COG per product), then ``hillshade`` and ``contours`` of the
DTM mosaic, and ``qc`` (the delivery checked as ``ws qc`` does, file by file, then merged). Photos and scans have phases of their own: ``sfm``, ``dense``
and ``mesh`` of the photo block (:mod:`.photos`), and ``register``, a task per scan and the
merge (:mod:`.scans`). Each task lists the tasks it depends on and carries a key (see
:mod:`.manifest`); the runner skips those done with the same key.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from . import tasks as T
from .manifest import Manifest, task_key

CLOUD_PHASES = ("index", "points", "rasters", "mosaic", "hillshade", "contours", "qc")
PHASES = CLOUD_PHASES + ("sfm", "dense", "mesh", "register")


@dataclass
class Task:
    """One unit of work for a Dask worker.

    Attributes
    ----------
    id : str
        ``phase/name`` (``points/482250_5452000``); unique in a run.
    phase : str
        One of :data:`PHASES`.
    func : callable
        A function of :mod:`.tasks`; called as ``func(*args, *upstream_results)``.
    args : tuple
    deps : list of str
        Ids of the tasks whose outputs it reads.
    key : str
    params : dict
        The parameters recorded in run.json.
    inputs : dict
        Input file -> SHA-256, for the tasks that read input tiles (recorded in run.json).
    barrier : bool
        Submitted only when every dependency has finished (mosaics: they take the tiles that
        exist, so a failed chunk leaves a hole rather than stopping the mosaic).
    """

    id: str
    phase: str
    func: object
    args: tuple
    deps: list = field(default_factory=list)
    key: str = ""
    params: dict = field(default_factory=dict)
    barrier: bool = False
    chunk: str | None = None
    inputs: dict = field(default_factory=dict)


def _point_folder(plan) -> str:
    return plan.point_stages[-1] if plan.point_stages else ""


def build_tasks(ctx: T.RunContext, plan, grid, manifest: Manifest) -> list[Task]:
    """Every task of the run in dependency order (keys computed, nothing run)."""
    tasks: list[Task] = []
    file_hash = {str(t.path): manifest.file_hash(t.path) for t in ctx.tiles}
    reads_inputs = bool(plan.point_stages) or plan.dem is not None or plan.density is not None
    index_of: dict[str, list[Task]] = {}
    if reads_inputs:
        for t in ctx.tiles:
            if t.copc:
                continue
            p, k = str(t.path), ctx.index_parts[str(t.path)]
            index_of[p] = [Task(f"index/{t.path.name}" + (f"#{i}" if k > 1 else ""), "index", T.index_task,
                                (ctx, p, grid.size, i),
                                key=task_key("index", {"size": grid.size, "part": [i, k]}, [file_hash[p]]),
                                params={"size": grid.size, "part": i, "parts": k}, inputs={p: file_hash[p]})
                        for i in range(k)]
            tasks += index_of[p]

    def input_deps(chunk):
        hit = [t for t in ctx.tiles if t.intersects(chunk.buffered)]
        return ([d for t in hit for d in index_of.get(str(t.path), [])],
                [file_hash[str(t.path)] for t in hit if t.copc])

    def inputs_of(chunk) -> dict:
        return {str(t.path): file_hash[str(t.path)] for t in ctx.tiles if t.intersects(chunk.buffered)}

    points_of: dict[tuple, Task] = {}
    if plan.point_stages:
        params = {s: plan.params_of(s) for s in plan.point_stages}
        for c in grid.chunks:
            deps, copc = input_deps(c)
            task = Task(f"points/{c.name}", "points", T.points_task, (ctx, plan, c, _point_folder(plan)),
                        [d.id for d in deps], task_key("points", [params, c.buffer], copc, [d.key for d in deps]),
                        params, chunk=c.name, inputs=inputs_of(c))
            points_of[(c.ix, c.iy)] = task
            tasks.append(task)
    raster_tasks = _raster_tasks(ctx, plan, grid, points_of, input_deps, inputs_of)
    tasks += raster_tasks
    mosaics = _mosaic_tasks(ctx, plan, raster_tasks)
    tasks += mosaics
    tasks += _qc_tasks(ctx, plan, list(points_of.values()), mosaics, file_hash)
    from .photos import photo_tasks
    from .scans import scan_tasks

    photo = photo_tasks(ctx, plan, manifest)
    return tasks + photo + scan_tasks(ctx, plan, manifest, photo)


def _qc_tasks(ctx, plan, points, mosaics, file_hash) -> list[Task]:
    """The QC of the run's point outputs (the input tiles without point stages) and its DTM,
    file by file and merged (:mod:`.qc_tasks`)."""
    if plan.qc is None:
        return []
    from .qc_tasks import qc_plan

    dtm = next((m for m in mosaics if m.id == "mosaic/dtm"), None)
    return qc_plan(ctx, plan, points, dtm, file_hash, _point_folder(plan), Task, T.qc_task)


def _raster_tasks(ctx, plan, grid, points_of, input_deps, inputs_of) -> list[Task]:
    if plan.dem is None and plan.density is None:
        return []
    params = {"dem": plan.params_of("dem"), "density": plan.params_of("density"),
              "grid": [ctx.dem_grid, ctx.density_grid]}
    out = []
    for c in grid.chunks:
        if points_of:
            deps = [points_of[(n.ix, n.iy)] for n in c.neighbours() if (n.ix, n.iy) in points_of]
            copc = []
        else:
            deps, copc = input_deps(c)
        out.append(Task(f"rasters/{c.name}", "rasters", T.raster_task, (ctx, plan, c), [d.id for d in deps],
                        task_key("rasters", params, copc, [d.key for d in deps]), params, chunk=c.name,
                        inputs={} if points_of else inputs_of(c)))
    return out


def _mosaic_tasks(ctx, plan, raster_tasks) -> list[Task]:
    """Mosaics of each DEM kind and of the density, then hillshade and contours of the DTM."""
    products = [(k, ctx.dem_grid, ctx.out / "dem" / f"{k}.tif") for k in (plan.dem.kinds if plan.dem else ())]
    if plan.density is not None:
        products.append(("density", ctx.density_grid, ctx.out / "density" / "density.tif"))
    out, dtm = [], None
    deps, keys = [t.id for t in raster_tasks], [t.key for t in raster_tasks]
    for name, g, path in products:
        meta = {"kind": name, "resolution": g.res}
        task = Task(f"mosaic/{name}", "mosaic", T.mosaic_task, (ctx, g, name, str(path), meta), deps,
                    task_key("mosaic", meta, (), keys), meta, barrier=True)
        out.append(task)
        dtm = task if name == "dtm" else dtm
    if dtm is not None and plan.hillshade is not None:
        p = plan.params_of("hillshade")
        out.append(Task("hillshade/dtm", "hillshade", T.hillshade_task,
                        (ctx, plan.hillshade, dtm.args[3], str(ctx.out / "dem" / "dtm_hillshade.tif")),
                        [dtm.id], task_key("hillshade", p, (), [dtm.key]), p))
    if dtm is not None and plan.contours is not None:
        p = plan.params_of("contours")
        out.append(Task("contours/dtm", "contours", T.contours_task,
                        (ctx, plan.contours, dtm.args[3], str(ctx.out / "dem" / "dtm_contours.geojson")),
                        [dtm.id], task_key("contours", p, (), [dtm.key]), p))
    return out


def forced_phases(plan, rerun_from: str | None) -> set[str]:
    """The phases ``--rerun-from STAGE`` forces: the phase that runs STAGE and every later one
    (a photo or scan stage: its own phase; the tasks after it run again as their inputs do)."""
    if rerun_from is None:
        return set()
    if rerun_from in PHASES[len(CLOUD_PHASES):]:
        return {rerun_from}
    phase = {"noise": "points", "ground": "points", "classify": "points", "hag": "points", "dem": "rasters",
             "density": "rasters", "hillshade": "hillshade", "contours": "contours", "index": "index",
             "mosaic": "mosaic", "qc": "qc"}[rerun_from]
    later = CLOUD_PHASES[CLOUD_PHASES.index(phase):]
    if phase in ("hillshade", "contours", "qc"):
        later = (phase,)
    return set(later)


def tile_paths(manifest: Manifest, raster_ids, product: str) -> list[str]:
    """The tiles of ``product`` (a DEM kind or ``density``) the raster tasks made."""
    folder = f"{Path('density') / 'tiles'}" if product == "density" else str(Path("dem") / "tiles" / product)
    return sorted(p for p in manifest.outputs_of(raster_ids) if folder in p and p.endswith(".tif"))
