"""The scan stage of a project run: every scan registered onto one reference, then merged.

One task per scan calls what ``ws register`` calls (:func:`workstation.registration.register.register`:
global registration verified and refined by ICP, with the same :class:`RegisterParams`) and
writes the scan moved into the reference's frame as ``OUT/register/<scan>.laz`` with its pose
beside the run's cache. The reference is the first scan in name order, the scan named by
``reference``, or the photos' dense cloud (``to = "dense"``); the reference scan keeps its
coordinates (identity pose). A last task, run when every scan task has ended, writes
``OUT/register/poses.json`` (the 4x4 pose, fitness and inlier RMSE of every registered scan,
and the scans that failed) and the merged cloud ``OUT/register/merged.laz`` of the scans that
registered. A scan that cannot be read or registered fails alone, naming its file and the
reason; the others finish.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, StageError, WorkstationError

from .manifest import task_key
from .tasks import elapsed, peak_rss_mb

RESERVED = ("merge", "merged", "poses")  # the names of the stage's own outputs


def scan_names(scans: tuple, project_path: Path) -> dict[str, Path]:
    """Output name (the file's stem) -> scan; two scans of one stem, or a stem the stage's own
    outputs use, are refused."""
    names: dict[str, Path] = {}
    for p in scans:
        stem = p.stem
        if stem in names:
            raise InvalidInputError(f"two scans are named {stem}: {names[stem]} and {p}",
                                    "rename one; each scan's output is OUT/register/<name>.laz",
                                    path=project_path, field="inputs.scans")
        if stem in RESERVED:
            raise InvalidInputError(f"a scan named {p.name}: OUT/register/{stem}.* is the stage's own output",
                                    "rename the scan", path=project_path, field="inputs.scans")
        names[stem] = p
    return names


def reference_of(names: dict, stage, project_path: Path) -> str | None:
    """The name of the reference scan (None when the reference is the dense cloud)."""
    if stage.to == "dense":
        return None
    if stage.reference is None:
        return next(iter(names))
    for name, p in names.items():
        if stage.reference in (name, p.name):
            return name
    raise InvalidInputError(f"reference {stage.reference!r} is none of the scans",
                            "use one of " + ", ".join(names), path=project_path, field="stages.register.reference")


def _failed(scan: str, e: Exception) -> StageError:
    msg = e.message if isinstance(e, WorkstationError) else f"{type(e).__name__}: {e}"
    hint = e.hint if isinstance(e, WorkstationError) else "check that the file is a readable point cloud"
    return StageError("register", msg if scan in msg else f"{scan}: {msg}", hint)


def register_task(out: str, name: str, scan: str, target: str | None, stage, *upstream) -> dict:
    """Register ``scan`` onto ``target`` (None: it is the reference) and write it moved as
    ``OUT/register/<name>.laz`` and its pose as ``OUT/.ws-cache/register/<name>.json``."""
    from workstation.io import atomic_path, read_cloud, write_cloud
    from workstation.registration.merge import transform_cloud
    from workstation.registration.register import register

    t0 = time.perf_counter()
    try:
        src = read_cloud(scan)
        pose = {"transform": np.eye(4).tolist(), "fitness": 1.0, "inlier_rmse": 0.0, "converged": True}
        moved = src
        if target is not None:
            tgt = read_cloud(target)
            result = register(src, tgt, stage.params)
            pose = {"transform": np.asarray(result.transform).tolist(), "fitness": float(result.fitness),
                    "inlier_rmse": float(result.inlier_rmse), "converged": bool(result.converged)}
            moved = transform_cloud(src, result.transform).with_crs(tgt.crs or src.crs)
    except Exception as e:  # noqa: BLE001 - any reader's or solver's error, reported with the scan's file
        raise _failed(scan, e) from None
    laz = Path(out) / "register" / f"{name}.laz"
    laz.parent.mkdir(parents=True, exist_ok=True)
    write_cloud(moved, laz, overwrite=True)
    from .runner import CACHE

    side = Path(out) / CACHE / "register" / f"{name}.json"
    side.parent.mkdir(parents=True, exist_ok=True)
    doc = {"name": name, "scan": scan, "reference": target is None, "target": target, "points": int(src.n),
           "output": str(laz), **pose}
    with atomic_path(side, overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(doc, indent=1))
    return {"points": int(src.n), "fitness": pose["fitness"], "inlier_rmse": pose["inlier_rmse"],
            "seconds": elapsed(t0), "peak_rss_mb": peak_rss_mb(), "outputs": [str(laz), str(side)]}


def merge_task(out: str, stage, names: list, poses: list, *upstream) -> dict:
    """``OUT/register/poses.json`` and ``merged.laz`` from the pose files of the scans that
    registered (``poses``, listed once every scan task has ended), in ``names`` order."""
    from workstation.io import atomic_path, read_cloud, write_cloud
    from workstation.registration.merge import merge_clouds

    t0 = time.perf_counter()
    docs = {d["name"]: d for d in (json.loads(Path(p).read_text()) for p in poses)}
    done = [n for n in names if n in docs]
    if not done:
        raise StageError("register", "no scan was registered", "check the scan tasks' errors")
    folder = Path(out) / "register"
    merged = merge_clouds([read_cloud(docs[n]["output"]) for n in done], None, stage.merge)
    write_cloud(merged, folder / "merged.laz", overwrite=True)
    keep = ("scan", "reference", "target", "transform", "fitness", "inlier_rmse", "converged", "points")
    doc = {"scans": {n: {k: docs[n][k] for k in keep} for n in done},
           "failed": [n for n in names if n not in docs]}
    with atomic_path(folder / "poses.json", overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(doc, indent=1))
    return {"points": int(merged.n), "scans": len(done), "failed_scans": doc["failed"], "seconds": elapsed(t0),
            "peak_rss_mb": peak_rss_mb(), "outputs": [str(folder / "merged.laz"), str(folder / "poses.json")]}


def scan_tasks(ctx, plan, manifest, photo_tasks: list) -> list:
    """A register task per scan (onto the reference scan, or the dense cloud after the dense
    task), then the merge task after them all."""
    from .plan import Task

    if plan.register is None:
        return []
    names = scan_names(ctx.scans, ctx.project_folder)  # checked by parse_stages, naming the project file
    ref = reference_of(names, plan.register, ctx.project_folder)
    p = plan.params_of("register")
    own_p = {k: v for k, v in p.items() if k != "merge"}  # a merge setting re-runs the merge alone
    out = str(ctx.out)
    deps, upstream, target = [], [], None
    if ref is None:
        dense = next(t for t in photo_tasks if t.phase == "dense")
        deps, upstream, target = [dense.id], [dense.key], str(ctx.out / "dense" / "dense.laz")
    else:
        target = str(names[ref])
    tasks = []
    for name, scan in names.items():
        h = manifest.file_hash(scan)
        own = [h] if name == ref else [h, manifest.file_hash(names[ref])] if ref else [h]
        tasks.append(Task(f"register/{name}", "register", register_task,
                          (out, name, str(scan), None if name == ref else target, plan.register), list(deps),
                          task_key("register", {**own_p, "reference": name == ref}, own, upstream), own_p,
                          inputs={str(scan): h}))
    tasks.append(Task("register/merge", "register", merge_task, (out, plan.register, list(names), []),
                      [t.id for t in tasks], task_key("merge", p["merge"], (), [t.key for t in tasks]), p["merge"],
                      barrier=True))
    return tasks
