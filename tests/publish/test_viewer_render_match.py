"""The `ws publish` viewer's picture matches `ws render` of the same cloud from the same camera
(issue 25), in headless Chromium (skipped without Chromium).

The viewer is opened at a camera given in its URL (``#view=`` position and target, ``&fov=``
vertical field of view) in a W x H window; `ws render` renders the cloud through the same
pinhole camera (a ``cameras.json`` holding it, ``--reconstruction``/``--camera``). The two
renderers draw points differently: `ws render` every point at a fixed size, the viewer the
octree nodes its level of detail picks, each point as large as its node's spacing (up to 4x
the point size), so their silhouettes (the pixels that are not background) differ by a few
pixels along every edge. They are compared with that tolerance:

- cover: the share of each silhouette's pixels within TOL_PX of the other silhouette (the
  smaller of the two shares) must be at least MIN_COVER;
- the silhouettes' bounding boxes (top, left, bottom, right) must agree within MAX_BOX_PX.

Each view holds the whole cloud inside the frame (checked: a silhouette touching the border
hides shifts). The thresholds were chosen on the roof scene (test_publish_site's ``_scene``),
seen from five cameras: cover 0.974-0.999 and boxes within 3 px where the cameras match;
cover 0.80-0.94 or boxes 7-31 px apart for a camera aimed 1.7° aside or with a 10 % wider
field of view. They were then checked on the hill-and-trees terrain below (cover 0.999-1.0,
boxes within 2 px; wrong cameras 0.84-0.94 and 18-29 px) and on the real TreeLS pine cloud
(0.993-0.995, 3 px; wrong cameras 0.37-0.84 and 23-31 px). Each test also renders those two
wrong cameras and requires the comparison to reject them.

A mesh published as 3D Tiles is compared the same way with `ws render` of the mesh file.
"""

from __future__ import annotations

import base64
import io
import math
import shutil
import sys
import time
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from test_publish_site import BG, CRS, EAST, X0, Y0, Z0, Chromium, _click, _frame, _scene, mesh_site  # noqa: E402, F401

W, H = 640, 480
TOL_PX = 3  # a viewer point's radius exceeds a `ws render` point's by up to 3 px (8 px vs 2 px)
MIN_COVER = 0.96
MAX_BOX_PX = 5
RENDER_POINT_PX = 2


def _terrain(n: int = 60_000, seed: int = 5):
    """A 120 m square of ground (class 2) over a Gaussian hill on a 5 % slope, with three
    conical trees (class 5) of 12-18 m: a cloud without colour, of another shape than the
    scene the thresholds were chosen on."""
    from workstation.core.cloud import Cloud

    rng = np.random.default_rng(seed)

    def ground(x, y):
        return 8 * np.exp(-((x - 40) ** 2 + (y - 70) ** 2) / 600) + 0.05 * x

    xy = rng.uniform(0, 120, (n, 2))
    parts = [np.column_stack([xy, ground(xy[:, 0], xy[:, 1])])]
    for cx, cy, h in [(80, 30, 15), (95, 80, 12), (30, 20, 18)]:
        t, a, s = rng.uniform(0, 1, (3, 4000))
        r = (1 - t) * h / 3 * np.sqrt(s)
        parts.append(np.column_stack([cx + r * np.cos(2 * np.pi * a), cy + r * np.sin(2 * np.pi * a),
                                      ground(cx, cy) + 2 + t * h]))
    xyz = np.vstack(parts) + [X0, Y0, Z0]
    cls = np.r_[np.full(n, 2), np.full(len(xyz) - n, 5)].astype(np.uint8)
    return Cloud(np.round(xyz, 3), {"classification": cls, "intensity": np.full(len(xyz), 500, np.uint16)}, crs=CRS)


def _cloud(name: str, request):
    """The roof scene, the terrain, or the real TreeLS pine (74 k points of one tree)."""
    if name == "pine":
        from workstation.io import read_cloud

        return read_cloud(request.getfixturevalue("shared_data") / "lidar" / "TreeLS_pine.laz")
    return {"scene": _scene, "terrain": _terrain}[name]()


# ---------------------------------------------------------------------------------- cameras
def _look_at(C, T):
    """The Pose (world -> camera, OpenCV axes) of a camera at C looking at T, z up (as the
    viewer's orbit camera: image x to the right of the view direction, no roll)."""
    from workstation.core.products import Pose

    C, T = np.asarray(C, float), np.asarray(T, float)
    fwd = (T - C) / np.linalg.norm(T - C)
    right = np.cross(fwd, [0.0, 0.0, 1.0])
    right /= np.linalg.norm(right)
    R = np.vstack([right, np.cross(fwd, right), fwd])
    return Pose(R, -R @ C)


