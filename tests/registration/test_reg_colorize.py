import json

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import StageError
from workstation.core.products import Camera, Image, Pose, Reconstruction
from workstation.registration.colorize import ColorizeParams, colorize, project


def _grid(x0, x1, y0, y1, z, step):
    x, y = np.meshgrid(np.arange(x0, x1 + 1e-9, step), np.arange(y0, y1 + 1e-9, step))
    return np.column_stack([x.ravel(), y.ravel(), np.full(x.size, z)])


def _scene():
    """A red wall (z = 5) partly in front of a green/blue striped wall (z = 8), camera at z = 0."""
    front = _grid(-1.0, 1.0, -1.0, 1.0, 5.0, 0.02)
    back = _grid(-3.0, 3.0, -2.0, 2.0, 8.0, 0.02)
    xyz = np.vstack([front, back])
    truth = np.zeros((xyz.shape[0], 3))
    truth[: len(front)] = [220, 30, 30]
    stripe = (np.floor(back[:, 0] / 0.5) % 2).astype(bool)
    truth[len(front):] = np.where(stripe[:, None], [30, 200, 40], [40, 40, 210])
    is_front = np.arange(xyz.shape[0]) < len(front)
    return xyz, truth, is_front


def _render(xyz, colors, cam, pose):
    """A synthetic photo by projection (painter's algorithm: far to near, 2x2-pixel splats)."""
    u, v, z = project(xyz, cam, pose)
    img = np.zeros((cam.height, cam.width, 3), dtype=np.uint8)
    ui = np.concatenate([np.floor(u).astype(int) + dx for dx in (0, 1) for dy in (0, 1)])
    vi = np.concatenate([np.floor(v).astype(int) + dy for dx in (0, 1) for dy in (0, 1)])
    zz = np.tile(z, 4)
    cc = np.tile(colors, (4, 1))
    keep = (z.size > 0) & (ui >= 0) & (ui < cam.width) & (vi >= 0) & (vi < cam.height) & (zz > 0)
    order = np.flatnonzero(keep)[np.argsort(-zz[keep], kind="stable")]  # far first, near last wins
    img[vi[order], ui[order]] = cc[order]
    return img


def test_occluded_points_are_not_painted_and_visible_ones_get_their_colour():
    xyz, truth, is_front = _scene()
    cam = Camera(640, 480, 500.0, 500.0, 319.5, 239.5, dist=(-0.05, 0.01, 0.0, 0.0, 0.0))
    pose = Pose(np.eye(3), np.zeros(3))  # camera at the origin looking along +z
    img = _render(xyz, truth.astype(np.uint8), cam, pose)
    rec = Reconstruction({1: cam}, {1: Image("a.png", 1, pose)})
    prior = np.full((xyz.shape[0], 3), 7, dtype=np.uint16)
    out = colorize(Cloud(xyz, {"rgb": prior}), rec, ColorizeParams(point_spacing=0.02), images={1: img})
    painted = out.attrs["colorized"].astype(bool)
    # points of the back wall hidden behind the front wall (|x|,|y| < 1.6 seen from z = 0)
    hidden = ~is_front & (np.abs(xyz[:, 0]) < 1.55) & (np.abs(xyz[:, 1]) < 1.55)
    assert hidden.sum() > 1000
    assert not painted[hidden].any()
    assert np.all(out.attrs["rgb"][hidden] == 7)  # unseen points keep their colour
    # the visible parts are painted with the right colour (away from stripe edges)
    vis = is_front | (~is_front & ((np.abs(xyz[:, 0]) > 1.7) | (np.abs(xyz[:, 1]) > 1.7)))
    inner = vis & (np.abs((xyz[:, 0] / 0.5) - np.round(xyz[:, 0] / 0.5)) > 0.15)
    on_image = painted & inner
    assert on_image.sum() > 0.8 * (inner & (np.abs(xyz[:, 0]) < 2.4)).sum() * 0.5
    err = np.abs(out.attrs["rgb"][on_image] / 257.0 - truth[on_image]).mean(axis=1)
    assert err.mean() < 10.0
    assert input_unchanged(prior)


