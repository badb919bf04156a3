"""SfM on photos from several cameras: intrinsics shared per camera group (image size and EXIF
camera), on the internet photos of the Sacré-Cœur (YFCC) and the Middlebury temple."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera
from workstation.photogrammetry.sfm import SfMParams, _extraction_batches, camera_groups, run_sfm

SACRE = "images/sfm/sacre_coeur_yfcc"
TEMPLE = "images/sfm/middlebury_templeSparseRing"


def _mixed_folder(shared_data, tmp_path, n_temple=3, n_sacre=3):
    """Temple views (one camera, 640x480 PNG, no EXIF) and Sacré-Cœur photos (one camera each)."""
    imgs = tmp_path / "imgs"
    imgs.mkdir()
    temple = sorted((shared_data / TEMPLE).glob("*.png"))[:n_temple]
    sacre = sorted((shared_data / SACRE).glob("*.jpg"))[:n_sacre]
    for f in temple + sacre:
        (imgs / f.name).symlink_to(f)
    return sorted(imgs.iterdir()), {f.name for f in temple}


@pytest.mark.realdata
def test_camera_groups_of_a_mixed_folder(shared_data, tmp_path):
    files, temple = _mixed_folder(shared_data, tmp_path)
    groups = camera_groups(files)
    assert sorted(len(g) for g in groups) == [1, 1, 1, 3]
    assert {f.name for g in groups if len(g) == 3 for f in g} == temple
    batches, sharing = _extraction_batches(files, None, SfMParams())
    assert sharing == "per camera group"
    assert [(mode, len(g)) for mode, g in batches] == [("SINGLE", 3), ("PER_IMAGE", 3)]
    assert _extraction_batches(files, None, SfMParams(cameras="per-image"))[0] == [("PER_IMAGE", files)]
    # one camera for images of different sizes: COLMAP would drop all but the first size
    with pytest.raises(InvalidInputError, match="is 1080x695 but") as e:
        _extraction_batches(files, None, SfMParams(cameras="single"))
    assert e.value.path.endswith("03903474_1471484089.jpg")
    only_temple = [f for f in files if f.name in temple]
    assert _extraction_batches(only_temple, None, SfMParams()) == ([("SINGLE", only_temple)], "shared")


@pytest.mark.realdata
def test_given_camera_refuses_any_image_of_another_size(shared_data, tmp_path):
    """Every image is checked against the calibrated size, not only the first one."""
    files, temple = _mixed_folder(shared_data, tmp_path, n_sacre=1)
    files = sorted(files, key=lambda f: f.name not in temple)  # the temple views first
    cam = Camera(640, 480, 1520.0, 1520.0, 319.5, 239.5)
    with pytest.raises(InvalidInputError, match="but the given camera is 640x480") as e:
        _extraction_batches(files, cam, SfMParams())
    assert e.value.path.endswith(".jpg")


@pytest.mark.realdata
@pytest.mark.slow
def test_internet_photos_get_one_camera_each_and_register(shared_data, tmp_path):
    """10 photos by 10 cameras, 675–1083 px: the default gives each its own intrinsics and
    registers them; a shared camera is refused up front (COLMAP imports only the first size,
    so that run registers nothing)."""
    src = shared_data / SACRE
    with pytest.raises(InvalidInputError, match="--cameras auto or per-image"):
        run_sfm(src, tmp_path / "single", params=SfMParams(cameras="single", max_image_size=640))
    res = run_sfm(src, tmp_path / "work", params=SfMParams(max_image_size=640))
    s = res.summary
    assert s["camera_sharing"] == "per-image" and s["camera_count"] == 10
    assert s["registered"] >= 8, res.unregistered
    cams = res.reconstruction.cameras
    assert len(cams) == s["registered"]  # one camera per registered image
    assert len({(c.width, c.height) for c in cams.values()}) == len(cams)
    assert s["mean_reprojection_error_px"] < 1.5 and s["points"] > 500
    # one view cannot tell its principal point from its rotation: it stays at the image centre
    assert any("one image only" in n for n in s["notes"])
    np.testing.assert_allclose([(c.cx, c.cy) for c in cams.values()],
                               [(c.width / 2 - 0.5, c.height / 2 - 0.5) for c in cams.values()], atol=1e-6)
    # self-calibrated focal lengths are those of photos (0.5–3 × the longer side)
    f_rel = np.array([c.fx / max(c.width, c.height) for c in cams.values()])
    assert np.all((f_rel > 0.5) & (f_rel < 3.0)), f_rel
