"""3D Tiles 1.1 output (workstation.publish.tiles3d): clouds and meshes, read back with trimesh's
glTF reader and an accessor decoder written from the glTF 2.0 spec, every point found once
after the tileset's transforms are undone to the CRS, and the Khronos glTF validator (npm
``gltf-validator`` in web/node_modules) when installed."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, OutputExistsError
from workstation.publish.copc import CopcParams
from workstation.publish.tiles3d import read_glb, save_tileset

CRS = "EPSG:32632"
X0, Y0, Z0 = 500_000.0, 4_000_000.0, 100.0
SMALL = CopcParams(max_points=1500, cells=16)  # a few levels on a small cloud
REPO = Path(__file__).resolve().parents[2]
VALIDATOR = REPO / "web" / "node_modules" / "gltf-validator"
_SIZES = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
_WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}
_DTYPES = {5120: "<i1", 5121: "<u1", 5122: "<i2", 5123: "<u2", 5125: "<u4", 5126: "<f4"}


def _cloud(n=20_000, crs=CRS, rgb=True, classes=True, seed=0, scale=1.0) -> Cloud:
    """Terrain with a block 12 units up over 300 x 200 units (``scale`` x metres)."""
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0, 300, n) * scale, rng.uniform(0, 200, n) * scale
    block = (np.abs(x / scale - 150) < 30) & (np.abs(y / scale - 100) < 20)
    z = (Z0 + 3 * np.sin(x / scale / 40) + np.where(block, 12.0, 0.0)) * scale
    attrs = {}
    if classes:
        attrs["classification"] = np.where(block, 6, 2).astype(np.uint8)
    if rgb:
        attrs["rgb"] = (np.where(block[:, None], [200, 60, 50], [90, 160, 70]) * 257).astype(np.uint16)
    return Cloud(np.round(np.column_stack([x + X0, y + Y0, z]), 3), attrs, crs=crs)


def _accessor(doc: dict, binary: bytes, index: int) -> np.ndarray:
    """An accessor's elements (count, width) by the glTF 2.0 rules (byteStride or packed)."""
    acc = doc["accessors"][index]
    view = doc["bufferViews"][acc["bufferView"]]
    width, size = _WIDTH[acc["type"]], _SIZES[acc["componentType"]]
    stride = view.get("byteStride", width * size)
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    assert stride % 4 == 0 or "target" in view and view["target"] == 34963  # vertex attributes 4-byte aligned
    assert start + stride * (acc["count"] - 1) + width * size <= view.get("byteOffset", 0) + view["byteLength"]
    raw = np.frombuffer(binary, np.uint8, count=stride * acc["count"], offset=start)
    rows = np.lib.stride_tricks.as_strided(raw, (acc["count"], width * size), (stride, 1)).copy()
    return rows.view(_DTYPES[acc["componentType"]]).reshape(acc["count"], width)


def _tiles(tile: dict, parent=None):
    """(tile, parent) of every tile of a tree, depth first."""
    yield tile, parent
    for child in tile.get("children", []):
        yield from _tiles(child, tile)


def _box_bounds(box):
    c, h = np.array(box[:3]), np.abs(np.array(box[3:]).reshape(3, 3)).sum(axis=0)
    return c - h, c + h


def _read_points(folder: Path):
    """(tileset doc, tile-frame xyz (n, 3) z-up, colours, classes, per-tile (tile, xyz)) of all tiles."""
    import trimesh

    doc = json.loads((folder / "tileset.json").read_text())
    xyz, rgb, cls, per_tile = [], [], [], []
    for tile, _ in _tiles(doc["root"]):
        data = (folder / tile["content"]["uri"]).read_bytes()
        gdoc, binary = read_glb(data)
        (prim,) = gdoc["meshes"][0]["primitives"]
        assert prim["mode"] == 0 and gdoc["asset"]["version"] == "2.0"
        scene = trimesh.load(folder / tile["content"]["uri"], file_type="glb")  # an independent glTF reader
        (pc,) = scene.dump()
        yup = np.asarray(pc.vertices, float)
        local = np.column_stack([yup[:, 0], -yup[:, 2], yup[:, 1]])  # glTF y-up -> tileset z-up
        own = _accessor(gdoc, binary, prim["attributes"]["POSITION"]).astype(float) + gdoc["nodes"][0]["translation"]
        np.testing.assert_allclose(own, yup, atol=1e-6)
        xyz.append(local)
        rgb.append(_accessor(gdoc, binary, prim["attributes"]["COLOR_0"]))
        if "_CLASSIFICATION" in prim["attributes"]:
            cls.append(_accessor(gdoc, binary, prim["attributes"]["_CLASSIFICATION"])[:, 0])
        per_tile.append((tile, local))
    return doc, np.vstack(xyz), np.vstack(rgb), (np.concatenate(cls) if cls else None), per_tile


