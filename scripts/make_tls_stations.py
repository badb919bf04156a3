"""Simulated multi-station TLS survey for ``bench_register.py --tls-laz`` (needs the LiDAR simulator).

  PYTHONPATH=. python scripts/make_tls_stations.py -o /tmp/tls6.laz [--stations 6] [--step-deg 0.4]

The small demo scene (seed 0), the default TLS survey with ``--stations`` stations along the
road (about 9 m apart) and a horizontal/vertical step of ``--step-deg``; the stations are told
apart by ``point_source_id``. The registration figures of docs/benchmarks.md used 6 stations
and 0.4 degrees (700 006 points) with the simulator of branch ``sim`` at commit 92cbcda.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-o", "--output", type=Path, required=True)
    ap.add_argument("--stations", type=int, default=6)
    ap.add_argument("--step-deg", type=float, default=0.4)
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args()
    try:
        from workstation.lidar.scene import build_scene
        from workstation.lidar.survey import default_stations, default_survey, run_survey
    except ImportError:
        sys.exit("the LiDAR simulator (workstation.lidar) is not installed in this checkout")
    from workstation.io import write_cloud

    scene = build_scene("demo_small", a.seed)
    cfg = default_survey("tls")
    cfg = replace(cfg, scanner=replace(cfg.scanner, h_step_deg=a.step_deg, v_step_deg=a.step_deg),
                  stations=default_stations(scene, a.stations))
    res = run_survey(scene, cfg, seed=a.seed)
    write_cloud(res.cloud, a.output, overwrite=True)
    print(f"{res.cloud.n} points, {a.stations} stations -> {a.output}")


if __name__ == "__main__":
    main()
