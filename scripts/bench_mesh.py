"""Meshing and rendering benchmarks (issue 10). Prints one JSON line per result.

    WS_SHARED_DATA=../../shared/data PYTHONPATH=. python scripts/bench_mesh.py \
        [--only render,poisson,poisson_backend_open3d,poisson_open3d,bunny,heritage] [--threads 2]
    PYTHONPATH=. python scripts/bench_mesh.py --only heritage_fused --with-truth-pose [--sfm-work /tmp/reg_sfm]

- bunny: Stanford bunny, 3 scans merged with bun.conf poses, screened Poisson depth 9,
  decimated to 20,000 faces; distances to the scans; Open3D's Poisson depth 9 + quadric
  decimation on the same oriented points as the anchor (needs ../shared/data).
- poisson: screened Poisson depth 10 on 1,000,000 points (a bumpy torus, analytic normals);
  poisson_backend_open3d: the same through ``PoissonParams(backend="open3d")`` (passive
  OpenMP); poisson_open3d: Open3D called directly, default OpenMP settings (anchor).
- heritage: the simulator's heritage church, 8 TLS stations, Poisson vs the true mesh.
- heritage_fused: the church of the synthetic photo rig meshed from its simulated TLS (4
  stations) merged with the rig's dense cloud, registered in 7 DoF to the TLS (data of
  ``bench_register.py --sfm-tls``, cached in ``--sfm-work``), against the true mesh; the TLS
  alone as the control (``--with-truth-pose``: also the dense cloud placed by the camera truth).
- render: a 1920x1080 top-view render of a 10,000,000-point cloud.
- texture: the true heritage-church mesh textured from the 24 photos of the synthetic rig,
  texture colour vs the true surface colour; with ``--occluder branch|pole``, instead the
  box-and-wall rig photographed with an occluder its mesh lacks, with and without the
  photo-consistency check.
- poisson_profile: Open3D's Poisson depth 10 on the 1 M-point torus, per PoissonRecon stage,
  for ``--variants`` (samples per node : point weight : full depth), accuracy vs the torus.
Timings are wall seconds and process CPU seconds (CPU is the contention-free estimate on a
shared machine).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from workstation.core.cloud import Cloud, concatenate  # noqa: E402


def emit(**kw):
    print(json.dumps(kw), flush=True)


def timed(fn, *a, **k):
    t, c = time.perf_counter(), time.process_time()
    out = fn(*a, **k)
    return out, time.perf_counter() - t, time.process_time() - c


def mls_plane_projection(vertices: np.ndarray, xyz: np.ndarray, k: int = 16) -> np.ndarray:
    """One first-order MLS projection step (Alexa et al., "Computing and rendering point set
    surfaces", IEEE TVCG 2003, with a plane as the local fit): every vertex moved to its foot on
    the Gaussian-weighted least-squares plane of its k nearest points (bandwidth = the median
    distance to the k-th neighbour)."""
    from scipy.spatial import cKDTree

    d, idx = cKDTree(xyz).query(vertices, k=k)
    nb = xyz[idx]
    w = np.exp(-(d / np.median(d[:, -1])) ** 2)
    c = (w[..., None] * nb).sum(1) / w.sum(1, keepdims=True)
    x = nb - c[:, None]
    _, vec = np.linalg.eigh(np.einsum("mk,mki,mkj->mij", w, x, x))
    n = vec[:, :, 0]
    return vertices - np.einsum("mi,mi->m", vertices - c, n)[:, None] * n


def bunny(threads, trims=(0.05,), mls=False, poisson_backend=None):
    from scipy.spatial.transform import Rotation

    from workstation.mesh import (CleanParams, DecimateParams, NormalParams, PoissonParams, QualityParams, clean,
                                  decimate, estimate_normals, keep_vertices, mesh_quality, poisson)
    from workstation.core.products import Mesh
    from workstation.io import read_cloud

    folder = Path(os.environ.get("WS_SHARED_DATA", REPO.parent / "shared" / "data")) / "registration"
    if not folder.is_dir():
        emit(bench="bunny", skipped=f"{folder} absent")
        return
    scans = []
    for line in (folder / "bun.conf").read_text().splitlines():
        s = line.split()
        if not s or s[0] != "bmesh":
            continue
        xyz = read_cloud(folder / s[1]).xyz
        R = Rotation.from_quat(np.array(s[5:9], float)).as_matrix()
        local, _ = estimate_normals(Cloud(xyz), NormalParams(k=10), viewpoints=np.array([0.0, 0.0, 1.0]))
        scans.append(Cloud(xyz @ R + np.array(s[2:5], float), {"normal": np.asarray(local.attrs["normal"], float) @ R}))
    merged = concatenate(scans)
    mm = lambda d: {k: round(v * 1000, 4) for k, v in d.items() if k != "n"}  # noqa: E731
    # one Poisson surface, then each density trim through the rest of the chain
    backend = {} if poisson_backend is None else {"backend": poisson_backend}
    (raw, prec), wall_p, cpu_p = timed(poisson, merged, PoissonParams(depth=9, trim_quantile=0.0, threads=threads, **backend))
    dens = np.asarray(raw.vertex_attrs["quality"], dtype=np.float64)
    for trim in trims:
        t0, c0 = time.perf_counter(), time.process_time()
        m = keep_vertices(raw, dens >= np.quantile(dens, trim)) if trim > 0 else raw
        m, _ = clean(m, CleanParams(min_piece_fraction=0.1, report_self_intersections=False))
        m, _ = decimate(m, DecimateParams(target_faces=20000))
        m, _ = clean(m, CleanParams(report_self_intersections=False))
        wall, cpu = time.perf_counter() - t0 + wall_p, time.process_time() - c0 + cpu_p
        q = mesh_quality(Mesh(m.vertices, m.faces), Cloud(merged.xyz), QualityParams(mesh_samples=200_000))
        emit(bench="bunny_poisson", poisson_backend=prec.params["backend"], point_weight=prec.params["point_weight"], points=merged.n, trim_quantile=trim, faces=q["faces"],
             wall_s=round(wall, 1), cpu_s=round(cpu, 1), poisson_wall_s=round(wall_p, 1),
             non_manifold_edges=q["non_manifold_edges"], mesh_to_scans_mm=mm(q["mesh_to_cloud"]),
             mesh_to_scans_floor_mm=mm(q["mesh_to_cloud_floor"]),
             mesh_to_scans_local_plane_mm=mm(q["mesh_to_cloud_local_plane"]), scans_to_mesh_mm=mm(q["cloud_to_mesh"]))
        if mls:
            pm = Mesh(mls_plane_projection(m.vertices, merged.xyz), m.faces)
            q = mesh_quality(pm, Cloud(merged.xyz), QualityParams(mesh_samples=200_000))
            emit(bench="bunny_poisson_pymeshlab_mls_projected", trim_quantile=trim, faces=q["faces"],
                 non_manifold_edges=q["non_manifold_edges"], mesh_to_scans_mm=mm(q["mesh_to_cloud"]),
                 mesh_to_scans_floor_mm=mm(q["mesh_to_cloud_floor"]),
                 mesh_to_scans_local_plane_mm=mm(q["mesh_to_cloud_local_plane"]),
                 scans_to_mesh_mm=mm(q["cloud_to_mesh"]))
    import open3d as o3d

    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.array(merged.xyz)))
    pc.normals = o3d.utility.Vector3dVector(np.asarray(merged.attrs["normal"], float))
    t, c = time.perf_counter(), time.process_time()
    m, dens = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pc, depth=9)
    dens = np.asarray(dens)
    m.remove_vertices_by_mask(dens < np.quantile(dens, 0.05))
    m = m.simplify_quadric_decimation(20000)
    wall, cpu = time.perf_counter() - t, time.process_time() - c
    q = mesh_quality(Mesh(np.asarray(m.vertices), np.asarray(m.triangles)), Cloud(merged.xyz),
                     QualityParams(mesh_samples=200_000))
    emit(bench="bunny_poisson_open3d_anchor", faces=q["faces"], wall_s=round(wall, 1), cpu_s=round(cpu, 1),
         non_manifold_edges=q["non_manifold_edges"], mesh_to_scans_mm=mm(q["mesh_to_cloud"]),
         mesh_to_scans_floor_mm=mm(q["mesh_to_cloud_floor"]),
         mesh_to_scans_local_plane_mm=mm(q["mesh_to_cloud_local_plane"]), scans_to_mesh_mm=mm(q["cloud_to_mesh"]))


def torus_1m():
    rng = np.random.default_rng(0)
    n = 1_000_000
    u, v = rng.uniform(0, 2 * np.pi, (2, n))
    Rr, r = 10.0, 3.0 + 0.3 * np.sin(5 * u) * np.cos(3 * v)  # bumpy torus, metres
    xyz = np.column_stack([(Rr + r * np.cos(v)) * np.cos(u), (Rr + r * np.cos(v)) * np.sin(u), r * np.sin(v)])
    c = np.column_stack([Rr * np.cos(u), Rr * np.sin(u), np.zeros(n)])
    nrm = (xyz - c) / np.linalg.norm(xyz - c, axis=1, keepdims=True)  # near-radial normals of the tube
    return Cloud(xyz + [500_000, 4_000_000, 100], {"normal": nrm})


def poisson_1m(threads, backend="pymeshlab", samples_per_node=1.5):
    from workstation.mesh import PoissonParams, poisson

    cloud = torus_1m()
    n = cloud.n
    (mesh, rec), wall, cpu = timed(poisson, cloud, PoissonParams(depth=10, trim_quantile=0.0, threads=threads,
                                                                 backend=backend, samples_per_node=samples_per_node))
    err = torus_radial_error(mesh.vertices)
    emit(bench="poisson_depth10_1M", backend=backend, points=n, threads=rec.params["threads"],
         samples_per_node=samples_per_node, faces=mesh.n_faces, wall_s=round(wall, 1), cpu_s=round(cpu, 1),
         radial_error_mm={"p50": round(1000 * float(np.median(err)), 2),
                          "p95": round(1000 * float(np.percentile(err, 95)), 2)},
         omp_wait_policy=os.environ.get("OMP_WAIT_POLICY"), loadavg=os.getloadavg()[0])


def torus_radial_error(v: np.ndarray) -> np.ndarray:
    """Distance (m) of points to the bumpy torus of :func:`torus_1m` along the tube's radius
    (the bumps are gentle, 0.3 m over 6-12 m wavelengths, so this is the surface distance to
    within a few per cent)."""
    p = v - [500_000, 4_000_000, 100]
    u = np.arctan2(p[:, 1], p[:, 0])
    rho = np.hypot(p[:, 0], p[:, 1]) - 10.0
    w = np.arctan2(p[:, 2], rho)
    return np.abs(np.hypot(rho, p[:, 2]) - (3.0 + 0.3 * np.sin(5 * u) * np.cos(3 * w)))


def _capture_fd1(fn, *a, **k):
    """Run fn with the process's stdout (fd 1, where Open3D's C++ logger writes) captured."""
    import tempfile

    sys.stdout.flush()
    saved = os.dup(1)
    with tempfile.TemporaryFile(mode="w+b") as tmp:
        os.dup2(tmp.fileno(), 1)
        try:
            out = fn(*a, **k)
        finally:
            sys.stdout.flush()
            os.dup2(saved, 1)
            os.close(saved)
        tmp.seek(0)
        text = tmp.read().decode("utf-8", "replace")
    return out, text


def poisson_profile(threads, variants):
    """Where the time of Open3D's Poisson (depth 10, 1 M points) goes, per PoissonRecon stage
    (its own profiler, Debug verbosity), for parameter variants; accuracy against the analytic
    torus. ``variants``: "spn:pw:full_depth" strings."""
    import re

    import open3d as o3d

    cloud = torus_1m()
    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.xyz - [500_000, 4_000_000, 100]))
    pc.normals = o3d.utility.Vector3dVector(np.asarray(cloud.attrs["normal"], float))
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Debug)
    for var in variants:
        spn, pw, fd = (float(x) for x in var.split(":"))
        call = lambda: o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(  # noqa: E731
            pc, depth=10, n_threads=threads, samples_per_node=spn, point_weight=pw, full_depth=int(fd))
        ((m, _), text), wall, cpu = timed(_capture_fd1, call)
        stages = {}
        for key in ("Got kernel density", "Got normal field", "Finalized tree", "Set FEM constraints",
                    "Set point constraints", "Linear system solved", "Got average", "Got Iso-surface"):
            hit = re.search(re.escape(key) + r":\s*([0-9.]+) \(s\)", text)
            if hit:
                stages[key] = round(float(hit.group(1)), 1)
        err = torus_radial_error(np.asarray(m.vertices) + [500_000, 4_000_000, 100])
        emit(bench="poisson_depth10_1M_profile", backend="open3d", samples_per_node=spn, point_weight=pw,
             full_depth=int(fd), threads=threads, faces=len(m.triangles), wall_s=round(wall, 1), cpu_s=round(cpu, 1),
             stages_wall_s=stages, radial_error_mm={"p50": round(1000 * float(np.median(err)), 2),
                                                     "p95": round(1000 * float(np.percentile(err, 95)), 2),
                                                     "rms": round(1000 * float(np.sqrt(np.mean(err ** 2))), 2)},
             omp_wait_policy=os.environ.get("OMP_WAIT_POLICY"), loadavg=os.getloadavg()[0])
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Warning)


def poisson_1m_open3d():
    """The same cloud and depth through Open3D's Poisson (the anchor for the ratio)."""
    import open3d as o3d

    cloud = torus_1m()
    pc = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.xyz - [500_000, 4_000_000, 100]))
    pc.normals = o3d.utility.Vector3dVector(np.asarray(cloud.attrs["normal"], float))
    (m, _), wall, cpu = timed(o3d.geometry.TriangleMesh.create_from_point_cloud_poisson, pc, depth=10)
    emit(bench="poisson_depth10_1M_open3d_anchor", points=cloud.n, faces=len(m.triangles), wall_s=round(wall, 1),
         cpu_s=round(cpu, 1))


