import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from regutil import shape_points

from workstation.core.cloud import Cloud
from workstation.core.errors import StageError
from workstation.registration.icp import ICPParams
from workstation.registration.register import RegisterParams, register
from workstation.registration.transforms import (
    apply_transform,
    make_transform,
    random_rotation,
    transform_error,
)

OFFSET = np.array([500_000.0, 5_000_000.0, 200.0])  # georeferenced-looking coordinates


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_auto_recovers_random_transforms_of_a_shape(seed):
    rng = np.random.default_rng(seed)
    pts = shape_points(6000, seed=seed)
    T = make_transform(random_rotation(rng, 180.0), rng.uniform(-2, 2, 3))
    target = Cloud(pts + OFFSET)
    # an independent sampling of the same surface, moved by the inverse transform
    src_pts = shape_points(6000, seed=seed + 100)
    Ti = np.linalg.inv(T)
    source = Cloud(apply_transform(Ti, src_pts) + OFFSET)
    # truth in world coordinates: x_t = Tr(o) T Tr(-o) ... composed with the inverse used above
    o = np.eye(4)
    o[:3, 3] = OFFSET
    T_world = o @ T @ np.linalg.inv(o)
    res = register(source, target, RegisterParams(voxel_size=0.03))
    rot, tr = transform_error(res.transform, T_world, center=source.xyz.mean(axis=0))
    assert rot < 0.5 and tr < 0.01, (rot, tr, res.meta.get("coarse_candidates"))
    assert res.converged and res.fitness > 0.5
    assert res.information.shape == (6, 6)


def test_quick_icp_without_the_information_matrix():
    """The hypothesis checks' short ICP (``QUICK_ICP``) with ``information=False`` returns no
    information matrix. The matrix is computed after the ICP loop, so the two calls' transforms
    agree by construction (the equality only guards that order); what is under test is that
    ``information`` is None, and the quick pose still near the truth."""
    from workstation.registration.icp import QUICK_ICP, refine
    from workstation.registration.preprocess import Radii, prepare

    T = make_transform(random_rotation(np.random.default_rng(5), 4.0), [0.03, -0.02, 0.01])
    src, tgt = (prepare(x, Radii(0.03), features=False).down
                for x in (apply_transform(np.linalg.inv(T), shape_points(5000, seed=5)), shape_points(5000, seed=6)))
    full, quick = (refine(src, tgt, 0.03, np.eye(4), QUICK_ICP, information=k) for k in (True, False))
    assert full.information.shape == (6, 6) and quick.information is None
    assert np.allclose(quick.transform, full.transform, rtol=0.0, atol=1e-9)
    assert transform_error(quick.transform, T)[0] < 0.5


@pytest.mark.parametrize("method", ["clique", "fpfh_ransac", "fgr"])
def test_each_coarse_method_alone(method):
    rng = np.random.default_rng(7)
    pts = shape_points(5000, seed=7)
    T = make_transform(random_rotation(rng, 120.0), [0.5, -0.3, 0.2])
    source = Cloud(apply_transform(np.linalg.inv(T), shape_points(5000, seed=8)))
    res = register(source, Cloud(pts), RegisterParams(method=method, voxel_size=0.03))
    rot, tr = transform_error(res.transform, T)
    assert rot < 0.5 and tr < 0.01
    assert res.meta["coarse_method"] == method


@pytest.mark.parametrize("fine", ["point_to_point", "point_to_plane", "generalized", "voxel_plane"])
def test_fine_methods_from_a_near_start(fine):
    rng = np.random.default_rng(11)
    pts = shape_points(8000, seed=11)
    T = make_transform(random_rotation(rng, 4.0), [0.02, -0.015, 0.01])
    source = Cloud(apply_transform(np.linalg.inv(T), shape_points(8000, seed=12)) + OFFSET)
    o = np.eye(4)
    o[:3, 3] = OFFSET
    res = register(source, Cloud(pts + OFFSET), RegisterParams(method="icp", voxel_size=0.03,
                                                               fine=ICPParams(method=fine, kernel="huber")))
    rot, tr = transform_error(res.transform, o @ T @ np.linalg.inv(o), center=source.xyz.mean(axis=0))
    assert rot < 0.3 and tr < 0.005, (fine, rot, tr)


def test_colored_icp_uses_colour():
    rng = np.random.default_rng(5)
    pts = shape_points(8000, seed=5)
    col = (np.column_stack([np.sin(pts[:, 0] * 8), np.cos(pts[:, 1] * 8), np.sin(pts[:, 2] * 8)]) * 0.5 + 0.5)
    T = make_transform(random_rotation(rng, 3.0), [0.01, 0.02, -0.01])
    src_pts = apply_transform(np.linalg.inv(T), pts)
    rgb = np.round(col * 65535).astype(np.uint16)
    res = register(Cloud(src_pts, {"rgb": rgb}), Cloud(pts, {"rgb": rgb}),
                   RegisterParams(method="icp", voxel_size=0.03, fine=ICPParams(method="colored")))
    rot, tr = transform_error(res.transform, T)
    assert rot < 0.2 and tr < 0.003


