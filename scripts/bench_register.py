"""Registration benchmarks; prints one JSON line per result.

  PYTHONPATH=. python scripts/bench_register.py [--data ../shared/data] [--skip-bunny] [--o3d-iterations 3]

1. Stanford bunny bun045 -> bun000 and bun090 -> bun000 from identity (``ws register`` defaults):
   rotation / translation error against bun.conf, wall and CPU seconds.
2. ICP on 1 million points, 30 iterations: our voxel-plane point-to-plane ICP beside Open3D's
   plain point-to-point and point-to-plane ICP on the same clouds. Open3D runs
   ``--o3d-iterations`` iterations and its time is also scaled to 30 (per-iteration cost is
   constant once correspondences settle), so a shared machine is not held for minutes.
3. ``--tls-laz``: every pair of stations of a simulated TLS survey, each station in a random
   frame, and a pose graph over all of them from the identity.
4. ``--colorize-sim``: colour a simulated TLS station from 8 synthetic photos (z-buffer, depth
   maps at pixel centres, footprint-minimum depth maps) and check against the scene.
5. ``--sfm-tls WORKDIR``: SfM-dense cloud of the heritage photo rig (render, ``ws sfm``, CPU
   dense, cached in WORKDIR) registered in 7 DoF to a simulated TLS survey of the same scene.
6. ``--merge-bunny``: the three bunny scans as a multi-station set through ``ws merge --register``'s
   pose graph, in two input orders and in random frames, against bun.conf; beside Open3D's
   multiway-registration tutorial.
Wall times on a shared machine are contended: CPU seconds (process_time) are given beside them.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "registration"))


def emit(d):
    print(json.dumps(d), flush=True)


def bench_bunny(data: Path):
    from test_reg_bunny import bunny_truth, read_bunny_ply

    from workstation.core.cloud import Cloud
    from workstation.registration.register import RegisterParams, register
    from workstation.registration.transforms import transform_error

    d = data / "registration"
    truth = bunny_truth(d / "bun.conf")
    tgt = Cloud(read_bunny_ply(d / "bun000.ply"))
    for scan in ("bun045.ply", "bun090.ply"):
        src = Cloud(read_bunny_ply(d / scan))
        w0, c0 = time.perf_counter(), time.process_time()
        r = register(src, tgt, RegisterParams())
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        rot, tr = transform_error(r.transform, truth[scan])
        emit({"bench": "bunny", "pair": f"{scan}->bun000.ply", "rotation_error_deg": round(rot, 4),
              "translation_error_mm": round(tr * 1000, 4), "fitness": round(r.fitness, 4),
              "coarse": r.meta.get("coarse_method"), "wall_s": round(wall, 2), "cpu_s": round(cpu, 2),
              "load1": os.getloadavg()[0]})


def bench_bunny_open3d(data: Path, voxel: float = 0.003):
    """Open3D's global-registration tutorial pipeline on the bunny pairs, unchanged except the
    voxel size: voxel downsampling, normals (radius 2 voxel, signs as Open3D leaves them),
    FPFH (5 voxel), RANSAC with mutual filter (100000 iterations, 0.999), point-to-plane ICP
    at 0.4 voxel."""
    import open3d as o3d
    from test_reg_bunny import bunny_truth, read_bunny_ply

    from workstation.interop.open3d import points_to_legacy
    from workstation.registration.transforms import transform_error

    reg = o3d.pipelines.registration
    d = data / "registration"
    truth = bunny_truth(d / "bun.conf")

    def prep(p):
        down = p.voxel_down_sample(voxel)
        down.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2 * voxel, max_nn=30))
        f = reg.compute_fpfh_feature(down, o3d.geometry.KDTreeSearchParamHybrid(radius=5 * voxel, max_nn=100))
        return down, f

    tgt_full = points_to_legacy(read_bunny_ply(d / "bun000.ply"))
    tgt_full.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2 * voxel, max_nn=30))
    for scan in ("bun045.ply", "bun090.ply"):
        src_full = points_to_legacy(read_bunny_ply(d / scan))
        w0, c0 = time.perf_counter(), time.process_time()
        (sd, sf), (td, tf) = prep(src_full), prep(tgt_full)
        dist = 1.5 * voxel
        r = reg.registration_ransac_based_on_feature_matching(
            sd, td, sf, tf, True, dist, reg.TransformationEstimationPointToPoint(False), 3,
            [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(dist)],
            reg.RANSACConvergenceCriteria(100000, 0.999))
        r2 = reg.registration_icp(src_full, tgt_full, 0.4 * voxel, r.transformation,
                                  reg.TransformationEstimationPointToPlane())
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        rot, tr = transform_error(np.asarray(r2.transformation), truth[scan])
        emit({"bench": "bunny_open3d_tutorial", "pair": f"{scan}->bun000.ply", "voxel": voxel,
              "rotation_error_deg": round(rot, 4), "translation_error_mm": round(tr * 1000, 4),
              "wall_s": round(wall, 2), "cpu_s": round(cpu, 2), "load1": os.getloadavg()[0]})


def terrain(n, rng):
    x = rng.uniform(-25, 25, (n, 2))
    z = np.sin(x[:, 0] / 3) * np.cos(x[:, 1] / 4) * 2 + 0.3 * np.sin(x[:, 0] * x[:, 1] / 40)
    return np.column_stack([x, z])


def bench_icp(n: int, o3d_iterations: int):
    import open3d as o3d

    from workstation.interop.open3d import points_to_legacy
    from workstation.registration.transforms import (
        apply_transform,
        invert,
        make_transform,
        random_rotation,
        transform_error,
    )
    from workstation.registration.voxelmap import VoxelPlanes, point_to_plane_voxel

    rng = np.random.default_rng(0)
    tgt = terrain(n, rng)
    T = make_transform(random_rotation(rng, 2.0), [0.15, -0.1, 0.05])
    src = apply_transform(invert(T), terrain(n, rng))
    voxel = 0.2
    w0, c0 = time.perf_counter(), time.process_time()
    planes = [VoxelPlanes.build(tgt, voxel * f) for f in (4.0, 2.0, 1.0)]
    wb, cb = time.perf_counter() - w0, time.process_time() - c0
    w0, c0 = time.perf_counter(), time.process_time()
    r = point_to_plane_voxel(src, tgt, voxel, iterations=30, planes=planes, tolerance=0.0)
    wi, ci = time.perf_counter() - w0, time.process_time() - c0
    rot, tr = transform_error(r.transform, T)
    emit({"bench": "icp_1M", "impl": "workstation voxel_plane (point-to-plane)", "points": n, "iterations": r.iterations,
          "build_wall_s": round(wb, 3), "build_cpu_s": round(cb, 3), "icp_wall_s": round(wi, 3), "icp_cpu_s": round(ci, 3),
          "rotation_error_deg": round(rot, 5), "translation_error_m": round(tr, 5), "load1": os.getloadavg()[0]})
    reg = o3d.pipelines.registration
    s = points_to_legacy(src)
    t = points_to_legacy(tgt)
    w0, c0 = time.perf_counter(), time.process_time()
    t.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=0.3, max_nn=20))
    wn = time.perf_counter() - w0
    for name, est in (("point_to_point", reg.TransformationEstimationPointToPoint()),
                      ("point_to_plane", reg.TransformationEstimationPointToPlane())):
        w0, c0 = time.perf_counter(), time.process_time()
        res = reg.registration_icp(s, t, 1.0, np.eye(4), est, reg.ICPConvergenceCriteria(0.0, 0.0, o3d_iterations))
        w, c = time.perf_counter() - w0, time.process_time() - c0
        rot, tr = transform_error(np.asarray(res.transformation), T)
        emit({"bench": "icp_1M", "impl": f"open3d {name}", "points": n, "iterations": o3d_iterations,
              "wall_s": round(w, 2), "cpu_s": round(c, 2), "wall_s_per_30_it": round(w * 30 / o3d_iterations, 1),
              "cpu_s_per_30_it": round(c * 30 / o3d_iterations, 1),
              "normals_wall_s": round(wn, 2) if name == "point_to_plane" else None,
              "rotation_error_deg": round(rot, 4), "translation_error_m": round(tr, 4), "load1": os.getloadavg()[0]})


def bench_tls(path: Path, seed: int = 0):
    """Stations of a simulated TLS survey (``point_source_id`` per station), each moved into its
    own frame by a random pose (up to 180 degrees about z, +-10 m, +-0.5 m in z), registered
    pairwise (every pair) and closed by a pose graph from the identity."""
    from workstation.io import read_cloud
    from workstation.registration.merge import transform_cloud
    from workstation.registration.posegraph import MultiwayParams, register_multiway
    from workstation.registration.transforms import (
        invert,
        make_transform,
        transform_error,
    )

    cloud = read_cloud(path)
    ids = np.unique(cloud.attrs["point_source_id"])
    rng = np.random.default_rng(seed)
    scans, G = [], []
    for i in ids:
        a = np.radians(rng.uniform(-180, 180))
        R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
        g = make_transform(R, np.append(rng.uniform(-10, 10, 2), rng.uniform(-0.5, 0.5)))
        scans.append(transform_cloud(cloud[cloud.attrs["point_source_id"] == i], g))
        G.append(g)
    w0, c0 = time.perf_counter(), time.process_time()
    mw = register_multiway(scans, MultiwayParams())
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    for e in mw.edges:
        rot, tr = transform_error(e.transform, G[e.target] @ invert(G[e.source]), center=scans[e.source].xyz.mean(axis=0))
        emit({"bench": "tls_pair", "source": int(e.source), "target": int(e.target), "kind": e.kind,
              "points": [scans[e.source].n, scans[e.target].n], "fitness": round(e.fitness, 4),
              "rotation_error_deg": round(rot, 4), "translation_error_m": round(tr, 4), "kept_in_graph": e.kept})
    errs = [transform_error(mw.poses[k], G[0] @ invert(G[k]), center=scans[k].xyz.mean(axis=0)) for k in range(len(scans))]
    n = len(scans)
    emit({"bench": "tls_pose_graph", "stations": n, "pairs_tried": n * (n - 1) // 2, "edges": len(mw.edges),
          "max_rotation_error_deg": round(max(e[0] for e in errs), 4),
          "max_translation_drift_m": round(max(e[1] for e in errs), 4), "wall_s": round(wall, 1),
          "cpu_s": round(cpu, 1), "load1": os.getloadavg()[0]})


def colorize_sim_data(seed: int = 0, step_deg: float = 0.4, supersample: int = 3):
    """One simulated TLS station of the demo scene (its own colours removed) and 8 synthetic
    photos rendered by ray casting the scene mesh with ``supersample``² rays per pixel (odd, so
    one ray goes through the pixel centre): each photo pixel is the mean colour of the faces its
    rays hit (anti-aliased, like a real sensor), and two exact depth maps come with it: the
    depth at the pixel centre, and the nearest depth over the pixel's rays (a conservative
    depth map that also shows occluders thinner than a pixel). Sky: depth ``inf``."""
    import open3d as o3d

    from workstation.core.products import Camera, Image, Pose, Reconstruction
    from workstation.lidar.scene import build_scene
    from workstation.lidar.survey import default_stations, default_survey, run_survey

    scene = build_scene("demo_small", seed)
    st = default_stations(scene, 3)
    cfg = default_survey("tls")
    cfg = replace(cfg, scanner=replace(cfg.scanner, h_step_deg=step_deg, v_step_deg=step_deg), stations=st)
    cloud = run_survey(scene, cfg, seed=seed).cloud
    cloud = cloud[cloud.attrs["point_source_id"] == np.unique(cloud.attrs["point_source_id"])[0]]
    cloud = cloud.without_attrs("rgb")
    o = np.asarray(scene.origin, float)
    rs = o3d.t.geometry.RaycastingScene()
    rs.add_triangles(o3d.core.Tensor(scene.vertices.astype(np.float32)), o3d.core.Tensor(scene.faces.astype(np.uint32)))
    local = cloud.xyz - o
    near = np.linalg.norm(local[:, :2] - [st[0].x, st[0].y], axis=1) < 3.0
    ground = float(np.median(local[near, 2])) if near.any() else 0.0
    cam = Camera(800, 600, 500.0, 500.0, 399.5, 299.5)
    images, recon_images, depths, depths_min = {}, {}, {}, {}
    sky = np.array([135, 206, 235], float)
    ss = int(supersample)
    sub = (np.arange(ss) + 0.5) / ss - 0.5  # sub-pixel offsets, 0 in the middle for odd ss
    k = 0
    for dx in (0.0, 5.0):
        C = np.array([st[0].x + dx, st[0].y + 2.0, ground + 1.7])
        for yaw in (0, 90, 180, 270):
            a = np.radians(yaw)
            fwd, right = np.array([np.cos(a), np.sin(a), 0.0]), np.array([np.sin(a), -np.cos(a), 0.0])
            R = np.vstack([right, [0.0, 0.0, -1.0], fwd])
            uu = (np.arange(cam.width)[:, None] + sub[None, :]).ravel()  # (w * ss,) column-major sub-columns
            vv = (np.arange(cam.height)[:, None] + sub[None, :]).ravel()
            U, V = np.meshgrid(uu, vv)  # (h * ss, w * ss)
            dirs_cam = np.column_stack([((U - cam.cx) / cam.fx).ravel(), ((V - cam.cy) / cam.fy).ravel(), np.ones(U.size)])
            dirs = dirs_cam @ R
            rays = np.hstack([np.tile(C, (dirs.shape[0], 1)), dirs]).astype(np.float32)
            hit = rs.cast_rays(o3d.core.Tensor(rays))
            prim = hit["primitive_ids"].numpy().astype(np.int64)
            # ray directions have a unit optical-axis component, so t_hit is the depth; inf = sky
            t = hit["t_hit"].numpy().astype(np.float64)
            ok = np.isfinite(t)
            col = np.tile(sky, (U.size, 1))
            col[ok] = scene.face_rgb[prim[ok]]
            col = col.reshape(cam.height, ss, cam.width, ss, 3)
            t = t.reshape(cam.height, ss, cam.width, ss)
            k += 1
            images[k] = np.round(col.mean(axis=(1, 3))).astype(np.uint8)
            depths[k] = t[:, ss // 2, :, ss // 2].copy()
            depths_min[k] = t.min(axis=(1, 3))
            Cw = C + o
            recon_images[k] = Image(f"v{k}.png", 1, Pose(R, -R @ Cw))
    rec = Reconstruction({1: cam}, recon_images)
    return cloud, rec, images, depths, depths_min, scene, local


def bench_colorize_sim(seed: int = 0, step_deg: float = 0.4, supersample: int = 3):
    """Colour the station of :func:`colorize_sim_data` from its 8 photos, then compare with the
    true face colours and check that no point hidden from every camera (ray cast from the
    camera to the point) was painted."""
    import open3d as o3d

    from workstation.registration.colorize import ColorizeParams, colorize

    cloud, rec, images, depths, depths_min, scene, local = colorize_sim_data(seed, step_deg, supersample)
    o = np.asarray(scene.origin, float)
    cam = rec.cameras[1]
    rs = o3d.t.geometry.RaycastingScene()
    rs.add_triangles(o3d.core.Tensor(scene.vertices.astype(np.float32)), o3d.core.Tensor(scene.faces.astype(np.uint32)))
    # exact depth maps: the tolerance only covers the scan's noise (3 mm range noise, 5 mm
    # station position) and the test's own bias, not a depth-map error
    exact = {"depth_tolerance": 0.03, "depth_tolerance_rel": 0.0}
    runs = [("zbuffer", None, {}), ("depth_maps_pixel_centre", depths, exact),
            ("depth_maps_footprint_min", depths_min, {**exact, "depth_footprint_px": (supersample - 1) / (2 * supersample)})]
    for mode, dm, kw in runs:
        prm = ColorizeParams(**kw)
        w0, c0 = time.perf_counter(), time.process_time()
        out = colorize(cloud, rec, prm, images=images, depth_maps=dm)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        per_view = {k: _colorize_one(cloud, rec, k, prm, images, dm) for k in rec.images}
        _colorize_report(mode, out, cloud, rec, rs, o, local, scene, cam, len(images), wall, cpu, per_view, kw)


def _surface_visible(rs, C, on_surface, inside, eps: float = 0.02):
    """Visibility truth that ignores the scan's noise: the ray from the camera centre ``C`` to
    each point's nearest point on the scene mesh (``on_surface``) hits nothing more than
    ``eps`` metres before it. A noisy point a few millimetres under its own surface seen at a
    grazing angle is then not counted as hidden by that surface (the plain test, a ray to the
    measured point with 5 cm slack, counts it hidden once it lies 5 cm behind along the ray,
    i.e. 6 mm under the ground at a cosine of 0.12)."""
    import open3d as o3d

    dd = on_surface[inside] - C
    dist = np.linalg.norm(dd, axis=1)
    t = rs.cast_rays(o3d.core.Tensor(np.hstack([np.broadcast_to(C, dd.shape), dd / dist[:, None]]).astype(np.float32)))["t_hit"].numpy()
    vis = np.zeros(on_surface.shape[0], bool)
    vis[np.flatnonzero(inside)] = t >= dist - eps
    return vis


def _colorize_one(cloud, rec, k, prm, images, depth_maps):
    """Colorized flags of ``cloud`` coloured from image ``k`` alone."""
    from workstation.core.errors import StageError
    from workstation.core.products import Reconstruction
    from workstation.registration.colorize import colorize

    try:
        return colorize(cloud, Reconstruction(rec.cameras, {k: rec.images[k]}), prm, images=images,
                        depth_maps=depth_maps).attrs["colorized"]
    except StageError:  # the image sees no point
        return np.zeros(cloud.n, np.uint8)


def _colorize_report(mode, out, cloud, rec, rs, o, local, scene, cam, n_images, wall, cpu, per_view=None, params=None):
    """One JSON line comparing a colourised cloud with the scene. ``per_view``: (image id ->
    colorized flags of the cloud coloured from that image alone), for the strict check that no
    view paints a point it does not see."""
    import open3d as o3d

    from workstation.registration.colorize import project

    recon_images = rec.images
    closest = rs.compute_closest_points(o3d.core.Tensor(local.astype(np.float32)))
    truth_face = closest["primitive_ids"].numpy()
    on_surface = closest["points"].numpy().astype(np.float64)
    truth = scene.face_rgb[truth_face.astype(np.int64)].astype(float)
    painted = out.attrs["colorized"].astype(bool)
    seen_any = np.zeros(cloud.n, bool)
    behind = np.full(cloud.n, np.inf)  # least depth by which a point is hidden in any camera
    view_bad = view_painted = view_visible = view_bad_surface = 0
    for kk, im in recon_images.items():
        u, v, z = project(cloud.xyz, cam, im.pose)
        inside = (z > 0) & (u >= 0) & (u <= cam.width - 1) & (v >= 0) & (v <= cam.height - 1)
        C = im.pose.center - o
        d = local[inside] - C
        dist = np.linalg.norm(d, axis=1)
        rays = np.hstack([np.tile(C, (d.shape[0], 1)), d / dist[:, None]]).astype(np.float32)
        t = rs.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy()
        vis = np.zeros(cloud.n, bool)
        vis[np.flatnonzero(inside)] = t >= dist - 0.05
        seen_any |= vis
        if per_view is not None:
            pv = per_view[kk].astype(bool)
            view_bad += int((pv & ~vis).sum())
            view_bad_surface += int((pv & ~_surface_visible(rs, C, on_surface, inside)).sum())
            view_painted += int(pv.sum())
            view_visible += int(vis.sum())
        ii = np.flatnonzero(inside)
        behind[ii] = np.minimum(behind[ii], np.where(np.isfinite(t), dist - t, np.inf))
    err = np.abs(out.attrs["rgb"][painted] / 257.0 - truth[painted]).mean(axis=1)
    bad = painted & ~seen_any
    cls = cloud.attrs["classification"][bad] if "classification" in cloud.attrs else np.zeros(0, int)
    bad_classes = {int(c): int(n) for c, n in zip(*np.unique(cls, return_counts=True))}
    emit({"bench": "colorize_sim_tls", "visibility": mode, "params": params or {}, "painted_but_hidden_by_class": bad_classes, "points": cloud.n, "images": n_images, "painted": int(painted.sum()),
          "truly_visible": int(seen_any.sum()),
          "hidden_painted_depth_behind_m_p50_p90": [round(float(x), 3) for x in np.percentile(behind[bad], [50, 90])] if bad.any() else None, "painted_but_hidden_from_all": int((painted & ~seen_any).sum()),
          "coverage_of_visible": round(float((painted & seen_any).sum() / max(seen_any.sum(), 1)), 4),
          "per_view_painted": view_painted if per_view is not None else None,
          "per_view_truly_visible": view_visible if per_view is not None else None,
          "per_view_painted_but_hidden_in_that_view": view_bad if per_view is not None else None,
          "per_view_painted_but_surface_hidden_in_that_view": view_bad_surface if per_view is not None else None,
          "mean_colour_error_255": round(float(err.mean()), 2), "median_colour_error_255": round(float(np.median(err)), 2),
          "wall_s": round(wall, 2), "cpu_s": round(cpu, 2), "load1": os.getloadavg()[0]})


def sfm_tls_survey(recipe, spec, step_deg: float = 0.3):
    """The TLS survey of the SfM <-> TLS scenario (a ``SurveyConfig``): 4 stations 10 m beyond the
    half-diagonal of the rig's target (32 m from the church centre) on its diagonals, 1.6 m
    above the ground, ``step_deg`` horizontal and vertical steps; station i is point source i + 1."""
    from workstation.lidar.platforms import Station
    from workstation.lidar.survey import default_survey
    from workstation.photogrammetry.rigs import _target_scene

    _, _, _, _, _, centre, size = _target_scene(recipe, spec)
    r = 0.5 * float(np.hypot(size[0], size[1])) + 10.0
    st = tuple(Station(float(centre[0] + r * np.cos(a)), float(centre[1] + r * np.sin(a)), 1.6, 0.0)
               for a in np.radians([45.0, 135.0, 225.0, 315.0]))
    cfg = default_survey("tls")
    return replace(cfg, scanner=replace(cfg.scanner, h_step_deg=step_deg, v_step_deg=step_deg), stations=st)


def similarity_errors(xyz: np.ndarray, T: np.ndarray, S: np.ndarray) -> dict:
    """How far the 4x4 similarity ``T`` puts the points ``xyz`` (n, 3) from where the true
    similarity ``S`` puts them: scale error (%) and position error mean / median / max (m)."""
    e = np.linalg.norm(xyz @ T[:3, :3].T + T[:3, 3] - (xyz @ S[:3, :3].T + S[:3, 3]), axis=1)
    sc, s_true = (float(np.cbrt(np.linalg.det(M[:3, :3]))) for M in (T, S))
    return {"scale_error_pct": round(100 * (sc / s_true - 1), 4), "position_error_mean_m": round(float(e.mean()), 4),
            "position_error_median_m": round(float(np.median(e)), 4), "position_error_max_m": round(float(e.max()), 4)}


def sfm_tls_data(work: Path, step_deg: float = 0.3, max_image_size: int = 640, reuse: bool = True,
                 calibrated: bool = True):
    """The SfM <-> TLS scenario's data (cached in ``work``): the heritage photo rig
    (``datasets_synth/rig_heritage.toml``: 24 renders of the church, 640 x 480), ``ws sfm``
    (pycolmap, arbitrary frame and scale), the CPU dense cloud, and a TLS survey of the same
    scene (4 stations 30 m from the church on its diagonals, ``step_deg`` steps). Returns
    (dense Cloud in the SfM frame, TLS Cloud in the scene's local frame, true similarity SfM ->
    local frame fitted on the camera centres, its camera-centre residuals (m), timings).

    ``calibrated``: SfM gets the rig's true intrinsics (as from ``ws calibrate``) and keeps them
    fixed. Self-calibrated, the focal length of a ring of convergent views is only known
    through the distance to the object, so the camera centres and the structure disagree in
    scale by about the focal-length error (measured: 0.14 %, 5 cm at the cameras), and the
    camera centres then no longer give the structure's true similarity."""
    from workstation.io import read_cloud, write_cloud
    from workstation.lidar.scene import build_scene
    from workstation.lidar.survey import run_survey
    from workstation.photogrammetry.dense import DenseParams, run_dense
    from workstation.photogrammetry.georef import fit_similarity
    from workstation.photogrammetry.rigs import load_rig, make_rig
    from workstation.photogrammetry.sfm import SfMParams, run_sfm
    from workstation.photogrammetry.sfm import read_reconstruction

    work.mkdir(parents=True, exist_ok=True)
    rigdir, sfmdir = work / "rig", work / ("rig_sfm_cal" if calibrated else "rig_sfm")
    recipe, spec = load_rig(Path(__file__).resolve().parents[1] / "datasets_synth" / "rig_heritage.toml")
    times = {}
    t0 = time.perf_counter()
    if not (reuse and (rigdir / "truth_mesh.npz").exists()):
        make_rig(recipe, spec, rigdir, overwrite=True)
    times["render_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    if not (reuse and (sfmdir / "sparse" / "0").exists()):
        run_sfm(rigdir / "images", sfmdir, camera=spec.camera() if calibrated else None, params=SfMParams(),
                overwrite=True)
    times["sfm_s"] = time.perf_counter() - t0
    dense_path = work / f"dense_{max_image_size}{'_cal' if calibrated else ''}.laz"
    t0 = time.perf_counter()
    if reuse and dense_path.exists():
        dense = read_cloud(dense_path)
    else:
        dense, _ = run_dense(sfmdir, rigdir / "images", DenseParams(device="cpu", max_image_size=max_image_size),
                             overwrite=True)
        write_cloud(dense, dense_path, overwrite=True)
    times["dense_s"] = time.perf_counter() - t0
    true = read_reconstruction(rigdir / "cameras.json")
    est = read_reconstruction(sfmdir / "sparse" / "0")
    by_name = {im.name: im for im in true.images.values()}
    names = [im.name for im in est.images.values() if im.name in by_name]
    ce = np.array([im.pose.center for im in est.images.values() if im.name in by_name])
    ct = np.array([by_name[n].pose.center for n in names])
    sim = fit_similarity(ce, ct)
    resid = np.linalg.norm(sim.apply(ce) - ct, axis=1)
    tls_path = work / f"tls_{step_deg}.laz"
    t0 = time.perf_counter()
    scene = build_scene(recipe, spec.seed)
    if reuse and tls_path.exists():
        tls = read_cloud(tls_path)
    else:
        tls = run_survey(scene, sfm_tls_survey(recipe, spec, step_deg), seed=spec.seed).cloud
        write_cloud(tls, tls_path, overwrite=True)
    times["tls_s"] = time.perf_counter() - t0
    tls = tls.with_xyz(tls.xyz - np.asarray(scene.origin, float))
    return dense, tls, sim, resid, times


def bench_sfm_tls(work: Path, seed: int = 0, calibrated: bool = True):
    """SfM-dense cloud of the heritage rig (arbitrary frame and scale, then moved once more by a
    random similarity: rotation up to 180 degrees, scale 0.1-10, +-100 units) registered to the
    simulated TLS cloud of the same scene by ``register(method="similarity")`` from the identity.
    Truth: the similarity from the SfM frame to the scene frame fitted on the camera centres
    (SfM vs the rig's true cameras). Reference: the same dense cloud fitted by 7-DoF ICP to a
    dense sampling of the true mesh (the best alignment this cloud admits); its distance from
    the camera truth is the SfM + dense cloud's own error, not the registration's."""
    from workstation.core.cloud import Cloud
    from workstation.photogrammetry.rigs import load_truth
    from workstation.registration.icp import similarity_plane_icp
    from workstation.registration.register import RegisterParams, register
    from workstation.registration.transforms import make_transform, random_rotation

    dense, tls, sim, resid, times = sfm_tls_data(work, calibrated=calibrated)
    rng = np.random.default_rng(seed)
    G = make_transform(random_rotation(rng, 180.0), rng.uniform(-100, 100, 3), 10 ** rng.uniform(-1, 1))
    src = Cloud(dense.xyz @ G[:3, :3].T + G[:3, 3])
    S = make_transform(sim.R, sim.t, sim.scale) @ np.linalg.inv(G)  # true similarity src -> scene
    s_true = float(np.cbrt(np.linalg.det(S[:3, :3])))
    w0, c0 = time.perf_counter(), time.process_time()
    r = register(src, tls, RegisterParams(method="similarity"))
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0

    def errors(T):
        return similarity_errors(src.xyz, T, S)

    import open3d as o3d

    truth = load_truth(work / "rig")
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(truth["vertices"]), o3d.utility.Vector3iVector(truth["faces"]))
    mesh.compute_triangle_normals()
    pc = mesh.sample_points_uniformly(2_000_000, use_triangle_normal=True)
    ref = similarity_plane_icp(src.xyz, np.asarray(pc.points), np.asarray(pc.normals), [1.0, 0.5, 0.25, 0.12], S, 30)
    e_ref = np.linalg.norm(src.xyz @ (r.transform[:3, :3] - ref.transform[:3, :3]).T + r.transform[:3, 3] - ref.transform[:3, 3], axis=1)
    emit({"bench": "sfm_dense_to_tls_7dof", "calibrated_sfm": calibrated, "dense_points": dense.n, "tls_points": tls.n,
          "cameras_registered": int(resid.size), "camera_truth_rms_m": round(float(np.sqrt(np.mean(resid**2))), 4),
          "camera_truth_max_m": round(float(resid.max()), 4), "sfm_scale_to_metres": round(s_true, 6),
          **errors(r.transform), "fitness": round(r.fitness, 4), "inlier_rmse_m": round(r.inlier_rmse, 4),
          "scale0_guess": round(r.meta.get("scale0", float("nan")) / s_true, 3),
          "hypotheses": len(r.meta.get("hypotheses", [])), "voxel_m": round(r.meta["voxel_size"], 3),
          "reference_dense_to_true_mesh": errors(ref.transform),
          "registration_vs_reference": {"scale_diff_pct": round(100 * (r.scale / ref.scale - 1), 4),
                                        "position_diff_mean_m": round(float(e_ref.mean()), 4),
                                        "position_diff_max_m": round(float(e_ref.max()), 4)},
          "wall_s": round(wall, 1), "cpu_s": round(cpu, 1), "data_s": {k: round(v, 1) for k, v in times.items()},
          "load1": os.getloadavg()[0]})


