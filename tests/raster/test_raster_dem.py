"""DSM/DTM/CHM gridding: TIN correctness, the synthetic-terrain goals, tiling, streaming, auto cells."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.products import Raster
from workstation.raster.dem import DemParams, auto_resolution, build_dem, height_above_ground, sample_bilinear
from workstation.raster.grid import GridSpec, lattice_tin, tin_surface

BUILDINGS = ((20.0, 25.0, 45.0, 50.0, 12.0), (70.0, 60.0, 90.0, 95.0, 20.0))


def terrain(x, y):
    """Analytic ground: tilt plus long gentle waves (curvature small over a building)."""
    return 100.0 + 0.03 * x - 0.02 * y + 1.5 * np.sin(x / 40.0) * np.cos(y / 55.0)


def synthetic_als(rng, n=120_000, size=120.0, noise=0.05):
    x = rng.uniform(0, size, n)
    y = rng.uniform(0, size, n)
    z = terrain(x, y) + rng.normal(0, noise, n)
    cls = np.full(n, int(ASPRSClass.GROUND), np.uint8)
    for x0, y0, x1, y1, h in BUILDINGS:
        m = (x >= x0) & (x < x1) & (y >= y0) & (y < y1)
        z[m] = terrain((x0 + x1) / 2, (y0 + y1) / 2) + h + rng.normal(0, noise, m.sum())
        cls[m] = int(ASPRSClass.BUILDING)
    return Cloud(np.column_stack([x, y, z]), {"classification": cls}, crs="EPSG:32632")


def building_mask(X, Y):
    m = np.zeros(X.shape, bool)
    for x0, y0, x1, y1, _ in BUILDINGS:
        m |= (X >= x0) & (X < x1) & (Y >= y0) & (Y < y1)
    return m


def test_grid_from_bounds_holds_every_point():
    g = GridSpec.from_bounds(0.0, 0.0, 10.0, 10.0, 1.0)
    r, c, inside = g.cell_index(np.array([0.0, 10.0, 5.5]), np.array([0.0, 10.0, 5.5]))
    assert inside.all()
    assert g.x0 == 0.0 and g.y1 == 11.0 and g.shape == (12, 11)  # rows hold their north edge


def test_tin_is_exact_on_a_plane_dense_and_sparse(rng):
    for n in (20_000, 300):  # lattice path and void-fill (Delaunay) path
        x, y = rng.uniform(0, 50, n), rng.uniform(0, 50, n)
        z = 3.0 + 0.2 * x - 0.1 * y
        r = build_dem(Cloud(np.column_stack([x, y, z]), {"classification": np.full(n, 2, np.uint8)}), DemParams(resolution=1.0))
        X, Y = r.cell_centers()
        ok = np.isfinite(r.array)
        assert ok.mean() > 0.85
        np.testing.assert_allclose(r.array[ok], (3.0 + 0.2 * X - 0.1 * Y)[ok], atol=2e-4)  # float32 storage


def brute_force_tin(pts, z, qx, qy):
    """Reference linear TIN: every query tested against every Delaunay triangle (numpy)."""
    from scipy.spatial import Delaunay

    s = Delaunay(pts).simplices
    a, b, c = pts[s[:, 0]], pts[s[:, 1]], pts[s[:, 2]]
    den = (b[:, 1] - c[:, 1]) * (a[:, 0] - c[:, 0]) + (c[:, 0] - b[:, 0]) * (a[:, 1] - c[:, 1])
    q = np.column_stack([qx.ravel(), qy.ravel()])[:, None, :]
    l0 = ((b[:, 1] - c[:, 1]) * (q[..., 0] - c[:, 0]) + (c[:, 0] - b[:, 0]) * (q[..., 1] - c[:, 1])) / den
    l1 = ((c[:, 1] - a[:, 1]) * (q[..., 0] - c[:, 0]) + (a[:, 0] - c[:, 0]) * (q[..., 1] - c[:, 1])) / den
    l2 = 1 - l0 - l1
    inside = (l0 >= -1e-9) & (l1 >= -1e-9) & (l2 >= -1e-9)
    val = l0 * z[s[:, 0]] + l1 * z[s[:, 1]] + l2 * z[s[:, 2]]
    first = np.where(inside.any(1), inside.argmax(1), -1)
    out = np.where(first >= 0, val[np.arange(len(first)), np.maximum(first, 0)], np.nan)
    return out.reshape(qx.shape)


def test_void_fill_matches_a_brute_force_linear_tin(rng):
    n = 300  # sparse: about one point per 8 cells, so the Delaunay void fill does the work
    pts = rng.uniform(0, 50, (n, 2))
    z = np.sin(pts[:, 0] / 7) + np.cos(pts[:, 1] / 5)
    g = GridSpec.from_bounds(0, 0, 50, 50, 1.0)
    row, col, _ = g.cell_index(pts[:, 0], pts[:, 1])
    uniq = np.unique(row * g.cols + col, return_index=True)[1]  # one point per cell
    pts, z, row, col = pts[uniq], z[uniq], row[uniq], col[uniq]
    u, v = g.to_uv(pts[:, 0], pts[:, 1])
    du = np.zeros(g.shape); dv = np.zeros(g.shape); zz = np.full(g.shape, np.nan); valid = np.zeros(g.shape, bool)
    du[row, col] = u - col; dv[row, col] = v - row; zz[row, col] = z; valid[row, col] = True
    ours = tin_surface(du, dv, zz, valid, tile=16)
    X, Y = Raster(zz, g.transform).cell_centers()
    ref = brute_force_tin(pts, z, X, Y)
    both = np.isfinite(ours) & np.isfinite(ref)
    assert both.sum() > 0.95 * np.isfinite(ref).sum()
    assert np.median(np.abs(ours[both] - ref[both])) < 1e-9
    assert np.abs(ours[both] - ref[both]).max() < 0.15  # another split only where 4 cells form a quad


def test_lattice_tiles_equal_untiled(rng):
    shape = (40, 50)
    du, dv = rng.uniform(-0.5, 0.5, shape), rng.uniform(-0.5, 0.5, shape)
    z = rng.normal(0, 1, shape)
    valid = rng.uniform(0, 1, shape) > 0.1
    whole = tin_surface(du, dv, z, valid, tile=1000)
    tiled = tin_surface(du, dv, z, valid, tile=7)
    np.testing.assert_array_equal(np.isnan(whole), np.isnan(tiled))
    np.testing.assert_allclose(whole[np.isfinite(whole)], tiled[np.isfinite(tiled)])
    assert lattice_tin(du, dv, z, np.zeros(shape, bool)).size == z.size


def test_dtm_goals_on_synthetic_terrain(rng):
    noise = 0.05
    c = synthetic_als(rng, noise=noise)
    r = build_dem(c, DemParams(kind="dtm", resolution=1.0))
    X, Y = r.cell_centers()
    err = r.array - terrain(X, Y)
    bld = building_mask(X, Y)
    # interpolation error of the same TIN on noise-free samples (the allowance of the goal)
    clean = Cloud(c.xyz.copy(), dict(c.attrs))
    xyz = clean.xyz.copy(); g = c.attrs["classification"] == 2
    xyz[g, 2] = terrain(xyz[g, 0], xyz[g, 1])
    r0 = build_dem(clean.with_xyz(xyz), DemParams(kind="dtm", resolution=1.0))
    interp = np.sqrt(np.nanmean((r0.array - terrain(X, Y))[~bld] ** 2))
    rmse = np.sqrt(np.nanmean(err[~bld] ** 2))
    assert rmse <= 1.5 * noise + interp
    assert np.nanmax(np.abs(err[bld])) <= 0.3  # no building leakage into the DTM
    assert np.isfinite(r.array[bld]).all()  # voids filled
    assert r.meta["kind"] == "dtm" and r.crs == "EPSG:32632"


def test_idw_and_natural_neighbour_close_to_tin(rng):
    c = synthetic_als(rng, n=40_000)
    a = build_dem(c, DemParams(kind="dtm", resolution=2.0)).array
    ok = np.isfinite(a)
    for method in ("idw", "nn"):
        b = build_dem(c, DemParams(kind="dtm", resolution=2.0, method=method)).array
        np.testing.assert_array_equal(ok, np.isfinite(b))
        assert np.sqrt(np.mean((a[ok] - b[ok]) ** 2)) < 0.2
    # natural neighbour keeps building voids as flat as the TIN does; IDW sags
    r = build_dem(c, DemParams(kind="dtm", resolution=1.0, method="nn"))
    X, Y = r.cell_centers()
    assert np.nanmax(np.abs(r.array - terrain(X, Y))[building_mask(X, Y)]) <= 0.3


def test_dsm_chm_and_pit_free(rng):
    c = synthetic_als(rng, n=60_000)
    dsm = build_dem(c, DemParams(kind="dsm", resolution=1.0))
    X, Y = dsm.cell_centers()
    roof = (X > 72) & (X < 88) & (Y > 62) & (Y < 93)
    top = terrain(80.0, 77.5) + 20
    assert abs(np.nanmedian(dsm.array[roof]) - top) < 0.1
    # highest return: a cell's value is the max of its points
    g = GridSpec.from_transform(dsm.transform, dsm.shape)
    row, col, _ = g.cell_index(c.xyz[:, 0], c.xyz[:, 1])
    k = np.flatnonzero((row == 30) & (col == 80))
    assert dsm.array[30, 80] == pytest.approx(c.xyz[k, 2].max(), abs=1e-4)
    tin = build_dem(c.with_attrs(return_number=np.ones(c.n, np.uint8)), DemParams(kind="dsm", resolution=1.0, method="tin"))
    assert abs(np.nanmedian(tin.array[roof]) - top) < 0.1 and np.isfinite(tin.array[roof]).all()
    # --max-edge: voids wider than the limit stay nodata (no made-up ground under buildings)
    holes = build_dem(c, DemParams(kind="dtm", resolution=1.0, max_edge=5.0)).array
    assert np.isnan(holes[roof]).all() and np.isfinite(holes[~building_mask(X, Y)]).mean() > 0.99
    chm = build_dem(c, DemParams(kind="chm", resolution=1.0))
    assert abs(np.nanmedian(chm.array[roof]) - 20) < 0.3
    assert np.nanmin(chm.array) >= 0 and np.nanmedian(chm.array[~building_mask(X, Y)]) < 0.1
    # pit-free: a canopy with sparse inner returns (pits) is smoother than DSM - DTM
    n = 30_000
    x, y = rng.uniform(0, 40, n), rng.uniform(0, 40, n)
    crown = np.hypot(x - 20, y - 20) < 12
    pit = rng.uniform(0, 1, n) < 0.15  # first returns that went deep into the crown
    z = np.where(crown & ~pit, 15.0 - 0.05 * np.hypot(x - 20, y - 20) ** 2 * 0.5, 0.0) + np.where(crown & pit, 2.0, 0.0)
    cls = np.where(crown, 5, 2).astype(np.uint8)
    gx, gy = rng.uniform(0, 40, 4000), rng.uniform(0, 40, 4000)
    cloud = Cloud(np.column_stack([np.r_[x, gx], np.r_[y, gy], np.r_[z, np.zeros(4000)]]),
                  {"classification": np.r_[cls, np.full(4000, 2, np.uint8)], "return_number": np.ones(n + 4000, np.uint8)})
    plain = build_dem(cloud, DemParams(kind="chm", resolution=0.5, method="highest")).array
    pf = build_dem(cloud, DemParams(kind="chm", resolution=0.5, pit_free=True)).array
    inner = np.zeros(plain.shape, bool); inner[30:50, 30:50] = True
    assert np.nanmin(pf[inner]) > 8.0 > np.nanmin(plain[inner])


def test_auto_resolution_rules():
    r, why = auto_resolution(1_000_000, 1_000_000)
    assert r == 1.0 and "spacing" in why
    r, why = auto_resolution(10_000_000, 1_000_000, vertical_rmse=0.3)  # NPS 0.32 m, 3σ = 0.9 m
    assert r == 1.0 and "accuracy governs" in why
    r, why = auto_resolution(400_000, 1_000_000, vertical_rmse=0.05)
    assert r == 2.0 and "point spacing governs" in why
    with pytest.raises(InvalidInputError):
        auto_resolution(0, 10)


def test_auto_resolution_in_build_and_meta(rng):
    c = synthetic_als(rng, n=30_000)  # 2 pts/m² -> NPS 0.7 m -> 1 m
    r = build_dem(c, DemParams(kind="dtm", resolution=None, vertical_rmse=0.5))
    assert r.meta["resolution"] == 1.5 or r.meta["resolution"] == 2.0
    assert "3 × vertical RMSE" in r.meta["resolution_reason"] and r.meta["vertical_rmse"] == 0.5


def test_sample_bilinear_and_hag(rng):
    g = GridSpec(0.0, 10.0, 1.0, 10, 10)
    X, Y = Raster(np.zeros(g.shape), g.transform).cell_centers()
    plane = Raster(2.0 + 0.5 * X - 0.25 * Y, g.transform)
    x, y = rng.uniform(0.5, 9.5, 100), rng.uniform(0.5, 9.5, 100)
    np.testing.assert_allclose(sample_bilinear(plane, x, y), 2.0 + 0.5 * x - 0.25 * y)
    assert np.isnan(sample_bilinear(plane, np.array([20.0]), np.array([5.0])))[0]
    c = Cloud(np.column_stack([x, y, 2.0 + 0.5 * x - 0.25 * y + 3.0]))
    h = height_above_ground(c, plane)
    np.testing.assert_allclose(h.attrs["hag"], 3.0, atol=1e-5)
    assert "hag" not in c.attrs  # input untouched
    with pytest.raises(StageError):
        height_above_ground(Cloud(np.array([[100.0, 100.0, 0.0]])), plane)


def test_streamed_files_and_mosaic_equal_in_memory(rng, tmp_path):
    from workstation.core.cloud import concatenate
    from workstation.io import read_cloud, write_cloud

    c = synthetic_als(rng, n=40_000)
    c = c.with_xyz(c.xyz + [500_000.0, 5_000_000.0, 0.0])
    west, east = c[c.xyz[:, 0] < 500_060.0], c[c.xyz[:, 0] >= 500_060.0]
    write_cloud(west, tmp_path / "w.laz")
    write_cloud(east, tmp_path / "e.laz")
    whole = build_dem(concatenate([read_cloud(tmp_path / "w.laz"), read_cloud(tmp_path / "e.laz")]), DemParams(resolution=1.0))
    mosaic = build_dem([tmp_path / "w.laz", tmp_path / "e.laz"], DemParams(resolution=1.0), chunk_size=7_000)
    assert mosaic.transform == whole.transform
    np.testing.assert_allclose(mosaic.array, whole.array, atol=1e-4, equal_nan=True)
    assert mosaic.crs == "EPSG:32632"


def test_dtm_without_classes_or_ground_is_an_error(rng):
    with pytest.raises(InvalidInputError, match="classification"):
        build_dem(Cloud(rng.uniform(0, 10, (100, 3))), DemParams(kind="dtm"))
    with pytest.raises(StageError, match="no ground"):
        build_dem(Cloud(rng.uniform(0, 10, (100, 3)), {"classification": np.full(100, 5, np.uint8)}), DemParams(kind="dtm"))
    with pytest.raises(InvalidInputError):
        DemParams(kind="dsm", method="idw")


@pytest.mark.parametrize("kind", ["dtm", "dsm", "chm"])
def test_out_of_core_tiles_equal_single_pass(rng, tmp_path, kind):
    from workstation.io import write_cloud

    c = synthetic_als(rng, n=40_000)
    c = c.with_xyz(c.xyz + [500_000.0, 5_000_000.0, 0.0]).with_attrs(return_number=np.ones(c.n, np.uint8))
    write_cloud(c, tmp_path / "a.laz")
    p = DemParams(kind=kind, resolution=1.0)
    whole = build_dem(tmp_path / "a.laz", p, tile_cells=0)
    tiled = build_dem(tmp_path / "a.laz", p, chunk_size=9_000, tile_cells=32, buffer_cells=40)  # 16 tiles
    assert "tiles" in tiled.meta and tiled.transform == whole.transform
    assert tiled.meta["points"] == whole.meta["points"]  # a point in the overlaps counted once
    inner = (slice(2, -2), slice(2, -2))  # the hull edge may triangulate differently per tile
    np.testing.assert_allclose(tiled.array[inner], whole.array[inner], atol=1e-4, equal_nan=True)
