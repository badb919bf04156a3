"""IO benchmark: 10-million-point LAS and LAZ, our reader/writer against bare laspy.

Prints one JSON line per result. Each measurement runs in a fresh subprocess so peak memory
(ru_maxrss) belongs to that measurement alone; the import baseline is subtracted.

"Bare laspy" read = ``laspy.read`` plus materialising x, y, z and every dimension as numpy
arrays (the same product our reader returns); "bare laspy" write = filling a ``LasData`` of
the same point format from numpy arrays and ``.write``. Ratios are ours/laspy in points/s
(higher is better; goal >= 0.9).

Usage: python scripts/bench_io.py [--points 10000000] [--repeat 3] [--workdir bench_out]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

CHILD = r"""
import json, sys, time
import numpy as np
import laspy
from workstation.io import read_cloud, write_cloud
def hwm():
    # VmHWM belongs to this process image (ru_maxrss would inherit the parent's peak)
    for line in open("/proc/self/status"):
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) * 1024
    return 0
mode, path, out = sys.argv[1], sys.argv[2], sys.argv[3]
base = hwm()
if mode.startswith("write"):
    src = read_cloud(path)
    base = hwm()
t0 = time.perf_counter()
if mode == "read_ours":
    c = read_cloud(path)
    nbytes = c.xyz.nbytes + sum(a.nbytes for a in c.attrs.values()); n = c.n
elif mode == "read_laspy":
    las = laspy.read(path)
    arrays = [np.asarray(las.x), np.asarray(las.y), np.asarray(las.z)]
    arrays += [np.asarray(las[d]) for d in las.point_format.dimension_names if d not in ("X", "Y", "Z")]
    nbytes = sum(a.nbytes for a in arrays); n = len(las.points)
elif mode == "read_laspy_raw":
    las = laspy.read(path)
    nbytes = las.points.array.nbytes; n = len(las.points)
elif mode == "write_ours":
    write_cloud(src, out, overwrite=True)
    n = src.n; nbytes = 0
elif mode == "write_laspy":
    h = laspy.LasHeader(point_format=src.meta["las"]["point_format"], version=src.meta["las"]["version"])
    h.scales = src.meta["las"]["scales"]; h.offsets = src.meta["las"]["offsets"]
    las = laspy.LasData(h)
    las.x, las.y, las.z = src.xyz[:, 0], src.xyz[:, 1], src.xyz[:, 2]
    for k, v in src.attrs.items():
        if k == "rgb":
            las.red, las.green, las.blue = v[:, 0], v[:, 1], v[:, 2]
        elif k == "scan_angle":
            las["scan_angle"] = np.round(v / 0.006).astype(np.int16)
        else:
            las[k] = v
    las.write(out)
    n = src.n; nbytes = 0
dt = time.perf_counter() - t0
peak = hwm()
print(json.dumps({"mode": mode, "seconds": dt, "points": int(n), "array_bytes": int(nbytes), "peak_bytes_above_start": int(peak - base)}))
"""


def make_file(path: Path, n: int, compress: bool) -> None:
    import numpy as np

    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    rng = np.random.default_rng(0)
    xyz = np.column_stack([rng.uniform(0, 1000, n), rng.uniform(0, 1000, n), rng.uniform(0, 50, n)])
    xyz[:, :2] += [500_000, 5_000_000]
    rn = rng.integers(1, 4, n)
    cloud = Cloud(
        np.round(xyz, 3),
        {
            "intensity": rng.integers(0, 4000, n),
            "return_number": rn,
            "number_of_returns": np.maximum(rn, 3),
            "classification": rng.choice([1, 2, 3, 5, 6], n),
            "scan_angle": np.round(rng.uniform(-20, 20, n) / 0.006) * 0.006,
            "gps_time": np.sort(rng.uniform(0, 3600, n)),
            "point_source_id": np.ones(n),
            "rgb": rng.integers(0, 65536, (n, 3)),
        },
        crs="EPSG:32632",
    )
    write_cloud(cloud, path, overwrite=True, compress=compress)


def child(mode: str, path: Path, out: Path) -> dict:
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    r = subprocess.run([sys.executable, "-c", CHILD, mode, str(path), str(out)], capture_output=True, text=True, env=env)
    if r.returncode:
        raise SystemExit(r.stderr)
    return json.loads(r.stdout.strip().splitlines()[-1])


def help_time(repeat: int) -> float:
    ws = Path(sys.executable).with_name("ws")
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run([str(ws), "--help"], capture_output=True, check=True)
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=10_000_000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--workdir", default="bench_out")
    a = ap.parse_args()
    wd = Path(a.workdir)
    wd.mkdir(exist_ok=True)
    for ext in ("las", "laz"):
        src = wd / f"io_{a.points}.{ext}"
        if not src.exists():
            make_file(src, a.points, ext == "laz")
        best = {}
        for _ in range(a.repeat):  # interleaved so load changes hit both sides alike
            for mode in ("read_laspy", "read_ours", "read_laspy_raw", "write_laspy", "write_ours"):
                r = child(mode, src, wd / f"out_{mode}.{ext}")
                if mode not in best or r["seconds"] < best[mode]["seconds"]:
                    best[mode] = r
        for op in ("read", "write"):
            ours, ref = best[f"{op}_ours"], best[f"{op}_laspy"]
            res = {
                "bench": f"io_{op}_{ext}",
                "points": ours["points"],
                "ours_points_per_s": ours["points"] / ours["seconds"],
                "laspy_points_per_s": ref["points"] / ref["seconds"],
                "ratio": ref["seconds"] / ours["seconds"],
                "ours_peak_mb": ours["peak_bytes_above_start"] / 2**20,
                "laspy_peak_mb": ref["peak_bytes_above_start"] / 2**20,
            }
            if op == "read":
                res["array_mb"] = ours["array_bytes"] / 2**20
                res["peak_over_arrays"] = ours["peak_bytes_above_start"] / ours["array_bytes"]
                raw = best["read_laspy_raw"]
                res["ratio_vs_laspy_read_only"] = raw["seconds"] / ours["seconds"]
            print(json.dumps(res), flush=True)
    print(json.dumps({"bench": "ws_help_startup", "seconds": help_time(5)}), flush=True)


if __name__ == "__main__":
    main()