def bench_colorize_rig(work: Path, supersample: int = 3, modes=("zbuffer", "exact_depth_maps_footprint_min", "mvs_depth_maps_sfm_frame")):
    """Colour the simulated TLS survey of the heritage scene (4 stations, the cloud of
    :func:`sfm_tls_data`) from the rig's 24 photos (the rig's own anti-aliased renders of the
    procedurally textured mesh), three ways: z-buffer of the cloud and exact depth maps of the
    true cameras (footprint minimum over ``supersample``² rays), both with the true cameras; and
    the MVS depth maps and undistorted images of the SfM dense workspace (``--depth-maps``), with
    the TLS cloud moved into the SfM frame by the camera-truth similarity. Truth: the texture at
    the nearest mesh point of each TLS point (``rigs.surface_colour``) and visibility by ray
    casting from the true camera centres."""
    import cv2
    import open3d as o3d

    from workstation.core.cloud import Cloud
    from workstation.interop.pycolmap import read_model
    from workstation.photogrammetry.rigs import _target_scene, load_rig, surface_colour
    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.photogrammetry.collinearity import camera_rays
    from workstation.registration.colorize import (
        ColorizeParams,
        colorize,
        read_depth_maps,
    )

    _, tls, sim, _, _ = sfm_tls_data(work)
    recipe, spec = load_rig(Path(__file__).resolve().parents[1] / "datasets_synth" / "rig_heritage.toml")
    V, F, alb, _, _, _, _ = _target_scene(recipe, spec)
    rs = o3d.t.geometry.RaycastingScene()
    rs.add_triangles(o3d.core.Tensor(V.astype(np.float32)), o3d.core.Tensor(F.astype(np.uint32)))
    cloud = tls.without_attrs("rgb") if "rgb" in tls.attrs else tls
    local = cloud.xyz
    cp = rs.compute_closest_points(o3d.core.Tensor(local.astype(np.float32)))
    prim = cp["primitive_ids"].numpy().astype(np.int64)
    tri = V[F[prim]]
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True)
    truth = np.round(255 * surface_colour(cp["points"].numpy().astype(np.float64), nrm, alb[prim]))
    rec = read_reconstruction(work / "rig" / "cameras.json")
    cam = rec.cameras[1]
    images = {k: cv2.imread(str(work / "rig" / "images" / im.name))[:, :, ::-1].copy() for k, im in rec.images.items()}
    ss = int(supersample)
    rays = camera_rays(cam, ss)
    dmin = {}
    for k, im in rec.images.items():
        d = rays.reshape(-1, 3) @ np.asarray(im.pose.R)
        hit = rs.cast_rays(o3d.core.Tensor(np.hstack([np.broadcast_to(im.pose.center, d.shape), d]).astype(np.float32)))
        depth = hit["t_hit"].numpy().astype(np.float64) * rays.reshape(-1, 3)[:, 2]
        dmin[k] = depth.reshape(cam.height, ss, cam.width, ss).min(axis=(1, 3))
    # visibility truth per true camera (by image name)
    vis_by_name, surf_by_name = {}, {}
    on_surface = cp["points"].numpy().astype(np.float64)
    for k, im in rec.images.items():
        from workstation.registration.colorize import project

        u, v, z = project(local, cam, im.pose)
        inside = (z > 0) & (u >= 0) & (u <= cam.width - 1) & (v >= 0) & (v <= cam.height - 1)
        C = im.pose.center
        dd = local[inside] - C
        dist = np.linalg.norm(dd, axis=1)
        t = rs.cast_rays(o3d.core.Tensor(np.hstack([np.broadcast_to(C, dd.shape), dd / dist[:, None]]).astype(np.float32)))["t_hit"].numpy()
        vis = np.zeros(cloud.n, bool)
        vis[np.flatnonzero(inside)] = t >= dist - 0.05
        vis_by_name[im.name] = vis
        surf_by_name[im.name] = _surface_visible(rs, C, on_surface, inside)
    seen_any = np.any(list(vis_by_name.values()), axis=0)
    sfm_dir = work / "rig_sfm_cal" / "dense"
    mvs_rec = read_model(sfm_dir)
    mvs_depth = read_depth_maps(sfm_dir, mvs_rec)
    mvs_images = {k: cv2.imread(str(sfm_dir / "images" / im.name))[:, :, ::-1].copy() for k, im in mvs_rec.images.items()}
    xyz_sfm = (local - sim.t) @ sim.R / sim.scale  # inverse of x = s R y + t
    exact = {"depth_tolerance": 0.03, "depth_tolerance_rel": 0.0, "depth_footprint_px": (ss - 1) / (2 * ss)}
    runs = [("zbuffer", cloud, rec, images, None, {}),
            ("exact_depth_maps_footprint_min", cloud, rec, images, dmin, exact),
            ("mvs_depth_maps_sfm_frame", Cloud(xyz_sfm), mvs_rec, mvs_images, mvs_depth, {})]
    for mode, c, r, imgs, dm, kw in runs:
        if mode not in modes:
            continue
        prm = ColorizeParams(**kw)
        w0, c0 = time.perf_counter(), time.process_time()
        out = colorize(c, r, prm, images=imgs, depth_maps=dm)
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        painted = out.attrs["colorized"].astype(bool)
        bad_view = painted_view = bad_surface = 0
        for k, im in r.images.items():
            pv = _colorize_one(c, r, k, prm, imgs, dm).astype(bool)
            painted_view += int(pv.sum())
            bad_view += int((pv & ~vis_by_name[im.name]).sum())
            bad_surface += int((pv & ~surf_by_name[im.name]).sum())
        err = np.abs(out.attrs["rgb"][painted] / 257.0 - truth[painted]).mean(axis=1)
        emit({"bench": "colorize_rig_tls", "visibility": mode, "params": kw, "points": cloud.n, "images": len(r.images),
              "truly_visible": int(seen_any.sum()), "painted": int(painted.sum()),
              "coverage_of_visible": round(float((painted & seen_any).sum() / seen_any.sum()), 4),
              "painted_but_hidden_from_all": int((painted & ~seen_any).sum()),
              "per_view_painted": painted_view, "per_view_painted_but_hidden_in_that_view": bad_view,
              "per_view_painted_but_surface_hidden_in_that_view": bad_surface,
              "mean_colour_error_255": round(float(err.mean()), 2), "median_colour_error_255": round(float(np.median(err)), 2),
              "p90_colour_error_255": round(float(np.percentile(err, 90)), 2),
              "wall_s": round(wall, 1), "cpu_s": round(cpu, 1), "load1": os.getloadavg()[0]})


