"""Multi-view geometric consistency filter of the CPU dense path (photogrammetry/dense.py) on
surfaces seen obliquely: exact depth maps of a plane must pass, wrong ones must not."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.photogrammetry.dense import DenseParams, _View, geometric_filter
from workstation.photogrammetry.rigs import look_at

W, H, F = 320, 240, 500.0
K = np.array([[F, 0.0, (W - 1) / 2], [0.0, F, (H - 1) / 2], [0.0, 0.0, 1.0]])


def _view(name: str, elevation_deg: float, azimuth_deg: float = 0.0, dist: float = 20.0) -> _View:
    """A camera ``dist`` from the origin looking at it, ``elevation_deg`` above the plane z = 0
    (the incidence on the plane is 90° minus the elevation)."""
    e, a = np.radians(elevation_deg), np.radians(azimuth_deg)
    c = dist * np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    pose = look_at(c, np.zeros(3), up=(0.0, 0.0, 1.0))
    return _View(name, K, np.asarray(pose.R, float), np.asarray(pose.t, float), W, H, 1.0, 100.0)


def _plane_depth(v: _View) -> np.ndarray:
    """Depth along the optical axis of every pixel's ray to the plane z = 0 (0 off the plane
    or behind the camera)."""
    u, w = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    rays = np.stack([(u - K[0, 2]) / F, (w - K[1, 2]) / F, np.ones_like(u)], -1) @ v.R  # world, z_cam = 1
    c = v.center
    with np.errstate(divide="ignore", invalid="ignore"):
        z = -c[2] / rays[..., 2]
    return np.where(np.isfinite(z) & (z > 0), z, 0.0).astype(np.float32)


@pytest.mark.parametrize("ref_el, src_el", [(20.0, 10.0), (10.0, 20.0), (45.0, 30.0)])
def test_geometric_filter_keeps_exact_depths_of_an_oblique_plane(ref_el, src_el):
    """The plane seen at 70° and 80° incidence (one view's pixels cover twice as much of it as
    the other's) and at 45°/60°: every exact depth whose point the source sees is confirmed."""
    ref, src = _view("ref", ref_el), _view("src", src_el, azimuth_deg=3.0)
    dr, ds = _plane_depth(ref), _plane_depth(src)
    out = geometric_filter(dr, ref, [ds], [src], DenseParams(device="cpu"))
    # reference pixels whose point lands well inside the source image, on a depth
    P = np.argwhere(dr > 0)
    z = dr[P[:, 0], P[:, 1]]
    X = np.stack([(P[:, 1] - K[0, 2]) / F * z, (P[:, 0] - K[1, 2]) / F * z, z], 1)
    Xs = (X - ref.t) @ ref.R @ src.R.T + src.t
    us, vs = Xs[:, 0] / Xs[:, 2] * F + K[0, 2], Xs[:, 1] / Xs[:, 2] * F + K[1, 2]
    seen = (Xs[:, 2] > 0) & (us > 2) & (us < W - 3) & (vs > 2) & (vs < H - 3)
    assert seen.sum() > 10_000
    kept = out[P[seen, 0], P[seen, 1]] > 0
    assert kept.mean() > 0.995, kept.mean()


def test_geometric_filter_rejects_inconsistent_depths_of_an_oblique_plane():
    """A source map 3 % too deep (three times ``max_rel_depth``) confirms nothing."""
    ref, src = _view("ref", 20.0), _view("src", 10.0, azimuth_deg=3.0)
    out = geometric_filter(_plane_depth(ref), ref, [_plane_depth(src) * 1.03], [src], DenseParams(device="cpu"))
    assert (out > 0).mean() < 0.01


def test_depth_normals_on_the_rims_of_holes_and_patches():
    """A tilted plane with a hole and a one-pixel-wide strip: every depth with a neighbour along
    each image axis gets the plane's normal (rim pixels included, by one-sided differences);
    a pixel with none along an axis gets no normal."""
    from workstation.photogrammetry.dense import depth_normals

    n_true = np.array([0.0, -np.sin(0.4), -np.cos(0.4)])  # facing the camera
    u, v = np.meshgrid(np.arange(W, dtype=float), np.arange(H, dtype=float))
    rays = np.stack([(u - K[0, 2]) / F, (v - K[1, 2]) / F, np.ones_like(u)], -1)
    depth = (10.0 * n_true[2] / (rays @ n_true)).astype(np.float32)  # the plane through (0, 0, 10)
    depth[100:140, 150:200] = 0  # a hole
    depth[:, [20, 22]] = 0  # column 21 is left without a neighbour along its rows
    nrm = depth_normals(depth, K)
    has = np.any(nrm != 0, -1)
    assert not has[:, 21].any() and not has[depth == 0].any()
    rim = np.zeros_like(has)
    rim[99, 150:200] = rim[140, 150:200] = rim[100:140, 149] = rim[100:140, 200] = True
    assert has[rim].all()
    ok = has.copy()
    ok[:, 21] = True
    assert ok[depth > 0].all()
    assert np.allclose(nrm[has], n_true, atol=1e-3)


@pytest.mark.parametrize("transpose", [False, True])
def test_sample_depth_on_a_map_one_pixel_high_or_wide(transpose):
    """A (1, 5) map and its (5, 1) transpose have no four pixels around any position: each
    position inside takes its nearest pixel's depth, and one that rounds outside gets 0."""
    from workstation.photogrammetry.dense import _sample_depth

    depth = np.float32([[1.0, 2.0, 3.0, 4.0, 5.0]])
    along = np.float32([0.2, 1.6, 3.4, 4.4, -0.6, 5.2, 2.0, 0.0])
    across = np.float32([0.2, -0.3, 0.4, 0.0, 0.0, 0.0, -0.6, 0.7])
    expected = np.float32([1.0, 3.0, 4.0, 5.0, 0.0, 0.0, 0.0, 0.0])
    if transpose:
        out = _sample_depth(np.ascontiguousarray(depth.T), across, along)
    else:
        out = _sample_depth(depth, along, across)
    assert out.dtype == np.float32
    np.testing.assert_array_equal(out, expected)