HERITAGE_MAX_POINTS = 600_000  # church points meshed at most (a seeded random subset beyond)


def heritage_chain(poisson_backend: str | None = None):
    """The meshing chain of the heritage benches: normals from 12 neighbours oriented toward
    each point's viewpoint, screened Poisson depth 9 trimmed at the 5 % density quantile
    (``poisson_backend``: None = the package default), pieces < 5 % of the diagonal removed,
    quadric decimation to 200,000 faces."""
    from workstation.mesh import (CleanParams, DecimateParams, MeshChainParams, NormalParams, PoissonParams,
                                  QualityParams)

    backend = {} if poisson_backend is None else {"backend": poisson_backend}
    return MeshChainParams(method="poisson", normals=NormalParams(k=12),
                           poisson=PoissonParams(depth=9, trim_quantile=0.05, **backend),
                           clean=CleanParams(min_piece_fraction=0.05), decimate=DecimateParams(target_faces=200_000),
                           quality=QualityParams(max_cloud_points=300_000))


def mesh_vs_truth(mesh, truth, samples: int = 300_000):
    """Distance statistics (m) mesh -> true mesh and true mesh -> mesh, each from ``samples``
    area-uniform samples of one surface to the other surface (MeshLab Hausdorff)."""
    from workstation.interop.pymeshlab import mesh_to_pymeshlab
    from workstation.mesh.quality import _hausdorff, _stats

    a, o = mesh_to_pymeshlab(mesh)
    b, _ = mesh_to_pymeshlab(truth, origin=o)
    d_t2m = _hausdorff(b, a, True, samples, 200.0)
    return _stats(_hausdorff(a, b, True, samples, 200.0)), {**_stats(d_t2m), "within_0.1m": float(np.mean(d_t2m <= 0.1))}


