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
- fscore: the heritage rig's 24 photos through ws sfm (rig intrinsics) and ws dense (CPU), the
  dense cloud and its ws mesh (per ``--support-trims``) against the true church seen by ≥ 2
  cameras: precision / recall / F-score at 1, 2, 5, 10 cm (rig and SfM kept in ``--work``);
  ``--image-size WxH`` renders the rig at another size with the same field of view (in
  ``WORK_WxH``), ``--fscore-camera true`` skips SfM for the rig's true cameras (dense accuracy
  without the SfM frame error), ``--dense-size`` and ``--poisson-depth`` set ws dense's image
  size and ws mesh's Poisson depth.
- render: a 1920x1080 top-view render of a 10,000,000-point cloud.
- texture: the true heritage-church mesh (and the ground around it) textured from the 24
  photos of the synthetic rig, texture colour vs the true surface colour, and the floor: the
  same points sampled directly in the photo of their face's view, bilinear and nearest pixel
  (``--tree``: a tree in front of the east façade in the photos only; ``--image-size WxH``:
  the rig rendered at that size, as for fscore); with ``--occluder branch|pole``, instead the
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
from collections.abc import Mapping
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


def heritage_texture_scene(workdir, image_size=None):
    """The synthetic convergent rig of the heritage church (datasets_synth/rig_heritage.toml,
    true cameras, rendered into ``workdir`` once and kept; ``image_size`` (width, height): the
    rig at that size and the same field of view, :func:`rig_spec_at`) and the mesh to texture: the true
    church, subdivided so that no edge exceeds 2 m (its 30 m wall triangles are rarely whole
    in a photo), and the ground within 5 m of its footprint (the ground hides the church's foot
    below the terrain in the photos, as it does in a photogrammetric mesh).

    Returns (rec, mesh, vals (m, 4): albedo and 1 on church faces, scene (V, F, albedo) as
    rendered, church centre, rig-render wall seconds or None)."""
    from workstation.core.products import Mesh
    from workstation.mesh import subdivide_midpoint
    from workstation.photogrammetry.rigs import _target_scene, load_rig, make_rig
    from workstation.photogrammetry.sfm import read_reconstruction

    recipe, spec = load_rig("rig_heritage")
    spec = rig_spec_at(spec, image_size)
    wall_r = None
    if not (Path(workdir) / "cameras.json").exists():  # the rig is kept between runs (--work)
        _, wall_r, _ = timed(make_rig, recipe, spec, workdir, overwrite=True)
    rec = read_reconstruction(workdir)
    V0, F0, alb, tmask, _, centre, _ = _target_scene(recipe, spec)
    used, inv = np.unique(F0[tmask], return_inverse=True)
    V, F, vals = subdivide_midpoint(V0[used], inv.reshape(-1, 3), np.column_stack([alb[tmask], np.ones(tmask.sum())]),
                                    max_edge=2.0)
    lo, hi = V0[used, :2].min(axis=0) - 5.0, V0[used, :2].max(axis=0) + 5.0
    cen = V0[F0].mean(axis=1)[:, :2]
    ground = ~tmask & np.all((cen >= lo) & (cen <= hi), axis=1)
    used_g, inv_g = np.unique(F0[ground], return_inverse=True)
    V = np.vstack([V, V0[used_g]])
    F = np.vstack([F, inv_g.reshape(-1, 3) + len(V) - len(used_g)])
    vals = np.vstack([vals, np.column_stack([alb[ground], np.zeros(ground.sum())])])
    return rec, Mesh(V, F), vals, (V0, F0, alb), centre, wall_r


def heritage_tree(centre) -> tuple:
    """A tree missing from the textured mesh, 10 m in front of the church's east façade (x = 7 m
    from the church centre's x + 17.5 m) on the axis of camera 1: a 0.6 m trunk from 3 m under
    the church's foot and a 4 m crown 8 m above it. Returns (V, F, albedo (n, 3) 0-1)."""
    import open3d as o3d

    base = np.array([centre[0] + 27.5, centre[1], centre[2]])
    crown = o3d.geometry.TriangleMesh.create_sphere(radius=4.0, resolution=16)
    crown.translate(base + [0.0, 0.0, 8.0])
    trunk = o3d.geometry.TriangleMesh.create_cylinder(radius=0.3, height=9.0, resolution=12)
    trunk.translate(base + [0.0, 0.0, 1.5])
    parts = [(np.asarray(g.vertices), np.asarray(g.triangles), c)
             for g, c in ((crown, (0.22, 0.45, 0.12)), (trunk, (0.35, 0.25, 0.15)))]
    V = np.vstack([p[0] for p in parts])
    F = np.vstack([parts[0][1], parts[1][1] + len(parts[0][0])])
    alb = np.vstack([np.tile(c, (len(f), 1)) for _, f, c in parts])
    return V, F, alb