def _to_crs(doc: dict, local: np.ndarray, crs: str, zunit: float = 1.0) -> np.ndarray:
    """Tileset-frame points through the root transform (ENU -> ECEF) and pyproj back to ``crs``
    (heights: ellipsoidal metres divided by ``zunit``, the CRS's metres per vertical unit)."""
    import pyproj

    m = np.array(doc["root"]["transform"]).reshape(4, 4).T  # column-major
    ecef = local @ m[:3, :3].T + m[:3, 3]
    x, y, z = pyproj.Transformer.from_crs("EPSG:4978", pyproj.CRS(crs).to_3d(), always_xy=True).transform(*ecef.T)
    return np.column_stack([x, y, z / zunit])


def _match(a: np.ndarray, b: np.ndarray, tol: float) -> np.ndarray:
    """Index into ``b`` of every point of ``a``, asserting a one-to-one match within ``tol``."""
    from scipy.spatial import cKDTree

    assert len(a) == len(b)
    d, idx = cKDTree(b).query(a)
    assert d.max() < tol, d.max()
    assert len(np.unique(idx)) == len(b)  # every point exactly once
    return idx


@pytest.fixture(scope="module")
def cloud_tileset(tmp_path_factory):
    from workstation.io import write_cloud

    d = tmp_path_factory.mktemp("t3d")
    cloud = _cloud()
    write_cloud(cloud, d / "cloud.laz")
    res = save_tileset(d / "cloud.laz", d / "tiles", params=SMALL)
    return cloud, d / "tiles", res


def test_cloud_tileset_holds_every_point_once_in_the_crs(cloud_tileset):
    cloud, folder, res = cloud_tileset
    doc, local, rgb, cls, _ = _read_points(folder)
    assert doc["asset"]["version"] == "1.1" and doc["root"]["refine"] == "ADD" and len(doc["root"]["transform"]) == 16
    assert res.points == cloud.n == len(local) and res.levels >= 3 and res.tiles > 8
    idx = _match(_to_crs(doc, local, CRS), cloud.xyz, tol=1e-3)
    assert (cls == cloud.attrs["classification"][idx]).all()
    assert (rgb == (cloud.attrs["rgb"][idx] >> 8)).all()


def test_cloud_tile_tree_errors_and_boxes(cloud_tileset):
    _, folder, _ = cloud_tileset
    doc, _, _, _, per_tile = _read_points(folder)
    assert doc["geometricError"] > doc["root"]["geometricError"] > 0
    boxes = {id(t): _box_bounds(t["boundingVolume"]["box"]) for t, _ in _tiles(doc["root"])}
    for tile, pts in per_tile:
        lo, hi = boxes[id(tile)]
        assert (pts >= lo - 1e-6).all() and (pts <= hi + 1e-6).all()
        assert tile["content"]["uri"].startswith("tiles/") and tile["content"]["uri"].endswith(".glb")
    for tile, parent in _tiles(doc["root"]):
        assert len(tile["boundingVolume"]["box"]) == 12
        if not tile.get("children"):
            assert tile["geometricError"] == 0
        if parent is not None:
            assert tile["geometricError"] < parent["geometricError"]
            if tile.get("children"):
                assert tile["geometricError"] == pytest.approx(parent["geometricError"] / 2)
            (lo, hi), (plo, phi) = boxes[id(tile)], boxes[id(parent)]
            assert (lo >= plo - 1e-6).all() and (hi <= phi + 1e-6).all()


