"""Scale without GCPs: scale-bar syntax, triangulated bars, known model distances."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Reconstruction
from workstation.photogrammetry.collinearity import project
from workstation.photogrammetry.georef import Similarity, transform_reconstruction
from workstation.photogrammetry.orient import estimate_orientation
from workstation.photogrammetry.rigs import look_at
from workstation.photogrammetry.scale import (
    compose,
    estimate_scale,
    is_scaled,
    length_text,
    parse_scale_bar,
    parse_scale_distance,
    scale_cloud,
    scale_reconstruction,
)

CAM = Camera(1000, 750, 900.0, 900.0, 499.5, 374.5)


def metric_scene() -> tuple[Reconstruction, np.ndarray]:
    """Three photos of a wall 10 m away (metres), and two 1 m bars on it (4 end points)."""
    images = {k + 1: Image(f"IMG {k}.JPG", 1, look_at(np.array([x, -10.0, 1.6]), np.array([0.0, 0.0, 1.5])))
              for k, x in enumerate((-3.0, 0.0, 3.0))}
    ends = np.array([[-1.0, 0.0, 1.0], [0.0, 0.0, 1.0], [0.5, 0.0, 2.0], [0.5, 0.0, 3.0]])
    pts = np.random.default_rng(0).uniform([-4, -0.1, 0], [4, 0.1, 4], (200, 3))
    return Reconstruction({1: CAM}, images, pts), ends


def sfm_frame(rec: Reconstruction, s: float, t=(0.0, 0.0, 0.0)) -> Reconstruction:
    """The scene in an SfM frame X' = s X + t (no georeference record)."""
    moved = transform_reconstruction(rec, Similarity(s, np.eye(3), np.asarray(t, float)))
    return Reconstruction(moved.cameras, moved.images, moved.points)


def bar_text(rec, a, b, length="1.000 m", images=(1, 2, 3), rng=None, noise_px=0.0) -> str:
    """The scale-bar text of the true end points a, b as clicked in ``images``."""
    def end(X):
        uv = [project(X[None], CAM, rec.images[i].pose)[0] for i in images]
        if rng is not None:
            uv = [p + rng.normal(0, noise_px, 2) for p in uv]
        return " ".join(f"{rec.images[i].name}:{u:.3f},{v:.3f}" for i, (u, v) in zip(images, uv))
    return f"{end(a)} ; {end(b)} = {length}"


def test_parse_forms_and_units():
    bar = parse_scale_bar("IMG 0.JPG:1520.5,1006 IMG 1.JPG:1498,1010.25 ; "
                          "IMG 0.JPG:2210,1003 IMG 2.JPG:2187,1009 = 1.000 m")
    a, b = bar.ends
    assert [o.image for o in a.observations] == ["IMG 0.JPG", "IMG 1.JPG"]
    assert (a.observations[1].x, a.observations[1].y) == (1498.0, 1010.25)
    assert [o.image for o in b.observations] == ["IMG 0.JPG", "IMG 2.JPG"]
    assert bar.length_m == 1.0
    assert parse_scale_bar("a:1,2 b:3,4;a:5,6 b:7,8=2").length_m == 2.0  # metres by default, tight spacing
    assert parse_scale_bar("a:1,2 b:3,4 ; a:5,6 b:7,8 = 25 mm").length_m == pytest.approx(0.025)
    assert parse_scale_bar("a:1,2 b:3,4 ; a:5,6 b:7,8 = 3 us-ft").length_m == pytest.approx(3 * 1200 / 3937)
    assert parse_scale_bar("a:-1e1,2 b:3,4 ; 1,2,3 = 1 ft").ends[1].model_xyz == (1.0, 2.0, 3.0)
    d = parse_scale_distance(" 0.5,-1,2 ; 1.5,-1,2 = 100 cm ")
    assert d.ends[0].model_xyz == (0.5, -1.0, 2.0) and d.length_m == pytest.approx(1.0)


@pytest.mark.parametrize("text, match", [
    ("a:1,2 b:3,4 ; a:5,6 b:7,8", "exactly one '='"),
    ("a:1,2 b:3,4 = 1 m", "two ends separated by ';'"),
    ("a:1,2 b:3,4 ; a:5,6 b:7,8 = 1 furlong", "unknown unit 'furlong'"),
    ("a:1,2 b:3,4 ; a:5,6 b:7,8 = -1 m", "positive"),
    ("a:1,2 b:3,4 ; a:5,6 b:7,8 = one m", "not a number"),
    ("a:1,2 ; a:5,6 b:7,8 = 1 m", "first end is observed in 1 image"),
    ("a:1,2 a:3,4 ; a:5,6 b:7,8 = 1 m", "first end is observed in 1 image"),
    ("a:1 b:3,4 ; a:5,6 b:7,8 = 1 m", "first end: cannot read"),
    ("a:1,2 b:3,4 ; a:5,6 b:7,8x = 1 m", "second end: cannot read"),
    ("1,2,3 ; 1,2,3 = 1 m", "same point"),
])
def test_parse_errors_say_what_is_wrong(text, match):
    with pytest.raises(InvalidInputError, match=match):
        parse_scale_bar(text)


def test_scale_distance_needs_model_points():
    with pytest.raises(InvalidInputError, match="model coordinates"):
        parse_scale_distance("a:1,2 b:3,4 ; 1,2,3 = 1 m")


