"""Ground filters on absurd parameters and degenerate clouds: refused early or run, never hang."""

import time

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.ground import common
from workstation.ground.methods import ground_filter

from ground_synth import terrain_with_boxes


@pytest.fixture(scope="module")
def terrain():
    xyz, _ = terrain_with_boxes(size=40.0, density=1.0)
    return Cloud(xyz, crs="EPSG:32632")


def test_a_cell_far_too_small_is_refused_before_allocating(terrain):
    t0 = time.perf_counter()
    with pytest.raises(InvalidInputError, match="--cell") as e:
        ground_filter(terrain, "smrf", cell=1e-6)
    assert time.perf_counter() - t0 < 2.0
    assert "--cell" in e.value.hint


def test_far_coordinates_are_refused_naming_the_option():
    xyz = np.array([[0.0, 0.0, 0.0], [1e12, 1e12, 1.0], [5.0, 5.0, 0.2], [3.0, 1.0, 0.1]])
    with pytest.raises(InvalidInputError, match="--cloth-resolution"):
        ground_filter(Cloud(xyz), "csf")


def test_a_window_beyond_the_data_is_clamped_exactly(terrain):
    t0 = time.perf_counter()
    huge = ground_filter(terrain, "smrf", window=1e9)
    assert time.perf_counter() - t0 < 20.0
    reach = ground_filter(terrain, "smrf", window=80.0)  # > the 40 m tile's diagonal in 1 m cells
    assert np.array_equal(huge.attrs["classification"], reach.attrs["classification"])


def test_opening_steps_radii_stop_at_the_grid_diagonal():
    z = np.random.default_rng(0).normal(size=(6, 9))
    (a,) = common.opening_steps(z, 1.0, (1e12,))
    # the unclamped sequence, well past the diagonal (10.8 cells): the same steepest steps
    steepest, last = np.zeros(z.shape), z
    for r in range(1, 31):
        opened = common.open_disk(last, r)
        steepest = np.maximum(steepest, (last - opened) / r)
        last = opened
    assert np.array_equal(a, steepest)


def test_pmf_linear_windows_stop_at_the_grid():
    from workstation.ground.pmf import PMFParams, _windows

    w = _windows(PMFParams(max_window=1e12, exponential=False), shape=(20, 30))
    assert w[-1] >= 61 and len(w) < 40


@pytest.mark.parametrize("method", ["smrf", "pmf", "csf", "ptd"])
@pytest.mark.parametrize("shape", ["identical", "collinear"])
def test_degenerate_clouds_do_not_crash(method, shape):
    n = 200
    if shape == "identical":
        xyz = np.tile([500000.0, 4e6, 100.0], (n, 1))
    else:
        xyz = np.column_stack([500000 + np.linspace(0, 50, n), np.full(n, 4e6), np.full(n, 100.0)])
    out = ground_filter(Cloud(xyz, crs="EPSG:32632"), method)
    assert (np.asarray(out.attrs["classification"]) == 2).any()
