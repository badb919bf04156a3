"""Project-runner (`ws run`) benchmarks; one JSON line per result on stdout.

  python scripts/bench_project.py catalog  --copies N --out DIR   a catalog of N shifted copies of the real
                                          bcts_1 + bcts_2 pair (1.36 M points each; the header offsets are
                                          moved, the LAZ point data copied as it is)
  python scripts/bench_project.py run      DIR [--workers N] [--stages ground,dem] [--size 250] [--buffer 30]
                                          noise -> ground -> DTM/DSM -> mosaic over DIR/tiles/*.laz: wall time,
                                          points/s, peak memory per worker (from run.json)
  python scripts/bench_project.py rerun    DIR                     a second run of the same project
  python scripts/bench_project.py scaling  DIR [--one-core]        1 worker against 2, and whether outputs agree
  python scripts/bench_project.py external DIR                     `dask scheduler` + two `dask worker`
                                          processes on loopback against a local run: identical outputs?
  python scripts/bench_project.py seams    [--data DIR]            four adjacent tiles cut from bcts_1/bcts_2,
                                          100 m chunks, 30 m buffer: DTM within 5 m of chunk borders against the
                                          whole-area DTM (ws ground + ws dem on the merged file)
  python scripts/bench_project.py overhead --out DIR [--points 10000000]   ws run against ws ground + ws dem on
                                          one file of that many points

DIR for the data defaults to ../shared/data (or $WS_SHARED_DATA).
"""

from __future__ import annotations

import argparse
import glob
import json
import os
import shutil
import struct
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
WS = str(Path(sys.executable).with_name("ws"))
DASK = str(Path(sys.executable).with_name("dask"))
PAIR = ("bcts_1.laz", "bcts_2.laz")


def emit(d):
    print(json.dumps(d), flush=True)


def data_dir(arg) -> Path:
    return Path(arg or os.environ.get("WS_SHARED_DATA") or REPO.parent / "shared" / "data")


def shifted_copy(src: Path, dst: Path, dx: float, dy: float) -> None:
    """Copy a LAS/LAZ file moved by (dx, dy): the header's offsets and bounds change, the
    (compressed) point records are the same bytes."""
    raw = bytearray(src.read_bytes())
    xo, yo = struct.unpack_from("<dd", raw, 155)
    struct.pack_into("<dd", raw, 155, xo + dx, yo + dy)
    maxx, minx, maxy, miny = struct.unpack_from("<dddd", raw, 179)
    struct.pack_into("<dddd", raw, 179, maxx + dx, minx + dx, maxy + dy, miny + dy)
    dst.write_bytes(bytes(raw))


def write_project(folder: Path, stages=("noise", "ground", "dem"), size=250.0, buffer=30.0) -> Path:
    text = f'[inputs]\nclouds = ["tiles/*.laz"]\n[chunks]\nsize = {size}\nbuffer = {buffer}\n'
    if "noise" in stages:
        text += "[stages.noise]\n"
    if "ground" in stages:
        text += '[stages.ground]\nmethod = "smrf"\n'
    if "dem" in stages:
        text += '[stages.dem]\nkinds = ["dtm", "dsm"]\nresolution = 1.0\n'
    p = folder / "project.toml"
    p.write_text(text)
    return p


def bench_catalog(args):
    out = Path(args.out)
    (out / "tiles").mkdir(parents=True, exist_ok=True)
    data = data_dir(args.data) / "lidar"
    side = int(np.ceil(np.sqrt(args.copies)))
    for k in range(args.copies):
        i, j = divmod(k, side)
        for name in PAIR:  # the pair spans 195 m x 543 m: copies every 200 m x 550 m
            shifted_copy(data / name, out / "tiles" / f"{Path(name).stem}_{i:03d}_{j:03d}.laz", 200.0 * i, 550.0 * j)
    write_project(out, tuple(args.stages.split(",")), args.size, args.buffer)
    emit({"bench": "catalog", "copies": args.copies, "files": 2 * args.copies, "points": 1_355_607 * args.copies})


def ws_run(project: Path, out: Path, *extra, prefix=()) -> tuple[dict, float]:
    t = time.perf_counter()
    res = subprocess.run([*prefix, WS, "-q", "run", str(project), "--out", str(out), "--json", *extra],
                         capture_output=True, text=True)
    wall = time.perf_counter() - t
    if res.returncode not in (0, 3):
        sys.exit(f"ws run failed: {res.stderr[-2000:]}")
    return json.loads(res.stdout), wall


def peak_rss(out: Path) -> float:
    tasks = json.loads((out / "run.json").read_text())["tasks"]
    return max((t.get("peak_rss_mb", 0) for t in tasks.values()), default=0.0)


