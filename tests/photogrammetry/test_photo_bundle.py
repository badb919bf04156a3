"""Bundle adjustment with GCP constraints: a deformed SfM model, independence of check points."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.core.products import Reconstruction, Tracks
from workstation.io.gcp import GCP
from workstation.photogrammetry.bundle import BundleParams, bundle_adjust
from workstation.photogrammetry.georef import georeference, transform_reconstruction
from workstation.photogrammetry.synthetic import gcp_scene

NOISE = 0.5  # px


def _scene(seed=7, **kw):
    kw = {"n_control": 6, "n_check": 20, "n_tie": 150, **kw}
    return gcp_scene(np.random.default_rng(seed), noise_px=NOISE, **kw)


def test_bundle_removes_a_bent_and_scale_drifting_model():
    """A dome of 0.3 m (9 GSD) and a 0.5 % scale drift: the similarity leaves them in the check
    points; the adjustment brings the check RMSE down to what the image noise explains."""
    rec, gcps, expected = _scene(bend=0.3, scale_drift=0.005)
    res = georeference(gcps, rec, sigma_px=NOISE)
    m = res.report.metrics
    assert res.meta["adjustment"] == "bundle"
    # the similarity alone is far off in Z (the dome) ...
    assert m["similarity_check_rmse_z"] > 3 * expected["rmse_z"]
    # ... the adjustment is consistent with the image noise
    assert 0.5 * expected["rmse_h"] < m["check_rmse_h"] < 2.0 * expected["rmse_h"]
    assert 0.5 * expected["rmse_z"] < m["check_rmse_z"] < 2.0 * expected["rmse_z"]
    assert m["check_rmse_3d"] < 0.4 * m["similarity_check_rmse_3d"]
    st = res.meta["bundle"]
    assert st["rms_px_before"] > 5 * NOISE and st["rms_px_after"] == pytest.approx(NOISE, rel=0.25)
    assert st["control_points"] == 6 and st["free_images"] == 9
    doc = res.to_dict()
    assert doc["adjustment"] == "bundle" and doc["bundle"]["tie_points"] == 150
    # the adjusted model sits in the survey frame: tie points on the ground, cameras 120 m above
    z_cam = np.array([im.pose.center[2] for im in res.reconstruction.images.values()])
    assert np.all(np.abs(z_cam - 320) < 2)


def test_bundle_matches_the_similarity_on_an_undeformed_model():
    rec, gcps, expected = _scene(seed=3)
    res = georeference(gcps, rec, sigma_px=NOISE)
    m = res.report.metrics
    assert res.meta["adjustment"] == "bundle"
    assert m["check_rmse_3d"] <= 1.1 * m["similarity_check_rmse_3d"]
    assert m["check_rmse_z"] < 2.0 * expected["rmse_z"]


def test_robust_loss_survives_gross_tie_errors():
    """3 % of the tie observations 40 px off in random directions (mismatches)."""
    rec, gcps, expected = _scene(seed=5, bend=0.2)
    rng = np.random.default_rng(0)
    uv = rec.tracks.uv.copy()
    bad = rng.choice(uv.shape[0], uv.shape[0] // 30, replace=False)
    uv[bad] += rng.normal(0, 40.0, (bad.shape[0], 2))
    noisy = Reconstruction(rec.cameras, rec.images, rec.points, None, None, rec.meta, Tracks(rec.tracks.point, rec.tracks.image, uv))
    clean = georeference(gcps, rec, sigma_px=NOISE).report.metrics
    res = georeference(gcps, noisy, sigma_px=NOISE)
    m = res.report.metrics
    assert m["check_rmse_3d"] < 1.1 * clean["check_rmse_3d"]
    assert m["check_rmse_z"] < 2.0 * expected["rmse_z"]
    # the large ones are found and dropped, with some good observations of the same short
    # tracks (a 2- or 3-ray point pulled by its bad ray leaves its good rays off too)
    big = np.linalg.norm(uv[bad] - rec.tracks.uv[bad], axis=1) > 10 * NOISE
    assert big.sum() - 2 <= res.meta["bundle"]["rejected_observations"] <= 2 * bad.shape[0]
    plain = georeference(gcps, noisy, sigma_px=NOISE, bundle=BundleParams(loss="linear", reject_sigma=None)).report.metrics
    assert plain["check_rmse_3d"] > 1.5 * m["check_rmse_3d"]


def test_check_points_never_enter_the_bundle():
    rec, gcps, _ = _scene(seed=8, n_check=5, bend=0.2)
    a = georeference(gcps, rec, sigma_px=NOISE)
    # move the check points 50 m and scramble their image observations: the fit must not move
    moved = [
        g if g.role == "control"
        else GCP(g.name, g.xyz + 50.0, g.role, g.sigma, tuple((i, u + 30.0, v - 20.0) for i, u, v in g.observations))
        for g in gcps
    ]
    b = georeference(moved, rec, sigma_px=NOISE)
    assert a.meta["adjustment"] == b.meta["adjustment"] == "bundle"
    for k, im in a.reconstruction.images.items():
        np.testing.assert_allclose(b.reconstruction.images[k].pose.t, im.pose.t, atol=1e-9)
    assert b.report.metrics["check_rmse_3d"] > 40 > a.report.metrics["check_rmse_3d"]
    with pytest.raises(InvalidInputError, match="check points must stay independent"):
        bundle_adjust(transform_reconstruction(rec, a.similarity), gcps)


def test_similarity_only_when_no_tracks_or_asked():
    rec, gcps, _ = gcp_scene(np.random.default_rng(9), noise_px=NOISE, n_control=4, n_check=3)
    res = georeference(gcps, rec)
    assert res.meta["adjustment"] == "similarity"
    assert any("no tie-point observations" in n for n in res.report.notes)
    with pytest.raises(InvalidInputError, match="cannot run"):
        georeference(gcps, rec, adjustment="bundle")
    rec2, gcps2, _ = _scene(seed=9, n_check=3)
    res2 = georeference(gcps2, rec2, adjustment="similarity")
    assert res2.meta["adjustment"] == "similarity" and "similarity_check_rmse_3d" not in res2.report.metrics


def test_gcp_sigma_weights_the_ground_coordinates():
    """A control point surveyed 0.3 m off: with a loose σ the adjustment follows the images,
    with a tight σ it is pulled to the wrong survey coordinate."""
    rec, gcps, _ = _scene(seed=4, n_check=6)

    def shifted(sigma):  # the first control point 0.3 m off in Z with σ; the others at 1 cm
        return [
            GCP(g.name, g.xyz + [0, 0, 0.3], g.role, sigma, g.observations) if i == 0 else GCP(g.name, g.xyz, g.role, 0.01, g.observations)
            for i, g in enumerate(gcps)
        ]

    loose = georeference(shifted(1.0), rec, sigma_px=NOISE, bundle=BundleParams(loss="linear"))
    tight = georeference(shifted(0.001), rec, sigma_px=NOISE, bundle=BundleParams(loss="linear"))
    name = gcps[0].name
    dz = [{r["name"]: r["dZ"] for r in res.report.tables["points"]}[name] for res in (loose, tight)]
    # loose: the images put the point at its true height, 0.3 m below the bad survey value;
    # tight: the adjustment bends towards the bad value
    assert dz[0] == pytest.approx(-0.3, abs=0.05) and abs(dz[1]) < abs(dz[0]) - 0.1
    assert loose.meta["bundle"]["control_sigma"][name] == 1.0


def test_analytic_jacobians_match_finite_differences():
    from scipy.spatial.transform import Rotation

    from workstation.photogrammetry.bundle import (
        _left_jacobian_so3,
        project_many,
        projection_jacobians,
    )

    rng = np.random.default_rng(2)
    m = 5
    X = rng.uniform(-5, 5, (m, 3))
    R = Rotation.from_rotvec(rng.normal(0, 0.3, (m, 3))).as_matrix()
    C = X + rng.uniform(15, 25, (m, 1)) * (R[:, 2, :] * -1)  # points in front of the cameras
    K = np.tile([3000.0, 2990.0, 2000.0, 1500.0, 1.5, -0.08, 0.02, 0.001, -0.002, 0.005], (m, 1))
    d_rot, d_c, d_x, d_k = projection_jacobians(X, R, C, K)
    h = 1e-6
    for j in range(3):
        e = np.zeros(3)
        e[j] = h
        num = (project_many(X + e, R, C, K)[0] - project_many(X - e, R, C, K)[0]) / (2 * h)
        np.testing.assert_allclose(d_x[:, :, j], num, rtol=1e-5, atol=1e-4)
        num = (project_many(X, R, C + e, K)[0] - project_many(X, R, C - e, K)[0]) / (2 * h)
        np.testing.assert_allclose(d_c[:, :, j], num, rtol=1e-5, atol=1e-4)
        Rp, Rm = Rotation.from_rotvec(e).as_matrix() @ R, Rotation.from_rotvec(-e).as_matrix() @ R
        num = (project_many(X, Rp, C, K)[0] - project_many(X, Rm, C, K)[0]) / (2 * h)
        np.testing.assert_allclose(d_rot[:, :, j], num, rtol=1e-5, atol=1e-3)
    for j, col in enumerate([0, 1, 2, 3, 5, 6]):
        dk = np.zeros(10)
        dk[col] = h
        num = (project_many(X, R, C, K + dk)[0] - project_many(X, R, C, K - dk)[0]) / (2 * h)
        np.testing.assert_allclose(d_k[:, :, j], num, rtol=1e-5, atol=1e-4)
    # the left Jacobian of SO(3): Exp(phi + eps) = Exp(J eps) Exp(phi)
    phi = rng.normal(0, 0.7, (4, 3))
    eps = rng.normal(0, 1e-7, (4, 3))
    lhs = Rotation.from_rotvec(phi + eps) * Rotation.from_rotvec(phi).inv()
    np.testing.assert_allclose(lhs.as_rotvec(), np.einsum("mij,mj->mi", _left_jacobian_so3(phi), eps), atol=1e-13)


def test_finite_difference_jacobian_gives_the_same_solution():
    rec, gcps, _ = _scene(seed=6, n_tie=60, n_check=4, bend=0.2)
    a = georeference(gcps, rec, sigma_px=NOISE)
    b = georeference(gcps, rec, sigma_px=NOISE, bundle=BundleParams(jacobian="2-point"))
    for k, im in a.reconstruction.images.items():
        np.testing.assert_allclose(b.reconstruction.images[k].pose.center, im.pose.center, atol=2e-4)
    np.testing.assert_allclose(b.reconstruction.points, a.reconstruction.points, atol=2e-3)


def test_refined_intrinsics_remove_a_dome_from_wrong_radial_distortion():
    """The SfM camera carries k1 = 0.03 where the lens has none (the classic cause of doming):
    check points come out ~0.3 m off in Z; with the adjustment refining the intrinsics the
    distortion goes and the check RMSE returns to the noise level."""
    from workstation.core.products import Camera

    rec, gcps, expected = gcp_scene(np.random.default_rng(2), noise_px=NOISE, n_control=8, n_check=20, n_tie=400)
    c = rec.cameras[1]
    wrong = Camera(c.width, c.height, c.fx, c.fy, c.cx, c.cy, 0.0, (0.03, 0.0, 0.0, 0.0, 0.0), "OPENCV")
    rec = Reconstruction({1: wrong}, rec.images, rec.points, None, None, rec.meta, rec.tracks)
    fixed = georeference(gcps, rec, sigma_px=NOISE).report.metrics
    res = georeference(gcps, rec, sigma_px=NOISE, bundle=BundleParams(refine_intrinsics=True))
    m, cam = res.report.metrics, res.reconstruction.cameras[1]
    assert fixed["check_rmse_z"] > 5 * expected["rmse_z"]
    assert m["check_rmse_z"] < 1.5 * expected["rmse_z"] and m["check_rmse_h"] < 1.5 * expected["rmse_h"]
    assert abs(cam.dist[0]) < 0.005 and abs(cam.fx / c.fx - 1) < 0.005
    assert res.meta["bundle"]["refine_intrinsics"]
