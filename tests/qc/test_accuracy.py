"""Absolute accuracy from checkpoints (workstation.qc.accuracy): NVA/VVA (ASPRS 2014), Edition 2
RMSE with the checkpoints' own accuracy, horizontal NSSDA forms, TIN matching, DEM accuracy."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.products import Raster
from workstation.core.units import FOOT, US_SURVEY_FOOT, Units
from workstation.qc.accuracy import (CheckpointParams, CheckpointPass, Checkpoints, dem_accuracy,
                                     horizontal_accuracy, outliers, read_checkpoints, three_x_rule, vertical_accuracy)

X0, Y0 = 500_000.0, 4_100_000.0


def plane(x, y):
    """The synthetic terrain: a tilted plane (CRS units)."""
    return 100.0 + 0.02 * (x - X0) - 0.03 * (y - Y0)


def ground_cloud(spacing=1.0, extent=200.0, *, rng=None, crs=None, extra=None):
    """Ground points (class 2) on a jittered lattice over the plane, plus vegetation (class 5)
    1-20 units above it that must never reach the TIN."""
    rng = rng or np.random.default_rng(7)
    g = np.arange(0.0, extent, spacing)
    xx, yy = np.meshgrid(g, g)
    x = X0 + xx.ravel() + rng.uniform(-0.3, 0.3, xx.size) * spacing
    y = Y0 + yy.ravel() + rng.uniform(-0.3, 0.3, xx.size) * spacing
    ground = np.column_stack([x, y, plane(x, y)])
    veg = ground[::3] + np.column_stack([np.zeros((len(ground[::3]), 2)), rng.uniform(1, 20, len(ground[::3]))])
    xyz = np.vstack([ground, veg])
    cls = np.r_[np.full(len(ground), 2), np.full(len(veg), 5)]
    order = rng.permutation(len(xyz))
    return Cloud(xyz[order], {"classification": cls[order]}, crs=crs)


def chunks(cloud, n):
    """The cloud cut into ``n`` chunks, as iter_chunks would stream it."""
    edges = np.linspace(0, cloud.n, n + 1).astype(int)
    return [cloud[a:b] for a, b in zip(edges[:-1], edges[1:])]


def cps_on_plane(dz, vegetated, *, rng, margin=20.0, extent=200.0, v_scale=1.0):
    """Checkpoints at random places inside the data, below the plane by ``dz`` (metres /
    ``v_scale`` units), so that lidar − checkpoint = dz exactly."""
    n = len(dz)
    x = X0 + rng.uniform(margin, extent - margin, n)
    y = Y0 + rng.uniform(margin, extent - margin, n)
    z = plane(x, y) - np.asarray(dz) / v_scale
    cover = np.where(vegetated, "forest", "open terrain")
    return Checkpoints.from_arrays([f"CP{i}" for i in range(n)], x, y, z, cover)


# Non-vegetated: 10 × +3 cm, 10 × −3 cm, 5 × +6 cm, 5 × −6 cm (30 points);
# vegetated: |dz| = 1 … 10 cm with alternating signs (10 points).
DZ_NV = np.r_[np.full(10, 0.03), np.full(10, -0.03), np.full(5, 0.06), np.full(5, -0.06)]
DZ_V = np.array([0.01, -0.02, 0.03, -0.04, 0.05, -0.06, 0.07, -0.08, 0.09, -0.10])


def run_pass(cloud, cps, units=Units(), nchunks=3, **kw):
    p = CheckpointPass(cps, units, **kw)
    for c in chunks(cloud, nchunks):
        p.add(c, "a.laz")
    return p


# ----------------------------------------------------------------------------- hand computations
def test_nva_vva_match_hand_computation_to_1mm():
    rng = np.random.default_rng(1)
    dz = np.r_[DZ_NV, DZ_V]
    veg = np.r_[np.zeros(30, bool), np.ones(10, bool)]
    cps = cps_on_plane(dz, veg, rng=rng, extent=100.0, margin=8.0)
    table = run_pass(ground_cloud(extent=100.0), cps).result()
    assert table["n_matched"] == 40 and not table["unmatched"]
    got = np.array([r["dz"] for r in table["checkpoints"]])
    np.testing.assert_allclose(got, dz, atol=1e-6)
    acc = vertical_accuracy(got, [r["vegetated"] for r in table["checkpoints"]], checkpoint_rmse_m=0.02)
    # RMSEz = sqrt((20·0.03² + 10·0.06²)/30) = sqrt(0.0018) = 0.042426 m; NVA = 1.96 × that
    a14 = acc["asprs2014"]
    assert a14["rmsez"] == pytest.approx(0.042426, abs=1e-3 / 2)
    assert a14["nva"] == pytest.approx(0.083156, abs=1e-3 / 2)
    # VVA: sorted |dz| 0.01…0.10, rank 0.95·9 + 1 = 9.55 -> 0.09 + 0.55·0.01 = 0.0955 m
    assert a14["vva"] == pytest.approx(0.0955, abs=1e-4)
    assert a14["mean"] == pytest.approx(0.0, abs=1e-6)
    # Edition 2: sqrt(0.0018 + 0.02²) = sqrt(0.0022) = 0.046904 m; VVA RMSE sqrt(0.00385 + 0.0004)
    ed2 = acc["edition2"]
    assert ed2["rmsev"] == pytest.approx(0.046904, abs=1e-4)
    assert ed2["rmsev_data"] == pytest.approx(0.042426, abs=1e-4)
    assert ed2["vva_rmsev"] == pytest.approx(math.sqrt(0.00385 + 0.0004), abs=1e-5)
    assert acc["n_nonvegetated"] == 30 and acc["n_vegetated"] == 10
    assert [c["pass"] for c in ed2["criteria"]] == [True]


def test_edition2_needs_30_and_2014_needs_20_nonvegetated_checkpoints():
    for n, ok14, ok2 in ((19, False, False), (20, True, False), (29, True, False), (30, True, True)):
        acc = vertical_accuracy(np.full(n, 0.05), np.zeros(n, bool))
        assert acc["asprs2014"]["criteria"][0]["pass"] is ok14
        assert acc["edition2"]["criteria"][0]["pass"] is ok2
        assert acc["edition2"]["criteria"][0]["value"] == n


def test_edition2_combination_hand_computed():
    # 1.00 cm against the checkpoints with a 2.0 cm checkpoint survey: sqrt(1 + 4) = 2.236 cm
    # (a third-party tool quotes this as row 1 of Edition 2 table 7.4; not checked against the text)
    acc = vertical_accuracy(np.r_[np.full(15, 0.01), np.full(15, -0.01)], checkpoint_rmse_m=0.02)
    assert acc["edition2"]["rmsev"] == pytest.approx(0.02236, abs=1e-5)
    h = horizontal_accuracy(np.full(30, 0.03), np.full(30, -0.04), checkpoint_rmse_m=0.12)
    assert h["edition2"]["rmseh"] == pytest.approx(0.13, abs=1e-9)  # sqrt(0.05² + 0.12²)


# ----------------------------------------------------------------------------- published example
def test_pers_may_2014_worked_example_sample_standard_deviations():
    """PE&RS May 2014 p. 397 (ASPRS), Table 3 'Residuals computations', 7 checkpoints: the
    published sample standard deviations are 0.075 m (E), 0.073 m (N) and 0.030 m (H)."""
    de = [-0.060, 0.100, -0.060, -0.112, -0.120, -0.100, -0.060]
    dn = [0.080, -0.045, 0.080, 0.007, 0.150, -0.045, 0.080]
    dh = [0.055, -0.006, -0.017, 0.042, -0.011, 0.013, 0.048]
    h = horizontal_accuracy(de, dn)
    v = vertical_accuracy(dh)
    assert round(h["x"]["std"], 3) == 0.075
    assert round(h["y"]["std"], 3) == 0.073
    assert round(v["nonvegetated"]["std"], 3) == 0.030
    # the rest by hand from the same residuals
    assert h["rmsex"] == pytest.approx(math.sqrt(np.mean(np.square(de))), abs=1e-12)
    assert h["rmser"] == pytest.approx(math.hypot(0.090825, 0.080887), abs=1e-5)
    assert v["asprs2014"]["rmsez"] == pytest.approx(0.033183, abs=1e-5)


# ----------------------------------------------------------------------------- horizontal (NSSDA)
def test_nssda_forms_and_ratio_test():
    eq = horizontal_accuracy([0.1, -0.1], [0.1, -0.1])
    assert eq["rmser"] == pytest.approx(0.1 * math.sqrt(2))
    assert eq["nssda"]["accuracy_r_1_7308"] == pytest.approx(1.7308 * 0.1 * math.sqrt(2))
    assert eq["nssda"]["accuracy_r"] == pytest.approx(0.24477)  # 2.4477·0.5·(0.1 + 0.1)
    mid = horizontal_accuracy([0.1, -0.1], [0.07, -0.07])  # ratio 0.7: approximation holds
    assert mid["nssda"]["ratio"] == pytest.approx(0.7) and mid["nssda"]["ratio_ok"]
    assert mid["nssda"]["accuracy_r"] == pytest.approx(2.4477 * 0.5 * 0.17)
    far = horizontal_accuracy([0.1, -0.1], [0.05, -0.05])  # ratio 0.5: no NSSDA form
    assert far["nssda"]["ratio_ok"] is False and far["nssda"]["accuracy_r"] is None
    assert far["nssda"]["accuracy_r_1_7308"] == pytest.approx(1.7308 * math.hypot(0.1, 0.05))


# ----------------------------------------------------------------------------- outliers
def test_outliers_listed_but_kept_in_the_figures():
    dz = np.r_[np.tile([0.02, -0.02], 15), 0.50]
    o = outliers(dz, ids=[f"P{i}" for i in range(31)])
    assert [it["index"] for it in o["items"]] == [30] and o["items"][0]["id"] == "P30"
    rmse = math.sqrt((30 * 0.02**2 + 0.5**2) / 31)  # the outlier is inside the RMSE
    assert o["threshold_m"] == pytest.approx(3 * rmse)
    acc = vertical_accuracy(dz, np.zeros(31, bool), ids=[f"P{i}" for i in range(31)])
    assert acc["asprs2014"]["rmsez"] == pytest.approx(rmse, abs=1e-12)
    assert acc["n_nonvegetated"] == 31
    assert [it["id"] for it in acc["outliers"]["items"]] == ["P30"]
    assert outliers(np.tile([0.02, -0.02], 15))["items"] == []


def test_outliers_are_judged_within_their_land_cover_group():
    dz = np.r_[np.tile([0.01, -0.01], 10), 0.4, np.tile([0.3, -0.3], 5)]
    veg = np.r_[np.zeros(21, bool), np.ones(10, bool)]
    items = vertical_accuracy(dz, veg)["outliers"]["items"]
    assert [(it["index"], it["vegetated"]) for it in items] == [(20, False)]


# ----------------------------------------------------------------------------- the TIN
def test_tin_interpolation_exact_on_a_plane_and_ignores_non_ground():
    rng = np.random.default_rng(3)
    cps = cps_on_plane(np.zeros(25), np.zeros(25, bool), rng=rng)
    cloud = ground_cloud(spacing=2.5)
    res = run_pass(cloud, cps, nchunks=5).result()
    for r in res["checkpoints"]:
        assert r["status"] == "ok"
        assert r["z_lidar"] == pytest.approx(plane(r["x"], r["y"]), abs=1e-9)
        assert abs(r["dz"]) < 1e-9
        assert 0 < r["max_edge_m"] < 3 * 2.5  # a local triangle of the 2.5 m lattice
        assert r["nearest_ground_m"] <= r["max_edge_m"]


def test_withheld_ground_points_are_not_used():
    cps = Checkpoints.from_arrays(["A"], [X0 + 50.0], [Y0 + 50.0], [plane(X0 + 50.0, Y0 + 50.0)], ["paved"])
    cloud = ground_cloud(spacing=2.0)
    spike = Cloud([[X0 + 50.0, Y0 + 50.0, 500.0]], {"classification": [2], "withheld": [1]})
    flags = Cloud(cloud.xyz, {"classification": cloud.attrs["classification"], "withheld": np.zeros(cloud.n)})
    p = CheckpointPass(cps, Units())
    p.add(flags)
    p.add(spike)
    assert p.result()["checkpoints"][0]["dz"] == pytest.approx(0.0, abs=1e-9)


def test_checkpoint_outside_the_ground_tin_is_reported_not_dropped():
    rng = np.random.default_rng(5)
    inside = cps_on_plane(np.full(4, 0.05), np.zeros(4, bool), rng=rng, extent=100.0, margin=10.0)
    x = np.r_[inside.x, X0 + 101.0, X0 + 300.0]  # just off the data's east edge; far away
    y = np.r_[inside.y, Y0 + 50.0, Y0 + 50.0]
    z = np.r_[inside.z, 100.0, 100.0]
    cps = Checkpoints.from_arrays(["a", "b", "c", "d", "edge", "far"], x, y, z, ["bare earth"] * 6)
    p = run_pass(ground_cloud(extent=100.0), cps)
    res = p.result()
    status = {r["id"]: r["status"] for r in res["checkpoints"]}
    assert status == {"a": "ok", "b": "ok", "c": "ok", "d": "ok", "edge": "outside_tin", "far": "no_ground"}
    assert [r["id"] for r in res["unmatched"]] == ["edge", "far"]
    assert res["n"] == 6 and res["n_matched"] == 4
    edge = next(r for r in res["checkpoints"] if r["id"] == "edge")
    assert edge["dz"] is None and edge["ground_points"] > 3 and 0.9 < edge["nearest_ground_m"] < 5
    found = [f for f in p.findings() if f.field == "checkpoint"]
    assert sorted(f.found for f in found) == ["no ground", "outside tin"]
    assert all(f.check == "accuracy" and f.severity == "warning" for f in found)


def test_max_points_bounds_the_kept_points_and_stays_exact():
    rng = np.random.default_rng(9)
    cps = cps_on_plane(np.full(3, -0.07), np.zeros(3, bool), rng=rng, extent=40.0, margin=10.0)
    p = run_pass(ground_cloud(spacing=0.25, extent=40.0), cps, nchunks=4, radius_m=5.0,
                 params=CheckpointParams(max_points=60))
    res = p.result()
    for r in res["checkpoints"]:
        assert r["ground_points"] == 60
        assert r["radius_m"] < 5.0 * 0.5  # shrunk to the 60 nearest of ~16 pts/m²
        assert r["dz"] == pytest.approx(-0.07, abs=1e-9)


# ----------------------------------------------------------------------------- units
def test_feet_crs_converts_radius_and_dz_to_metres():
    """Coordinates in US survey feet: the 5 m radius is 16.4 ft, so points on a 10 ft lattice
    reach the checkpoints (a radius left at 5 CRS units would find nothing), and dz given as
    0.1 ft comes out as 0.03048 m."""
    units = Units(US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot")
    rng = np.random.default_rng(11)
    cps = cps_on_plane(np.full(5, 0.1), np.zeros(5, bool), rng=rng, margin=50.0, extent=600.0)
    cloud = ground_cloud(spacing=10.0, extent=600.0)
    ground = cloud.xyz[cloud.attrs["classification"] == 2]
    res = run_pass(cloud, cps, units).result()
    assert [r["status"] for r in res["checkpoints"]] == ["ok"] * 5
    for r in res["checkpoints"]:
        assert r["dz"] == pytest.approx(0.1 * US_SURVEY_FOOT, abs=1e-9)
        assert r["radius_m"] == pytest.approx(5.0)
        nearest_ft = np.hypot(ground[:, 0] - r["x"], ground[:, 1] - r["y"]).min()
        assert r["nearest_ground_m"] == pytest.approx(nearest_ft * US_SURVEY_FOOT, abs=1e-9)
        assert r["max_edge_m"] < 3 * 10 * US_SURVEY_FOOT
    metres = run_pass(cloud, cps, Units()).result()
    assert {r["status"] for r in metres["checkpoints"]} <= {"no_ground", "outside_tin"}


def test_feet_heights_on_metre_eastings():
    units = Units(1.0, FOOT, "metre", "foot")
    rng = np.random.default_rng(12)
    cps = cps_on_plane(np.full(3, 0.5), np.zeros(3, bool), rng=rng)  # 0.5 ft below
    res = run_pass(ground_cloud(spacing=2.0), cps, units).result()
    assert [r["dz"] for r in res["checkpoints"]] == pytest.approx([0.5 * FOOT] * 3, abs=1e-9)


# ----------------------------------------------------------------------------- DEM
def plane_dem(cell=1.0, n=100, crs=None, meta=None):
    xc = X0 + (np.arange(n) + 0.5) * cell
    yc = Y0 + n * cell - (np.arange(n) + 0.5) * cell
    xx, yy = np.meshgrid(xc, yc)
    return Raster(plane(xx, yy), (cell, 0, X0, 0, -cell, Y0 + n * cell), crs, np.nan, meta or {})


def test_dem_accuracy_bilinear_on_plane_and_off_dem_reported():
    rng = np.random.default_rng(13)
    dz = np.r_[DZ_NV, DZ_V]
    veg = np.r_[np.zeros(30, bool), np.ones(10, bool)]
    inside = cps_on_plane(-dz, veg, rng=rng, extent=100.0, margin=5.0)  # DEM − checkpoint = −dz
    cps = Checkpoints.from_arrays(list(inside.id) + ["off"], np.r_[inside.x, X0 - 50], np.r_[inside.y, Y0 + 10],
                                  np.r_[inside.z, 0.0], list(inside.cover) + ["urban"])
    d = dem_accuracy(plane_dem(), cps, checkpoint_rmse_m=0.02)
    np.testing.assert_allclose([r["dz"] for r in d["checkpoints"][:40]], -dz, atol=1e-9)
    assert [r["id"] for r in d["unmatched"]] == ["off"]
    assert d["rmsez"] == pytest.approx(0.042426, abs=1e-5)
    assert d["asprs2014"]["nva"] == pytest.approx(0.083156, abs=1e-5)
    assert d["asprs2014"]["vva"] == pytest.approx(0.0955, abs=1e-9)
    assert d["edition2"]["rmsev"] == pytest.approx(0.046904, abs=1e-5)
    assert d["cell_m"] == 1.0 and d["n"] == 40


def test_dem_accuracy_in_feet(tmp_path):
    units = {"horizontal": "foot", "vertical": "foot", "metres_per_unit": {"horizontal": FOOT, "vertical": FOOT}}
    dem = plane_dem(cell=3.0, n=60, meta={"units": units})
    rng = np.random.default_rng(14)
    cps = cps_on_plane(np.full(4, -0.2), np.zeros(4, bool), rng=rng, extent=180.0)  # DEM 0.2 ft above
    d = dem_accuracy(dem, cps)
    assert d["cell_m"] == pytest.approx(3.0 * FOOT)
    assert d["rmsez"] == pytest.approx(0.2 * FOOT, abs=1e-9)


def test_three_x_rule_states_pass_or_fail_with_numbers():
    fine = three_x_rule(0.5, 0.2, 0.7, checkpoint_rmse_m=0.05)
    assert [(r["value"], r["threshold"], r["pass"]) for r in fine] == [
        (0.5, pytest.approx(0.6), False), (0.5, 0.7, False), (0.05, pytest.approx(0.2 / 3), True)]
    ok = three_x_rule(1.0, 0.2, 0.7, checkpoint_rmse_m=0.1)
    assert [r["pass"] for r in ok] == [True, True, False]
    unknown = three_x_rule(1.0, None, None)
    assert [(r["threshold"], r["pass"]) for r in unknown] == [(None, None), (None, None)]
    assert all(r["unit"] == "m" and r["source"] for r in fine)


# ----------------------------------------------------------------------------- the CSV
def write(tmp_path, text, name="cp.csv"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_read_checkpoints_header_spellings_and_cover_words(tmp_path):
    p = write(tmp_path, "# survey 2024\nEasting,Northing,Elevation,Land_Cover,Point\n"
                        "500010.5,4100020.25,101.5,Open Terrain,CP1\n"
                        "500011,4100021,102,tall-grass,CP2\n\n"
                        "500012,4100022,103,VVA,CP3\n500013,4100023,104,nva,CP4\n")
    cps = read_checkpoints(p)
    assert list(cps.id) == ["CP1", "CP2", "CP3", "CP4"]
    assert cps.x.tolist() == [500010.5, 500011.0, 500012.0, 500013.0]
    assert cps.y[0] == 4100020.25 and cps.z.tolist() == [101.5, 102.0, 103.0, 104.0]
    assert cps.vegetated.tolist() == [False, True, True, False]
    assert cps.cover[1] == "tall-grass"
    with pytest.raises(ValueError):
        cps.x[0] = 0.0  # read-only


def test_read_checkpoints_without_header_in_order(tmp_path):
    cps = read_checkpoints(write(tmp_path, "A 1.5 2.5 3.5 open terrain\nB 4 5 6 forest\n"))
    assert list(cps.id) == ["A", "B"] and cps.z.tolist() == [3.5, 6.0]
    assert list(cps.cover) == ["open terrain", "forest"] and cps.vegetated.tolist() == [False, True]
    bare = read_checkpoints(write(tmp_path, "A;1;2;3\nB;4;5;6\n", "b.csv"))
    assert list(bare.cover) == ["unspecified"] * 2 and not bare.vegetated.any()
    noid = read_checkpoints(write(tmp_path, "x,y,z,class\n1,2,3,urban\n4,5,6,brush\n", "c.csv"))
    assert list(noid.id) == ["2", "3"] and noid.vegetated.tolist() == [False, True]


@pytest.mark.parametrize("text, where", [
    ("id,x,y,z,cover\nA,1,2,3,open\nB,4,5,6,grass\n", "line 3, column 'cover': unknown land cover 'grass'"),
    ("id,x,y,z,cover\nA,1,2,3,open\nB,4,abc,6,open\n", "line 3, column 'y': 'abc' is not a number"),
    ("A,1,2,3,open\nB,4,5,inf,open\n", "line 2, column 'z': 'inf' is not finite"),
    ("id,x,y,height\nA,1,2,3\nB,4,5\n", "line 3: 3 fields, expected at least 4"),
    ("id,east,north,elev\nA,1,2,3\nA,4,5,6\n", "checkpoint id 'A' repeats line 2"),
    ("name,x,y\nA,1,2\n", "names no z column"),
    ("id,x,y,z\n", "only a header"),
    ("# nothing\n\n", "no checkpoints"),
])
def test_bad_checkpoint_files_name_the_line(tmp_path, text, where):
    with pytest.raises(InvalidInputError) as e:
        read_checkpoints(write(tmp_path, text))
    assert where in str(e.value)
    assert "cp.csv" in str(e.value)


def test_missing_checkpoint_file(tmp_path):
    with pytest.raises(InvalidInputError, match="not found"):
        read_checkpoints(tmp_path / "none.csv")


def test_vertical_accuracy_rejects_mismatched_input():
    with pytest.raises(InvalidInputError, match="2 errors but 3"):
        vertical_accuracy([0.1, 0.2], [True, False, True])
    with pytest.raises(InvalidInputError, match="finite"):
        vertical_accuracy([0.1, np.nan])
    empty = vertical_accuracy(np.array([0.1]), np.array([True]))
    assert empty["asprs2014"]["rmsez"] is None and empty["asprs2014"]["nva"] is None
    assert empty["asprs2014"]["vva"] == pytest.approx(0.1)


# ----------------------------------------------------------------------------- real data
@pytest.mark.realdata
def test_checkpoints_on_real_ground_points_are_recovered(shared_data):
    """Checkpoints placed on 30 ground points of a real ALS file with known offsets: the TIN
    has a vertex there, so dz comes back exactly, through the streaming reader."""
    from workstation.io.registry import iter_chunks, read_cloud

    path = shared_data / "lidar" / "Topography.laz"
    if not path.exists():
        pytest.skip("Topography.laz absent")
    cloud = read_cloud(path)
    g = np.flatnonzero(cloud.attrs["classification"] == 2)
    lo, hi = cloud.xyz[g, :2].min(0) + 30, cloud.xyz[g, :2].max(0) - 30
    inner = g[np.all((cloud.xyz[g, :2] > lo) & (cloud.xyz[g, :2] < hi), axis=1)]
    pick = np.random.default_rng(0).choice(inner, 30, replace=False)
    dz = np.linspace(-0.15, 0.15, 30)
    xyz = cloud.xyz[pick]
    cps = Checkpoints.from_arrays([f"R{i}" for i in range(30)], xyz[:, 0], xyz[:, 1], xyz[:, 2] - dz,
                                  ["bare earth"] * 30)
    p = CheckpointPass(cps, Units())
    for c in iter_chunks(path, 20_000):
        p.add(c, str(path))
    rows = p.result()["checkpoints"]
    assert [r["status"] for r in rows] == ["ok"] * 30
    np.testing.assert_allclose([r["dz"] for r in rows], dz, atol=1e-6)


def test_error_stats_shape_by_hand():
    from workstation.qc.accuracy import error_stats

    s = error_stats([-1.0, -1.0, 1.0, 1.0])  # m2 = m4 = 1: g2 = -2, G2 = (5·(-2) + 6)·3/(2·1) = -6
    assert s["skew"] == pytest.approx(0.0) and s["kurtosis"] == pytest.approx(-6.0)
    assert s["std"] == pytest.approx(math.sqrt(4 / 3)) and s["nmad"] == pytest.approx(1.4826)
    skewed = error_stats([0.0, 0.0, 3.0])  # m2 = 2, m3 = 2: g1 = 2/2^1.5, G1 = g1·sqrt(6)/1
    assert skewed["skew"] == pytest.approx(2 / 2**1.5 * math.sqrt(6))
    assert error_stats([0.2, 0.2, 0.2])["skew"] is None
