"""Benchmark of the LiDAR simulator; prints one JSON line per result.

Figures (ALS over the default mixed scene, 300 m x 300 m, ~240k triangles):

* ``open3d_raycast``: the anchor, Open3D ``RaycastingScene.cast_rays`` on the same scene with
  ALS-like rays (wall and CPU rate), measured in the same run so ratios survive a busy machine;
* ``als_single_return``: pulses per second, one ray per pulse (goal >= 1,000,000 /s on 2 cores);
* ``als_5_subrays``: pulses per second with 5 sub-rays per pulse and multiple returns
  (goal >= 250,000 /s);
* ``memory_10M``: peak resident memory of ``ws simulate`` writing a ~10-million-point LAZ, in
  a subprocess (``resource.getrusage(RUSAGE_CHILDREN).ru_maxrss``; goal < 3 GB).

Usage: ``PYTHONPATH=. python scripts/bench_simulate.py [--skip-memory]``
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np


def emit(**kw):
    print(json.dumps(kw), flush=True)


def anchor(scene, n=2_000_000, seed=0):
    from workstation.interop.open3d_raycast import RaycastScene

    rng = np.random.default_rng(seed)
    rc = RaycastScene(scene.vertices, scene.faces)
    rays = np.empty((n, 6), np.float32)
    rays[:, 0] = rng.uniform(-150, 150, n)
    rays[:, 1] = rng.uniform(-150, 150, n)
    rays[:, 2] = 620.0
    a = rng.uniform(-np.radians(20), np.radians(20), n)
    rays[:, 3] = np.sin(a)
    rays[:, 4] = 0.0
    rays[:, 5] = -np.cos(a)
    rc.cast_rays(rays[:10000])
    w, c = time.perf_counter(), time.process_time()
    rc.cast_rays(rays)
    return n / (time.perf_counter() - w), n / (time.process_time() - c)


def run_sim(scene, subrays, prf, seed=0):
    from workstation.lidar.survey import count_pulses, default_survey, run_survey, survey_trajectory

    cfg = default_survey("als")
    cfg = replace(cfg, sensor=replace(cfg.sensor, subrays=subrays), scanner=replace(cfg.scanner, prf=prf))
    traj = survey_trajectory(scene, cfg, seed)
    w, c = time.perf_counter(), time.process_time()
    res = run_survey(scene, cfg, seed, trajectory=traj)
    wall, cpu = time.perf_counter() - w, time.process_time() - c
    n = count_pulses(traj, cfg.scanner)
    return n, res.cloud.n, wall, cpu, res.stats["multiple_return_share"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--skip-memory", action="store_true")
    args = ap.parse_args()
    from workstation.lidar.scene import build_scene

    cores = len(os.sched_getaffinity(0))
    load = os.getloadavg()[0]
    scene = build_scene("mixed", 0)
    ray_wall, ray_cpu = anchor(scene)
    emit(bench="open3d_raycast", rays_per_s_wall=round(ray_wall), rays_per_s_cpu=round(ray_cpu), cores=cores,
         load_avg_1min=load, triangles=scene.n_faces)
    for name, subrays, prf, goal in (("als_single_return", 1, 600_000, 1_000_000), ("als_5_subrays", 5, 300_000, 250_000)):
        n, pts, wall, cpu, multi = run_sim(scene, subrays, prf)
        ray_wall2, ray_cpu2 = anchor(scene, seed=1)
        emit(bench=name, pulses=n, points=pts, seconds_wall=round(wall, 2), seconds_cpu=round(cpu, 2),
             pulses_per_s_wall=round(n / wall), pulses_per_s_cpu=round(n / cpu),
             open3d_rays_per_s_wall_same_run=round((ray_wall + ray_wall2) / 2),
             open3d_rays_per_s_cpu_same_run=round((ray_cpu + ray_cpu2) / 2),
             ratio_pulses_to_open3d_rays_cpu=round((n / cpu) / ((ray_cpu + ray_cpu2) / 2), 3),
             multiple_return_share=round(multi, 4), goal_pulses_per_s=goal, cores=cores, load_avg_1min=os.getloadavg()[0])
    if not args.skip_memory:
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "big.laz"
            cmd = [sys.executable, "-m", "workstation.cli.main", "simulate", "als", "-o", str(out), "--subrays", "1",
                   "--prf", "1500000", "--json"]
            w = time.perf_counter()
            proc = subprocess.run(cmd, capture_output=True, text=True, env={**os.environ, "WS_PROGRESS": "0"})
            wall = time.perf_counter() - w
            if proc.returncode != 0:
                emit(bench="memory_10M", error=proc.stderr[-2000:])
                return
            info = json.loads(proc.stdout)
            ru = resource.getrusage(resource.RUSAGE_CHILDREN)
            emit(bench="memory_10M", points=info["point_count"], pulses=info["pulses"], peak_rss_gb=round(ru.ru_maxrss / 1024 ** 2, 3),
                 seconds_wall=round(wall, 1), child_cpu_s=round(ru.ru_utime + ru.ru_stime, 1), goal_gb=3.0,
                 command="ws simulate als -o big.laz --subrays 1 --prf 1500000")


if __name__ == "__main__":
    main()