def test_root_transform_is_enu_at_the_centre(cloud_tileset):
    import pyproj

    cloud, folder, _ = cloud_tileset
    doc = json.loads((folder / "tileset.json").read_text())
    m = np.array(doc["root"]["transform"]).reshape(4, 4).T
    np.testing.assert_allclose(m[:3, :3].T @ m[:3, :3], np.eye(3), atol=1e-12)
    assert (m[3] == [0, 0, 0, 1]).all()
    centre = np.array(doc["extras"]["ws"]["origin"])
    assert centre == pytest.approx((cloud.xyz.min(axis=0) + cloud.xyz.max(axis=0)) / 2, abs=1e-3)
    to_ecef = pyproj.Transformer.from_crs(pyproj.CRS(CRS).to_3d(), "EPSG:4978", always_xy=True)
    np.testing.assert_allclose(m[:3, 3], to_ecef.transform(*centre), atol=1e-3)
    up10 = m[:3, :3] @ [0.0, 0.0, 10.0] + m[:3, 3]  # 10 m straight up: the same E, N, h + 10
    np.testing.assert_allclose(up10, to_ecef.transform(centre[0], centre[1], centre[2] + 10), atol=1e-3)


def _validate(files) -> list[dict]:
    script = ("const v=require(process.argv[1]);const fs=require('fs');(async()=>{const o=[];"
              "for(const f of process.argv.slice(2)){const r=await v.validateBytes(new Uint8Array(fs.readFileSync(f)));"
              "o.push({file:f,errors:r.issues.numErrors,warnings:r.issues.numWarnings,"
              "messages:r.issues.messages.map(m=>m.code+' '+(m.pointer||'')+' '+m.message)})}"
              "console.log(JSON.stringify(o))})()")
    out = subprocess.run(["node", "-e", script, str(VALIDATOR), *map(str, files)], capture_output=True, text=True,
                         check=True, timeout=120)
    return json.loads(out.stdout)


@pytest.mark.skipif(not (VALIDATOR.is_dir() and shutil.which("node")),
                    reason="npm gltf-validator not in web/node_modules")
def test_khronos_gltf_validator_accepts_every_tile(cloud_tileset, mesh_tilesets):
    files = sorted(cloud_tileset[1].rglob("*.glb"))
    files += [f for k in ("tex", "col") for f in sorted(mesh_tilesets[k].rglob("*.glb"))]
    assert len(files) > len(list(cloud_tileset[1].rglob("*.glb"))) + 16
    reports = _validate(files)
    assert len(reports) == len(files)
    bad = [r for r in reports if r["errors"] or r["warnings"]]
    assert not bad, bad[:3]


def test_publish_makes_the_cloud_tiles_from_the_copc_octree(tmp_path, monkeypatch, cloud_tileset):
    from workstation.publish import tiles3d
    from workstation.publish.site import PublishParams, publish_site

    calls, real = [], tiles3d.write_cloud_tileset
    monkeypatch.setattr(tiles3d, "write_cloud_tileset", lambda *a, **k: calls.append(a) or real(*a, **k))
    _, folder, _ = cloud_tileset
    publish_site([folder.parent / "cloud.laz"], tmp_path / "site", params=PublishParams(tiles3d=True, copc=SMALL))
    assert not calls  # the cloud was read and sorted once, by the COPC writer
    site = tmp_path / "site" / "3dtiles" / "cloud"
    files = sorted(p.relative_to(folder) for p in folder.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(site) for p in site.rglob("*") if p.is_file()) and len(files) > 8
    assert all((folder / f).read_bytes() == (site / f).read_bytes() for f in files)  # as a tileset of its own


def test_cloud_without_crs_is_local(tmp_path):
    from workstation.io import write_cloud

    cloud = _cloud(4000, crs=None, rgb=False)
    write_cloud(cloud, tmp_path / "c.las")
    save_tileset(tmp_path / "c.las", tmp_path / "t", params=SMALL)
    doc, local, rgb, cls, _ = _read_points(tmp_path / "t")
    assert "transform" not in doc["root"] and doc["extras"]["ws"]["frame"] == "local"
    idx = _match(local + doc["extras"]["ws"]["origin"], cloud.xyz, tol=1e-3)
    from workstation.core.classes import class_colors

    assert (rgb == class_colors(cloud.attrs["classification"][idx])).all()  # no RGB: class colours


