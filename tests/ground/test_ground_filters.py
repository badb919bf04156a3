"""Each ground filter on a small synthetic terrain with box buildings and a low outlier."""

from __future__ import annotations

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import StageError
from workstation.ground.evaluate import ground_errors
from workstation.ground.methods import METHOD_NAMES, ground_filter, make_params


@pytest.fixture(scope="module")
def scene():
    xyz, truth = terrain_with_boxes(seed=3)
    n = xyz.shape[0]
    rng = np.random.default_rng(0)
    cloud = Cloud(xyz, {"intensity": rng.integers(0, 60000, n), "gps_time": np.arange(n, dtype=float)},
                  crs="EPSG:32632")
    return cloud, truth


# total error each method reaches on the synthetic scene (fails when a filter breaks)
LIMITS = {"smrf": 0.02, "csf": 0.05, "pmf": 0.05, "ptd": 0.05, "auto": 0.02, "lowest": 0.5, "local_min": 0.1}


@pytest.mark.parametrize("method", METHOD_NAMES)
def test_filter_separates_boxes(scene, method):
    cloud, truth = scene
    out = ground_filter(cloud, method)
    cls = np.asarray(out.attrs["classification"])
    assert set(np.unique(cls)) <= {1, 2, 7}
    e = ground_errors(truth, cls == ASPRSClass.GROUND)
    assert e.total_error < LIMITS[method], (method, e)
    # the 30 m deep outlier is never ground: the low-noise step makes it class 7, and only it
    assert cls[-1] == ASPRSClass.LOW_POINT
    assert np.count_nonzero(cls == ASPRSClass.LOW_POINT) == 1
    # attributes kept, input untouched
    assert np.array_equal(out.attrs["intensity"], cloud.attrs["intensity"])
    assert "classification" not in cloud.attrs
    assert out.history[-1].stage.startswith("ground.")


def test_roofs_are_not_ground_with_smrf(scene):
    cloud, truth = scene
    cls = np.asarray(ground_filter(cloud, "smrf").attrs["classification"])
    roof = ~truth
    roof[-1] = False
    assert np.mean(cls[roof] == ASPRSClass.GROUND) < 0.02
    assert np.mean(cls[truth] == ASPRSClass.GROUND) > 0.97


def test_smrf_trend_slope_keeps_a_ridge_and_still_finds_the_roof():
    # a sharp ridge with flanks of slope 0.7 and a flat-roofed box 8 m above the upper flank
    rng = np.random.default_rng(3)
    xy = rng.uniform(0, 80, (12800, 2))
    z = 0.7 * (40 - np.abs(xy[:, 0] - 40)) + rng.normal(0, 0.03, len(xy))
    box = (xy[:, 0] > 52) & (xy[:, 0] < 64) & (xy[:, 1] > 30) & (xy[:, 1] < 42)
    z[box] = 0.7 * 28 + 8.0 + rng.normal(0, 0.03, box.sum())
    cloud = Cloud(np.column_stack([xy + [500000, 4e6], z + 100]))
    ridge = ~box & (np.abs(xy[:, 0] - 40) < 5)
    fixed = np.asarray(ground_filter(cloud, "smrf").attrs["classification"]) == ASPRSClass.GROUND
    trend = np.asarray(ground_filter(cloud, "smrf", trend_slope=1.0).attrs["classification"]) == ASPRSClass.GROUND
    # PDAL's fixed slope 0.15 cuts the ridge as an object; the terrain-following test keeps it
    assert np.mean(~fixed[ridge]) > 0.5
    assert np.mean(~trend[ridge]) < 0.25
    assert np.mean(~trend[~box]) < 0.03
    # the roof is still an object in both
    assert not fixed[box].any() and not trend[box].any()


def test_progressive_steps_give_each_tolerance_the_flags_of_its_own_opening_sequence():
    # one opening sequence serves the fixed and the per-cell slope tests: the flags are those
    # of the textbook loop run for each tolerance
    from workstation.ground import common
    from workstation.ground.smrf import progressive_filter

    rng = np.random.default_rng(8)
    surface = np.cumsum(rng.normal(0, 0.3, (60, 70)), axis=1) + rng.exponential(0.5, (60, 70))
    surface[20:30, 10:25] += 6.0  # a building

    def textbook(slope):
        last, obj = surface, np.zeros(surface.shape, bool)
        for r in range(1, 9):
            opened = common.open_disk(last, r)
            obj |= (last - opened) > slope * 0.5 * r
            last = opened
        return obj

    per_cell = rng.uniform(0.1, 1.5, surface.shape)
    for slope in (0.15, 0.7, per_cell):
        want = textbook(slope)
        assert want.any() and not want.all()
        assert np.array_equal(progressive_filter(surface, 0.5, slope, 4.0), want)


