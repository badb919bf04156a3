"""Density, coverage and voids (USGS LBS): known answers on tiny synthetic point grids."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.units import METRES
from workstation.io.crs import crs_units
from workstation.qc.coverage import CoverageParams, CoveragePass, DensityPass, coverage_grid

D = 0.5  # point spacing (m): 4 first returns per m², ANPS 0.5 m, 2×ANPS cells of 1 m


def lattice(x0, x1, y0, y1, d=D):
    """Points at the centres of a d-spaced lattice over [x0, x1) × [y0, y1)."""
    xs, ys = np.arange(x0, x1 - 1e-9, d) + d / 2, np.arange(y0, y1 - 1e-9, d) + d / 2
    return np.stack(np.meshgrid(xs, ys), -1).reshape(-1, 2)


def cut(xy, x0, x1, y0, y1):
    """``xy`` without the points in [x0, x1) × [y0, y1)."""
    inside = (xy[:, 0] >= x0) & (xy[:, 0] < x1) & (xy[:, 1] >= y0) & (xy[:, 1] < y1)
    return xy[~inside]


def cloud(xy, psid=None, cls=None, crs="EPSG:32632", scale=1.0, **attrs):
    """First returns at ``xy`` (metres), coordinates divided by ``scale`` (metres per CRS unit)."""
    n = len(xy)
    a = {"return_number": np.ones(n), "number_of_returns": np.ones(n),
         "classification": np.full(n, 2) if cls is None else cls, **attrs}
    if psid is not None:
        a["point_source_id"] = np.broadcast_to(psid, (n,))
    return Cloud(np.c_[xy / scale, np.zeros(n)], a, crs=crs)


def coverage(clouds, anps_m=D, params=CoverageParams(), files=None):
    """A pass 2 over ``clouds`` (each its own file unless ``files``) on the grid over their bounds."""
    xy = np.vstack([c.xyz[:, :2] for c in clouds])
    units = crs_units(clouds[0].crs)
    grid = coverage_grid((*xy.min(0), *xy.max(0)), anps_m, units)
    cp = CoveragePass(grid, anps_m, params)
    for i, c in enumerate(clouds):
        cp.add(c, files[i] if files else f"f{i}.laz")
    return cp


def test_anpd_of_overlapping_swaths_is_the_single_swath_density():
    a, b = lattice(0, 100, 0, 60), lattice(70, 170, 0, 60)  # 30 % overlap
    extra = lattice(0, 100, 0, 60)  # second returns, withheld and noise points must not count
    n = len(extra)
    chunk = Cloud(np.r_[np.c_[a, np.zeros(len(a))], np.c_[b, np.zeros(len(b))], np.c_[extra, np.zeros(n)],
                        np.c_[extra, np.zeros(n)], np.c_[extra, np.zeros(n)]],
                  {"return_number": np.r_[np.ones(len(a) + len(b)), np.full(n, 2), np.ones(2 * n)],
                   "point_source_id": np.r_[np.full(len(a), 1), np.full(len(b), 2), np.ones(3 * n)],
                   "withheld": np.r_[np.zeros(len(a) + len(b) + n), np.ones(n), np.zeros(n)],
                   "classification": np.r_[np.full(len(a) + len(b) + 2 * n, 2), np.full(n, 7)]}, crs="EPSG:32632")
    p = DensityPass(METRES)
    p.add(chunk, "a.laz")
    r = p.result()
    assert r["anpd"] == pytest.approx(4.0, rel=0.02)  # all first returns over the union would be 4.7
    assert r["anps"] == pytest.approx(0.5, rel=0.01)
    assert r["first_returns"] == len(a) + len(b)
    assert [s["id"] for s in r["swaths"]] == [1, 2]
    assert [s["area_m2"] for s in r["swaths"]] == pytest.approx([6000.0, 6000.0], rel=0.005)
    assert p.findings() == []


def test_a_swath_split_over_files_and_chunks_adds_its_pieces():
    xy = lattice(0, 100, 0, 60)
    p = DensityPass(METRES)
    left, right = xy[xy[:, 0] < 40], xy[xy[:, 0] >= 40]
    for part in np.array_split(right, 5):  # chunks of one file
        p.add(cloud(part, psid=9), "b.laz")
    p.add(cloud(left, psid=9), "a.laz")
    s = p.result()["swaths"]
    assert len(s) == 1 and s[0]["files"] == 2
    assert s[0]["area_m2"] == pytest.approx(6000.0, rel=0.002)
    assert s[0]["anpd"] == pytest.approx(4.0, rel=0.002)


def test_without_swath_ids_a_warning_says_overlap_inflates_density():
    xy = np.r_[lattice(0, 100, 0, 60), lattice(70, 170, 0, 60)]
    p = DensityPass(METRES)
    p.add(cloud(xy), "tile.laz")
    r = p.result()
    assert r["anpd"] > 4.5 and len(r["swaths"]) == 1  # measured as one swath: doubled in the overlap
    (f,) = p.findings()
    assert (f.severity, f.field, f.file) == ("warning", "point_source_id", "tile.laz")


def test_no_first_returns_is_an_error_and_nan():
    c = Cloud(np.zeros((3, 3)), {"return_number": np.full(3, 2)})
    p = DensityPass(METRES)
    p.add(c, "x.laz")
    assert np.isnan(p.result()["anpd"])
    assert [f.severity for f in p.findings() if f.field == "first_returns"] == ["error"]


def test_coverage_of_a_perfect_grid_is_one_without_voids():
    cp = coverage([cloud(lattice(0, 50, 0, 40), psid=1)])
    r = cp.result()
    assert r["coverage"] == 1.0 and r["voids"] == 0
    assert r["cells"] == r["filled"] == 50 * 40
    assert r["cell_m"] == pytest.approx(1.0)
    assert r["min_void_area_m2"] == pytest.approx(4.0)
    assert cp.findings() == []


@pytest.mark.parametrize("offset", [0.0, 0.3])  # hole on cell edges, and across them
def test_a_square_hole_is_one_void_of_its_area(offset):
    lo, hi = 20 + offset, 28 + offset
    cp = coverage([cloud(cut(lattice(0, 50, 0, 40), lo, hi, lo, hi), psid=1)])
    r = cp.result()
    assert r["voids"] == 1
    (v,) = r["void_list"]
    assert abs(v["area_m2"] - 64.0) <= 8.0  # within one cell row of 1 m
    assert v["centroid"] == pytest.approx([24 + offset, 24 + offset], abs=0.5)
    assert v["bbox"][0] >= lo - 1 and v["bbox"][2] <= hi + 1 and not v["edge"]
    assert r["coverage"] == pytest.approx(1 - v["cells"] / 2000)
    (f,) = cp.findings()
    assert (f.severity, f.field) == ("error", "void")


def test_a_hole_smaller_than_4_anps_squared_is_not_a_void():
    xy = cut(lattice(0, 50, 0, 40), 20, 21.5, 20, 22.5)  # 1.5 m × 2.5 m = 3.75 m² < (4 × 0.5 m)²
    r = coverage([cloud(xy, psid=1)]).result()
    assert r["filled"] == r["cells"] - 2  # its two empty cells lower the coverage
    assert r["voids"] == 0


def test_holes_in_water_are_not_voids_but_a_hole_on_land_is():
    xy = cut(lattice(0, 80, 0, 60), 20, 28, 20, 28)  # a hole on land
    xy = cut(cut(xy, 45, 67, 25, 47), 7, 13, 47, 53)  # a lake and a pond with returns only near their shores
    lake = (xy[:, 0] >= 42) & (xy[:, 0] < 70) & (xy[:, 1] >= 22) & (xy[:, 1] < 50)
    pond = (np.abs(xy[:, 0] - 10) < 4) & (np.abs(xy[:, 1] - 50) < 4)
    cls = np.where(lake | pond, 9, 2)
    cp = coverage([cloud(xy, psid=1, cls=cls)])
    r = cp.result()
    assert r["voids"] == 1
    assert r["void_list"][0]["centroid"] == pytest.approx([24, 24], abs=0.5)
    assert r["water_cells"] >= 22 * 22 + 6 * 6 - 10
    assert r["cells"] == r["footprint_cells"] - r["water_cells"]
    # the same lake classified as ground is a void
    dry = coverage([cloud(xy, psid=1)]).result()
    assert dry["voids"] == 3 and dry["water_cells"] == 0


def test_an_empty_area_whose_shore_is_partly_water_follows_the_border_fraction():
    xy = cut(lattice(0, 60, 0, 60), 20, 32, 20, 32)
    shore = ((xy[:, 0] >= 16) & (xy[:, 0] < 20) | (xy[:, 1] >= 16) & (xy[:, 1] < 20)) & \
        (xy[:, 0] >= 16) & (xy[:, 0] < 32) & (xy[:, 1] >= 16) & (xy[:, 1] < 32)  # water on two of four sides
    c = cloud(xy, psid=1, cls=np.where(shore, 9, 2))
    assert coverage([c]).result()["voids"] == 0
    strict = coverage([c], params=CoverageParams(water_border_fraction=0.6)).result()
    assert strict["voids"] == 1 and 0.4 < strict["void_list"][0]["water_border"] < 0.6


def test_empty_cells_beside_water_points_are_water():
    xy = cut(lattice(0, 60, 0, 60), 30, 31, 10, 50)  # a 1 m strip without returns along a river bank
    c = cloud(xy, psid=1, cls=np.where((xy[:, 0] >= 20) & (xy[:, 0] < 30), 9, 2))
    only_buffer = CoverageParams(water_border_fraction=1.0)  # the shore-share rule cannot excuse it
    r = coverage([c], params=only_buffer).result()
    assert r["voids"] == 0 and r["water_cells"] == 40 and r["coverage"] == 1.0
    no_buffer = coverage([c], params=CoverageParams(water_buffer_cells=0, water_border_fraction=1.0)).result()
    assert no_buffer["voids"] == 1 and no_buffer["water_cells"] == 0


def test_tile_corners_outside_the_flown_area_are_not_empty():
    tri = lattice(0, 60, 0, 60)
    tri = tri[tri.sum(axis=1) < 60]  # file A is flown only below its diagonal
    cp = coverage([cloud(tri, psid=1), cloud(lattice(60, 120, 0, 60), psid=1)])
    r = cp.result()
    assert r["voids"] == 0
    assert r["coverage"] > 0.995
    assert r["footprint_area_m2"] == pytest.approx(1800 + 3600, rel=0.02)  # not the 7200 m² grid


def test_a_gap_between_swaths_inside_a_tile_is_a_void():
    xy = np.r_[lattice(0, 50, 0, 60), lattice(53, 100, 0, 60)]
    r = coverage([cloud(xy, psid=np.r_[np.ones(100 * 120), np.full(94 * 120, 2)])]).result()
    assert r["voids"] == 1
    assert abs(r["void_list"][0]["area_m2"] - 3 * 60) <= 60  # within one cell row along the gap
    assert r["void_list"][0]["edge"]


def test_a_file_in_feet_reports_metres():
    ft = 0.3048
    a, b = lattice(0, 60, 0, 40), lattice(42, 102, 0, 40)  # two swaths overlapping 18 m
    xy, ps = np.r_[a, b], np.r_[np.ones(len(a)), np.full(len(b), 2)]
    keep = ~((xy[:, 0] >= 20) & (xy[:, 0] < 28) & (xy[:, 1] >= 20) & (xy[:, 1] < 28))
    xy, ps = xy[keep], ps[keep]
    first = cloud(xy[: len(xy) // 2], psid=ps[: len(xy) // 2], crs="EPSG:2994", scale=ft)
    second = cloud(xy[len(xy) // 2:], psid=ps[len(xy) // 2:], crs="EPSG:2994", scale=ft)
    units = crs_units("EPSG:2994")
    assert units.h == ft
    p = DensityPass(units)
    for c in (first, second):
        p.add(c, "ft.laz")
    r = p.result()
    assert r["anpd"] == pytest.approx(4.0, rel=0.02) and r["anps"] == pytest.approx(0.5, rel=0.01)
    cov = coverage([first, second], anps_m=0.5, files=["ft.laz", "ft.laz"]).result()
    assert cov["cell_m"] == pytest.approx(1.0) and cov["min_void_area_m2"] == pytest.approx(4.0)
    assert cov["voids"] == 1 and abs(cov["void_list"][0]["area_m2"] - 64.0) <= 8.0


def test_chunks_in_any_order_give_the_same_result(rng):
    xy = cut(lattice(0, 50, 0, 40), 10.3, 18.3, 10.3, 18.3)
    whole = coverage([cloud(xy, psid=1)]).result()
    grid = coverage_grid((*xy.min(0), *xy.max(0)), D, METRES)
    cp = CoveragePass(grid, D)
    for part in np.array_split(rng.permutation(len(xy)), 7):  # each chunk spans the whole grid
        cp.add(cloud(xy[np.sort(part)], psid=1), "f0.laz")
    assert cp.result() == whole


def test_write_products(tmp_path):
    from workstation.io.geotiff import read_raster

    tri = lattice(0, 40, 0, 40)
    tri = cut(tri[tri.sum(axis=1) < 60], 10, 18, 10, 18)
    cp = coverage([cloud(tri, psid=1)])
    r = cp.result()
    paths = cp.write(tmp_path, "EPSG:32632")
    dens, voids = read_raster(paths["density"]), read_raster(paths["voids"], nan_nodata=False)
    assert dens.array.dtype == np.float32 and np.nanmax(dens.array) == pytest.approx(4.0)
    assert np.count_nonzero(np.isnan(dens.array)) == voids.array.size - r["footprint_cells"] > 0
    assert np.count_nonzero(voids.array == 1) == r["void_list"][0]["cells"]
    assert np.count_nonzero(voids.array == 255) == voids.array.size - r["footprint_cells"]
    doc = json.loads(paths["voids_geojson"].read_text())
    assert doc["crs"]["properties"]["name"].endswith("EPSG::32632")
    (feat,) = doc["features"]
    ring = np.array(feat["geometry"]["coordinates"][0])
    area = 0.5 * abs(np.dot(ring[:-1, 0], ring[1:, 1]) - np.dot(ring[1:, 0], ring[:-1, 1]))
    assert area == pytest.approx(r["void_list"][0]["cells"] * r["cell_m"] ** 2)
    assert feat["properties"]["id"] == 1


def test_bad_spacing_and_parameters_are_refused():
    grid = coverage_grid((0, 0, 10, 10), 0.5, METRES)
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(InvalidInputError, match="spacing"):
            CoveragePass(grid, bad)
    with pytest.raises(InvalidInputError):
        CoverageParams(required_coverage=95)


@pytest.mark.realdata
def test_bcts_1_density_and_coverage(shared_data):
    from workstation.io.registry import iter_chunks

    path = shared_data / "lidar" / "bcts_1.laz"
    if not path.exists():
        pytest.skip(f"{path} is absent")
    chunks = list(iter_chunks(path, 200_000))
    units = crs_units(chunks[0].crs)
    p = DensityPass(units)
    for c in chunks:
        p.add(c, path.name)
    r = p.result()
    assert len(r["swaths"]) == 3
    assert 2.0 < r["anpd"] < 15.0 and 0.25 < r["anps"] < 0.7
    xy = np.vstack([c.xyz[:, :2] for c in chunks])
    from scipy.spatial import ConvexHull

    tile_m2 = ConvexHull(xy).volume  # the tile is a little skewed: its hull, not its bounding box
    assert r["first_returns"] / tile_m2 > 1.5 * r["anpd"]  # the overlaps are not counted twice
    cp = CoveragePass(coverage_grid((*xy.min(0), *xy.max(0)), r["anps"], units), r["anps"])
    for c in chunks:
        cp.add(c, path.name)
    cov = cp.result()
    assert 0.95 < cov["coverage"] <= 1.0
    assert cov["footprint_area_m2"] == pytest.approx(tile_m2, rel=0.02)