def test_similarity_icp_recovers_scale():
    rng = np.random.default_rng(2)
    pts = shape_points(8000, seed=2)
    s = 0.37  # an SfM cloud in arbitrary units
    T = make_transform(random_rotation(rng, 2.0), [0.01, 0.0, -0.02], 1.0 / s)
    src = apply_transform(np.linalg.inv(T), shape_points(8000, seed=3))
    init = make_transform(np.eye(3), [0, 0, 0], 1.0 / s * 1.03)  # 3 % scale error to start
    res = register(Cloud(src), Cloud(pts), RegisterParams(method="similarity", voxel_size=0.03), init=init)
    assert res.scale == pytest.approx(1.0 / s, rel=0.003)
    rot, tr = transform_error(res.transform, T)
    assert rot < 0.3 and tr < 0.01


@pytest.mark.slow
def test_similarity_from_the_identity_finds_scale_rotation_and_shift():
    """7 DoF without a start (5 s CPU): an 'SfM' cloud at 0.37 of the true size (a scale the
    voxel-size guess misses by more than 10 %), turned by up to 180 degrees, covering 3/4 of the
    object, sampled independently, with 2 mm noise."""
    rng = np.random.default_rng(5)
    pts = shape_points(8000, seed=2)
    s = 0.37
    T = make_transform(random_rotation(rng, 180.0), [0.4, -0.2, 0.1], 1.0 / s)
    src = apply_transform(np.linalg.inv(T), shape_points(6000, seed=7)[:4500] + rng.normal(0, 0.002, (4500, 3)))
    res = register(Cloud(src), Cloud(pts), RegisterParams(method="similarity"))
    assert res.meta["coarse_method"] == "scale_search"
    assert abs(res.meta["scale0"] * s - 1) > 0.1  # the central guess alone would not do
    assert res.scale == pytest.approx(1.0 / s, rel=0.003)
    rot, tr = transform_error(res.transform, T, center=pts.mean(axis=0))
    assert rot < 0.3 and tr < 0.005
    # the returned transform really carries the scale: a known source point lands on its target
    p = apply_transform(np.linalg.inv(T), pts[:5])
    assert np.allclose(apply_transform(res.transform, p), pts[:5], atol=0.01)


def test_no_overlap_raises_stage_error_with_hint():
    pts = shape_points(4000, seed=1)
    far = Cloud(pts[pts[:, 0] > 0.3] + [0, 0, 0])
    near = Cloud(pts[pts[:, 0] < -0.3])
    with pytest.raises(StageError) as e:
        register(far, near, RegisterParams(method="icp", voxel_size=0.03, min_fitness=0.3))
    assert e.value.hint and "overlap" in e.value.hint


def test_inputs_are_not_modified():
    pts = shape_points(3000, seed=4)
    a = Cloud(pts)
    b = Cloud(pts + [0.01, 0, 0])
    before = a.xyz.copy()
    register(a, b, RegisterParams(method="icp", voxel_size=0.03))
    assert np.array_equal(a.xyz, before)


def test_wrong_alignment_on_a_surface_is_refused():
    """Smooth terrain turned by 180 degrees still overlaps itself, but not on its planes."""
    sys.path.insert(0, str(Path(__file__).parent))
    from regutil import wavy_scene

    pts = wavy_scene(20000, seed=1)
    pts = pts[(pts[:, 0] < 15) & (pts[:, 1] < 15)]
    R = np.array([[-1.0, 0, 0], [0, -1.0, 0], [0, 0, 1.0]])
    c = pts.mean(axis=0)
    wrong = make_transform(R, c - R @ c)  # a 180-degree turn about the centre: a wrong start
    with pytest.raises(StageError, match="surface|overlap"):
        register(Cloud(pts), Cloud(wavy_scene(20000, seed=2)), RegisterParams(method="icp", voxel_size=0.3), init=wrong)


def test_two_raycast_tls_stations_from_a_rough_pose():
    """Two ray-cast stations of a box block (partial overlap, 3 mm range noise), the second in
    its own frame, refined from a field-sketch pose (3 degrees, 1 m off)."""
    sys.path.insert(0, str(Path(__file__).parent))
    from regutil import block_mesh, tls_station

    mesh = block_mesh()
    a = tls_station(mesh, (26, 22, 1.6), step_deg=0.8, seed=1)
    b = tls_station(mesh, (38, 24, 1.6), step_deg=0.8, seed=2)
    ang = np.radians(130.0)
    R = np.array([[np.cos(ang), -np.sin(ang), 0], [np.sin(ang), np.cos(ang), 0], [0, 0, 1]])
    G = make_transform(R, [4.0, -7.0, 0.3])  # block frame -> station B frame
    src = Cloud(apply_transform(G, b))
    truth = np.linalg.inv(G)
    rough = truth @ make_transform(random_rotation(np.random.default_rng(0), 3.0), [0.7, -0.7, 0.1])
    res = register(src, Cloud(a), RegisterParams(method="icp", voxel_size=0.5), init=rough)
    rot, tr = transform_error(res.transform, truth, center=src.xyz.mean(axis=0))
    assert rot < 0.2 and tr < 0.02, (rot, tr)
    assert res.meta["plane_inlier_share"] > 0.9