@pytest.mark.parametrize("shape", [(1, 1), (1, 9), (9, 1), (23, 31), (64, 40)])
def test_disk_erosion_and_dilation_equal_scipy_with_the_disk_footprint(shape):
    # the chord-by-chord filter gives scipy's grey erosion/dilation by the disk footprint,
    # edges extended outward, value for value (minima and maxima are exact)
    from scipy import ndimage

    from workstation.ground import common

    rng = np.random.default_rng(sum(shape))
    a = np.cumsum(rng.normal(0, 1, shape), axis=0) + rng.exponential(1.0, shape)
    a[rng.random(shape) < 0.05] = np.inf
    for r in (1, 2, 3, 7, 12, 40):
        fp = common.disk(r)
        assert np.array_equal(common._disk_filter(a, r, True), ndimage.grey_erosion(a, footprint=fp, mode="nearest"))
        b = np.where(np.isinf(a), -np.inf, a)
        assert np.array_equal(common._disk_filter(b, r, False), ndimage.grey_dilation(b, footprint=fp, mode="nearest"))


def test_barycentric_transforms_are_scipys_and_mark_degenerate_triangles():
    from scipy.spatial import Delaunay

    from workstation.ground import common

    rng = np.random.default_rng(4)
    pts = np.vstack([rng.uniform(0, 50, (300, 2)), np.mgrid[0:5, 0:5].reshape(2, -1).T + 60.0])
    tri = Delaunay(pts)
    got = common.barycentric_transforms(tri.points, tri.simplices)
    assert np.allclose(got, tri.transform, rtol=1e-9, atol=1e-12, equal_nan=True)
    # three collinear corners: no transform, as scipy marks them
    flat = common.barycentric_transforms(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]), np.array([[0, 1, 2]]))
    assert np.isnan(flat).all()


def test_inpaint_is_linear_over_the_tin_of_the_border_cells():
    # a plane with holes comes back as the plane (up to the corners' tie-breaking jitter of
    # 1e-4 cell), and the grid's own cells are kept
    from workstation.ground import common

    rr, cc = np.mgrid[0:40, 0:50]
    plane = 0.3 * rr - 0.2 * cc + 5.0
    grid = plane.copy()
    grid[5:15, 8:30] = np.nan
    grid[25:38, 2:6] = np.nan
    out = common.inpaint(grid)
    assert np.allclose(out, plane, atol=1e-3)
    assert np.array_equal(out[~np.isnan(grid)], grid[~np.isnan(grid)])


def test_inpaint_with_fast_transforms_equals_scipys_own(monkeypatch):
    # a curved surface with holes: the vectorised transforms inpaint exactly what scipy's own
    # (computed when its private cache is left empty) give
    from workstation.ground import common

    rr, cc = np.mgrid[0:60, 0:70].astype(float)
    grid = 0.01 * (rr - 30) ** 2 + 0.02 * (cc - 20) ** 2
    grid[10:25, 12:40] = np.nan
    grid[np.random.default_rng(1).random(grid.shape) < 0.3] = np.nan
    fast = common.inpaint(grid)
    monkeypatch.setattr(common, "barycentric_transforms", lambda points, simplices: None)
    assert np.allclose(fast, common.inpaint(grid), rtol=0, atol=1e-9)


def test_existing_classes_kept_unless_reclassify(scene):
    cloud, truth = scene
    cls = np.ones(cloud.n, np.uint8)
    cls[:20] = ASPRSClass.WATER
    cls[20:25] = ASPRSClass.LOW_POINT
    c = cloud.with_attrs(classification=cls)
    out = np.asarray(ground_filter(c, "smrf").attrs["classification"])
    assert np.all(out[:20] == ASPRSClass.WATER)
    assert np.all(out[20:25] == ASPRSClass.LOW_POINT)
    out2 = np.asarray(ground_filter(c, "smrf", reclassify=True).attrs["classification"])
    assert set(np.unique(out2[:25])) <= {1, 2}
    assert np.mean(out2[:20][truth[:20]] == ASPRSClass.GROUND) > 0.9


