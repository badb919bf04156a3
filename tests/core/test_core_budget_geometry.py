"""Size estimates before allocation (core.budget) and geometry checks before C++ (core.geometry)."""

import time

import numpy as np
import pytest

from workstation.core.budget import CELLS_PER_POINT, MIN_CELLS, cells_for, check_grid, max_cells
from workstation.core.errors import InvalidInputError
from workstation.core.geometry import affine_dimension, require_spread


def test_petabyte_grid_refused_in_milliseconds_with_a_fitting_hint():
    t0 = time.perf_counter()
    with pytest.raises(InvalidInputError) as e:
        check_grid(cells_for(1e12, 1.0), cells_for(1e12, 1.0), what="test grid", option="--cell", cell=1.0)
    assert time.perf_counter() - t0 < 1.0  # a petabyte grid would take hours to allocate
    assert e.value.field == "--cell" and "EiB" in str(e.value)
    hinted = float(e.value.hint.split("--cell ")[1].split()[0])
    # the hinted cell fits: the same extent at that cell passes the same check
    check_grid(cells_for(1e12, hinted), cells_for(1e12, hinted), what="test grid", option="--cell")


def test_point_bound_caps_cells_per_point_above_the_floor():
    n = 100_000
    assert max_cells(8, n_points=n) <= CELLS_PER_POINT * n
    check_grid(1000, 1000, what="g", option="--cell", n_points=n)  # 10 cells a point
    with pytest.raises(InvalidInputError, match="100000 points"):
        check_grid(10_000, 10_000, what="g", option="--cell", n_points=n)
    check_grid(MIN_CELLS ** 0.5, MIN_CELLS ** 0.5, what="g", option="--cell", n_points=3)  # the floor


def test_infinite_or_nan_sizes_are_refused():
    for rows in (np.inf, np.nan):
        with pytest.raises(InvalidInputError):
            check_grid(rows, 10, what="g", option="--cell")
    assert cells_for(10.0, 0.0) == np.inf


@pytest.mark.parametrize("points, dim", [
    (np.tile([5e5, 4e6, 100.0], (50, 1)), 0),
    (np.column_stack([np.linspace(0, 9, 50), 2 * np.linspace(0, 9, 50), np.full(50, 3.0)]) + [5e5, 4e6, 0], 1),
    (np.column_stack([np.random.default_rng(0).uniform(0, 50, (50, 2)), np.zeros(50)]) + [5e5, 4e6, 100], 2),
    (np.random.default_rng(1).uniform(0, 1, (50, 3)), 3),
])
def test_affine_dimension_of_degenerate_sets_far_from_the_origin(points, dim):
    R = np.linalg.qr(np.random.default_rng(2).normal(size=(3, 3)))[0]
    assert affine_dimension(points @ R.T) == dim


def test_require_spread_names_the_shape_and_the_file():
    line = np.column_stack([np.arange(20.0), np.arange(20.0), np.zeros(20)])
    with pytest.raises(InvalidInputError, match="collinear") as e:
        require_spread(line, 2, what="meshing", path="bad.ply", field="xyz")
    assert "bad.ply" in str(e.value)
    with pytest.raises(InvalidInputError, match="at least 10 points"):
        require_spread(line[:5], 2, what="meshing", min_points=10)
    require_spread(np.vstack([line, [[0.0, 1.0, 0.0]]]), 2, what="meshing")
