"""Rectified pairwise SGBM (photogrammetry/sgbm.py) and the ``DenseParams.method`` dispatch."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.photogrammetry.dense import DenseParams, _View
from workstation.photogrammetry.sgbm import (
    SGBMParams,
    match_pair,
    merge_depths,
    rectify,
    rectify_images,
    to_rectified,
)

W, H, F = 200, 150, 220.0
K = np.array([[F, 0.0, (W - 1) / 2], [0.0, F, (H - 1) / 2], [0.0, 0.0, 1.0]])


def _rot(axis, deg):
    import cv2

    return cv2.Rodrigues(np.asarray(axis, float) * np.radians(deg))[0]


def _views(centre, rot_deg=(0.0, 4.0, 2.0)):
    """Reference at the origin (identity pose) and a source at ``centre`` (world = reference
    camera frame) turned by small angles about x, y, z."""
    ref = _View("ref", K, np.eye(3), np.zeros(3), W, H, 2.0, 12.0)
    R = _rot([1, 0, 0], rot_deg[0]) @ _rot([0, 1, 0], rot_deg[1]) @ _rot([0, 0, 1], rot_deg[2])
    src = _View("src", K, R, -R @ np.asarray(centre, float), W, H, 2.0, 12.0)
    return ref, src


def _plane_pair(ref, src, n=(0.15, -0.1, 1.0), d=5.0, seed=0):
    """A textured plane n·X = d (reference frame): the reference image is random texture, the
    source image its exact plane-induced homography warp. Returns (ref img, src img, true depth)."""
    import cv2

    rng = np.random.default_rng(seed)
    tex = cv2.GaussianBlur(rng.uniform(0, 255, (H, W)).astype(np.float32), (0, 0), 1.0)
    tex = cv2.normalize(tex, None, 0, 255, cv2.NORM_MINMAX).astype(np.uint8)
    n = np.asarray(n, float) / np.linalg.norm(n)
    Hm = src.K @ (src.R + np.outer(src.t, n) / d) @ np.linalg.inv(ref.K)  # ref pixel -> src pixel
    src_img = cv2.warpPerspective(tex, Hm, (W, H), flags=cv2.INTER_CUBIC)
    u, v = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    rays = np.stack([u, v, np.ones_like(u)], -1) @ np.linalg.inv(ref.K).T
    return tex, src_img, d / (rays @ n)


# baselines right, left, down (vertical) and diagonal: every in-plane turn of the rectification
BASELINES = [(0.6, 0.0, 0.0), (-0.6, 0.05, 0.0), (0.0, 0.6, 0.05), (0.4, -0.4, 0.1)]


@pytest.mark.parametrize("centre", BASELINES)
def test_sgbm_plane_depth_within_disparity_precision(centre):
    ref, src = _views(centre)
    ref_img, src_img, z = _plane_pair(ref, src)
    depth = match_pair(ref_img, src_img, ref, src, SGBMParams(speckle_window=0))
    # source pixels that see the reference pixel's plane point (inside the source image)
    ok = depth > 0
    assert ok.mean() > 0.6
    # depth precision of a disparity error δ: z² δ / (f b); SGBM's sub-pixel fit reaches
    # about a quarter pixel on sharp texture: median within 0.25 px, 90 % within 1 px
    b = np.linalg.norm(centre)
    per_px = z[ok] ** 2 / (F * b)
    err = np.abs(depth[ok] - z[ok])
    assert np.median(err / per_px) < 0.25
    assert np.mean(err <= per_px) > 0.9


def test_rectification_round_trip():
    import cv2

    ref, src = _views((0.3, 0.5, 0.1), rot_deg=(3.0, -5.0, 8.0))
    rect = rectify(ref, src, pad=40)
    # the source centre is on the rectified +x axis of the reference
    c = rect.R1 @ (ref.R @ (src.center - ref.center))
    assert c[0] == pytest.approx(rect.baseline) and abs(c[1]) < 1e-9 and abs(c[2]) < 1e-9
    # a 3-D point projects to the same rectified row in both images, disparity f·b/z_rect
    rng = np.random.default_rng(1)
    X = np.column_stack([rng.uniform(-1, 1, 50), rng.uniform(-1, 1, 50), rng.uniform(3, 9, 50)])
    xr = []
    for view, R in ((ref, rect.R1), (src, rect.R2)):
        p = (X @ view.R.T + view.t) @ R.T @ rect.K.T
        xr.append(p[:, :2] / p[:, 2:])
    zr = ((X @ ref.R.T + ref.t) @ rect.R1.T)[:, 2]
    assert np.max(np.abs(xr[0][:, 1] - xr[1][:, 1])) < 1e-9
    assert np.allclose(xr[0][:, 0] - xr[1][:, 0], rect.focal * rect.baseline / zr)
    # every reference pixel lands inside the grid, right of the padding
    mx, my, _ = to_rectified(rect, ref)
    assert mx.min() >= 40 - 0.5 and mx.max() <= rect.size[0] - 0.5 and my.min() >= -0.5 and my.max() <= rect.size[1] - 0.5
    # resampling a linear image into the rectified grid and back gives it again
    u, v = np.meshgrid(np.arange(W, dtype=np.float32), np.arange(H, dtype=np.float32))
    img = (0.7 * u + 0.4 * v + 10).astype(np.float32)
    left, _ = rectify_images(rect, ref, src, img, img)
    back = cv2.remap(left, mx, my, cv2.INTER_LINEAR)
    inner = (slice(3, -3), slice(3, -3))
    assert np.max(np.abs(back[inner] - img[inner])) < 0.05


def test_merge_depths_median_of_consistent():
    d = np.zeros((3, 1, 5), np.float32)
    d[:, 0, 0] = [1.0, 1.004, 2.0]  # two agree, one outlier
    d[:, 0, 1] = [3.0, 0.0, 0.0]  # one pair only
    d[:, 0, 2] = [1.0, 1.5, 0.0]  # two pairs disagree
    d[:, 0, 3] = [4.0, 4.02, 4.01]  # all agree within 1 % of the median
    out = merge_depths(d, 0.01)[0]
    assert out[0] == pytest.approx(1.002, abs=1e-6)
    assert out[1] == pytest.approx(3.0)
    assert out[2] == 0.0
    assert out[3] == pytest.approx(4.01, abs=1e-6)
    assert out[4] == 0.0


def test_dense_params_method_validation():
    assert DenseParams().method == "sgbm"
    with pytest.raises(InvalidInputError):
        DenseParams(method="patchmatch")
    with pytest.raises(InvalidInputError):
        SGBMParams(block=4)
    with pytest.raises(InvalidInputError):
        SGBMParams(mode="fast")


def test_run_dense_sgbm_tiny_rig_end_to_end(tmp_path):
    """Five 160 × 120 views of a box before a wall (true cameras): the dispatcher runs SGBM
    (the written photometric map is the one sgbm_depth gives), and the fused cloud lies on the
    true surfaces within half a pixel's footprint."""
    from workstation.photogrammetry.dense import _grey, _load_views, evaluate, read_array, run_dense, select_sources
    from workstation.photogrammetry.rigs import box_wall_rig, box_wall_scene
    from workstation.photogrammetry.sgbm import sgbm_depth
    from workstation.interop.pycolmap import import_pycolmap

    box_wall_rig(tmp_path)
    params = DenseParams(depth_range=(5.0, 20.0), device="cpu", method="sgbm", num_sources=4, num_threads=1)
    # views and sources as the run sees them (before it adds overlap points to its model copy)
    rec = import_pycolmap().Reconstruction(str(tmp_path / "sparse" / "0"))
    views, pts, _, obs = _load_views(rec, params.depth_range)
    iid = sorted(views)[2]
    srcs = [views[j] for j in select_sources(views, pts, obs, params)[iid]]
    cloud, summary = run_dense(tmp_path, params=params)
    assert summary["method"] == "sgbm" and cloud.history[-1].params["method"] == "sgbm"
    V, Fc, _ = box_wall_scene()
    ev = evaluate(cloud.xyz, V, Fc, 16.0, cloud.xyz[:10])
    assert cloud.n > 2000
    assert ev["accuracy_median"] < 0.04  # a pixel covers ~8 cm on the wall at 160 × 120
    wall = cloud.xyz[:, 1] > 11.8
    assert wall.sum() > 500 and np.median(np.abs(np.asarray(cloud.attrs["normal"])[wall, 1])) > 0.9
    d = tmp_path / "dense"
    grey = [_grey(d / "images" / v.name, (v.width, v.height), np.uint8) for v in [views[iid], *srcs]]
    expect = sgbm_depth(grey[0], views[iid], grey[1:], srcs, params.sgbm, params.max_rel_depth, params.min_texture)
    got = read_array(d / "stereo" / "depth_maps" / f"{views[iid].name}.photometric.bin")
    assert (expect > 0).mean() > 0.5 and np.array_equal(got, expect)


