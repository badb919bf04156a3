"""Dense reconstruction benchmarks (issue 7). Prints one JSON line per result.

    python scripts/bench_dense.py rig       # synthetic heritage rig, 24 images, SfM cameras
    python scripts/bench_dense.py rig --recipe rig_aerial --samples-on all   # aerial block
    python scripts/bench_dense.py rig --dist -0.12 0.05 [--camera given]    # radial distortion
    python scripts/bench_dense.py temple    # Middlebury templeSparseRing, true cameras
    python scripts/bench_dense.py fountain  # Strecha fountain-P11 at 1536 px, true cameras
    python scripts/bench_dense.py fountain --images 6   # same size, fewer images (memory)
    python scripts/bench_dense.py fusion --dense-dir DIR --fusion-cache-gb 0   # fusion alone

CPU depth-map method (issue 24): ``--method sgbm`` / ``sweep`` runs one; ``--method both``
(the default) runs the sweep and then SGBM, each in its own process (so each peak RSS is its
own), one after the other on the same data, and for the temple and the fountain adds a line
comparing the two fused clouds (``compare``: share of one cloud's points with a point of the
other within a radius, and median nearest distances).

Options: --work DIR (scratch folder, default /tmp/bench_dense), --reuse (keep a rendered rig
and its SfM workdir), --render PNG (off-screen view of the dense cloud).
Wall time is contended on a shared machine; ``cpu_s`` (process CPU time) is also reported.
Peak memory is the process's maximum resident set size.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

DATA = Path(os.environ.get("WS_SHARED_DATA", "/work/shared/data")) / "images" / "sfm"


def _peak_gb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024**2


def _emit(d: dict) -> None:
    print(json.dumps(d), flush=True)


def _surface_samples(V, F, mask, cams, n=60_000, seed=0):
    """Area-weighted samples on the faces in ``mask`` seen (unoccluded, in frame) by ≥ 2 cameras."""
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.photogrammetry.collinearity import project

    rng = np.random.default_rng(seed)
    tri = V[F[mask]]
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    k = rng.choice(len(tri), n, p=area / area.sum())
    a, b = rng.random(n), rng.random(n)
    flip = a + b > 1
    a[flip], b[flip] = 1 - a[flip], 1 - b[flip]
    P = tri[k, 0] + a[:, None] * (tri[k, 1] - tri[k, 0]) + b[:, None] * (tri[k, 2] - tri[k, 0])
    sc = RaycastScene(V, F)
    seen = np.zeros(n, int)
    for cam, pose in cams:
        C = pose.center
        d = P - C
        dist = np.linalg.norm(d, axis=1)
        t, _ = sc.cast(np.broadcast_to(C, d.shape), d / dist[:, None])
        uv, z = project(P, cam, pose, return_depth=True)
        inside = (z > 0) & (uv[:, 0] >= 0) & (uv[:, 0] < cam.width) & (uv[:, 1] >= 0) & (uv[:, 1] < cam.height)
        seen += inside & (np.abs(t - dist) < 0.002 * dist + 1e-3)
    return P[seen >= 2]


def _render(cloud, path, view=None) -> None:
    """Off-screen render (workstation.render, pyvista/VTK) of a dense cloud in its RGB colours:
    from ``view`` = (Camera, Pose) scaled to 900 px wide, else the iso view."""
    from dataclasses import replace

    from workstation.render.render import RenderParams, render, save_png

    params = RenderParams(size=(900, 675), color="rgb", view="iso", point_size=2.0)
    if view is not None:
        cam, pose = view
        s = 900.0 / cam.width
        cam = replace(cam, width=900, height=round(cam.height * s), fx=cam.fx * s, fy=cam.fy * s,
                      cx=(cam.cx + 0.5) * s - 0.5, cy=(cam.cy + 0.5) * s - 0.5, dist=(0.0,) * 5, model="PINHOLE")
        img = render(cloud, params, camera=(cam, pose))
    else:
        img = render(cloud, params)
    save_png(img, path, overwrite=True)


def bench_rig(work: Path, reuse: bool, render: str | None, min_consistent: int = 1, min_ncc: float = 0.4,
              fusion_min_pixels: int = 2, recipe_name: str = "rig_heritage", dist=None, camera: str = "self",
              samples_on: str = "target", scale: float = 1.0) -> None:
    """Render a synthetic rig, orient it by SfM, densify, compare with the true mesh.

    ``dist``: (k1, k2) radial distortion rendered into the images; ``camera``: "self" (SfM
    self-calibrates: RADIAL with distortion, else the SfM default) or "given" (the true
    intrinsics and distortion, held fixed, as ``ws sfm --camera``) or "true" (no SfM: the rig's
    true cameras, with a loose depth range of 0.1-2.4 times the rig's distance); ``samples_on``: "target"
    (completeness on the target object) or "all" (every surface seen by ≥ 2 true cameras);
    ``scale``: image size and focal length times this (same footprint), one ray per pixel below 1.
    """
    from dataclasses import replace

    from workstation.photogrammetry.dense import evaluate, run_dense
    from workstation.photogrammetry.georef import fit_similarity
    from workstation.photogrammetry.rigs import load_rig, load_truth, make_rig
    from workstation.photogrammetry.sfm import SfMParams, run_sfm
    from workstation.photogrammetry.sfm import read_reconstruction

    recipe, spec = load_rig(Path(__file__).resolve().parents[1] / "datasets_synth" / f"{recipe_name}.toml")
    tag = recipe_name
    if scale != 1.0:
        spec = replace(spec, width=round(spec.width * scale), height=round(spec.height * scale),
                       focal_px=spec.focal_px * scale, supersample=spec.supersample if scale >= 1 else 1)
        tag += f"_x{scale:g}"
    if dist is not None:
        spec = replace(spec, dist=(float(dist[0]), float(dist[1]), 0.0, 0.0, 0.0))
        tag += f"_k1_{dist[0]:g}_k2_{dist[1]:g}"
    rigdir, sfmdir = work / tag, work / f"{tag}_sfm_{camera}"
    t0 = time.perf_counter()
    if not (reuse and (rigdir / "truth_mesh.npz").exists()):
        make_rig(recipe, spec, rigdir, overwrite=True)
    t_render = time.perf_counter() - t0
    t0 = time.perf_counter()
    extra = {}
    if camera == "true":
        shutil.rmtree(sfmdir, ignore_errors=True)
        shutil.copytree(rigdir / "sparse" / "0", sfmdir / "sparse" / "0")
        extra["depth_range"] = (0.1 * spec.distance, 2.4 * spec.distance)
    elif not (reuse and (sfmdir / "sparse" / "0").exists()):
        sfm_cam = spec.camera() if camera == "given" else None
        sfm_params = SfMParams(camera_model="RADIAL") if dist is not None and camera == "self" else SfMParams()
        run_sfm(rigdir / "images", sfmdir, sfm_cam, params=sfm_params, overwrite=True)
    t_sfm = time.perf_counter() - t0
    c0, t0 = time.process_time(), time.perf_counter()
    cloud, summary = run_dense(sfmdir, rigdir / "images", _params(min_consistent=min_consistent, min_ncc=min_ncc,
                                                                  fusion_min_pixels=fusion_min_pixels, **extra),
                               overwrite=True)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    true = read_reconstruction(rigdir / "cameras.json")
    est = read_reconstruction(sfmdir / "sparse" / "0")
    est_cam = next(iter(est.cameras.values()))
    by_name = {im.name: im for im in true.images.values()}
    pairs = [(im.pose.center, by_name[im.name].pose.center) for im in est.images.values() if im.name in by_name]
    sim = fit_similarity(np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs]))
    xyz = sim.apply(cloud.xyz)
    T = load_truth(rigdir)
    cams = [(true.cameras[im.camera_id], im.pose) for im in true.images.values()]
    mask = T["target"] if samples_on == "target" else np.ones(len(T["faces"]), bool)
    samples = _surface_samples(T["vertices"], T["faces"], mask, cams)
    ev = evaluate(xyz, T["vertices"], T["faces"], float(T["extent"]), samples)
    gsd = None
    if spec.layout == "grid":
        gsd = spec.distance / spec.focal_px  # ground sampling distance at the base of the target, m
    _emit({"bench": f"dense_{tag}", **_method_fields(), "layout": spec.layout, "camera": camera, "true_dist": list(spec.dist[:2]),
           "sfm_camera": {"model": est_cam.model, "f": round(est_cam.fx, 1), "dist": [round(float(x), 4) for x in est_cam.dist[:2]]},
           "min_consistent": min_consistent, "min_ncc": min_ncc, "fusion_min_pixels": fusion_min_pixels,
           "registered": len(pairs), "images": len(true.images), "sim_scale": round(float(sim.scale), 5),
           "render_s": round(t_render, 1), "sfm_s": round(t_sfm, 1), "dense_wall_s": round(wall, 1),
           "dense_cpu_s": round(cpu, 1), "peak_gb": round(_peak_gb(), 2),
           **{k: (round(v, 5) if isinstance(v, float) else v) for k, v in ev.items()},
           "accuracy_gsd": None if gsd is None else round(ev["accuracy_median"] / gsd, 3),
           "samples_on": samples_on, "samples": len(samples), "summary": summary["timings_s"]})
    if render:
        _render(cloud.with_xyz(xyz), render)


def _true_workdir(work: Path, name: str, cams: list) -> Path:
    """A COLMAP workdir (sparse/0) holding true cameras; images are read from the data folder."""
    from workstation.core.products import Reconstruction
    from workstation.photogrammetry.rigs import write_colmap_text

    wd = work / name
    if wd.exists():
        shutil.rmtree(wd)
    from workstation.core.products import Image

    cameras, images = {}, {}
    for k, (img, cam, pose) in enumerate(cams, start=1):
        cameras[k] = cam
        images[k] = Image(img, k, pose)
    write_colmap_text(Reconstruction(cameras, images), wd / "sparse" / "0")
    return wd


def bench_temple(work: Path, render: str | None) -> None:
    from workstation.core.products import Camera, Pose
    from workstation.photogrammetry.dense import run_dense

    folder = DATA / "middlebury_templeSparseRing"
    cams = []
    for line in (folder / "templeSR_par.txt").read_text().splitlines()[1:]:
        f = line.split()
        v = np.array(f[1:], float)
        K, R, t = v[:9].reshape(3, 3), v[9:18].reshape(3, 3), v[18:21]
        cams.append((f[0], Camera(640, 480, K[0, 0], K[1, 1], K[0, 2], K[1, 2]), Pose(R, t)))
    wd = _true_workdir(work, f"temple_{METHOD['method']}", cams)
    c0, t0 = time.process_time(), time.perf_counter()
    cloud, summary = run_dense(wd, folder, _params(depth_range=(0.45, 0.8), max_image_size=-1), overwrite=True)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    lo, hi = np.array([-0.073568, 0.021728, -0.012445]), np.array([0.028855, 0.181892, 0.062736])
    inside = np.all((cloud.xyz >= lo - 0.005) & (cloud.xyz <= hi + 0.005), axis=1)
    _emit({"bench": "dense_middlebury_templeSR", **_method_fields(), "fused": str(wd / "dense" / "fused.ply"), "images": len(cams), "points": cloud.n, "wall_s": round(wall, 1),
           "cpu_s": round(cpu, 1), "peak_gb": round(_peak_gb(), 2), "inside_bbox": round(float(inside.mean()), 4),
           "goal_wall_s": 180, "summary": summary["timings_s"]})
    if render:
        _render(cloud, render, view=cams[0][1:])


def fountain_cameras(folder: Path) -> list:
    """(image name, Camera, Pose) of the Strecha ``gt_dense_cameras/*.camera`` files of
    ``folder`` (K, distortion, camera-to-world R, centre C, size), by image name."""
    from workstation.core.products import Camera, Pose

    cams = []
    for p in sorted((folder / "gt_dense_cameras").glob("*.camera")):
        v = np.array(p.read_text().split(), float)
        K, Rcw, C, (w, h) = v[:9].reshape(3, 3), v[12:21].reshape(3, 3), v[21:24], v[24:26]
        R = Rcw.T
        cams.append((p.name.replace(".camera", ""), Camera(int(w), int(h), K[0, 0], K[1, 1], K[0, 2], K[1, 2]), Pose(R, -R @ C)))
    return cams


def bench_fountain(work: Path, size: int, render: str | None, n_images: int = 0, fusion_cache_gb: float = 1.0) -> None:
    """fountain-P11 with true cameras, stage by stage (undistort, depth maps, fusion: what
    ``run_dense`` does on the CPU) so that the peak RSS after each stage is reported.
    ``n_images`` > 0 keeps the first n images (memory against image count at one size)."""
    from workstation.photogrammetry.dense import (
        compute_depth_maps,
        fuse,
        undistort,
    )

    folder = DATA / "strecha_fountain-P11"
    cams = fountain_cameras(folder)
    if n_images > 0:
        cams = cams[:n_images]
    name = f"fountain_{len(cams)}_{size}_{METHOD['method']}"
    wd = _true_workdir(work, name, cams)
    params = _params(depth_range=(3.0, 25.0), max_image_size=size, fusion_cache_gb=fusion_cache_gb)
    c0, t0 = time.process_time(), time.perf_counter()
    dense_dir = undistort(wd, folder / "images", size, overwrite=True)
    stats = compute_depth_maps(dense_dir, params)
    peak_depth, t_depth = _peak_gb(), time.perf_counter() - t0
    cloud = fuse(dense_dir, params)
    wall, cpu = time.perf_counter() - t0, time.process_time() - c0
    _emit({"bench": f"dense_fountain_P11_{size}", **_method_fields(), "size": size, "fused": str(dense_dir / "fused.ply"), "images": len(cams), "points": cloud.n, "wall_s": round(wall, 1),
           "cpu_s": round(cpu, 1), "depth_maps_wall_s": round(t_depth, 1), "peak_gb_after_depth_maps": round(peak_depth, 2),
           "peak_gb": round(_peak_gb(), 2), "fusion_cache_gb": fusion_cache_gb, "goal_wall_s": 900, "goal_peak_gb": 6,
           "valid_geometric": stats["valid_geometric"], "workdir": str(wd)})
    if render:
        _render(cloud, render, view=cams[len(cams) // 2][1:])


METHOD = {"method": "sgbm", "num_sources": None}


def _params(**kw):
    """DenseParams on the CPU with the method (and source count) chosen on the command line."""
    from workstation.photogrammetry.dense import DenseParams

    if METHOD["num_sources"]:
        kw["num_sources"] = METHOD["num_sources"]
        kw["top_k"] = min(2, METHOD["num_sources"])
    return DenseParams(device="cpu", method=METHOD["method"], **kw)


def _method_fields() -> dict:
    p = _params()
    return {"method": p.method, "num_sources": p.sources, "threads": os.cpu_count()}


def compare_clouds(a_path, b_path, radius: float, label: str) -> dict:
    """Agreement of cloud A (SGBM) with cloud B (sweep): the share of B's points with an A
    point within ``radius`` (A's completeness against B), the share of A's points with a B
    point within ``radius`` (A's points that B confirms), and the median nearest distances."""
    from scipy.spatial import cKDTree

    from workstation.io import read_cloud

    A, B = read_cloud(a_path).xyz, read_cloud(b_path).xyz
    dab, _ = cKDTree(B).query(A, k=1, workers=-1)
    dba, _ = cKDTree(A).query(B, k=1, workers=-1)
    return {"bench": f"compare_{label}", "a": str(a_path), "b": str(b_path), "points_a": len(A), "points_b": len(B),
            "radius": radius, "b_covered_by_a": round(float(np.mean(dba <= radius)), 4),
            "a_confirmed_by_b": round(float(np.mean(dab <= radius)), 4),
            "median_a_to_b": round(float(np.median(dab)), 5), "median_b_to_a": round(float(np.median(dba)), 5)}


def run_both(argv: list[str], what: str, reuse: bool) -> None:
    """Run the sweep then SGBM in child processes on the same data; compare the fused clouds."""
    import subprocess

    lines = {}
    for k, m in enumerate(("sweep", "sgbm")):
        extra = ["--reuse"] if (what == "rig" and k > 0 and not reuse) else []
        out = subprocess.run([sys.executable, __file__, *argv, "--method", m, *extra], check=True,
                             stdout=subprocess.PIPE, text=True).stdout
        for line in out.splitlines():
            print(line, flush=True)
            if line.startswith("{"):
                lines[m] = json.loads(line)
    if what in ("temple", "fountain") and "fused" in lines.get("sgbm", {}) and "fused" in lines.get("sweep", {}):
        # radius: 3 pixel footprints at the scene (temple: 0.5 mm/px at 0.6 m; fountain at
        # 1536 px: 6 mm/px at 8.5 m, scaled with the image size)
        r = 0.0015 if what == "temple" else 0.018 * 1536 / lines["sgbm"].get("size", 1536)
        _emit(compare_clouds(lines["sgbm"]["fused"], lines["sweep"]["fused"], r, what))


def bench_fusion(dense_dir: Path, fusion_cache_gb: float) -> None:
    """Fusion alone on an existing workspace (its peak RSS, with and without the cache)."""
    from workstation.photogrammetry.dense import DenseParams, fuse

    base = _peak_gb()
    c0, t0 = time.process_time(), time.perf_counter()
    cloud = fuse(dense_dir, DenseParams(device="cpu", fusion_cache_gb=fusion_cache_gb))
    _emit({"bench": "dense_fusion", "workspace": str(dense_dir), "fusion_cache_gb": fusion_cache_gb, "points": cloud.n,
           "wall_s": round(time.perf_counter() - t0, 1), "cpu_s": round(time.process_time() - c0, 1),
           "peak_gb_before": round(base, 2), "peak_gb": round(_peak_gb(), 2)})


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=["rig", "temple", "fountain", "fusion"])
    ap.add_argument("--work", default="/tmp/bench_dense")
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--render")
    ap.add_argument("--size", type=int, default=1536)
    ap.add_argument("--min-consistent", type=int, default=1)
    ap.add_argument("--min-ncc", type=float, default=0.4)
    ap.add_argument("--fusion-min-pixels", type=int, default=2)
    ap.add_argument("--recipe", default="rig_heritage", help="rig: datasets_synth/NAME.toml")
    ap.add_argument("--dist", type=float, nargs=2, metavar=("K1", "K2"), help="rig: render with radial distortion")
    ap.add_argument("--camera", choices=["self", "given", "true"], default="self",
                    help="rig: SfM self-calibrates, gets the true camera, or is skipped for the true poses")
    ap.add_argument("--scale", type=float, default=1.0, help="rig: image size and focal length times this")
    ap.add_argument("--samples-on", choices=["target", "all"], default="target", help="rig: completeness samples")
    ap.add_argument("--images", type=int, default=0, help="fountain: keep the first N images (0: all)")
    ap.add_argument("--fusion-cache-gb", type=float, default=1.0)
    ap.add_argument("--dense-dir", help="fusion: an existing dense workspace")
    ap.add_argument("--method", choices=["sgbm", "sweep", "both"], default="both", help="CPU depth maps (both: side by side)")
    ap.add_argument("--sources", type=int, default=0, help="source views per image (0: DenseParams default)")
    a = ap.parse_args()
    if a.method == "both" and a.what != "fusion":
        argv = [x for i, x in enumerate(sys.argv[1:]) if x != "--method" and (i == 0 or sys.argv[i] != "--method")]
        run_both(argv, a.what, a.reuse)
        return
    METHOD["method"] = "sgbm" if a.method == "both" else a.method
    METHOD["num_sources"] = a.sources or None
    work = Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    if a.what == "rig":
        bench_rig(work, a.reuse, a.render, a.min_consistent, a.min_ncc, a.fusion_min_pixels, a.recipe, a.dist,
                  a.camera, a.samples_on, a.scale)
    elif a.what == "temple":
        bench_temple(work, a.render)
    elif a.what == "fountain":
        bench_fountain(work, a.size, a.render, a.images, a.fusion_cache_gb)
    else:
        bench_fusion(Path(a.dense_dir), a.fusion_cache_gb)


if __name__ == "__main__":
    main()
