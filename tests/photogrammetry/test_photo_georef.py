"""Georeferencing: similarity, hold-out check points, accuracy figures, GCP file, bad input."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.io.gcp import GCP, read_gcp
from workstation.photogrammetry.collinearity import opk_to_matrix
from workstation.photogrammetry.georef import accuracy_report, fit_similarity, georeference
from workstation.photogrammetry.synthetic import gcp_scene


def test_similarity_recovers_known_transform(rng):
    src = rng.normal(size=(10, 3))
    R = opk_to_matrix(0.4, -1.0, 2.5)
    sim = fit_similarity(src, 0.37 * src @ R.T + [1e5, 2e6, 30])
    assert sim.scale == pytest.approx(0.37)
    np.testing.assert_allclose(sim.R, R, atol=1e-12)
    np.testing.assert_allclose(sim.apply(src), 0.37 * src @ R.T + [1e5, 2e6, 30], atol=1e-8)


def test_similarity_rejects_reflection_and_collinear(rng):
    src = rng.normal(size=(6, 3))
    sim = fit_similarity(src, src * [1, 1, -1])  # a mirror image: best proper rotation
    assert np.linalg.det(sim.R) == pytest.approx(1.0)
    line = np.outer(np.arange(5.0), [1, 2, 3])
    with pytest.raises(InvalidInputError, match="collinear"):
        fit_similarity(line, line)


@pytest.mark.parametrize("noise", [0.3, 1.0])
def test_check_rmse_is_consistent_with_image_noise(noise):
    rec, gcps, expected = gcp_scene(np.random.default_rng(7), noise_px=noise, n_control=6, n_check=20)
    res = georeference(gcps, rec)
    m = res.report.metrics
    assert m["control_n"] == 6 and m["check_n"] == 20
    assert 0.5 * expected["rmse_h"] < m["check_rmse_h"] < 2.0 * expected["rmse_h"]
    assert 0.5 * expected["rmse_z"] < m["check_rmse_z"] < 2.0 * expected["rmse_z"]
    assert m["check_ce90"] == pytest.approx(1.5175 * m["check_rmse_h"])
    assert m["check_contour_interval_min"] == pytest.approx(3 * m["check_rmse_z"])
    rows = res.report.tables["points"]
    assert {r["role"] for r in rows} == {"control", "check"} and all("dZ" in r and r["rays"] >= 2 for r in rows)
    # the georeferenced reconstruction puts the cameras above the surveyed ground
    centres = np.array([im.pose.center for im in res.reconstruction.images.values()])
    assert np.all(centres[:, 2] > 300)


def test_check_points_are_not_used_in_the_fit():
    rec, gcps, _ = gcp_scene(np.random.default_rng(8), noise_px=0.5, n_control=5, n_check=5)
    a = georeference(gcps, rec)
    moved = [GCP(g.name, g.xyz + (0 if g.role == "control" else 50.0), g.role, g.sigma, g.observations) for g in gcps]
    b = georeference(moved, rec)
    np.testing.assert_allclose(a.similarity.matrix, b.similarity.matrix)
    assert b.report.metrics["check_rmse_3d"] > 40 > a.report.metrics["check_rmse_3d"]


def test_two_control_points_explain_why():
    pts = [GCP(n, np.array(x, float), "control", model_xyz=np.array(x, float)) for n, x in (("A", (0, 0, 0)), ("B", (1, 0, 0)))]
    pts.append(GCP("C", np.array([0.0, 1, 0]), "check", model_xyz=np.array([0.0, 1, 0])))
    with pytest.raises(InvalidInputError, match="at least 3 control points") as e:
        georeference(pts)
    assert "rotation about" in e.value.message


def test_missing_image_is_reported(rng):
    rec, gcps, _ = gcp_scene(np.random.default_rng(9), noise_px=0.5, n_control=4, n_check=2)
    g = gcps[4]
    gcps[4] = GCP(g.name, g.xyz, g.role, None, (("NOPE.JPG", 10.0, 10.0),))
    res = georeference(gcps, rec)
    assert any(g.name in n and "NOPE.JPG" in n for n in res.report.notes)
    assert res.report.metrics["check_n"] == 1


def test_accuracy_report_formulas():
    e = np.array([[0.03, -0.04, 0.1], [-0.03, 0.04, -0.1]])
    r = accuracy_report(e, np.zeros_like(e))
    assert r["rmse_h"] == pytest.approx(0.05) and r["rmse_3d"] == pytest.approx(np.sqrt(0.05**2 + 0.01))
    assert r["le90"] == pytest.approx(1.6449 * 0.1) and r["accuracy_v95"] == pytest.approx(0.196)
    assert r["dem_cell_size_min"] == pytest.approx(0.15)


def test_gcp_csv_observations_and_errors(tmp_path):
    p = tmp_path / "gcp.csv"
    p.write_text(
        "# survey 2024\nname,X,Y,Z,role,sigma,image,u,v\n"
        "G1,500000.1,4100000.2,100.5,control,0.02,a.jpg,10.5,20.5\n"
        "G1,,,,,,b.jpg,30,40\n"
        "C1,500010,4100010,101,check,,a.jpg,50,60\n"
    )
    pts = read_gcp(p)
    assert [g.name for g in pts] == ["G1", "C1"]
    assert pts[0].observations == (("a.jpg", 10.5, 20.5), ("b.jpg", 30.0, 40.0)) and pts[0].sigma == 0.02
    assert pts[1].role == "check"
    p.write_text("name,X,Y,Z,role\nG1,1,2,3,tie\n")
    with pytest.raises(InvalidInputError, match="role"):
        read_gcp(p)
    p.write_text("name,X,Y\nG1,1,2\n")
    with pytest.raises(InvalidInputError, match="missing column 'z'"):
        read_gcp(p)
