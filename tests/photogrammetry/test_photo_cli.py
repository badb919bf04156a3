"""`ws calibrate` and `ws sfm` command lines: products, --json, and user errors (exit 1)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.products import Camera
from workstation.io.camera import read_camera
from workstation.photogrammetry.calibration import board_points
from workstation.photogrammetry.collinearity import pose_from_opk, project
from workstation.photogrammetry.synthetic import dlt_case


def _write_dlt_points(path, X, uv):
    lines = ["name,X,Y,Z,u,v"] + [f"P{i},{x[0]},{x[1]},{x[2]},{u[0]},{u[1]}" for i, (x, u) in enumerate(zip(X, uv))]
    path.write_text("\n".join(lines) + "\n")


def test_calibrate_dlt_json(tmp_path, capsys):
    cam, pose, X, uv, dist = dlt_case(np.random.default_rng(4), 0.1, 20)
    pts = tmp_path / "points.csv"
    _write_dlt_points(pts, X, uv)
    out = tmp_path / "camera.json"
    rc = main(["calibrate", "dlt", str(pts), "--image-size", "4000x3000", "--refine", "--no-skew", "-o", str(out), "--json"])
    assert rc == 0
    doc = json.loads(capsys.readouterr().out)
    for k in ("model", "width", "height", "fx", "fy", "cx", "cy", "skew", "dist", "rms", "std", "extrinsics"):
        assert k in doc
    assert len(doc["dist"]) == 5 and doc["skew"] == 0.0
    c = read_camera(out)
    assert abs(c.fx / cam.fx - 1) < 0.005 and np.hypot(c.cx - cam.cx, c.cy - cam.cy) < 2.0
    np.testing.assert_allclose(doc["extrinsics"][0]["centre"], pose.center, atol=0.001 * dist)
    # refuses to overwrite
    assert main(["calibrate", "dlt", str(pts), "--image-size", "4000x3000", "-o", str(out)]) == 1


def test_calibrate_dlt_coplanar_exit_1(tmp_path, capsys):
    rng = np.random.default_rng(0)
    X = np.column_stack([rng.uniform(0, 10, (10, 2)), np.full(10, 5.0)])
    pts = tmp_path / "flat.csv"
    _write_dlt_points(pts, X, rng.uniform(0, 1000, (10, 2)))
    rc = main(["calibrate", "dlt", str(pts), "--image-size", "1000x1000", "-o", str(tmp_path / "c.json")])
    err = capsys.readouterr().err
    assert rc == 1 and "coplanar" in err and "zhang" in err.lower()
    assert not (tmp_path / "c.json").exists()


def _corner_files(tmp_path, n_views):
    rng = np.random.default_rng(1)
    cam = Camera(1280, 960, 1000.0, 1000.0, 640.0, 480.0, dist=(-0.1, 0.02, 0, 0, 0))
    obj = board_points(8, 6, 20.0)
    (tmp_path / "Model.txt").write_text("\n".join(f"{x:g} {y:g}" for x, y, _ in obj))
    d = tmp_path / "corners"
    d.mkdir()
    for k in range(n_views):
        pose = pose_from_opk(np.pi + rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.3, 0.3), [70, 50, -400 + rng.normal(0, 40)])
        uv = project(obj, cam, pose) + rng.normal(0, 0.05, (len(obj), 2))
        (d / f"data{k + 1}.txt").write_text("\n".join(f"{u:.4f} {v:.4f}" for u, v in uv))
    return cam, d


def test_calibrate_zhang_corner_files(tmp_path, capsys):
    cam, d = _corner_files(tmp_path, 6)
    out = tmp_path / "cam.json"
    rc = main(["calibrate", "zhang", "--model", str(tmp_path / "Model.txt"), "--corners", str(d), "--image-size", "1280x960", "-o", str(out)])
    assert rc == 0, capsys.readouterr().err
    c = read_camera(out)
    np.testing.assert_allclose([c.fx, c.fy, c.cx, c.cy], [1000, 1000, 640, 480], atol=1.5)
    doc = json.loads(out.read_text())
    assert len(doc["per_image"]) == 6 and doc["rms"] < 0.1


def test_calibrate_zhang_too_few_views(tmp_path, capsys):
    _, d = _corner_files(tmp_path, 2)
    rc = main(["calibrate", "zhang", "--model", str(tmp_path / "Model.txt"), "--corners", str(d), "--image-size", "1280x960", "-o", str(tmp_path / "c.json")])
    assert rc == 1 and "at least 3 views" in capsys.readouterr().err


def test_calibrate_zhang_needs_board_or_corners(tmp_path, capsys):
    assert main(["calibrate", "zhang", str(tmp_path), "-o", str(tmp_path / "c.json")]) == 1
    assert "--board" in capsys.readouterr().err


def test_sfm_bad_inputs(tmp_path, capsys):
    assert main(["sfm", str(tmp_path / "nope"), "-o", str(tmp_path / "w")]) == 1
    assert "not found" in capsys.readouterr().err
    (tmp_path / "imgs").mkdir()
    gcp = tmp_path / "gcp.csv"
    gcp.write_text("name,X,Y,Z,role,mx,my,mz\nA,0,0,0,control,0,0,0\nB,1,0,0,control,1,0,0\nC,0,1,0,check,0,1,0\n")
    assert main(["sfm", str(tmp_path / "imgs"), "-o", str(tmp_path / "w"), "--gcp", str(gcp)]) == 1
    assert "at least 3" in capsys.readouterr().err
    cam = tmp_path / "cam.json"
    cam.write_text('{"model": "PINHOLE", "width": 10}')
    assert main(["sfm", str(tmp_path / "imgs"), "-o", str(tmp_path / "w"), "--camera", str(cam)]) == 1
    assert "missing key" in capsys.readouterr().err
    assert main(["sfm", str(tmp_path / "imgs"), "-o", str(tmp_path / "w")]) == 1
    assert "no image files" in capsys.readouterr().err