BUNNY_SCANS = ("bun000.ply", "bun045.ply", "bun090.ply")


def bunny_gauge_errors(poses, names, truth, clouds, frames=None) -> list[tuple[float, float]]:
    """(rotation degrees, translation metres at the scan's centroid) of each pose against
    bun.conf with the gauge fixed on bun000. ``poses`` map each input scan into the first
    input's frame; an input is scan k moved by ``frames[k]`` (identity when None), so
    ``inv(F_bun000) inv(P_bun000) P_k F_k`` maps the original scan k into bun000's frame, as
    bun.conf does."""
    from workstation.registration.transforms import invert, transform_error

    frames = [np.eye(4)] * len(names) if frames is None else frames
    i0 = names.index("bun000.ply")
    g = invert(np.asarray(poses[i0]) @ frames[i0])
    return [transform_error(g @ np.asarray(p) @ f, truth[n], center=c.xyz.mean(axis=0))
            for p, f, n, c in zip(poses, frames, names, clouds)]


def bench_merge_bunny(data: Path, orders=(BUNNY_SCANS, ("bun090.ply", "bun000.ply", "bun045.ply")),
                      frame_seeds=(0, 1, 2)):
    """The three bunny scans as a multi-station set through ``ws merge --register``'s pose graph
    (``register_multiway`` with defaults): in their own scanner frames (45 and 90 degrees apart)
    in each of ``orders``, then, for each of ``frame_seeds``, each scan moved into a random frame
    (any rotation, +-10 m). Every scan's pose error against bun.conf with the gauge fixed on
    bun000, the per-edge residuals, wall and CPU seconds."""
    from test_reg_bunny import bunny_truth

    from workstation.io import read_cloud
    from workstation.registration.merge import transform_cloud
    from workstation.registration.posegraph import MultiwayParams, register_multiway
    from workstation.registration.transforms import make_transform, random_rotation

    d = data / "registration"
    truth = bunny_truth(d / "bun.conf")
    scans = {n: read_cloud(d / n) for n in BUNNY_SCANS}
    cases = [(list(o), "scanner", None) for o in orders]
    for s in frame_seeds:
        rng = np.random.default_rng(s)
        cases.append((list(BUNNY_SCANS), f"random_{s}",
                      [make_transform(random_rotation(rng), rng.uniform(-10, 10, 3)) for _ in BUNNY_SCANS]))
    for names, frame, F in cases:
        clouds = [scans[n] for n in names]
        moved = clouds if F is None else [transform_cloud(c, f) for c, f in zip(clouds, F)]
        w0, c0 = time.perf_counter(), time.process_time()
        mw = register_multiway(moved, MultiwayParams())
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        errs = bunny_gauge_errors(mw.poses, names, truth, clouds, F)
        emit({"bench": "merge_bunny", "order": names, "frames": frame,
              "rotation_error_deg": {n: round(e[0], 4) for n, e in zip(names, errs)},
              "translation_error_mm": {n: round(e[1] * 1000, 4) for n, e in zip(names, errs)},
              "edges": [{"edge": f"{names[e.source]}->{names[e.target]}", "kind": e.kind,
                         "fitness": round(e.fitness, 3),
                         "rotation_residual_deg": round(e.rotation_residual_deg, 4),
                         "translation_residual_mm": round(e.translation_residual * 1000, 4), "kept": e.kept}
                        for e in mw.edges],
              "wall_s": round(wall, 1), "cpu_s": round(cpu, 1), "load1": os.getloadavg()[0]})
