"""`ws info --summary` / `--metadata` (header only), COPC shown as COPC, and the shared reading
options --bounds / --resolution / --level on the commands that read one cloud."""

from __future__ import annotations

import json

import numpy as np
import pytest
from click.testing import CliRunner

pytest.importorskip("copclib")
from copc_synth import write_copc  # noqa: E402

from workstation.cli.main import cli  # noqa: E402

X0, Y0 = 500_000.0, 4_000_000.0


@pytest.fixture(scope="module")
def copc_file(tmp_path_factory):
    from pyproj import CRS

    rng = np.random.default_rng(3)
    n = 8000
    xyz = np.column_stack([rng.uniform(X0, X0 + 100, n), rng.uniform(Y0, Y0 + 80, n), rng.uniform(10, 20, n)])
    path = tmp_path_factory.mktemp("copc") / "a.copc.laz"
    write_copc(path, xyz, wkt=CRS.from_epsg(32632).to_wkt(), max_levels=4)
    return path


def run(*args):
    r = CliRunner().invoke(cli, [str(a) for a in args], catch_exceptions=False)
    return r


def test_summary_json_of_copc(copc_file):
    r = run("info", copc_file, "--summary", "--json")
    assert r.exit_code == 0, r.output
    s = json.loads(r.stdout)
    assert s["format"] == "copc" and s["format_version"] == "COPC 1.0 (LAZ 1.4 PDRF 6)"
    assert s["point_count"] == 8000 and s["crs"]["epsg"] == 32632 and s["crs"]["unit"] == "metre"
    assert s["copc"]["levels"] == 4 and sum(s["copc"]["points_per_level"]) == 8000
    assert ["copc", 1] in [[v["user_id"], v["record_id"]] for v in s["vlrs"]]


def test_metadata_has_pdal_keys(copc_file):
    r = run("info", copc_file, "--metadata")
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    md = doc["metadata"]
    assert doc["reader"] == "readers.copc" and md["copc"] is True
    for key in ("count", "minx", "maxz", "scale_x", "offset_x", "dataformat_id", "major_version", "minor_version"):
        assert key in md
    assert md["count"] == 8000 and md["dataformat_id"] == 6 and (md["major_version"], md["minor_version"]) == (1, 4)
    assert md["srs"]["units"]["horizontal"] == "metre" and "32632" in md["srs"]["wkt"]
    assert md["copc_info"]["spacing"] > 0 and md["vlr_0"]["user_id"] == "copc"


def test_full_info_shows_copc_without_warning(copc_file):
    r = run("info", copc_file)
    assert r.exit_code == 0, r.output
    assert "COPC 1.0" in r.output and "level 3" in r.output and "could not be kept" not in r.output


def test_info_bounds_matches_copcreader(copc_file):
    import laspy
    from laspy.copc import Bounds

    b = (X0 + 10, Y0 + 5, X0 + 60, Y0 + 40)
    r = run("info", copc_file, "--bounds", ",".join(map(str, b)), "--json")
    assert r.exit_code == 0, r.output
    with laspy.CopcReader.open(str(copc_file)) as rd:
        n = len(rd.query(bounds=Bounds(mins=np.array(b[:2]), maxs=np.array(b[2:]))))
    assert json.loads(r.stdout)["point_count"] == n


def test_convert_bounds_and_level(copc_file, tmp_path):
    import laspy

    out = tmp_path / "lod.laz"
    r = run("convert", copc_file, out, "--level", 1)
    assert r.exit_code == 0, r.output
    with laspy.CopcReader.open(str(copc_file)) as rd:
        n = len(rd.query(level=range(0, 2)))
    s = json.loads(run("info", out, "--summary", "--json").stdout)
    assert s["point_count"] == n and s["format"] == "laz" and s["copc"] is None


def test_convert_writes_copc(copc_file, tmp_path):
    from workstation.cli.main import main
    from workstation.io import copc

    out = tmp_path / "b.copc.laz"
    assert main(["convert", str(copc_file), str(out)]) == 0
    assert copc.summary(out)["points"] == copc.summary(copc_file)["points"]


def test_plain_writers_refuse_copc_names(copc_file, tmp_path, capsys):
    from workstation.cli.main import main

    rc = main(["thin", str(copc_file), "-o", str(tmp_path / "b.copc.laz"), "--voxel", "1"])
    assert rc == 1 and "cannot write COPC" in capsys.readouterr().err and not (tmp_path / "b.copc.laz").exists()


def test_level_refused_on_plain_file(copc_file, tmp_path, capsys):
    from workstation.cli.main import main

    plain = tmp_path / "p.laz"
    assert run("convert", copc_file, plain).exit_code == 0
    rc = main(["info", str(plain), "--level", "2"])
    assert rc == 1 and "not COPC" in capsys.readouterr().err


@pytest.mark.parametrize("bad", ["1,2,3", "a,b,c,d", "5,0,1,1", "0,0,1,1,5,2"])
def test_bad_bounds_is_a_usage_error(copc_file, bad):
    assert run("info", copc_file, "--bounds", bad).exit_code == 2


def test_summary_refuses_point_selection(copc_file):
    assert run("info", copc_file, "--summary", "--level", 1).exit_code == 2


@pytest.mark.parametrize("command", ["info", "convert", "ground", "classify", "mesh", "colorize"])
def test_read_options_on_commands(command):
    r = run(command, "--help")
    for flag in ("--bounds", "--resolution", "--level"):
        assert flag in r.output


@pytest.mark.realdata
def test_summary_of_real_files(shared_data):
    for name in ("autzen_trim.las", "lidarhd_extra_bytes.laz"):
        r = run("info", shared_data / "lidar" / name, "--summary", "--json")
        assert r.exit_code == 0, r.output
        s = json.loads(r.stdout)
        assert s["copc"] is None and s["point_count"] > 0 and s["crs"] is not None
