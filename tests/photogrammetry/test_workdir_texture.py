"""Textured meshes are named after their file: two meshes in one folder never share a texture
(OBJ + MTL + PNG and GLB), and --overwrite rules cover the texture files, checked before any work."""

from __future__ import annotations

import json
import struct
import time

import numpy as np
import pytest

from workstation.cli.main import main


@pytest.fixture(scope="module")
def terrain(tmp_path_factory):
    """A 20 x 20 m terrain patch (41 x 41 points) and a work folder with three near-nadir photos
    (COLMAP text model in sparse/0, PNGs in images/)."""
    import cv2

    from workstation.core.cloud import Cloud
    from workstation.core.products import Camera, Image, Reconstruction
    from workstation.io import write_cloud
    from workstation.photogrammetry.rigs import look_at, render, write_colmap_text

    root = tmp_path_factory.mktemp("texture")
    x, y = np.meshgrid(np.linspace(-10, 10, 41), np.linspace(-10, 10, 41))
    z = 0.4 * np.sin(x / 3.0) + 0.2 * np.cos(y / 4.0)
    V = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    r, c = np.divmod(np.arange(40 * 40), 40)
    a = r * 41 + c
    F = np.concatenate([np.stack([a, a + 1, a + 42], 1), np.stack([a, a + 42, a + 41], 1)])
    cam = Camera(160, 120, 110.0, 110.0, 79.5, 59.5)
    (root / "work" / "images").mkdir(parents=True)
    images = {}
    for k, cx in enumerate((-4.0, 0.0, 4.0), start=1):
        pose = look_at(np.array([cx, -1.0, 16.0]), np.array([cx * 0.5, 0.0, 0.0]))
        img = render(V, F, np.full((len(F), 3), [0.8, 0.7, 0.5]), cam, pose, 1)
        cv2.imwrite(str(root / "work" / "images" / f"im{k}.png"), img[:, :, ::-1])
        images[k] = Image(f"im{k}.png", 1, pose)
    write_colmap_text(Reconstruction({1: cam}, images), root / "work" / "sparse" / "0")
    write_cloud(Cloud(V), root / "ground.ply")
    return root


def mesh(root, out, *extra, cloud=None) -> int:
    return main(["mesh", str(cloud or root / "ground.ply"), "-o", str(out), "--method", "delaunay25d", "--no-quality",
                 "--reconstruction", str(root / "work"), *extra])


def glb_materials(path) -> list[dict]:
    """The ``materials`` of a GLB's JSON chunk."""
    b = path.read_bytes()
    n = struct.unpack("<I", b[12:16])[0]
    return json.loads(b[20:20 + n])["materials"]


def test_two_textured_obj_in_one_folder_keep_their_own_texture(terrain, tmp_path):
    from PIL import Image as PILImage

    from workstation.io.mesh import read_mesh

    assert mesh(terrain, tmp_path / "facade.obj", "--texture-size", "1024") == 0
    assert mesh(terrain, tmp_path / "roof.obj", "--texture-size", "256") == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["facade.mtl", "facade.obj", "facade.png", "roof.mtl", "roof.obj", "roof.png"]
    for stem in ("facade", "roof"):
        mtl = (tmp_path / f"{stem}.mtl").read_text()
        assert f"newmtl {stem}" in mtl and f"map_Kd {stem}.png" in mtl
        obj = (tmp_path / f"{stem}.obj").read_text()
        assert f"mtllib {stem}.mtl" in obj and f"usemtl {stem}" in obj
        with PILImage.open(tmp_path / f"{stem}.png") as im:
            size = im.size
        assert read_mesh(tmp_path / f"{stem}.obj").meta["texture"].shape[1::-1] == size
    with PILImage.open(tmp_path / "facade.png") as a, PILImage.open(tmp_path / "roof.png") as b:
        assert a.size != b.size  # each OBJ reads its own atlas, not the last one written
    rec = json.loads((terrain / "work" / "mesh_roof.json").read_text())
    assert rec["stage"] == "mesh" and [p.rsplit("/", 1)[1] for p in rec["outputs"]] == ["roof.obj", "roof.mtl", "roof.png"]


def test_glb_material_named_after_the_mesh(terrain, tmp_path):
    from workstation.io.mesh import read_mesh

    for stem in ("facade", "roof"):
        assert mesh(terrain, tmp_path / f"{stem}.glb") == 0
        (mat,) = glb_materials(tmp_path / f"{stem}.glb")
        assert mat["name"] == stem
        assert mat["pbrMetallicRoughness"]["baseColorFactor"] == [1.0, 1.0, 1.0, 1.0]  # texture not darkened
        assert "texture" in read_mesh(tmp_path / f"{stem}.glb").meta
    assert sorted(p.name for p in tmp_path.iterdir()) == ["facade.glb", "roof.glb"]


def test_overwrite_rules_cover_the_texture_files_before_any_work(terrain, tmp_path, capsys):
    out = tmp_path / "facade.obj"
    assert mesh(terrain, out) == 0
    assert mesh(terrain, out) == 1  # the mesh exists
    out.unlink()
    (tmp_path / "facade.mtl").unlink()
    png = (tmp_path / "facade.png").read_bytes()
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    rng = np.random.default_rng(1)
    big = tmp_path / "big.ply"  # 200 k points: meshing and texturing them takes seconds of CPU
    write_cloud(Cloud(np.column_stack([rng.uniform(-10, 10, (200_000, 2)), rng.normal(0, 0.1, 200_000)])), big)
    capsys.readouterr()
    t0 = time.process_time()  # CPU seconds of the process: insensitive to other jobs' load
    assert mesh(terrain, out, cloud=big) == 1  # its texture file exists: refused before the cloud is read
    assert time.process_time() - t0 < 1.0
    assert "facade.png" in capsys.readouterr().err
    assert not out.exists() and (tmp_path / "facade.png").read_bytes() == png
    assert mesh(terrain, out, "--overwrite") == 0
    assert out.exists()
