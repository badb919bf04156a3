"""Mesh quality summary: counts, topology (watertight, genus), area, volume, distances to a cloud.

Distances to the input cloud follow MeshLab's Hausdorff filter (Cignoni et al., "Metro:
measuring error on simplified surfaces", CGF 1998):

- mesh -> cloud: points sampled on the faces uniformly by area, distance to the nearest cloud
  point (how far the surface strays from the data: invented surface shows here);
- cloud -> mesh: every cloud point's distance to the nearest point of the surface (how much
  of the data the surface misses).

Against a known true surface, :func:`fscore_against_truth` gives the F-score of Knapitsch et
al., "Tanks and Temples: benchmarking large-scale scene reconstruction", ACM TOG 2017, and
Schöps et al., "A multi-view stereo benchmark with high-resolution images and multi-camera
videos" (ETH3D), CVPR 2017: at a tolerance τ, precision is the share of the reconstruction
(area-uniform samples of a mesh, or the points of a cloud) within τ of the true surface,
recall the share of the true surface (area-uniform samples of the part that at least two
cameras see) within τ of the reconstruction, and F = 2PR / (P + R).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.products import Mesh

from .steps import import_pymeshlab


@dataclass(frozen=True)
class QualityParams:
    """Parameters of the quality summary.

    Attributes
    ----------
    mesh_samples : int
        Points sampled on the surface for mesh -> cloud distances (count; 0 = one per face,
        at least 10,000).
    max_cloud_points : int
        Cloud points used for cloud -> mesh distances, a seeded random subset above this
        (count).
    self_intersections : bool
        Count self-intersecting faces.
    """

    mesh_samples: int = 0
    max_cloud_points: int = 1_000_000
    self_intersections: bool = True


def _stats(d: np.ndarray) -> dict:
    d = np.asarray(d, dtype=np.float64)
    return {"mean": float(d.mean()), "rms": float(np.sqrt(np.mean(d ** 2))), "max": float(d.max()),
            "p50": float(np.percentile(d, 50)), "p95": float(np.percentile(d, 95)), "n": int(d.size)}


def sample_surface(mesh: Mesh, n: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """n points (n, 3) sampled uniformly by area on the faces (seeded), and the face (n,) of
    each: a face is drawn with probability proportional to its area, then a point uniformly
    in it (two uniform barycentric coordinates folded back into the triangle)."""
    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces to sample", field="faces")
    rng = np.random.default_rng(seed)
    a = mesh.face_areas()
    if not a.sum() > 0:
        raise InvalidInputError("the mesh has zero area: no surface to sample", field="faces")
    f = rng.choice(mesh.n_faces, size=int(n), p=a / a.sum())
    u, v = rng.random((2, int(n)))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    t = mesh.vertices[mesh.faces[f]]
    return t[:, 0] + u[:, None] * (t[:, 1] - t[:, 0]) + v[:, None] * (t[:, 2] - t[:, 0]), f


def _hausdorff(surface, points, sample_faces: bool, n: int, maxdist: float) -> np.ndarray:
    """Per-sample distances (n,) float64: from samples on ``surface`` faces to ``points``
    (``sample_faces``), or from every vertex of ``points`` to ``surface``."""
    pml = import_pymeshlab()
    from workstation.interop.pymeshlab import meshset_with

    ms = meshset_with(surface, points)  # ids 0 and 1
    sampled, target = (0, 1) if sample_faces else (1, 0)
    ms.get_hausdorff_distance(sampledmesh=sampled, targetmesh=target, savesample=True, samplevert=not sample_faces,
                              sampleedge=False, sampleface=sample_faces, samplenum=int(n),
                              maxdist=pml.PureValue(float(maxdist)))
    # savesample adds two layers (ids 2 and 3): the closest points, and the samples with
    # their distance as vertex quality
    for mid in (2, 3):
        if ms.mesh_id_exists(mid) and ms.mesh(mid).label() == "Hausdorff Sample Point":
            return np.asarray(ms.mesh(mid).vertex_scalar_array(), dtype=np.float64)
    raise StageError("quality", "MeshLab's Hausdorff filter did not return its samples")


def _local_planes(samples: np.ndarray, xyz: np.ndarray, k: int):
    """Nearest-neighbour distances (m, k), centroids (m, 3) and unit normals (m, 3) of the
    least-squares planes of each sample's k nearest points of ``xyz``."""
    from scipy.spatial import cKDTree

    tree = cKDTree(xyz)
    d, idx = tree.query(samples, k=k)
    d = d.reshape(len(samples), k)
    nb = xyz[idx.reshape(len(samples), k)]
    c = nb.mean(axis=1)
    x = nb - c[:, None, :]
    _, vec = np.linalg.eigh(np.einsum("mki,mkj->mij", x, x))
    return tree, d, c, vec[:, :, 0]