def test_feet_crs_becomes_metres_and_unclassified_gets_elevation_colours(tmp_path):
    from workstation.io import write_cloud

    crs = "EPSG:2994"  # Oregon Lambert, international feet
    cloud = _cloud(3000, crs=crs, rgb=False, classes=False, scale=1 / 0.3048)
    cloud = Cloud(cloud.xyz - [X0 - 1_400_000, Y0 - 600_000, 0], {}, crs=crs)  # inside Oregon
    write_cloud(cloud, tmp_path / "ft.las")
    save_tileset(tmp_path / "ft.las", tmp_path / "t", params=SMALL)
    doc, local, rgb, cls, _ = _read_points(tmp_path / "t")
    assert cls is None or (cls <= 1).all()
    _match(_to_crs(doc, local, crs, 0.3048), cloud.xyz, tol=1e-3 / 0.3048)
    extent_m = np.ptp(local, axis=0)  # ENU metres: 300 m x 200 m, heights in feet made metres
    assert extent_m[:2] == pytest.approx([300, 200], rel=0.01)
    assert extent_m[2] == pytest.approx(np.ptp(cloud.xyz[:, 2]) * 0.3048, rel=0.01)
    top, bottom = rgb[np.argmax(local[:, 2])], rgb[np.argmin(local[:, 2])]
    assert top.tolist() == [200, 40, 30] and bottom.tolist() == [48, 18, 140]  # the ends of the elevation ramp


def test_save_tileset_refuses_existing_and_empty(tmp_path, cloud_tileset):
    from workstation.io import write_cloud

    _, folder, _ = cloud_tileset
    src = folder.parent / "cloud.laz"
    (tmp_path / "t").mkdir()
    with pytest.raises(OutputExistsError):
        save_tileset(src, tmp_path / "t")
    save_tileset(src, tmp_path / "t", overwrite=True, params=SMALL)
    assert (tmp_path / "t" / "tileset.json").is_file() and not list(tmp_path.glob(".t.*"))
    write_cloud(_cloud(0), tmp_path / "empty.las")
    with pytest.raises(InvalidInputError):
        save_tileset(tmp_path / "empty.las", tmp_path / "t2")
    assert not (tmp_path / "t2").exists()


# ---------------------------------------------------------------------------------- meshes
def _grid_mesh(n=50, **attrs):
    from workstation.core.products import Mesh

    x, y = np.meshgrid(np.linspace(0, 100, n), np.linspace(0, 80, n))
    v = np.column_stack([x.ravel() + X0, y.ravel() + Y0, Z0 + 5 * np.sin(x.ravel() / 10) * np.cos(y.ravel() / 13)])
    i = np.arange(n * n).reshape(n, n)
    a, b, c, d = i[:-1, :-1].ravel(), i[:-1, 1:].ravel(), i[1:, 1:].ravel(), i[1:, :-1].ravel()
    f = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])])
    uv = np.column_stack([x.ravel() / 100, y.ravel() / 80]).astype(np.float32)
    return Mesh(v, f, {k: (uv if k == "uv" else val) for k, val in attrs.items()}, crs=CRS), uv


MESH_LEAF = 600  # max_faces: the 4,802-triangle grid becomes a few levels of tiles


@pytest.fixture(scope="module")
def mesh_tilesets(tmp_path_factory):
    from workstation.io.mesh import write_mesh

    d = tmp_path_factory.mktemp("meshes")
    tex = np.random.default_rng(0).integers(0, 256, (32, 48, 3), dtype=np.uint8)
    textured, _ = _grid_mesh(uv=True)
    textured = type(textured)(textured.vertices, textured.faces, textured.vertex_attrs, meta={"texture": tex})
    write_mesh(textured, d / "tex.obj")
    rgb = np.random.default_rng(1).integers(0, 256, (2500, 3), dtype=np.uint8)
    write_mesh(_grid_mesh(rgb=rgb)[0], d / "col.ply")
    res = save_tileset(d / "tex.obj", d / "tex", crs=CRS, max_faces=MESH_LEAF)
    save_tileset(d / "col.ply", d / "col", max_faces=MESH_LEAF)  # the PLY records its CRS
    return {"tex": d / "tex", "col": d / "col", "texture": tex, "rgb": rgb, "dir": d, "result": res}


