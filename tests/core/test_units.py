"""The unit model: length parsing, CRS units (pyproj, GeoKey overrides, compound CRSs),
plausibility warnings, grids sized by points, and unit-aware labels."""

from types import SimpleNamespace

import laspy
import numpy as np
import pytest

from workstation.core.budget import fit_cell
from workstation.core.units import FOOT, METRES, US_SURVEY_FOOT, Units, parse_length
from workstation.io.crs import crs_units, crs_warnings, override_units, unit_geokeys

US = Units(US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot")


@pytest.mark.parametrize("text, metres", [("2.5", 2.5), ("1m", 1.0), ("3ft", 3 * FOOT), ("3 ft", 3 * FOOT),
                                          ("2usft", 2 * US_SURVEY_FOOT), ("10cm", 0.1), ("1.5km", 1500.0),
                                          ("1e-1", 0.1), (4, 4.0)])
def test_parse_length(text, metres):
    assert parse_length(text) == pytest.approx(metres, rel=1e-12)


@pytest.mark.parametrize("text", ["", "ft", "3 parsec", "1..2", "m3"])
def test_parse_length_refuses(text):
    with pytest.raises(ValueError):
        parse_length(text)


def test_units_convert_both_ways_and_describe():
    assert US.h_from_m(1.0) == pytest.approx(3.280833333, rel=1e-9)
    assert US.v_to_m(US.v_from_m(7.0)) == pytest.approx(7.0)
    assert US.area_to_m2(1.0) == pytest.approx(US_SURVEY_FOOT ** 2)
    assert US.describe_h(1.0) == "1 m (3.281 US ft in the CRS units)"
    assert METRES.describe_v(2.5) == "2.5 m"
    assert Units.from_dict(US.to_dict()) == US
    assert Units.from_dict({"metres_per_unit": {"horizontal": -1, "vertical": 1}}) is None
    # feet heights on metre cells: slopes need 0.3048 x the height differences
    assert Units(1.0, FOOT, "metre", "foot").z_factor == pytest.approx(FOOT)


@pytest.mark.parametrize("crs, h, v, hname, vname", [
    ("EPSG:32632", 1.0, 1.0, "metre", "metre"),
    ("EPSG:2994", FOOT, FOOT, "foot", "foot"),
    ("EPSG:2264", US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot"),
    ("EPSG:26910+6360", 1.0, US_SURVEY_FOOT, "metre", "US survey foot"),   # compound: NAVD88 height (ftUS)
    ("EPSG:2264+5703", US_SURVEY_FOOT, 1.0, "US survey foot", "metre"),    # feet plan, metre heights
])
def test_crs_units_horizontal_and_vertical(crs, h, v, hname, vname):
    u = crs_units(crs)
    assert (u.h, u.v, u.h_name, u.v_name) == (pytest.approx(h, rel=1e-12), pytest.approx(v, rel=1e-12), hname, vname)


def test_crs_units_geographic_and_unknown():
    g = crs_units("EPSG:4326")
    assert g.geographic and g.h_name == "degree" and g.v == 1.0
    assert crs_units(None) == Units(known=False) and crs_units(None).is_metric


def test_override_units_like_geokeys():
    import pyproj

    c = pyproj.CRS.from_epsg(26910)
    feet = override_units(c, 9003, 9003)
    u = crs_units(feet.to_wkt())
    assert u.h == pytest.approx(US_SURVEY_FOOT) and u.v == pytest.approx(US_SURVEY_FOOT)
    assert feet.to_epsg() is None  # no longer EPSG:26910, whose unit is the metre
    mixed = crs_units(override_units(c, 9001, 9003).to_wkt())
    assert (mixed.h, mixed.v) == (1.0, pytest.approx(US_SURVEY_FOOT))
    assert override_units(c, 9001, 9001) is c  # nothing to override: the EPSG code stays


def test_unit_geokeys_ignored_under_a_wkt_vlr():
    keys = SimpleNamespace(record_id=34735, user_id="LASF_Projection",
                           geo_keys=[SimpleNamespace(id=3072, tiff_tag_location=0, value_offset=26910),
                                     SimpleNamespace(id=3076, tiff_tag_location=0, value_offset=9003)])
    assert unit_geokeys([keys]) == {3076: 9003}
    assert unit_geokeys([keys, SimpleNamespace(record_id=2112, user_id="LASF_Projection")]) == {}


def _write_geokeys_las(path, xyz, epsg, h_unit=None, v_unit=None):
    from laspy.vlrs.geotiff import GeoKeyEntryStruct
    from laspy.vlrs.known import GeoKeyDirectoryVlr

    keys = [(1024, 0, 1, 1), (3072, 0, 1, epsg)] + ([(3076, 0, 1, h_unit)] if h_unit else []) \
        + ([(4099, 0, 1, v_unit)] if v_unit else [])
    vlr = GeoKeyDirectoryVlr()
    vlr.geo_keys_header.key_directory_version, vlr.geo_keys_header.key_revision = 1, 1
    vlr.geo_keys_header.number_of_keys = len(keys)
    vlr.geo_keys = [GeoKeyEntryStruct(*k) for k in keys]
    h = laspy.LasHeader(point_format=1, version="1.2")
    h.offsets, h.scales = np.floor(xyz.min(0)), [0.001] * 3
    h.vlrs.append(vlr)
    las = laspy.LasData(h)
    las.x, las.y, las.z = xyz.T
    las.write(str(path))


def test_las_reader_honours_unit_geokeys(tmp_path):
    from workstation.io import read_cloud

    xyz = np.array([[1640420.0, 16404170.0, 330.0], [1640500.0, 16404250.0, 335.0]])
    _write_geokeys_las(tmp_path / "f.las", xyz, 26910, 9003, 9003)
    _write_geokeys_las(tmp_path / "v.las", xyz / 3.2808333, 26910, 9001, 9003)
    _write_geokeys_las(tmp_path / "m.las", xyz / 3.2808333, 26910, 9001, 9001)
    f, v, m = (crs_units(read_cloud(tmp_path / n).crs) for n in ("f.las", "v.las", "m.las"))
    assert f.h_name == f.v_name == "US survey foot"
    assert (v.h_name, v.v_name) == ("metre", "US survey foot")
    assert read_cloud(tmp_path / "m.las").crs == "EPSG:26910"


def test_crs_warnings_name_the_reason():
    near = ([500_000.0, 5_000_000.0, 100.0], [500_500.0, 5_000_500.0, 130.0])
    assert crs_warnings("EPSG:26910", near) == []
    geoc = crs_warnings("EPSG:4978", near)
    assert len(geoc) == 1 and "geocentric" in geoc[0] and "look projected" in geoc[0]
    # true ECEF coordinates (a point in Oregon) pass
    assert crs_warnings("EPSG:4978", ([-2_500_000.0, -3_800_000.0, 4_500_000.0], [-2_499_000.0, -3_799_000.0, 4_501_000.0])) == []
    assert "longitudes" in crs_warnings("EPSG:4326", near)[0]
    assert crs_warnings("EPSG:4326", ([-123.1, 45.0, 0.0], [-123.0, 45.1, 10.0])) == []
    far = crs_warnings("EPSG:26910", ([1_640_418.0, 16_404_167.0, 0.0], [1_656_820.0, 16_420_561.0, 10.0]))
    assert len(far) == 1 and "area of use" in far[0] and "feet read as metres" in far[0]
    vert = crs_warnings("EPSG:26910+6360", near)
    assert len(vert) == 1 and "heights are in US survey foot" in vert[0]


def test_fit_cell_sizes_grids_by_points():
    assert fit_cell(1.0, 150.0, 150.0, 20_000) == 1.0           # ordinary density: a default stays
    c = fit_cell(1.0, 5000.0, 5000.0, 6000)                     # 6,000 points over 25 km²
    assert c in (2.0, 2.5, 5.0, 10.0, 20.0)
    cells = (5000 / c + 1) ** 2
    assert cells <= max(16 * 6000, 1 << 18)


def test_length_click_type():
    import click

    from workstation.cli.options import Length

    t = Length(auto=True)
    assert t.convert("3ft", None, None) == pytest.approx(0.9144)
    assert t.convert("auto", None, None) is None
    for bad in ("-1", "0", "nan", "1 parsec"):
        with pytest.raises(click.BadParameter):
            t.convert(bad, None, None)


def test_scale_bar_is_metres_in_crs_units():
    from workstation.render.render import scale_bar

    w_ft, label_ft = scale_bar(1.0, 800, US)          # 200 ft across a quarter: 60.96 m -> a 50 m bar
    w_m, label_m = scale_bar(1.0, 800, METRES)        # 200 m -> a 200 m bar
    assert label_ft == "50 m" and w_ft == pytest.approx(50 / US_SURVEY_FOOT)
    assert label_m == "200 m" and w_m == pytest.approx(200.0)


def test_render_elevation_in_metres_with_a_true_label():
    from workstation.core.cloud import Cloud
    from workstation.render.render import RenderParams, _scalar_colors

    xyz = np.array([[0.0, 0.0, 100.0], [10.0, 0.0, 110.0], [0.0, 10.0, 120.0]])
    _, _, z_ft, title_ft = _scalar_colors(Cloud(xyz, {}, crs="EPSG:2264"), RenderParams(color="elevation"))
    _, _, z_m, title_m = _scalar_colors(Cloud(xyz * US_SURVEY_FOOT, {}, crs="EPSG:32617"), RenderParams(color="elevation"))
    assert title_ft == title_m == "Elevation (m)"
    np.testing.assert_allclose(z_ft, z_m)
    assert _scalar_colors(Cloud(xyz, {}), RenderParams(color="elevation"))[3] == "Elevation (m, no CRS)"


def test_hillshade_and_slope_convert_feet_heights():
    from workstation.core.products import Raster
    from workstation.raster.terrain import hillshade, slope

    yy, xx = np.mgrid[0:20, 0:20].astype(float)
    z_m = 0.3 * xx + 0.1 * yy
    metre = Raster(z_m, (1.0, 0, 0, 0, -1.0, 20.0), meta={"units": METRES.to_dict()})
    feet_heights = Raster(z_m / FOOT, (1.0, 0, 0, 0, -1.0, 20.0),
                          meta={"units": Units(1.0, FOOT, "metre", "foot").to_dict()})
    np.testing.assert_array_equal(hillshade(metre).array, hillshade(feet_heights).array)
    np.testing.assert_allclose(slope(metre).array, slope(feet_heights).array, atol=1e-4)