def cameras_seeing(rec, scene_v, scene_f, P) -> np.ndarray:
    """(n, len(rec.images)) bool: whether each camera sees each point ``P`` (inside the image,
    first hit of the ray from the camera within 2 cm of the point) in the scene (V, F)."""
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.registration.colorize import project

    caster = RaycastScene(scene_v, scene_f)
    out = np.zeros((len(P), len(rec.images)), bool)
    for j, (iid, im) in enumerate(sorted(rec.images.items())):
        cam = rec.cameras[im.camera_id]
        u, v, z = project(P, cam, im.pose)
        d = P - im.pose.center
        dl = np.linalg.norm(d, axis=1)
        t, _ = caster.cast(np.broadcast_to(im.pose.center, d.shape), d / dl[:, None])
        out[:, j] = (z > 0) & (u >= 0) & (u <= cam.width - 1) & (v >= 0) & (v <= cam.height - 1) & (t >= dl - 0.02)
    return out


def tree_share(rec, scene, with_tree, P, view, err, stats) -> dict:
    """The façade behind the tree (the points ``P`` it hides from at least one camera that sees
    them in ``scene`` (V, F); ``with_tree`` the scene with the tree) and the share of it, and of
    all points, textured from a view (``view``: image id per point) in which the tree hides the
    point; the colour error ``err`` there."""
    ids = sorted(rec.images)
    behind = cameras_seeing(rec, *scene, P) & ~cameras_seeing(rec, *with_tree, P)
    facade = behind.any(axis=1)
    painted = behind[np.arange(len(P)), np.searchsorted(ids, view)]
    return {"facade_points": int(facade.sum()),
            "tree_colour_share_of_facade": round(float(painted[facade].mean()), 4),
            "tree_colour_share_of_church": round(float(painted.mean()), 4),
            "abs_error_facade": stats(err[facade].ravel())}


class PhotosOnce(Mapping):
    """The photos of ``rec`` (image id -> (h, w, 3) pixels), each read from ``root`` when first
    asked for and kept: the texturing reads them inside its timing, as it does when given no
    pixels, and the photo floor samples the same arrays without reading them again."""

    def __init__(self, rec, root):
        self.rec, self.root, self.pixels = rec, root, {}

    def __getitem__(self, iid):
        if iid not in self.pixels:
            from workstation.io.images import read_image

            self.pixels[iid] = read_image(self.rec.images[iid], self.root)[..., :3]
        return self.pixels[iid]

    def __contains__(self, iid):
        return iid in self.rec.images

    def __iter__(self):
        return iter(sorted(self.rec.images))

    def __len__(self):
        return len(self.rec.images)


def photo_samples(rec, view: np.ndarray, P: np.ndarray, images) -> dict:
    """The colours (n, 3) of the points ``P`` (n, 3) in the photo of their view ``view`` (n,
    image ids), sampled directly: {"bilinear": ..., "nearest": ... (the pixel holding the
    point)}; ``images``: image id -> pixels. For the points of a texture made from those
    views, the floor of its colour error: what the photos give without the texture's own
    resampling."""
    from workstation.registration.colorize import bilinear, project

    out = {"bilinear": np.zeros((len(P), 3)), "nearest": np.zeros((len(P), 3))}
    for iid in np.unique(view):
        sel = np.flatnonzero(view == iid)
        im = rec.images[int(iid)]
        cam = rec.cameras[im.camera_id]
        pix = images[int(iid)]
        u, v, _ = project(P[sel], cam, im.pose)
        u, v = np.clip(u, 0, cam.width - 1), np.clip(v, 0, cam.height - 1)
        out["bilinear"][sel] = bilinear(pix, u, v)[:, :3]
        out["nearest"][sel] = pix[np.rint(v).astype(int), np.rint(u).astype(int), :3]
    return out


