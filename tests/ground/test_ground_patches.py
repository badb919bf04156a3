"""The raised-patch test (workstation.ground.patches) and its use by ``auto``."""

from __future__ import annotations

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.core.cloud import Cloud
from workstation.ground.auto import AutoParams, auto_ground
from workstation.ground.methods import ground_filter
from workstation.ground.patches import PatchParams, raised_patches


def _hillside(seed=0, size=80.0, density=2.0, slope=0.35):
    """A steep, undulating hillside (35 % slope) with a 2 m bump and a 1.5 m pit, all terrain."""
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    z = slope * xy[:, 0] + 0.8 * np.sin(xy[:, 1] / 9.0) + rng.normal(0, 0.05, n)
    z += 2.0 * np.exp(-((xy[:, 0] - 20) ** 2 + (xy[:, 1] - 60) ** 2) / 30.0)
    z -= 1.5 * np.exp(-((xy[:, 0] - 60) ** 2 + (xy[:, 1] - 20) ** 2) / 20.0)
    return np.column_stack([xy, z])


def test_roofs_accepted_as_ground_are_taken_out():
    xyz, truth = terrain_with_boxes()
    local = xyz - xyz.min(axis=0)
    everything = np.ones(len(xyz), bool)
    everything[xyz[:, 2] < 80] = False  # the low outlier is not what this test is about
    out = raised_patches(local, everything)
    # both roofs go, their edges too (1 m cells there hold roof and terrain), the terrain stays
    assert not out[~truth & everything].any()
    assert out[truth].all()


def test_terrain_patches_are_kept_on_a_steep_hillside():
    xyz = _hillside()
    # 4 m gaps in the ground (as a filter leaves them under rows of trees): across the slope a
    # gap is a 1.4 m step, so the hillside falls apart into strips, each with a step up and down
    ground = xyz[:, 0] % 12 >= 4
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    from workstation.ground.retile import full_edges

    pts = xyz[ground]
    src, dst, _ = full_edges(pts[:, :2])
    joined = np.abs(pts[src, 2] - pts[dst, 2]) < PatchParams().step
    graph = coo_matrix((np.ones(joined.sum()), (src[joined], dst[joined])), shape=(len(pts),) * 2)
    assert connected_components(graph, directed=False)[0] >= 5
    assert raised_patches(xyz, ground).sum() == ground.sum()
    # without the test of the drops' directions the top strip (drops on its downhill side
    # only) would go, and then, pass after pass, the next one down the hill
    top = xyz[:, 0] >= 76
    without = raised_patches(xyz, ground, PatchParams(max_resultant=1.0))
    assert not without[top & ground].any() and without.sum() < 0.95 * ground.sum()


@pytest.mark.parametrize("shape", ["cone", "ridge"])
def test_steep_peaks_and_ridges_are_kept(shape):
    """A 56° cone or knife-edge ridge (slope 1.5) at 10 points/m²: the crest drops on all
    sides, by more than 1 m from one 1 m cell to the next only where the slope exceeds 1."""
    rng = np.random.default_rng(0)
    n = 36000
    xy = rng.uniform(0, 60, (n, 2))
    r = np.hypot(xy[:, 0] - 30, xy[:, 1] - 30) if shape == "cone" else np.abs(xy[:, 0] - 30)
    xyz = np.column_stack([xy, 100 - 1.5 * r - 0.05 * xy[:, 1] + rng.normal(0, 0.05, n)])
    g = np.ones(n, bool)
    assert raised_patches(xyz, g).all()
    # 2 m cells see the crest as a raised patch
    assert not raised_patches(xyz, g, PatchParams(cell=2.0)).all()


def test_a_roof_on_a_roof_goes_in_the_second_pass():
    xyz, truth = terrain_with_boxes()
    local = xyz - xyz.min(axis=0)
    keep = local[:, 2] > 10  # without the low outlier
    local, truth = local[keep], truth[keep]
    # a 3 m tower on the middle of the 9 m roof
    tower = (local[:, 0] > 49) & (local[:, 0] < 55) & (local[:, 1] > 52) & (local[:, 1] < 56)
    local[tower, 2] += 3.0
    ground = np.ones(len(local), bool)
    one = raised_patches(local, ground, PatchParams(max_passes=1))
    assert one[~truth & ~tower].mean() > 0.3  # the tower was the raised patch; much of the roof stays
    assert not one[tower].any()
    both = raised_patches(local, ground)
    assert not both[~truth].any() and both[truth].all()


def test_off_and_degenerate_inputs():
    xyz, _ = terrain_with_boxes()
    g = np.ones(len(xyz), bool)
    assert raised_patches(xyz, g, PatchParams(max_passes=0)).all()
    assert raised_patches(xyz[:3], g[:3]).all()
    line = np.column_stack([np.arange(10.0), np.zeros(10), np.zeros(10)])
    assert raised_patches(line, np.ones(10, bool)).all()


def test_auto_runs_the_test_and_can_leave_it_out():
    xyz, truth = terrain_with_boxes()
    local = xyz - xyz.min(axis=0)
    on = auto_ground(local, AutoParams(risers=False))
    off = auto_ground(local, AutoParams(raised_patches=False, risers=False))
    assert (on <= off).all()  # the test only takes ground away
    out = ground_filter(Cloud(xyz), "auto", raised_patches=False)
    assert ((np.asarray(out.attrs["classification"]) == 2) == off).sum() > 0.99 * len(xyz)
