"""Demo step of the LiDAR simulator: an ALS flight (two overlapping lines) and three TLS stations
over the small mixed demo scene, plus the scene itself (labelled mesh as .npz)."""

from __future__ import annotations

from dataclasses import replace

from workstation.io import write_cloud
from workstation.lidar.scene import build_scene, save_scene, scene_summary
from workstation.lidar.simulate import write_trajectory_csv
from workstation.lidar.survey import default_survey, run_survey


def step(ctx) -> dict:
    scene = build_scene("demo_small", ctx.seed)
    mesh_path = save_scene(scene, ctx.outdir / "scene_mesh.npz", overwrite=True)
    als_cfg = default_survey("als")
    als_cfg = replace(als_cfg, flight=replace(als_cfg.flight, altitude=200.0),
                      scanner=replace(als_cfg.scanner, prf=150_000.0))
    als = run_survey(scene, als_cfg, seed=ctx.seed)
    als_path = write_cloud(als.cloud, ctx.outdir / "als.laz", overwrite=True)
    traj_path = write_trajectory_csv(als, ctx.outdir / "als_trajectory.csv", overwrite=True)
    tls_cfg = default_survey("tls")
    tls_cfg = replace(tls_cfg, scanner=replace(tls_cfg.scanner, h_step_deg=0.4, v_step_deg=0.4))
    tls = run_survey(scene, tls_cfg, seed=ctx.seed)
    tls_path = write_cloud(tls.cloud, ctx.outdir / "tls.laz", overwrite=True)
    ctx.summaries["simulate"] = {
        "scene": scene_summary(scene),
        "als": {k: als.stats[k] for k in ("pulses", "returns", "seconds", "multiple_return_share")},
        "tls": {k: tls.stats[k] for k in ("pulses", "returns", "seconds")},
    }
    return {"als_laz": als_path, "als_trajectory": traj_path, "tls_laz": tls_path, "scene_mesh": mesh_path}