def test_compute_depth_maps_dispatches_to_the_sweep(tmp_path):
    """``method="sweep"`` writes the plane sweep's own depth map (not SGBM's)."""
    from workstation.photogrammetry.dense import (
        _grey,
        _load_views,
        compute_depth_maps,
        plane_sweep,
        read_array,
        select_sources,
        undistort,
    )
    from workstation.photogrammetry.rigs import box_wall_rig
    from workstation.interop.pycolmap import import_pycolmap

    box_wall_rig(tmp_path, n=3, width=96, height=72, focal_px=90.0)
    params = DenseParams(depth_range=(5.0, 20.0), device="cpu", method="sweep", num_sources=2, num_threads=1)
    d = undistort(tmp_path, tmp_path / "images")
    rec = import_pycolmap().Reconstruction(str(d / "sparse"))
    views, pts, _, obs = _load_views(rec, params.depth_range)
    iid = sorted(views)[1]
    srcs = [views[j] for j in select_sources(views, pts, obs, params)[iid]]
    stats = compute_depth_maps(d, params)
    assert stats["method"] == "sweep"
    grey = [_grey(d / "images" / v.name, (v.width, v.height)) for v in [views[iid], *srcs]]
    expect, _ = plane_sweep(grey[0], views[iid], grey[1:], srcs, params)
    got = read_array(d / "stereo" / "depth_maps" / f"{views[iid].name}.photometric.bin")
    assert (expect > 0).mean() > 0.3 and np.array_equal(got, expect)
