"""``ws run``: a project's tasks on a Dask cluster, with re-runs, faults and progress.

With no scheduler address a local cluster of single-threaded worker processes is started
(one per core by default); with ``scheduler="tcp://host:8786"`` the tasks go to an existing
cluster (``dask scheduler`` and ``dask worker`` on other machines, which must see the project
and output folders at the same paths). Dask schedules, retries and moves the data: a worker
killed mid-task has its task run again elsewhere, and since every output is written
atomically and deterministically the result is the same bytes.

Tasks whose key is recorded as done in ``run.json`` with their outputs present are not
submitted, so a re-run after Ctrl-C, a crash or a parameter change does only what is missing
or changed. A task that fails (bad data in one tile) is reported with the file and reason; the
tasks that do not depend on it finish, and the run is marked incomplete.
"""

from __future__ import annotations

import hashlib
import time
import uuid
from dataclasses import dataclass, field
from pathlib import Path

from workstation.core.errors import InvalidInputError, WorkstationError
from workstation.core.log import get_logger
from workstation.core.signals import caught_signals

from . import plan as P
from workstation.io.catalog import build_catalog
from .chunks import chunk_grid
from .manifest import Manifest
from .project import load_project
from .stages import parse_stages
from . import tasks as T
from .tasks import RunContext

log = get_logger(__name__)
CACHE = ".ws-cache"


@dataclass(frozen=True)
class RunOptions:
    """How to run a project.

    Attributes
    ----------
    out : path or None
        Output folder (default: the project file's folder).
    scheduler : str or None
        Address of a running Dask scheduler; None starts a local cluster.
    workers : int or None
        Local cluster size (default: the project's ``[dask] workers``, else one per core).
    rerun_from, end_with : str or None
        Force a stage and the later ones to run again; stop after a stage.
    dry_run : bool
        Plan and report what would run, run nothing.
    retries : int
        Times Dask runs a task again after it raised (a killed worker is retried anyway).
    """

    out: Path | None = None
    scheduler: str | None = None
    workers: int | None = None
    rerun_from: str | None = None
    end_with: str | None = None
    dry_run: bool = False
    retries: int = 0


@dataclass
class RunResult:
    """What a run did: per-task status and the summary written to ``run.json``."""

    out: Path
    status: str
    summary: dict
    failures: list = field(default_factory=list)

    @property
    def complete(self) -> bool:
        return self.status == "complete"


def _context(project, plan, catalog, grid, out: Path) -> RunContext:
    from workstation.ground.common import crs_unit_factors
    from workstation.raster.grid import GridSpec

    if catalog is None:  # photos and scans only
        return RunContext(out, out / CACHE, project.crs, (), {}, {}, None, None, project.folder, project.photos,
                          project.scans)
    per_unit = crs_unit_factors(catalog.crs)[0]
    b = catalog.bounds
    dem = GridSpec.from_bounds(*b, plan.dem.params.resolution / per_unit) if plan.dem else None
    dens = GridSpec.from_bounds(*b, plan.density.cell / per_unit) if plan.density else None
    for g, what in ((dem, "stages.dem.resolution"), (dens, "stages.density.cell")):
        if g is not None and g.rows * g.cols > 2_000_000_000:
            raise InvalidInputError(f"a grid of {g.rows:,} x {g.cols:,} cells over the survey is too large",
                                    "use a coarser cell", path=project.path, field=what)
    cache = out / CACHE
    index = {str(t.path): cache / "index" / f"{t.path.stem}-{hashlib.sha1(str(t.path).encode()).hexdigest()[:10]}"
             for t in catalog.tiles if not t.copc}
    parts = {str(t.path): T.index_parts(t.point_count) for t in catalog.tiles if not t.copc}
    return RunContext(out, cache, catalog.crs, catalog.tiles, index, parts, dem, dens, project.folder, project.photos,
                      project.scans)


