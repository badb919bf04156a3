"""Synthetic scenes: recipes, determinism, contents and the exported Mesh."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass as C
from workstation.core.errors import InvalidInputError
from workstation.core.products import Mesh
from workstation.lidar.materials import MATERIALS, material_arrays
from workstation.lidar.scene import Scene, build_scene, load_recipe, recipe_names


def test_shipped_recipes_load():
    names = recipe_names()
    for r in ("mixed", "urban", "rural", "forest", "mountain"):
        assert r in names
        assert load_recipe(r).name == r


@pytest.fixture(scope="module")
def demo_scene():
    return build_scene("demo_small", 0)


def test_demo_scene_has_every_kind_of_object(demo_scene):
    s = demo_scene
    classes = set(np.unique(s.classification).tolist())
    for c in (C.GROUND, C.ROAD_SURFACE, C.BUILDING, C.HIGH_VEGETATION, C.MEDIUM_VEGETATION, C.LOW_VEGETATION,
              C.WATER, C.BRIDGE_DECK, C.WIRE_CONDUCTOR, C.TRANSMISSION_TOWER, C.UNCLASSIFIED):
        assert c in classes, c
    kinds = set(s.meta["objects"].values())
    assert {"heritage_church", "car", "bridge", "pylon", "power_line", "terrain"} <= kinds
    assert any(k.startswith("tree_") for k in kinds)
    # every object id in the faces is listed, terrain is object 0
    assert set(np.unique(s.object_id).astype(str)) <= set(s.meta["objects"])
    assert np.all(s.object_id[s.classification == C.GROUND] == 0)


def test_mixed_scene_roof_types_and_terrain_features():
    s = build_scene("mixed", 0)
    kinds = set(s.meta["objects"].values())
    assert {"building_flat", "building_gabled", "building_hipped", "building_courtyard", "pond", "stream"} <= kinds
    lo, hi = s.bounds_local()
    assert hi[0] - lo[0] == pytest.approx(300, abs=1) and hi[1] - lo[1] == pytest.approx(300, abs=1)
    # roofs: gabled / hipped roof faces are sloped, flat roofs horizontal
    tri = s.vertices[s.faces]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    bld = s.classification == C.BUILDING
    tilt = np.degrees(np.arccos(np.abs(n[bld, 2])))
    assert np.any((tilt > 20) & (tilt < 50)) and np.any(tilt < 1) and np.any(tilt > 89)
    # terrain has a steep embankment (> 30 degrees) somewhere and a ditch below its surroundings
    g = s.classification == C.GROUND
    gt = np.degrees(np.arccos(np.abs(n[g, 2])))
    assert gt.max() > 30


def test_mesh_export_round_trip(demo_scene):
    m = demo_scene.to_mesh()
    assert isinstance(m, Mesh) and m.crs == "EPSG:32632"
    assert m.vertices[:, 0].mean() == pytest.approx(500_000, abs=100)
    for k in ("classification", "material", "object_id", "rgb"):
        assert len(m.face_attrs[k]) == m.n_faces
    assert m.face_attrs["material"].max() < len(MATERIALS)
    back = Scene.from_mesh(m, origin=demo_scene.origin)
    np.testing.assert_allclose(back.vertices, demo_scene.vertices, atol=1e-9)
    assert np.array_equal(back.classification, demo_scene.classification)


def test_materials_and_bad_recipe(tmp_path):
    mats = material_arrays(1064)
    water = [m.id for m in MATERIALS if m.name == "water"][0]
    leaves = [m.id for m in MATERIALS if m.name == "leaves"][0]
    assert mats["reflectance"][water] < 0.01 < mats["reflectance"][leaves]
    assert material_arrays(1550)["reflectance"][leaves] < mats["reflectance"][leaves]  # leaf water absorbs at 1550
    bad = tmp_path / "bad.toml"
    bad.write_text('[scene]\nname = "x"\nbuildingz = 3\n')
    with pytest.raises(InvalidInputError, match="buildingz"):
        load_recipe(bad)


def test_save_and_load_scene(tmp_path, demo_scene):
    from workstation.lidar.scene import load_scene, save_scene

    p = save_scene(demo_scene, tmp_path / "scene.npz")
    back = load_scene(p)
    for k in ("vertices", "faces", "classification", "material", "object_id", "face_rgb", "origin"):
        assert np.array_equal(getattr(back, k), getattr(demo_scene, k)), k
    assert back.meta["objects"] == demo_scene.meta["objects"] and back.materials == demo_scene.materials
    with pytest.raises(InvalidInputError):
        save_scene(demo_scene, tmp_path / "scene.ply")


def test_face_parts_split_roofs_walls_trunks_crowns(demo_scene):
    from workstation.lidar.scene import PART_ID

    s = demo_scene
    part = s.part
    bld = s.classification == C.BUILDING
    assert set(np.unique(part[bld]).tolist()) == {PART_ID["roof"], PART_ID["wall"]}
    tri = s.vertices[s.faces[bld & (part == PART_ID["wall"])]]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    assert np.all(np.abs(n[:, 2]) / np.linalg.norm(n, axis=1) <= 0.3 + 1e-9)  # walls are steep
    hv = s.classification == C.HIGH_VEGETATION
    assert {PART_ID["trunk"], PART_ID["crown"]} == set(np.unique(part[hv]).tolist())
    assert np.all(s.classification[part == PART_ID["vehicle"]] == C.UNCLASSIFIED)
    assert "part" in s.to_mesh().face_attrs


def test_new_recipe_options_at_their_defaults_keep_the_scene():
    """A (recipe, seed) pair builds the same scene after recipe options were added."""
    from dataclasses import replace

    from workstation.lidar.scene import SceneRecipe, _recipe_key

    r = SceneRecipe()
    assert "houses" not in _recipe_key(r) and "large_buildings" not in _recipe_key(r)
    assert "houses=3" in _recipe_key(replace(r, houses=3))
    # demo_small as built before the options existed (vertex count of the first release)
    assert build_scene("demo_small", 0).vertices.shape[0] == 58382
