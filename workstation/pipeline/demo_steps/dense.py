"""Demo step of dense reconstruction: a tiny synthetic rig (5 views of a box in front of a wall,
true cameras) densified on the CPU (semi-global matching, the default method) and fused by COLMAP's fusion."""

from __future__ import annotations

import json


def step(ctx) -> dict:
    from workstation.io import atomic_path, write_cloud
    from workstation.photogrammetry.dense import DenseParams, evaluate, run_dense
    from workstation.photogrammetry.rigs import box_wall_rig, box_wall_scene

    work = ctx.outdir / "dense_rig"
    box_wall_rig(work)
    cloud, summary = run_dense(work, params=DenseParams(device="cpu", depth_range=(5.0, 20.0), num_sources=4), overwrite=True)
    V, F, _ = box_wall_scene()
    ev = evaluate(cloud.xyz, V, F, 16.0, cloud.xyz[:1])
    out = ctx.outdir / "dense_box.ply"
    write_cloud(cloud, out, overwrite=True)
    rep = ctx.outdir / "dense_summary.json"
    with atomic_path(rep, overwrite=True) as tmp:
        tmp.write_text(json.dumps({**summary, "accuracy_median_m": ev["accuracy_median"]}, indent=2))
    return {"dense_ply": out, "dense_summary": rep}