def _views(xyz):
    """Two cameras (position, target, vertical fov in degrees) that hold the whole cloud in the
    frame: from the south 35° up, and from the north-east 20° up with a narrower lens."""
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    c, r = (lo + hi) / 2, float(np.linalg.norm(hi - lo)) / 2
    out = []
    for az, el, fov in ((-90.0, 35.0, 40.0), (35.0, 20.0, 30.0)):
        half = math.atan(math.tan(math.radians(fov) / 2) * min(1.0, W / H))
        d = 1.1 * r / math.sin(half)
        a, e = math.radians(az), math.radians(el)
        out.append((c + d * np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)]), c, fov))
    return out


def _wrong_cameras(C, T, fov):
    """Cameras that must not match: aimed 3 % of the distance aside (1.7°), 10 % wider lens."""
    side = np.cross(T - C, [0.0, 0.0, 1.0])
    side *= 0.03 * np.linalg.norm(T - C) / np.linalg.norm(side)
    return {"aside": (C, T + side, fov), "wider": (C, T, fov * 1.1)}


def _ws_render(cloud_path: Path, cams: dict, folder: Path) -> dict:
    """`ws render` of the cloud through each named camera (position, target, fov): a
    cameras.json of pinhole cameras of W x H pixels, rendered by the CLI."""
    from PIL import Image

    from workstation.cli.main import main
    from workstation.core.products import Camera, Image as Shot, Reconstruction
    from workstation.io.reconstruction import write_reconstruction_json

    cameras, images = {}, {}
    for i, (name, (C, T, fov)) in enumerate(cams.items(), start=1):
        f = (H / 2) / math.tan(math.radians(fov) / 2)
        cameras[i] = Camera(W, H, f, f, (W - 1) / 2, (H - 1) / 2)
        images[i] = Shot(f"{name}.png", i, _look_at(C, T))
    rec_path = folder / "cameras.json"
    write_reconstruction_json(Reconstruction(cameras, images), rec_path)
    out = {}
    for name in cams:
        png = folder / f"render_{name}.png"
        assert main(["render", str(cloud_path), "-o", str(png), "--reconstruction", str(rec_path), "--camera",
                     f"{name}.png", "--background", "#{:02x}{:02x}{:02x}".format(*BG), "--no-legend",
                     "--point-size", str(RENDER_POINT_PX)]) == 0
        out[name] = np.asarray(Image.open(png).convert("RGB"))
    return out


# ---------------------------------------------------------------------------------- comparison
def silhouette(img: np.ndarray, tol: int = 16) -> np.ndarray:
    """Pixels that differ from the background colour by more than ``tol`` in some channel."""
    return np.abs(img.astype(int) - BG).max(axis=-1) > tol


def agreement(a: np.ndarray, b: np.ndarray) -> tuple[float, int]:
    """(cover, box): the smaller of the shares of ``a``'s pixels within TOL_PX of ``b`` and of
    ``b``'s within TOL_PX of ``a``; the largest difference of their bounding boxes' edges, px."""
    from scipy import ndimage

    near_a, near_b = ndimage.distance_transform_edt(~a) <= TOL_PX, ndimage.distance_transform_edt(~b) <= TOL_PX
    cover = min(float(near_b[a].mean()), float(near_a[b].mean()))
    box = lambda m: np.r_[np.argwhere(m).min(axis=0), np.argwhere(m).max(axis=0)]  # noqa: E731
    return cover, int(np.abs(box(a) - box(b)).max())


def matches(a, b) -> bool:
    cover, box = agreement(a, b)
    return cover >= MIN_COVER and box <= MAX_BOX_PX


def test_agreement_tolerates_thicker_points_but_not_a_shift():
    a = np.zeros((100, 100), bool)
    a[20:60, 30:70] = True
    thick = np.zeros_like(a)
    thick[18:62, 28:72] = True  # the same square drawn with points 2 px larger
    assert agreement(a, thick) == (1.0, 2) and matches(a, thick)
    shifted = np.roll(a, 8, axis=1)
    assert agreement(a, shifted)[1] == 8 and not matches(a, shifted)


# ---------------------------------------------------------------------------------- the viewer
@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if exe is None:
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    b = Chromium(exe, tmp_path_factory.mktemp("chrome-profile"), size=(W, H))
    yield b
    b.close()


def _open(browser, server, C, T, fov) -> None:
    """Open the viewer at the camera (C, T, fov) and wait until it is ready, with no error
    (the server's request log starts afresh)."""
    view = ",".join(f"{v:.4f}" for v in [*C, *T])
    url = f"http://127.0.0.1:{server.server_address[1]}/index.html?t={time.monotonic_ns()}#view={view}&fov={fov}"
    server.requests.clear()
    browser.errors()
    browser.call("Page.navigate", session=True, url=url)
    state, _ = browser.wait_state(url, 30.0)
    errors = browser.errors()
    assert state == "ready" and not errors, (state, errors)


