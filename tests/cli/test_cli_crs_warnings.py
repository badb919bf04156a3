"""A CRS that does not fit the coordinates (``workstation.io.crs.crs_warnings``) is reported by every
command that reads a cloud: once per file, as a warning on stderr, never failing the command."""

from __future__ import annotations

import json
import logging

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import write_cloud


def _laz(path, crs):
    rng = np.random.default_rng(0)
    xyz = rng.uniform(0, 50, (3000, 3)) + [480_000, 5_450_000, 100]
    c = Cloud(xyz, {"classification": np.full(3000, 2, np.uint8), "return_number": np.ones(3000, np.uint8)}, crs=crs)
    write_cloud(c, path)
    return path


def _crs_records(caplog, what: str):
    return [r for r in caplog.records if r.levelno == logging.WARNING and what in r.getMessage()]


@pytest.fixture
def geocentric(tmp_path):
    """Projected eastings/northings labelled EPSG:4978 (geocentric): ~5,470 km from the Earth's centre."""
    return _laz(tmp_path / "geo.laz", "EPSG:4978")


@pytest.mark.parametrize("argv", [
    ["dem", "{src}", "-o", "{tmp}/d.tif", "--kind", "dsm"],  # auto cell: the file is read twice (survey, grid)
    ["convert", "{src}", "{tmp}/o.ply"],
    ["crop", "{src}", "-o", "{tmp}/c.laz", "--bounds", "480010,5450010,480030,5450030"],
    ["thin", "{src}", "-o", "{tmp}/t.laz", "--voxel", "2"],
])
def test_warned_once_and_the_command_succeeds(tmp_path, geocentric, caplog, argv):
    caplog.set_level(logging.WARNING, logger="workstation")
    args = [a.format(src=geocentric, tmp=tmp_path) for a in argv]
    assert main(args) == 0
    recs = _crs_records(caplog, "geocentric")
    assert len(recs) == 1, [r.getMessage() for r in caplog.records]
    assert recs[0].getMessage().startswith("geo.laz: EPSG:4978 is geocentric")


def test_warning_reaches_stderr_as_a_warning_line(tmp_path, geocentric, capsys):
    assert main(["convert", str(geocentric), str(tmp_path / "o.ply")]) == 0
    err = capsys.readouterr().err
    assert err.count("is geocentric") == 1 and "WARNING" in err


def test_no_warning_when_the_crs_fits(tmp_path, caplog):
    caplog.set_level(logging.WARNING, logger="workstation")
    src = _laz(tmp_path / "utm.laz", "EPSG:32632")
    assert main(["convert", str(src), str(tmp_path / "o.ply")]) == 0
    assert not [r for r in caplog.records if r.levelno >= logging.WARNING and "utm.laz" in r.getMessage()]


def test_info_reports_it_in_its_output_not_twice(tmp_path, geocentric, caplog, capsys):
    caplog.set_level(logging.WARNING, logger="workstation")
    assert main(["info", str(geocentric), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert any("geocentric" in w for w in doc["crs_warnings"])
    assert not _crs_records(caplog, "geocentric")


def test_a_failing_check_never_stops_a_read(tmp_path, geocentric, monkeypatch, caplog):
    import workstation.io.crs as crs_mod
    from workstation.io import read_cloud

    def boom(*a, **k):
        raise RuntimeError("broken check")

    monkeypatch.setattr(crs_mod, "crs_warnings", boom)
    caplog.set_level(logging.WARNING, logger="workstation")
    assert read_cloud(geocentric).n == 3000
    assert not [r for r in caplog.records if r.levelno >= logging.WARNING]
