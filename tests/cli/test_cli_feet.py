"""Every command on a metre file and its US-survey-feet copy gives the same products after
conversion: a metre stays a metre whatever the CRS unit (the feet copy is the metre file's
coordinates divided by 0.3048006096 m/ft, written under the same EPSG code with GeoKeys
overriding its horizontal and vertical units to US survey feet, as real files do)."""

import json

import laspy
import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.units import US_SURVEY_FOOT as US_FT

EPSG = 26910  # NAD83 / UTM zone 10N, metres; the data lie inside its area of use


def _geokeys(h_unit=None, v_unit=None, epsg=EPSG):
    from laspy.vlrs.geotiff import GeoKeyEntryStruct
    from laspy.vlrs.known import GeoKeyDirectoryVlr

    keys = [(1024, 0, 1, 1), (1025, 0, 1, 1), (3072, 0, 1, epsg)]
    keys += [(3076, 0, 1, h_unit)] if h_unit else []
    keys += [(4099, 0, 1, v_unit)] if v_unit else []
    vlr = GeoKeyDirectoryVlr()
    vlr.geo_keys_header.key_directory_version, vlr.geo_keys_header.key_revision = 1, 1
    vlr.geo_keys_header.number_of_keys = len(keys)
    vlr.geo_keys = [GeoKeyEntryStruct(*k) for k in keys]
    return vlr


def write_las(path, xyz, cls, scale, feet=False, epsg=EPSG, offsets=None):
    """A LAS 1.2 file with a GeoKey directory (unit overrides to US survey feet with ``feet``)."""
    h = laspy.LasHeader(point_format=1, version="1.2")
    h.offsets = np.floor(xyz.min(axis=0)) if offsets is None else offsets
    h.scales = [scale] * 3
    h.vlrs.append(_geokeys(9003, 9003, epsg) if feet else _geokeys(epsg=epsg))
    las = laspy.LasData(h)
    las.x, las.y, las.z = xyz.T
    las.classification = cls
    las.return_number, las.number_of_returns = np.ones(len(xyz), np.uint8), np.ones(len(xyz), np.uint8)
    las.write(str(path))


