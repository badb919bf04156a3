"""Scene recipe options for the classifier's training data: houses under trees, large blocks."""

from __future__ import annotations

import numpy as np
import pytest

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


def _earthwork_frame(e: dict, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distance across an earthwork's bent centre line and position along it (scene meta)."""
    p, d = np.array(e["p"]), np.array(e["d"])
    s = (xy - p) @ d
    signed = (xy - p) @ np.array([-d[1], d[0]])
    return np.abs(signed - e["amp"] * np.sin(2 * np.pi * s / e["wavelength"] + e["phase"])), s


def _crests(s, w: dict, extent, cen: np.ndarray):
    """Masks of the points ``cen`` on an earthwork's crest (floor) at full height inside the
    scene, on its feet on both sides and on its road, and their positions along it."""
    dist, along = _earthwork_frame(w, cen[:, :2])
    inside = (np.abs(cen[:, :2]) < np.array(extent) / 2 - 5.0).all(axis=1)
    lo = -np.inf if w["s0"] is None else w["s0"] + w["ramp"]
    hi = np.inf if w["s1"] is None else w["s1"] - w["ramp"]
    full = inside & (along > lo) & (along < hi)
    foot = w["crest"] / 2 + w["side"] * w["height"]
    return (full & (dist < w["crest"] / 2 - 0.5), full & (dist > foot + 1.0) & (dist < foot + 4.0),
            full & (dist < w["road_half_width"] - 0.5), along)


def _above_plane(top: np.ndarray, base: np.ndarray) -> float:
    """Median height of the points ``top`` above the least-squares plane of the points ``base``."""
    A = np.column_stack([base[:, :2], np.ones(len(base))])
    coef = np.linalg.lstsq(A, base[:, 2], rcond=None)[0]
    return float(np.median(top[:, 2] - np.column_stack([top[:, :2], np.ones(len(top))]) @ coef))


def test_earthworks_recipe_has_ground_embankments_and_cuttings():
    r = load_recipe("earthworks")
    s = build_scene(r, seed=3)
    works = s.meta["earthworks"]
    assert [w["kind"] for w in works] == ["embankment"] * r.embankments + ["cutting"] * r.cuttings
    terrain = s.object_id == 0
    cls = s.classification[terrain]
    assert np.isin(cls, (C.GROUND, C.ROAD_SURFACE)).all()
    cen = s.vertices[s.faces[terrain]].mean(axis=1)
    seen = 0
    for w in works:
        assert r.earthwork_height[0] <= w["height"] <= r.earthwork_height[1]
        assert r.earthwork_crest[0] <= w["crest"] <= r.earthwork_crest[1]
        assert r.earthwork_side[0] <= w["side"] <= r.earthwork_side[1]
        crest, feet, road, _ = _crests(s, w, r.extent, cen)
        seen += crest.sum() > 50
        if w["road_half_width"] > 0 and road.sum() > 50:  # the road or track on the crest
            assert (cls[road] == C.ROAD_SURFACE).mean() > 0.95
    assert seen >= 3  # most of them cross the scene at full height


def test_earthwork_crests_stand_their_height_above_the_feet():
    """On a plain slope (no relief, water or road) every crest stands its height above its
    feet's plane (a cutting's floor below) in most 15 m bins along it (crossings take a few)."""
    from dataclasses import replace

    r = load_recipe("earthworks")
    r = replace(r, terrain=replace(r.terrain, relief=0.0, roughness=0.0, breakline_slope_percent=0.0),
                road=False, stream=False, buildings=0, houses=0, trees=0, bushes=0, grass_patches=0, cars=0)
    for seed in (0, 1):
        s = build_scene(r, seed=seed)
        v = s.vertices[np.unique(s.faces[s.object_id == 0])]  # the terrain's grid nodes
        for w in s.meta["earthworks"]:
            crest, feet, _, along = _crests(s, w, r.extent, v)
            if crest.sum() < 50:
                continue
            bins = np.floor(along / 15.0)
            common = np.intersect1d(bins[crest], bins[feet])
            rise = [_above_plane(v[crest & (bins == b)], v[feet & (bins == b)]) for b in common]
            sign = 1.0 if w["kind"] == "embankment" else -1.0
            assert np.mean(np.abs(sign * np.array(rise) - w["height"]) < 0.3) > 0.5, (w, rise)


@pytest.mark.parametrize("field, value", [("earthwork_side", (0.0, 2.0)), ("earthwork_height", (0.0, 3.0)),
                                          ("earthwork_crest", (5.0, 2.0)), ("embankments", -1),
                                          ("earthwork_side", (1.0, float("nan"))), ("earthwork_height", (1.0, float("inf")))])
def test_earthwork_ranges_that_give_no_shape_are_refused(field, value):
    from dataclasses import replace

    from workstation.core.errors import InvalidInputError
    from workstation.lidar.scene import build_scene, load_recipe

    r = replace(load_recipe("earthworks"), extent=(60.0, 60.0), **{field: value})
    with pytest.raises(InvalidInputError) as e:
        build_scene(r, seed=0)
    assert e.value.field == field