def bench_run(args):
    folder = Path(args.dir)
    out = Path(args.result or folder / f"out_w{args.workers}")
    summary, wall = ws_run(folder / "project.toml", out, "--workers", str(args.workers))
    n = summary["catalog"]["points"]
    emit({"bench": "run", "points": n, "files": summary["catalog"]["files"], "chunks": summary["chunks"]["count"],
          "workers": args.workers, "wall_s": round(wall, 1), "points_per_s": round(n / wall),
          "peak_rss_per_worker_mb": peak_rss(out), "status": summary["status"],
          "phases": {k: v["seconds"] for k, v in summary["phases"].items()}})


def bench_rerun(args):
    folder = Path(args.dir)
    out = Path(args.result or folder / "out_w2")
    first = json.loads((out / "run.json").read_text())["seconds"]
    summary, wall = ws_run(folder / "project.toml", out)
    emit({"bench": "rerun", "first_run_s": first, "rerun_wall_s": round(wall, 2), "ratio": round(wall / first, 4),
          "tasks_run": sum(v["run"] for v in summary["phases"].values())})


def outputs_equal(a: Path, b: Path) -> bool:
    """The same point files and rasters (point arrays and cell values, as read back)."""
    import laspy
    import rasterio

    fa = sorted(p.relative_to(a) for p in a.rglob("*") if p.suffix in (".laz", ".tif") and ".ws-cache" not in str(p))
    fb = sorted(p.relative_to(b) for p in b.rglob("*") if p.suffix in (".laz", ".tif") and ".ws-cache" not in str(p))
    if fa != fb:
        return False
    for rel in fa:
        if rel.suffix == ".laz":
            pa, pb = laspy.read(a / rel).points.array, laspy.read(b / rel).points.array
            if not np.array_equal(pa, pb):
                return False
        else:
            with rasterio.open(a / rel) as x, rasterio.open(b / rel) as y:
                if not np.array_equal(x.read(), y.read(), equal_nan=True):
                    return False
    return True


def bench_scaling(args):
    """2 workers against 1; with --one-core the single worker runs pinned to one core
    (``taskset -c 0``), so it cannot spread its LAZ threads over the second core."""
    folder = Path(args.dir)
    walls = {}
    for w in (1, 2):
        out = folder / f"scale_w{w}"
        shutil.rmtree(out, ignore_errors=True)
        pin = ("taskset", "-c", "0") if (w == 1 and args.one_core) else ()
        _, walls[w] = ws_run(folder / "project.toml", out, "--workers", str(w), prefix=pin)
    emit({"bench": "scaling", "one_worker_pinned_to_one_core": args.one_core, "wall_1_worker_s": round(walls[1], 1),
          "wall_2_workers_s": round(walls[2], 1), "speedup": round(walls[1] / walls[2], 3),
          "identical": outputs_equal(folder / "scale_w1", folder / "scale_w2")})


