"""Upright models: gravity and main façade of reconstructions in arbitrary frames."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Pose, Reconstruction
from workstation.photogrammetry import orient
from workstation.photogrammetry.orient import (
    OrientParams,
    estimate_orientation,
    level_rotation,
    orient_cloud,
    orient_reconstruction,
    upright,
)
from workstation.photogrammetry.rigs import load_rig, look_at, rig_poses

CAM = Camera(640, 480, 520.0, 520.0, 319.5, 239.5)


def angle_deg(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return math.degrees(math.acos(float(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1))))


def random_rotation(rng) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    return Rotation.random(random_state=int(rng.integers(1 << 31))).as_matrix()


def small_rotation(rng, sigma_deg) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(np.radians(rng.normal(0, sigma_deg, 3))).as_matrix()


def move(rec: Reconstruction, R: np.ndarray, t: np.ndarray, s: float) -> Reconstruction:
    """The same scene in another frame: X' = s R X + t (as an SfM frame would be)."""
    from workstation.photogrammetry.georef import Similarity, transform_reconstruction

    return transform_reconstruction(rec, Similarity(s, R, t))


def facade_rig(rng, n: int = 14, portrait: int = 2) -> Reconstruction:
    """A 30 m × 8 m × 12 m building whose long façade (y = 0) faces -y, photographed from an
    arc in front of it (pitch up to the façade, roll noise 1°, some portrait shots), with
    sparse points on the façade, a side wall, the roof edge and the ground."""
    images = {}
    for k, a in enumerate(np.radians(np.linspace(-140, -40, n))):
        C = np.array([20 * math.cos(a), 20 * math.sin(a), rng.uniform(1.2, 2.0)])
        pose = look_at(C, np.array([rng.uniform(-5, 5), 0.0, rng.uniform(3, 9)]))
        R = small_rotation(rng, 1.0) @ np.asarray(pose.R)
        if k < portrait:  # camera turned 90° about its optical axis
            R = np.array([[0, 1, 0], [-1, 0, 0], [0, 0, 1.0]]) @ R
        images[k + 1] = Image(f"img_{k}.jpg", 1, Pose(R, -R @ C))
    m = 3000
    facade = np.column_stack([rng.uniform(-15, 15, m), rng.normal(0, 0.03, m), rng.uniform(0, 12, m)])
    side = np.column_stack([np.full(m // 4, -15.0) + rng.normal(0, 0.03, m // 4), rng.uniform(0, 8, m // 4),
                            rng.uniform(0, 12, m // 4)])
    ground = np.column_stack([rng.uniform(-20, 20, m), rng.uniform(-15, 0, m), rng.normal(0, 0.03, m)])
    return Reconstruction({1: CAM}, images, np.vstack([facade, side, ground]))


@pytest.mark.parametrize("seed", range(6))
def test_random_frame_recovers_vertical_and_facade(seed):
    """Property: whatever similarity the SfM frame is in, up and the façade are recovered."""
    rng = np.random.default_rng(seed)
    truth = facade_rig(rng)
    R0, t0, s0 = random_rotation(rng), rng.normal(0, 100, 3), float(rng.uniform(0.1, 10))
    rec = move(truth, R0, t0, s0)
    o = estimate_orientation(rec)
    assert o.method == "image-orientation" and o.facade_source == "points"
    # 12 upright photos with 1° roll noise: the goal is 2° (30 seeds tried: at most 1.4°)
    assert angle_deg(o.up, R0 @ [0, 0, 1]) < 2.0
    assert angle_deg(o.facade_normal, R0 @ [0, -1, 0]) < 3.0
    # the upright frame is the true one up to a shift and the scale: R_o R0 = identity
    assert angle_deg((o.R @ R0)[:, 2], [0, 0, 1]) < 2.0
    assert np.degrees(np.arccos(np.clip((np.trace(o.R @ R0) - 1) / 2, -1, 1))) < 4.0
    out = orient_reconstruction(rec, o)
    # rotation about the camera centroid, no scale change
    c0 = np.mean([im.pose.center for im in rec.images.values()], axis=0)
    c1 = np.mean([im.pose.center for im in out.images.values()], axis=0)
    assert np.allclose(c0, c1, atol=1e-6 * s0)
    assert np.linalg.norm(out.points[0] - out.points[1]) == pytest.approx(np.linalg.norm(rec.points[0] - rec.points[1]))
    assert out.meta["upright"] is True and out.meta["upright_tilt_deg"] == pytest.approx(o.tilt_deg, abs=1e-3)
    # projections are unchanged: the same pixels see the same points
    from workstation.photogrammetry.collinearity import project

    im0, im1 = rec.images[3], out.images[3]
    assert np.allclose(project(rec.points[:50], CAM, im0.pose), project(out.points[:50], CAM, im1.pose), atol=1e-6)


def test_facing_plus_y_and_cameras_only():
    rng = np.random.default_rng(3)
    truth = facade_rig(rng, portrait=0)
    R0 = random_rotation(rng)
    rec = move(truth, R0, np.zeros(3), 1.0)
    plus = estimate_orientation(rec, OrientParams(facing="+y"))
    assert angle_deg(plus.R @ (R0 @ [0, -1, 0]), [0, 1, 0]) < 3.0
    no_pts = Reconstruction(rec.cameras, rec.images)
    o = estimate_orientation(no_pts)
    assert o.facade_source == "cameras"
    # the arc's mean viewing direction is +y in the true frame: the façade faces -y
    assert angle_deg(o.facade_normal, R0 @ [0, -1, 0]) < 5.0
    level = estimate_orientation(no_pts, OrientParams(facade="none"))
    assert level.facade_source == "none" and np.allclose(level.R, level_rotation(level.up))


def test_refinement_removes_common_pitch():
    """Cameras all looking up by 15°: the mean up vector leans 15°, the horizon rows do not."""
    rng = np.random.default_rng(0)
    images = {}
    for k, a in enumerate(np.radians(np.linspace(-120, -60, 7))):
        C = np.array([20 * math.cos(a), 20 * math.sin(a), 0.0])
        pose = look_at(C, np.array([0.0, 0.0, 20 * math.tan(math.radians(15))]))
        images[k + 1] = Image(f"{k}.jpg", 1, pose)
    R0 = random_rotation(rng)
    rec = move(Reconstruction({1: CAM}, images), R0, np.zeros(3), 1.0)
    plain, _ = orient.consensus_axis(np.stack([np.asarray(im.pose.R)[1] for im in rec.images.values()]))
    assert angle_deg(-plain, R0 @ [0, 0, 1]) > 10.0
    assert angle_deg(estimate_orientation(rec).up, R0 @ [0, 0, 1]) < 0.5


def test_nadir_block_looks_down():
    rng = np.random.default_rng(1)
    Rn = np.diag([1.0, -1.0, -1.0])
    images = {}
    for k in range(12):
        R = small_rotation(rng, 2.0) @ Rn
        C = np.array([k % 4 * 30.0, k // 4 * 40.0, 300.0])
        images[k + 1] = Image(f"{k}.jpg", 1, Pose(R, -R @ C))
    R0 = random_rotation(rng)
    rec = move(Reconstruction({1: CAM}, images), R0, np.zeros(3), 1.0)
    o = estimate_orientation(rec)
    assert o.method == "nadir" and o.facade_source == "none"
    assert angle_deg(o.up, R0 @ [0, 0, 1]) < 2.0
    # told the photos are upright instead, the image -y axes (north here) would be taken as up
    wrong = estimate_orientation(rec, OrientParams(assume="upright"))
    assert angle_deg(wrong.up, R0 @ [0, 0, 1]) > 45.0


def test_heritage_rig_vertical_within_2_degrees():
    """The castle/heritage convergent rig (two rings, pitched up and down), with SfM-like
    pose noise (0.3°), in a random frame."""
    _, spec = load_rig("rig_heritage")
    rng = np.random.default_rng(11)
    poses = rig_poses(spec, np.array([5.0, -3.0, 0.0]), np.array([30.0, 14.0, 25.0]))
    images = {}
    for k, p in enumerate(poses, start=1):
        R = small_rotation(rng, 0.3) @ np.asarray(p.R)
        images[k] = Image(f"img_{k:03d}.png", 1, Pose(R, -R @ p.center))
    for seed in range(3):
        R0 = random_rotation(np.random.default_rng(seed))
        rec = move(Reconstruction({1: spec.camera()}, images), R0, np.ones(3), 0.37)
        o = estimate_orientation(rec)
        assert o.inliers == len(poses)
        assert angle_deg(o.up, R0 @ [0, 0, 1]) < 2.0


def fountain_reconstruction(folder) -> Reconstruction:
    """The true cameras of fountain-P11 (R in the files is camera → world, C the centre)."""
    images = {}
    for k, f in enumerate(sorted(folder.glob("*.jpg.camera")), start=1):
        rows = [[float(v) for v in line.split()] for line in f.read_text().splitlines() if line.strip()]
        K, Rcw, C, (w, h) = np.array(rows[0:3]), np.array(rows[4:7]), np.array(rows[7]), rows[8]
        cam = Camera(int(w), int(h), K[0, 0], K[1, 1], K[0, 2], K[1, 2])
        images[k] = Image(f.name[: -len(".camera")], 1, Pose(Rcw.T, -Rcw.T @ C))
    return Reconstruction({1: cam}, images)


@pytest.mark.realdata
def test_fountain_true_cameras_vertical_within_2_degrees(shared_data):
    """fountain-P11's ground-truth frame has z pointing down (the image y axes of all 11
    photos lie within 7° of +z and their rows within 1.3° of the horizontal plane)."""
    rec = fountain_reconstruction(shared_data / "images" / "sfm" / "strecha_fountain-P11" / "gt_dense_cameras")
    assert len(rec.images) == 11
    for seed in range(3):
        rng = np.random.default_rng(seed)
        R0 = random_rotation(rng)
        o = estimate_orientation(move(rec, R0, rng.normal(0, 10, 3), 2.0))
        assert o.inliers == 11
        assert angle_deg(o.up, R0 @ [0, 0, -1]) < 2.0
        # the photos look at the façade: it faces back toward the cameras
        views = np.stack([np.asarray(im.pose.R)[2] for im in rec.images.values()]).mean(axis=0)
        assert angle_deg(o.facade_normal, R0 @ -views) < 15.0


def test_orient_cloud_moves_points_and_normals():
    rng = np.random.default_rng(5)
    rec = move(facade_rig(rng), random_rotation(rng), np.zeros(3), 1.0)
    o = estimate_orientation(rec)
    n = np.tile([0.0, 0.0, 1.0], (rec.points.shape[0], 1))
    cloud = Cloud(rec.points, {"normal": n})
    out = orient_cloud(cloud, o)
    assert np.allclose(out.xyz, o.similarity.apply(rec.points))
    assert np.allclose(out.attrs["normal"], (o.R @ [0, 0, 1.0]).astype(np.float32), atol=1e-6)
    assert np.array_equal(cloud.xyz, rec.points)  # input untouched
    assert out.history[-1].stage == "upright"
    rec2, o2 = upright(rec)
    assert np.allclose(o2.R, o.R) and np.allclose(rec2.points, out.xyz)


def test_bad_parameters_and_empty_reconstruction():
    with pytest.raises(InvalidInputError):
        OrientParams(facing="x")
    with pytest.raises(InvalidInputError):
        OrientParams(assume="sideways")
    with pytest.raises(InvalidInputError, match="no oriented images"):
        estimate_orientation(Reconstruction({1: CAM}, {}))

