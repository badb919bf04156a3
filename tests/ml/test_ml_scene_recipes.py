"""Scene recipe options for the classifier's training data: houses under trees, large blocks."""

from __future__ import annotations

import numpy as np

from workstation.core.classes import ASPRSClass as C
from workstation.lidar.scene import SceneRecipe, TerrainSpec, build_scene, load_recipe

_FLAT = TerrainSpec(slope_percent=0.0, roughness=0.0, ridge_height=0.0, embankment_height=0.0)


def _recipe(**kw):
    base = dict(extent=(160.0, 160.0), terrain=_FLAT, buildings=0, courtyards=0, heritage=False, trees=0,
                bushes=0, grass_patches=0, cars=0, stream=False, pond=False, powerline=False)
    base.update(kw)
    return SceneRecipe(**base)


def test_houses_get_trees_beside_their_walls():
    s = build_scene(_recipe(houses=4, house_size=(6.0, 8.0), house_height=(2.5, 3.0)), seed=2)
    kinds = s.meta["objects"]
    houses = [int(k) for k, v in kinds.items() if v.startswith("building_")]
    trees = [int(k) for k, v in kinds.items() if v.startswith("tree_")]
    assert len(houses) >= 3 and len(trees) >= len(houses)
    v, f = s.vertices, s.faces
    cen = v[f].mean(axis=1)
    for h in houses:
        hb = cen[s.object_id == h]
        # low eaves: the highest building face is at most eaves + roof rise above the ground
        assert hb[:, 2].max() - hb[:, 2].min() < 3.0 + 8.0 * np.tan(np.radians(45)) / 2 + 1.0
        hc = hb[:, :2].mean(axis=0)
        d = [np.linalg.norm(cen[s.object_id == t][:, :2].mean(axis=0) - hc) for t in trees]
        assert min(d) < 0.5 * np.hypot(8.0, 8.0) + 3.5  # a tree stands next to every house


def test_large_blocks_are_large_flat_and_deterministic():
    r = _recipe(extent=(260.0, 260.0), road=False, large_buildings=1, large_size=(60.0, 70.0),
                large_height=(20.0, 22.0))
    s = build_scene(r, seed=5)
    assert "building_large" in s.meta["objects"].values()
    bld = s.classification == C.BUILDING
    xy = s.vertices[s.faces[bld]].reshape(-1, 3)
    ext = xy[:, :2].max(axis=0) - xy[:, :2].min(axis=0)
    assert ext.max() > 60.0  # at least the block's side
    assert xy[:, 2].max() - xy[:, 2].min() > 20.0
    again = build_scene(r, seed=5)
    assert np.array_equal(again.faces, s.faces) and np.array_equal(again.vertices, s.vertices)


def test_training_recipes_load():
    for name in ("suburb", "industrial"):
        r = load_recipe(name)
        assert r.name == name and (r.houses > 0 or r.large_buildings > 0)