def _canvas(browser) -> np.ndarray:
    """The viewer's WebGL canvas (W x H, without the panels over it), once redrawn."""
    from PIL import Image

    _frame(browser)
    png = browser.eval("document.getElementById('view').toDataURL('image/png')")
    img = np.asarray(Image.open(io.BytesIO(base64.b64decode(png.split(",", 1)[1]))).convert("RGB"))
    assert img.shape == (H, W, 3)
    return img


def _check_framed(*masks) -> None:
    """Each silhouette lies inside the frame (none of the border pixels) and is not a speck."""
    for m in masks:
        assert not (m[0].any() or m[-1].any() or m[:, 0].any() or m[:, -1].any())
        assert m.mean() > 0.01


@pytest.mark.parametrize("name", ["scene", "terrain", pytest.param("pine", marks=pytest.mark.realdata)])
def test_viewer_matches_ws_render_of_the_same_view(name, browser, tmp_path, request):
    from workstation.io import write_cloud
    from workstation.publish.copc import CopcParams
    from workstation.publish.site import PublishParams, publish_site, serve_in_thread

    cloud = _cloud(name, request)
    src = tmp_path / "cloud.laz"
    write_cloud(cloud, src)
    # small nodes: several octree levels, so the viewer's level of detail is part of the check
    publish_site([src], tmp_path / "site", params=PublishParams(copc=CopcParams(max_points=2000, cells=16)))
    srv = serve_in_thread(tmp_path / "site")
    try:
        for k, (C, T, fov) in enumerate(_views(cloud.xyz)):
            _open(browser, srv, C, T, fov)
            seen = silhouette(_canvas(browser))
            folder = tmp_path / f"view{k}"
            folder.mkdir()
            renders = _ws_render(src, {"same": (C, T, fov), **_wrong_cameras(C, T, fov)}, folder)
            drawn = silhouette(renders["same"])
            _check_framed(seen, drawn)
            assert matches(seen, drawn), (name, k, agreement(seen, drawn))
            for wrong in ("aside", "wider"):
                assert not matches(seen, silhouette(renders[wrong])), (name, k, wrong)
    finally:
        srv.shutdown()


def test_viewer_draws_the_mesh_where_ws_render_does(browser, mesh_site, tmp_path):
    """The box mesh of ``mesh_site`` (3D Tiles, placed by site.json's matrix): its tile is not
    fetched while the box is out of view; in view, with the points hidden, the viewer's picture
    matches `ws render` of the PLY; a distance measured by two clicks on its roof is the
    distance between the CRS points under them; its layer box hides it."""
    from workstation.publish.site import serve_in_thread

    work, site = mesh_site
    e = X0 + EAST
    srv = serve_in_thread(site)
    try:
        _open(browser, srv, (e + 85, Y0 + 15, Z0 + 10), (e + 98, Y0 + 2, Z0), 55)  # the far corner
        assert any(r[0].endswith("/box/tileset.json") for r in srv.requests)
        assert not any(r[0].endswith(".glb") for r in srv.requests)
        centre = np.array([e + 20, Y0 + 70, Z0 + 4])
        C = centre + [-45.0, -60.0, 40.0]
        _open(browser, srv, C, centre, 40)
        assert any(r[0].endswith(".glb") for r in srv.requests)
        browser.eval("document.querySelectorAll('#classes input').forEach(b => { if (b.checked) b.click(); })")
        seen = silhouette(_canvas(browser))
        drawn = silhouette(_ws_render(work / "box.ply", {"same": (C, centre, 40)}, tmp_path)["same"])
        _check_framed(seen, drawn)
        assert matches(seen, drawn), agreement(seen, drawn)
        pose, f = _look_at(C, centre), (H / 2) / math.tan(math.radians(40) / 2)
        roof = np.array([[e + 20, Y0 + 70, Z0 + 8], [e + 13, Y0 + 63, Z0 + 8]])  # its middle, 7 m from two sides
        cam = roof @ pose.R.T + pose.t
        px = f * cam[:, :2] / cam[:, 2:] + [(W - 1) / 2, (H - 1) / 2] + 0.5  # CSS pixels: corners at integers
        browser.eval("document.getElementById('measure-distance').click()")
        _click(browser, px[0])
        _click(browser, px[1])
        m = browser.eval("wsViewer.lastMeasure")
        assert m["kind"] == "distance" and m["dz"] == pytest.approx(0, abs=1e-3)  # both on the flat roof
        assert m["value"] == pytest.approx(7 * math.sqrt(2), abs=0.3)  # 1 px is 0.13 m there
        browser.eval("document.getElementById('measure-distance').click()")  # clears the marks
        browser.eval("document.querySelector('#meshes input[data-mesh=\"box\"]').click()")
        assert not silhouette(_canvas(browser)).any()
        assert not browser.errors()
    finally:
        srv.shutdown()