def prepare(project_path, options: RunOptions):
    """Load, plan and key every task; nothing runs. Returns (project, plan, catalog, grid,
    context, manifest, tasks)."""
    project = load_project(project_path)
    plan = parse_stages(project, options.end_with)
    if options.rerun_from is not None and options.rerun_from not in ("index",) + plan.stages:
        raise InvalidInputError(f"--rerun-from {options.rerun_from}: the project has no such stage",
                                "use one of " + ", ".join(("index",) + plan.stages), field="rerun_from")
    catalog = build_catalog(project.clouds, project.crs) if project.clouds else None
    grid = chunk_grid(catalog, project.chunks.size, project.chunks.buffer) if catalog else None
    out = Path(options.out).resolve() if options.out else project.folder  # workers may run elsewhere
    out.mkdir(parents=True, exist_ok=True)
    manifest = Manifest(out / "run.json")
    ctx = _context(project, plan, catalog, grid, out)
    tasks = P.build_tasks(ctx, plan, grid, manifest)
    return project, plan, catalog, grid, ctx, manifest, tasks


def _todo(tasks, manifest: Manifest, forced: set) -> list:
    """The tasks to run: not done with the same key, forced, or downstream of one that runs."""
    running: set[str] = set()
    out = []
    for t in tasks:
        if t.phase in forced or not manifest.is_done(t.id, t.key) or any(d in running for d in t.deps):
            running.add(t.id)
            out.append(t)
    return out


def run_project(project_path, options: RunOptions = RunOptions(), on_progress=None) -> RunResult:
    """Run (or re-run) a project; see the module doc. ``on_progress(phase, done, total, points)``
    is called as tasks finish."""
    t0 = time.perf_counter()
    project, plan, catalog, grid, ctx, manifest, tasks = prepare(project_path, options)
    todo = _todo(tasks, manifest, P.forced_phases(plan, options.rerun_from))
    info = {"project": str(project.path), "name": project.name, "catalog": catalog.summary() if catalog else None,
            "chunks": {"size": grid.size, "buffer": grid.buffer, "count": len(grid.chunks)} if grid else None,
            "photos": len(project.photos), "scans": len(project.scans),
            "stages": list(plan.stages), "versions": _versions()}
    counts = {ph: {"total": sum(t.phase == ph for t in tasks), "run": sum(t.phase == ph for t in todo)}
              for ph in P.PHASES if any(t.phase == ph for t in tasks)}
    if options.dry_run:
        return RunResult(ctx.out, "planned", {**info, "status": "planned", "phases": counts, "failures": [],
                                              "seconds": round(time.perf_counter() - t0, 3)})
    failures: list = []
    dashboard = None
    run_id = uuid.uuid4().hex
    if todo:
        dashboard = _execute(todo, manifest, ctx, options, project, failures, on_progress, run_id)
    status = "complete" if not failures else "incomplete"
    for ph in counts:
        done = [manifest.tasks.get(t.id, {}) for t in tasks if t.phase == ph]
        counts[ph].update(points=sum(r.get("points", 0) for r in done),
                          seconds=round(sum(r.get("seconds", 0) for r in done if r.get("run_id") == run_id), 3),
                          failed=sum(r.get("status") in ("failed", "skipped") for r in done))
    summary = {**info, "status": status, "phases": counts, "seconds": round(time.perf_counter() - t0, 3),
               "dashboard": dashboard, "failures": failures}
    manifest.save(**summary)
    return RunResult(ctx.out, status, summary, failures)


def _versions() -> dict:
    import dask
    import distributed
    import numpy

    from workstation import __version__

    return {"workstation": __version__, "dask": dask.__version__, "distributed": distributed.__version__,
            "numpy": numpy.__version__}


