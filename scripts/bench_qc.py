"""`ws qc` benchmarks; one JSON line per result on stdout.

  python scripts/bench_qc.py real   [--data DIR]            ws qc on bcts_1 and bcts_2 (three flight lines
                                                          each): seconds, ANPD, coverage, voids, swath pairs
  python scripts/bench_qc.py swath  [--bias 0.10] [--seeds 3]  simulated ALS flights (ws simulate als, two
                                                          lines) with and without line 2 raised by --bias metres
                                                          (--line-bias), default errors and GNSS noise off:
                                                          RMSDz of the pair against the injected offset
  python scripts/bench_qc.py scale  TILES... [--max-points N]   ws qc over a catalog (e.g. /work/bench/c200/tiles,
                                                          made by bench_project.py catalog): seconds, points/s,
                                                          peak memory
  python scripts/bench_qc.py project TILES... [--max-points N] [--workers 2] [--out DIR] [--no-single]
                                                          ws run with [stages.qc] alone over the tiles (QC per
                                                          file, swath fits per block, one merge) against ws qc
                                                          over the same tiles (the single-task QC): wall and CPU
                                                          seconds, peak memory per worker and per QC task kind,
                                                          qc.json fields that differ beyond 1e-9 relative

DIR for the data defaults to ../shared/data (or $WS_SHARED_DATA).
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
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
WS = str(Path(sys.executable).with_name("ws"))


def emit(d):
    print(json.dumps(d), flush=True)


def data_dir(arg) -> Path:
    return Path(arg or os.environ.get("WS_SHARED_DATA") or REPO.parent / "shared" / "data")


def ws_qc(inputs, out: Path, *extra) -> tuple[dict, float, float]:
    """Run `ws qc` as its own process: (the JSON document, seconds, peak RSS of the child in MB)."""
    t0 = time.perf_counter()
    r = subprocess.run([WS, "-q", "qc", *map(str, inputs), "-o", str(out), "--json", "--overwrite", *extra],
                       capture_output=True, text=True)
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        raise SystemExit(f"ws qc failed ({r.returncode}): {r.stderr[-2000:]}")
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return json.loads(r.stdout), dt, peak


def _brief(doc: dict) -> dict:
    return {"points": doc["points"], "anpd": doc["anpd"], "anps": doc["anps"], "coverage": doc["coverage"],
            "voids": doc["voids"], "swaths": doc["swaths"], "findings": len(doc["findings"]),
            "verdict": doc["verdict"]["pass"], "spec": doc["verdict"]["spec"]}


def real(args):
    d = data_dir(args.data) / "lidar"
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("bcts_1.laz", "bcts_2.laz"):
            doc, dt, peak = ws_qc([d / name], Path(tmp) / name)
            emit({"bench": "qc_real", "file": name, "seconds": round(dt, 2), "peak_mb": round(peak), **_brief(doc)})


def swath(args):
    """Each seed flown with and without line 2 raised, with the default errors and with the GNSS
    noise off (each line then carries no navigation offset of its own): RMSDz of each pair
    against the injected offset."""
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for seed in range(args.seeds):
            for gnss in ("default", "off"):
                for bias in (0.0, args.bias):
                    laz = tmp / f"flight_{seed}_{gnss}_{bias:g}.laz"
                    cmd = [WS, "-q", "simulate", "als", "-o", str(laz), "--scene", args.scene, "--seed", str(seed),
                           "--lines", "2", "--overwrite"]
                    cmd += ["--gnss-noise", "0,0,0"] if gnss == "off" else []
                    cmd += ["--line-bias", f"2:0,0,{bias}"] if bias else []
                    subprocess.run(cmd, check=True, capture_output=True)
                    doc, dt, _ = ws_qc([laz], tmp / f"qc_{seed}_{gnss}_{bias:g}")
                    for p in doc["swaths"]:
                        injected = bias if 2 in (p["a"], p["b"]) else 0.0
                        emit({"bench": "qc_swath", "seed": seed, "gnss_noise": gnss, "injected_m": injected,
                              "a": p["a"], "b": p["b"], "rmsdz": round(p["rmsdz"], 4), "mean_dz": round(p["mean_dz"], 4),
                              "cells": p["cells"], "error_m": round(abs(p["rmsdz"] - injected), 4),
                              "seconds": round(dt, 2)})


def scale(args):
    tiles = sorted(Path(t) for t in args.tiles)
    if args.max_points:
        from workstation.io.catalog import read_tile_info

        keep, n = [], 0
        for t in tiles:
            if n >= args.max_points:
                break
            keep.append(t)
            n += read_tile_info(t).point_count
        tiles = keep
    with tempfile.TemporaryDirectory() as tmp:
        doc, dt, peak = ws_qc(tiles, Path(tmp) / "qc")
        emit({"bench": "qc_scale", "files": len(tiles), "seconds": round(dt, 1),
              "points_per_s": round(doc["points"] / dt), "peak_mb": round(peak), **_brief(doc) | {"swaths": len(doc["swaths"])}})


def _select(tiles, max_points: int) -> list[Path]:
    tiles = sorted(Path(t).resolve() for t in tiles)
    if not max_points:
        return tiles
    from workstation.io.catalog import read_tile_info

    keep, n = [], 0
    for t in tiles:
        if n >= max_points:
            break
        keep.append(t)
        n += read_tile_info(t).point_count
    return keep


def _differences(a, b, path="", rel=1e-9) -> list[str]:
    """Fields of two JSON documents that differ (numbers beyond ``rel`` relative)."""
    import math

    if isinstance(a, dict) and isinstance(b, dict):
        out = [f"{path}/{k}" for k in sorted(set(a) ^ set(b))]
        return out + [d for k in sorted(set(a) & set(b)) for d in _differences(a[k], b[k], f"{path}/{k}", rel)]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [path]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in _differences(x, y, f"{path}[{i}]", rel)]
    if isinstance(a, float) and isinstance(b, float):
        ok = a == b or (math.isnan(a) and math.isnan(b)) or abs(a - b) <= rel * max(abs(a), abs(b))
        return [] if ok else [path]
    return [] if a == b else [path]


def project(args):
    """ws qc (one process: the single-task QC) then ws run [stages.qc] on the same tiles."""
    tiles = _select(args.tiles, args.max_points)
    work = Path(args.out or tempfile.mkdtemp(prefix="qcproj"))
    (work / "tiles").mkdir(parents=True, exist_ok=True)
    for t in tiles:
        link = work / "tiles" / t.name
        if not link.exists():
            link.symlink_to(t)
    (work / "project.toml").write_text('[inputs]\nclouds = ["tiles/*.laz"]\n[chunks]\nsize = 250.0\nbuffer = 30.0\n'
                                       '[stages.qc]\nspec = "usgs-ql2"\n')
    cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if not args.no_single:
        doc, dt, peak = ws_qc(tiles, work / "single")  # the resolved paths, as the project lists them
        cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        emit({"bench": "qc_single_task", "files": len(tiles), "points": doc["points"], "wall_s": round(dt, 1),
              "cpu_s": round(cpu1.ru_utime + cpu1.ru_stime - cpu0.ru_utime - cpu0.ru_stime, 1), "peak_mb": round(peak)})
    cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([WS, "-q", "run", str(work / "project.toml"), "--out", str(work / "out"), "--json",
                        "--workers", str(args.workers)], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    cpu2 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise SystemExit(f"ws run failed ({r.returncode}): {r.stderr[-2000:]}")
    tasks = json.loads((work / "out" / "run.json").read_text())["tasks"]
    kinds: dict = {}
    for tid, rec in tasks.items():
        k = tid.split("/")[1] if tid.count("/") >= 1 else tid
        e = kinds.setdefault(k, {"tasks": 0, "task_s": 0.0, "task_cpu_s": 0.0, "max_task_s": 0.0, "peak_rss_mb": 0.0})
        e["tasks"] += 1
        e["task_s"] = round(e["task_s"] + rec.get("seconds", 0.0), 1)
        e["task_cpu_s"] = round(e["task_cpu_s"] + rec.get("cpu_s", 0.0), 1)
        e["max_task_s"] = max(e["max_task_s"], rec.get("seconds", 0.0))
        e["peak_rss_mb"] = max(e["peak_rss_mb"], rec.get("peak_rss_mb", 0.0))
    a = json.loads((work / "out" / "qc" / "qc.json").read_text())
    b = a if args.no_single else json.loads((work / "single" / "qc.json").read_text())
    emit({"bench": "qc_per_chunk", "files": len(tiles), "workers": args.workers, "wall_s": round(wall, 1),
          "cpu_s_incl_workers": round(cpu2.ru_utime + cpu2.ru_stime - cpu1.ru_utime - cpu1.ru_stime, 1),
          "peak_rss_per_worker_mb": max(e["peak_rss_mb"] for e in kinds.values()), "by_task": kinds,
          "fields_beyond_1e-9": [d for d in _differences(a, b) if d != "/seconds"],
          "fields_not_bit_equal": len([d for d in _differences(a, b, rel=0) if d != "/seconds"]),
          "state_mb": round(sum(f.stat().st_size for f in (work / "out" / ".ws-cache" / "qc").rglob("*")
                                if f.is_file()) / 2**20, 1)})


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("real")
    r.add_argument("--data")
    s = sub.add_parser("swath")
    s.add_argument("--bias", type=float, default=0.10)
    s.add_argument("--scene", default="demo_small")
    s.add_argument("--seeds", type=int, default=3)
    c = sub.add_parser("scale")
    c.add_argument("tiles", nargs="+")
    c.add_argument("--max-points", type=int, default=0)
    j = sub.add_parser("project")
    j.add_argument("tiles", nargs="+")
    j.add_argument("--max-points", type=int, default=0)
    j.add_argument("--workers", type=int, default=2)
    j.add_argument("--out")
    j.add_argument("--no-single", action="store_true", help="leave out ws qc (the single-task QC)")
    args = ap.parse_args()
    sys.path.insert(0, str(REPO))
    {"real": real, "swath": swath, "scale": scale, "project": project}[args.cmd](args)


if __name__ == "__main__":
    main()
