"""Cost of every command on a sparse cloud over a large extent (grids sized by points).

Builds 6,000 points spread over 5 km x 5 km (rolling terrain, one building), stored in US
survey feet under EPSG:26910 with GeoKeys overriding its unit (ProjLinearUnitsGeoKey and
VerticalUnitsGeoKey = 9003), then runs each command in its own process and prints one JSON
line per command: wall time and the process's peak resident memory (``wait4`` rusage).

    .venv/bin/python scripts/bench_sparse_extent.py [--points 6000] [--size 5000]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import laspy
import numpy as np

US_FT = 1200.0 / 3937.0


def build(path: Path, n: int, size: float, seed: int = 11) -> None:
    """The sparse feet file (see the module docstring)."""
    from laspy.vlrs.geotiff import GeoKeyEntryStruct
    from laspy.vlrs.known import GeoKeyDirectoryVlr

    rng = np.random.default_rng(seed)
    xy = rng.uniform(0.0, size, (n, 2))
    z = 100.0 + 5.0 * np.sin(xy[:, 0] / 30.0) + 0.05 * xy[:, 1]
    roof = (np.abs(xy[:, 0] - size / 2) < 15) & (np.abs(xy[:, 1] - size / 2) < 15)
    z[roof] += 8.0
    xyz = np.column_stack([xy[:, 0] + 500_000.3, xy[:, 1] + 5_000_000.7, z]) / US_FT
    keys = [(1024, 0, 1, 1), (1025, 0, 1, 1), (3072, 0, 1, 26910), (3076, 0, 1, 9003), (4099, 0, 1, 9003)]
    vlr = GeoKeyDirectoryVlr()
    vlr.geo_keys_header.key_directory_version, vlr.geo_keys_header.key_revision = 1, 1
    vlr.geo_keys_header.number_of_keys = len(keys)
    vlr.geo_keys = [GeoKeyEntryStruct(*k) for k in keys]
    h = laspy.LasHeader(point_format=1, version="1.2")
    h.offsets, h.scales = np.floor(xyz.min(axis=0)), [0.001] * 3
    h.vlrs.append(vlr)
    las = laspy.LasData(h)
    las.x, las.y, las.z = xyz.T
    las.classification = np.where(roof, 6, 2).astype(np.uint8)
    las.return_number, las.number_of_returns = np.ones(n, np.uint8), np.ones(n, np.uint8)
    las.write(str(path))


def measure(args: list[str]) -> dict:
    """Run ``ws ARGS`` in a child process: exit code, seconds, peak RSS in MB, last stderr line."""
    ws = str(Path(sys.executable).with_name("ws"))
    t0 = time.perf_counter()
    p = subprocess.Popen([ws, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(p.pid, 0)
    dt = time.perf_counter() - t0
    err = p.stderr.read().strip().splitlines()
    return {"command": "ws " + " ".join(args), "rc": os.waitstatus_to_exitcode(status), "seconds": round(dt, 2),
            "peak_mb": round(usage.ru_maxrss / 1024.0, 1), "stderr": err[-1][:160] if err else ""}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=6000)
    ap.add_argument("--size", type=float, default=5000.0, help="side of the square, metres")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="ws_sparse_") as tmp:
        d = Path(tmp)
        src = d / "sparse.las"
        build(src, a.points, a.size)
        runs = [
            ["info", src],
            ["dem", src, "-o", d / "dtm.tif"],
            ["dem", src, "-o", d / "dsm.tif", "--kind", "dsm"],
            ["contours", d / "dtm.tif", "-o", d / "c.geojson"],
            ["hillshade", d / "dtm.tif", "-o", d / "hs.tif"],
            ["ground", src, "-o", d / "g_smrf.las", "--method", "smrf"],
            ["ground", src, "-o", d / "g_csf.las", "--method", "csf"],
            ["ground", src, "-o", d / "g_pmf.las", "--method", "pmf"],
            ["ground", src, "-o", d / "g_ptd.las", "--method", "ptd"],
            ["classify", src, "-o", d / "cls.las"],
            ["render", src, "-o", d / "top.png", "--view", "top", "--color", "elevation"],
            ["dem", src, "-o", d / "fine.tif", "--resolution", "0.5"],  # absurd: refused, naming the option
        ]
        for r in runs:
            print(json.dumps({"points": a.points, "extent_m": a.size, **measure([str(x) for x in r])}), flush=True)


if __name__ == "__main__":
    main()