def input_unchanged(prior):
    return np.all(prior == 7)


def test_depth_maps_replace_the_zbuffer():
    xyz, truth, is_front = _scene()
    cam = Camera(320, 240, 250.0, 250.0, 159.5, 119.5)
    pose = Pose(np.eye(3), np.zeros(3))
    img = _render(xyz, truth.astype(np.uint8), cam, pose)
    depth = np.full((240, 320), 8.0)
    depth[119 - 51:119 + 52, 159 - 51:159 + 52] = 5.0  # the front wall spans +-50 px around the centre
    rec = Reconstruction({1: cam}, {1: Image("a.png", 1, pose)})
    out = colorize(Cloud(xyz), rec, ColorizeParams(point_spacing=0.02), images={1: img}, depth_maps={1: depth})
    hidden = ~is_front & (np.abs(xyz[:, 0]) < 1.5) & (np.abs(xyz[:, 1]) < 1.5)
    assert not out.attrs["colorized"][hidden].any()
    assert out.attrs["colorized"][is_front].mean() > 0.9


def test_best_views_are_blended_and_nothing_seen_raises():
    xyz = _grid(-1, 1, -1, 1, 5.0, 0.05)
    cam = Camera(200, 200, 150.0, 150.0, 99.5, 99.5)
    p1 = Pose(np.eye(3), np.zeros(3))
    p2 = Pose(np.eye(3), np.array([0.0, 0.0, 1.0]))  # centre at z = -1: one metre further back
    red = np.zeros((200, 200, 3), np.uint8)
    red[..., 0] = 200
    blue = np.zeros((200, 200, 3), np.uint8)
    blue[..., 2] = 200
    rec = Reconstruction({1: cam}, {1: Image("r", 1, p1), 2: Image("b", 1, p2)})
    out = colorize(Cloud(xyz), rec, ColorizeParams(point_spacing=0.05), images={1: red, 2: blue})
    c = out.attrs["rgb"][out.attrs["color_views"] == 2] / 257.0
    assert len(c) > 0
    # the nearer view (distance 5 vs 6 m) weighs (6/5)^2 = 1.44 times more
    assert np.allclose(c[:, 0] / (c[:, 0] + c[:, 2]), 1.44 / 2.44, atol=0.02)
    away = Reconstruction({1: cam}, {1: Image("r", 1, Pose(np.diag([1.0, -1.0, -1.0]), np.zeros(3)))})
    with pytest.raises(StageError):
        colorize(Cloud(xyz), away, images={1: red})


def test_ws_colorize_reads_a_colmap_text_model(tmp_path, capsys):
    import cv2

    from workstation.cli.main import main
    from workstation.io import read_cloud, write_cloud

    xyz, truth, is_front = _scene()
    cam = Camera(320, 240, 250.0, 250.0, 159.5, 119.5, dist=(-0.05, 0.01, 0.0, 0.0, 0.0))
    # camera 0.5 m to the right of the origin, looking along +z: x_cam = X + t with t = (-0.5, 0, 0)
    pose = Pose(np.eye(3), np.array([-0.5, 0.0, 0.0]))
    img = _render(xyz, truth.astype(np.uint8), cam, pose)
    model = tmp_path / "work" / "sparse" / "0"
    model.mkdir(parents=True)
    (model / "cameras.txt").write_text("1 OPENCV 320 240 250 250 159.5 119.5 -0.05 0.01 0 0\n")
    (model / "images.txt").write_text("1 1 0 0 0 -0.5 0 0 1 view.png\n\n")
    (model / "points3D.txt").write_text("")
    (tmp_path / "work" / "images").mkdir()
    cv2.imwrite(str(tmp_path / "work" / "images" / "view.png"), img[:, :, ::-1])
    write_cloud(Cloud(xyz), tmp_path / "walls.laz")
    rc = main(["colorize", str(tmp_path / "walls.laz"), "--reconstruction", str(tmp_path / "work"),
               "-o", str(tmp_path / "out.laz"), "--json"])
    assert rc == 0
    out = read_cloud(tmp_path / "out.laz")
    painted = out.attrs["colorized"].astype(bool)
    # seen from x = 0.5, the front wall (|x| <= 1 at 5 m) hides back-wall x in (-1.1, 2.1) roughly
    hidden = ~is_front & (np.abs((xyz[:, 0] - 0.5) * 5.0 / 8.0) < 0.45) & (np.abs(xyz[:, 1] * 5.0 / 8.0) < 0.95)
    assert hidden.sum() > 500 and not painted[hidden].any()
    front_seen = is_front & painted
    assert front_seen.sum() > 0.9 * is_front.sum()
    err = np.abs(out.attrs["rgb"][front_seen] / 257.0 - truth[front_seen]).mean()
    assert err < 10.0
    assert json.loads(capsys.readouterr().out)["painted"] == int(painted.sum())