def _glb_mesh(path: Path):
    import trimesh

    (m,) = trimesh.load(path, file_type="glb", process=False).dump()
    yup = np.asarray(m.vertices, float)
    return m, np.column_stack([yup[:, 0], -yup[:, 2], yup[:, 1]])


def _mesh_leaves(folder: Path, src):
    """(tileset doc, per leaf: (tile, trimesh mesh, index of each of its vertices into
    ``src.vertices``)), the leaf vertices taken through the root transform back to the CRS
    and matched to the source vertices within 1 mm."""
    from scipy.spatial import cKDTree

    doc = json.loads((folder / "tileset.json").read_text())
    leaves = []
    for tile, _ in _tiles(doc["root"]):
        if tile.get("children"):
            continue
        m, local = _glb_mesh(folder / tile["content"]["uri"])
        d, idx = cKDTree(src.vertices).query(_to_crs(doc, local, CRS))
        assert d.max() < 1e-3, d.max()
        leaves.append((tile, m, idx))
    return doc, leaves


def test_mesh_tileset_holds_every_triangle_once_at_full_resolution(mesh_tilesets):
    from workstation.io.mesh import read_mesh

    src = read_mesh(mesh_tilesets["dir"] / "tex.obj")
    doc, leaves = _mesh_leaves(mesh_tilesets["tex"], src)
    assert doc["asset"]["version"] == "1.1" and doc["root"]["refine"] == "REPLACE"
    assert len(leaves) >= 8 and mesh_tilesets["result"].levels >= 3 and mesh_tilesets["result"].faces == src.n_faces
    got = np.concatenate([np.sort(idx[np.asarray(m.faces)], axis=1) for _, m, idx in leaves])
    assert all(len(m.faces) <= MESH_LEAF for _, m, _ in leaves)
    want = np.sort(src.faces, axis=1)
    assert len(got) == len(want)  # no triangle twice ...
    assert np.array_equal(np.unique(got, axis=0), np.unique(want, axis=0))  # ... and none missing


def test_mesh_leaves_keep_their_texture(mesh_tilesets):
    from workstation.io.mesh import read_mesh
    from workstation.publish.tiles3d import _texture_at

    src = read_mesh(mesh_tilesets["dir"] / "tex.obj")
    _, leaves = _mesh_leaves(mesh_tilesets["tex"], src)
    full = mesh_tilesets["texture"]
    for _, m, idx in leaves:
        img = np.asarray(m.visual.material.baseColorTexture.convert("RGB"))
        assert img.shape[0] * img.shape[1] < full.shape[0] * full.shape[1]  # a leaf holds only its part
        uv = np.asarray(m.visual.uv, float)  # trimesh flips v back to the OBJ convention
        texel = src.vertex_attrs["uv"][idx] * [full.shape[1], full.shape[0]]
        inner = (np.abs(texel % 1 - 0.5) < 0.49).all(axis=1)  # off texel edges, where float32 may pick the neighbour
        assert inner.mean() > 0.5
        assert np.array_equal(_texture_at(img, uv)[inner], _texture_at(full, src.vertex_attrs["uv"][idx])[inner])


