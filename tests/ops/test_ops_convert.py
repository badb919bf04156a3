"""ws convert: scales and offsets that fit the target CRS, and a 1 mm round trip through degrees."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud
from workstation.io.las import auto_offsets, auto_scales, read_header


def _utm_cloud(rng, n=5000, extent=800.0) -> Cloud:
    """A UTM 32N survey on a 1 cm grid (as a LAS file at scale 0.01 stores it)."""
    xyz = np.column_stack([rng.uniform(0, extent, n) + 480000.0, rng.uniform(0, extent, n) + 5450000.0,
                           rng.uniform(300, 420, n)])
    return Cloud(np.round(xyz, 2), {"intensity": rng.integers(0, 5000, n)}, crs="EPSG:32632")


def _round_trip(tmp_path, src, crs):
    """IN -> EPSG:4326 -> crs with the automatic scales; returns (geographic header, back cloud)."""
    geo, back = tmp_path / "geo.laz", tmp_path / "back.laz"
    assert main(["convert", str(src), str(geo), "--to-crs", "EPSG:4326"]) == 0
    assert main(["convert", str(geo), str(back), "--to-crs", crs]) == 0
    return read_header(geo), read_cloud(back)


def test_auto_scales_keep_the_source_resolution():
    assert auto_scales("EPSG:4326").tolist() == [1e-7, 1e-7, 0.001]
    assert auto_scales("EPSG:4326", [0.01, 0.01, 0.01], "EPSG:32632").tolist() == [1e-9, 1e-9, 0.01]
    assert auto_scales("EPSG:4326", [0.001] * 3, "EPSG:32632").tolist()[:2] == [1e-10, 1e-10]
    assert auto_scales("EPSG:32632", [1e-7, 1e-7, 0.01], "EPSG:4326").tolist() == [0.01, 0.01, 0.01]
    assert auto_scales("EPSG:32632", [1e-9, 1e-9, 0.01], "EPSG:4326").tolist()[:2] == [1e-4, 1e-4]
    assert auto_scales("EPSG:2994", [0.01] * 3, "EPSG:32610").tolist()[:2] == [0.01, 0.01]  # metres -> feet
    # offsets at the rounded centre, inside the 32-bit reach of the scale
    off = auto_offsets([-123.07, 44.05, 406], [-123.06, 44.06, 520], [1e-9, 1e-9, 0.01], "EPSG:4326")
    assert off.tolist() == [-123.1, 44.1, 0.0]
    assert auto_offsets([481260, 3812921, 0], [481350, 3813011, 32], [0.01] * 3, "EPSG:26912").tolist() == [481000, 3813000, 0]


def test_round_trip_through_degrees_within_a_millimetre(tmp_path, rng):
    src = tmp_path / "utm.laz"
    cloud = _utm_cloud(rng)
    write_cloud(cloud, src, scales=[0.01] * 3)
    geo, back = _round_trip(tmp_path, src, "EPSG:32632")
    assert geo["scales"][:2] == [1e-9, 1e-9] and geo["scales"][2] == 0.01  # heights keep their scale
    assert abs(geo["offsets"][0] - 8.7) < 1 and abs(geo["offsets"][1] - 49.2) < 1  # the data's rounded centre
    assert np.abs(back.xyz - cloud.xyz).max() < 0.001
    assert np.abs(back.xyz[:, 2] - cloud.xyz[:, 2]).max() < 1e-9  # vertical as is
    assert np.array_equal(back.attrs["intensity"], cloud.attrs["intensity"])


def test_explicit_scale_and_offset(tmp_path, rng, capsys):
    src, out = tmp_path / "utm.laz", tmp_path / "g.las"
    write_cloud(_utm_cloud(rng, 500), src, scales=[0.01] * 3)
    assert main(["convert", str(src), str(out), "--to-crs", "EPSG:4326", "--scale", "1e-7,1e-7,0.001",
                 "--offset", "8,49,0", "--pipeline-out", str(tmp_path / "p.json")]) == 0
    h = read_header(out)
    assert h["scales"] == [1e-7, 1e-7, 0.001] and h["offsets"] == [8.0, 49.0, 0.0]
    stages = json.loads((tmp_path / "p.json").read_text())
    assert [s["type"] for s in stages] == ["readers.las", "filters.reprojection", "writers.las"]
    assert stages[2]["scale_x"] == 1e-7 and stages[2]["offset_y"] == 49.0
    # one value stands for x, y and z; a scale too fine for the extent is an error with a hint
    assert main(["convert", str(src), str(tmp_path / "h.las"), "--scale", "0.01"]) == 0
    assert read_header(tmp_path / "h.las")["scales"] == [0.01] * 3
    assert main(["convert", str(src), str(tmp_path / "x.las"), "--scale", "1e-9", "--offset", "0,0,0"]) == 1
    assert "32-bit" in capsys.readouterr().err and not (tmp_path / "x.las").exists()
    assert main(["convert", str(src), str(tmp_path / "y.las"), "--scale", "0,1,1"]) == 2
    assert main(["convert", str(src), str(tmp_path / "y.ply"), "--scale", "0.01"]) == 2


def test_geographic_cloud_without_las_metadata_gets_fitting_defaults(tmp_path, rng):
    lonlat = np.column_stack([rng.uniform(-123.08, -123.06, 100), rng.uniform(44.04, 44.06, 100), rng.uniform(0, 50, 100)])
    write_cloud(Cloud(lonlat, crs="EPSG:4326"), tmp_path / "g.las")  # used to fail: offsets rounded to 1000
    h = read_header(tmp_path / "g.las")
    assert h["scales"] == [1e-7, 1e-7, 0.001] and h["offsets"][:2] == [-123.0, 44.0]
    err = np.abs(read_cloud(tmp_path / "g.las").xyz - lonlat).max(axis=0)
    assert err[0] < 1e-7 and err[1] < 1e-7 and err[2] <= 0.0005


FILES_WITH_CRS = ["MixedConifer.laz", "Topography.laz", "autzen_trim.las", "bcts_1.laz", "bcts_2.laz", "fullwave.laz",
                  "lidarhd_extra_bytes.laz"]


@pytest.mark.realdata
@pytest.mark.parametrize("name", FILES_WITH_CRS)
def test_real_files_round_trip_through_wgs84(tmp_path, shared_data, name):
    """Every shared file with a CRS goes to EPSG:4326 and back within 1 mm (in metres)."""
    from workstation.io.crs import crs_info

    src = shared_data / "lidar" / name
    orig = read_cloud(src)
    _, back = _round_trip(tmp_path, src, orig.crs)
    err_m = np.abs(back.xyz - orig.xyz).max(axis=0) * [crs_info(orig.crs).metres_per_unit] * 3
    assert back.n == orig.n and err_m.max() < 0.001, err_m


def test_wide_survey_gets_a_coarser_scale_that_fits(tmp_path, rng):
    """1e-10 degree reaches only ±0.21 degree: a 150 km wide survey steps up to 1e-9 in x."""
    xyz = np.column_stack([rng.uniform(400000, 550000, 200), rng.uniform(5.40e6, 5.41e6, 200), rng.uniform(0, 9, 200)])
    write_cloud(Cloud(np.round(xyz, 3), crs="EPSG:32632"), tmp_path / "w.las", scales=[0.001] * 3)
    assert main(["convert", str(tmp_path / "w.las"), str(tmp_path / "g.las"), "--to-crs", "EPSG:4326"]) == 0
    assert read_header(tmp_path / "g.las")["scales"][:2] == [1e-9, 1e-10]  # per axis