def nearest_point_floor(samples: np.ndarray, xyz: np.ndarray, k: int = 8) -> np.ndarray:
    """Distance (m,) from the foot of each sample on the local plane of its k nearest points
    to the nearest point: what the point-to-nearest-point distance would be for a surface lying
    exactly on the data's local surface. Its RMS is the floor of the mesh -> cloud RMS that the
    point spacing alone sets (about 0.41 x the spacing for a regular grid)."""
    k = int(min(k, len(xyz)))
    tree, _, c, n = _local_planes(samples, xyz, k)
    foot = samples - np.einsum("mi,mi->m", samples - c, n)[:, None] * n
    return tree.query(foot)[0]


def local_plane_distance(samples: np.ndarray, xyz: np.ndarray, k: int = 8) -> np.ndarray:
    """Distance (m,) from each sample (m, 3) to the least-squares plane of its k nearest points
    of ``xyz`` (n, 3) (CloudCompare's cloud-to-cloud distance with a local plane model), made
    conservative outside the neighbourhood: ``max(plane distance, nearest distance - r_k)``
    with r_k the distance to the k-th neighbour, so surface invented away from the data still
    counts. Removes the floor of point-to-point distances set by the point spacing.
    """
    k = int(min(k, len(xyz)))
    _, d, c, n = _local_planes(samples, xyz, k)
    plane = np.abs(np.einsum("mi,mi->m", samples - c, n))
    return np.maximum(plane, d[:, 0] - d[:, -1])


def mesh_quality(mesh: Mesh, cloud: Cloud | None = None, params: QualityParams = QualityParams()) -> dict:
    """Quality figures of a mesh, and its distances to ``cloud`` when given.

    Returns
    -------
    dict
        ``faces``, ``vertices``, ``area`` (CRS units²), ``watertight`` (bool: no border and
        no non-manifold edge), ``two_manifold``, ``genus`` (None unless watertight),
        ``components``, ``holes``, ``boundary_edges``, ``non_manifold_edges``,
        ``non_manifold_vertices``, ``volume`` (CRS units³, None unless watertight),
        optionally ``self_intersecting_faces``, and with a cloud ``mesh_to_cloud`` and
        ``cloud_to_mesh`` (MeshLab Hausdorff, point to nearest point / point to surface) and
        ``mesh_to_cloud_local_plane`` (see :func:`local_plane_distance`) and
        ``mesh_to_cloud_floor`` (see :func:`nearest_point_floor`), each with ``mean``, ``rms``, ``max``, ``p50``, ``p95`` (CRS units).
    """
    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces")
    import_pymeshlab()
    from workstation.interop.pymeshlab import cloud_to_pymeshlab, mesh_to_pymeshlab, meshset_with

    m, origin = mesh_to_pymeshlab(Mesh(mesh.vertices, mesh.faces))
    ms = meshset_with(m)
    topo = ms.get_topological_measures()
    watertight = topo["boundary_edges"] == 0 and topo["non_two_manifold_edges"] == 0
    area = float(mesh.face_areas().sum())
    out = {
        "faces": mesh.n_faces,
        "vertices": mesh.n_vertices,
        "area": area,
        "watertight": bool(watertight),
        "two_manifold": bool(topo["is_mesh_two_manifold"]),
        "genus": int(topo["genus"]) if watertight and topo["is_mesh_two_manifold"] else None,
        "components": int(topo["connected_components_number"]),
        "holes": int(topo["number_holes"]) if topo["is_mesh_two_manifold"] else None,
        "boundary_edges": int(topo["boundary_edges"]),
        "non_manifold_edges": int(topo["non_two_manifold_edges"]),
        "non_manifold_vertices": int(topo["non_two_manifold_vertices"]),
        "volume": None,
    }
    if watertight:
        t = mesh.vertices[mesh.faces] - origin
        out["volume"] = float(abs(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum()) / 6.0)
    if params.self_intersections:
        ms.compute_selection_by_self_intersections_per_face()
        out["self_intersecting_faces"] = int(ms.current_mesh().selected_face_number())
        ms.set_selection_none()
    if cloud is not None:
        if cloud.n == 0:
            raise InvalidInputError("the reference cloud is empty")
        ref = cloud
        if cloud.n > params.max_cloud_points:
            idx = np.sort(np.random.default_rng(0).choice(cloud.n, params.max_cloud_points, replace=False))
            ref = cloud[idx]
        c, _ = cloud_to_pymeshlab(Cloud(ref.xyz), origin=origin)
        diag = float(np.linalg.norm(np.ptp(np.vstack([mesh.vertices, ref.xyz]), axis=0)))
        n_samples = params.mesh_samples or max(10_000, mesh.n_faces)
        out["mesh_to_cloud"] = _stats(_hausdorff(m, c, True, n_samples, diag))
        samples = sample_surface(mesh, n_samples)[0]
        out["mesh_to_cloud_local_plane"] = _stats(local_plane_distance(samples, ref.xyz))
        out["mesh_to_cloud_floor"] = _stats(nearest_point_floor(samples, ref.xyz))
        out["cloud_to_mesh"] = _stats(_hausdorff(m, c, False, ref.n, diag))
    return out