def terrain(n, size, seed):
    """Rolling terrain with a tilted plane and one 30 m x 30 m, 8 m high building (class 6)."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0.0, size, (n, 2))
    z = 100.0 + 5.0 * np.sin(xy[:, 0] / 30.0) + 0.05 * xy[:, 1]
    roof = (np.abs(xy[:, 0] - size / 2) < 15) & (np.abs(xy[:, 1] - size / 2) < 15)
    z[roof] += 8.0
    cls = np.where(roof, 6, 2).astype(np.uint8)
    return np.column_stack([xy[:, 0] + 500_000.3, xy[:, 1] + 5_000_000.7, z]), cls


def lattice(spacing, size, angle):
    """Points on a square lattice (``spacing`` apart, turned by ``angle`` radians) over rolling,
    twisted ground with one 12 m x 10 m building (class 6): every quad of neighbours is
    co-circular, points fall on cell edges and cell centres are equally far from several
    points, the ties where a DEM decides by the rounding of the coordinates."""
    g = np.arange(0.0, size, spacing)
    gx, gy = (a.ravel() for a in np.meshgrid(g, g))
    x, y = np.cos(angle) * gx - np.sin(angle) * gy, np.sin(angle) * gx + np.cos(angle) * gy
    z = 100.0 + 5.0 * np.sin(x / 7.0) + 0.002 * x * y + 0.5 * np.cos(y / 5.0)
    roof = (np.abs(x - size / 3) < 6) & (np.abs(y - size / 2) < 5)
    z[roof] += 8.0
    cls = np.where(roof, 6, 2).astype(np.uint8)
    return np.column_stack([x + 500_000.0, y + 5_000_000.0, z]), cls


def _write_pair(d, xyz, cls, scale):
    """(metre file, feet copy): the feet copy holds the metre file's coordinates / 0.3048006096,
    with the scale and offsets in feet too, so both files store the same integers and hold
    exactly the same points."""
    m, f = d / "m.las", d / "f.las"
    write_las(m, xyz, cls, scale)
    src = laspy.read(str(m))
    write_las(f, src.xyz / US_FT, cls, scale / US_FT, feet=True, offsets=np.asarray(src.header.offsets) / US_FT)
    return m, f


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    """(metre file, feet copy): 6,000 points over 120 m x 120 m."""
    xyz, cls = terrain(6000, 120.0, 7)
    return _write_pair(tmp_path_factory.mktemp("feet"), xyz, cls, 1e-4)  # 0.1 mm: fewer exact ties with the filters' thresholds


@pytest.fixture(scope="module", params=[(0.5, 0.0), (0.8, 0.35)], ids=["grid-0.5m", "turned-0.8m"])
def lattice_pair(request, tmp_path_factory):
    """(metre file, feet copy) of a lattice of points (:func:`lattice`, 60 m x 60 m): one on
    the cell edges of 0.5 m, 1 m and 2 m DEMs, one turned by 20 degrees."""
    return _lattice_pair(tmp_path_factory, *request.param)


def _lattice_pair(tmp_path_factory, spacing, angle):
    xyz, cls = lattice(spacing, 60.0, angle)
    return _write_pair(tmp_path_factory.mktemp("lattice"), xyz, cls, 1e-3)


def _run(capsys, *args):
    rc = main([str(a) for a in args])
    out, err = capsys.readouterr()
    return rc, out, err


def _json(capsys, *args):
    rc, out, err = _run(capsys, *args, "--json")
    assert rc == 0, err
    return json.loads(out), err


def _dem(capsys, src, out, *opts):
    return _json(capsys, "dem", src, "-o", out, "--overwrite", *opts)


def _assert_same_heights(m_tif, f_tif, scale=US_FT):
    """The metre raster and the feet raster (values × ``scale``) cover the same cells, with
    the same cells missing, and every cell holds the same value within 1 mm."""
    from workstation.io.geotiff import read_raster

    rm, rf = read_raster(m_tif), read_raster(f_tif)
    assert rm.shape == rf.shape
    np.testing.assert_allclose(np.asarray(rf.transform) * US_FT, rm.transform, atol=1e-3)
    am, af = np.asarray(rm.array, float), np.asarray(rf.array, float) * scale
    np.testing.assert_array_equal(np.isnan(am), np.isnan(af))
    assert np.isfinite(am).sum() > 0.25 * am.size  # not a vacuous comparison
    np.testing.assert_allclose(af, am, rtol=0, atol=1e-3)


@pytest.mark.parametrize("opts", [("--resolution", "1"), ("--resolution", "auto"), ("--resolution", "3ft")])
def test_dem_in_feet_equals_dem_in_metres(pair, tmp_path, capsys, opts):
    m, f = pair
    jm, _ = _dem(capsys, m, tmp_path / "m.tif", *opts)
    jf, err = _dem(capsys, f, tmp_path / "f.tif", *opts)
    assert jf["resolution_m"] == pytest.approx(jm["resolution_m"], abs=1e-9)
    assert jf["resolution"] == pytest.approx(jm["resolution_m"] / US_FT)
    assert jf["resolution_unit"] == "US survey foot" and jf["z_unit"] == "US survey foot"
    assert f"{jm['resolution_m']:g} m (" in err and "US ft in the CRS units" in err
    _assert_same_heights(tmp_path / "m.tif", tmp_path / "f.tif")


@pytest.mark.parametrize("resolution", ["1", "3ft"])
@pytest.mark.parametrize("opts", [
    ("--method", "tin"), ("--method", "nn"), ("--method", "idw"), ("--max-edge", "2"), ("--kind", "dsm"),
    ("--kind", "dsm", "--method", "tin"), ("--kind", "chm", "--pit-free"),
], ids=lambda o: "-".join(x.strip("-") for x in o))
def test_every_dem_of_a_lattice_in_feet_equals_metres(lattice_pair, tmp_path, capsys, opts, resolution):
    """On a lattice every interpolation meets ties (co-circular quads, points on cell edges,
    equidistant neighbours, edges as long as the freeze distance); the DEM of the feet copy
    still matches the metre DEM in every cell."""
    m, f = lattice_pair
    _dem(capsys, m, tmp_path / "m.tif", "--resolution", resolution, *opts)
    _dem(capsys, f, tmp_path / "f.tif", "--resolution", resolution, *opts)
    _assert_same_heights(tmp_path / "m.tif", tmp_path / "f.tif")


@pytest.fixture(scope="module", params=["random", "turned-lattice"])
def dems(request, tmp_path_factory):
    """The 1 m DTMs of a metre file and of its feet copy (random points, a turned lattice)."""
    d = tmp_path_factory.mktemp("dems")
    out = []
    files = request.getfixturevalue("pair") if request.param == "random" else _lattice_pair(tmp_path_factory, 0.8, 0.35)
    for src in files:
        assert main(["dem", str(src), "-o", str(d / f"{src.stem}.tif"), "--resolution", "1"]) == 0
        out.append(d / f"{src.stem}.tif")
    return out


@pytest.mark.parametrize("opts", [("--interval", "1", "--base", "0.5"), ("--interval", "2ft"), ()])
def test_contours_in_feet_equal_contours_in_metres(dems, tmp_path, capsys, opts):
    res = []
    for dem in dems:
        j, err = _json(capsys, "contours", dem, "-o", tmp_path / f"{dem.stem}.geojson", "--overwrite", *opts)
        fc = json.loads((tmp_path / f"{dem.stem}.geojson").read_text())
        res.append((j, err, sorted(feat["properties"]["elevation"] for feat in fc["features"])))
    (jm, _, lm), (jf, errf, lf) = res
    assert jf["interval_m"] == pytest.approx(jm["interval_m"]) and jf["z_unit"] == "US survey foot"
    assert jf["interval"] == pytest.approx(jm["interval_m"] / US_FT)
    assert "US ft in the CRS units" in errf
    assert len(lf) == len(lm) > 0
    np.testing.assert_allclose(np.asarray(lf) * US_FT, lm, atol=1e-3)


def test_hillshade_of_feet_dem_equals_metre_dem(dems, tmp_path, capsys):
    from workstation.io.geotiff import read_raster

    for dem in dems:
        assert _run(capsys, "hillshade", dem, "-o", tmp_path / f"{dem.stem}_hs.tif")[0] == 0
    hm, hf = (np.asarray(read_raster(tmp_path / f"{d.stem}_hs.tif").array, int) for d in dems)
    assert np.abs(hm - hf).max() <= 1


def test_info_density_and_area_in_metres(pair, capsys):
    sm, _ = _json(capsys, "info", pair[0])
    sf, _ = _json(capsys, "info", pair[1])
    for key in ("density_occupied", "density_footprint", "footprint_area_m2", "occupied_area_m2", "nps_m"):
        assert sf["density"][key] == pytest.approx(sm["density"][key], rel=1e-6), key
    assert sf["units"]["horizontal"] == sf["units"]["vertical"] == "US survey foot"
    assert sf["crs_warnings"] == [] and sm["crs_warnings"] == []
    assert sf["density"]["footprint_area_m2"] == pytest.approx(120 * 120, rel=0.02)


@pytest.mark.parametrize("method", ["smrf", "pmf"])
def test_ground_classes_identical_in_feet(pair, tmp_path, capsys, method):
    out = []
    for src in pair:
        dst = tmp_path / f"{src.stem}_g.las"
        rc, _, err = _run(capsys, "ground", src, "-o", dst, "--method", method, "--reclassify")
        assert rc == 0, err
        out.append(np.asarray(laspy.read(str(dst)).classification))
    assert (out[0] == 2).sum() > 1000
    np.testing.assert_array_equal(out[0], out[1])


def test_info_reports_vertical_feet_under_metres_and_geocentric(tmp_path, capsys):
    xyz, cls = terrain(300, 50.0, 3)
    # metre plan, US-feet heights: the vertical unit is reported
    h = laspy.LasHeader(point_format=1, version="1.2")
    h.offsets, h.scales = np.floor(xyz.min(axis=0)), [0.001] * 3
    h.vlrs.append(_geokeys(9001, 9003))
    las = laspy.LasData(h)
    las.x, las.y, las.z = xyz.T
    las.write(str(tmp_path / "v.las"))
    s, _ = _json(capsys, "info", tmp_path / "v.las")
    assert s["units"]["vertical"] == "US survey foot" and s["units"]["horizontal"] == "metre"
    assert any("heights are in US survey foot" in w for w in s["crs_warnings"])
    rc, out, _ = _run(capsys, "info", tmp_path / "v.las")
    assert rc == 0 and "heights in US survey foot" in out
    # a geocentric CRS on projected coordinates
    write_las(tmp_path / "g.las", xyz, cls, 0.001, epsg=4978)
    s, _ = _json(capsys, "info", tmp_path / "g.las")
    assert len(s["crs_warnings"]) == 1 and "geocentric" in s["crs_warnings"][0]


@pytest.fixture(scope="module")
def sparse(tmp_path_factory):
    """6,000 points over 5 km x 5 km, in US survey feet by GeoKey overrides."""
    xyz, cls = terrain(6000, 5000.0, 11)
    p = tmp_path_factory.mktemp("sparse") / "sparse.las"
    write_las(p, xyz / US_FT, cls, 0.001, feet=True)
    return p


def test_sparse_extent_info_in_metres(sparse, capsys):
    s, _ = _json(capsys, "info", sparse)
    assert s["crs_warnings"] == []  # read in feet, the coordinates fit the CRS's area of use
    assert s["density"]["footprint_area_m2"] == pytest.approx(25e6, rel=0.05)
    assert s["density"]["density_footprint"] == pytest.approx(6000 / 25e6, rel=0.05)


def test_sparse_extent_dem_sized_by_points(sparse, tmp_path, capsys):
    j, err = _dem(capsys, sparse, tmp_path / "s.tif")
    assert j["rows"] * j["cols"] <= 16 * 6000  # a cell near the point spacing, not a 1 m grid of the box
    assert j["resolution_m"] >= 50 and "points over" in j["resolution_reason"]
    rc, _, err = _run(capsys, "dem", sparse, "-o", tmp_path / "x.tif", "--resolution", "0.5")
    assert rc == 1 and "--resolution" in err  # an absurd request is refused, naming the option
    rc, _, err = _run(capsys, "contours", tmp_path / "s.tif", "-o", tmp_path / "s.geojson")
    assert rc == 0, err


def test_sparse_extent_ground_coarsens_default_cell_only(sparse, tmp_path, capsys):
    rc, _, err = _run(capsys, "ground", sparse, "-o", tmp_path / "g.las", "--method", "lowest")
    assert rc == 0, err
    assert (laspy.read(str(tmp_path / "g.las")).classification == 2).sum() > 3000
    rc, _, err = _run(capsys, "ground", sparse, "-o", tmp_path / "g2.las", "--method", "smrf", "--cell", "0.1")
    assert rc == 1 and "--cell" in err


LIDAR = ["MixedConifer.laz", "Topography.laz", "TreeLS_pine.laz", "autzen_trim.las", "bcts_1.laz", "bcts_2.laz",
         "fullwave.laz", "lidarhd_extra_bytes.laz", "sample_c.las", "vegetation_1_3.las", "warsaw_small.las"]


@pytest.mark.realdata
@pytest.mark.parametrize("name", LIDAR)
def test_real_files_units_and_crs_fit(shared_data, capsys, name):
    s, _ = _json(capsys, "info", shared_data / "lidar" / name)
    assert s["crs_warnings"] == []  # every CRS of the real files fits its coordinates
    feet = name == "autzen_trim.las"  # its WKT says international feet
    assert s["units"]["horizontal"] == ("foot" if feet else "metre")
    assert s["units"]["known"] == (s["crs"] is not None)
    lo, hi = np.asarray(s["bounds"]["min"]), np.asarray(s["bounds"]["max"])
    box_m2 = float(np.prod(hi[:2] - lo[:2])) * s["units"]["metres_per_unit"]["horizontal"] ** 2
    assert 0.3 * box_m2 < s["density"]["footprint_area_m2"] <= box_m2 * 1.0001


@pytest.mark.realdata
def test_real_feet_file_dem_and_contours_in_metres(shared_data, tmp_path, capsys):
    src = shared_data / "lidar" / "autzen_trim.las"
    j, err = _dem(capsys, src, tmp_path / "a.tif", "--kind", "dsm", "--resolution", "2")
    assert j["resolution_m"] == 2.0 and j["resolution_unit"] == "foot"
    assert j["resolution"] == pytest.approx(2 / 0.3048) and "6.562 ft in the CRS units" in err
    c, err = _json(capsys, "contours", tmp_path / "a.tif", "-o", tmp_path / "a.geojson", "--interval", "5")
    assert c["interval"] == pytest.approx(5 / 0.3048) and c["interval_m"] == pytest.approx(5.0)
