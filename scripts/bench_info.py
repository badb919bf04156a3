"""Timings of `ws info`: header summary on a big LAZ, full info against a plain laspy read, and a
COPC bounds query against laspy's CopcReader.

    .venv/bin/python scripts/bench_info.py [--points 40000000] [--work /tmp/ws_bench] [--source FILE]

Builds (once, in --work, never in the repository) a LAZ of about --points points by tiling a
real file side by side, and a COPC file of 1 M points with copc-lib (tests/copc_synth.py).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "tests"))


def make_big(src: Path, dst: Path, n_target: int) -> None:
    """``src`` tiled side by side (integer coordinate shifts) until ``n_target`` points."""
    import laspy

    las = laspy.read(src)
    h = las.header
    span = h.maxs - h.mins
    copies = -(-n_target // len(las.points))
    side = int(np.ceil(np.sqrt(copies)))
    hdr = laspy.LasHeader(point_format=h.point_format.id, version=str(h.version))
    hdr.scales, hdr.offsets = h.scales, h.offsets
    for v in h.vlrs:
        hdr.vlrs.append(v)
    with laspy.open(dst, mode="w", header=hdr, do_compress=True) as w:
        for k in range(copies):
            i, j = divmod(k, side)
            p = las.points.copy()
            p.X = p.X + int(round(i * (span[0] + 1) / h.scales[0]))
            p.Y = p.Y + int(round(j * (span[1] + 1) / h.scales[1]))
            w.write_points(p)


def make_copc(dst: Path, n: int = 1_000_000) -> None:
    from copc_synth import write_copc
    from pyproj import CRS

    rng = np.random.default_rng(1)
    xyz = np.column_stack([rng.uniform(5e5, 5e5 + 2000, n), rng.uniform(4e6, 4e6 + 2000, n), rng.uniform(0, 50, n)])
    write_copc(dst, xyz, wkt=CRS.from_epsg(32632).to_wkt(), max_levels=6)


def best(f, repeat: int = 3) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=40_000_000)
    ap.add_argument("--work", type=Path, default=Path("/tmp/ws_bench"))
    ap.add_argument("--source", type=Path, default=REPO.parent / "shared/data/lidar/autzen_trim.las")
    ap.add_argument("--repeat", type=int, default=1, help="runs of the long timings (best is kept)")
    a = ap.parse_args()
    a.work.mkdir(parents=True, exist_ok=True)
    big = a.work / f"big{a.points // 1_000_000}m.laz"
    if not big.exists():
        make_big(a.source, big, a.points)
    cp = a.work / "bench.copc.laz"
    if not cp.exists():
        make_copc(cp)

    import laspy
    from laspy.copc import Bounds

    from workstation.io import read_cloud
    from workstation.qc.header import header_summary
    from workstation.qc.summary import summarize

    n = laspy.open(big).header.point_count
    header_summary(big)  # imports and the CRS database warm
    t_sum = best(lambda: header_summary(big), 5)
    t0 = time.perf_counter()
    subprocess.run([str(REPO / ".venv/bin/ws"), "info", "--summary", str(big)], check=True, capture_output=True)
    t_cli = time.perf_counter() - t0
    print(f"header summary, {n:,} points: {t_sum:.3f} s in process; `ws info --summary` {t_cli:.2f} s "
          "(process start and imports included)")

    t_laspy = best(lambda: laspy.read(big), a.repeat)
    t_info = best(lambda: summarize(big, density_strict=False), a.repeat)
    print(f"full info {t_info:.2f} s, laspy.read {t_laspy:.2f} s: ratio {t_info / t_laspy:.2f}")

    with laspy.open(cp) as r:
        h = r.header
    lo, hi = h.mins, h.maxs
    box = (lo[0], lo[1], (lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)  # a quarter of the file

    def copc_reader():
        with laspy.CopcReader.open(str(cp)) as r:
            return r.query(bounds=Bounds(mins=np.array(box[:2]), maxs=np.array(box[2:])))

    t_ref = best(copc_reader)
    t_ws = best(lambda: read_cloud(cp, bounds=box))
    m = len(copc_reader())
    print(f"COPC quarter query ({m:,} of {h.point_count:,} points): read_cloud {t_ws:.2f} s, "
          f"CopcReader.query {t_ref:.2f} s: ratio {t_ws / t_ref:.2f}")


if __name__ == "__main__":
    main()
