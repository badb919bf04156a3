"""The district-wide pass of the footprints: banded smoothing on threads, nearest regions from a
k-d tree of edge cells, and the points' direction from one GEOS line string."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.footprints import (FootprintParams, _by_bands, _nearest_label, _points_direction, _smooth,
                                              district_components, extract_footprints)


def test_banded_smoothing_is_the_whole_rasters_bit_for_bit():
    """Bands of rows smoothed on threads with the kernel's reach around them give the same bits
    as one gaussian_filter over the raster, whatever the number of bands."""
    from scipy import ndimage

    counts = np.random.default_rng(0).poisson(0.3, (700, 300)).astype(float)
    whole = ndimage.gaussian_filter(counts, 5.0, mode="constant", truncate=3.0)
    for threads in (2, 3):
        assert np.array_equal(_smooth(counts, 5.0, threads), whole)


@pytest.mark.parametrize("threads", [2, 3])
def test_banded_core_and_edge_filters_are_the_whole_rasters(threads):
    """The roof cores' minimum filter (reflecting edges) and the edge cells' binary erosion (an
    empty border) by bands of rows give the whole raster's result, whatever the number of bands."""
    from scipy import ndimage

    noise = ndimage.gaussian_filter(np.random.default_rng(2).random((500, 170)), 8.0)
    mask = noise > np.median(noise)  # blobs, some wider than the filter
    u8 = mask.view(np.uint8)
    whole = ndimage.minimum_filter(u8, size=21)
    assert whole.any() and not whole.all()
    assert np.array_equal(_by_bands(lambda a: ndimage.minimum_filter(a, size=21), u8, 11, threads), whole)
    eroded = ndimage.binary_erosion(mask)
    assert np.array_equal(_by_bands(ndimage.binary_erosion, mask, 2, threads), eroded)


def test_nearest_region_agrees_with_the_distance_transform():
    """Every cell gets the label of the nearest labelled cell within the reach, as the feature
    transform of scipy gives it (regions far enough apart that no cell is equidistant)."""
    from scipy import ndimage

    labels = np.zeros((60, 80), np.int64)
    labels[5:20, 5:30] = 1
    labels[35:55, 10:25] = 2
    labels[10:50, 50:70] = 3
    labels[40:45, 52:56] = 0  # a hole: its cells take the surrounding label
    rows, cols = np.divmod(np.arange(labels.size), labels.shape[1])
    dist, (ii, jj) = ndimage.distance_transform_edt(labels == 0, return_indices=True)
    want = (labels[ii, jj] * (dist <= 4.0)).ravel()
    got = _nearest_label(labels, rows, cols, 4.0, threads=2)
    assert np.array_equal(got, want)
    assert set(np.unique(got)) == {0, 1, 2, 3}


def test_nearest_region_between_two_regions_within_reach():
    """Two regions 5 cells apart, both within the reach of the cells between them: a cell off
    the middle takes the nearer region (2 cells against 4; below region 2's end, 2.8 diagonally
    against 4), as the distance transform says for every cell not equidistant from both."""
    from scipy import ndimage

    labels = np.zeros((30, 30), np.int64)
    labels[5:25, 5:10] = 1   # columns 5-9
    labels[10:20, 15:20] = 2  # columns 15-19: columns 10-14 lie between
    got = _nearest_label(labels, np.array([12, 12, 21, 21]), np.array([11, 13, 11, 13]), 4.0)
    assert got.tolist() == [1, 2, 1, 2]
    rows, cols = np.divmod(np.arange(labels.size), labels.shape[1])
    d1 = ndimage.distance_transform_edt(labels != 1)
    d2 = ndimage.distance_transform_edt(labels != 2)
    sure = (np.abs(d1 - d2) > 1e-9).ravel()
    dist, (ii, jj) = ndimage.distance_transform_edt(labels == 0, return_indices=True)
    want = (labels[ii, jj] * (dist <= 4.0)).ravel()
    full = _nearest_label(labels, rows, cols, 4.0)
    assert np.array_equal(full[sure], want[sure]) and {1, 2} <= set(full[sure & (cols > 9) & (cols < 15)])