def texture_heritage(workdir, jitter: float = 0.0, balance: bool = True, consistency: bool = True,
                     tree: bool = False, last_resort: bool = True, max_views: int = 1, texel_size: float | None = None,
                     image_size: tuple[int, int] | None = None):
    """Texture the church and ground of :func:`heritage_texture_scene` from the 24 photos;
    texture colour at random points of the textured church faces against the scene's true
    surface colour (0-255). The textured share of the church is given of all its area and of
    the area some photo sees (face centroids visible from at least one camera in the rendered
    scene). With ``jitter`` J, each photo's channels are first multiplied by gains drawn from
    U(1 - J, 1 + J) (seed 7: photos of unequal exposure), and the error is also given after the
    one gain per channel that best fits the truth. With ``tree``, the photos show
    :func:`heritage_tree` (not in the mesh); the points its crown or trunk hides from some
    camera are the façade behind it, and a point takes the tree's colour when the tree hides
    it from the view its face is textured from. ``max_views`` and ``texel_size`` are passed to
    :class:`TextureParams` (views blended per face; texel size, m); ``image_size``: the rig at
    that size (``workdir``: :func:`rig_workdir`). The floor: the same points in their view's photo."""
    from workstation.mesh import TextureParams, texture_from_photos
    from workstation.mesh.texture import ranked_views
    from workstation.photogrammetry.rigs import render, surface_colour
    from workstation.registration.colorize import bilinear

    rec, mesh, vals, (V0, F0, alb0), centre, wall_r = heritage_texture_scene(workdir, image_size)
    images = PhotosOnce(rec, workdir)
    if tree:
        tv, tf, ta = heritage_tree(centre)
        sv, sf, sa = np.vstack([V0, tv]), np.vstack([F0, tf + len(V0)]), np.vstack([alb0, ta])
        cache = Path(workdir) / "tree_photos.npz"  # rendered once, kept with the rig
        if not cache.exists():
            np.savez(cache, **{str(i): render(sv, sf, sa, rec.cameras[im.camera_id], im.pose, 2)
                               for i, im in sorted(rec.images.items())})
        with np.load(cache) as z:
            images = {int(i): z[i] for i in z.files}
    if jitter:
        rng = np.random.default_rng(7)
        images = {i: np.clip(np.round(a * rng.uniform(1 - jitter, 1 + jitter, 3)), 0, 255).astype(np.uint8)
                  for i, a in images.items()}
    (out, step), wall, cpu = timed(texture_from_photos, mesh, rec,
                                   TextureParams(exposure_balance=balance, photo_consistency=consistency,
                                                 last_resort=last_resort, max_views=max_views, texel_size=texel_size),
                                   images=images, image_root=workdir)
    church = vals[:, 3] > 0.5
    tex = out.meta["texture"]
    h, w = tex.shape[:2]
    rng = np.random.default_rng(0)
    view = out.face_attrs["texture_view"]
    faces = rng.choice(np.flatnonzero((view >= 0) & church), 100_000)
    bary = rng.dirichlet([2.0, 2.0, 2.0], len(faces))
    t = out.vertices[out.faces[faces]]
    P = np.einsum("nk,nkd->nd", bary, t)
    uv = np.einsum("nk,nkd->nd", bary, np.asarray(out.vertex_attrs["uv"], float)[out.faces[faces]])
    col = bilinear(tex, uv[:, 0] * w - 0.5, (1 - uv[:, 1]) * h - 0.5)
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    truth = 255 * surface_colour(P, n / np.linalg.norm(n, axis=1, keepdims=True), vals[faces, :3])
    err = np.abs(col - truth)
    fit = np.abs(col * (col * truth).sum(0) / (col * col).sum(0) - truth)
    stats = lambda e: {"p50": round(float(np.median(e)), 2), "mean": round(float(e.mean()), 2),  # noqa: E731
                       "p95": round(float(np.percentile(e, 95)), 2)}
    area = mesh.face_areas()
    seen = view >= 0
    full = ranked_views(mesh, rec, TextureParams(), 1)[3][:, 0][faces]  # points on faces with full views
    visible = cameras_seeing(rec, V0, F0, mesh.vertices[mesh.faces].mean(axis=1)).any(axis=1)
    extra = tree_share(rec, (V0, F0), (sv, sf), P, view[faces], err, stats) if tree else {}
    # the floor is the photos' own: with jittered exposures it would include the jitter the gains undo
    floor = {} if jitter else {k: stats(np.abs(c - truth)[full])
                               for k, c in photo_samples(rec, view[faces], P, images).items()}
    emit(bench="texture_heritage_rig", images=len(rec.images), faces=mesh.n_faces, church_faces=int(church.sum()),
         tree=tree, last_resort=last_resort, max_views=max_views, texture_px=[int(w), int(h)],
         texel_size_m=round(step.params["texel_size"], 4),
         church_area_textured_fraction=round(float(area[church & seen].sum() / area[church].sum()), 3),
         church_area_seen_fraction=round(float(area[church & visible].sum() / area[church].sum()), 3),
         seen_area_textured_fraction=round(float(area[church & visible & seen].sum() / area[church & visible].sum()), 3),
         abs_error_0_255=stats(err), abs_error_full_views=stats(err[full]), photo_floor_full_views=floor,
         abs_error_last_resort=stats(err[~full]) if (~full).any() else None,
         area_last_resort_fraction=round(step.summary["area_last_resort_fraction"], 4), **extra,
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
    views, _, _ = select_views(mesh, rec, TextureParams(last_resort=False), 8)  # faces with full views
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


def rig_spec_at(spec, image_size: tuple[int, int] | None):
    """The rig ``spec`` at another image size (width, height) with the same field of view: the
    focal length scales with the width; the aspect ratio must be the rig's. None: ``spec``."""
    from dataclasses import replace

    from workstation.core.errors import InvalidInputError

    if image_size is None or tuple(image_size) == (spec.width, spec.height):
        return spec
    w, h = (int(x) for x in image_size)
    if w < 8 or h < 8 or w * spec.height != h * spec.width:
        raise InvalidInputError(f"--image-size {w}x{h}: needs the rig's aspect ratio {spec.width}:{spec.height}",
                                field="image_size")
    return replace(spec, width=w, height=h, focal_px=spec.focal_px * w / spec.width)


def rig_workdir(work, image_size: tuple[int, int] | None) -> Path:
    """Folder of the heritage rig rendered at ``image_size`` (width, height): ``work`` itself
    at the rig's own size (or None), else ``WORK_WxH`` beside it."""
    from workstation.photogrammetry.rigs import load_rig

    work = Path(work)
    _, spec0 = load_rig("rig_heritage")
    spec = rig_spec_at(spec0, image_size)
    return work if spec is spec0 else work.parent / f"{work.name}_{spec.width}x{spec.height}"


def fscore_data(work: Path, spec, camera: str = "sfm", dense_size: int = 1600):
    """The rendered rig (``work``), its oriented workdir and dense cloud, both kept between
    runs: ``camera`` "sfm" runs ``ws sfm`` with the rig's intrinsics held fixed
    (``WORK_sfm``); "true" copies the rig's true cameras (``WORK_true``; dense depth range
    0.1-2.4 times the rig's distance, as there are no sparse points). ``ws dense`` on the CPU
    at ``dense_size`` (longest side, pixels; -1: full size; 1600 is its default). Returns
    (cloud, workdir, {sfm,dense}_{wall,cpu}_s of the steps run now: 0 when cached)."""
    import shutil

    from workstation.io import read_cloud
    from workstation.photogrammetry.dense import DenseParams, run_dense
    from workstation.photogrammetry.rigs import load_rig, make_rig
    from workstation.photogrammetry.sfm import run_sfm

    recipe, _ = load_rig("rig_heritage")
    if not (work / "cameras.json").exists():
        make_rig(recipe, spec, work, overwrite=True)
    times = {"sfm_wall_s": 0.0, "sfm_cpu_s": 0.0, "dense_wall_s": 0.0, "dense_cpu_s": 0.0}
    wall0, cpu0 = time.perf_counter(), time.process_time()
    sparse_dir = work.parent / f"{work.name}_{camera}"
    wd = sparse_dir if dense_size == 1600 else work.parent / f"{work.name}_{camera}_dense{dense_size}"
    extra = {}
    if camera == "true":
        extra["depth_range"] = (0.1 * spec.distance, 2.4 * spec.distance)
        if not (sparse_dir / "sparse" / "0").exists():
            shutil.copytree(work / "sparse" / "0", sparse_dir / "sparse" / "0")
    elif not (sparse_dir / "sparse" / "0").exists():
        run_sfm(work / "images", sparse_dir, spec.camera(), overwrite=True)
        times.update(sfm_wall_s=time.perf_counter() - wall0, sfm_cpu_s=time.process_time() - cpu0)
    if not (wd / "sparse" / "0").exists():
        shutil.copytree(sparse_dir / "sparse" / "0", wd / "sparse" / "0")
    fused = wd / "dense" / "fused.ply"
    if fused.exists():
        return read_cloud(fused), wd, times
    wall0, cpu0 = time.perf_counter(), time.process_time()
    cloud = run_dense(wd, work / "images", DenseParams(device="cpu", max_image_size=dense_size, **extra),
                      overwrite=True)[0]
    times.update(dense_wall_s=time.perf_counter() - wall0, dense_cpu_s=time.process_time() - cpu0)
    return cloud, wd, times


def fscore_heritage(work: Path, support_trims=(0.0, 3.0), refine_ks=(0,), image_size=None, camera: str = "sfm",
                    dense_size: int = 1600, depth: int = 9):
    """Dense and mesh F-score on the synthetic heritage rig (issue 24): the rig's 24 photos
    (rendered into ``work`` when missing; ``image_size`` (width, height): the rig at that size
    and the same field of view, in ``WORK_WxH``) oriented and densified by :func:`fscore_data`,
    the cloud placed in the truth frame by the similarity of the SfM camera centres to the true
    ones (the identity for true cameras), meshed by
    the chain of ``ws mesh`` with its defaults (normals toward the cameras, Poisson ``depth`` 9,
    density trim 5 %, pieces < 5 % removed) for each support trim and MLS refinement (k points, 0 =
    none); precision, recall and F at
    1, 2, 5 and 10 cm against the true church seen by ≥ 2 true cameras
    (:func:`workstation.mesh.quality.fscore_against_truth`)."""
    from workstation.core.products import Mesh
    from workstation.mesh import CleanParams, MeshChainParams, PoissonParams, mesh_cloud
    from workstation.mesh.quality import FScoreParams, fscore_against_truth
    from workstation.mesh.reconstruct import RefineParams
    from workstation.photogrammetry.georef import fit_similarity, transform_reconstruction
    from workstation.photogrammetry.rigs import load_rig, load_truth
    from workstation.photogrammetry.sfm import read_reconstruction

    _, spec0 = load_rig("rig_heritage")
    spec = rig_spec_at(spec0, image_size)
    work = rig_workdir(work, image_size)
    cloud, wd, times = fscore_data(work, spec, camera, dense_size)
    true = read_reconstruction(work / "cameras.json")
    est = read_reconstruction(wd / "sparse" / "0")
    by_name = {im.name: im.pose.center for im in true.images.values()}
    names = [im.name for im in est.images.values() if im.name in by_name]
    src = np.array([im.pose.center for im in est.images.values() if im.name in by_name])
    sim = fit_similarity(src, np.array([by_name[n] for n in names]))
    cam_rms = float(np.sqrt(np.mean(np.sum((sim.apply(src) - np.array([by_name[n] for n in names])) ** 2, axis=1))))
    cloud = Cloud(sim.apply(cloud.xyz), {"normal": np.asarray(cloud.attrs["normal"], float) @ np.asarray(sim.R).T})
    rec = transform_reconstruction(est, sim)
    T = load_truth(work)
    truth, target = Mesh(T["vertices"], T["faces"]), T["target"]
    fp = FScoreParams(taus=(0.01, 0.02, 0.05, 0.1))
    common = dict(image_size=f"{spec.width}x{spec.height}", camera=camera, dense_size=dense_size,
                  pixel_at_rig_distance_m=round(spec.distance / spec.focal_px, 4))

    def row(label, recon, **kw):
        t, c = time.perf_counter(), time.process_time()
        out = fscore_against_truth(recon, truth, true, target, fp)
        emit(bench=f"fscore_heritage_{label}", **common, **kw, registered=len(names), images=len(true.images),
             camera_truth_rms_m=round(cam_rms, 4),
             scores={f"{tau * 100:g}cm": {k: round(v, 3) for k, v in d.items()} for tau, d in out["scores"].items()},
             recon_samples=out["recon_samples"], truth_samples=out["truth_samples"],
             truth_seen_share=round(out["truth_seen_share"], 3),
             precision_dist_m={k: round(v, 4) for k, v in out["precision_dist"].items()},
             recall_dist_m={k: round(v, 4) for k, v in out["recall_dist"].items()},
             fscore_wall_s=round(time.perf_counter() - t, 1), fscore_cpu_s=round(time.process_time() - c, 1),
             load1=os.getloadavg()[0])

    row("dense", cloud.xyz, points=cloud.n, **{k: round(v, 1) for k, v in times.items()})
    for trim in support_trims:
        for k in refine_ks:
            params = MeshChainParams(poisson=PoissonParams(depth=depth, support_trim=trim),
                                     refine=RefineParams(k=k) if k else None,
                                     clean=CleanParams(min_piece_fraction=0.05), color=None, quality=None, texture=None)
            res, wall, cpu = timed(mesh_cloud, cloud, params, rec)
            row("mesh", res.mesh, depth=depth, support_trim=trim, refine_k=k, faces=res.mesh.n_faces,
                mesh_wall_s=round(wall, 1), mesh_cpu_s=round(cpu, 1))


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
    ap.add_argument("--tree", action="store_true", help="texture: a tree in front of the church in the photos only")
    ap.add_argument("--no-last-resort", action="store_true", help="texture: without grazing / partly hidden views")
    ap.add_argument("--max-views", type=int, default=1, help="texture (heritage rig): views blended per face")
    ap.add_argument("--texel-size", type=float, default=None,
                    help="texture (heritage rig): one texel size, m (default: per face, from its photo footprint)")
    ap.add_argument("--occluder", choices=sorted(OCCLUDERS), default=None,
                    help="texture: instead of the heritage rig, the box-and-wall rig with this occluder in the photos")
    ap.add_argument("--mls", action="store_true", help="bunny: also project the vertices on the scans' MLS planes")
    ap.add_argument("--support-trims", default="0,3",
                    help="fscore: Poisson support trims (point spacings, 0 = off), comma separated")
    ap.add_argument("--refine-ks", default="0",
                    help="fscore: MLS refinement neighbours (0 = none), comma separated")
    ap.add_argument("--image-size", default=None, metavar="WxH",
                    help="fscore, texture (heritage rig): render the rig at this size, same field of view, "
                         "in WORK_WxH (default: the rig's 640x480)")
    ap.add_argument("--fscore-camera", choices=("sfm", "true"), default="sfm",
                    help="fscore: orient by ws sfm (rig intrinsics fixed) or use the rig's true cameras")
    ap.add_argument("--dense-size", type=int, default=1600,
                    help="fscore: ws dense --max-image-size (longest side, px; -1 full size; 1600 its default)")
    ap.add_argument("--poisson-depth", type=int, default=9, help="fscore: Poisson octree depth (9: ws mesh's default)")
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
    size = tuple(int(x) for x in a.image_size.lower().split("x")) if a.image_size else None
    if "texture" in todo:
        if a.occluder:
            texture_occluder(a.occluder)
        else:
            texture_heritage(rig_workdir(a.work, size), a.exposure_jitter, not a.no_exposure_balance,
                             not a.no_photo_consistency, a.tree, not a.no_last_resort, a.max_views, a.texel_size, size)
    if "fscore" in todo:
        fscore_heritage(Path(a.work), tuple(float(t) for t in a.support_trims.split(",")),
                        tuple(int(k) for k in a.refine_ks.split(",")), size,
                        a.fscore_camera, a.dense_size, a.poisson_depth)
    if "heritage_fused" in todo:
        heritage_fused(Path(a.sfm_work), a.with_truth_pose, a.poisson_backend)