# ---------------------------------------------------------------------------------------------
# F-score against a true surface
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class FScoreParams:
    """Parameters of :func:`fscore_against_truth`.

    Attributes
    ----------
    taus : tuple of float
        Distance tolerances τ (CRS units).
    truth_samples : int
        Area-uniform samples drawn on the true target surface before the visibility test
        (count).
    recon_samples : int
        Area-uniform samples of a reconstructed mesh; a cloud with more points is reduced to a
        seeded random subset of this size (count).
    min_views : int
        A true sample counts for recall when at least this many cameras see it (in frame, in
        front, not hidden by the true scene).
    seed : int
    """

    taus: tuple = (0.01, 0.02, 0.05)
    truth_samples: int = 200_000
    recon_samples: int = 200_000
    min_views: int = 2
    seed: int = 0

    def __post_init__(self):
        if not self.taus or any(not np.isfinite(t) or t <= 0 for t in self.taus):
            raise InvalidInputError("every tolerance τ must be a positive number", field="taus")
        for name in ("truth_samples", "recon_samples", "min_views"):
            if getattr(self, name) < 1:
                raise InvalidInputError(f"{name} must be ≥ 1", field=name)


def mesh_scene(vertices: np.ndarray, faces: np.ndarray):
    """Ray-casting scene (:class:`~workstation.interop.open3d_raycast.RaycastScene`) of a
    triangle mesh in float32 around its vertices' mean, and that origin (3,), so that map
    coordinates keep their precision. Built once, it serves :func:`closest_on_mesh` and
    :func:`views_seeing` on the same mesh."""
    from workstation.interop.open3d_raycast import RaycastScene

    V = np.asarray(vertices, np.float64)
    o = V.mean(axis=0)
    return RaycastScene(V - o, faces), o


def closest_on_mesh(points: np.ndarray, vertices: np.ndarray, faces: np.ndarray,
                    scene=None) -> tuple[np.ndarray, np.ndarray]:
    """Distance (n,) from each point (n, 3) to the nearest point of a triangle mesh, and the
    index (n,) of that nearest face (:meth:`RaycastScene.closest
    <workstation.interop.open3d_raycast.RaycastScene.closest>` on :func:`mesh_scene`, or on
    ``scene``, that function's result for this mesh, when given)."""
    rs, o = mesh_scene(vertices, faces) if scene is None else scene
    p = np.asarray(points, np.float64) - o
    q, prim = rs.closest(p)
    return np.linalg.norm(q.astype(np.float64) - p, axis=1), prim


def views_seeing(points: np.ndarray, rec, vertices: np.ndarray, faces: np.ndarray,
                 rel_tol: float = 0.002, abs_tol: float = 1e-3, scene=None) -> np.ndarray:
    """How many cameras of ``rec`` (a Reconstruction in the points' frame) see each point
    (n, 3) of a surface: in front of the camera, inside its frame (OpenCV distortion
    included), and not hidden by the occluding mesh ``vertices``/``faces`` (the ray from the
    camera centre hits the mesh no nearer than the point, within ``rel_tol`` × range +
    ``abs_tol``). ``scene``: :func:`mesh_scene` of that mesh, when already built. The loop
    runs over the cameras; each is one vectorised ray cast."""
    from workstation.photogrammetry.collinearity import project

    scene, o = mesh_scene(vertices, faces) if scene is None else scene
    P = np.asarray(points, np.float64)
    count = np.zeros(len(P), np.int64)
    for im in rec.images.values():
        cam = rec.cameras[im.camera_id]
        C = np.asarray(im.pose.center, np.float64)
        d = P - C
        dist = np.linalg.norm(d, axis=1)
        uv, z = project(P, cam, im.pose, return_depth=True)
        inside = (z > 0) & (uv[:, 0] >= -0.5) & (uv[:, 0] < cam.width - 0.5) & (uv[:, 1] >= -0.5) & \
            (uv[:, 1] < cam.height - 0.5)
        t, _ = scene.cast(np.broadcast_to(C - o, d.shape), d / np.maximum(dist, 1e-12)[:, None])
        count += inside & (t >= dist - (rel_tol * dist + abs_tol))
    return count