def test_scale_bar_recovers_metres_in_an_sfm_frame():
    """The metric scene moved by a similarity of scale 0.137: two bars seen in the photos give
    back metres (1/0.137), and the bars agree with each other."""
    metric, ends = metric_scene()
    s0 = 0.137
    rec = sfm_frame(metric, s0, (3.0, -2.0, 7.0))
    texts = [bar_text(metric, ends[0], ends[1]), bar_text(metric, ends[2], ends[3], "100 cm", images=(1, 3))]
    res = estimate_scale(rec, [parse_scale_bar(t) for t in texts])
    assert res.scale == pytest.approx(1 / s0, rel=1e-4)
    assert all(abs(b["residual_m"]) < 1e-3 for b in res.bars)
    assert res.bars[0]["ends"][0]["rays"] == 3 and res.bars[1]["ends"][0]["rays"] == 2
    assert 0 < res.scale_rel_std < 0.01
    out = scale_reconstruction(rec, res)
    c0, c1 = out.images[1].pose.center, out.images[2].pose.center
    assert np.linalg.norm(c1 - c0) == pytest.approx(3.0, rel=1e-4)  # the true 3 m baseline
    assert np.allclose(out.images[1].pose.R, rec.images[1].pose.R)
    assert np.allclose(project(out.points[:20], CAM, out.images[2].pose),
                       project(rec.points[:20], CAM, rec.images[2].pose))
    assert is_scaled(out) and not is_scaled(rec)
    assert out.meta["scale_m_per_unit"] == pytest.approx(1 / s0, rel=1e-4)


def test_pixel_noise_shows_in_the_uncertainty_and_residuals():
    metric, ends = metric_scene()
    rng = np.random.default_rng(2)
    bars = [parse_scale_bar(bar_text(metric, ends[a], ends[b], f"{np.linalg.norm(ends[b] - ends[a]):.6f} m",
                                     rng=rng, noise_px=0.5)) for a, b in ((0, 1), (2, 3), (0, 3))]
    res = estimate_scale(metric, bars, sigma_px=0.5)
    assert res.scale == pytest.approx(1.0, abs=4 * res.scale_rel_std)
    assert 1e-4 < res.scale_rel_std < 0.02
    assert max(abs(b["residual_m"]) for b in res.bars) > 1e-5  # the noise shows in the check


def test_known_model_distance_and_compose_with_upright():
    metric, _ = metric_scene()
    rec = sfm_frame(metric, 2.0)
    p, q = rec.images[1].pose.center, rec.images[3].pose.center  # 6 m apart in truth
    text = f"{p[0]},{p[1]},{p[2]} ; {q[0]},{q[1]},{q[2]} = 6 m"
    res = estimate_scale(rec, [parse_scale_distance(text)])
    assert res.scale == pytest.approx(0.5, rel=1e-9)
    up = estimate_orientation(rec).similarity
    both = compose(up, res.similarity)
    X = rec.points[:5]
    assert np.allclose(both.apply(X), res.similarity.apply(up.apply(X)))
    cloud = Cloud(X)
    assert np.allclose(scale_cloud(cloud, res).xyz, 0.5 * X)


def test_missing_image_and_no_bars():
    metric, ends = metric_scene()
    text = bar_text(metric, ends[0], ends[1]).replace("IMG 2.JPG", "IMG 9.JPG")
    with pytest.raises(InvalidInputError, match="IMG 9.JPG"):
        estimate_scale(metric, [parse_scale_bar(text)])
    with pytest.raises(InvalidInputError, match="no scale bar"):
        estimate_scale(metric, [])


def test_is_scaled_and_length_text():
    metric, _ = metric_scene()
    assert not is_scaled(metric)
    assert is_scaled(Reconstruction(metric.cameras, metric.images, crs="EPSG:32632"))
    assert is_scaled({"georef": {"metrics": {}}}) and is_scaled({"scale": {"scaled": True}})
    assert not is_scaled({}) and not is_scaled(None)
    assert length_text(1.23456, True) == "1.235 m"
    assert length_text(1.23456, False, 2) == "1.23 (unscaled)"
    assert math.isclose(parse_scale_bar("1,2,3 ; 4,5,6 = 2 yd").length_m, 1.8288)



def test_upright_and_scale_in_one_similarity():
    """An SfM-like frame (rotated, shifted, scale 0.2): the combined frame is metric and upright."""
    from scipy.spatial.transform import Rotation

    from workstation.photogrammetry.scale import upright_and_scale

    metric, ends = metric_scene()
    R0 = Rotation.from_euler("xyz", [40, -25, 110], degrees=True).as_matrix()
    moved = transform_reconstruction(metric, Similarity(0.2, R0, np.array([5.0, 1.0, -2.0])))
    rec = Reconstruction(moved.cameras, moved.images, moved.points)
    frame = upright_and_scale(rec, bars=[parse_scale_bar(bar_text(metric, ends[0], ends[1]))])
    out = frame.apply_reconstruction(rec)
    assert np.allclose(out.points, frame.similarity.apply(rec.points))
    assert frame.summary["upright"]["applied"] and frame.summary["scale"]["scaled"]
    assert frame.summary["scale"]["scale_m_per_unit"] == pytest.approx(5.0, rel=1e-4)
    assert is_scaled(frame.summary) and is_scaled(out) and out.meta["upright"] is True
    c = np.stack([im.pose.center for im in out.images.values()])
    assert np.linalg.norm(c[2] - c[0]) == pytest.approx(6.0, rel=1e-4)
    # upright: the cameras stood at 1.6 m, the wall points span 0-4 m in z (after the shift)
    assert np.ptp(c[:, 2]) < 0.01
    assert np.ptp(out.points[:, 2]) == pytest.approx(np.ptp(metric.points[:, 2]), rel=0.02)
    cloud = frame.apply_cloud(Cloud(rec.points))
    assert np.allclose(cloud.xyz, out.points)
    nothing = upright_and_scale(rec, upright=False)
    assert nothing.similarity is None and nothing.summary == {"upright": {"applied": False}, "scale": {"scaled": False}}
