import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from regutil import wavy_scene  # noqa: E402

from workstation.core.cloud import Cloud
from workstation.registration.merge import merge_clouds
from workstation.registration.posegraph import MultiwayParams, register_multiway
from workstation.registration.register import RegisterParams
from workstation.registration.transforms import apply_transform, invert, make_transform, transform_error


def _rz(deg):
    a = np.radians(deg)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def _scans():
    """Four overlapping windows of one scene, each in its own frame (rotated about z, shifted)."""
    windows = [(0, 0), (5, 0), (5, 5), (0, 5)]  # 15 m windows around a 20 m scene: a closed loop
    angles = [0.0, 70.0, 160.0, -110.0]
    shifts = [(0, 0, 0), (5.0, -3.0, 0.2), (-4.0, 6.0, -0.1), (2.0, 2.0, 0.3)]
    scans, G = [], []
    for k, ((x0, y0), ang, sh) in enumerate(zip(windows, angles, shifts)):
        pts = wavy_scene(25000, seed=10 + k)
        keep = (pts[:, 0] >= x0) & (pts[:, 0] <= x0 + 15) & (pts[:, 1] >= y0) & (pts[:, 1] <= y0 + 15)
        g = make_transform(_rz(ang), sh)
        scans.append(Cloud(apply_transform(g, pts[keep]), {"intensity": np.full(keep.sum(), 100 * (k + 1))}))
        G.append(g)
    return scans, G


@pytest.mark.slow
def test_pose_graph_of_four_scans_closes():
    scans, G = _scans()
    # rough station poses (a field sketch: 2 degrees and 0.3 m off), refined pairwise by ICP
    rng = np.random.default_rng(0)
    rough = [invert(g) @ make_transform(_rz(rng.uniform(-2, 2)), np.append(rng.uniform(-0.3, 0.3, 2), 0.0)) for g in G]
    res = register_multiway(scans, MultiwayParams(pair=RegisterParams(voxel_size=0.3), initial_poses=tuple(rough)))
    assert len(res.poses) == 4
    kinds = {(e.source, e.target): e.kind for e in res.edges}
    assert kinds[(0, 1)] == "odometry" and kinds[(2, 3)] == "odometry"
    assert any(k == "loop" for k in kinds.values())  # 0-3 (and the diagonals) close the loop
    for k in range(4):
        truth = G[0] @ invert(G[k])  # scan k -> scan 0 frame
        rot, tr = transform_error(res.poses[k], truth, center=scans[k].xyz.mean(axis=0))
        assert rot < 0.2 and tr < 0.02, (k, rot, tr)
    table = res.residual_table()
    assert all(np.isfinite(r["translation_residual"]) for r in table)
    assert max(r["translation_residual"] for r in table if r["kept"]) < 0.05
    # the poses put every scan back onto the scene: merged, scan 2 lies on scan 0's surface
    merged = merge_clouds(scans, res.poses)
    assert merged.n == sum(s.n for s in scans)
    assert set(np.unique(merged.attrs["point_source_id"])) == {1, 2, 3, 4}


def test_edge_information_is_moved_to_the_pose_graph_source_frame():
    """Open3D's information matrix of a pair (target points, registration frame) re-expressed for
    the pose graph (source points, graph frame) equals the one computed there directly."""
    import open3d as o3d

    from workstation.interop.open3d import points_to_legacy
    from workstation.registration.posegraph import _graph_information

    info_of = o3d.pipelines.registration.get_information_matrix_from_point_clouds
    pts = wavy_scene(8000, seed=3)
    L = make_transform(_rz(130.0), (4.0, -7.0, 1.5))  # source -> target, graph frame
    pair_origin, graph_origin = np.array([12.0, -3.0, 2.0]), np.array([-5.0, 8.0, 0.0])
    src_graph = pts - graph_origin  # the source scan in the graph's local frame
    tgt_graph = apply_transform(L, src_graph)
    shift = make_transform(np.eye(3), graph_origin - pair_origin)
    T_pair = shift @ L @ invert(shift)  # the same motion in the registration's frame
    info_pair = np.asarray(info_of(points_to_legacy(src_graph + graph_origin - pair_origin),
                                   points_to_legacy(tgt_graph + graph_origin - pair_origin), 0.05, T_pair))
    moved = _graph_information(info_pair, pair_origin - graph_origin, L)
    direct = np.asarray(info_of(points_to_legacy(tgt_graph), points_to_legacy(src_graph), 0.05, invert(L)))
    assert np.abs(moved - direct).max() < 1e-6 * np.abs(direct).max()
    assert np.abs(info_pair - direct).max() > 0.1 * np.abs(direct).max()  # the frames do differ


def test_a_similarity_pair_method_is_refused_before_any_work():
    """The pose graph holds rigid poses: a 7-DoF pair method is refused, naming the field."""
    from workstation.core.errors import InvalidInputError

    clouds = [Cloud(np.random.default_rng(k).random((50, 3))) for k in range(2)]
    with pytest.raises(InvalidInputError, match="rigid") as err:
        register_multiway(clouds, MultiwayParams(pair=RegisterParams(method="similarity")))
    assert err.value.field == "pair.method"