def test_mesh_tile_boxes_and_errors(mesh_tilesets):
    folder = mesh_tilesets["tex"]
    doc = json.loads((folder / "tileset.json").read_text())
    assert doc["geometricError"] > doc["root"]["geometricError"] > 0
    boxes = {id(t): _box_bounds(t["boundingVolume"]["box"]) for t, _ in _tiles(doc["root"])}
    faces_below = {}
    for tile, parent in reversed(list(_tiles(doc["root"]))):  # children before parents
        m, local = _glb_mesh(folder / tile["content"]["uri"])
        lo, hi = boxes[id(tile)]
        assert (local >= lo).all() and (local <= hi).all()
        gdoc, _ = read_glb((folder / tile["content"]["uri"]).read_bytes())
        if tile.get("children"):
            below = sum(faces_below[id(c)] for c in tile["children"])
            assert tile["geometricError"] > 0 and len(m.faces) < below  # simplified, with vertex colours
            assert "COLOR_0" in gdoc["meshes"][0]["primitives"][0]["attributes"]
            faces_below[id(tile)] = below
        else:
            assert tile["geometricError"] == 0 and "images" in gdoc
            faces_below[id(tile)] = len(m.faces)
        if parent is not None:
            assert tile["geometricError"] <= parent["geometricError"]
            plo, phi = boxes[id(parent)]
            assert (lo >= plo - 1e-9).all() and (hi <= phi + 1e-9).all()
    assert faces_below[id(doc["root"])] == 2 * 49 * 49


def test_mesh_with_a_vertex_per_corner_is_simplified(tmp_path, mesh_tilesets):
    from workstation.core.products import Mesh
    from workstation.io.mesh import read_mesh, write_mesh

    grid, uv = _grid_mesh(uv=True)
    wedge = grid.faces.reshape(-1)  # as texturing writes it: every face corner its own vertex and UV
    soup = Mesh(grid.vertices[wedge], np.arange(len(wedge)).reshape(-1, 3), {"uv": uv[wedge]}, crs=CRS,
                meta={"texture": mesh_tilesets["texture"]})
    write_mesh(soup, tmp_path / "soup.obj")
    assert read_mesh(tmp_path / "soup.obj").vertices.shape[0] == len(wedge)
    save_tileset(tmp_path / "soup.obj", tmp_path / "t", crs=CRS, max_faces=MESH_LEAF)
    doc = json.loads((tmp_path / "t" / "tileset.json").read_text())
    root, _ = _glb_mesh(tmp_path / "t" / doc["root"]["content"]["uri"])
    assert "children" in doc["root"] and len(root.faces) <= 1.2 * MESH_LEAF  # welded, then decimated
    assert 0 < doc["root"]["geometricError"] < 10.0


def test_vertex_colour_ply_tileset(mesh_tilesets):
    from workstation.io.mesh import read_mesh

    src = read_mesh(mesh_tilesets["dir"] / "col.ply")
    doc, leaves = _mesh_leaves(mesh_tilesets["col"], src)
    assert doc["extras"]["ws"]["crs"] == CRS and len(doc["root"]["transform"]) == 16
    for tile, _, idx in leaves:
        gdoc, binary = read_glb((mesh_tilesets["col"] / tile["content"]["uri"]).read_bytes())
        (prim,) = gdoc["meshes"][0]["primitives"]
        assert prim["mode"] == 4 and gdoc["materials"][0]["doubleSided"]
        colours = _accessor(gdoc, binary, prim["attributes"]["COLOR_0"])
        assert np.array_equal(colours, mesh_tilesets["rgb"][idx])
        faces = _accessor(gdoc, binary, prim["indices"]).reshape(-1, 3)
        assert faces.max() < len(colours)


def test_small_mesh_is_one_leaf(tmp_path, mesh_tilesets):
    res = save_tileset(mesh_tilesets["dir"] / "col.ply", tmp_path / "t")  # 4,802 faces <= 50,000
    doc = json.loads((tmp_path / "t" / "tileset.json").read_text())
    assert res.tiles == res.levels == 1 and "children" not in doc["root"] and doc["root"]["geometricError"] == 0
    assert doc["geometricError"] > 0
    with pytest.raises(InvalidInputError):
        save_tileset(mesh_tilesets["dir"] / "col.ply", tmp_path / "t2", max_faces=0)


