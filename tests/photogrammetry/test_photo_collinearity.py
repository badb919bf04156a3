"""Collinearity tools: projection against OpenCV, rotations, resection, intersection, formulas."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Pose
from workstation.photogrammetry import collinearity as co


@pytest.fixture
def cam():
    return Camera(3000, 2000, 2500.0, 2490.0, 1510.3, 985.7, dist=(-0.12, 0.05, 0.001, -0.0005, 0.01))


def test_projection_matches_opencv(cam, rng):
    import cv2

    X = rng.uniform([-10, -8, 20], [10, 8, 40], (50, 3))
    rvec = np.array([0.1, -0.2, 0.05])
    R = co.rotvec_to_matrix(rvec)
    t = np.array([0.3, -0.2, 1.0])
    ours = co.project(X, cam, Pose(R, t))
    ref, _ = cv2.projectPoints(X, rvec, t, cam.K, np.array(cam.dist))
    np.testing.assert_allclose(ours, ref.reshape(-1, 2), atol=1e-7)


def test_undistort_inverts_distort(cam, rng):
    xy = rng.uniform(-0.5, 0.5, (200, 2))
    back = co.undistort_normalized(co.distort_normalized(xy, cam.dist), cam.dist)
    np.testing.assert_allclose(back, xy, atol=1e-9)


@settings(max_examples=50, deadline=None)
@given(
    st.floats(-1.5, 1.5), st.floats(-1.5, 1.5), st.floats(-3.1, 3.1),
)
def test_opk_roundtrip(om, ph, ka):
    M = co.opk_to_matrix(om, ph, ka)
    assert np.allclose(M @ M.T, np.eye(3)) and np.isclose(np.linalg.det(M), 1.0)
    np.testing.assert_allclose(co.matrix_to_opk(M), (om, ph, ka), atol=1e-9)


def test_opk_sequence_is_kappa_phi_omega():
    # M = M_kappa M_phi M_omega with passive rotations about x, y, z (Wolf et al. C-33)
    om, ph, ka = 0.2, -0.4, 0.9
    Mo = np.array([[1, 0, 0], [0, np.cos(om), np.sin(om)], [0, -np.sin(om), np.cos(om)]])
    Mp = np.array([[np.cos(ph), 0, -np.sin(ph)], [0, 1, 0], [np.sin(ph), 0, np.cos(ph)]])
    Mk = np.array([[np.cos(ka), np.sin(ka), 0], [-np.sin(ka), np.cos(ka), 0], [0, 0, 1]])
    np.testing.assert_allclose(co.opk_to_matrix(om, ph, ka), Mk @ Mp @ Mo, atol=1e-12)


def test_nadir_photo_axes():
    cam = Camera(1000, 1000, 1000.0, 1000.0, 499.5, 499.5)
    pose = co.pose_from_opk(0, 0, 0, [0, 0, 100])
    uv = co.project(np.array([[10.0, 0, 0], [0, 10.0, 0]]), cam, pose)
    assert uv[0, 0] > 499.5 and np.isclose(uv[0, 1], 499.5)  # East -> right
    assert uv[1, 1] < 499.5 and np.isclose(uv[1, 0], 499.5)  # North -> up in the image


def test_resection_recovers_pose_and_covariance_is_honest(cam, rng):
    true = co.pose_from_opk(0.05, -0.08, 2.0, [12.0, -4.0, 80.0])
    X = np.column_stack([rng.uniform(-30, 50, 12), rng.uniform(-40, 30, 12), rng.uniform(0, 15, 12)])
    uv0 = co.project(X, cam, true)
    errs, stds = [], []
    for k in range(30):
        res = co.resect(X, uv0 + rng.normal(0, 0.5, uv0.shape), cam)
        errs.append(res.centre - true.center)
        stds.append(res.std_centre)
        assert res.converged and res.residuals.shape == (12, 2)
    errs, stds = np.array(errs), np.array(stds)
    # the spread of the estimates matches the predicted standard deviation within a factor 2
    ratio = errs.std(axis=0) / stds.mean(axis=0)
    assert np.all((ratio > 0.5) & (ratio < 2.0)), ratio
    assert 0.3 < np.mean([r for r in [co.resect(X, uv0 + rng.normal(0, 0.5, uv0.shape), cam).sigma0_px]]) < 0.8


def test_resection_three_points_and_initial_guess(cam):
    true = co.pose_from_opk(0.02, 0.01, 0.3, [0.0, 0.0, 50.0])
    X = np.array([[-10.0, -5, 0], [12, -3, 1], [2, 11, 2]])
    guess = co.pose_from_opk(0, 0, 0.25, [1.0, -1.0, 48.0])
    res = co.resect(X, co.project(X, cam, true), cam, initial=guess)
    np.testing.assert_allclose(res.centre, true.center, atol=1e-6)
    assert np.isnan(res.sigma0_px)  # no redundancy
    assert np.all(np.isfinite(res.std_centre))


def test_resection_needs_three_points(cam):
    with pytest.raises(InvalidInputError, match="at least 3"):
        co.resect(np.zeros((2, 3)), np.zeros((2, 2)), cam)


def test_intersection_precision(cam, rng):
    poses = [co.pose_from_opk(0, 0, 0, [x, 0, 100.0]) for x in (0, 40, 80)]
    X = np.array([[40.0, 10, 5]])
    uv0 = np.vstack([co.project(X, cam, p) for p in poses])
    pts = np.array([co.intersect(uv0 + rng.normal(0, 0.3, uv0.shape), [cam] * 3, poses).point for _ in range(60)])
    pred = co.intersect(uv0, [cam] * 3, poses, sigma_px=0.3, a_posteriori=False).std
    ratio = pts.std(axis=0) / pred
    assert np.all((ratio > 0.6) & (ratio < 1.6)), ratio
    # depth is the weakest coordinate for a B/H of 0.8
    assert pred[2] > pred[0]


def test_intersection_needs_two_rays(cam):
    with pytest.raises(InvalidInputError, match="2 rays"):
        co.intersect(np.zeros((1, 2)), [cam], [Pose(np.eye(3), np.zeros(3))])


def test_stereo_formulas_agree_with_intersection():
    cam = Camera(4000, 3000, 4000.0, 4000.0, 1999.5, 1499.5)
    H, B = 100.0, 60.0
    sp = co.stereo_precision(H, B, cam.fx, sigma_px=0.5)
    p1, p2 = co.pose_from_opk(0, 0, 0, [0, 0, H]), co.pose_from_opk(0, 0, 0, [B, 0, H])
    X = np.array([[B / 2, 0.0, 0.0]])
    uv = np.vstack([co.project(X, cam, p1), co.project(X, cam, p2)])
    # depth comes from the x-parallax p = x1 - x2, measured with sigma_p = sqrt(2) sigma_px
    res = co.intersect(uv, [cam, cam], [p1, p2], sigma_px=0.5, a_posteriori=False)
    assert res.std[2] == pytest.approx(sp.sigma_z * np.sqrt(2), rel=0.02)
    # parallax height: p = B f / (H - h)
    p = (uv[0, 0] - uv[1, 0])
    assert co.height_from_parallax(p, B, cam.fx, H) == pytest.approx(0.0, abs=1e-9)
    assert co.gsd(H, cam.fx) == pytest.approx(sp.gsd)


def test_relief_displacement_matches_projection():
    cam = Camera(4000, 4000, 3000.0, 3000.0, 1999.5, 1999.5)
    H = 500.0
    pose = co.pose_from_opk(0, 0, 0, [0, 0, H])
    top, foot = co.project(np.array([[100.0, 50, 30], [100.0, 50, 0]]), cam, pose)
    r_top = np.hypot(*(top - [cam.cx, cam.cy]))
    d = np.hypot(*(top - foot))
    assert co.relief_displacement(r_top, 30.0, H) == pytest.approx(d, rel=1e-9)
    assert co.height_from_relief_displacement(d, r_top, H) == pytest.approx(30.0, rel=1e-9)