def fscore(precision_dist: np.ndarray, recall_dist: np.ndarray, taus) -> dict:
    """Precision, recall and F-score per tolerance from the distances of the reconstruction's
    samples to the truth (``precision_dist``) and of the truth's samples to the
    reconstruction (``recall_dist``). Keys are the tolerances; F is 0 where P + R = 0."""
    pd_, rd = np.asarray(precision_dist, float), np.asarray(recall_dist, float)
    if pd_.size == 0 or rd.size == 0:
        raise InvalidInputError("an F-score needs reconstruction and truth samples",
                                "the reconstruction may lie outside the true target, or no camera sees it",
                                field="precision_dist" if pd_.size == 0 else "recall_dist")
    out = {}
    for tau in taus:
        p, r = float(np.mean(pd_ <= tau)), float(np.mean(rd <= tau))
        out[float(tau)] = {"precision": p, "recall": r, "f": 2 * p * r / (p + r) if p + r > 0 else 0.0}
    return out


def fscore_against_truth(recon, truth: Mesh, rec, target: np.ndarray | None = None,
                         params: FScoreParams = FScoreParams()) -> dict:
    """F-score of a reconstruction (a :class:`Mesh`, or (n, 3) points) against a true scene.

    ``truth`` is the whole true scene (it hides what the cameras of ``rec`` cannot see);
    ``target`` (m,) bool marks its faces that are measured (default all). Recall: area-uniform
    samples of the target faces seen by ≥ ``params.min_views`` cameras, distance to the
    reconstructed surface (mesh) or nearest point (cloud, KD-tree). Precision: samples of the
    reconstruction whose nearest true face is a target face (the reconstruction cropped to
    the target as Tanks and Temples crops to its bounding volume), distance to the true
    surface.

    Returns
    -------
    dict
        ``scores`` ({τ: {precision, recall, f}}), ``recon_samples`` (after the crop),
        ``truth_samples`` (seen ones), ``truth_seen_share``, ``precision_dist`` and
        ``recall_dist`` medians and 90th percentiles.
    """
    from scipy.spatial import cKDTree

    faces = np.asarray(truth.faces, np.int64)
    target = np.ones(len(faces), bool) if target is None else np.asarray(target, bool)
    if target.shape != (len(faces),) or not target.any():
        raise InvalidInputError("target must be one bool per true face, with at least one True", field="target")
    tm = Mesh(truth.vertices, faces[target])
    ts, _ = sample_surface(tm, params.truth_samples, params.seed)
    scene = mesh_scene(truth.vertices, faces)  # one scene for the visibility and the precision queries
    seen = views_seeing(ts, rec, truth.vertices, faces, scene=scene) >= params.min_views
    ts = ts[seen]
    if isinstance(recon, Mesh):
        rs, _ = sample_surface(recon, params.recon_samples, params.seed + 1)
        rd, _ = closest_on_mesh(ts, recon.vertices, recon.faces)
    else:
        rs = np.asarray(recon, np.float64)
        if rs.ndim != 2 or rs.shape[1] != 3 or len(rs) == 0:
            raise InvalidInputError("the reconstruction must be a Mesh or (n, 3) points", field="recon")
        rd = cKDTree(rs).query(ts)[0]
        if len(rs) > params.recon_samples:
            rs = rs[np.sort(np.random.default_rng(params.seed).choice(len(rs), params.recon_samples, replace=False))]
    pdist, pf = closest_on_mesh(rs, truth.vertices, faces, scene=scene)
    pdist = pdist[target[pf]]
    out = {"scores": fscore(pdist, rd, params.taus), "recon_samples": int(pdist.size), "truth_samples": int(len(ts)),
           "truth_seen_share": float(seen.mean())}
    for name, d in (("precision_dist", pdist), ("recall_dist", rd)):
        out[name] = {"p50": float(np.median(d)), "p90": float(np.percentile(d, 90))}
    return out