def bench_merge_bunny_open3d(data: Path, voxel: float = 0.003, global_init: bool = False):
    """Open3D's multiway-registration tutorial on the three bunny scans, unchanged except the
    voxel size: voxel downsampling, normals (radius 2 voxel), pairwise point-to-plane ICP at 15
    then 1.5 voxel from the identity (``global_init``: from the global-registration tutorial's
    FPFH + RANSAC instead), odometry and uncertain loop edges, Levenberg-Marquardt pose graph
    (correspondence 1.5 voxel, prune 0.25, reference node 0)."""
    import open3d as o3d
    from test_reg_bunny import bunny_truth

    from workstation.interop.open3d import points_to_legacy
    from workstation.io import read_cloud

    reg, kd = o3d.pipelines.registration, o3d.geometry.KDTreeSearchParamHybrid
    d = data / "registration"
    truth = bunny_truth(d / "bun.conf")
    clouds = [read_cloud(d / n) for n in BUNNY_SCANS]
    w0, c0 = time.perf_counter(), time.process_time()
    pcds = [points_to_legacy(np.array(c.xyz)).voxel_down_sample(voxel) for c in clouds]
    for p in pcds:
        p.estimate_normals(kd(radius=2 * voxel, max_nn=30))

    def init(s, t):
        if not global_init:
            return np.eye(4)
        fs, ft = (reg.compute_fpfh_feature(p, kd(radius=5 * voxel, max_nn=100)) for p in (s, t))
        dist = 1.5 * voxel
        return reg.registration_ransac_based_on_feature_matching(
            s, t, fs, ft, True, dist, reg.TransformationEstimationPointToPoint(False), 3,
            [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(dist)],
            reg.RANSACConvergenceCriteria(100000, 0.999)).transformation

    graph, odometry = reg.PoseGraph(), np.eye(4)
    graph.nodes.append(reg.PoseGraphNode(odometry))
    for i in range(len(pcds)):
        for j in range(i + 1, len(pcds)):
            coarse = reg.registration_icp(pcds[i], pcds[j], 15 * voxel, init(pcds[i], pcds[j]),
                                          reg.TransformationEstimationPointToPlane())
            fine = reg.registration_icp(pcds[i], pcds[j], 1.5 * voxel, coarse.transformation,
                                        reg.TransformationEstimationPointToPlane())
            info = reg.get_information_matrix_from_point_clouds(pcds[i], pcds[j], 1.5 * voxel, fine.transformation)
            if j == i + 1:
                odometry = fine.transformation @ odometry
                graph.nodes.append(reg.PoseGraphNode(np.linalg.inv(odometry)))
            graph.edges.append(reg.PoseGraphEdge(i, j, fine.transformation, info, uncertain=j != i + 1))
    option = reg.GlobalOptimizationOption(max_correspondence_distance=1.5 * voxel, edge_prune_threshold=0.25,
                                          reference_node=0)
    with o3d.utility.VerbosityContextManager(o3d.utility.VerbosityLevel.Error):
        reg.global_optimization(graph, reg.GlobalOptimizationLevenbergMarquardt(),
                                reg.GlobalOptimizationConvergenceCriteria(), option)
    wall, cpu = time.perf_counter() - w0, time.process_time() - c0
    errs = bunny_gauge_errors([np.asarray(nd.pose) for nd in graph.nodes], list(BUNNY_SCANS), truth, clouds)
    emit({"bench": "merge_bunny_open3d_tutorial", "voxel": voxel, "init": "fpfh_ransac" if global_init else "identity",
          "rotation_error_deg": {n: round(e[0], 4) for n, e in zip(BUNNY_SCANS, errs)},
          "translation_error_mm": {n: round(e[1] * 1000, 4) for n, e in zip(BUNNY_SCANS, errs)},
          "wall_s": round(wall, 2), "cpu_s": round(cpu, 2), "load1": os.getloadavg()[0]})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", type=Path, default=Path(os.environ.get("WS_SHARED_DATA", "../shared/data")))
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--o3d-iterations", type=int, default=3)
    ap.add_argument("--skip-bunny", action="store_true")
    ap.add_argument("--skip-icp", action="store_true")
    ap.add_argument("--colorize-sim", action="store_true", help="colour a simulated TLS station from synthetic photos")
    ap.add_argument("--sfm-tls", type=Path, default=None, metavar="WORKDIR",
                    help="SfM-dense cloud of the heritage rig to its simulated TLS cloud (7 DoF); data cached in WORKDIR")
    ap.add_argument("--colorize-rig", type=Path, default=None, metavar="WORKDIR",
                    help="colour the simulated TLS of the heritage scene from the rig photos (needs --sfm-tls data)")
    ap.add_argument("--sfm-self-calibrated", action="store_true", help="with --sfm-tls: SfM self-calibrates the focal length")
    ap.add_argument("--tls-laz", type=Path, default=None,
                    help="simulated multi-station TLS survey (point_source_id per station), e.g. from ws simulate tls")
    ap.add_argument("--merge-bunny", action="store_true",
                    help="the three bunny scans through the pose graph of ws merge --register, beside Open3D's")
    a = ap.parse_args()
    emit({"bench": "machine", "cpus": os.cpu_count(), "load1": os.getloadavg()[0]})
    if not a.skip_bunny and (a.data / "registration").is_dir():
        bench_bunny(a.data)
        for v in (0.002, 0.003, 0.004):
            bench_bunny_open3d(a.data, v)
    if a.merge_bunny:
        bench_merge_bunny(a.data)
        for v in (0.002, 0.003, 0.004):
            for g in (False, True):
                bench_merge_bunny_open3d(a.data, v, g)
    if a.colorize_sim:
        bench_colorize_sim()
    if a.sfm_tls is not None:
        bench_sfm_tls(a.sfm_tls, calibrated=not a.sfm_self_calibrated)
    if a.colorize_rig is not None:
        bench_colorize_rig(a.colorize_rig)
    if a.tls_laz is not None:
        bench_tls(a.tls_laz)
    if not a.skip_icp:
        bench_icp(a.points, a.o3d_iterations)


if __name__ == "__main__":
    main()
