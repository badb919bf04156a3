"""The work folder remembers its photos: `ws sfm` records the image folder and camera settings,
`dense`, `mesh --reconstruction`, `colorize` and `ortho` find the photos from that record,
an explicit --images wins, and a moved folder or a missing image fails before any work."""

from __future__ import annotations

import json
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from workstation.cli.main import main


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    """`ws sfm PHOTOS -o WORK` on a 6-photo rig (box in front of a wall, 200 x 150 px)."""
    from workstation.photogrammetry.rigs import box_wall_rig

    root = tmp_path_factory.mktemp("workdir")
    box_wall_rig(root / "rig", n=6, width=200, height=150, focal_px=190.0)
    photos = root / "photos"
    shutil.move(str(root / "rig" / "images"), photos)  # the photos live outside the work folder
    assert main(["sfm", str(photos), "-o", str(root / "work"), "--max-image-size", "180"]) == 0
    return root


@pytest.fixture
def moved(work):
    """The photo folder renamed for the test, put back after it."""
    src, dst = work / "photos", work / "photos_moved"
    src.rename(dst)
    try:
        yield dst
    finally:
        dst.rename(src)


def run(args, capsys) -> tuple[int, str, float]:
    """(exit code, stderr, process CPU seconds) of a command; CPU time, unlike wall time, does
    not grow when other jobs load the machine, and counts the work of every thread."""
    capsys.readouterr()
    t0 = time.process_time()
    rc = main(args)
    return rc, capsys.readouterr().err, time.process_time() - t0


def test_sfm_records_image_folder_and_camera_settings(work):
    rec = json.loads((work / "work" / "summary.json").read_text())
    assert rec["stage"] == "sfm"
    assert rec["inputs"]["image_dir"] == str((work / "photos").absolute())
    assert Path(rec["inputs"]["image_dir"]).is_absolute()
    p = rec["params"]
    assert (p["camera_model"], p["intrinsics"], p["max_image_size"], p["matcher"]) == ("SIMPLE_RADIAL", "shared", 180, "auto")
    assert rec["registered"] == 6  # the figures of --json stay in the record
    assert str((work / "work" / "sparse" / "0").absolute()) in rec["outputs"]


def test_resolve_image_dir_order(work, tmp_path):
    from workstation.core.errors import InvalidInputError
    from workstation.io.reconstruction import resolve_image_dir

    wd = work / "work"
    assert resolve_image_dir(wd, tmp_path) == tmp_path  # explicit wins
    assert resolve_image_dir(wd) == (work / "photos").absolute()  # the record
    assert resolve_image_dir(wd / "sparse" / "0") == (work / "photos").absolute()  # model folder -> its work folder
    rig = work / "rig"  # true-camera rig: sparse/0, no record, no images/ (moved away)
    with pytest.raises(InvalidInputError, match="no image folder") as e:
        resolve_image_dir(rig)
    assert "--images" in str(e.value)
    (tmp_path / "images").mkdir()
    (tmp_path / "sparse").mkdir()
    assert resolve_image_dir(tmp_path) == tmp_path / "images"  # rig folders keep WORKDIR/images
    (tmp_path / "cameras.json").write_text("{}")
    assert resolve_image_dir(tmp_path) is None  # a cameras JSON names its images itself


@pytest.mark.parametrize("command", ["dense", "mesh", "colorize", "ortho"])
def test_moved_image_folder_names_the_recorded_path_and_the_option(work, moved, command, capsys, tmp_path):
    wd = work / "work"
    dsm = _dsm(tmp_path)
    args = {
        "dense": ["dense", str(wd), "--device", "cpu"],
        "mesh": ["mesh", str(wd / "sparse.ply"), "-o", str(tmp_path / "m.obj"), "--reconstruction", str(wd)],
        "colorize": ["colorize", str(wd / "sparse.ply"), "--reconstruction", str(wd), "-o", str(tmp_path / "c.laz")],
        "ortho": ["ortho", str(wd), "--dsm", str(dsm), "-o", str(tmp_path / "o.tif")],
    }[command]
    rc, err, _ = run(args, capsys)
    assert rc == 1
    assert str((work / "photos").absolute()) in err and "no longer exists" in err
    assert "--images" in err
    assert not (wd / "dense").exists() and not list(tmp_path.glob("[mco].*"))


def test_explicit_images_wins_over_the_record(work, moved, capsys, tmp_path):
    wd = work / "work"
    out = tmp_path / "c.laz"
    rc, err, _ = run(["colorize", str(wd / "sparse.ply"), "--reconstruction", str(wd), "--images", str(moved),
                      "-o", str(out), "--json"], capsys)
    assert rc == 0, err
    from workstation.io import read_cloud

    c = read_cloud(out)
    assert np.count_nonzero(c.attrs["colorized"]) > 0.5 * c.n
    rec = json.loads((wd / "colorize_c.json").read_text())
    assert rec["stage"] == "colorize" and rec["inputs"]["image_dir"] == str(moved.absolute())


def test_missing_image_named_before_any_work(work, capsys, tmp_path):
    """One photo the model names is gone: dense and mesh name it and stop at once, even with a
    cloud that takes seconds to mesh; nothing is written."""
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    wd = work / "work"
    gone = work / "photos" / "im3.png"
    hidden = work / "im3.png.hidden"
    rng = np.random.default_rng(0)
    big = tmp_path / "big.ply"  # 300 k points on the wall: Poisson meshing takes many seconds
    write_cloud(Cloud(np.column_stack([rng.uniform(-8, 8, 300_000), np.full(300_000, 12.0),
                                       rng.uniform(-5, 7, 300_000)])), big)
    gone.rename(hidden)
    try:
        rc, err, dt = run(["dense", str(wd), "--device", "cpu"], capsys)
        assert rc == 1 and "im3.png" in err and "1 of the 6 images" in err and "--images" in err
        assert dt < 1.0 and not (wd / "dense").exists()  # dense on 6 photos takes several CPU seconds
        rc, err, dt = run(["mesh", str(big), "-o", str(tmp_path / "m.obj"), "--reconstruction", str(wd)], capsys)
        assert rc == 1 and "im3.png" in err
        assert dt < 1.0 and not (tmp_path / "m.obj").exists()  # reading + meshing the cloud: many seconds
    finally:
        hidden.rename(gone)


def test_no_model_fails_at_once(tmp_path, capsys):
    (tmp_path / "images").mkdir()
    rc, err, dt = run(["dense", str(tmp_path), "--device", "cpu"], capsys)
    assert rc == 1 and "no COLMAP model" in err and dt < 1.0


def _dsm(folder: Path) -> Path:
    """A flat 1-cell-per-metre DSM over the rig (only needs to exist and be readable)."""
    from workstation.core.products import Raster
    from workstation.io.geotiff import write_raster

    p = folder / "dsm.tif"
    write_raster(Raster(np.zeros((20, 20), np.float32), (1.0, 0.0, -10.0, 0.0, -1.0, 20.0), None, -9999.0), p)
    return p