def heritage(poisson_backend: str | None = None):
    """Synthetic heritage church (simulator scene), 8 TLS stations on a 35 m circle, screened
    Poisson of the church returns (normals toward each point's station) against the true mesh."""
    from dataclasses import replace

    from workstation.core.products import Mesh
    from workstation.lidar.platforms import Station
    from workstation.lidar.scene import SceneRecipe, build_scene
    from workstation.lidar.survey import default_survey, run_survey
    from workstation.mesh import mesh_cloud

    rec = SceneRecipe(name="heritage", extent=(120.0, 120.0), buildings=0, courtyards=0, heritage=True, trees=0,
                      bushes=0, grass_patches=0, cars=0, stream=False, pond=False, powerline=False)
    scene = build_scene(rec, 0)
    oid = next(int(k) for k, v in scene.meta["objects"].items() if v == "heritage_church")
    fm = scene.object_id == oid
    used = np.unique(scene.faces[fm])
    lo, hi = scene.vertices[used].min(0), scene.vertices[used].max(0)
    centre, height = 0.5 * (lo + hi), float(hi[2] - lo[2])
    stations = tuple(Station(float(centre[0] + 35 * np.cos(a)), float(centre[1] + 35 * np.sin(a)), 1.6)
                     for a in np.linspace(0, 2 * np.pi, 8, endpoint=False))
    cfg = default_survey("tls")
    cfg = replace(cfg, stations=stations, scanner=replace(cfg.scanner, h_step_deg=0.12, v_step_deg=0.12))
    res = run_survey(scene, cfg, seed=0)
    c = res.cloud
    ch = c[np.asarray(c.attrs["object_id"]) == oid]
    traj = res.true_trajectory  # station i is point source i + 1
    spos = np.array([traj.position[np.searchsorted(traj.time, sg.t0)] for sg in traj.segments]) + scene.origin
    vp = spos[np.asarray(ch.attrs["point_source_id"]).astype(int) - 1]
    keep = np.sort(np.random.default_rng(0).choice(ch.n, min(HERITAGE_MAX_POINTS, ch.n), replace=False))
    out, wall, cpu = timed(mesh_cloud, Cloud(ch[keep].xyz), heritage_chain(poisson_backend), vp[keep])
    remap = -np.ones(len(scene.vertices), int)
    remap[used] = np.arange(len(used))
    truth = Mesh(scene.vertices[used] + scene.origin, remap[scene.faces[fm]])
    m2t, t2m = mesh_vs_truth(out.mesh, truth)
    emit(bench="heritage_church_tls_poisson", tls_points=int(c.n), church_points=int(ch.n), meshed_points=int(keep.size),
         height_m=height, faces=out.mesh.n_faces, mesh_to_truth_m={k: round(v, 4) for k, v in m2t.items()},
         truth_to_mesh_m={k: round(v, 4) for k, v in t2m.items()},
         rms_over_height_percent=round(100 * m2t["rms"] / height, 3), mesh_wall_s=round(wall, 1),
         mesh_cpu_s=round(cpu, 1))


