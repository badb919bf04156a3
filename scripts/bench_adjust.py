"""Benchmarks of `ws strip-adjust` (boresight calibration and strip adjustment).

Subcommands (each prints one JSON line per result on stdout):

* ``sim``   - simulated ALS calibration block (mixed scene, 4 lines, 70 % overlap) with an
  injected boresight error and range offset; the rigorous estimates against the truth and
  the swath RMSDz before/after. ``--errors realistic`` keeps the simulator's other default
  errors (GNSS/IMU noise, lever-arm error, scan-angle scale, range walk) on.
* ``real``  - bcts_1 and bcts_2 (../shared/data/lidar, three flight lines each, no
  trajectory): strip-wise shifts and RMSDz per strip pair before/after, jointly and per tile.
* ``speed`` - about 10 M points in the overlaps (the same block at a higher pulse rate): time
  and peak memory of the estimation, of applying it, and of the whole command.

Usage::

    .venv/bin/python scripts/bench_adjust.py sim [--errors none|realistic] [--estimate LIST] [--work DIR]
    .venv/bin/python scripts/bench_adjust.py real [--data ../shared/data]
    .venv/bin/python scripts/bench_adjust.py speed [--prf 850000] [--work DIR]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
WS = str(REPO / ".venv" / "bin" / "ws")
INJECTED = (0.05, -0.03, 0.08)  # boresight error, degrees
RANGE_OFFSET = 0.05  # metres
RANGE_NOISE = 0.02
LEVER = "0.1,0,0.25"  # the ALS preset's nominal lever arm


def _emit(obj: dict) -> None:
    print(json.dumps(obj, default=float), flush=True)


def _simulate(work: Path, errors: str, prf: float | None = None) -> Path:
    """The calibration block (cached in ``work``)."""
    name = f"block_{errors}{'' if prf is None else f'_{int(prf)}'}.laz"
    out = work / name
    if out.exists():
        return out
    cmd = [WS, "-q", "simulate", "als", "-o", str(out), "--lines", "4", "--overlap", "0.7", "--range-noise",
           str(RANGE_NOISE), "--boresight-error", ",".join(map(str, INJECTED)), "--range-offset", str(RANGE_OFFSET)]
    if errors == "none":
        cmd.insert(cmd.index("--range-noise"), "--no-errors")
    if prf:
        cmd += ["--prf", str(prf)]
    subprocess.run(cmd, check=True)
    return out


def _adjust(inputs, out: Path, *extra) -> tuple[dict, float]:
    t0 = time.perf_counter()
    p = subprocess.run([WS, "-q", "strip-adjust", *map(str, inputs), "-o", str(out), "--overwrite", "--json", *extra],
                       check=True, capture_output=True, text=True)
    return json.loads(p.stdout), time.perf_counter() - t0


def bench_sim(args) -> None:
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    laz = _simulate(work, args.errors)
    rep, dt = _adjust([laz], work / f"adjusted_{args.errors}", "--trajectory", str(laz.with_suffix(".trajectory.csv")),
                      "--lever-arm", LEVER, "--estimate", args.estimate)
    b = rep["boresight_deg"]
    err = [None if v is None else v - t for v, t in zip(b, INJECTED)]
    _emit({"bench": "adjust_sim", "errors": args.errors, "estimate": args.estimate, "boresight_deg": b, "boresight_sigma_deg": rep["boresight_sigma_deg"],
           "boresight_error_deg": err, "range_offset_m": rep["range_offset_m"],
           "range_offset_error_m": None if rep["range_offset_m"] is None else rep["range_offset_m"] - RANGE_OFFSET,
           "scan_angle_scale": rep["scan_angle_scale"], "strips": rep["strips"],
           "not_determined": rep["not_determined"], "correspondences": rep["correspondences"],
           "rmsdz_before_m": rep["rmsdz_before_m"], "rmsdz_after_m": rep["rmsdz_after_m"],
           "rmsdz_after_over_noise": rep["rmsdz_after_m"] / RANGE_NOISE, "seconds": dt})


def bench_real(args) -> None:
    data = Path(args.data) / "lidar"
    files = [data / "bcts_1.laz", data / "bcts_2.laz"]
    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    for label, inputs in (("bcts_1+bcts_2", files), ("bcts_1", files[:1]), ("bcts_2", files[1:])):
        try:
            rep, dt = _adjust(inputs, work / f"real_{label.replace('+', '_')}")
        except subprocess.CalledProcessError as e:
            _emit({"bench": "adjust_real", "inputs": label, "error": e.stderr.strip().splitlines()[0]})
            continue
        _emit({"bench": "adjust_real", "inputs": label, "strips": rep["strips"], "not_determined": rep["not_determined"],
               "noise_m": rep["noise_m"], "correspondences": rep["correspondences"],
               "rmsdz_before_m": rep["rmsdz_before_m"], "rmsdz_after_m": rep["rmsdz_after_m"],
               "pairs": [{k: p[k] for k in ("a", "b", "rmsdz_before_m", "rmsdz_after_m", "cells_before")}
                         for p in rep["pairs"]],
               "worse_pairs": [(p["a"], p["b"]) for p in rep["pairs"]
                               if p["rmsdz_after_m"] is not None and p["rmsdz_after_m"] > p["rmsdz_before_m"]],
               "seconds": dt})


def bench_speed(args) -> None:
    from workstation.adjust import AdjustParams, apply_corrections, estimate_corrections, read_trajectory_csv
    from workstation.io import read_cloud

    work = Path(args.work)
    work.mkdir(parents=True, exist_ok=True)
    laz = _simulate(work, "none", args.prf)
    cloud = read_cloud(laz)
    nav = read_trajectory_csv(laz.with_suffix(".trajectory.csv"))
    attrs = dict(cloud.attrs)
    sid = attrs["point_source_id"]
    # points in the overlap: their 2 m cell holds another strip too
    q = np.floor(cloud.xyz[:, :2] / 2.0).astype(np.int64)
    q -= q.min(axis=0)
    cell = q[:, 0] * (int(q[:, 1].max()) + 1) + q[:, 1]
    pairs = np.unique(cell * 65536 + sid)
    strips_per_cell = np.bincount(np.searchsorted(np.unique(cell), pairs // 65536))
    overlap = int(np.sum((strips_per_cell >= 2)[np.searchsorted(np.unique(cell), cell)]))
    for est in (("strip-shift",), ("boresight", "range")):
        params = AdjustParams(estimate=est, lever_arm=tuple(map(float, LEVER.split(","))))
        t0 = time.perf_counter()
        res = estimate_corrections(cloud.xyz, attrs, params, nav)
        t1 = time.perf_counter()
        apply_corrections(cloud.xyz, attrs, res, params, nav)
        t2 = time.perf_counter()
        _emit({"bench": "adjust_speed", "estimate": list(est), "points": cloud.n, "overlap_points": overlap,
               "correspondences": res.correspondences, "estimate_s": t1 - t0, "apply_s": t2 - t1,
               "peak_rss_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024})
    rep, dt = _adjust([laz], work / "speed_out", "--trajectory", str(laz.with_suffix(".trajectory.csv")),
                      "--lever-arm", LEVER)
    _emit({"bench": "adjust_speed_cli", "points": cloud.n, "seconds": dt, "rmsdz_before_m": rep["rmsdz_before_m"],
           "rmsdz_after_m": rep["rmsdz_after_m"]})


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sim")
    s.add_argument("--errors", choices=["none", "realistic"], default="none")
    s.add_argument("--estimate", default="boresight,range", help="as ws strip-adjust --estimate")
    s.add_argument("--work", default="build/bench_adjust")
    r = sub.add_parser("real")
    r.add_argument("--data", default=str(REPO.parent / "shared" / "data"))
    r.add_argument("--work", default="build/bench_adjust")
    p = sub.add_parser("speed")
    p.add_argument("--prf", type=float, default=850_000.0)
    p.add_argument("--work", default="build/bench_adjust")
    args = ap.parse_args(argv)
    {"sim": bench_sim, "real": bench_real, "speed": bench_speed}[args.cmd](args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