def test_last_returns_only(scene):
    cloud, truth = scene
    rn = np.ones(cloud.n, np.uint8)
    nr = np.ones(cloud.n, np.uint8)
    nr[::7] = 2  # every 7th point is a first of two returns: cannot be ground
    out = ground_filter(cloud.with_attrs(return_number=rn, number_of_returns=nr), "smrf")
    cls = np.asarray(out.attrs["classification"])
    assert np.all(cls[::7] == ASPRSClass.UNCLASSIFIED)
    out2 = ground_filter(cloud.with_attrs(return_number=rn, number_of_returns=nr), "smrf", last_returns_only=False)
    assert np.mean(np.asarray(out2.attrs["classification"])[::7][truth[::7]] == 2) > 0.9


def test_feet_crs_gives_the_same_classes(scene):
    cloud, _ = scene
    ft = 0.3048  # EPSG:2994 is in international feet
    c_ft = Cloud(cloud.xyz / ft, dict(cloud.attrs), crs="EPSG:2994")
    a = np.asarray(ground_filter(cloud, "smrf").attrs["classification"])
    b = np.asarray(ground_filter(c_ft, "smrf").attrs["classification"])
    assert np.mean(a == b) > 0.995
    # the filters see metres: the prepared coordinates of both clouds agree
    from workstation.ground.common import prepare

    pa = prepare(cloud, "t")
    pb = prepare(c_ft, "t")
    assert pb.hfac == pytest.approx(ft) and pb.vfac == pytest.approx(ft)
    np.testing.assert_allclose(pa.xyz, pb.xyz, atol=1e-6)


def test_refuses_empty_and_all_noise(scene):
    cloud, _ = scene
    with pytest.raises(StageError):
        ground_filter(cloud[np.zeros(cloud.n, bool)], "smrf")
    noisy = cloud.with_attrs(classification=np.full(cloud.n, ASPRSClass.LOW_POINT))
    with pytest.raises(StageError, match="usable"):
        ground_filter(noisy, "pmf")


def test_unknown_parameter_rejected():
    with pytest.raises(ValueError, match="no parameter"):
        make_params("smrf", "default", rigidness=2)
    p = make_params("smrf", "urban", threshold=0.7)
    assert p.threshold == 0.7 and p.window == 30.0


def test_noise_and_hag(scene):
    from workstation.ground.hag import height_above_ground
    from workstation.ground.noise import classify_noise

    cloud, truth = scene
    c = classify_noise(cloud)
    cls = np.asarray(c.attrs["classification"])
    assert cls[-1] == ASPRSClass.LOW_POINT
    assert np.mean(cls[:-1] == ASPRSClass.LOW_POINT) < 0.01
    g = ground_filter(c, "smrf")
    assert np.asarray(g.attrs["classification"])[-1] == ASPRSClass.LOW_POINT
    h = height_above_ground(g)
    hag = np.asarray(h.attrs["hag"])
    assert hag.dtype == np.float32
    roof = ~truth
    roof[-1] = False
    # roofs are 6 and 9 m high; ground near 0
    assert np.median(np.abs(hag[truth])) < 0.1
    assert 5.0 < np.median(hag[roof]) < 9.5
    assert hag[-1] < -25


def test_hag_needs_ground(scene):
    from workstation.ground.hag import height_above_ground

    cloud, _ = scene
    with pytest.raises(StageError):
        height_above_ground(cloud.with_attrs(classification=np.ones(cloud.n, np.uint8)))


def test_noise_tests_in_blocks_are_one_query_of_all():
    """The statistical and isolated-low tests look their points up a block at a time on the
    cores: the flags are those of one KD-tree query of every point (a 1 cm grid: ties)."""
    from scipy.spatial import cKDTree

    from workstation.ground.noise import isolated_low_points, statistical_outliers

    rng = np.random.default_rng(9)
    xyz = np.round(np.column_stack([rng.uniform(0, 150, (80_000, 2)), rng.normal(0, 0.3, 80_000)]), 2)
    xyz[::997, 2] -= 5  # low noise
    xyz[::1499, 2] += 30  # high
    d, _ = cKDTree(xyz).query(xyz, k=9)
    md = d[:, 1:].mean(axis=1)
    assert np.array_equal(statistical_outliers(xyz), md > md.mean() + 3.0 * md.std())
    _, j = cKDTree(xyz[:, :2]).query(xyz[:, :2], k=11)
    low = xyz[:, 2] < np.partition(xyz[j[:, 1:], 2], 1, axis=1)[:, 1] - 1.5
    assert low.sum() >= 70 and np.array_equal(isolated_low_points(xyz), low)
