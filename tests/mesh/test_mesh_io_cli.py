"""Mesh files (PLY, OBJ+MTL+texture, GLB/glTF, OFF) and the `ws mesh` command."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import OutputExistsError, UnsupportedFormatError
from workstation.core.products import Mesh
from workstation.io.mesh import read_mesh, write_mesh

V = np.array([[500000.123, 4000000.456, 100.789], [500001.0, 4000000.0, 101.0],
              [500000.0, 4000001.0, 102.0], [500001.5, 4000001.5, 99.0]])
F = np.array([[0, 1, 2], [1, 3, 2]])
RGB = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255], [10, 20, 30]], np.uint8)


@pytest.mark.parametrize("ext,tol", [("ply", 0.0), ("obj", 1e-9), ("glb", 1e-7), ("gltf", 1e-7), ("off", 1e-9)])
def test_round_trip_keeps_coordinates_faces_colours(tmp_path, ext, tol):
    m = Mesh(V, F, {"rgb": RGB}, crs="EPSG:32632")
    p = write_mesh(m, tmp_path / f"a.{ext}")
    r = read_mesh(p)
    assert np.abs(r.vertices - V).max() <= tol  # projected coordinates keep sub-mm precision
    assert r.faces.tolist() == F.tolist()
    if ext != "off":
        assert r.vertex_attrs["rgb"].tolist() == RGB.tolist()


def test_ply_keeps_normals_and_u16_colours(tmp_path):
    n = np.tile(np.float32([0, 0, 1]), (4, 1))
    m = Mesh(V, F, {"rgb": RGB.astype(np.uint16) * 257, "normal": n})
    r = read_mesh(write_mesh(m, tmp_path / "n.ply"))
    assert np.allclose(r.vertex_attrs["normal"], n)
    assert r.vertex_attrs["rgb"].tolist() == RGB.tolist()
    assert b"double x" in (tmp_path / "n.ply").read_bytes()[:400]


def test_obj_with_texture_writes_mtl_and_png(tmp_path):
    uv = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], np.float32)
    tex = np.zeros((8, 8, 3), np.uint8)
    tex[:4] = [200, 10, 10]
    write_mesh(Mesh(V, F, {"uv": uv}, meta={"texture": tex}), tmp_path / "t.obj")
    assert (tmp_path / "t.mtl").exists()
    assert any(p.suffix == ".png" for p in tmp_path.iterdir())
    r = read_mesh(tmp_path / "t.obj")
    assert np.abs(r.vertex_attrs["uv"] - uv).max() < 1e-6
    assert r.meta["texture"].shape == (8, 8, 3) and r.meta["texture"][0, 0].tolist() == [200, 10, 10]


def test_refuses_overwrite_and_unknown_extension(tmp_path):
    m = Mesh(V, F)
    write_mesh(m, tmp_path / "a.ply")
    before = (tmp_path / "a.ply").read_bytes()
    with pytest.raises(OutputExistsError):
        write_mesh(Mesh(V + 1, F), tmp_path / "a.ply")
    assert (tmp_path / "a.ply").read_bytes() == before
    with pytest.raises(UnsupportedFormatError):
        write_mesh(m, tmp_path / "a.xyz")
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporary left


def test_ws_mesh_cli_poisson_and_delaunay(tmp_path, capsys):
    from workstation.cli.main import main
    from workstation.io import write_cloud

    i = np.arange(3000) + 0.5
    phi = np.arccos(1 - 2 * i / 3000)
    th = np.pi * (1 + 5 ** 0.5) * i
    xyz = 600_000 + 3 * np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    xyz = np.round(xyz, 3)
    src = tmp_path / "s.laz"
    rgb = np.full((3000, 3), 40000, np.uint16)
    write_cloud(Cloud(xyz, {"rgb": rgb}), src)
    out = tmp_path / "s.glb"
    rc = main(["mesh", str(src), "-o", str(out), "--depth", "6", "--trim-quantile", "0", "--target-faces", "800",
               "--viewpoint", "600000", "600000", "600000", "--threads", "1", "--json"])
    assert rc == 0
    res = json.loads(capsys.readouterr().out)
    assert res["faces"] <= 800 and res["quality"]["watertight"]
    assert [s["name"] for s in res["steps"]][:4] == ["normals", "poisson", "clean", "decimate"]
    m = read_mesh(out)
    assert m.n_faces == res["faces"]
    assert np.all(m.vertex_attrs["rgb"] == round(40000 / 65535 * 255))
    # inward viewpoint: normals point in, Poisson turns the surface inside out; the sphere is still found
    assert np.abs(np.linalg.norm(m.vertices - 600_000, axis=1) - 3).max() < 0.1
    assert main(["mesh", str(src), "-o", str(out)]) == 1  # exists, no --overwrite
    g = np.stack(np.meshgrid(np.arange(20.0), np.arange(20.0)), -1).reshape(-1, 2)
    write_cloud(Cloud(np.column_stack([g + 500_000, 0.1 * g[:, 0]])), tmp_path / "t.las")
    rc = main(["mesh", str(tmp_path / "t.las"), "-o", str(tmp_path / "t.ply"), "--method", "delaunay25d", "--json"])
    assert rc == 0
    assert json.loads(capsys.readouterr().out)["faces"] == 2 * 19 * 19


def test_pymeshlab_interop_round_trip_keeps_precision_and_colours():
    from workstation.interop.pymeshlab import (cloud_to_pymeshlab, mesh_to_pymeshlab, pymeshlab_to_cloud,
                                               pymeshlab_to_mesh, rgb_to_u8)

    rgb16 = (RGB.astype(np.uint16) * 257)
    c = Cloud(V, {"rgb": rgb16, "normal": np.tile(np.float32([0, 0, 1]), (4, 1))}, crs="EPSG:32632")
    m, origin = cloud_to_pymeshlab(c)
    assert np.all(np.abs(m.vertex_matrix()) < 10)  # shifted to a local origin
    back = pymeshlab_to_cloud(m, origin, template=c)
    assert np.abs(back.xyz - V).max() < 1e-9 and back.crs == c.crs
    assert np.abs(back.attrs["rgb"].astype(int) - rgb16).max() <= 1
    mm, o2 = mesh_to_pymeshlab(Mesh(V, F, {"rgb": RGB}))
    r = pymeshlab_to_mesh(mm, o2)
    assert np.abs(r.vertices - V).max() < 1e-9 and r.faces.tolist() == F.tolist()
    assert r.vertex_attrs["rgb"].tolist() == RGB.tolist()
    assert rgb_to_u8(np.array([[255, 128, 0]], np.uint16)).tolist() == [[255, 128, 0]]  # 8-bit values in u16
