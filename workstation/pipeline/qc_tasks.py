"""The QC stage of ``ws run`` as tasks: ``ws qc`` of the run's point files, in parts.

The point files are the chunks' outputs (or the input tiles, without point stages). Each is
checked on its own and the partial states merged (:mod:`workstation.qc.partial`):

* ``qc/catalog`` — the files' headers, once every point task has ended (a barrier: it takes
  the files there are);
* ``qc/pass1/<file>`` — pass 1 of one file (format, density pieces, class cells);
* ``qc/surface`` — pass 1 added up: ANPS and the ground surface of the whole delivery;
* ``qc/pass2/<file>`` — pass 2 of one file (coverage cells, swath sums, surface tests);
* ``qc/fit/<block>`` — the swath planes of the cells a block owns (the chunks; without point
  stages, blocks of one file's share of the area), from the swath sums of the files around it;
* ``qc/delivery`` — the merge into ``OUT/qc/`` (:func:`.tasks.qc_task`).

State files live in ``<cache>/qc/``; each task is keyed like the others, so a re-run with
nothing changed runs none of them.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from workstation.qc.partial import block_side, blocks_over, boxes_meet

from .manifest import task_key
from .tasks import RunContext, peak_rss_mb


def qc_params(ctx: RunContext, stage, dtm: str | None = None):
    """The ``ws qc`` parameters of a ``[stages.qc]`` table (checkpoints relative to the project)."""
    from workstation.qc.run import QCParams

    cps = None if stage.checkpoints is None else ctx.project_folder / stage.checkpoints
    return QCParams(spec=stage.spec, checkpoints=cps, checkpoint_rmse_m=float(stage.checkpoint_rmse),
                    dem=Path(dtm) if dtm else None)


def state_root(ctx: RunContext) -> Path:
    return Path(ctx.cache) / "qc"


def qc_catalog_task(ctx: RunContext, stage, units: list, blocks: list, size: float, *upstream) -> dict:
    """Catalog the point files of ``units`` ([(path, state folder)]) that exist."""
    from workstation.core.errors import StageError
    from workstation.qc.partial import write_catalog

    have = [(p, n) for p, n in units if Path(p).exists()]
    if not have:
        raise StageError("qc", "no point file to check", "check the earlier stages' errors")
    doc = write_catalog([p for p, _ in have], [n for _, n in have], state_root(ctx), blocks, size)
    return {"files": len(doc["files"]), "peak_rss_mb": peak_rss_mb(),
            "outputs": [str(state_root(ctx) / "catalog.json")]}


def _catalog(ctx: RunContext) -> dict:
    """``catalog.json`` of the run's QC states, read once per task; a point file missing from
    its ``names`` did not exist when the catalog was made, so its per-file tasks have nothing
    to do."""
    from workstation.qc.partial import read_json

    return read_json(state_root(ctx) / "catalog.json")


def qc_pass1_task(ctx: RunContext, stage, path: str, *upstream) -> dict:
    from workstation.qc.partial import pass1_file

    cat = _catalog(ctx)
    if path not in cat["names"]:
        return {"points": 0, "outputs": []}
    return {**pass1_file(state_root(ctx), path, qc_params(ctx, stage), cat), "peak_rss_mb": peak_rss_mb()}


def qc_surface_task(ctx: RunContext, stage, *upstream) -> dict:
    from workstation.qc.partial import pass1_merge

    return {**pass1_merge(state_root(ctx), qc_params(ctx, stage)), "peak_rss_mb": peak_rss_mb()}


def qc_pass2_task(ctx: RunContext, stage, path: str, *upstream) -> dict:
    from workstation.qc.partial import pass2_file

    cat = _catalog(ctx)
    if path not in cat["names"]:
        return {"outputs": []}
    r = pass2_file(state_root(ctx), path, qc_params(ctx, stage), cat)
    return {**r, "points": 0, "pass2_points": r["points"], "peak_rss_mb": peak_rss_mb()}


def qc_fit_task(ctx: RunContext, stage, ix: int, iy: int, *upstream) -> dict:
    from workstation.qc.partial import fit_block

    return {**fit_block(state_root(ctx), ix, iy, qc_params(ctx, stage)), "peak_rss_mb": peak_rss_mb()}


def _units(ctx: RunContext, points: list, folder: str) -> tuple[list, list, float]:
    """The point files as [(path, state folder, (xmin, ymin, xmax, ymax), upstream task)], the
    blocks of the swath fits and their side (CRS units)."""
    if points:
        chunks = [t.args[2] for t in points]
        units = [(str(ctx.out / folder / f"{c.name}.laz"), f"chunk-{c.name}", c.bounds, t)
                 for c, t in zip(chunks, points)]
        return units, sorted((c.ix, c.iy) for c in chunks), float(chunks[0].size)
    units = [(str(t.path), f"{t.path.stem}-{hashlib.sha1(str(t.path).encode()).hexdigest()[:10]}",
              (t.bounds[0], t.bounds[1], t.bounds[3], t.bounds[4]), None) for t in ctx.tiles]
    b = [u[2] for u in units]
    size = block_side((min(x[0] for x in b), min(x[1] for x in b), max(x[2] for x in b), max(x[3] for x in b)),
                      len(units))
    return units, blocks_over(b, size), size


def qc_plan(ctx: RunContext, plan, points: list, dtm, file_hash: dict, folder: str, task_cls, qc_task) -> list:
    """The QC tasks (see the module doc); ``points`` the point tasks, ``dtm`` the DTM mosaic
    task or None, ``task_cls`` the plan's Task class and ``qc_task`` the merge function."""
    p = plan.params_of("qc")
    units, blocks, size = _units(ctx, points, folder)
    inputs = {} if points else dict(file_hash)
    Task = task_cls
    cat = Task("qc/catalog", "qc", qc_catalog_task, (ctx, plan.qc, [(u[0], u[1]) for u in units], blocks, size),
               [t.id for t in points], task_key("qc-catalog", [p, blocks, size], list(inputs.values()),
                                                [t.key for t in points]), p, barrier=True, inputs=inputs)
    pass1 = [Task(f"qc/pass1/{name}", "qc", qc_pass1_task, (ctx, plan.qc, path), [cat.id],
                  task_key("qc-pass1", p, (), [cat.key, path]), p) for path, name, _, _ in units]
    surf = Task("qc/surface", "qc", qc_surface_task, (ctx, plan.qc), [t.id for t in pass1],
                task_key("qc-surface", p, (), [t.key for t in pass1]), p, barrier=True)
    pass2 = [Task(f"qc/pass2/{name}", "qc", qc_pass2_task, (ctx, plan.qc, path), [surf.id],
                  task_key("qc-pass2", p, (), [surf.key, path]), p) for path, name, _, _ in units]
    fits = []
    for ix, iy in blocks:  # the files within a block of the block: those its cells' windows reach
        near = (ix * size - size, iy * size - size, ix * size + 2 * size, iy * size + 2 * size)
        deps = [t for t, u in zip(pass2, units) if boxes_meet(u[2], near)]
        fits.append(Task(f"qc/fit/{ix}_{iy}", "qc", qc_fit_task, (ctx, plan.qc, ix, iy), [t.id for t in deps],
                         task_key("qc-fit", [p, ix, iy], (), [t.key for t in deps]), p, barrier=True))
    last = [surf, *pass2, *fits, *([dtm] if dtm else [])]
    merge = Task("qc/delivery", "qc", qc_task, (ctx, plan.qc, dtm.args[3] if dtm else None, str(ctx.out / "qc")),
                 [t.id for t in last], task_key("qc", p, (), [t.key for t in last]), p, barrier=True)
    return [cat, *pass1, surf, *pass2, *fits, merge]