def _plane_depth(cam, u, v, n, d):
    """Depth of the plane n . X = d along the pixel rays (u, v) of a pinhole camera at the origin."""
    ray = np.stack([(u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, np.ones_like(u)], axis=-1)
    return d / (ray @ n)


def test_depth_map_test_is_safe_at_a_silhouette_edge_and_exact_on_a_slanted_plane():
    from workstation.registration.colorize import depth_map_visible

    cam = Camera(200, 100, 100.0, 100.0, 99.5, 49.5)
    uu, vv = np.meshgrid(np.arange(200.0), np.arange(100.0))
    depth = np.full((100, 200), 8.0)
    depth[:, :101] = 5.0  # a nearer object covering u < 100.6: pixel centres 0..100 see it, 101 sees past it
    u = np.array([100.55, 100.9, 103.5, 98.5, 50.0])
    v = np.full(5, 40.3)
    z = np.array([8.0, 8.0, 8.0, 5.0, 8.0])  # hidden, visible, visible, front, hidden
    vis, *_ = depth_map_visible(depth, u, v, z, np.full(5, 0.02), cam)
    # 100.55 and 100.9 are both next to the edge: the first is hidden, the second cannot be told
    # apart at pixel resolution and must not be painted either
    assert vis.tolist() == [False, False, True, True, False]
    nearest = depth[np.round(v).astype(int), np.round(u).astype(int)]
    assert z[0] <= nearest[0] + 0.02  # what nearest-pixel sampling would have painted
    # a plane seen at a grazing angle (depth changes by up to 0.3 m per pixel row): exact
    n, d = np.array([0.0, 1.0, 0.12]), 1.5  # ground 1.5 m below the camera, rising slowly
    n = n / np.linalg.norm(n)
    dm = _plane_depth(cam, uu, vv, n, d)
    rng = np.random.default_rng(0)
    pu, pv = rng.uniform(2, 197, 500), rng.uniform(60, 97, 500)
    pz = _plane_depth(cam, pu, pv, n, d)
    assert np.ptp(dm[60:, 100]) > 4.0 and np.abs(np.diff(dm[60:, 100])).max() > 0.25
    vis, *_ = depth_map_visible(dm, pu, pv, pz, np.full(500, 0.01), cam)
    assert vis.all()
    vis, *_ = depth_map_visible(dm, pu, pv, pz + 0.05, np.full(500, 0.01), cam)  # 5 cm behind the plane
    assert not vis.any()
    # a footprint-minimum depth map of the same plane: biased by half a pixel, corrected
    sub = np.array([-1 / 3, 0.0, 1 / 3])
    dmin = np.min([_plane_depth(cam, uu + a, vv + b, n, d) for a in sub for b in sub], axis=0)
    vis, *_ = depth_map_visible(dmin, pu, pv, pz, np.full(500, 0.01), cam, footprint_px=1 / 3)
    assert vis.mean() > 0.99
    vis, *_ = depth_map_visible(dmin, pu, pv, pz, np.full(500, 0.01), cam)
    assert vis.mean() < 0.5  # uncorrected, the bias of up to 0.2 m hides most of them


def test_a_cell_across_an_edge_gives_no_mixed_colour():
    # a red wall at 5 m covering u < 100.6 in front of a blue one at 8 m; points of both near the edge
    cam = Camera(200, 100, 100.0, 100.0, 99.5, 49.5)
    depth = np.full((100, 200), 8.0)
    depth[:, :101] = 5.0
    img = np.zeros((100, 200, 3), np.uint8)
    img[:, :101] = [200, 0, 0]
    img[:, 101:] = [0, 0, 200]
    u = np.linspace(90.0, 110.0, 81)
    v = np.full(u.size, 40.0)
    z = np.where(u < 100.6, 5.0, 8.0)
    xyz = np.column_stack([(u - cam.cx) / cam.fx * z, (v - cam.cy) / cam.fy * z, z])
    rec = Reconstruction({1: cam}, {1: Image("a", 1, Pose(np.eye(3), np.zeros(3)))})
    out = colorize(Cloud(xyz), rec, ColorizeParams(depth_tolerance=0.02, depth_tolerance_rel=0.0),
                   images={1: img}, depth_maps={1: depth})
    painted = out.attrs["colorized"].astype(bool)
    rgb = out.attrs["rgb"] / 257.0
    red = z == 5.0
    assert painted[red].sum() > 30 and painted[~red].sum() > 30
    assert np.all(rgb[painted & red] == [200, 0, 0]) and np.all(rgb[painted & ~red] == [0, 0, 200])
    assert not painted[(u > 100.0) & (u < 102.0)].any()  # the cells touching the edge


def test_ws_colorize_with_the_depth_maps_of_a_dense_workspace(tmp_path, capsys):
    import cv2

    from workstation.cli.main import main
    from workstation.io import read_cloud, write_cloud
    from workstation.photogrammetry.dense import write_array

    xyz, truth, is_front = _scene()
    cam = Camera(320, 240, 250.0, 250.0, 159.5, 119.5)
    pose = Pose(np.eye(3), np.zeros(3))
    img = _render(xyz, truth.astype(np.uint8), cam, pose)
    dense = tmp_path / "work" / "dense"
    (dense / "sparse").mkdir(parents=True)
    (dense / "sparse" / "cameras.txt").write_text("1 PINHOLE 320 240 250 250 159.5 119.5\n")
    (dense / "sparse" / "images.txt").write_text("1 1 0 0 0 0 0 0 1 view.png\n\n")
    (dense / "sparse" / "points3D.txt").write_text("")
    (dense / "images").mkdir()
    cv2.imwrite(str(dense / "images" / "view.png"), img[:, :, ::-1])
    depth = np.full((240, 320), 8.0, np.float32)
    depth[119 - 51:119 + 52, 159 - 51:159 + 52] = 5.0  # the front wall: +-50 px around the centre
    depth[:, :20] = 0.0  # no depth: not used
    (dense / "stereo" / "depth_maps").mkdir(parents=True)
    write_array(depth, dense / "stereo" / "depth_maps" / "view.png.geometric.bin")
    write_cloud(Cloud(xyz), tmp_path / "walls.laz")
    rc = main(["colorize", str(tmp_path / "walls.laz"), "--reconstruction", str(tmp_path / "work"), "--depth-maps",
               "--depth-tolerance", "0.05", "-o", str(tmp_path / "out.laz"), "--json"])
    assert rc == 0
    out = read_cloud(tmp_path / "out.laz")
    painted = out.attrs["colorized"].astype(bool)
    hidden = ~is_front & (np.abs(xyz[:, 0]) < 1.5) & (np.abs(xyz[:, 1]) < 1.5)
    assert hidden.sum() > 1000 and not painted[hidden].any()
    u = project(xyz, cam, pose)[0]
    assert not painted[u < 20.0].any()  # cells with a corner where the depth map has no depth
    inner_front = is_front & (np.abs(xyz[:, 0]) < 0.9) & (np.abs(xyz[:, 1]) < 0.9)
    assert painted[inner_front].all()
    assert json.loads(capsys.readouterr().out)["painted"] == int(painted.sum())
