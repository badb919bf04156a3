"""Timings of `ws info`: header summary on a big LAZ, full info against a plain laspy read, and a
COPC bounds query against laspy's CopcReader.

    .venv/bin/python scripts/bench_info.py [--points 40000000] [--work /tmp/ws_bench] [--source FILE]
                                           [--repeat 1] [--parts summary,info,copc]

Builds (once, in --work, never in the repository) a LAZ of about --points points by tiling a
real file side by side, and a COPC file of 1 M points with copc-lib (tests/copc_synth.py).

The full-info part runs, ``--repeat`` times in turn, ``laspy.read``, the in-process
:func:`workstation.qc.summary.summarize` and a ``ws info --json`` process on the big file, and
prints the best wall and CPU times (all threads; the child's for the process) of each, their
ratios to ``laspy.read`` and the load average, as the machine may be shared.
"""

from __future__ import annotations

import argparse
import os
import resource
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


def timed(f) -> tuple[float, float]:
    """(wall, CPU) seconds of one call of ``f``; CPU of this process, every thread."""
    w, c = time.perf_counter(), time.process_time()
    f()
    return time.perf_counter() - w, time.process_time() - c


def timed_process(cmd: list[str]) -> tuple[float, float]:
    """(wall, CPU) seconds of running ``cmd`` to its end; CPU of the child, user and system."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    w = time.perf_counter() - w
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return w, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def bench_full_info(big: Path, repeat: int) -> None:
    """``laspy.read`` against full ``ws info`` (in process and as a process), runs interleaved."""
    import laspy

    from workstation.qc.summary import summarize

    runs = {
        "laspy.read": lambda: timed(lambda: laspy.read(big)),
        "summarize": lambda: timed(lambda: summarize(big, density_strict=False)),
        "`ws info --json`": lambda: timed_process([str(REPO / ".venv/bin/ws"), "info", "--json", str(big)]),
    }
    best = {k: (float("inf"), float("inf")) for k in runs}
    load = []
    for _ in range(repeat):
        for k, run in runs.items():
            load.append(os.getloadavg()[0])
            w, c = run()
            best[k] = (min(best[k][0], w), min(best[k][1], c))
    w0, c0 = best["laspy.read"]
    for k, (w, c) in best.items():
        print(f"  {k:<18} wall {w:7.2f} s ({w / w0:.2f}x)   CPU {c:7.2f} s ({c / c0:.2f}x)")
    print(f"  load average (1 min) during the runs: {min(load):.1f} to {max(load):.1f} on {os.cpu_count()} CPUs")


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=40_000_000)
    ap.add_argument("--work", type=Path, default=Path("/tmp/ws_bench"))
    ap.add_argument("--source", type=Path, default=REPO.parent / "shared/data/lidar/autzen_trim.las")
    ap.add_argument("--repeat", type=int, default=1, help="runs of the long timings (best is kept)")
    ap.add_argument("--parts", default="summary,info,copc", help="which timings: summary, info, copc")
    a = ap.parse_args()
    parts = set(a.parts.split(","))
    a.work.mkdir(parents=True, exist_ok=True)
    big = a.work / f"big{a.points // 1_000_000}m.laz"
    if not big.exists():
        make_big(a.source, big, a.points)
    cp = a.work / "bench.copc.laz"
    if "copc" in parts and not cp.exists():
        make_copc(cp)

    import laspy
    from laspy.copc import Bounds

    from workstation.io import read_cloud
    from workstation.qc.header import header_summary

    n = laspy.open(big).header.point_count
    if "summary" in parts:
        header_summary(big)  # imports and the CRS database warm
        t_sum = best(lambda: header_summary(big), 5)
        t0 = time.perf_counter()
        subprocess.run([str(REPO / ".venv/bin/ws"), "info", "--summary", str(big)], check=True, capture_output=True)
        t_cli = time.perf_counter() - t0
        print(f"header summary, {n:,} points: {t_sum:.3f} s in process; `ws info --summary` {t_cli:.2f} s "
              "(process start and imports included)")
    if "info" in parts:
        print(f"full info, {n:,} points ({big}), best of {a.repeat}:")
        bench_full_info(big, a.repeat)
    if "copc" not in parts:
        return
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
