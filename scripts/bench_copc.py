"""Benchmark the COPC writer against a plain LAZ write of the same cloud.

Subcommands (each prints one JSON line per result on stdout):

    bench_copc.py run --points N --mode {copc,laz,stream,publish3d} [--dir DIR]
        one measurement in this process: ``copc`` writes an in-memory cloud with
        write_copc, ``laz`` writes it as plain LAZ (workstation.io.las.write: laspy + lazrs),
        ``stream`` converts a LAZ file of that cloud chunk by chunk (the path of
        ``ws convert IN.laz OUT.copc.laz``), ``publish3d`` publishes that LAZ file as a site
        with its COPC and its 3D Tiles (``ws publish --3d-tiles``). Reports seconds, points/s, the peak RSS of the
        process (MiB), the RSS before the write, the CPU seconds of all threads (``cpu_s``, less
        sensitive than wall time to other processes on a shared machine) and the load average.
    bench_copc.py mesh3d --faces N [--max-faces M] [--dir DIR]
        a textured terrain mesh of about N triangles, textured as ``ws mesh`` textures (one
        vertex per face corner, faces packed into an atlas of at most 4096 px by
        workstation.mesh.texture.build_atlas), written as OBJ and published as a 3D Tiles
        tileset (workstation.publish.tiles3d.save_tileset, leaves of at most M triangles).
        Reports seconds, CPU seconds, tiles, levels, the tileset and texture sizes and the
        root's geometric error.
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
import shutil
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
    if mode in ("stream", "publish3d") and not src.exists():
        write_las(make_cloud(points), src)
    cloud = None if mode in ("stream", "publish3d") else make_cloud(points)
    warm = make_cloud(1000)  # imports (laspy, lazrs, pyproj) and CRS parsing outside the timing
    write_las(warm, folder / "warm.laz")
    write_copc(warm, folder / "warm.copc.laz")
    before = _rss_mib()
    cpu0 = resource.getrusage(resource.RUSAGE_SELF)
    suffix = {"laz": ".laz", "publish3d": "_site"}.get(mode, ".copc.laz")
    out = folder / f"out_{points}_{mode}{suffix}"
    t0 = time.perf_counter()
    extra = {}
    if mode == "copc":
        r = write_copc(cloud, out)
        extra = {"nodes": r.nodes, "levels": r.levels}
    elif mode == "laz":
        write_las(cloud, out)
    elif mode == "publish3d":
        from workstation.publish.site import PublishParams, publish_site

        res = publish_site([src], out, params=PublishParams(tiles3d=True))
        extra = {"tiles": res.doc["tilesets"][0]["tiles"], "nodes": res.doc["clouds"][0]["nodes"]}
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
    if out.is_dir():
        size = sum(p.stat().st_size for p in out.rglob("*") if p.is_file())
        shutil.rmtree(out)
    else:
        size = out.stat().st_size
        out.unlink()
    return {"bench": "copc", "mode": mode, "points": points, "seconds": round(dt, 2),
            "points_per_s": round(points / dt), "cpu_s": round(cpu, 2),
            "load_avg_1min": round(os.getloadavg()[0], 1), "peak_rss_mib": round(peak), "rss_before_mib": round(before),
            "file_mib": round(size / 2**20, 1), "cpus": os.cpu_count(), **extra}


def make_textured_mesh(faces: int, seed: int = 0):
    """A rolling terrain grid of about ``faces`` triangles (1 km wide) with a texture atlas."""
    from workstation.core.products import Mesh
    from workstation.mesh.texture import TextureParams, _textured_mesh, build_atlas

    n = max(3, int(np.sqrt(faces / 2.0)) + 1)
    x, y = np.meshgrid(np.linspace(0, 1000, n), np.linspace(0, 1000, n))
    z = 200 + 20 * np.sin(x / 150.0) * np.cos(y / 170.0)
    v = np.column_stack([x.ravel() + 500_000.0, y.ravel() + 4_000_000.0, z.ravel()])
    i = np.arange(n * n).reshape(n, n)
    a, b, c, d = i[:-1, :-1].ravel(), i[:-1, 1:].ravel(), i[1:, 1:].ravel(), i[1:, :-1].ravel()
    mesh = Mesh(v, np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])]), crs="EPSG:32632")
    atlas = build_atlas(mesh, 1000.0 / n / 4, TextureParams())
    rng = np.random.default_rng(seed)
    yy, xx = np.mgrid[0 : atlas.height, 0 : atlas.width]
    base = (128 + 60 * np.sin(xx / 37.0) * np.cos(yy / 23.0))[..., None]
    base = base + rng.normal(0, 8, (atlas.height, atlas.width, 3))
    texture = np.clip(base, 0, 255).astype(np.uint8)
    return _textured_mesh(mesh, atlas, np.zeros((mesh.n_faces, 1), np.int64), texture)


def mesh3d(faces: int, max_faces: int, folder: Path) -> dict:
    import inspect

    from workstation.io.mesh import write_mesh
    from workstation.publish.tiles3d import save_tileset, write_mesh_tileset

    mesh = make_textured_mesh(faces)
    src = folder / "mesh.obj"
    write_mesh(mesh, src)
    opts = {"max_faces": max_faces} if "max_faces" in inspect.signature(write_mesh_tileset).parameters else {}
    cpu0 = resource.getrusage(resource.RUSAGE_SELF)
    t0 = time.perf_counter()
    res = save_tileset(src, folder / "tiles", **opts)
    dt = time.perf_counter() - t0
    use = resource.getrusage(resource.RUSAGE_SELF)
    doc = json.loads((folder / "tiles" / "tileset.json").read_text())
    tex = sum(p.stat().st_size for p in folder.glob("*.png")) + sum(p.stat().st_size for p in folder.glob("*.jpg"))
    return {"bench": "mesh3d", "faces": int(mesh.n_faces), "texture_px": list(mesh.meta["texture"].shape[:2]),
            "source_texture_mib": round(tex / 2**20, 1), "max_faces": opts.get("max_faces"),
            "seconds": round(dt, 2), "cpu_s": round(use.ru_utime + use.ru_stime - cpu0.ru_utime - cpu0.ru_stime, 2),
            "load_avg_1min": round(os.getloadavg()[0], 1), "peak_rss_mib": round(use.ru_maxrss / 1024.0),
            "tiles": res.tiles, "levels": res.levels, "tileset_mib": round(res.bytes / 2**20, 1),
            "root_error_m": round(doc["root"]["geometricError"], 3)}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    one = sub.add_parser("run")
    one.add_argument("--points", type=float, required=True)
    one.add_argument("--mode", choices=["copc", "laz", "stream", "publish3d"], required=True)
    one.add_argument("--dir", type=Path, default=None)
    mesh = sub.add_parser("mesh3d")
    mesh.add_argument("--faces", type=float, required=True)
    mesh.add_argument("--max-faces", type=int, default=50_000)
    mesh.add_argument("--dir", type=Path, default=None)
    every = sub.add_parser("all")
    every.add_argument("--sizes", default="1e6,5e6,2e7")
    every.add_argument("--dir", type=Path, default=None)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory(dir=a.dir) as tmp:
        if a.cmd == "mesh3d":
            print(json.dumps(mesh3d(int(a.faces), a.max_faces, Path(tmp))), flush=True)
            return
        if a.cmd == "run":
            print(json.dumps(run(int(a.points), a.mode, Path(tmp))), flush=True)
            return
        for size in (int(float(s)) for s in a.sizes.split(",")):
            for mode in ("laz", "copc", "stream"):
                subprocess.run([sys.executable, __file__, "run", "--points", str(size), "--mode", mode,
                                "--dir", tmp], check=True)


if __name__ == "__main__":
    main()
