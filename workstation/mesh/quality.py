"""Mesh quality summary: counts, topology (watertight, genus), area, volume, distances to a cloud.

Distances to the input cloud follow MeshLab's Hausdorff filter (Cignoni et al., "Metro:
measuring error on simplified surfaces", CGF 1998):

- mesh -> cloud: points sampled on the faces uniformly by area, distance to the nearest cloud
  point (how far the surface strays from the data: invented surface shows here);
- cloud -> mesh: every cloud point's distance to the nearest point of the surface (how much
  of the data the surface misses).
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


def _sample_surface(mesh: Mesh, n: int, seed: int = 0) -> np.ndarray:
    """n points (n, 3) sampled uniformly by area on the faces (seeded)."""
    rng = np.random.default_rng(seed)
    a = mesh.face_areas()
    f = rng.choice(mesh.n_faces, size=int(n), p=a / a.sum())
    u, v = rng.random((2, int(n)))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    t = mesh.vertices[mesh.faces[f]]
    return t[:, 0] + u[:, None] * (t[:, 1] - t[:, 0]) + v[:, None] * (t[:, 2] - t[:, 0])


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
        samples = _sample_surface(mesh, n_samples)
        out["mesh_to_cloud_local_plane"] = _stats(local_plane_distance(samples, ref.xyz))
        out["mesh_to_cloud_floor"] = _stats(nearest_point_floor(samples, ref.xyz))
        out["cloud_to_mesh"] = _stats(_hausdorff(m, c, False, ref.n, diag))
    return out
