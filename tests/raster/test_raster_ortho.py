"""True orthophoto: projection, occlusion, and the synthetic-aerial goals (shift, colour, roof edges)."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.products import Camera, Pose, Raster, Reconstruction
from workstation.photogrammetry.collinearity import camera_rays, pixels_to_normalized
from workstation.photogrammetry.sfm import read_reconstruction
from workstation.raster.ortho import OrthoParams, project_points, true_ortho
from workstation.raster.synthetic_aerial import AerialRig, AerialScene, make_dataset

SCENE = AerialScene(size=100.0, buildings=((25.0, 30.0, 45.0, 48.0, 12.0), (60.0, 55.0, 78.0, 80.0, 18.0)))
RIG = AerialRig(height=60.0, width=160, height_px=120, focal_px=150.0)
RES = 0.5


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    d = tmp_path_factory.mktemp("aerial")
    js = make_dataset(d, SCENE, RIG)
    return read_reconstruction(js), SCENE.true_dsm(RES)


def roof_mask(rgb):
    return (rgb[..., 0] > 150) & (rgb[..., 1] < 56)


def test_project_points_matches_opencv(rng):
    cv2 = pytest.importorskip("cv2")
    cam = Camera(640, 480, 500.0, 510.0, 320.5, 239.0, 0.0, (-0.1, 0.02, 0.001, -0.002, 0.003))
    rvec = np.array([0.1, -0.2, 0.05])
    R = cv2.Rodrigues(rvec)[0]
    t = np.array([0.3, -0.1, 5.0])
    X = rng.uniform(-2, 2, (50, 3))
    uv, depth = project_points(cam, Pose(R, t), X)
    ref = cv2.projectPoints(X, rvec, t, cam.K, np.array(cam.dist))[0][:, 0]
    np.testing.assert_allclose(uv, ref, atol=1e-6)
    np.testing.assert_allclose(depth, (X @ R.T + t)[:, 2])
    # the renderer's inverse model: pixels_to_normalized(project(X)) is the pinhole ray of X
    xc = X @ R.T + t
    np.testing.assert_allclose(pixels_to_normalized(uv, cam), xc[:, :2] / xc[:, 2:], atol=1e-7)


def test_rig_has_the_planned_overlap():
    poses = RIG.poses(SCENE)
    centres = np.array([p.center for p in poses])
    xs, ys = np.unique(centres[:, 0].round(3)), np.unique(centres[:, 1].round(3))
    fw, fh = RIG.height * RIG.width / RIG.focal_px, RIG.height * RIG.height_px / RIG.focal_px
    assert np.diff(xs).mean() == pytest.approx(0.4 * fw, rel=1e-6)  # 60 % forward overlap
    assert np.diff(ys).mean() == pytest.approx(0.7 * fh, rel=1e-6)  # 30 % side overlap
    d = camera_rays(RIG.camera(), 1)
    assert d.shape == (RIG.height_px, RIG.width, 3) and np.allclose(np.linalg.norm(d, axis=2), 1)


def test_true_ortho_goals(dataset):
    from scipy.ndimage import binary_erosion, distance_transform_edt

    rec, dsm = dataset
    res = true_ortho(rec, dsm, OrthoParams())
    o = res.ortho.array
    assert o.shape[0] == 4 and o.dtype == np.uint8
    seen = o[3] > 0
    assert seen.mean() > 0.9
    rgb = o[:3].transpose(1, 2, 0)
    truth = SCENE.true_ortho(RES)
    err = np.abs(rgb.astype(float) - truth)[seen].mean()
    assert err <= 12.0  # mean colour error ≤ 12/255
    cv2 = pytest.importorskip("cv2")
    g1 = cv2.cvtColor(np.ascontiguousarray(rgb), cv2.COLOR_RGB2GRAY).astype(float) * seen
    g2 = cv2.cvtColor(truth, cv2.COLOR_RGB2GRAY).astype(float) * seen
    (dx, dy), _ = cv2.phaseCorrelate(g1, g2)
    assert np.hypot(dx, dy) <= 1.0  # geometric shift ≤ 1 cell
    # roof edges: the roof-coloured area matches the footprints within one cell
    X, Y = dsm.cell_centers()
    fp = SCENE.footprints(X, Y) >= 0
    edge = fp ^ binary_erosion(fp)
    dist = distance_transform_edt(~edge)
    wrong = (roof_mask(rgb) ^ fp) & seen
    assert dist[wrong].max(initial=0) <= 1.0
    assert res.meta["accuracy_rms_m"] == 0.0  # exact DSM and orientation of the synthetic rig


def test_ortho_over_terrain_only_leans_and_fails_the_edge_check(dataset):
    """The edge check can fail: over a bare-terrain 'DSM' roofs are displaced (relief displacement)."""
    from scipy.ndimage import binary_erosion, distance_transform_edt

    rec, dsm = dataset
    X, Y = dsm.cell_centers()
    dtm = Raster(SCENE.terrain(X, Y).astype(np.float32), dsm.transform, dsm.crs)
    o = true_ortho(rec, dtm, OrthoParams()).ortho.array
    rgb = o[:3].transpose(1, 2, 0)
    fp = SCENE.footprints(X, Y) >= 0
    edge = fp ^ binary_erosion(fp)
    dist = distance_transform_edt(~edge)
    assert dist[(roof_mask(rgb) ^ fp) & (o[3] > 0)].max() > 2.0


def test_occlusion_matches_exact_ray_casting(dataset):
    rec, dsm = dataset
    # one image far off-nadir of the tall building: its hidden ground must be nodata
    k = max(rec.images, key=lambda i: -np.linalg.norm(rec.images[i].pose.center[:2] - [SCENE.origin[0] + 69, SCENE.origin[1] + 67.5]))
    one = Reconstruction(rec.cameras, {k: rec.images[k]}, crs=rec.crs)
    params = OrthoParams(max_off_nadir=80.0)
    seen = true_ortho(one, dsm, params).ortho.array[3] > 0
    ghost = true_ortho(one, dsm, OrthoParams(max_off_nadir=80.0, occlusion=False)).ortho.array[3] > 0
    X, Y = dsm.cell_centers()
    Z = dsm.array.astype(float)
    P = np.column_stack([X.ravel(), Y.ravel(), Z.ravel() + 0.05])
    C = rec.images[k].pose.center
    d = C - P
    dist = np.linalg.norm(d, axis=1)
    hit, kind = SCENE.cast(P, d / dist[:, None])
    hidden = ((kind >= 0) & (np.linalg.norm(hit - P, axis=1) < dist - 0.5)).reshape(X.shape)
    inview = ghost  # cells inside the image footprint
    assert hidden[inview].sum() > 100  # the building really hides ground in this view
    agree = (seen == ~hidden)[inview].mean()
    assert agree > 0.99
    assert seen.sum() < ghost.sum()


def test_cameras_json_round_trip(tmp_path, dataset):
    from workstation.core.errors import InvalidInputError
    from workstation.io.reconstruction import write_reconstruction_json

    from workstation.io.paths import ALLOW_OUTSIDE

    rec, _ = dataset
    p = write_reconstruction_json(rec, tmp_path / "cams.json")
    with pytest.raises(InvalidInputError, match="leads outside"):  # its images are in another folder
        read_reconstruction(p)
    token = ALLOW_OUTSIDE.set(True)  # as --allow-outside does
    try:
        back = read_reconstruction(p)
    finally:
        ALLOW_OUTSIDE.reset(token)
    assert back.cameras[1] == rec.cameras[1]
    k = next(iter(rec.images))
    np.testing.assert_allclose(back.images[k].pose.R, rec.images[k].pose.R)
    (tmp_path / "bad.json").write_text("{}")
    with pytest.raises(InvalidInputError):
        read_reconstruction(tmp_path / "bad.json")


def test_colmap_model_reader_matches_pycolmap_projection(tmp_path, rng):
    pycolmap = pytest.importorskip("pycolmap")
    rec = pycolmap.Reconstruction()
    cam = pycolmap.Camera.create_from_model_name(1, "OPENCV", 500.0, 640, 480)
    cam.params = [500, 510, 320, 240, -0.1, 0.01, 0.001, -0.002]
    rec.add_camera_with_trivial_rig(cam)
    im = pycolmap.Image(name="a.png", camera_id=1, image_id=1)
    rec.add_image_with_trivial_frame(im, pycolmap.Rigid3d(pycolmap.Rotation3d(np.array([0.1, 0.2, 0.3])), np.array([1.0, 2.0, 3.0])))
    model = tmp_path / "work" / "sparse" / "0"
    model.mkdir(parents=True)
    (tmp_path / "work" / "images").mkdir()
    rec.write(str(model))
    ours = read_reconstruction(tmp_path / "work")
    X = rng.uniform(-1, 1, (10, 3))
    uv, _ = project_points(ours.cameras[1], ours.images[1].pose, X)
    ref = np.array([rec.images[1].project_point(x) for x in X])
    np.testing.assert_allclose(uv, ref - 0.5, atol=1e-6)  # COLMAP pixel centres sit at +0.5
    assert ours.images[1].path == str(tmp_path / "work" / "images" / "a.png")


def test_points_folded_back_by_distortion_are_not_seen():
    from workstation.raster.ortho import _max_radius2, _project

    from workstation.core.errors import StageError
    from workstation.core.products import Image

    cam = Camera(200, 200, 200.0, 200.0, 99.5, 99.5, 0.0, (-0.1, 0.0, 0.0, 0.0, 0.0))
    pose = Pose(np.eye(3), np.zeros(3))
    X = np.array([[3.0, 0.0, 1.0]])  # 72° off-axis: r - 0.1 r³ = 0.3 maps it back inside the image
    uv, depth, r2 = _project(cam, pose, X)
    assert 0 <= uv[0, 0] <= 199 and depth[0] > 0
    assert r2[0] > 1.1 * _max_radius2(cam)  # ...so true_ortho rejects it
    rec = Reconstruction({1: cam}, {1: Image("a", 1, Pose(np.diag([1.0, -1.0, -1.0]), np.array([0.0, 0.0, 1.0])))})
    dsm = Raster(np.zeros((4, 4), np.float32), (0.25, 0, 2.5, 0, -0.25, 0.5))  # X 2.5-3.5: folded or outside
    with pytest.raises(StageError, match="no DSM cell is seen"):
        true_ortho(rec, dsm, OrthoParams(max_off_nadir=89.0), images={1: np.zeros((200, 200, 3), np.uint8)})


def test_seam_blending_feathers_an_exposure_step(dataset):
    """Two overlapping images, one 40 levels brighter: blending spreads the step over cells."""
    rec, dsm = dataset
    ids = sorted(rec.images)[:2]  # neighbours along a flight line
    two = Reconstruction(rec.cameras, {k: rec.images[k] for k in ids}, crs=rec.crs)
    from workstation.raster.ortho import _load_image

    imgs = {ids[0]: _load_image(rec.images[ids[0]]),
            ids[1]: np.clip(_load_image(rec.images[ids[1]]).astype(int) + 40, 0, 255).astype(np.uint8)}
    truth = SCENE.true_ortho(RES).astype(float)

    def max_step(blend):
        o = true_ortho(two, dsm, OrthoParams(blend_angle=blend), images=imgs).ortho.array
        seen = (o[3] > 0)
        excess = (o[:3].astype(float) - truth.transpose(2, 0, 1)).mean(0)  # exposure offset per cell
        jump = np.abs(np.diff(excess, axis=1))[seen[:, 1:] & seen[:, :-1]]
        return np.percentile(jump, 99.9)

    hard, soft = max_step(0.0), max_step(2.0)
    assert hard > 30 and soft < 0.6 * hard


def test_bilinear_sample_takes_more_positions_than_opencv_maps_allow():
    """cv2.remap refuses a map side of 32,767 or more; the sampler lays positions out in rows,
    so 100,000 positions give the same values as sampling them in small pieces."""
    import cv2

    from workstation.raster.ortho import _bilinear_sample

    rng = np.random.default_rng(0)
    img = rng.integers(0, 255, (120, 160, 3), dtype=np.uint8)
    uv = rng.uniform(-3, 163, (100_000, 2))
    got = _bilinear_sample(img, uv)
    m = uv.astype(np.float32)
    ref = np.concatenate([cv2.remap(img, m[s:s + 1000, 0:1], m[s:s + 1000, 1:2], cv2.INTER_LINEAR,
                                    borderMode=cv2.BORDER_REPLICATE).reshape(-1, 3) for s in range(0, len(m), 1000)])
    assert got.shape == (100_000, 3)
    np.testing.assert_array_equal(got, ref.astype(np.float32))
