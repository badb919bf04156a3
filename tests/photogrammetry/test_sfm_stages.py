"""SfM stages run in steps for progress: feature extraction in runs of images and matching in
blocks of pairs write the database that one COLMAP call writes; the large-set path (sequential
matching above ``exhaustive_max_images``) registers a rendered strip of photos."""

from __future__ import annotations

import shutil

import numpy as np
import pytest

from workstation.photogrammetry.sfm import (
    SfMParams,
    _chunks,
    _extract_features,
    _match,
    _match_at_once,
    _reader_options,
    _verification_options,
    choose_matcher,
    run_sfm,
)

TEMPLE = "images/sfm/middlebury_templeSparseRing"
SACRE = "images/sfm/sacre_coeur_yfcc"


def _db_contents(pycolmap, db) -> dict:
    """Images (id, name, camera id), cameras and keypoints of a database."""
    with pycolmap.Database.open(str(db)) as d:
        images = sorted((int(i.image_id), i.name, int(i.camera_id)) for i in d.read_all_images())
        keypoints = {name: np.asarray(d.read_keypoints(iid)) for iid, name, _ in images}
        return {"images": images, "cameras": d.num_cameras(), "keypoints": keypoints}


def _verified_pairs(pycolmap, db) -> dict:
    """Verified image pairs of a database and their inlier counts."""
    with pycolmap.Database.open(str(db)) as d:
        ids, geoms = d.read_two_view_geometries()
    return {pycolmap.pair_id_to_image_pair(int(p)): len(g.inlier_matches) for p, g in zip(ids, geoms)}


def _folder(shared_data, tmp_path, names) -> tuple:
    imgs = tmp_path / "imgs"
    imgs.mkdir()
    for n in names:
        (imgs / n.name).symlink_to(n)
    return imgs, sorted(imgs.iterdir())


def test_chunks_cover_the_items_in_order():
    items = list(range(45))
    runs = _chunks(items, 4)
    assert [x for r in runs for x in r] == items
    assert all(len(r) >= 4 for r in runs[:-1]) and len(runs) <= 20
    assert _chunks(list(range(3)), 4) == [[0, 1, 2]]


@pytest.mark.realdata
@pytest.mark.slow
@pytest.mark.parametrize("source, n, cameras", [(TEMPLE, 8, "auto"), (SACRE, 5, "per-image")])
def test_extraction_and_matching_in_steps_equal_one_call(shared_data, tmp_path, source, n, cameras):
    """A shared camera (temple: one 640x480 camera, extracted in 4 runs of 2 images; the later
    runs reuse the first run's camera) and one camera per image (Sacré-Cœur): same images, ids,
    cameras and keypoints as one extraction call; then the blocks of pairs give the verified
    pairs of one exhaustive matching call with the same inlier counts (one thread, RANSAC
    seeded per pair)."""
    import pycolmap

    imgs, files = _folder(shared_data, tmp_path, sorted((shared_data / source).glob("*.[jp]*g"))[:n])
    params = SfMParams(cameras=cameras, max_image_size=320, num_threads=1, max_features=2000)
    pycolmap.set_random_seed(0)
    stepped = tmp_path / "stepped.db"
    _extract_features(pycolmap, stepped, imgs, files, None, params)
    once = tmp_path / "once.db"
    ext = pycolmap.FeatureExtractionOptions()
    ext.max_image_size, ext.num_threads, ext.sift.max_num_features = 320, 1, 2000
    mode = pycolmap.CameraMode.SINGLE if cameras == "auto" else pycolmap.CameraMode.PER_IMAGE
    pycolmap.extract_features(once, imgs, image_names=[f.name for f in files], camera_mode=mode,
                              reader_options=_reader_options(pycolmap, None, params), extraction_options=ext,
                              device=pycolmap.Device.cpu)
    a, b = _db_contents(pycolmap, stepped), _db_contents(pycolmap, once)
    assert a["images"] == b["images"]
    assert a["cameras"] == b["cameras"] == (1 if cameras == "auto" else n)
    for name, kp in b["keypoints"].items():
        assert kp.shape[0] > 100 and np.array_equal(a["keypoints"][name], kp), name

    shutil.copy(stepped, tmp_path / "blocks.db")
    assert _match(pycolmap, tmp_path / "blocks.db", n, params) == ("exhaustive", n * (n - 1) // 2)
    mopt = pycolmap.FeatureMatchingOptions()
    mopt.num_threads = 1
    _match_at_once(pycolmap, stepped, "exhaustive", mopt, _verification_options(pycolmap, params), params,
                   pycolmap.Device.cpu)
    blocks, one = _verified_pairs(pycolmap, tmp_path / "blocks.db"), _verified_pairs(pycolmap, stepped)
    assert len(one) >= n // 2 and blocks == one  # each pair's RANSAC starts from the seed


@pytest.mark.slow
def test_a_strip_above_the_exhaustive_limit_is_matched_by_sequence_and_retrieval_and_registers(tmp_path):
    """18 rendered views of a textured wall and box on a 5 m strip (256x192 px), with the
    exhaustive limit set below the image count: sequential pairs in name order plus retrieval
    pairs (fewer than exhaustive), ≥ 95 %
    registered, camera centres within 5 cm of the true ones after a similarity."""
    from workstation.photogrammetry.georef import fit_similarity
    from workstation.photogrammetry.rigs import box_wall_rig

    rec = box_wall_rig(tmp_path / "rig", n=18, width=256, height=192, focal_px=240.0)
    imgs = tmp_path / "rig" / "images"
    true = {}
    for im in rec.images.values():  # zero-padded names keep the strip's order in name order
        name = f"im{int(im.name[2:-4]):02d}.png"
        (imgs / im.name).rename(imgs / name)
        true[name] = im.pose.center
    params = SfMParams(exhaustive_max_images=12)
    assert choose_matcher(18, False, params) == "retrieval"
    res = run_sfm(imgs, tmp_path / "work", params=params)
    s = res.summary
    assert s["matcher"] == "retrieval" and s["matched_pairs"] < 18 * 17 // 2
    assert s["registered"] >= 0.95 * 18, res.unregistered
    assert s["mean_reprojection_error_px"] < 1.0
    got = {im.name: np.asarray(im.pose.center) for im in res.reconstruction.images.values() if im.pose is not None}
    names = sorted(got)
    est, ref = np.array([got[n] for n in names]), np.array([true[n] for n in names])
    assert np.linalg.norm(fit_similarity(est, ref).apply(est) - ref, axis=1).max() < 0.05