def bench_external(args):
    import socket

    folder = Path(args.dir)
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    addr = f"tcp://127.0.0.1:{port}"
    procs = [subprocess.Popen([DASK, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
                              stderr=subprocess.DEVNULL)]
    try:
        time.sleep(3)
        for _ in range(2):
            procs.append(subprocess.Popen([DASK, "worker", addr, "--nthreads", "1", "--no-dashboard"],
                                          stderr=subprocess.DEVNULL))
        time.sleep(4)
        out_ext, out_loc = folder / "ext_out", folder / "ext_local"
        for o in (out_ext, out_loc):
            shutil.rmtree(o, ignore_errors=True)
        _, wall_ext = ws_run(folder / "project.toml", out_ext, "--scheduler", addr)
        _, wall_loc = ws_run(folder / "project.toml", out_loc, "--workers", "2")
        emit({"bench": "external", "scheduler": addr, "wall_external_s": round(wall_ext, 1),
              "wall_local_s": round(wall_loc, 1), "identical": outputs_equal(out_ext, out_loc)})
    finally:
        for p in procs[::-1]:
            p.terminate()
            p.wait(timeout=30)


def bench_seams(args):
    """Four adjacent tiles (bcts_1 and bcts_2 each cut in two at their middle x) as a catalog
    with 100 m chunks and a 30 m buffer, against the whole-area DTM of the merged file."""
    import rasterio

    from workstation.core.cloud import concatenate
    from workstation.io import read_cloud, write_cloud

    data = data_dir(args.data) / "lidar"
    work = Path(args.out or "/tmp/ws_bench_seams")
    shutil.rmtree(work, ignore_errors=True)
    (work / "tiles").mkdir(parents=True)
    whole = concatenate([read_cloud(data / n) for n in PAIR])
    xm = float(np.median(whole.xyz[:, 0]))
    for k, name in enumerate(PAIR):
        c = read_cloud(data / name)
        for side, m in (("w", c.xyz[:, 0] < xm), ("e", c.xyz[:, 0] >= xm)):
            write_cloud(c[m], work / "tiles" / f"t{k}{side}.laz")
    write_cloud(whole, work / "whole.laz")
    write_project(work, ("ground", "dem"), size=100.0, buffer=30.0)
    summary, wall = ws_run(work / "project.toml", work / "out")
    subprocess.run([WS, "-q", "ground", str(work / "whole.laz"), "-o", str(work / "whole_g.laz"), "--method", "smrf"],
                   check=True)
    subprocess.run([WS, "-q", "dem", str(work / "whole_g.laz"), "-o", str(work / "whole_dtm.tif"), "--kind", "dtm",
                    "--resolution", "1"], check=True)
    with rasterio.open(work / "out" / "dem" / "dtm.tif") as a, rasterio.open(work / "whole_dtm.tif") as b:
        za, zb = a.read(1, masked=True), b.read(1, masked=True)
        ta, tb = a.transform, b.transform
    r0, c0 = int(round((ta.f - tb.f) / tb.e)), int(round((ta.c - tb.c) / tb.a))
    zb = zb[r0 : r0 + za.shape[0], c0 : c0 + za.shape[1]]
    rows, cols = np.indices(za.shape)
    x = ta.c + (cols + 0.5) * ta.a
    y = ta.f + (rows + 0.5) * ta.e
    size = summary["chunks"]["size"]
    dist = np.minimum(np.abs(x - np.round(x / size) * size), np.abs(y - np.round(y / size) * size))
    ok = ~za.mask & ~zb.mask
    d = (za - zb).filled(np.nan)
    near = ok & (dist <= 5.0)
    emit({"bench": "seams", "chunks": summary["chunks"]["count"], "cells_near_borders": int(near.sum()),
          "rms_near_borders_m": float(np.sqrt(np.nanmean(d[near] ** 2))),
          "max_abs_near_borders_m": float(np.nanmax(np.abs(d[near]))),
          "rms_all_m": float(np.sqrt(np.nanmean(d[ok] ** 2))), "cells_differing": int((np.abs(d[ok]) > 1e-4).sum()),
          "cells": int(ok.sum()), "wall_s": round(wall, 1)})


def bench_overhead(args):
    """One file of ``--points`` points (shifted copies of bcts_2 merged), through ws ground + ws dem
    (twice: DTM and DSM) and through ws run with the same stages."""
    from workstation.core.cloud import concatenate
    from workstation.io import read_cloud, write_cloud

    work = Path(args.out)
    (work / "tiles").mkdir(parents=True, exist_ok=True)
    big = work / "tiles" / "big.laz"
    if not big.exists():
        c = read_cloud(data_dir(args.data) / "lidar" / "bcts_2.laz")
        reps = int(np.ceil(args.points / c.n))
        side = int(np.ceil(np.sqrt(reps)))
        parts = [c.with_xyz(c.xyz + [200.0 * (k % side), 300.0 * (k // side), 0.0]) for k in range(reps)]
        write_cloud(concatenate(parts)[: args.points], big)
    write_project(work, ("ground", "dem"), size=args.size, buffer=30.0)
    shutil.rmtree(work / "direct", ignore_errors=True)
    (work / "direct").mkdir()
    t = time.perf_counter()
    subprocess.run([WS, "-q", "ground", str(big), "-o", str(work / "direct" / "g.laz"), "--method", "smrf",
                    "--tile-points", "0"], check=True)
    for kind in ("dtm", "dsm"):
        subprocess.run([WS, "-q", "dem", str(work / "direct" / "g.laz"), "-o", str(work / "direct" / f"{kind}.tif"),
                        "--kind", kind, "--resolution", "1"], check=True)
    direct = time.perf_counter() - t
    shutil.rmtree(work / "out", ignore_errors=True)
    summary, wall = ws_run(work / "project.toml", work / "out", "--workers", str(args.workers))
    emit({"bench": "overhead", "points": summary["catalog"]["points"], "direct_s": round(direct, 1),
          "ws_run_s": round(wall, 1), "workers": args.workers, "ratio": round(wall / direct, 3),
          "phases": {k: v["seconds"] for k, v in summary["phases"].items()}})


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["catalog", "run", "rerun", "scaling", "external", "seams", "overhead"])
    ap.add_argument("dir", nargs="?")
    ap.add_argument("--out")
    ap.add_argument("--result")
    ap.add_argument("--data")
    ap.add_argument("--copies", type=int, default=37)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--stages", default="noise,ground,dem")
    ap.add_argument("--size", type=float, default=250.0)
    ap.add_argument("--buffer", type=float, default=30.0)
    ap.add_argument("--points", type=int, default=10_000_000)
    ap.add_argument("--one-core", action="store_true", help="scaling: pin the single worker to one core")
    args = ap.parse_args(argv)
    globals()[f"bench_{args.what}"](args)


if __name__ == "__main__":
    main()
