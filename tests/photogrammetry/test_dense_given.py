"""Dense stereo with given (true) cameras and no sparse points: source views and depth maps
must not depend on a tight depth range."""

from __future__ import annotations

import numpy as np

from workstation.photogrammetry.dense import DenseParams, _pair_point, _View, select_sources
from workstation.photogrammetry.rigs import box_wall_rig, box_wall_scene, look_at


def _view(center, target, near=5.0, far=120.0, name="v"):
    pose = look_at(np.asarray(center, float), np.asarray(target, float))
    K = np.array([[500.0, 0, 319.5], [0, 500.0, 239.5], [0, 0, 1]])
    return _View(name, K, np.asarray(pose.R, float), np.asarray(pose.t, float), 640, 480, near, far)


def test_pair_point_is_where_converging_axes_meet():
    target = np.array([3.0, -2.0, 12.0])
    a = _view([50.0, 0.0, 8.0], target)
    b = _view([43.3, 25.0, 8.0], target)  # 30° round the ring, same aim point
    assert np.allclose(_pair_point(a, b), target, atol=1e-6)
    assert np.allclose(_pair_point(b, a), target, atol=1e-6)


def test_pair_point_falls_back_to_mid_depth_for_parallel_or_diverging_axes():
    a = _view([0.0, 0.0, 100.0], [0.0, 0.0, 0.0])
    b = _view([20.0, 0.0, 100.0], [20.0, 0.0, 0.0])  # nadir strip: parallel axes
    mid = 2.0 / (1.0 / 5.0 + 1.0 / 120.0)
    assert np.allclose(_pair_point(a, b), a.center + a.R[2] * mid)
    c = _view([0.0, 0.0, 0.0], [-10.0, 50.0, 0.0])
    d = _view([5.0, 0.0, 0.0], [15.0, 50.0, 0.0])  # looking apart: the axes meet behind
    assert np.allclose(_pair_point(c, d), c.center + c.R[2] * mid)


def test_select_sources_true_cameras_loose_depth_range(tmp_path):
    import pycolmap

    from workstation.photogrammetry.dense import _load_views

    box_wall_rig(tmp_path, n=5)
    rec = pycolmap.Reconstruction(str(tmp_path / "sparse" / "0"))
    params = DenseParams(device="cpu", depth_range=(1.0, 100.0), num_sources=2)
    views, pts, _, obs = _load_views(rec, params.depth_range)
    assert len(pts) == 0
    sources = select_sources(views, pts, obs, params)
    assert all(len(s) == 2 for s in sources.values())
    assert all(i not in s for i, s in sources.items())


def test_dense_true_cameras_loose_depth_range_near_surface(tmp_path):
    from workstation.photogrammetry.dense import evaluate, run_dense

    box_wall_rig(tmp_path, n=5)
    V, F, _ = box_wall_scene()
    cloud, _ = run_dense(tmp_path, params=DenseParams(depth_range=(1.0, 100.0), device="cpu", num_sources=4))
    # every view has sources, so most of the 5 x 160 x 120 pixels see the surface (a range
    # midpoint 2 m from the cameras left the outer views without sources and ~500 points)
    assert cloud.n > 3000
    ev = evaluate(cloud.xyz, V, F, 16.0, cloud.xyz[:10])
    # one pixel covers ~8 cm on the wall at 160 x 120 px: half a pixel at the median
    assert ev["accuracy_median"] < 0.04 and ev["accuracy_p90"] < 0.12
    box = (cloud.xyz[:, 1] > 7.9) & (cloud.xyz[:, 1] < 10.1) & (np.abs(cloud.xyz[:, 0]) < 1.1)
    wall = cloud.xyz[:, 1] > 11.8
    assert box.sum() > 400 and wall.sum() > 2000


def test_dense_without_any_source_view_names_the_cause(tmp_path):
    import pytest

    from workstation.core.errors import StageError
    from workstation.photogrammetry.dense import compute_depth_maps, undistort

    box_wall_rig(tmp_path, n=3, width=64, height=48, focal_px=60.0)
    d = undistort(tmp_path, tmp_path / "images")
    # the views are at most ~28° apart: an angle window of 40-45° leaves every view without sources
    with pytest.raises(StageError, match="no image has a source view"):
        compute_depth_maps(d, DenseParams(device="cpu", depth_range=(5.0, 20.0), min_angle_deg=40.0, max_angle_deg=45.0))
    assert not list((d / "stereo" / "depth_maps").glob("*.bin"))
