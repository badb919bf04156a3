"""Benchmarks of the raster products; prints one JSON line per result.

    PYTHONPATH=. python scripts/bench_raster.py [--only dtm10m,contours,synthetic,real,ortho] [--docs-img docs/img]

* dtm10m    — 1 m DTM (linear TIN) from 10 million in-memory points (wall and CPU seconds, peak RSS).
* stream    — the same from a 10M-point LAZ streamed in 1M-point chunks (child-process peak RSS).
* contours  — contour lines of a 4000×4000 DEM (40 levels), and the GeoJSON write.
* synthetic — DTM accuracy against an analytic terrain with Gaussian noise and box buildings.
* real      — bcts_1 + bcts_2 (../shared/data/lidar): DTM from a ground filter vs DTM from the
              files' own class 2; the two tiles as one mosaic vs pasted single-tile DTMs across
              their common edge; hillshade and contour figures (``--docs-img``).
* ortho     — true orthophoto of the synthetic aerial rig against the true texture ortho.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO)) if str(REPO) not in sys.path else None

from workstation.core.classes import ASPRSClass  # noqa: E402
from workstation.core.cloud import Cloud  # noqa: E402
from workstation.core.products import Raster  # noqa: E402
from workstation.raster.dem import DemParams, build_dem  # noqa: E402

DATA = Path(os.environ.get("WS_SHARED_DATA", REPO.parent / "shared" / "data"))


def emit(**kw):
    print(json.dumps(kw), flush=True)


def timed(fn, *a, **k):
    t0, c0 = time.perf_counter(), time.process_time()
    out = fn(*a, **k)
    return out, time.perf_counter() - t0, time.process_time() - c0


def bench_dtm10m():
    rng = np.random.default_rng(0)
    n, w = 10_000_000, 1000.0
    x, y = rng.uniform(0, w, n), rng.uniform(0, w, n)
    z = 100 + 5 * np.sin(x / 60) + 3 * np.cos(y / 45) + rng.normal(0, 0.05, n)
    cls = rng.choice(np.array([1, 2, 5], np.uint8), n, p=[0.2, 0.6, 0.2])
    c = Cloud(np.column_stack([x + 500_000, y + 5_000_000, z]), {"classification": cls}, crs="EPSG:32632")
    del x, y, z, cls
    rss0 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    r, wall, cpu = timed(build_dem, c, DemParams(kind="dtm", resolution=1.0))
    rss1 = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    emit(bench="dtm_10M_points_1m", points=n, ground_points=int((c.attrs["classification"] == 2).sum()),
         cells=int(r.array.size), wall_s=round(wall, 2), cpu_s=round(cpu, 2), peak_rss_mb=round(rss1, 0),
         rss_before_mb=round(rss0, 0), goal_s=15.0)


def bench_stream(tmp: Path):
    """DTM of a 10M-point LAZ streamed in 1M-point chunks, in a child process.

    Peak memory is the child's VmHWM (reset at exec; ``ru_maxrss`` would carry the parent's)."""
    import subprocess

    from workstation.io import write_cloud

    rng = np.random.default_rng(2)
    n, w = 10_000_000, 1000.0
    x, y = rng.uniform(0, w, n), rng.uniform(0, w, n)
    z = 100 + 5 * np.sin(x / 60) + 3 * np.cos(y / 45) + rng.normal(0, 0.05, n)
    cls = rng.choice(np.array([1, 2, 5], np.uint8), n, p=[0.2, 0.6, 0.2])
    path = tmp / "ten_million.laz"
    write_cloud(Cloud(np.column_stack([x + 500_000, y + 5_000_000, z]), {"classification": cls}, crs="EPSG:32632"), path)
    del x, y, z, cls
    for tile in (0, 256):
        code = (
            "import time,json;from workstation.raster.dem import build_dem,DemParams;"
            f"t=time.perf_counter();r=build_dem('{path}',DemParams(resolution=1.0),chunk_size=1_000_000,tile_cells={tile},buffer_cells=64);"
            "print(json.dumps({'wall_s':round(time.perf_counter()-t,2),'cpu_s':round(time.process_time(),2),"
            "'cells':int(r.array.size),'peak_rss_mb':[round(int(l.split()[1])/1024) for l in open('/proc/self/status')"
            " if l.startswith('VmHWM')][0]}))"
        )
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, "PYTHONPATH": str(REPO)})
        res = json.loads(out.stdout.strip().splitlines()[-1]) if out.returncode == 0 else {"error": out.stderr[-500:]}
        emit(bench="dtm_10M_points_streamed_laz", points=n, file_mb=round(path.stat().st_size / 2**20, 1), chunk_points=1_000_000,
             tiles="single pass" if tile == 0 else f"{tile}x{tile} cells + 64 overlap, spilled to temp files", **res)


def bench_contours(tmp: Path):
    from workstation.raster.contours import ContourParams, contour_lines, write_geojson

    n = 4000
    y, x = np.mgrid[0:n, 0:n].astype(np.float64)
    z = 100 + 20 * np.sin(x / 300) * np.cos(y / 250) + 0.01 * x + 0.3 * np.sin(x / 13) * np.sin(y / 17)
    r = Raster(z, (1, 0, 500_000, 0, -1, 5_004_000), "EPSG:32632")
    cs, wall, cpu = timed(contour_lines, r, ContourParams(interval=1.0))
    _, wall_w, cpu_w = timed(write_geojson, cs, tmp / "c.geojson", overwrite=True)
    emit(bench="contours_4000x4000", levels=int(len(set(cs.levels.tolist()))), lines=len(cs),
         vertices=int(sum(len(p) for p in cs.lines)), wall_s=round(wall, 2), cpu_s=round(cpu, 2),
         geojson_write_wall_s=round(wall_w, 2), geojson_write_cpu_s=round(cpu_w, 2), goal_s=5.0)


def bench_synthetic():
    rng = np.random.default_rng(1)
    size, n, noise = 300.0, 600_000, 0.05
    terrain = lambda x, y: 100 + 0.03 * x - 0.02 * y + 1.5 * np.sin(x / 40) * np.cos(y / 55)  # noqa: E731
    blds = [(40, 50, 70, 80, 12), (150, 120, 185, 170, 20), (220, 40, 260, 70, 8), (100, 220, 130, 260, 15)]
    x, y = rng.uniform(0, size, n), rng.uniform(0, size, n)
    zt = terrain(x, y)
    cls = np.full(n, int(ASPRSClass.GROUND), np.uint8)
    z = zt.copy()
    for x0, y0, x1, y1, h in blds:
        m = (x >= x0) & (x < x1) & (y >= y0) & (y < y1)
        z[m] = terrain((x0 + x1) / 2, (y0 + y1) / 2) + h
        cls[m] = int(ASPRSClass.BUILDING)
    xyz = np.column_stack([x, y, z + rng.normal(0, noise, n)])
    clean = np.column_stack([x, y, z])
    for method in ("tin", "nn", "idw"):
        r = build_dem(Cloud(xyz, {"classification": cls}), DemParams(kind="dtm", resolution=1.0, method=method))
        r0 = build_dem(Cloud(clean, {"classification": cls}), DemParams(kind="dtm", resolution=1.0, method=method))
        X, Y = r.cell_centers()
        bld = np.zeros(X.shape, bool)
        for x0, y0, x1, y1, _ in blds:
            bld |= (X >= x0) & (X < x1) & (Y >= y0) & (Y < y1)
        e = r.array - terrain(X, Y)
        e0 = r0.array - terrain(X, Y)
        rmse = float(np.sqrt(np.nanmean(e[~bld] ** 2)))
        interp = float(np.sqrt(np.nanmean(e0[~bld] ** 2)))
        emit(bench="synthetic_dtm", method=method, points=n, density_per_m2=n / size**2, noise_m=noise,
             rmse_open_m=round(rmse, 4), interpolation_rmse_m=round(interp, 4),
             goal_rmse_m=round(1.5 * noise + interp, 4), max_abs_err_buildings_m=round(float(np.nanmax(np.abs(e[bld]))), 4),
             goal_buildings_m=0.3)


def _csf_ground(path: Path) -> Cloud:
    """Ground by the CSF library (Zhang et al. 2016): stand-in while our ground filter is not on main."""
    import CSF

    from workstation.io import read_cloud

    c = read_cloud(path)
    csf = CSF.CSF()
    csf.params.bSloopSmooth = True
    csf.params.cloth_resolution = 0.5
    csf.params.rigidness = 2
    csf.params.class_threshold = 0.25
    csf.params.interations = 500
    xyz = c.xyz - c.xyz.min(0)
    csf.setPointCloud(xyz)
    g, ng = CSF.VecInt(), CSF.VecInt()
    sys.stdout.flush()
    saved = os.dup(1)
    os.dup2(os.open(os.devnull, os.O_WRONLY), 1)  # CSF prints progress on stdout (C++)
    try:
        csf.do_filtering(g, ng, exportCloth=False)
    finally:
        os.dup2(saved, 1)
        os.close(saved)
    cls = np.full(c.n, int(ASPRSClass.UNCLASSIFIED), np.uint8)
    cls[np.array(g, dtype=np.int64)] = int(ASPRSClass.GROUND)
    return c.with_attrs(classification=cls)


def _ground_filter(path: Path):
    """Our ground filter when it is on main (workstation.ground), else the CSF library."""
    try:
        from workstation.ground import csf as ours  # type: ignore[attr-defined]

        fn = getattr(ours, "csf", None) or getattr(ours, "classify_ground", None)
        if fn is not None:
            from workstation.io import read_cloud

            return fn(read_cloud(path)), "workstation.ground.csf"
    except ImportError:
        pass
    return _csf_ground(path), "CSF library 1.1.7 (stand-in; workstation.ground not on main)"


def bench_real(docs_img: Path | None):
    from workstation.raster.grid import GridSpec

    files = [DATA / "lidar" / "bcts_1.laz", DATA / "lidar" / "bcts_2.laz"]
    if not all(f.exists() for f in files):
        emit(bench="real_tiles", skipped=f"{DATA}/lidar/bcts_*.laz absent")
        return
    p = DemParams(kind="dtm", resolution=1.0)
    mosaic, wall, cpu = timed(build_dem, files, p)
    grid = GridSpec.from_transform(mosaic.transform, mosaic.shape)
    emit(bench="real_mosaic_dtm", files=[f.name for f in files], rows=mosaic.shape[0], cols=mosaic.shape[1],
         points=mosaic.meta["points"], wall_s=round(wall, 2), cpu_s=round(cpu, 2))
    # the two tiles separately on the same grid, pasted: what a seam looks like
    singles = [build_dem(f, p, grid=grid).array for f in files]
    edge_y = 629400.0
    X, Y = mosaic.cell_centers()
    south = Y < edge_y
    pasted = np.where(south, singles[0], singles[1])
    r_e = int(np.argmax(Y[:, 0] < edge_y))  # first row south of the edge
    def jump(a, r):
        d_edge = a[r - 1] - a[r]
        d_n = a[r - 2] - a[r - 1]
        d_s = a[r] - a[r + 1]
        ex = d_edge - 0.5 * (d_n + d_s)
        ok = np.isfinite(ex)
        return float(np.mean(ex[ok])), float(np.mean(np.abs(ex[ok]))), int(ok.sum())
    m_signed, m_abs, ncols = jump(mosaic.array, r_e)
    p_signed, p_abs, _ = jump(pasted, r_e)
    i_signed, i_abs, _ = jump(mosaic.array, r_e + 40)
    both = np.isfinite(singles[0]) & np.isfinite(mosaic.array) & south
    interior = both & (Y < edge_y - 10)
    emit(bench="real_mosaic_seam", edge_y=edge_y, columns=ncols,
         mosaic_edge_excess_mean_m=round(m_signed, 4), mosaic_edge_excess_abs_m=round(m_abs, 4),
         interior_row_excess_mean_m=round(i_signed, 4), interior_row_excess_abs_m=round(i_abs, 4),
         pasted_tiles_edge_excess_mean_m=round(p_signed, 4), pasted_tiles_edge_excess_abs_m=round(p_abs, 4),
         mosaic_vs_single_tile_interior_max_m=round(float(np.abs(mosaic.array - singles[0])[interior].max()), 4),
         goal_m=0.05)
    # ground filter vs the files' own class 2
    from workstation.core.cloud import concatenate

    gf, which = zip(*[_ground_filter(f) for f in files])
    ours = build_dem(concatenate(list(gf)), p, grid=grid)
    d = ours.array - mosaic.array
    ok = np.isfinite(d)
    emit(bench="real_dtm_ground_filter_vs_file_class", filter=which[0],
         ground_points_filter=int(sum((c.attrs["classification"] == 2).sum() for c in gf)),
         ground_points_file=int(mosaic.meta["points"]), cells=int(ok.sum()),
         rmse_m=round(float(np.sqrt(np.mean(d[ok] ** 2))), 4), mean_m=round(float(np.mean(d[ok])), 4),
         p95_abs_m=round(float(np.percentile(np.abs(d[ok]), 95)), 4), goal_rmse_m=0.25)
    if docs_img is not None:
        figures(files[1], docs_img)


def figures(path: Path, docs_img: Path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from workstation.raster.contours import ContourParams, contour_lines
    from workstation.raster.terrain import HillshadeParams, hillshade

    docs_img.mkdir(parents=True, exist_ok=True)
    dsm = build_dem(path, DemParams(kind="dsm", resolution=0.5))
    dtm = build_dem(path, DemParams(kind="dtm", resolution=1.0))
    hs_dsm = hillshade(dsm, HillshadeParams(315, 45, 1.0)).array
    hs_dtm = hillshade(dtm, HillshadeParams(315, 45, 3.0)).array
    fig, ax = plt.subplots(1, 2, figsize=(8, 6.2), dpi=90)
    for a, img, title in ((ax[0], hs_dsm, "DSM 0.5 m, hillshade"), (ax[1], hs_dtm, "DTM 1 m, hillshade (z×3)")):
        a.imshow(np.ma.masked_equal(img, 0), cmap="gray", extent=_extent(dsm if img is hs_dsm else dtm))
        a.set_title(f"{path.name}: {title}", fontsize=9)
        a.tick_params(labelsize=6)
    fig.tight_layout()
    _save_small(fig, docs_img / "raster_hillshade_bcts_2.png", grey=True)
    cs = contour_lines(dtm, ContourParams(interval=1.0, smooth=1))
    fig, a = plt.subplots(figsize=(5.5, 6.5), dpi=90)
    a.imshow(np.ma.masked_equal(hs_dtm, 0), cmap="gray", alpha=0.5, extent=_extent(dtm))
    for pts, idx in zip(cs.lines, cs.index):
        a.plot(pts[:, 0], pts[:, 1], color="saddlebrown", lw=1.0 if idx else 0.4)
    for pts, lev, idx in zip(cs.lines, cs.levels, cs.index):
        if idx and len(pts) > 40:
            m = pts[len(pts) // 2]
            a.text(m[0], m[1], f"{lev:g}", fontsize=6, color="saddlebrown")
    a.set_title(f"{path.name}: DTM contours, 1 m (index every 5 m)", fontsize=9)
    a.tick_params(labelsize=6)
    fig.tight_layout()
    _save_small(fig, docs_img / "raster_contours_bcts_2.png", grey=False)
    emit(bench="figures", files=[str(docs_img / "raster_hillshade_bcts_2.png"), str(docs_img / "raster_contours_bcts_2.png")],
         contour_lines=len(cs))


def _save_small(fig, path: Path, grey: bool):
    """PNG under 300 KB: greyscale or a 64-colour palette (PIL), written atomically."""
    import io

    import matplotlib.pyplot as plt
    from PIL import Image as PILImage

    from workstation.io import atomic_path

    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    im = PILImage.open(buf).convert("RGB")
    im = im.convert("L") if grey else im.quantize(colors=64)
    with atomic_path(path, overwrite=True) as tmp:
        im.save(tmp, format="PNG", optimize=True)


def _extent(r: Raster):
    a, _, c, _, e, f = r.transform
    rows, cols = r.shape
    return (c, c + a * cols, f + e * rows, f)


def bench_ortho(tmp: Path):
    import cv2
    from scipy.ndimage import binary_erosion, distance_transform_edt

    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.raster.ortho import OrthoParams, true_ortho
    from workstation.raster.synthetic_aerial import AerialRig, AerialScene, make_dataset

    scene, rig, res = AerialScene(), AerialRig(), 0.5
    js, wall_r, _ = timed(make_dataset, tmp / "aerial", scene, rig)
    rec = read_reconstruction(js)
    dsm = scene.true_dsm(res)
    X, Y = dsm.cell_centers()
    fp = scene.footprints(X, Y) >= 0
    dist = distance_transform_edt(~(fp ^ binary_erosion(fp)))
    truth = scene.true_ortho(res)
    dtm = Raster(scene.terrain(X, Y).astype(np.float32), dsm.transform, dsm.crs)
    for label, surface, occ in (("true_ortho_dsm", dsm, True), ("dsm_no_occlusion", dsm, False), ("over_dtm", dtm, True)):
        o, wall, cpu = timed(true_ortho, rec, surface, OrthoParams(occlusion=occ))
        a = o.ortho.array
        seen = a[3] > 0
        rgb = a[:3].transpose(1, 2, 0)
        err = float(np.abs(rgb.astype(float) - truth)[seen].mean())
        g1 = cv2.cvtColor(np.ascontiguousarray(rgb), cv2.COLOR_RGB2GRAY).astype(float) * seen
        g2 = cv2.cvtColor(truth, cv2.COLOR_RGB2GRAY).astype(float) * seen
        (dx, dy), _ = cv2.phaseCorrelate(g1, g2)
        roof = (rgb[..., 0] > 150) & (rgb[..., 1] < 56)
        wrong = (roof ^ fp) & seen
        emit(bench="ortho_synthetic", variant=label, images=len(rec.images), image_px=[rig.width, rig.height_px],
             cells=int(seen.size), coverage=round(float(seen.mean()), 4), mean_colour_error_255=round(err, 2),
             shift_cells=round(float(np.hypot(dx, dy)), 3), roof_edge_max_offset_cells=round(float(dist[wrong].max(initial=0)), 2),
             render_wall_s=round(wall_r, 2), ortho_wall_s=round(wall, 2), ortho_cpu_s=round(cpu, 2),
             goals={"shift_cells": 1, "colour_255": 12, "roof_edge_cells": 1})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default="dtm10m,stream,contours,synthetic,real,ortho")
    ap.add_argument("--docs-img", default=None)
    args = ap.parse_args()
    which = set(args.only.split(","))
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        if "synthetic" in which:
            bench_synthetic()
        if "ortho" in which:
            bench_ortho(tmp)
        if "real" in which:
            bench_real(Path(args.docs_img) if args.docs_img else None)
        if "contours" in which:
            bench_contours(tmp)
        if "dtm10m" in which:
            bench_dtm10m()
        if "stream" in which:
            bench_stream(tmp)


if __name__ == "__main__":
    main()
