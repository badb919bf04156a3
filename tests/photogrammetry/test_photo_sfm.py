"""SfM through pycolmap: interop conversions (fast) and a small real run on the Middlebury temple."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera
from workstation.interop.pycolmap import camera_from_pycolmap, camera_to_colmap_params, camera_to_pycolmap
from workstation.photogrammetry.sfm import SfMParams, choose_matcher


@pytest.mark.parametrize(
    "dist,model",
    [((0, 0, 0, 0, 0), "PINHOLE"), ((-0.1, 0.02, 0.001, 0.0, 0), "OPENCV"), ((-0.1, 0.02, 0.001, 0.0, 0.003), "FULL_OPENCV")],
)
def test_camera_roundtrip_and_half_pixel_shift(dist, model):
    cam = Camera(640, 480, 500.0, 502.0, 319.5, 239.5, dist=dist)
    name, params = camera_to_colmap_params(cam)
    assert name == model and params[2] == 320.0 and params[3] == 240.0  # COLMAP: pixel corner origin
    back = camera_from_pycolmap(camera_to_pycolmap(cam))
    np.testing.assert_allclose([back.fx, back.fy, back.cx, back.cy], [500, 502, 319.5, 239.5])
    np.testing.assert_allclose(back.dist, dist)


def test_camera_with_skew_refused():
    with pytest.raises(InvalidInputError, match="skew"):
        camera_to_colmap_params(Camera(640, 480, 500.0, 500.0, 320.0, 240.0, skew=2.0))


def test_matcher_choice_and_override():
    assert choose_matcher(30, False, SfMParams()) == "exhaustive"
    assert choose_matcher(300, False, SfMParams()) == "retrieval"
    assert choose_matcher(300, True, SfMParams()) == "spatial"
    assert choose_matcher(300, True, SfMParams(matcher="exhaustive")) == "exhaustive"
    with pytest.raises(InvalidInputError):
        SfMParams(matcher="vocab")


def _temple_gt(folder):
    gt = {}
    for line in (folder / "templeSR_par.txt").read_text().splitlines()[1:]:
        p = line.split()
        v = np.array(p[1:], dtype=float)
        K, R, t = v[:9].reshape(3, 3), v[9:18].reshape(3, 3), v[18:21]
        gt[p[0]] = (K, R, -R.T @ t)
    return gt


@pytest.mark.realdata
@pytest.mark.slow
def test_sfm_cli_temple_subset_with_camera(shared_data, tmp_path, capsys):
    """6 temple views + a blank image: the 6 are registered where the ground truth puts them,
    the blank one is reported by name, intrinsics come from --camera (fixed)."""
    import cv2

    from workstation.cli.main import main
    from workstation.io.camera import write_camera
    from workstation.photogrammetry.georef import fit_similarity

    src = shared_data / "images/sfm/middlebury_templeSparseRing"
    gt = _temple_gt(src)
    names = [f"templeSR{k:04d}.png" for k in (6, 7, 8, 9, 10, 11)]
    imgs = tmp_path / "imgs"
    imgs.mkdir()
    for n in names:
        (imgs / n).symlink_to(src / n)
    cv2.imwrite(str(imgs / "zz_blank.png"), np.full((480, 640, 3), 128, np.uint8))
    K = gt[names[0]][0]
    write_camera(Camera(640, 480, K[0, 0], K[1, 1], K[0, 2], K[1, 2]), tmp_path / "cam.json")
    # virtual GCPs in the ground-truth frame (metres), observed through the true cameras
    rng = np.random.default_rng(0)
    P = rng.uniform([-0.07, 0.02, -0.01], [0.03, 0.18, 0.06], (9, 3))
    rows = ["name,X,Y,Z,role,image,u,v"]
    for i, X in enumerate(P):
        role = "control" if i < 5 else "check"
        for n in names:
            Kn, R, C = gt[n]
            x = Kn @ (R @ (X - C))
            rows.append(f"G{i},{X[0]:.9f},{X[1]:.9f},{X[2]:.9f},{role},{n},{x[0] / x[2]:.4f},{x[1] / x[2]:.4f}")
    rows.append("G0,,,,,zz_missing.png,10,10")
    (tmp_path / "gcp.csv").write_text("\n".join(rows) + "\n")
    rc = main(["sfm", str(imgs), "-o", str(tmp_path / "work"), "--camera", str(tmp_path / "cam.json"),
               "--gcp", str(tmp_path / "gcp.csv"), "--json"])
    out = capsys.readouterr()
    assert rc == 0, out.err
    doc = json.loads(out.out)
    assert doc["registered"] == 6 and doc["unregistered"] == ["zz_blank.png"]
    assert "zz_blank.png" in out.err
    assert doc["intrinsics"] == "fixed" and doc["cameras"]["1"]["fx"] == pytest.approx(K[0, 0])
    assert doc["mean_reprojection_error_px"] < 1.0 and doc["points"] > 100
    assert (tmp_path / "work/sparse/0/images.bin").exists() and (tmp_path / "work/database.db").exists()
    from workstation.io import read_cloud

    cloud = read_cloud(doc["sparse_cloud"])
    assert cloud.n == doc["points"] and cloud.attrs["rgb"].max() > 0
    geo = doc["georef"]["metrics"]
    assert geo["control_n"] == 5 and geo["check_n"] == 4
    assert geo["check_rmse_3d"] < 0.002, geo  # metres, on an object 0.16 m across
    # the control points' image observations allow the bundle adjustment with GCP constraints
    assert doc["georef"]["adjustment"] == "bundle" and doc["georef"]["bundle"]["tie_points"] > 100
    assert geo["check_rmse_3d"] <= 1.2 * geo["similarity_check_rmse_3d"]
    assert (tmp_path / "work/georef/0/images.bin").exists() and (tmp_path / "work/georef_report.json").exists()
    assert "check points 4" in out.err and "bundle adjustment" in out.err
    import pycolmap as _pc

    from workstation.interop.pycolmap import reconstruction_from_pycolmap
    from workstation.io.gcp import read_gcp
    from workstation.photogrammetry.georef import triangulate_gcps

    # the written georef/0 model holds the adjusted poses: check points intersect where surveyed
    georef = reconstruction_from_pycolmap(_pc.Reconstruction(str(tmp_path / "work/georef/0")))
    pts = read_gcp(tmp_path / "gcp.csv")
    pos, _, _ = triangulate_gcps([g for g in pts if g.role == "check"], georef)
    err = [np.linalg.norm(pos[g.name] - g.xyz) for g in pts if g.role == "check"]
    assert np.sqrt(np.mean(np.square(err))) == pytest.approx(geo["check_rmse_3d"], rel=1e-3, abs=1e-6)

    import pycolmap

    from workstation.interop.pycolmap import pose_from_pycolmap

    rec = pycolmap.Reconstruction(str(tmp_path / "work/sparse/0"))
    est = {im.name: pose_from_pycolmap(im).center for im in rec.images.values()}
    Ce = np.array([est[n] for n in names])
    Cg = np.array([gt[n][2] for n in names])
    sim = fit_similarity(Ce, Cg)
    err = np.linalg.norm(sim.apply(Ce) - Cg, axis=1)
    radius = np.linalg.norm(Cg - Cg.mean(0), axis=1).mean()
    assert np.median(err) < 0.01 * radius  # within 1 % of the ring's size


@pytest.mark.realdata
@pytest.mark.slow
def test_global_mapper_self_calibrated_keeps_principal_point_sane(shared_data, tmp_path):
    from workstation.photogrammetry.sfm import run_sfm

    src = shared_data / "images/sfm/middlebury_templeSparseRing"
    imgs = tmp_path / "imgs"
    imgs.mkdir()
    for k in (6, 7, 8, 9, 10, 11):
        (imgs / f"templeSR{k:04d}.png").symlink_to(src / f"templeSR{k:04d}.png")
    res = run_sfm(imgs, tmp_path / "work", params=SfMParams(mapper="global"))
    assert res.summary["mapper"] == "global" and res.summary["registered"] == 6
    cam = res.reconstruction.cameras[1]
    # six narrow views barely constrain the principal point: it stays within 10 % of the centre
    assert np.hypot(cam.cx - 319.5, cam.cy - 239.5) <= 0.1 * 640 + 1e-6
    assert res.cloud.n == res.summary["points"] > 100


@pytest.mark.slow
def test_sfm_on_one_thread_repeats_itself(tmp_path, capsys):
    """`ws sfm --threads 1` twice on the same 8 photos: the same model, camera for camera, and
    the thread count in the work folder's record."""
    import pycolmap

    from workstation.cli.main import main
    from workstation.photogrammetry.rigs import box_wall_rig

    box_wall_rig(tmp_path / "rig", n=8, width=200, height=150, focal_px=190.0)
    centres = []
    for k in range(2):
        work = tmp_path / f"work{k}"
        assert main(["sfm", str(tmp_path / "rig" / "images"), "-o", str(work), "--threads", "1"]) == 0
        rec = pycolmap.Reconstruction(str(work / "sparse" / "0"))
        centres.append({im.name: np.asarray(im.projection_center()) for im in rec.images.values()})
    capsys.readouterr()
    assert len(centres[0]) == 8 and centres[0].keys() == centres[1].keys()
    assert all(np.array_equal(centres[0][n], centres[1][n]) for n in centres[0])
    assert json.loads((tmp_path / "work0" / "summary.json").read_text())["params"]["num_threads"] == 1
