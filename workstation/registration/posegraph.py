"""Multi-scan registration: pairwise edges, loop closures and a global pose-graph optimisation.

Sequential (odometry) edges i -> i+1 and loop-closure edges between every other overlapping
pair are registered pairwise; Open3D's pose graph is optimised with Levenberg-Marquardt and
line-process edge pruning (Choi, Zhou & Koltun 2015, "Robust reconstruction of indoor
scenes", CVPR). The result gives each scan's pose (scan -> frame of scan ``reference``) and a
residual table: how far each edge's measured transform disagrees with the optimised poses.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.geometry import default_origin
from workstation.core.log import get_logger

from .register import RegisterParams, register
from .transforms import invert, rotation_angle_deg

log = get_logger(__name__)
STAGE = "register-multiway"


@dataclass(frozen=True)
class EdgeRecord:
    """One pose-graph edge and its residual after optimisation.

    Attributes
    ----------
    source, target : int
        Scan indices; ``transform`` maps source into target.
    kind : str
        ``"odometry"`` (consecutive scans) or ``"loop"``.
    fitness, inlier_rmse : float
        Of the pairwise registration (rmse in metres).
    rotation_residual_deg, translation_residual : float
        Disagreement between the edge and the optimised poses (degrees, metres).
    kept : bool
        False when the optimiser pruned the edge as an outlier.
    """

    source: int
    target: int
    kind: str
    transform: np.ndarray
    fitness: float
    inlier_rmse: float
    rotation_residual_deg: float = float("nan")
    translation_residual: float = float("nan")
    kept: bool = True

    def to_dict(self) -> dict:
        return {"source": self.source, "target": self.target, "kind": self.kind, "fitness": self.fitness,
                "inlier_rmse": self.inlier_rmse, "rotation_residual_deg": self.rotation_residual_deg,
                "translation_residual": self.translation_residual, "kept": self.kept}


@dataclass(frozen=True)
class MultiwayResult:
    """Poses of every scan (4x4, scan -> reference frame) and the edge residual table."""

    poses: list
    edges: list
    reference: int = 0
    meta: dict = field(default_factory=dict)

    def residual_table(self) -> list[dict]:
        return [e.to_dict() for e in self.edges]

    def to_dict(self) -> dict:
        return {"reference": self.reference, "poses": [np.asarray(p).tolist() for p in self.poses],
                "edges": self.residual_table(), **self.meta}


@dataclass(frozen=True)
class MultiwayParams:
    """Parameters of :func:`register_multiway`.

    Attributes
    ----------
    pair : RegisterParams
        Pairwise registration (its ``voxel_size`` also scales the optimiser's distance).
    loop_closure : bool
        Also register non-consecutive pairs and add them as uncertain loop-closure edges.
    loop_min_fitness : float
        Loop-closure pairs below this fitness are left out (they do not overlap).
    edge_prune_threshold : float
        Open3D line-process threshold below which a loop edge is pruned.
    reference : int
        Index of the scan whose frame the poses are expressed in.
    initial_poses : list of (4, 4) float, optional
        Rough pose of every scan (scan -> one common frame, e.g. from GNSS or a field sketch):
        pairs are then refined by ICP from ``inv(P_j) P_i`` instead of global registration.
    """

    pair: RegisterParams = field(default_factory=RegisterParams)
    loop_closure: bool = True
    loop_min_fitness: float = 0.3
    edge_prune_threshold: float = 0.25
    reference: int = 0
    initial_poses: tuple | None = None


def register_multiway(clouds: list[Cloud], params: MultiwayParams = MultiwayParams()) -> MultiwayResult:
    """Register many overlapping scans into the frame of ``params.reference``.

    Parameters
    ----------
    clouds : list of Cloud
        At least two scans, consecutive ones overlapping.
    params : MultiwayParams

    Returns
    -------
    MultiwayResult

    Raises
    ------
    StageError
        When an odometry edge fails (the chain would break).
    """
    from workstation.interop.open3d import require_open3d, world_transform

    require_open3d()
    n = len(clouds)
    if n < 2:
        raise InvalidInputError(f"{n} scan(s) given; multi-scan registration needs 2 or more")
    if params.initial_poses is not None and len(params.initial_poses) != n:
        raise InvalidInputError(f"{len(params.initial_poses)} initial poses for {n} scans", field="initial_poses")
    if not 0 <= params.reference < n:
        raise InvalidInputError(f"reference {params.reference} out of range", field="reference")
    if params.pair.method == "similarity":
        raise InvalidInputError("the pose graph holds rigid poses; a similarity (scale) between scans is not one",
                                "register the scans rigidly, or scale the odd one first (ws register --method "
                                "similarity)", field="pair.method")
    origin = default_origin(clouds[params.reference].xyz)
    edges, L, infos = _pair_edges(clouds, params, origin)
    voxel = float(params.pair.voxel_size) if params.pair.voxel_size else None
    if voxel is None:
        from .preprocess import estimate_voxel_size

        voxel = estimate_voxel_size(clouds[params.reference].xyz - origin)
    P, kept_pairs = _optimise_pose_graph(n, edges, L, infos, voxel, params)
    out_edges = [_edge_residuals(e, L[(e.source, e.target)], P, clouds[e.source].xyz.mean(axis=0) - origin, kept_pairs)
                 for e in edges]
    poses = [world_transform(p, origin, origin) for p in P]
    return MultiwayResult(poses, out_edges, params.reference, {"voxel_size": voxel, "n_scans": n})


def _pair_edges(clouds: list[Cloud], params: MultiwayParams,
                origin: np.ndarray) -> tuple[list[EdgeRecord], dict, dict]:
    """Register each consecutive pair (odometry edges, which must succeed) and, with
    ``params.loop_closure``, every other pair (loop edges, kept only when they pass
    ``params.loop_min_fitness``); from the initial poses when given (ICP only). Returns the
    edges, their transforms in the pose graph's local frame (world minus ``origin``) by
    ``(i, j)``, and their 6 x 6 information matrices by ``(i, j)``, expressed in that frame as
    the graph's residuals are (:func:`_graph_information`)."""
    from workstation.interop.open3d import local_transform

    n = len(clouds)
    edges: list[EdgeRecord] = []
    L: dict = {}
    infos: dict = {}
    for i in range(n):
        for j in range(i + 1, n):
            odo = j == i + 1
            if not odo and not params.loop_closure:
                continue
            p = params.pair if odo else replace(params.pair, min_fitness=params.loop_min_fitness)
            init = None
            if params.initial_poses is not None:
                init = invert(np.asarray(params.initial_poses[j], float)) @ np.asarray(params.initial_poses[i], float)
                p = replace(p, method="icp")
            try:
                r = register(clouds[i], clouds[j], p, init=init)
            except StageError as e:
                if odo:
                    raise StageError(STAGE, f"scans {i} and {j} could not be registered: {e.message}", e.hint) from None
                log.info("no loop closure %d-%d: %s", i, j, e.message)
                continue
            edges.append(EdgeRecord(i, j, "odometry" if odo else "loop", r.transform, r.fitness, r.inlier_rmse))
            L[(i, j)] = local_transform(r.transform, origin, origin)
            infos[(i, j)] = np.eye(6) if r.information is None else _graph_information(
                r.information, np.asarray(r.meta["origin"], float) - origin, L[(i, j)])
            log.info("edge %d->%d (%s): fitness %.3f", i, j, edges[-1].kind, r.fitness)
    return edges, L, infos


def _graph_information(info: np.ndarray, shift: np.ndarray, L: np.ndarray) -> np.ndarray:
    """Re-express a pairwise information matrix in the frame of the pose graph's residual.

    Open3D's ``get_information_matrix_from_point_clouds`` returns ``sum G(q)^T G(q)`` over the
    target points ``q`` of the correspondences, in the pair registration's local frame, with
    ``G(q) = [-[q]x | I]`` (the motion of ``q`` under a small twist ``(omega, v)``). The pose
    graph's residual is the twist of ``inv(L) inv(P_t) P_s``: a motion of the *source* scan, in
    the graph's local frame. The matrix is therefore moved to the source points
    ``p = R^T (q + shift - tau)`` of the same correspondences, where ``L = (R, tau)`` is the
    edge's transform and ``shift`` the registration's origin minus the graph's: since
    ``G(q + a) = G(q) J(a)`` with ``J(a) = [[I, 0], [-[a]x, I]]`` and
    ``G(R^T b) = R^T G(b) diag(R, R)``, the result is ``M^T info M`` with
    ``M = J(shift - tau) diag(R, R)``. Without this the weights depend on where the scans'
    coordinates happen to lie and on how far each pair is turned, and the optimised poses move
    with them.
    """
    R, tau = L[:3, :3], L[:3, 3]
    a = np.asarray(shift, dtype=np.float64) - tau
    M = np.zeros((6, 6))
    M[:3, :3] = R
    M[3:, 3:] = R
    M[3:, :3] = -np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]]) @ R
    return M.T @ np.asarray(info, dtype=np.float64) @ M


