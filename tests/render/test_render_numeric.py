"""Renders checked by numbers first: projections, extents, class colours, determinism."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass, CLASS_COLORS
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Mesh, Pose
from workstation.render import RenderParams, projection_matrix, render, save_gif, save_png, turntable

O = np.array([500_000.0, 4_000_000.0, 100.0])  # far from the origin: float32 handling matters


def rot(rx, ry, rz):
    from scipy.spatial.transform import Rotation

    return Rotation.from_euler("xyz", [rx, ry, rz], degrees=True).as_matrix()


def polygon_area(uv):
    return 0.5 * abs(np.dot(uv[:, 0], np.roll(uv[:, 1], 1)) - np.dot(uv[:, 1], np.roll(uv[:, 0], 1)))


def test_projection_matrix_maps_pixel_centres():
    cam = Camera(100, 80, 90.0, 95.0, 40.0, 30.0)
    m = projection_matrix(cam, 0.1, 100.0)
    X = np.array([0.3, -0.2, 2.0])  # OpenCV camera frame
    u = cam.fx * X[0] / X[2] + cam.cx
    v = cam.fy * X[1] / X[2] + cam.cy
    clip = m @ np.array([X[0], -X[1], -X[2], 1.0])  # eye frame: y up, looking down -z
    ndc = clip[:3] / clip[3]
    assert (ndc[0] + 1) / 2 * cam.width - 0.5 == pytest.approx(u)
    assert (1 - ndc[1]) / 2 * cam.height - 0.5 == pytest.approx(v)
    assert -1 < ndc[2] < 1


def test_pinhole_silhouette_matches_projection():
    """A 2 m x 1 m rectangle seen by an oblique camera with an off-centre principal point."""
    v = O + np.array([[9, 19.5, 0], [11, 19.5, 0], [11, 20.5, 0], [9, 20.5, 0]], float)
    mesh = Mesh(v, np.array([[0, 1, 2], [0, 2, 3]]))
    cam = Camera(320, 240, 300.0, 310.0, 150.3, 130.7)
    R = rot(170, 10, 5)
    C = O + np.array([10.3, 20.2, 6.0])
    img = render(mesh, RenderParams(background="black", color="uniform"), camera=(cam, Pose(R, -R @ C)))
    assert img.shape == (240, 320, 3)
    x = (v - C) @ R.T
    uv = x[:, :2] / x[:, 2:] * [cam.fx, cam.fy] + [cam.cx, cam.cy]
    g = img.max(axis=2).astype(float)
    fg = np.percentile(g[g > 0], 90)
    coverage = np.clip(g / fg, 0, 1)  # anti-aliased edges count by their coverage
    assert coverage.sum() == pytest.approx(polygon_area(uv), rel=0.02)
    ys, xs = np.nonzero(g > 0.5 * fg)
    # pixel centres inside the projected bounding box, within one pixel
    assert xs.min() == pytest.approx(np.ceil(uv[:, 0].min()), abs=1)
    assert xs.max() == pytest.approx(np.floor(uv[:, 0].max()), abs=1)
    assert ys.min() == pytest.approx(np.ceil(uv[:, 1].min()), abs=1)
    assert ys.max() == pytest.approx(np.floor(uv[:, 1].max()), abs=1)
    # centroid of the silhouette at the projected centroid (sub-pixel: principal point convention)
    yy, xx = np.mgrid[0:240, 0:320]
    cx, cy = (coverage * xx).sum() / coverage.sum(), (coverage * yy).sum() / coverage.sum()
    a = uv
    cross = a[:, 0] * np.roll(a[:, 1], -1) - np.roll(a[:, 0], -1) * a[:, 1]
    ex = ((a[:, 0] + np.roll(a[:, 0], -1)) * cross).sum() / (3 * cross.sum())
    ey = ((a[:, 1] + np.roll(a[:, 1], -1)) * cross).sum() / (3 * cross.sum())
    assert cx == pytest.approx(ex, abs=0.3) and cy == pytest.approx(ey, abs=0.3)


def test_reconstruction_view_renders_like_its_camera():
    from workstation.core.products import Image, Reconstruction
    from workstation.render import reconstruction_view

    mesh = Mesh(O + np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]))
    cam = Camera(80, 60, 70.0, 70.0, 40.0, 30.0)
    R = rot(180, 0, 0)  # looking down
    C = O + [0.3, 0.3, 3.0]
    rec = Reconstruction({1: cam}, {7: Image("a.jpg", 1, Pose(R, -R @ C))})
    got = reconstruction_view(rec, 7)
    assert got[0] is cam
    a = render(mesh, RenderParams(color="uniform"), camera=got)
    b = render(mesh, RenderParams(color="uniform"), camera=(cam, Pose(R, -R @ C)))
    assert np.array_equal(a, b) and a.shape == (60, 80, 3)
    assert (a.max(axis=2) < 250).sum() > 50  # the triangle is in view
    with pytest.raises(InvalidInputError):
        reconstruction_view(rec, 8)


def test_object_behind_camera_is_an_error():
    mesh = Mesh(O + np.eye(3), np.array([[0, 1, 2]]))
    cam = Camera(64, 48, 50.0, 50.0, 32.0, 24.0)
    C = O + [0, 0, 10.0]
    R = np.eye(3)  # looking up +Z, away from the triangle
    with pytest.raises(InvalidInputError):
        render(mesh, camera=(cam, Pose(R, -R @ C)))


def two_class_cloud(n_side=120):
    """A 60 m x 40 m grid: ground, with a building block in the north-east quarter."""
    x, y = np.meshgrid(np.linspace(0, 60, int(n_side * 1.5)), np.linspace(0, 40, n_side))
    x, y = x.ravel(), y.ravel()
    bld = (x > 40) & (y > 25)
    z = np.where(bld, 10.0, 0.0)
    cls = np.where(bld, ASPRSClass.BUILDING, ASPRSClass.GROUND).astype(np.uint8)
    return Cloud(O + np.column_stack([x, y, z]), {"classification": cls}, crs="EPSG:32632")


def test_top_view_north_up_extent_and_class_colours():
    c = two_class_cloud()
    w, h = 400, 300
    p = RenderParams(size=(w, h), color="class", view="top", legend=False, scale_bar=False, edl=False, margin=0.05)
    img = render(c, p)
    bg = np.all(img == 255, axis=2)
    ys, xs = np.nonzero(~bg)
    # expected: the 60 x 40 m footprint fits the 400 x 300 frame with 5 % margins on each side
    upp = 40 * 1.1 / h  # 4:3 frame, 3:2 object: height-limited? width: 60*1.1/400 = 0.165 > 0.1467
    upp = max(upp, 60 * 1.1 / w)
    assert (xs.max() - xs.min() + 1) * upp == pytest.approx(60, rel=0.02)
    assert (ys.max() - ys.min() + 1) * upp == pytest.approx(40, rel=0.02)
    # the building (north-east) is at the top right; colours are the palette's, exactly
    u = lambda x: int(round(w / 2 + (x - 30) / upp - 0.5))  # noqa: E731
    v = lambda y: int(round(h / 2 - (y - 20) / upp - 0.5))  # noqa: E731
    assert img[v(33), u(50)].tolist() == list(CLASS_COLORS[ASPRSClass.BUILDING])
    assert img[v(10), u(10)].tolist() == list(CLASS_COLORS[ASPRSClass.GROUND])
    assert img[v(33), u(10)].tolist() == list(CLASS_COLORS[ASPRSClass.GROUND])
    assert img[v(10), u(50)].tolist() == list(CLASS_COLORS[ASPRSClass.GROUND])


def test_top_view_legend_and_scale_bar_are_drawn():
    c = two_class_cloud()
    plain = render(c, RenderParams(size=(400, 300), color="class", view="top", legend=False, scale_bar=False))
    full = render(c, RenderParams(size=(400, 300), color="class", view="top"))
    diff = np.any(plain != full, axis=2)
    assert diff[:60, 250:].any()  # legend top right
    assert diff[270:, :120].any()  # scale bar bottom left
    assert not diff[100:200, 150:250].any()  # the middle is untouched


def test_elevation_colours_follow_the_colour_map():
    from matplotlib import colormaps

    x, y = np.meshgrid(np.linspace(0, 100, 200), np.linspace(0, 50, 100))
    c = Cloud(O + np.column_stack([x.ravel(), y.ravel(), 0.5 * x.ravel()]))
    img = render(c, RenderParams(size=(400, 200), color="elevation", view="top", legend=False, scale_bar=False,
                                 edl=False, clip_percent=0.0, margin=0.0))
    cmap = colormaps["viridis"]
    for frac in (0.1, 0.5, 0.9):
        col = img[100, int(frac * 400)].astype(float)
        exp = np.array(cmap(frac)[:3]) * 255
        assert np.abs(col - exp).max() < 12


def test_renders_are_deterministic_and_edl_shades():
    c = two_class_cloud(60)
    p = RenderParams(size=(200, 150), color="class", view="iso", edl=True)
    a, b = render(c, p), render(c, p)
    assert np.array_equal(a, b)
    flat = render(c, RenderParams(size=(200, 150), color="class", view="iso"))
    fg = ~np.all(flat == 255, axis=2)
    assert a[fg].mean() < flat[fg].mean() - 1  # eye-dome lighting darkens depth edges


def test_color_errors_and_params():
    c = two_class_cloud(20)
    with pytest.raises(InvalidInputError):
        render(c, RenderParams(color="rgb"))
    with pytest.raises(InvalidInputError):
        render(c, RenderParams(color="nope"))
    with pytest.raises(InvalidInputError):
        RenderParams(view="side")
    with pytest.raises(InvalidInputError):
        render(Cloud(np.zeros((0, 3))))


def test_turntable_frames_and_gif(tmp_path):
    c = two_class_cloud(40)
    frames = turntable(c, RenderParams(size=(120, 90), color="class", legend=False), frames=4)
    assert len(frames) == 4 and frames[0].shape == (90, 120, 3)
    assert not np.array_equal(frames[0], frames[1])
    save_gif(frames, tmp_path / "t.gif")
    from PIL import Image

    with Image.open(tmp_path / "t.gif") as im:
        assert im.n_frames == 4
    save_png(frames[0], tmp_path / "f.png")
    assert np.array_equal(np.asarray(Image.open(tmp_path / "f.png").convert("RGB")), frames[0])


def test_render_leaves_pyvista_global_off_screen_alone():
    """Rendering uses its own off-screen Plotter; pyvista.OFF_SCREEN (a notebook's setting) stays."""
    pv = pytest.importorskip("pyvista")
    before = pv.OFF_SCREEN
    c = Cloud(O + np.random.default_rng(0).uniform(0, 10, (200, 3)))
    img = render(c, RenderParams(size=(64, 48)))
    assert img.shape == (48, 64, 3)
    assert pv.OFF_SCREEN == before
