"""The water-surface test (workstation.ground.water): still water among the ground points."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.ground.water import WaterParams, water_surfaces


def pond_scene(seed=0, size=100.0, density=2.0, radius=16.0, noise=0.03, tilt=0.0):
    """Undulating terrain with a round pond (level at z = 100, or tilted by ``tilt``) whose
    banks stand 0.1-0.5 m above it at the shore and rise 10 % beyond. Returns xyz and the
    truth mask."""
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    r = np.hypot(xy[:, 0] - 50, xy[:, 1] - 50)
    pond = r < radius
    z = 100.3 + 0.1 * (r - radius) + 0.2 * np.sin(xy[:, 0] / 15.0)
    z[pond] = 100.0 + tilt * (xy[pond, 0] - 50)
    z += rng.normal(0, noise, n)
    return np.column_stack([xy, z]), pond


def _shore(xyz, radius=16.0):
    """Points within 1 m outside the pond's shore."""
    return np.hypot(xyz[:, 0] - 50, xyz[:, 1] - 50) < radius + 1.0


def test_a_pond_is_found_and_the_banks_stay_ground():
    xyz, pond = pond_scene()
    water, offset = water_surfaces(xyz, np.ones(len(xyz), bool))
    assert water[pond].mean() > 0.95
    assert not water[~pond & ~_shore(xyz)].any()  # at the shore the banks are within 0.1 m of it
    assert (water & ~pond).sum() < 0.01 * pond.sum()
    assert np.abs(offset[water]).max() <= WaterParams().point_tolerance
    assert np.isnan(offset[~water]).all()


def test_only_ground_single_returns_can_be_water():
    xyz, pond = pond_scene(seed=1)
    ground = np.ones(len(xyz), bool)
    ground[::2] = False  # half the points are not ground
    nret = np.ones(len(xyz), np.uint8)
    nret[1::4] = 2  # water under overhanging trees answers as the last of two echoes
    water, _ = water_surfaces(xyz, ground, nret)
    assert not water[~ground].any() and not water[nret > 1].any()
    assert water[pond & ground & (nret == 1)].mean() > 0.9
    # unknown echo counts (0) count as single returns
    water0, _ = water_surfaces(xyz, ground, np.zeros(len(xyz), np.uint8))
    assert water0[pond & ground].mean() > 0.9


@pytest.mark.parametrize("what", ["level plain", "tilted", "small", "no banks below"])
def test_what_is_not_water(what):
    if what == "level plain":  # a level field: no banks rise from it
        rng = np.random.default_rng(2)
        xy = rng.uniform(0, 100, (20000, 2))
        xyz = np.column_stack([xy, 100 + rng.normal(0, 0.03, len(xy))])
    elif what == "tilted":  # the same basin with a 3 % floor: not level over 10 m
        xyz, _ = pond_scene(seed=3, tilt=0.03)
    elif what == "small":  # a pond of 9 m radius: its level core (5 m in from the banks) is under min_area
        xyz, _ = pond_scene(seed=4, radius=9.0)
    else:  # a level terrace with ground below it on one side: the "banks" are not all higher
        rng = np.random.default_rng(5)
        xy = rng.uniform(0, 100, (20000, 2))
        z = np.where(xy[:, 0] < 50, 100.0, 100.0 - 0.2 * (xy[:, 0] - 50))
        xyz = np.column_stack([xy, z + rng.normal(0, 0.03, len(xy))])
    water, _ = water_surfaces(xyz, np.ones(len(xyz), bool))
    assert not water.any()


def test_a_noisier_scan_and_nothing_to_test():
    xyz, pond = pond_scene(seed=6, noise=0.06, density=4.0)
    water, _ = water_surfaces(xyz, np.ones(len(xyz), bool))
    assert water[pond].mean() > 0.85 and not water[~pond & ~_shore(xyz)].any()
    none, off = water_surfaces(xyz, np.zeros(len(xyz), bool))
    assert not none.any() and np.isnan(off).all()
    empty, _ = water_surfaces(np.zeros((0, 3)), np.zeros(0, bool))
    assert empty.shape == (0,)


def test_classify_water_stage_keeps_other_classes_and_converts_feet():
    from workstation.core.classes import ASPRSClass as C
    from workstation.core.cloud import Cloud
    from workstation.core.errors import StageError
    from workstation.ground.water import classify_water

    xyz, pond = pond_scene(seed=11)
    cls = np.full(len(xyz), C.GROUND, np.uint8)
    cls[::7] = C.HIGH_VEGETATION  # not ground: never water
    ft = 1200 / 3937  # the same scene in US survey feet (Oregon Lambert)
    for crs, scale in (("EPSG:32632", 1.0), ("EPSG:2992", 1 / ft)):
        c = Cloud(xyz * scale, {"classification": cls}, crs=crs)
        out = classify_water(c)
        got = np.asarray(out.attrs["classification"])
        assert (got[pond & (cls == C.GROUND)] == C.WATER).mean() > 0.95
        np.testing.assert_array_equal(got[cls != C.GROUND], cls[cls != C.GROUND])
        assert out.history[-1].params["water_points"] == int((got == C.WATER).sum())
    with pytest.raises(StageError):
        classify_water(Cloud(xyz))
