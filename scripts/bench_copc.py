"""Benchmark the COPC writer against a plain LAZ write of the same cloud.

Subcommands (each prints one JSON line per result on stdout):

    bench_copc.py run --points N --mode {copc,laz,stream} [--dir DIR]
        one measurement in this process: ``copc`` writes an in-memory cloud with
        write_copc, ``laz`` writes it as plain LAZ (workstation.io.las.write: laspy + lazrs),
        ``stream`` converts a LAZ file of that cloud chunk by chunk (the path of
        ``ws convert IN.laz OUT.copc.laz``). Reports seconds, points/s, the peak RSS of the
        process (MiB), the RSS before the write, the CPU seconds of all threads (``cpu_s``, less
        sensitive than wall time to other processes on a shared machine) and the load average.
    bench_copc.py all [--sizes 1e6,5e6,2e7] [--dir DIR]
        every mode and size, each in a fresh process so the peak RSS is its own.

The cloud is synthetic ALS-like terrain (deterministic, seed 0): a 1 km wide square with
gently rolling ground at about the density N / 1e6 m², 1 mm coordinates, intensity,
returns, class, GPS time in acquisition order (scan lines) and RGB (point format 7).
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

import numpy as np


def make_cloud(n: int, seed: int = 0):
    """A synthetic ALS strip of ``n`` points in acquisition order (scan lines along y)."""
    from workstation.core.cloud import Cloud

    rng = np.random.default_rng(seed)
    lines = max(1, int(np.sqrt(n)))
    t = np.arange(n, dtype=np.float64)
    x = (t % lines) / lines * 1000.0 + rng.normal(0, 0.05, n)
    y = np.floor(t / lines) / max(1, n // lines) * 1000.0 + rng.normal(0, 0.05, n)
    z = 200 + 20 * np.sin(x / 150.0) * np.cos(y / 170.0) + rng.normal(0, 0.05, n)
    xyz = np.round(np.column_stack([x + 500_000.0, y + 4_000_000.0, z]), 3)
    rn = rng.integers(1, 3, n).astype(np.uint8)
    attrs = {
        "intensity": rng.integers(0, 4000, n).astype(np.uint16),
        "return_number": rn,
        "number_of_returns": np.maximum(rn, 2).astype(np.uint8),
        "classification": rng.choice(np.array([1, 2, 5, 6], np.uint8), n),
        "gps_time": 300_000.0 + t * 2e-6,
        "rgb": rng.integers(0, 65535, (n, 3)).astype(np.uint16),
    }
    return Cloud.from_owned_arrays(xyz, attrs, crs="EPSG:32632")


def _rss_mib() -> float:
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def run(points: int, mode: str, folder: Path) -> dict:
    from workstation.io import iter_chunks
    from workstation.io.las import write as write_las
    from workstation.publish.copc import write_copc, write_copc_chunks

    src = folder / f"src_{points}.laz"
    if mode == "stream" and not src.exists():
        write_las(make_cloud(points), src)
    cloud = None if mode == "stream" else make_cloud(points)
    warm = make_cloud(1000)  # imports (laspy, lazrs, pyproj) and CRS parsing outside the timing
    write_las(warm, folder / "warm.laz")
    write_copc(warm, folder / "warm.copc.laz")
    before = _rss_mib()
    cpu0 = resource.getrusage(resource.RUSAGE_SELF)
    out = folder / f"out_{points}_{mode}.{'laz' if mode == 'laz' else 'copc.laz'}"
    t0 = time.perf_counter()
    extra = {}
    if mode == "copc":
        r = write_copc(cloud, out)
        extra = {"nodes": r.nodes, "levels": r.levels}
    elif mode == "laz":
        write_las(cloud, out)
    else:
        import laspy

        with laspy.open(str(src)) as f:
            bounds = (np.asarray(f.header.mins), np.asarray(f.header.maxs))
        r = write_copc_chunks(iter_chunks(src, 1_048_576), out, bounds=bounds)
        extra = {"nodes": r.nodes, "levels": r.levels}
    dt = time.perf_counter() - t0
    use = resource.getrusage(resource.RUSAGE_SELF)
    cpu = use.ru_utime + use.ru_stime - cpu0.ru_utime - cpu0.ru_stime
    peak = use.ru_maxrss / 1024.0
    size = out.stat().st_size
    out.unlink()
    return {"bench": "copc", "mode": mode, "points": points, "seconds": round(dt, 2),
            "points_per_s": round(points / dt), "cpu_s": round(cpu, 2),
            "load_avg_1min": round(os.getloadavg()[0], 1), "peak_rss_mib": round(peak), "rss_before_mib": round(before),
            "file_mib": round(size / 2**20, 1), "cpus": os.cpu_count(), **extra}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    one = sub.add_parser("run")
    one.add_argument("--points", type=float, required=True)
    one.add_argument("--mode", choices=["copc", "laz", "stream"], required=True)
    one.add_argument("--dir", type=Path, default=None)
    every = sub.add_parser("all")
    every.add_argument("--sizes", default="1e6,5e6,2e7")
    every.add_argument("--dir", type=Path, default=None)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(dir=a.dir) as tmp:
        if a.cmd == "run":
            print(json.dumps(run(int(a.points), a.mode, Path(tmp))), flush=True)
            return
        for size in (int(float(s)) for s in a.sizes.split(",")):
            for mode in ("laz", "copc", "stream"):
                subprocess.run([sys.executable, __file__, "run", "--points", str(size), "--mode", mode,
                                "--dir", tmp], check=True)


if __name__ == "__main__":
    main()