def nearest_face(vertices: np.ndarray, faces: np.ndarray, xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index (n,) of the nearest face of a triangle mesh to each point of ``xyz`` (n, 3), and the
    distance (n,) in the mesh's units (Open3D's closest-point query)."""
    import open3d as o3d

    rs = o3d.t.geometry.RaycastingScene()
    o = vertices.mean(0)
    rs.add_triangles(o3d.core.Tensor((vertices - o).astype(np.float32)), o3d.core.Tensor(faces.astype(np.uint32)))
    q = rs.compute_closest_points(o3d.core.Tensor((xyz - o).astype(np.float32)))
    return q["primitive_ids"].numpy().astype(np.int64), np.linalg.norm(q["points"].numpy() + o - xyz, axis=1)


def truth_samples(truth, n: int = 300_000, n_dirs: int = 64, seed: int = 0, occluders=None) -> dict:
    """``n`` area-uniform samples (n, 3) of a true mesh with the orientation class of their face
    (``up``: normal z > 0.3, roofs and ledges; ``wall``: |z| <= 0.3; ``down``: z < -0.3,
    soffits) and whether they are ``open``: at least one of ``n_dirs`` random rays over the
    outer hemisphere (from 2 cm off the face) escapes ``occluders`` (a mesh, default ``truth``;
    give the whole scene so that the terrain counts). Samples that are not open lie below the
    ground or on faces enclosed by other parts: no survey sees them."""
    import open3d as o3d

    rng = np.random.default_rng(seed)
    a = truth.face_areas()
    f = rng.choice(truth.n_faces, size=n, p=a / a.sum())
    u, v = rng.random((2, n))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    t = truth.vertices[truth.faces]
    nrm = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    nrm = (nrm / np.linalg.norm(nrm, axis=1, keepdims=True))[f]
    t = t[f]
    xyz = t[:, 0] + u[:, None] * (t[:, 1] - t[:, 0]) + v[:, None] * (t[:, 2] - t[:, 0])
    occ = truth if occluders is None else occluders
    o = truth.vertices.mean(0)
    rs = o3d.t.geometry.RaycastingScene()
    rs.add_triangles(o3d.core.Tensor((occ.vertices - o).astype(np.float32)),
                     o3d.core.Tensor(occ.faces.astype(np.uint32)))
    dirs = rng.normal(size=(n_dirs, 3))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    org = xyz + 0.02 * nrm - o
    open_ = np.zeros(n, bool)
    for d in dirs:
        dd = np.where((nrm @ d)[:, None] > 0, d, -d)
        hit = rs.cast_rays(o3d.core.Tensor(np.hstack([org, dd]).astype(np.float32)))["t_hit"].numpy()
        open_ |= ~np.isfinite(hit)
    cls = np.where(nrm[:, 2] > 0.3, "up", np.where(nrm[:, 2] < -0.3, "down", "wall"))
    return {"xyz": xyz, "class": cls, "open": open_}


def coverage(samples: dict, mesh, tol: float = 0.1) -> dict:
    """Share of the true surface samples (:func:`truth_samples`) within ``tol`` (m) of ``mesh``:
    all of them, the open ones, and per orientation class (with its share of the true area and
    of its open part)."""
    _, d = nearest_face(mesh.vertices, mesh.faces, samples["xyz"])
    near, op = d <= tol, samples["open"]
    out = {"tol_m": tol, "all": round(float(near.mean()), 3), "open": round(float(near[op].mean()), 3),
           "open_share": round(float(op.mean()), 3)}
    for name in ("up", "wall", "down"):
        m = samples["class"] == name
        out[name] = {"area_share": round(float(m.mean()), 3), "open_share": round(float(op[m].mean()), 3),
                     "all": round(float(near[m].mean()), 3), "open": round(float(near[m & op].mean()), 3)}
    return out


def heritage_fused(work: Path, with_truth_pose: bool = False, poisson_backend: str | None = None):
    """The heritage church of the synthetic photo rig (``datasets_synth/rig_heritage.toml``)
    meshed from its simulated TLS survey merged with the rig's dense cloud, against the true
    church mesh (data of ``bench_register.py --sfm-tls WORKDIR``, made there if missing).

    The dense cloud (SfM frame, arbitrary scale) is brought into the scene frame as a user would:
    ``register(dense, tls, method="similarity")``; the camera-truth similarity (SfM camera
    centres fitted to the rig's true cameras) is reported as a check. Church points: the TLS
    returns the simulator labels as the church, and the dense points whose nearest true face is
    a church face (the same truth-based selection for both). Normals are oriented toward each
    point's viewpoint: its station for TLS points, the nearest registered camera centre for
    dense points. Then the chain of :func:`heritage` (same parameters) and the same distances.
    Rows: the TLS alone (the control on the same survey), TLS + dense, and with
    ``with_truth_pose`` TLS + dense placed by the camera-truth similarity."""
    sys.path.insert(0, str(REPO / "scripts"))
    from bench_register import sfm_tls_data, sfm_tls_survey, similarity_errors

    from workstation.core.products import Mesh
    from workstation.lidar.scene import build_scene
    from workstation.lidar.survey import survey_trajectory
    from workstation.mesh import mesh_cloud
    from workstation.mesh.normals import viewpoints_from_reconstruction
    from workstation.photogrammetry.georef import Similarity, transform_reconstruction
    from workstation.photogrammetry.rigs import load_rig, load_truth
    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.registration.register import RegisterParams, register
    from workstation.registration.transforms import make_transform

    wall0, cpu0 = time.perf_counter(), time.process_time()
    work = Path(work)
    dense, tls, sim, resid, data_s = sfm_tls_data(work)  # calibrated SfM, as bench_register's default
    recipe, spec = load_rig(REPO / "datasets_synth" / "rig_heritage.toml")
    scene = build_scene(recipe, spec.seed)
    truth = load_truth(work / "rig")  # scene-local frame, like ``tls``
    tri = truth["faces"][truth["target"]]
    used, inv = np.unique(tri, return_inverse=True)
    church = Mesh(truth["vertices"][used], inv.reshape(-1, 3))
    height = float(np.ptp(church.vertices[:, 2]))
    oid = next(int(k) for k, v in scene.meta["objects"].items() if v == spec.target)
    samples = truth_samples(church, occluders=Mesh(truth["vertices"], truth["faces"]))

    # TLS: church returns, each with its station (point source i + 1 = station i)
    traj = survey_trajectory(scene, sfm_tls_survey(recipe, spec))
    spos = np.array([traj.position[np.searchsorted(traj.time, sg.t0)] for sg in traj.segments])
    ch = tls[np.asarray(tls.attrs["object_id"]) == oid]
    vp_tls = spos[np.asarray(ch.attrs["point_source_id"]).astype(int) - 1]

    # dense: 7-DoF registration to the whole TLS cloud, from the identity (the SfM frame)
    src = Cloud(dense.xyz)
    r, wall_r, cpu_r = timed(register, src, tls, RegisterParams(method="similarity"))
    S = make_transform(sim.R, sim.t, sim.scale)
    est = read_reconstruction(work / "rig_sfm_cal" / "sparse" / "0")
    reg_check = {**similarity_errors(src.xyz, r.transform, S), "fitness": round(r.fitness, 4),
                 "inlier_rmse_m": round(r.inlier_rmse, 4), "wall_s": round(wall_r, 1), "cpu_s": round(cpu_r, 1)}
    emit(bench="heritage_fused_registration", dense_points=dense.n, tls_points=tls.n,
         cameras_registered=int(resid.size), camera_truth_rms_m=round(float(np.sqrt(np.mean(resid ** 2))), 4),
         registration_vs_camera_truth=reg_check, data_s={k: round(v, 1) for k, v in data_s.items()})

    def run(label, T=None):
        if T is None:
            xyz, vp, n_dense, d_dense = ch.xyz, vp_tls, 0, None
        else:
            A = T[:3, :3]
            sc = float(np.cbrt(np.linalg.det(A)))
            dxyz = dense.xyz @ A.T + T[:3, 3]
            f, dist = nearest_face(truth["vertices"], truth["faces"], dxyz)
            on = truth["target"][f]
            d_dense = {"p50": round(float(np.median(dist[on])), 4), "p95": round(float(np.percentile(dist[on], 95)), 4),
                       "rms": round(float(np.sqrt(np.mean(dist[on] ** 2))), 4)}
            rec = transform_reconstruction(est, Similarity(sc, A / sc, T[:3, 3]))
            d = Cloud(dxyz[on])
            xyz = np.vstack([ch.xyz, d.xyz])
            vp = np.vstack([vp_tls, viewpoints_from_reconstruction(d, rec)])
            n_dense = d.n
        keep = np.sort(np.random.default_rng(0).choice(len(xyz), min(HERITAGE_MAX_POINTS, len(xyz)), replace=False))
        t, c = time.perf_counter(), time.process_time()
        out = mesh_cloud(Cloud(xyz[keep]), heritage_chain(poisson_backend), vp[keep])
        wall, cpu = time.perf_counter() - t, time.process_time() - c
        m2t, t2m = mesh_vs_truth(out.mesh, church)
        emit(bench=f"heritage_fused_{label}", poisson_backend=next(st.params["backend"] for st in out.steps if st.name == "poisson"),
             church_height_m=round(height, 3), tls_church_points=int(ch.n),
             dense_church_points=int(n_dense), dense_church_points_to_truth_m=d_dense, meshed_points=int(keep.size),
             faces=out.mesh.n_faces,
             mesh_to_truth_m={k: round(v, 4) for k, v in m2t.items()},
             truth_to_mesh_m={k: round(v, 4) for k, v in t2m.items()},
             truth_covered=coverage(samples, out.mesh),
             rms_over_height_percent=round(100 * m2t["rms"] / height, 3), mesh_wall_s=round(wall, 1),
             mesh_cpu_s=round(cpu, 1), load1=os.getloadavg()[0])

    run("tls_only")
    run("tls_dense_registered", r.transform)
    if with_truth_pose:
        run("tls_dense_camera_truth", S)
    emit(bench="heritage_fused_total", wall_s=round(time.perf_counter() - wall0, 1),
         cpu_s=round(time.process_time() - cpu0, 1))


def texture_heritage(workdir, jitter: float = 0.0, balance: bool = True, consistency: bool = True):
    """Texture the true heritage-church mesh from the 24 photos of the synthetic convergent rig
    (datasets_synth/rig_heritage.toml, true cameras); texture colour at random points of the
    textured church faces against the scene's true surface colour (0-255). With ``jitter`` J,
    each photo's channels are first multiplied by gains drawn from U(1 - J, 1 + J) (seed 7:
    photos of unequal exposure), and the error is also given after the one gain per channel
    that best fits the truth (what exposure balancing can recover)."""
    from workstation.core.products import Mesh
    from workstation.mesh import TextureParams, subdivide_midpoint, texture_from_photos
    from workstation.photogrammetry.rigs import _target_scene, load_rig, make_rig, surface_colour
    from workstation.registration.colorize import bilinear

    from workstation.photogrammetry.sfm import read_reconstruction

    recipe, spec = load_rig("rig_heritage")
    wall_r = None
    if not (Path(workdir) / "cameras.json").exists():  # the rig is kept between runs (--work)
        _, wall_r, _ = timed(make_rig, recipe, spec, workdir, overwrite=True)
    rec = read_reconstruction(workdir)
    V, F, alb, tmask, *_ = _target_scene(recipe, spec)
    # the church only (the ground around it is not what is measured), subdivided so that no
    # face is longer than 2 m (the true mesh has 30 m wall triangles, rarely whole in a photo)
    used, inv = np.unique(F[tmask], return_inverse=True)
    V, F, vals = subdivide_midpoint(V[used], inv.reshape(-1, 3), np.column_stack([alb[tmask], np.ones(tmask.sum())]),
                                    max_edge=2.0)
    mesh = Mesh(V, F)
    images = None
    if jitter:
        from workstation.io.images import read_image

        rng = np.random.default_rng(7)
        images = {i: np.clip(np.round(read_image(im, workdir)[..., :3] * rng.uniform(1 - jitter, 1 + jitter, 3)), 0, 255)
                  .astype(np.uint8) for i, im in sorted(rec.images.items())}
    (out, step), wall, cpu = timed(texture_from_photos, mesh, rec, TextureParams(exposure_balance=balance,
                                                                             photo_consistency=consistency),
                                   images=images, image_root=workdir)
    tex = out.meta["texture"]
    h, w = tex.shape[:2]
    rng = np.random.default_rng(0)
    ok = np.flatnonzero((out.face_attrs["texture_view"] >= 0) & (vals[:, 3] > 0.5))
    faces = rng.choice(ok, 100_000)
    bary = rng.dirichlet([2.0, 2.0, 2.0], len(faces))
    t = out.vertices[out.faces[faces]]
    P = np.einsum("nk,nkd->nd", bary, t)
    uv = np.einsum("nk,nkd->nd", bary, np.asarray(out.vertex_attrs["uv"], float)[out.faces[faces]])
    col = bilinear(tex, uv[:, 0] * w - 0.5, (1 - uv[:, 1]) * h - 0.5)
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    truth = 255 * surface_colour(P, n / np.linalg.norm(n, axis=1, keepdims=True), vals[faces, :3])
    err = np.abs(col - truth)
    fit = np.abs(col * (col * truth).sum(0) / (col * col).sum(0) - truth)
    area = mesh.face_areas()
    church = vals[:, 3] > 0.5
    seen = out.face_attrs["texture_view"] >= 0
    emit(bench="texture_heritage_rig", images=len(rec.images), faces=mesh.n_faces,
         texture_px=[int(w), int(h)], texel_size_m=round(step.params["texel_size"], 4),
         church_area_textured_fraction=round(float(area[church & seen].sum() / area[church].sum()), 3),
         abs_error_0_255={"p50": round(float(np.median(err)), 2), "mean": round(float(err.mean()), 2),
                          "p95": round(float(np.percentile(err, 95)), 2)},
         exposure_jitter=jitter, exposure_balance=balance, gain_range=step.summary["exposure_gain_range"],
         photo_consistency=step.summary["photo_consistency"],
         abs_error_after_global_gain={"p50": round(float(np.median(fit)), 2), "mean": round(float(fit.mean()), 2)},
         texture_wall_s=round(wall, 1), texture_cpu_s=round(cpu, 1),
         rig_render_wall_s=None if wall_r is None else round(wall_r, 1))


#: Occluders of the box-and-wall rig missing from the textured mesh: centre, size (m), albedo.
OCCLUDERS = {"branch": ((1.0, 5.0, 1.0), (0.8, 0.4, 0.6), (0.25, 0.55, 0.1)),
             "pole": ((-2.0, 7.0, 0.0), (0.2, 0.2, 10.0), (0.35, 0.22, 0.12))}


def texture_occluder(name: str):
    """The box-and-wall rig of tests/mesh/test_mesh_texture.py (5 cameras, 200 x 150 px)
    rendered with an extra box (``OCCLUDERS[name]``: a floating "branch", a thin pole) that
    the textured mesh lacks; texture colour vs the true wall and box colour, on the faces the
    occluder hides from at least one candidate view (centroid ray) and on all faces, with and
    without the photo-consistency check, 1 and 2 views per face."""
    from workstation.core.products import Camera, Image, Mesh, Reconstruction
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.mesh import TextureParams, subdivide_midpoint, texture_from_photos
    from workstation.mesh.texture import select_views
    from workstation.photogrammetry.rigs import box_wall_scene, look_at, render, surface_colour
    from workstation.registration.colorize import bilinear

    V, F, alb = box_wall_scene()
    Vs, Fs, As = subdivide_midpoint(np.asarray(V, float), F, alb, times=3)
    mesh = Mesh(Vs, Fs)
    c, size, albedo = OCCLUDERS[name]
    cube = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], float)
    bv = np.asarray(c) + 0.5 * cube * np.asarray(size)
    bf = F[2:] - 4  # box_wall_scene's box faces, on the cube's corners in the same order
    scene_v, scene_f = np.vstack([V, bv]), np.vstack([F, bf + len(V)])
    scene_a = np.vstack([alb, np.tile(albedo, (len(bf), 1))])
    cam = Camera(200, 150, 190.0, 185.0, 101.0, 73.5)
    images, pix = {}, {}
    for k, x in enumerate(np.linspace(-2.5, 2.5, 5), start=1):
        pose = look_at(np.array([x, 0.0, 0.5 * ((k - 1) % 2)]), np.array([0.0, 10.0, 0.0]))
        images[k] = Image(f"im{k}.png", 1, pose)
        pix[k] = render(scene_v, scene_f, scene_a, cam, pose, 1)
    rec = Reconstruction({1: cam}, images)
    views, _, _ = select_views(mesh, rec, TextureParams(), 8)
    cen = Vs[Fs].mean(axis=1)
    occ = RaycastScene(bv, bf)
    hidden = np.zeros(len(Fs), bool)
    for iid, im in images.items():
        f = np.flatnonzero((views == iid).any(axis=1))
        d = cen[f] - im.pose.center
        dl = np.linalg.norm(d, axis=1)
        t, _ = occ.cast(np.broadcast_to(im.pose.center, d.shape), d / dl[:, None])
        hidden[f[t < dl]] = True

    def error(out, sel):
        tex = out.meta["texture"]
        h, w = tex.shape[:2]
        rng = np.random.default_rng(0)
        faces = rng.choice(np.flatnonzero((out.face_attrs["texture_view"] >= 0) & sel), 20000)
        bary = rng.dirichlet([2.0, 2.0, 2.0], len(faces))
        t = Vs[Fs[faces]]
        P = np.einsum("nk,nkd->nd", bary, t)
        uv = np.einsum("nk,nkd->nd", bary, np.asarray(out.vertex_attrs["uv"], float)[out.faces[faces]])
        n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
        truth = 255 * surface_colour(P, n / np.linalg.norm(n, axis=1, keepdims=True), As[faces])
        e = np.abs(bilinear(tex, uv[:, 0] * w - 0.5, (1 - uv[:, 1]) * h - 0.5) - truth)
        return {"p50": round(float(np.median(e)), 2), "mean": round(float(e.mean()), 2),
                "p95": round(float(np.percentile(e, 95)), 2)}

    for views_per_face in (1, 2):
        for check in (False, True):
            (out, step), wall, cpu = timed(texture_from_photos, mesh, rec,
                                           TextureParams(max_views=views_per_face, photo_consistency=check), images=pix)
            emit(bench="texture_occluder", occluder=name, faces=mesh.n_faces, faces_hidden=int(hidden.sum()),
                 max_views=views_per_face, photo_consistency=check, check=step.summary["photo_consistency"],
                 abs_error_hidden_faces=error(out, hidden), abs_error_all_faces=error(out, np.ones(len(Fs), bool)),
                 texture_wall_s=round(wall, 2), texture_cpu_s=round(cpu, 2))


def render_10m():
    from workstation.render import RenderParams, render

    rng = np.random.default_rng(1)
    n = 10_000_000
    xy = rng.uniform(0, 1000, (n, 2))
    z = 100 + 10 * np.sin(xy[:, 0] / 80) * np.cos(xy[:, 1] / 120)
    cloud = Cloud(np.column_stack([xy + [500_000, 4_000_000], z]), {"classification": rng.choice([2, 5, 6], n)})
    img, wall, cpu = timed(render, cloud, RenderParams(size=(1920, 1080), view="top", color="elevation"))
    emit(bench="render_10M_1920x1080", points=n, wall_s=round(wall, 1), cpu_s=round(cpu, 1), shape=list(img.shape))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default="render,poisson,poisson_backend_open3d,poisson_open3d,bunny,heritage")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--work", default="/tmp/bench_mesh_rig", help="texture: folder of the rendered rig (kept)")
    ap.add_argument("--sfm-work", default="/tmp/reg_sfm",
                    help="heritage_fused: data folder of bench_register.py --sfm-tls (made there if missing)")
    ap.add_argument("--poisson-backend", choices=("open3d", "pymeshlab"), default=None,
                    help="heritage, heritage_fused: Poisson backend (default: the package's)")
    ap.add_argument("--with-truth-pose", action="store_true",
                    help="heritage_fused: also mesh with the dense cloud placed by the camera-truth similarity")
    ap.add_argument("--exposure-jitter", type=float, default=0.0,
                    help="texture: multiply each photo's channels by gains from U(1-J, 1+J) (seed 7)")
    ap.add_argument("--no-exposure-balance", action="store_true", help="texture: without the exposure balance")
    ap.add_argument("--no-photo-consistency", action="store_true", help="texture: without the photo-consistency check")
    ap.add_argument("--occluder", choices=sorted(OCCLUDERS), default=None,
                    help="texture: instead of the heritage rig, the box-and-wall rig with this occluder in the photos")
    ap.add_argument("--mls", action="store_true", help="bunny: also project the vertices on the scans' MLS planes")
    ap.add_argument("--trims", default="0.05", help="bunny: density trim quantiles, comma separated")
    ap.add_argument("--samples-per-node", type=float, default=2.0, help="poisson, poisson_backend_open3d (2: the package default)")
    ap.add_argument("--variants", default="1.5:4:5,5:4:5,1.5:0:5",
                    help="poisson_profile: samples_per_node:point_weight:full_depth, comma separated")
    a = ap.parse_args()
    todo = a.only.split(",")
    if "render" in todo:
        render_10m()
    if "poisson" in todo:
        poisson_1m(a.threads, samples_per_node=a.samples_per_node)
    if "poisson_backend_open3d" in todo:
        poisson_1m(a.threads, backend="open3d", samples_per_node=a.samples_per_node)
    if "poisson_profile" in todo:
        os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")
        poisson_profile(a.threads, a.variants.split(","))
    if "poisson_open3d" in todo:
        poisson_1m_open3d()
    if "bunny" in todo:
        bunny(a.threads, tuple(float(t) for t in a.trims.split(",")), a.mls, a.poisson_backend)
    if "heritage" in todo:
        heritage(a.poisson_backend)
    if "texture" in todo:
        if a.occluder:
            texture_occluder(a.occluder)
        else:
            texture_heritage(Path(a.work), a.exposure_jitter, not a.no_exposure_balance, not a.no_photo_consistency)
    if "heritage_fused" in todo:
        heritage_fused(Path(a.sfm_work), a.with_truth_pose, a.poisson_backend)
