"""Normal estimation and orientation for point clouds (MeshLab ``compute_normal_for_point_clouds``).

Normals are fitted by PCA of the k nearest neighbours (Hoppe et al., "Surface reconstruction
from unorganized points", SIGGRAPH 1992). Their sign is then chosen, in order of preference:
toward the scanner or camera that saw each point when those positions are known (the only
choice that is right on thin and multi-sided objects), straight up for terrain, or by
MeshLab's propagation over the neighbour graph (Hoppe's minimum-spanning-tree orientation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Reconstruction

from .steps import StepRecord, Timer, import_pymeshlab

log = get_logger(__name__)

ORIENTATIONS = ("auto", "viewpoint", "up", "propagate", "keep")


@dataclass(frozen=True)
class NormalParams:
    """Parameters of normal estimation.

    Attributes
    ----------
    k : int
        Neighbours used for each PCA plane fit (count).
    smooth_iterations : int
        Passes of neighbour averaging of the normals after the fit (count; 0 = none).
    orient : {"auto", "viewpoint", "up", "propagate", "keep"}
        How signs are chosen: ``viewpoint`` toward the given scanner/camera positions, ``up``
        with a positive Z component (terrain, aerial scans), ``propagate`` consistently over
        the neighbour graph, ``keep`` leave the fitted sign. ``auto`` = ``viewpoint`` when
        positions are given, else ``propagate``.
    recompute : bool
        Re-estimate even when the cloud already carries ``normal``.
    """

    k: int = 10
    smooth_iterations: int = 0
    orient: str = "auto"
    recompute: bool = False

    def __post_init__(self):
        if self.k < 3:
            raise InvalidInputError(f"k={self.k}: a plane fit needs at least 3 neighbours", field="k")
        if self.orient not in ORIENTATIONS:
            raise InvalidInputError(f"unknown orientation '{self.orient}'", "use one of " + ", ".join(ORIENTATIONS),
                                    field="orient")


def viewpoints_from_reconstruction(cloud: Cloud, rec: Reconstruction) -> np.ndarray:
    """Per-point viewpoint (n, 3): the centre of the nearest camera of ``rec``.

    A point seen by a camera lies in front of it, so the nearest camera centre is on the
    visible side of the surface for all but grazing views.
    """
    from scipy.spatial import cKDTree

    centres = np.array([np.asarray(im.pose.center, dtype=np.float64) for im in rec.images.values()])
    if centres.size == 0:
        raise InvalidInputError("the reconstruction has no oriented images", field="images")
    _, idx = cKDTree(centres).query(cloud.xyz)
    return centres[idx]


def orient_toward(xyz: np.ndarray, normals: np.ndarray, viewpoints: np.ndarray) -> np.ndarray:
    """Flip normals (n, 3) so each points toward its viewpoint ((3,) or (n, 3)), vectorised."""
    vp = np.broadcast_to(np.asarray(viewpoints, dtype=np.float64), xyz.shape)
    s = np.einsum("ij,ij->i", normals, vp - xyz)
    return np.where((s < 0)[:, None], -normals, normals)


def estimate_normals(cloud: Cloud, params: NormalParams = NormalParams(), viewpoints=None) -> tuple[Cloud, StepRecord]:
    """Estimate (or reuse) and orient per-point normals.

    Parameters
    ----------
    cloud : Cloud
    params : NormalParams
    viewpoints : (3,) or (n, 3) float, or Reconstruction, optional
        Scanner position(s) or cameras, in the cloud's coordinates. One position for a single
        scan, one per point for merged scans (e.g. looked up from ``point_source_id``).

    Returns
    -------
    (Cloud, StepRecord)
        A new cloud with ``normal`` (n, 3) float32 unit vectors; the input is unchanged.
    """
    if cloud.n < params.k + 1:
        raise InvalidInputError(f"{cloud.n} points: too few for normals with k={params.k}")
    if isinstance(viewpoints, Reconstruction):
        viewpoints = viewpoints_from_reconstruction(cloud, viewpoints)
    if viewpoints is not None:
        viewpoints = np.asarray(viewpoints, dtype=np.float64)
        if viewpoints.shape not in ((3,), (cloud.n, 3)):
            raise InvalidInputError(f"viewpoints must be (3,) or ({cloud.n}, 3), got {viewpoints.shape}",
                                    field="viewpoints")
    orient = params.orient
    if orient == "auto":
        orient = "viewpoint" if viewpoints is not None else "propagate"
    if orient == "viewpoint" and viewpoints is None:
        raise InvalidInputError("orientation 'viewpoint' needs scanner or camera positions",
                                "pass viewpoints, or use orient='propagate' or 'up'", field="orient")
    with Timer() as t:
        reused = "normal" in cloud.attrs and not params.recompute
        if reused:
            n = np.asarray(cloud.attrs["normal"], dtype=np.float64)
        else:
            pml = import_pymeshlab()
            from workstation.interop.pymeshlab import cloud_to_pymeshlab, meshset_with

            m, origin = cloud_to_pymeshlab(cloud.without_attrs(*[a for a in ("normal", "rgb") if a in cloud.attrs]))
            ms = meshset_with(m)
            # MeshLab orients by propagation over the kNN graph unless a view position is given.
            ms.compute_normal_for_point_clouds(k=int(params.k), smoothiter=int(params.smooth_iterations),
                                               flipflag=False, viewpos=np.zeros(3))
            n = np.asarray(ms.current_mesh().vertex_normal_matrix(), dtype=np.float64)
            del pml
        norm = np.linalg.norm(n, axis=1)
        if n.shape != (cloud.n, 3) or not np.all(np.isfinite(n)) or np.any(norm < 1e-12):
            raise StageError("normals", "normal estimation failed for some points",
                             "remove duplicate points or raise k")
        n = n / norm[:, None]
        if orient == "viewpoint":
            n = orient_toward(cloud.xyz, n, viewpoints)
        elif orient == "up":
            n = np.where((n[:, 2] < 0)[:, None], -n, n)
        elif reused and orient == "propagate":
            orient = "keep"  # given normals are taken as oriented
    rec = StepRecord("normals", {"k": params.k, "smooth_iterations": params.smooth_iterations, "orient": orient,
                                 "reused_existing": bool(reused)}, t.seconds)
    out = cloud.with_attrs(normal=n.astype(np.float32)).with_history("mesh.normals", rec.params, t.seconds)
    return out, rec