@pytest.mark.parametrize("decimals", [None, 2])
def test_points_direction_equals_the_multipoints(decimals):
    """The line string of the points has the rectangle of their multipoint (random and
    centimetre-rounded points, which have many collinear hull vertices)."""
    import shapely

    rng = np.random.default_rng(1)
    for _ in range(200):
        pts = rng.uniform(0, rng.uniform(3, 30), (int(rng.integers(5, 800)), 2)) @ rng.normal(size=(2, 2))
        pts = pts + 5e5 if decimals is None else np.round(pts + 5e5, decimals)
        rect = np.asarray(shapely.minimum_rotated_rectangle(shapely.MultiPoint(pts)).exterior.coords)
        assert _points_direction(pts) == math.atan2(*(rect[1] - rect[0])[::-1])


def test_threads_do_not_change_the_footprints():
    xyz, cls, _ = synth.district(6, seed=4, density=8.0)
    xy = xyz[cls == 6][:, :2]
    one = district_components(xy, FootprintParams(), threads=1)
    two = district_components(xy, FootprintParams(), threads=2)
    assert one.spacing == two.spacing and one.ref == two.ref and np.array_equal(one.point_label, two.point_label)
    assert all(np.array_equal(a.outline_field(), b.outline_field()) and np.array_equal(a.origin, b.origin)
               for a, b in zip(one.components, two.components))
    fps, owner = extract_footprints(xy)
    assert len(fps) == len(one.components) == 6
    assert np.array_equal(owner >= 0, one.point_label > 0)


def test_assignment_reach_covers_a_corner_beyond_the_half_density_line():
    """On a uniform roof (a lattice at the spacing) the level-0.5 line of the smoothed density
    passes a right-angled corner at sqrt(2) t CORNER_RADIUS spacings, Phi(t)^2 = 1/2 (1.93
    spacings), where the corner's own points lie; the assignment reach leaves two half-spacing
    deviations of the line beyond that."""
    from statistics import NormalDist

    from workstation.buildings.footprints import ASSIGN_REACH, CORNER_RADIUS, density_field, trace_outline

    s = 0.5
    g = np.arange(0.0, 20.0, s) + s / 2
    xy = np.column_stack([a.ravel() for a in np.meshgrid(g, g)])
    field, origin, cell, _ = density_field(xy, s)
    ring = trace_outline(field, origin, cell)
    # each point counts at the centre of its cell, half a cell up and right of the lattice's own
    corner = float(np.hypot(*(ring - cell / 2).T).min())
    assert corner == pytest.approx(math.sqrt(2) * NormalDist().inv_cdf(math.sqrt(0.5)) * CORNER_RADIUS * s, abs=0.02)
    assert ASSIGN_REACH * s == pytest.approx(corner + 2 * 0.5 * s, abs=0.02)


def test_given_footprints_over_one_spot_of_building_points_give_a_clear_error():
    # 20 building points on one spot have no spacing: a StageError naming the cause, not a
    # NaN cell deep in the models
    from workstation.buildings.pipeline import reconstruct_buildings
    from workstation.core.errors import StageError

    rng = np.random.default_rng(0)
    ground = np.column_stack([rng.uniform(0, 40, (2000, 2)), np.zeros(2000)])
    xyz = np.vstack([ground, np.tile([[20.0, 20.0, 8.0]], (20, 1))])
    cls = np.r_[np.full(2000, 2), np.full(20, 6)].astype(np.uint8)
    with pytest.raises(StageError, match="fewer than two distinct positions"):
        reconstruct_buildings(xyz, cls, footprints=[np.array([[10.0, 10], [30, 10], [30, 30], [10, 30]])])
