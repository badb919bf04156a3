"""Benchmarks of `ws publish`: publishing time of a large synthetic cloud, and the viewer's time
to its first complete view in headless Chromium (SwiftShader WebGL).

    python scripts/bench_publish.py publish --points 20000000 [--out DIR] [--keep]
    python scripts/bench_publish.py viewer --site DIR
    python scripts/bench_publish.py tiles3d --points 20000000 [--out DIR] [--keep]

Each prints one JSON line. ``publish`` writes a synthetic LAZ (terrain with buildings-like
blocks, four classes, RGB, intensity; not timed) and times ``publish_site`` on it (COPC
conversion + statistics + site files); ``viewer`` serves a published site and times the page
from navigation to ``data-ws-state="ready"`` (the Chromium driver is the one of
tests/publish/test_publish_site.py); ``tiles3d`` times the 3D Tiles tileset of the same synthetic
LAZ (:func:`workstation.publish.tiles3d.save_tileset`: staging, octree, one GLB per node).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]


def synthetic_laz(path: Path, n: int, chunk: int = 2_000_000, seed: int = 0) -> None:
    """Write ``n`` points over a 1 km x 1 km tile, streamed in chunks (bounded memory)."""
    import laspy

    header = laspy.LasHeader(point_format=7, version="1.4")
    header.scales, header.offsets = np.array([0.001] * 3), np.array([500_000.0, 4_000_000.0, 0.0])
    header.add_crs(__import__("pyproj").CRS.from_epsg(32632))
    rng = np.random.default_rng(seed)
    with laspy.open(str(path), mode="w", header=header) as w:
        for start in range(0, n, chunk):
            m = min(chunk, n - start)
            x, y = rng.uniform(0, 1000, m), rng.uniform(0, 1000, m)
            ground = 100 + 8 * np.sin(x / 90) * np.cos(y / 70)
            block = (np.sin(x / 23) > 0.7) & (np.sin(y / 31) > 0.7)
            tree = ~block & (rng.random(m) < 0.15)
            z = ground + np.where(block, 12.0, 0) + np.where(tree, rng.uniform(2, 15, m), 0)
            rec = laspy.ScaleAwarePointRecord.zeros(m, header=header)
            rec.x, rec.y, rec.z = x + 500_000, y + 4_000_000, z
            rec.classification = np.where(block, 6, np.where(tree, 5, 2)).astype(np.uint8)
            rec.intensity = rng.integers(200, 4000, m).astype(np.uint16)
            rgb = np.where(block[:, None], [200, 80, 60], np.where(tree[:, None], [40, 140, 50], [150, 130, 90]))
            rec.red, rec.green, rec.blue = (rgb * 257).T.astype(np.uint16)
            rec.return_number = np.ones(m, np.uint8)
            rec.number_of_returns = np.ones(m, np.uint8)
            w.write_points(rec)


def bench_publish(args) -> dict:
    from workstation.publish.site import publish_site

    work = Path(args.out or tempfile.mkdtemp(prefix="bench_publish_"))
    work.mkdir(parents=True, exist_ok=True)
    src = work / "input" / "cloud.laz"
    src.parent.mkdir(exist_ok=True)
    if not src.exists():
        t = time.perf_counter()
        synthetic_laz(src, args.points)
        print(f"# wrote {src} in {time.perf_counter() - t:.1f} s", file=sys.stderr)
    t0, c0 = time.perf_counter(), time.process_time()
    res = publish_site([src.parent], work / "site", overwrite=True)
    seconds, cpu = time.perf_counter() - t0, time.process_time() - c0
    size = sum(p.stat().st_size for p in (work / "site").rglob("*") if p.is_file())
    out = {"bench": "publish", "points": res.points, "seconds": round(seconds, 2),
           "cpu_s": round(cpu, 1), "points_per_s": round(res.points / seconds), "site_mb": round(size / 1e6, 1),
           "input_mb": round(src.stat().st_size / 1e6, 1), "levels": res.doc["clouds"][0]["levels"],
           "nodes": res.doc["clouds"][0]["nodes"],
           "peak_rss_mb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
           "load_avg_1min": round(__import__("os").getloadavg()[0], 1), "cpus": __import__("os").cpu_count()}
    if not args.keep and not args.out:
        shutil.rmtree(work, ignore_errors=True)
    return out


def _synthetic_input(args) -> tuple[Path, Path]:
    """(work folder, its synthetic input/cloud.laz of ``args.points`` points, written once)."""
    work = Path(args.out or tempfile.mkdtemp(prefix="bench_publish_"))
    src = work / "input" / "cloud.laz"
    src.parent.mkdir(parents=True, exist_ok=True)
    if not src.exists():
        t = time.perf_counter()
        synthetic_laz(src, args.points)
        print(f"# wrote {src} in {time.perf_counter() - t:.1f} s", file=sys.stderr)
    return work, src


def bench_tiles3d(args) -> dict:
    from workstation.publish.tiles3d import save_tileset

    work, src = _synthetic_input(args)
    t0, c0 = time.perf_counter(), time.process_time()
    res = save_tileset(src, work / "3dtiles", overwrite=True)
    seconds, cpu = time.perf_counter() - t0, time.process_time() - c0
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = {"bench": "tiles3d", "points": res.points, "seconds": round(seconds, 2), "cpu_s": round(cpu, 1),
           "points_per_s": round(res.points / seconds), "tiles": res.tiles, "levels": res.levels,
           "tileset_mb": round(res.bytes / 1e6, 1), "input_mb": round(src.stat().st_size / 1e6, 1),
           "peak_rss_mb": round(max(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, children.ru_maxrss) / 1024),
           "load_avg_1min": round(__import__("os").getloadavg()[0], 1), "cpus": __import__("os").cpu_count()}
    if not args.keep and not args.out:
        shutil.rmtree(work, ignore_errors=True)
    return out


def bench_viewer(args) -> dict:
    spec = importlib.util.spec_from_file_location("t", REPO / "tests" / "publish" / "test_publish_site.py")
    t = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(t)
    from workstation.publish.site import serve_in_thread

    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    srv = serve_in_thread(args.site)
    browser = t.Chromium(exe, Path(tempfile.mkdtemp(prefix="bench_chrome_")), size=tuple(args.size))
    try:
        state, seconds = t._open(browser, srv, args.view)
        if args.screenshot:
            time.sleep(1.0)  # the finest nodes of the view drawn
            from PIL import Image

            Image.fromarray(browser.screenshot()).save(args.screenshot)
        errors = browser.errors()
        nodes = browser.eval("document.documentElement.dataset.wsNodes")
        status = browser.eval("document.getElementById('status').textContent")
        marks = browser.eval("wsViewer.marks")
    finally:
        browser.close()
        srv.shutdown()
    ranges = sum(1 for r in srv.requests if r[1])
    return {"bench": "viewer", "site": str(args.site), "state": state, "seconds_to_ready": round(seconds, 2),
            "marks_ms": marks, "nodes_drawn": int(nodes or 0), "range_requests": ranges, "errors": len(errors), "status": status}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("publish", help="time publish_site on a synthetic LAZ")
    p.add_argument("--points", type=int, default=20_000_000)
    p.add_argument("--out", default=None, help="work folder (kept; the LAZ is reused when present)")
    p.add_argument("--keep", action="store_true", help="keep the temporary work folder")
    v = sub.add_parser("viewer", help="time the viewer to its first complete view")
    v.add_argument("--site", required=True)
    v.add_argument("--screenshot", help="also save the page once ready as this PNG")
    v.add_argument("--size", type=int, nargs=2, default=(640, 480), metavar=("W", "H"), help="window size, pixels")
    v.add_argument("--view", default="", help="a '#view=px,py,pz,tx,ty,tz' camera (CRS units)")
    t = sub.add_parser("tiles3d", help="time the 3D Tiles tileset of a synthetic LAZ")
    t.add_argument("--points", type=int, default=20_000_000)
    t.add_argument("--out", default=None, help="work folder (kept; the LAZ is reused when present)")
    t.add_argument("--keep", action="store_true", help="keep the temporary work folder")
    args = ap.parse_args()
    run = {"publish": bench_publish, "viewer": bench_viewer, "tiles3d": bench_tiles3d}[args.cmd]
    print(json.dumps(run(args)), flush=True)


if __name__ == "__main__":
    main()
