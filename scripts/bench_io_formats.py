"""Benchmark: read and write speed of the PLY, PCD, text and E57 modules on 1 million points.

Prints one JSON line per (format, operation): wall seconds, CPU seconds of this process
(``time.process_time``, less sensitive to other load on a shared machine), points per second,
and the same operation by an anchor library in the same run (open3d for PLY/PCD/XYZ,
numpy's ``loadtxt``/``savetxt`` for XYZ, pye57 for E57) with ``speed_vs_anchor`` =
anchor seconds / our seconds (above 1: faster than the anchor).

Usage: python scripts/bench_io_formats.py [--points 1000000] [--repeat 2]
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud
from workstation.io import e57, pcd, ply, text


def _time(fn, repeat):
    best_wall, best_cpu = float("inf"), float("inf")
    for _ in range(repeat):
        w0, c0 = time.perf_counter(), time.process_time()
        fn()
        best_wall = min(best_wall, time.perf_counter() - w0)
        best_cpu = min(best_cpu, time.process_time() - c0)
    return best_wall, best_cpu


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=2)
    args = ap.parse_args()
    import open3d as o3d
    import pye57

    n = args.points
    rng = np.random.default_rng(0)
    xyz = np.round(rng.uniform(0, 1000, (n, 3)), 3)
    rgb8 = rng.integers(0, 256, (n, 3))
    normal = rng.normal(size=(n, 3)).astype(np.float32)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    full = Cloud(xyz, {"rgb": rgb8 * 257, "normal": normal})
    xyz_only = Cloud(xyz)
    intensity = rng.integers(0, 65536, n)
    xyzi = Cloud(xyz, {"intensity": intensity})
    xyzi_np = np.column_stack([xyz, intensity])
    legacy = o3d.geometry.PointCloud()
    legacy.points = o3d.utility.Vector3dVector(xyz)
    legacy.colors = o3d.utility.Vector3dVector(rgb8 / 255.0)
    legacy.normals = o3d.utility.Vector3dVector(normal.astype(np.float64))
    legacy_xyz = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(xyz))

    with tempfile.TemporaryDirectory() as d:
        d = Path(d)

        def o3d_write(cloud, name, **kw):
            return lambda: o3d.io.write_point_cloud(str(d / name), cloud, **kw)

        def o3d_read(name):
            return lambda: o3d.io.read_point_cloud(str(d / name))

        def e57_anchor_read():
            f = pye57.E57(str(d / "a.e57"))
            f.read_scan(0, intensity=True, colors=True, ignore_missing_fields=True)
            f.close()

        def e57_anchor_write():
            f = pye57.E57(str(d / "anchor.e57"), mode="w")
            f.write_scan_raw({"cartesianX": xyz[:, 0], "cartesianY": xyz[:, 1], "cartesianZ": xyz[:, 2],
                              "colorRed": rgb8[:, 0].astype(np.uint8), "colorGreen": rgb8[:, 1].astype(np.uint8),
                              "colorBlue": rgb8[:, 2].astype(np.uint8)})
            f.close()

        cases = [
            # (format, attrs, our write, our read, anchor name, anchor write, anchor read)
            ("ply_binary", "xyz f8, rgb, normal", lambda: ply.write(full, d / "a.ply"), lambda: ply.read(d / "a.ply"),
             "open3d", o3d_write(legacy, "o.ply"), o3d_read("o.ply")),
            ("ply_ascii", "xyz f8, rgb, normal", lambda: ply.write(full, d / "t.ply", ascii=True), lambda: ply.read(d / "t.ply"),
             "open3d", o3d_write(legacy, "ot.ply", write_ascii=True), o3d_read("ot.ply")),
            ("pcd_binary", "xyz f8, rgb, normal", lambda: pcd.write(full, d / "a.pcd"), lambda: pcd.read(d / "a.pcd"),
             "open3d (xyz f4)", o3d_write(legacy, "o.pcd"), o3d_read("o.pcd")),
            ("xyz_text", "xyz, 3 decimals", lambda: text.write(xyz_only, d / "a.xyz", precision=3), lambda: text.read(d / "a.xyz"),
             "open3d", o3d_write(legacy_xyz, "o.xyz"), o3d_read("o.xyz")),
            ("txt_xyzi", "x y z intensity, 3 decimals", lambda: text.write(xyzi, d / "a.txt", precision=3, header=False),
             lambda: text.read(d / "a.txt", columns="x,y,z,intensity"),
             "numpy savetxt/loadtxt", lambda: np.savetxt(d / "np.txt", xyzi_np, fmt="%.3f %.3f %.3f %d"),
             lambda: np.loadtxt(d / "a.txt")),
            ("e57", "xyz f8, rgb", lambda: e57.write(full.without_attrs("normal"), d / "a.e57"), lambda: e57.read(d / "a.e57"),
             "pye57", e57_anchor_write, e57_anchor_read),
        ]
        for fmt, attrs, w, r, anchor, aw, ar in cases:
            for op, ours, theirs in (("write", w, aw), ("read", r, ar)):
                a_wall, a_cpu = _time(theirs, args.repeat)
                rec = {"format": fmt, "op": op, "points": n, "attrs": attrs, "anchor": anchor,
                       "anchor_seconds": round(a_wall, 3), "anchor_cpu_seconds": round(a_cpu, 3)}
                if ours is not None:
                    wall, cpu = _time(ours, args.repeat)
                    rec.update({"seconds": round(wall, 3), "cpu_seconds": round(cpu, 3),
                                "points_per_s": round(n / wall), "points_per_cpu_s": round(n / cpu),
                                "speed_vs_anchor": round(a_wall / wall, 2)})
                print(json.dumps(rec), flush=True)
        # a cross-check that the files hold what was written (a benchmark of wrong output is worthless)
        back = ply.read(d / "a.ply")
        if not np.array_equal(back.xyz, xyz) or not np.array_equal(pcd.read(d / "a.pcd").xyz, xyz):
            raise SystemExit("round trip mismatch")


if __name__ == "__main__":
    main()