def _optimise_pose_graph(n: int, edges: list[EdgeRecord], L: dict, infos: dict, voxel: float,
                         params: MultiwayParams) -> tuple[list[np.ndarray], set]:
    """Global pose-graph optimisation (Choi, Zhou & Koltun 2015; Open3D's Levenberg-Marquardt
    with line processes): nodes start at the chained odometry (scan -> scan 0), loop edges are
    uncertain and may be pruned. ``L`` holds the edges' local-frame transforms. Returns the
    poses (local frame) relative to the reference scan and the ``(i, j)`` of the edges kept."""
    from workstation.interop.open3d import require_open3d

    o3d = require_open3d()
    reg = o3d.pipelines.registration
    # chain odometry for initial poses (scan -> scan 0), local frame
    pose0 = [np.eye(4)]
    for i in range(1, n):
        pose0.append(pose0[-1] @ invert(L[(i - 1, i)]))
    graph = reg.PoseGraph()
    for i in range(n):
        graph.nodes.append(reg.PoseGraphNode(pose0[i]))
    for e in edges:
        graph.edges.append(reg.PoseGraphEdge(e.source, e.target, L[(e.source, e.target)], infos[(e.source, e.target)],
                                             uncertain=e.kind == "loop"))
    option = reg.GlobalOptimizationOption(max_correspondence_distance=float(params.pair.fine.schedule[-1] * voxel),
                                          edge_prune_threshold=float(params.edge_prune_threshold),
                                          preference_loop_closure=1.0, reference_node=int(params.reference))
    g = reg.PoseGraph(graph)  # Open3D optimises in place: work on a copy
    with o3d.utility.VerbosityContextManager(o3d.utility.VerbosityLevel.Error):
        reg.global_optimization(g, reg.GlobalOptimizationLevenbergMarquardt(),
                                reg.GlobalOptimizationConvergenceCriteria(), option)
    kept_pairs = {(e.source_node_id, e.target_node_id) for e in g.edges}
    P = [np.asarray(nd.pose) for nd in g.nodes]
    ref_inv = invert(P[params.reference])
    return [ref_inv @ p for p in P], kept_pairs


def _edge_residuals(e: EdgeRecord, Tij: np.ndarray, P: list[np.ndarray], c: np.ndarray, kept_pairs: set) -> EdgeRecord:
    """The edge with its disagreement with the optimised poses: the rotation (degrees) and the
    displacement of the source scan's centroid ``c`` (local frame) of ``inv(Tij) inv(P_j) P_i``,
    and whether the optimisation kept it."""
    # edge predicts x_j = Tij x_i; poses give x_j = inv(P_j) P_i x_i
    D = invert(Tij) @ invert(P[e.target]) @ P[e.source]
    moved = D[:3, :3] @ c + D[:3, 3] - c
    return replace(e, rotation_residual_deg=rotation_angle_deg(D[:3, :3]),
                   translation_residual=float(np.linalg.norm(moved)), kept=(e.source, e.target) in kept_pairs)
