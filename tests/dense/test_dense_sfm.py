"""``ws sfm --dense``: orient then densify in one command, on distorted images with --camera."""

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.io import read_cloud
from workstation.io.camera import write_camera
from workstation.photogrammetry.rigs import box_wall_rig, box_wall_scene


@pytest.mark.slow
def test_sfm_dense_flag_orients_then_densifies(tmp_path, capsys):
    from workstation.photogrammetry.dense import evaluate
    from workstation.photogrammetry.georef import fit_similarity
    from workstation.photogrammetry.sfm import read_reconstruction

    # radial distortion in the images; the true camera (with k1, k2) given as ws calibrate writes it
    rec = box_wall_rig(tmp_path / "rig", n=8, width=320, height=240, focal_px=300.0, dist=(-0.12, 0.04, 0, 0, 0))
    write_camera(rec.cameras[1], tmp_path / "camera.json")
    wd = tmp_path / "wd"
    rc = main(["sfm", str(tmp_path / "rig" / "images"), "-o", str(wd), "--camera", str(tmp_path / "camera.json"),
               "--dense", "--device", "cpu", "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out)
    assert out["registered"] == 8
    assert out["dense"]["device"] == "cpu" and out["dense"]["points"] > 5000
    fused = read_cloud(wd / "dense" / "fused.ply")
    assert fused.n == out["dense"]["points"]
    assert "rgb" in fused.attrs and "normal" in fused.attrs
    # the dense cloud sits where the sparse one does (same SfM frame)
    sparse = read_cloud(wd / "sparse.ply")
    lo, hi = sparse.xyz.min(axis=0), sparse.xyz.max(axis=0)
    pad = 0.2 * (hi - lo)
    inside = ((fused.xyz > lo - pad) & (fused.xyz < hi + pad)).all(axis=1)
    assert inside.mean() > 0.95
    # and, moved into the true frame by the camera centres, on the true surface
    est = read_reconstruction(wd / "sparse" / "0")
    by_name = {im.name: im.pose.center for im in rec.images.values()}
    a = np.array([im.pose.center for im in est.images.values()])
    b = np.array([by_name[im.name] for im in est.images.values()])
    xyz = fit_similarity(a, b).apply(fused.xyz)
    V, F, _ = box_wall_scene()
    assert evaluate(xyz, V, F, 16.0, xyz[:10])["accuracy_median"] < 0.03  # ~0.4 px at 12 m, 320 px wide