def _client(options: RunOptions, project):
    """A Dask client: on the given scheduler, or on a new local cluster sized to the machine."""
    import logging

    from distributed import Client, LocalCluster

    scheduler = options.scheduler or project.dask.get("scheduler")
    if scheduler:
        from workstation.core.dasktasks import connect

        return connect(scheduler), None
    from workstation.core.cpu import available_cores

    n = options.workers or project.dask.get("workers") or available_cores()
    if not (isinstance(n, int) and 1 <= n <= 512):
        raise InvalidInputError(f"workers {n!r} is not a number of processes", "use 1 or more", field="workers")
    from workstation.core.dasktasks import starting_local_workers

    with starting_local_workers():
        # the cores a worker may use for LAZ (de)compression threads: its share of the machine
        share = str(max(1, available_cores() // n))
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0",
                               silence_logs=logging.CRITICAL, memory_limit=project.dask.get("memory_limit", "auto"),
                               env={"RAYON_NUM_THREADS": share})
        try:
            client = Client(cluster)
        except BaseException:
            cluster.close()
            raise
    return client, cluster


def _execute(todo, manifest, ctx, options, project, failures, on_progress, run_id: str) -> str | None:
    """Submit ``todo`` to Dask and record each task as it ends; returns the dashboard address."""
    from distributed import as_completed

    from .progress import RunProgress

    client, cluster = _client(options, project)
    services = client.scheduler_info().get("services", {})
    dashboard = client.dashboard_link if "dashboard" in services else None
    by_id = {t.id: t for t in todo}
    futures: dict = {}
    waiting = [t for t in todo if t.barrier]
    finished: set[str] = set()
    broken: set[str] = set()
    try:
        with caught_signals() as latch, RunProgress(todo, dashboard, on_progress) as progress:
            ac = as_completed()
            for t in todo:
                if not t.barrier and not any(d in by_id and by_id[d].barrier for d in t.deps):
                    ac.add(_submit(client, t, futures, manifest, options))
            while not ac.is_empty() or waiting:
                for t in [w for w in waiting if all(d in finished or d not in by_id for d in w.deps)]:
                    waiting.remove(t)
                    ac.add(_submit(client, t, futures, manifest, options))
                    for d in todo:  # tasks after a barrier (hillshade after the DTM mosaic)
                        if t.id in d.deps and not d.barrier:
                            ac.add(_submit(client, d, futures, manifest, options))
                if ac.is_empty():
                    break
                while not ac.has_ready():
                    latch.sleep(0.05)
                fut = next(ac)
                if fut.status not in ("finished", "error", "cancelled"):
                    ac.add(fut)  # its result was lost with a worker and is being computed again
                    continue
                t = by_id[fut.key.split("|")[0]]
                finished.add(t.id)
                rec = _record(t, fut, futures, manifest, broken, run_id)
                if rec["status"] == "failed":
                    failures.append({"task": t.id, "error": rec["error"]})
                progress.advance(t.phase, rec.get("points", 0))
                latch.check()
    except KeyboardInterrupt:
        _quiet_event_loop_logs()
        client.cancel(list(futures.values()), force=True)
        raise
    finally:
        manifest.save()
        client.close()
        if cluster is not None:
            cluster.close()
    return dashboard


def _quiet_event_loop_logs() -> None:
    """After Ctrl-C or a signal, the tasks cancelled under Dask's event loop log their
    interruption with tracebacks (tornado, asyncio, distributed): not errors of the run, which
    ends with "Interrupted." and exit 128 + n."""
    import logging

    for name in ("tornado.application", "tornado.general", "asyncio", "distributed"):
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)


def _submit(client, t, futures, manifest, options):
    args = t.args
    if t.phase == "mosaic":  # the tiles that exist once every raster task has ended
        ctx, grid, product, out, meta = args
        args = (ctx, grid, P.tile_paths(manifest, t.deps, product), out, meta)
    if t.phase == "register" and t.barrier:  # the scans registered once every scan task has ended
        out, stage, names, _ = args
        args = (out, stage, names, sorted(p for p in manifest.outputs_of(t.deps) if p.endswith(".json")))
    deps = [futures[d] for d in t.deps if d in futures and not t.barrier]
    fut = client.submit(t.func, *args, *deps, key=f"{t.id}|{t.key[:12]}", pure=False, retries=options.retries)
    futures[t.id] = fut
    return fut


def _record(t, fut, futures, manifest, broken: set, run_id) -> dict:
    """The run.json record of a finished future; a task after a failed one is 'skipped'."""
    base = {"phase": t.phase, "chunk": t.chunk, "key": t.key, "params": t.params, "inputs": t.inputs, "deps": t.deps,
            "run_id": run_id,
            "finished": time.strftime("%Y-%m-%dT%H:%M:%S")}
    if fut.status == "finished":
        rec = {**base, "status": "done", **fut.result()}
        if t.barrier and any(d in broken for d in t.deps):
            rec["status"] = "partial"  # built from the tiles there are; not 'done', so it reruns
    elif any(d in broken or (d in futures and futures[d].status in ("error", "cancelled")) for d in t.deps):
        rec = {**base, "status": "skipped", "error": "an upstream task failed"}
        broken.add(t.id)
    else:
        exc = fut.exception()
        msg = exc.message if isinstance(exc, WorkstationError) else f"{type(exc).__name__}: {exc}"
        rec = {**base, "status": "failed", "error": msg}
        broken.add(t.id)
        log.error("%s failed: %s", t.id, rec["error"])
    manifest.record(t.id, rec)
    return rec