def test_split_faces_puts_every_face_in_one_leaf():
    from workstation.publish.tiles3d import split_faces

    rng = np.random.default_rng(3)
    cent = np.vstack([rng.uniform(0, [400, 300, 20], (5000, 3)), np.full((700, 3), 7.0)])  # 700 at one point
    tree = split_faces(cent, 300)
    assert len(tree["children"]) == 4  # flat data: a quadtree split
    leaves, stack = [], [tree]
    while stack:
        node = stack.pop()
        if node["children"]:
            kids = np.concatenate([k["faces"] for k in node["children"]])
            assert np.array_equal(np.sort(kids), np.sort(node["faces"])) and len(node["children"]) >= 2
            stack += node["children"]
        else:
            leaves.append(node)
    owner = np.concatenate([n["faces"] for n in leaves])
    assert np.array_equal(np.sort(owner), np.arange(len(cent)))
    big = [n for n in leaves if len(n["faces"]) > 300]
    assert len(big) == 1 and (big[0]["faces"] >= 5000).all()  # only coincident centroids cannot be split


def _scattered_atlas(cells=16, seed=7):
    """Unshared triangles each with its own 4 x 4 texel cell at a random place in a 64 x 64
    atlas (as texturing packs faces): (uv (3m, 2), faces (m, 3), texture)."""
    rng = np.random.default_rng(seed)
    m = 200
    slot = rng.permutation(cells * cells)[:m]
    x0, y0 = (slot % cells) * 4, (slot // cells) * 4
    corner = np.array([[0.5, 0.5], [3.5, 0.5], [0.5, 3.5]])  # texel units inside the cell, rows down
    px = np.stack([x0, y0], 1)[:, None, :] + corner[None]
    uv = np.column_stack([px[..., 0].ravel() / 64, 1 - px[..., 1].ravel() / 64])
    return uv, np.arange(3 * m).reshape(m, 3), rng.integers(0, 256, (64, 64, 3), dtype=np.uint8)


def test_sub_atlas_keeps_texels_and_only_what_is_used():
    from workstation.publish.tiles3d import _texture_at, sub_atlas

    uv, faces, tex = _scattered_atlas()
    part = faces[:25]  # an eighth of the faces, spread over the whole atlas
    used = np.unique(part)
    sub, uv2 = sub_atlas(tex, uv[: used.max() + 1], part)
    assert sub.shape[0] * sub.shape[1] < tex.shape[0] * tex.shape[1] / 3
    assert np.array_equal(_texture_at(sub, uv2[used]), _texture_at(tex, uv[used]))
    corners = (uv2[part] * [sub.shape[1], sub.shape[0]])  # the 3 x 3 texel triangle and 2 texels round it fit
    assert (corners >= 0).all() and (corners[..., 0] <= sub.shape[1]).all()
    rng = np.random.default_rng(5)  # one chart (a regular grid): a crop of its box
    grid = rng.uniform([0.2, 0.55], [0.45, 0.9], (400, 2))
    tri = np.column_stack([np.arange(398), np.arange(1, 399), np.arange(2, 400)])
    sub, uv3 = sub_atlas(tex, grid, tri)
    assert np.array_equal(_texture_at(sub, uv3), _texture_at(tex, grid)) and sub.shape[0] * sub.shape[1] < 1000
    same, uv4 = sub_atlas(tex, grid + 0.6, tri)  # beyond 1: a repeating texture is kept whole
    assert same is tex and np.array_equal(uv4, grid + 0.6)


# ---------------------------------------------------------------------------------- the CLI
def test_ws_publish_3d_tiles(tmp_path, capsys, mesh_tilesets):
    from workstation.io import write_cloud

    work = tmp_path / "work"
    work.mkdir()
    write_cloud(_cloud(6000), work / "cloud.laz")
    shutil.copy(mesh_tilesets["dir"] / "col.ply", work / "surface.ply")
    out = tmp_path / "site"
    assert main(["publish", str(work), "-o", str(out), "--3d-tiles", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert {t["name"]: t["kind"] for t in doc["tilesets"]} == {"cloud": "cloud", "surface": "mesh"}
    for t in doc["tilesets"]:
        assert (out / t["url"]).is_file() and t["url"].startswith("3dtiles/")
    site = json.loads((out / "site.json").read_text())
    assert site["tilesets"] == doc["tilesets"] and (out / "clouds" / "cloud.copc.laz").is_file()
    assert main(["publish", str(work), "-o", str(out), "--3d-tiles"]) == 1  # exists: refused
    assert main(["publish", str(work), "-o", str(out), "--overwrite"]) == 0
    assert not (out / "3dtiles").exists()
