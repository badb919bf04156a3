"""Format validation (workstation.qc.validate): tiny LAS files written with laspy, each broken
in one known way (header bytes patched at the offsets of LAS 1.4 R15 Table 3)."""

from __future__ import annotations

import struct

import laspy
import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io.registry import iter_chunks
from workstation.qc.validate import FormatCheck, FormatParams, _hash, _Positions

N = 60  # points of every test file: a 10 x 6 grid, 1 m apart, two returns a pulse
COUNT64, BY_RETURN64, LEGACY_COUNT, MAX_X, MIN_Z, ENCODING = 247, 255, 107, 179, 219, 6


def _write(path, fmt=6, version="1.4", crs="EPSG:32632", edit=None):
    """A clean file: distinct positions, classes 1/2/5/6, adjusted standard GPS time."""
    import pyproj

    header = laspy.LasHeader(point_format=fmt, version=version)
    header.scales = np.array([0.01, 0.01, 0.01])
    header.offsets = np.array([500000.0, 4000000.0, 0.0])
    if crs:
        header.add_crs(pyproj.CRS(crs))
    header.global_encoding.gps_time_type = laspy.header.GpsTimeType.STANDARD
    las = laspy.LasData(header)
    i = np.arange(N)
    las.x = 500000.25 + (i % 10)
    las.y = 4000000.5 + (i // 10)
    las.z = 100.0 + 0.01 * i
    las.return_number = 1 + i % 2
    las.number_of_returns = np.full(N, 2)
    las.classification = np.array([2, 5, 6, 1])[i % 4]
    las.gps_time = 3.5e8 + 1e-3 * i
    if edit:
        edit(las)
    las.write(str(path))
    return path


def _patch(path, offset, fmt, value):
    with open(path, "r+b") as f:
        f.seek(offset)
        f.write(struct.pack("<" + fmt, value))


def _check(path, params=FormatParams()):
    check = FormatCheck(path, params)
    for chunk in iter_chunks(path, chunk_size=25):  # several chunks: the sums must carry over
        check.add(chunk)
    return check


def _only(check, field):
    hits = [f for f in check.findings() if f.field == field]
    assert len(hits) == 1, [f.to_dict() for f in check.findings()]
    return hits[0]


def test_clean_file_has_no_finding(tmp_path):
    check = _check(_write(tmp_path / "ok.las"))
    assert check.findings() == []
    r = check.result()
    assert (r["version"], r["point_format"], r["points"], r["header_points"]) == ("1.4", 6, N, N)
    assert (r["errors"], r["warnings"], r["pass"]) == (0, 0, True)
    assert r["duplicates"] == {"points": 0, "positions": 0, "exact": True, "examples": []}


def test_clean_legacy_laz_has_no_finding(tmp_path):
    check = _check(_write(tmp_path / "ok.laz", fmt=1, version="1.2"))
    assert check.findings() == []
    assert check.result()["compressed"] is True


def test_header_count_above_the_points_is_an_error_and_blocks_streaming(tmp_path):
    path = _write(tmp_path / "count.las")
    _patch(path, COUNT64, "Q", N + 5)
    check = FormatCheck(path)
    f = _only(check, "point_count")
    assert (f.severity, f.expected, f.found) == ("error", str(N + 5), str(N))
    assert check.result()["pass"] is False
    with pytest.raises(InvalidInputError):  # the reader refuses it: the finding is all the runner gets
        next(iter_chunks(path))


def test_legacy_counts_of_las_14(tmp_path):
    path = _write(tmp_path / "legacy1.las", fmt=1)  # laspy writes legacy fields 0: allowed
    _patch(path, LEGACY_COUNT, "I", N - 1)
    f = _only(_check(path), "legacy_point_count")
    assert (f.severity, f.expected, f.found) == ("error", f"{N} (or 0)", str(N - 1))
    path6 = _write(tmp_path / "legacy6.las", fmt=6)
    _patch(path6, LEGACY_COUNT, "I", N)
    f = _only(_check(path6), "legacy_point_count")
    assert (f.expected, f.found) == ("0 (point formats 6-10)", str(N))


def test_wrong_counts_by_return(tmp_path):
    path = _write(tmp_path / "byret.las")
    _patch(path, BY_RETURN64 + 8, "Q", 29)  # return 2: header 29, points 30
    f = _only(_check(path), "points_by_return")
    assert (f.severity, f.expected, f.found) == ("error", "[30, 29]", "[30, 30]")
    assert "return 2 " in f.message


def test_points_outside_the_header_box_and_a_loose_box(tmp_path):
    path = _write(tmp_path / "bounds.las")
    _patch(path, MAX_X, "d", 500005.0)  # points reach x = 500009.25
    _patch(path, MIN_Z, "d", 99.0)  # points start at z = 100.00
    check = _check(path)
    f = _only(check, "max_x")
    assert (f.severity, f.expected, f.found) == ("error", "500005.00", "500009.25")
    f = _only(check, "min_z")
    assert (f.severity, f.expected, f.found) == ("warning", "99.00", "100.00")


def test_half_a_scale_step_is_tolerated(tmp_path):
    path = _write(tmp_path / "tol.las")
    _patch(path, MAX_X, "d", 500009.25 - 0.004)
    assert not [f for f in _check(path).findings() if f.field == "max_x"]


def test_return_number_above_number_of_returns(tmp_path):
    def edit(las):
        rn = np.array(las.return_number)
        rn[:4] = 3
        las.return_number = rn

    check = _check(_write(tmp_path / "rn.las", edit=edit))
    f = _only(check, "return_number")
    assert (f.severity, f.expected, f.found) == ("error", "<= number_of_returns", "4 points")


def test_reserved_classes(tmp_path):
    def edit(las):
        c = np.array(las.classification)
        c[:3], c[3], c[4] = 12, 40, 70  # reserved, reserved, user defined
        las.classification = c

    f = _only(_check(_write(tmp_path / "cls.las", edit=edit)), "classification")
    assert f.severity == "error"
    assert f.found == "class 12: 3 points, class 40: 1 points"


def test_class_above_31_in_a_legacy_format(tmp_path):
    path = _write(tmp_path / "c31.las", fmt=1, version="1.4")
    check = FormatCheck(path)
    chunk = next(iter_chunks(path))
    check.add(chunk.with_attrs(classification=np.where(np.arange(N) < 2, 40, chunk.attrs["classification"])))
    found = [(f.expected, f.found) for f in check.findings() if f.field == "classification"]
    assert ("0-31 (point formats 0-5)", "class 40: 2 points") in found


def test_duplicate_points_are_counted_with_examples(tmp_path):
    def edit(las):
        for axis in ("x", "y", "z"):
            v = np.array(getattr(las, axis))
            v[[20, 21, 45]] = v[[0, 1, 0]]
            setattr(las, axis, v)

    check = _check(_write(tmp_path / "dup.las", edit=edit))
    f = _only(check, "duplicate_points")
    assert (f.severity, f.found) == ("warning", "3 points")
    d = check.result()["duplicates"]
    assert (d["points"], d["positions"], d["exact"]) == (3, 2, True)
    assert [e["indices"] for e in d["examples"]] == [[0, 20, 45], [1, 21]]
    assert np.allclose(d["examples"][0]["xyz"], [500000.25, 4000000.5, 100.0])
    assert np.allclose(d["examples"][1]["xyz"], [500001.25, 4000000.5, 100.01])


def test_duplicates_survive_a_wrong_header_box(tmp_path):
    """A point outside the header box in the last chunk turns the exact keys stored so far
    into hashes mid-stream; the duplicate across that switch is still found."""
    def edit(las):
        for axis in ("x", "y", "z"):
            v = np.array(getattr(las, axis))
            v[59] = v[3]
            setattr(las, axis, v)
        x = np.array(las.x)
        x[50] = 500020.25
        las.x = x

    path = _write(tmp_path / "dupbox.las", edit=edit)
    _patch(path, MAX_X, "d", 500009.25)  # the box packs 10 bits of x: up to 500010.48
    check = _check(path)
    assert _only(check, "max_x").found == "500020.25"
    d = check.result()["duplicates"]
    assert (d["points"], d["exact"]) == (1, False)
    assert d["examples"][0]["indices"] == [3, 59] and d["examples"][0]["xyz"] is None


def test_exact_and_hashed_keys_agree():
    rng = np.random.default_rng(1)
    ints = rng.integers(0, 50, size=(5000, 3))  # many repeats
    exact = _Positions(np.zeros(3, np.int64), np.full(3, 49), 0)
    exact.add(ints)
    hashed = _Positions(None, None, 0)
    hashed.add(ints)
    true_repeats = len(ints) - len(np.unique(ints, axis=0))
    assert exact.exact and not hashed.exact
    assert exact.summary(3)["points"] == hashed.summary(3)["points"] == true_repeats
    assert len(np.unique(_hash(np.unique(ints, axis=0)))) == len(np.unique(ints, axis=0))


def test_format_6_without_wkt_bit(tmp_path):
    path = _write(tmp_path / "wkt.las")
    with open(path, "rb") as fh:
        enc = struct.unpack_from("<H", fh.read(8), ENCODING)[0]
    _patch(path, ENCODING, "H", enc & ~0b10000)
    check = _check(path)
    f = _only(check, "global_encoding.wkt")
    assert (f.severity, f.expected, f.found) == ("error", "set (point formats 6-10)", "not set")
    assert [x.field for x in check.findings()] == ["global_encoding.wkt"]


def test_missing_crs_is_a_warning(tmp_path):
    check = _check(_write(tmp_path / "nocrs.las", fmt=1, version="1.2", crs=None))
    f = _only(check, "crs")
    assert (f.severity, f.found) == ("warning", "none")
    assert check.result()["pass"] is True


def test_withheld_points_are_a_warning(tmp_path):
    def edit(las):
        w = np.zeros(N, dtype=bool)
        w[[5, 6]] = True
        las.withheld = w

    check = _check(_write(tmp_path / "withheld.las", edit=edit))
    f = _only(check, "withheld")
    assert (f.severity, f.found) == ("warning", "2 points")
    assert check.result()["flags"]["withheld"] == 2


def test_scan_angle_and_week_time_out_of_range(tmp_path):
    def edit(las):
        a = np.zeros(N, dtype=np.int8)
        a[:2] = 100
        las.scan_angle_rank = a
        las.gps_time = 604800.0 + np.arange(N)  # beyond a GPS week

    path = _write(tmp_path / "scan.las", fmt=1, version="1.2", edit=edit)
    with open(path, "rb") as fh:
        enc = struct.unpack_from("<H", fh.read(8), ENCODING)[0]
    _patch(path, ENCODING, "H", enc & ~1)  # GPS week time
    check = _check(path)
    f = _only(check, "scan_angle")
    assert (f.severity, f.expected) == ("error", "-90..+90 degrees")
    assert f.found.startswith("2 points")
    f = _only(check, "gps_time")
    assert (f.severity, f.found) == ("error", f"{N} points, range 604800.000000..{604800 + N - 1}.000000")


def test_undocumented_extra_bytes_in_las_14(tmp_path):
    def edit(las):
        las.add_extra_dim(laspy.ExtraBytesParams("height", "f4"))

    path = _write(tmp_path / "eb.las", edit=edit)
    data = path.read_bytes()
    at = data.index(b"LASF_Spec\0")  # the Extra Bytes VLR's user id; its record id follows
    _patch(path, at + 16, "H", 5)
    f = _only(FormatCheck(path), "extra_bytes")
    assert (f.severity, f.expected, f.found) == ("error", "4 bytes described by an Extra Bytes VLR", "0 described")


def test_vlr_count_beyond_the_point_data(tmp_path):
    path = _write(tmp_path / "vlr.las")
    _patch(path, 100, "I", 5)  # one VLR (the WKT) in the file
    check = FormatCheck(path)
    assert _only(check, "vlr").severity == "error"
    assert check.result()["pass"] is False


def test_not_las_gives_one_info(tmp_path):
    path = tmp_path / "pts.xyz"
    path.write_text("0 0 0\n1 1 1\n")
    check = FormatCheck(path)
    for chunk in iter_chunks(path):
        check.add(chunk)
    [f] = check.findings()
    assert (f.severity, f.field, f.message) == ("info", "format", "format checks apply to LAS/LAZ")
    r = check.result()
    assert (r["points"], r["pass"], r["version"]) == (2, True, None)


def test_unreadable_header_is_a_finding(tmp_path):
    path = tmp_path / "bad.las"
    path.write_bytes(b"NOTLAS" + bytes(300))
    f = _only(FormatCheck(path), "signature")
    assert (f.severity, f.expected) == ("error", "LASF")


def test_chunk_of_another_file_is_refused(tmp_path):
    check = FormatCheck(_write(tmp_path / "a.las"))
    with pytest.raises(InvalidInputError):
        check.add(Cloud(np.zeros((1, 3))), source=tmp_path / "b.las")


@pytest.mark.realdata
def test_vendor_file_runs_and_counts_match(shared_data):
    path = shared_data / "lidar" / "bcts_1.laz"
    check = FormatCheck(path)
    for chunk in iter_chunks(path):
        check.add(chunk)
    r = check.result()
    assert r["points"] == r["header_points"] == 531_662
    assert (r["version"], r["point_format"]) == ("1.2", 1)
    fields = {f.field for f in check.findings()}
    assert not fields & {"point_count", "points_by_return", "min_x", "max_x", "min_y", "max_y", "min_z", "max_z"}
