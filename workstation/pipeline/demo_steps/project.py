"""Demo step of ``ws run``: the simulated ALS flight cut into four tiles and run as a project."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.log import get_logger

log = get_logger(__name__)

PROJECT = """\
[project]
name = "demo survey"

[inputs]
clouds = ["tiles/*.laz"]

[chunks]
size = 50.0
buffer = 30.0

[stages.noise]
[stages.ground]
method = "smrf"
[stages.dem]
kinds = ["dtm", "dsm"]
resolution = 1.0
[stages.density]
cell = 5.0
[stages.hillshade]
[stages.contours]
interval = 1.0

[dask]
workers = 2
"""


def step(ctx) -> dict:
    from workstation.io import read_cloud, write_cloud
    from workstation.pipeline.runner import run_project

    src = ctx.products.get("als_laz")
    if src is None:
        log.warning("project step: no simulated ALS cloud; skipped")
        return {}
    folder = ctx.outdir / "project"
    (folder / "tiles").mkdir(parents=True, exist_ok=True)
    cloud = read_cloud(src)
    xy = cloud.xyz[:, :2]
    mid = np.median(xy, axis=0)
    for name, m in (("sw", (xy[:, 0] < mid[0]) & (xy[:, 1] < mid[1])), ("se", (xy[:, 0] >= mid[0]) & (xy[:, 1] < mid[1])),
                    ("nw", (xy[:, 0] < mid[0]) & (xy[:, 1] >= mid[1])), ("ne", (xy[:, 0] >= mid[0]) & (xy[:, 1] >= mid[1]))):
        write_cloud(cloud[m], folder / "tiles" / f"{name}.laz", overwrite=True)
    (folder / "project.toml").write_text(PROJECT)
    result = run_project(folder / "project.toml")
    again = run_project(folder / "project.toml")  # nothing changed: every task is skipped
    summary = {"status": result.status, "chunks": result.summary["chunks"]["count"],
               "points": result.summary["catalog"]["points"], "seconds": result.summary["seconds"],
               "rerun_tasks": sum(p["run"] for p in again.summary["phases"].values()),
               "rerun_seconds": again.summary["seconds"]}
    (folder / "demo_summary.json").write_text(json.dumps(summary, indent=2))
    ctx.summaries["project"] = summary
    return {"project_toml": folder / "project.toml", "project_dtm": folder / "dem" / "dtm.tif",
            "project_run_json": folder / "run.json"}
