"""`ws publish`: the static site (site.json, COPC clouds, raster previews, camera frusta), the
Range-capable server, and the viewer in headless Chromium (skipped without Chromium)."""

from __future__ import annotations

import base64
import io
import json
import os
import queue
import shutil
import subprocess
import threading
import time
import urllib.request
from pathlib import Path

import numpy as np
import pytest

from workstation.cli.main import main

CRS = "EPSG:32632"
X0, Y0, Z0 = 500_000.0, 4_000_000.0, 100.0
ROOF = 10.0  # height of the flat roof above the flat ground, metres
BG = (0x20, 0x24, 0x2A)  # the viewer's background colour


def _scene(n_ground: int = 40_000, seed: int = 3):
    """Flat ground (class 2) over 100 m x 100 m at Z0 and a 30 m x 30 m flat roof (class 6) at
    Z0 + ROOF in the middle; ground red, roof blue (16-bit RGB); intensity 1000 / 3000."""
    from workstation.core.cloud import Cloud

    rng = np.random.default_rng(seed)
    g = rng.uniform(0, 100, (n_ground, 2))
    g = g[~((np.abs(g[:, 0] - 50) < 15) & (np.abs(g[:, 1] - 50) < 15))]
    r = rng.uniform(35, 65, (n_ground * 9 // 100, 2))
    xy = np.vstack([g, r]) + [X0, Y0]
    roof = np.r_[np.zeros(len(g), bool), np.ones(len(r), bool)]
    z = Z0 + np.where(roof, ROOF, 0.0)
    rgb = np.where(roof[:, None], [[0, 0, 60000]], [[60000, 0, 0]]).astype(np.uint16)
    attrs = {"classification": np.where(roof, 6, 2).astype(np.uint8), "rgb": rgb,
             "intensity": np.where(roof, 3000, 1000).astype(np.uint16)}
    return Cloud(np.round(np.column_stack([xy, z]), 3), attrs, crs=CRS)


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    """A work folder: the scene as LAS, a DTM GeoTIFF and a cameras.json of two cameras."""
    from workstation.core.products import Camera, Image, Pose, Raster, Reconstruction
    from workstation.io import write_cloud
    from workstation.io.geotiff import write_raster
    from workstation.io.reconstruction import write_reconstruction_json

    d = tmp_path_factory.mktemp("work")
    write_cloud(_scene(), d / "cloud.las")
    zz = Z0 + np.add.outer(np.linspace(2, 0, 50), np.linspace(0, 1, 100))  # 100 x 50 cells of 1 m
    write_raster(Raster(zz.astype(np.float32), (1.0, 0, X0, 0, -1.0, Y0 + 50), CRS, -9999.0), d / "dtm.tif")
    down = np.diag([1.0, -1.0, -1.0])  # looking straight down, image x east
    imgs = {i: Image(f"im{i}.png", 1, Pose(down, -down @ np.array([X0 + 30 + 20 * i, Y0 + 50, Z0 + 60]))) for i in (1, 2)}
    write_reconstruction_json(Reconstruction({1: Camera(400, 300, 300.0, 300.0, 199.5, 149.5)}, imgs, crs=CRS),
                              d / "cameras.json")
    return d


#: A small octree (nodes of at most 2,000 points, 16 cells a side) so the scene has 5 levels.
SMALL_NODES = dict(max_points=2000, cells=16)


@pytest.fixture(scope="module")
def site(work, tmp_path_factory):
    from workstation.publish.copc import CopcParams
    from workstation.publish.site import PublishParams, publish_site

    out = tmp_path_factory.mktemp("pub") / "site"
    publish_site([work], out, params=PublishParams(copc=CopcParams(**SMALL_NODES)))
    return out


def test_ws_publish_cli_json(work, tmp_path, capsys):
    out = tmp_path / "site"
    assert main(["publish", str(work), "-o", str(out), "--title", "Demo", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["index"] == str(out / "index.html") and doc["cameras"] == 2
    assert doc["clouds"][0]["points"] == doc["points"] > 35_000 and doc["rasters"][0]["kind"] == "hillshade"
    assert json.loads((out / "site.json").read_text())["title"] == "Demo"
    assert main(["publish", str(work), "--serve"]) == 2  # neither -o nor a published site


# ---------------------------------------------------------------------------------- the site
def test_site_json_lists_the_cloud_classes_raster_and_cameras(site):
    import laspy

    doc = json.loads((site / "site.json").read_text())
    n_roof = 40_000 * 9 // 100
    (cloud,) = doc["clouds"]
    assert cloud["url"] == "clouds/cloud.copc.laz" and cloud["rgb_bits"] == 16
    with laspy.CopcReader.open(str(site / cloud["url"])) as r:  # a valid COPC file with every point
        pts = r.query()
    assert len(pts) == cloud["points"] and cloud["points"] > 35_000
    assert {c["code"]: c["count"] for c in doc["classes"]} == {2: cloud["points"] - n_roof, 6: n_roof}
    assert doc["classes"][1]["name"] == "Building" and doc["classes"][1]["color"] == [220, 60, 50]
    assert doc["intensity_range"] == [1000.0, 3000.0]
    assert doc["bounds"][2] == pytest.approx(Z0) and doc["bounds"][5] == pytest.approx(Z0 + ROOF)
    assert doc["units"] == "m" and "32632" in (doc["crs"] or "")
    (ras,) = doc["rasters"]
    assert ras["kind"] == "hillshade" and ras["bounds"] == pytest.approx([X0, Y0, X0 + 100, Y0 + 50])
    from PIL import Image

    im = np.asarray(Image.open(site / ras["url"]))
    assert im.shape == (50, 100, 4) and (im[..., 3] == 255).all() and im[..., 0].std() < 5  # a plane: even shade
    import rasterio

    from workstation.io.geotiff import read_raster

    src = read_raster(ras["source"])  # the raster itself beside the preview, as a COG with overviews
    with rasterio.open(site / ras["cog"]) as cog:
        assert cog.tags(ns="IMAGE_STRUCTURE")["LAYOUT"] == "COG"
        assert np.array_equal(cog.read(1), np.asarray(src.array)) and cog.crs.to_epsg() == 32632
    cams = doc["cameras"]
    assert [c["name"] for c in cams] == ["im1.png", "im2.png"]
    assert cams[0]["center"] == pytest.approx([X0 + 50, Y0 + 50, Z0 + 60])
    # depth = half the 20 m between the centres; looking down, image x east, image y south
    c = np.array(cams[0]["corners"])
    assert c[:, 2] == pytest.approx(np.full(4, Z0 + 50))
    assert c[0, :2] == pytest.approx([X0 + 50 - 200 / 300 * 10, Y0 + 50 + 150 / 300 * 10])
    for f in ("index.html", "viewer/viewer.js", "viewer/laz-perf.wasm", "viewer/licenses/README.txt"):
        assert (site / f).is_file(), f
    readme = (site / "viewer/licenses/README.txt").read_text()
    assert all(p in readme for p in ("three", "copc", "laz-perf"))


def test_publish_refuses_existing_site_and_a_site_holding_an_input(work, site, tmp_path, capsys):
    assert main(["publish", str(work), "-o", str(site)]) == 1
    assert "exists" in capsys.readouterr().err
    assert main(["publish", str(work), "-o", str(work.parent), "--overwrite"]) == 1
    assert work.is_dir() and "input" in capsys.readouterr().err
    empty = tmp_path / "empty"
    empty.mkdir()
    assert main(["publish", str(empty), "-o", str(tmp_path / "s")]) == 1
    assert not (tmp_path / "s").exists()


EAST = 200_000.0  # the mesh site's shift east: 3 degrees off the UTM central meridian


def box_mesh(lo, hi):
    """A closed box (12 triangles, outward faces) between the corners ``lo`` and ``hi``, green
    vertex colours."""
    from workstation.core.products import Mesh

    v = np.array([[(hi if i & k else lo)[j] for j, k in enumerate((1, 2, 4))] for i in range(8)], float)
    f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4], [2, 6, 3], [3, 6, 7],
                  [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return Mesh(v, f, {"rgb": np.tile(np.array([[0, 200, 0]], np.uint8), (8, 1))}, crs=CRS)


@pytest.fixture(scope="module")
def mesh_site(tmp_path_factory):
    """The scene moved EAST metres east (where UTM's grid north is 1.3 degrees off true north,
    so a tileset's east-north-up frame is turned against the CRS) with a 20 m x 20 m x 8 m box
    mesh (PLY) on its ground at x 10-30 m, y 60-80 m, published with 3D Tiles."""
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud
    from workstation.io.mesh import write_mesh
    from workstation.publish.site import PublishParams, publish_site

    d = tmp_path_factory.mktemp("mesh-work")
    c = _scene()
    write_cloud(Cloud(c.xyz + [EAST, 0.0, 0.0], dict(c.attrs), crs=CRS), d / "cloud.las")
    write_mesh(box_mesh(np.array([X0 + EAST + 10, Y0 + 60, Z0]), np.array([X0 + EAST + 30, Y0 + 80, Z0 + 8])),
               d / "box.ply")
    out = tmp_path_factory.mktemp("mesh-pub") / "site"
    publish_site([d], out, params=PublishParams(tiles3d=True))
    return d, out


def test_site_json_places_the_mesh_tileset_in_the_viewer_frame(mesh_site):
    """The tileset's matrix takes every vertex of its glb tiles (glTF y-up turned z-up, node
    translations applied) to the mesh's CRS coordinates minus the site origin, within 1 mm."""
    import trimesh

    from workstation.io.mesh import read_mesh

    work, site = mesh_site
    doc = json.loads((site / "site.json").read_text())
    (mesh,) = [t for t in doc["tilesets"] if t["kind"] == "mesh"]
    m = np.array(mesh["matrix"]).reshape(4, 4).T  # column-major
    assert m[3].tolist() == [0, 0, 0, 1] and abs(np.degrees(np.arctan2(m[1, 0], m[0, 0]))) > 1.0  # turned
    tileset = json.loads((site / mesh["url"]).read_text())
    todo, uris = [tileset["root"]], []
    while todo:
        tile = todo.pop()
        todo += tile.get("children", [])
        uris += [tile["content"]["uri"]] if "content" in tile else []
    want = read_mesh(work / "box.ply").vertices - np.array(doc["origin"])
    for uri in uris:
        for part in trimesh.load((site / mesh["url"]).parent / uri, file_type="glb", process=False).dump():
            g = np.asarray(part.vertices)
            local = np.column_stack([g[:, 0], -g[:, 2], g[:, 1]])  # glTF (x, y, z) is z-up (x, -z, y)
            placed = local @ m[:3, :3].T + m[:3, 3]
            assert np.abs(placed[:, None, :] - want[None]).max(axis=-1).min(axis=1).max() < 1e-3


def test_tileset_matrix_refuses_a_tileset_without_its_frame(tmp_path):
    from workstation.core.errors import InvalidInputError
    from workstation.publish.site import tileset_matrix

    p = tmp_path / "tileset.json"
    p.write_text(json.dumps({"asset": {"version": "1.1"}, "root": {"boundingVolume": {"box": [0] * 12}}}))
    with pytest.raises(InvalidInputError, match="extras.ws.origin"):
        tileset_matrix(p, [0, 0, 0])


def test_a_copc_input_is_copied_byte_for_byte(site, tmp_path):
    from workstation.publish.site import publish_site

    src = site / "clouds" / "cloud.copc.laz"
    res = publish_site([src], tmp_path / "s2")
    assert (tmp_path / "s2" / "clouds" / "cloud.copc.laz").read_bytes() == src.read_bytes()
    assert res.points == res.doc["clouds"][0]["points"]


def test_collect_inputs_prefers_a_hillshade_and_skips_published_sites(tmp_path, small_cloud):
    from workstation.io import write_cloud
    from workstation.publish.site import collect_inputs, publish_site

    d = tmp_path / "products"
    (d / "dem").mkdir(parents=True)
    for name in ("dem/dtm.tif", "dem/dtm_hillshade.tif", "ortho.tif", "dsm.tif"):
        (d / name).write_bytes(b"")
    (d / "sparse" / "0").mkdir(parents=True)
    (d / "sparse" / "0" / "cameras.txt").write_text("")
    found = collect_inputs([d])
    assert sorted((p.name, k) for p, k in found.rasters) == [("dtm_hillshade.tif", "hillshade"), ("ortho.tif", "ortho")]
    assert found.cameras == (d / "sparse" / "0",) and found.clouds == ()
    (d / "cameras.json").write_text("{}")
    assert collect_inputs([d]).cameras == (d / "cameras.json",)  # the JSON wins over the model
    for name in ("dem/dtm.tif", "dem/dtm_hillshade.tif", "ortho.tif", "dsm.tif", "cameras.json"):
        (d / name).unlink()
    write_cloud(small_cloud, d / "a.laz")
    publish_site([d], d / "site")  # a site inside its input folder...
    res = publish_site([d], d / "site", overwrite=True)  # ...is not an input of the next one
    assert [c["name"] for c in res.doc["clouds"]] == ["a"] and res.points == 1000


# ---------------------------------------------------------------------------------- the server
def _get(url, rng=None):
    req = urllib.request.Request(url, headers={"Range": rng} if rng else {})
    try:
        with urllib.request.urlopen(req, timeout=10) as r:
            return r.status, dict(r.headers), r.read()
    except urllib.error.HTTPError as e:
        return e.code, dict(e.headers), b""


def test_server_answers_range_requests(site):
    from workstation.publish.site import serve_in_thread

    data = (site / "clouds" / "cloud.copc.laz").read_bytes()
    srv = serve_in_thread(site)
    try:
        url = f"http://127.0.0.1:{srv.server_address[1]}/clouds/cloud.copc.laz"
        status, head, body = _get(url, "bytes=100-199")
        assert status == 206 and body == data[100:200]
        assert head["Content-Range"] == f"bytes 100-199/{len(data)}" and head["Content-Length"] == "100"
        assert _get(url, "bytes=-10")[2] == data[-10:]
        assert _get(url, f"bytes={len(data) - 5}-")[2] == data[-5:]
        assert _get(url, f"bytes={len(data) - 5}-{len(data) + 100}")[2] == data[-5:]
        status, head, _ = _get(url, f"bytes={len(data)}-")
        assert status == 416 and head["Content-Range"] == f"bytes */{len(data)}"
        status, head, body = _get(url)
        assert status == 200 and body == data and head["Accept-Ranges"] == "bytes"
        assert _get(url, "bytes=0-1,5-9")[0] == 200  # several ranges: the whole file
        wasm = _get(url.replace("clouds/cloud.copc.laz", "viewer/laz-perf.wasm"))[1]
        assert wasm["Content-type"] == "application/wasm"
        assert ("/clouds/cloud.copc.laz", "bytes=100-199", 206) == srv.requests[0]
    finally:
        srv.shutdown()


# ---------------------------------------------------------------------------------- the viewer
class Chromium:
    """Headless Chromium driven over the DevTools protocol on a pipe (--remote-debugging-pipe:
    JSON messages separated by NUL bytes, commands on fd 3, replies and events on fd 4), so the
    test sees console errors and exceptions, evaluates JavaScript and takes screenshots with no
    library beyond the standard one. WebGL runs on SwiftShader (software)."""

    def __init__(self, exe: str, profile: Path, size=(640, 480)):
        to_r, self._to_w = os.pipe()
        self._from_r, from_w = os.pipe()
        flags = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--remote-debugging-pipe", f"--user-data-dir={profile}", f"--window-size={size[0]},{size[1]}",
                 "--no-first-run", "--mute-audio", "about:blank"]
        self.proc = subprocess.Popen(["bash", "-c", f'exec "$0" "$@" 3<&{to_r} 4>&{from_w}', exe, *flags],
                                     pass_fds=(to_r, from_w), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_r)
        os.close(from_w)
        self._next, self.replies, self.events = 0, {}, queue.Queue()
        self._cv = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()
        page = next(t for t in self.call("Target.getTargets")["targetInfos"] if t["type"] == "page")
        self.session = self.call("Target.attachToTarget", targetId=page["targetId"], flatten=True)["sessionId"]
        for domain in ("Runtime", "Log", "Page"):
            self.call(f"{domain}.enable", session=True)
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=size[0], height=size[1],
                  deviceScaleFactor=1, mobile=False)

    def _read(self):
        buf = b""
        with os.fdopen(self._from_r, "rb", buffering=0) as f:
            while chunk := f.read(1 << 16):
                buf += chunk
                *msgs, buf = buf.split(b"\0")
                for m in msgs:
                    msg = json.loads(m)
                    if "id" in msg:
                        with self._cv:
                            self.replies[msg["id"]] = msg
                            self._cv.notify_all()
                    else:
                        self.events.put(msg)

    def call(self, method, session=False, timeout=30, **params):
        self._next += 1
        msg = {"id": self._next, "method": method, "params": params}
        if session:
            msg["sessionId"] = self.session
        os.write(self._to_w, json.dumps(msg).encode() + b"\0")
        with self._cv:
            if not self._cv.wait_for(lambda: self._next in self.replies, timeout):
                raise TimeoutError(method)
            reply = self.replies.pop(self._next)
        if "error" in reply:
            raise RuntimeError(f"{method}: {reply['error']}")
        return reply["result"]

    def eval(self, expr):
        r = self.call("Runtime.evaluate", session=True, expression=expr, returnByValue=True)
        if "exceptionDetails" in r:
            raise RuntimeError(f"{expr}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def wait_state(self, url: str, timeout=10.0) -> tuple[str, float]:
        """Poll <html data-ws-state> of the page at ``url`` until 'ready' or 'error'; (state, seconds)."""
        t0 = time.perf_counter()
        probe = f"location.href === {json.dumps(url)} ? document.documentElement?.dataset.wsState : 'navigating'"
        while time.perf_counter() - t0 < timeout:
            state = self.eval(probe)
            if state in ("ready", "error"):
                return state, time.perf_counter() - t0
            time.sleep(0.1)
        return str(state), time.perf_counter() - t0

    def errors(self) -> list[str]:
        """Console errors, uncaught exceptions and failed loads logged so far."""
        out = []
        while not self.events.empty():
            e = self.events.get()
            p = e.get("params", {})
            if e["method"] == "Runtime.exceptionThrown":
                out.append(json.dumps(p["exceptionDetails"])[:500])
            elif e["method"] == "Runtime.consoleAPICalled" and p["type"] in ("error", "assert"):
                out.append(json.dumps(p["args"])[:500])
            elif e["method"] == "Log.entryAdded" and p["entry"]["level"] == "error":
                out.append(p["entry"]["text"])
        return out

    def screenshot(self) -> np.ndarray:
        from PIL import Image

        png = base64.b64decode(self.call("Page.captureScreenshot", session=True, format="png")["data"])
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except (TimeoutError, RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        os.close(self._to_w)


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    exe = shutil.which("chromium") or shutil.which("chromium-browser") or shutil.which("google-chrome")
    if exe is None:
        pytest.skip("chromium is not installed (Debian: apt-get install -y chromium)")
    b = Chromium(exe, tmp_path_factory.mktemp("chrome-profile"))
    yield b
    b.close()


@pytest.fixture(scope="module")
def server(site):
    from workstation.publish.site import serve_in_thread

    srv = serve_in_thread(site)
    yield srv
    srv.shutdown()


def _open(browser, server, fragment=""):
    """Load the viewer (``fragment``: a ``#view=`` camera); (state, seconds to 'ready')."""
    server.requests.clear()
    browser.errors()
    url = f"http://127.0.0.1:{server.server_address[1]}/index.html?t={time.monotonic_ns()}{fragment}"
    browser.call("Page.navigate", session=True, url=url)
    return browser.wait_state(url, 10.0)


def _default_view(browser, server):
    """The page on the default view, opened unless it already is (the tests share one page and
    restore what they change)."""
    if browser.eval("document.documentElement?.dataset.wsState === 'ready' && location.hash === ''"):
        return "ready"
    return _open(browser, server)[0]


def test_viewer_opens_in_headless_chromium_and_draws_the_cloud(browser, server):
    state, seconds = _open(browser, server)
    errors = browser.errors()
    assert state == "ready" and not errors, (state, errors, browser.eval("document.getElementById('status').textContent"))
    assert seconds < 10.0
    img = browser.screenshot()
    assert img.std() > 20  # not blank
    red = (img[..., 0] > 150) & (img[..., 1] < 80) & (img[..., 2] < 80)  # ground, RGB mode
    blue = (img[..., 2] > 150) & (img[..., 0] < 80)  # roof
    assert red.mean() > 0.05 and blue.mean() > 0.005
    assert int(browser.eval("document.documentElement.dataset.wsNodes")) >= 1
    hill = browser.eval("document.getElementById('map-img').naturalWidth")
    assert hill == 100  # the DTM hillshade preview in the map panel


def _requested_nodes(site, server):
    """Hierarchy entries of every node with points, the xy of each node's lower corner (CRS
    units), and which nodes the viewer fetched (matched by exact byte range)."""
    from workstation.io.copc import hierarchy, read_info

    path = site / "clouds" / "cloud.copc.laz"
    info = read_info(path)
    e = hierarchy(path, info)
    e = e[e["point_count"] > 0]
    size = 2 * info.halfsize / 2.0 ** e["level"]
    corner = np.column_stack([info.center[0] - info.halfsize + e["x"] * size,
                              info.center[1] - info.halfsize + e["y"] * size])
    asked = {tuple(map(int, r[1].split("=")[1].split("-"))) for r in server.requests if r[1] and "cloud" in r[0]}
    fetched = np.array([(int(o), int(o + b - 1)) in asked for o, b in zip(e["offset"], e["byte_size"])])
    return e, corner, fetched


def test_viewer_requests_only_the_nodes_in_view(browser, server, site):
    # stand over (15, 15) m and look south-west, down at the corner (0, 0) of the scene
    view = f"#view={X0 + 15},{Y0 + 15},{Z0 + 10},{X0 + 2},{Y0 + 2},{Z0}"
    state, _ = _open(browser, server, view)
    assert state == "ready" and not browser.errors()
    e, corner, fetched = _requested_nodes(site, server)
    near = (corner[:, 0] < X0 + 30) & (corner[:, 1] < Y0 + 30)  # nodes starting within 30 m of the corner
    deepest = e["level"] == e["level"].max()
    assert (fetched & deepest).any()  # refined down to the leaves near the camera
    assert not (fetched & ~near).any(), e[fetched & ~near]  # nothing from the far side of the scene
    assert fetched.sum() < 0.35 * len(e)
    # the default view of the whole scene fetches nodes everywhere (so the check above can fail)
    state, _ = _open(browser, server)
    e, corner, fetched = _requested_nodes(site, server)
    assert state == "ready" and (fetched & ~near).sum() > 10


@pytest.fixture(scope="module")
def lod_site(tmp_path_factory):
    """The scene with a wavy 100 m x 100 m terrain mesh (7,200 triangles) over it, published
    with 3D Tiles; the mesh's tileset is then rewritten in tiles of at most 800 triangles (a
    tree of 21 tiles, 3 levels, refined by REPLACE) and its site.json matrix refitted."""
    from workstation.core.products import Mesh
    from workstation.io import write_cloud
    from workstation.io.mesh import write_mesh
    from workstation.publish.site import PublishParams, publish_site, tileset_matrix
    from workstation.publish.tiles3d import write_mesh_tileset

    d = tmp_path_factory.mktemp("lod-work")
    write_cloud(_scene(), d / "cloud.las")
    n = 61
    x, y = np.meshgrid(np.linspace(0, 100, n), np.linspace(0, 100, n))
    z = 3 * np.sin(x / 7) * np.cos(y / 9) + 2
    i = np.arange(n * n).reshape(n, n)
    a, b, c, e = i[:-1, :-1].ravel(), i[:-1, 1:].ravel(), i[1:, :-1].ravel(), i[1:, 1:].ravel()
    faces = np.vstack([np.column_stack([a, b, e]), np.column_stack([a, e, c])])
    rgb = np.column_stack([np.full(n * n, 200), np.clip(z.ravel() * 40, 0, 255), np.full(n * n, 50)]).astype(np.uint8)
    xyz = np.column_stack([x.ravel() + X0, y.ravel() + Y0, z.ravel() + Z0])
    write_mesh(Mesh(xyz, faces, {"rgb": rgb}, crs=CRS), d / "terrain.ply")
    site = tmp_path_factory.mktemp("lod-pub") / "site"
    publish_site([d], site, params=PublishParams(tiles3d=True))
    doc = json.loads((site / "site.json").read_text())
    (entry,) = [t for t in doc["tilesets"] if t["kind"] == "mesh"]
    folder = (site / entry["url"]).parent
    shutil.rmtree(folder)
    write_mesh_tileset(d / "terrain.ply", folder, max_faces=800)
    entry["matrix"] = tileset_matrix(folder / "tileset.json", doc["origin"])
    (site / "site.json").write_text(json.dumps(doc))
    return site, entry


def _tiles(tileset: dict) -> dict:
    """{content uri: (depth, box centre x, y)} of every tile of a tileset document."""
    out, todo = {}, [(tileset["root"], 0)]
    while todo:
        tile, depth = todo.pop()
        todo += [(c, depth + 1) for c in tile.get("children", [])]
        if "content" in tile:
            out[tile["content"]["uri"]] = (depth, *tile["boundingVolume"]["box"][:2])
    return out


def test_viewer_refines_mesh_tiles_by_screen_space_error_in_view(browser, lod_site):
    """The whole site seen from afar needs no full-resolution leaf; a camera low over the
    south-west corner looking at it fetches leaves there and nothing of the north-east
    quarter, which is behind it."""
    from workstation.publish.site import serve_in_thread

    site, entry = lod_site
    tiles = _tiles(json.loads((site / entry["url"]).read_text()))
    leaf = max(d for d, _, _ in tiles.values())
    srv = serve_in_thread(site)
    try:
        def fetched(fragment=""):
            state, _ = _open(browser, srv, fragment)
            assert state == "ready" and not browser.errors()
            prefix = "/" + entry["url"].rsplit("/", 1)[0] + "/"
            return {r[0][len(prefix):] for r in srv.requests if r[0].startswith(prefix) and r[0].endswith(".glb")}

        far = fetched()
        assert far and all(tiles[u][0] < leaf for u in far)
        near = fetched(f"#view={X0 + 15},{Y0 + 15},{Z0 + 10},{X0 + 2},{Y0 + 2},{Z0}")
        assert any(tiles[u][0] == leaf for u in near)
        assert not [u for u in near if tiles[u][0] > 0 and tiles[u][1] > 0 and tiles[u][2] > 0]  # north-east
        assert int(browser.eval("wsViewer.tilesets[0].tiles.filter(t => t.object && t.object.visible).length")) > 0
    finally:
        srv.shutdown()


def _frame(browser):
    """Wait for the viewer to draw the change just made (two animation frames)."""
    browser.call("Runtime.evaluate", session=True, awaitPromise=True,
                 expression="new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")


def _share(img, rgb, tol=12):
    return float((np.abs(img.astype(int) - rgb).max(axis=-1) <= tol).mean())


def _set_colour(browser, mode):
    browser.eval(f"(() => {{ const s = document.getElementById('color'); s.value = '{mode}';"
                 f"s.dispatchEvent(new Event('change')); }})()")
    _frame(browser)
    return browser.screenshot()


def test_colour_modes_class_toggle_and_camera_frusta(browser, server):
    assert _default_view(browser, server) == "ready"
    img = _set_colour(browser, "classification")
    assert _share(img, (166, 113, 52)) > 0.05 and _share(img, (220, 60, 50)) > 0.005  # ground, building
    img = _set_colour(browser, "elevation")  # the ramp's ends: purple ground, yellow roof
    assert _share(img, (68, 1, 84), 20) > 0.05 and _share(img, (253, 231, 37), 20) > 0.005
    img = _set_colour(browser, "intensity")  # 1000 and 3000 are the 2nd and 98th percentiles
    assert _share(img, (255, 255, 255), 3) > 0.005 and _share(img, (0, 0, 0), 3) > 0.05
    img = _set_colour(browser, "rgb")
    frusta = _share(img, (255, 204, 0), 30)
    assert _share(img, (0, 0, 234), 20) > 0.005 and frusta > 0
    browser.eval("document.querySelector('#classes input[data-code=\"6\"]').click()")
    _frame(browser)
    hidden = browser.screenshot()
    assert _share(hidden, (0, 0, 234), 20) == 0 and _share(hidden, (234, 0, 0), 20) > 0.05
    browser.eval("document.getElementById('cameras').click()")
    _frame(browser)
    assert _share(browser.screenshot(), (255, 204, 0), 30) == 0 < frusta
    browser.eval("document.getElementById('cameras').click();"
                 "document.querySelector('#classes input[data-code=\"6\"]').click()")
    assert not browser.errors()


def _click(browser, xy):
    for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
        browser.call("Input.dispatchMouseEvent", session=True, type=kind, x=int(xy[0]), y=int(xy[1]),
                     button="left", clickCount=1)


def test_measure_a_height_and_a_distance_by_two_clicks(browser, server):
    assert _default_view(browser, server) == "ready"
    img = _set_colour(browser, "rgb")
    roof = np.argwhere((img[..., 2] > 200) & (img[..., 0] < 50))  # (row, col) of roof pixels
    ground = np.argwhere((img[..., 0] > 200) & (img[..., 2] < 50))
    r = roof[np.argmin(np.abs(roof - np.median(roof, axis=0)).sum(axis=1))]  # near the roof's middle
    row = int(np.percentile(ground[:, 0], 90))  # a row of ground near the bottom of the view
    cols = ground[ground[:, 0] == row, 1]
    g1, g2 = (row, cols.min() + 30), (row, cols.max() - 30)
    browser.eval("document.getElementById('measure-height').click()")
    _click(browser, r[::-1])
    _click(browser, g1[::-1])
    m = browser.eval("wsViewer.lastMeasure")
    assert m["kind"] == "height" and m["value"] == pytest.approx(ROOF, abs=2e-3)
    assert "height 10.000 m" in browser.eval("document.getElementById('measure-out').textContent")
    browser.eval("document.getElementById('measure-distance').click()")
    _click(browser, g1[::-1])
    _click(browser, g2[::-1])
    m = browser.eval("wsViewer.lastMeasure")
    assert m["kind"] == "distance", browser.eval("document.getElementById('measure-out').textContent")
    assert m["dz"] == pytest.approx(0, abs=2e-3)  # both on the flat ground
    assert m["value"] == pytest.approx(m["horizontal"], abs=1e-3) and m["value"] > 30
    assert not browser.errors()


def test_viewer_works_from_a_static_server_without_range_support(browser, site):
    """`python -m http.server` answers every request with the whole file: the viewer still
    opens (it keeps the one full download) and logs no error."""
    import functools
    from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer

    class Quiet(SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    srv = ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=str(site)))
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    try:
        browser.errors()
        url = f"http://127.0.0.1:{srv.server_address[1]}/index.html"
        browser.call("Page.navigate", session=True, url=url)
        state, _ = browser.wait_state(url, 10.0)
        assert state == "ready" and not browser.errors()
        assert int(browser.eval("document.documentElement.dataset.wsNodes")) >= 1
    finally:
        srv.shutdown()


def test_ws_publish_serve_serves_a_published_site(site):
    import re
    import signal
    import sys

    proc = subprocess.Popen([sys.executable, "-m", "workstation.cli.main", "publish", str(site), "--serve", "--port", "0"],
                            stderr=subprocess.PIPE, text=True)
    try:
        line = proc.stderr.readline()
        m = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        assert m, line
        status, head, body = _get(f"http://127.0.0.1:{m.group(1)}/site.json", "bytes=0-9")
        assert status == 206 and body == (site / "site.json").read_bytes()[:10]
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(timeout=20) == 130
