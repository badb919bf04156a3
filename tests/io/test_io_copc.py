"""COPC reading: detection, the octree summary, queries by bounds / resolution / level equal to
laspy's CopcReader.query, the streamed bounds filter of plain LAS/LAZ, and COPC dropped
honestly on writing. COPC files are written by copc-lib (tests/copc_synth.py)."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("copclib")
laspy = pytest.importorskip("laspy")

from copc_synth import write_copc  # noqa: E402

from workstation.core.errors import InvalidInputError  # noqa: E402
from workstation.io import copc, iter_chunks, read_cloud, write_cloud  # noqa: E402

X0, Y0 = 500_000.0, 4_000_000.0


@pytest.fixture(scope="module")
def copc_file(tmp_path_factory):
    """A 20,000-point, 5-level COPC file in EPSG:32632 with class and intensity."""
    from pyproj import CRS

    rng = np.random.default_rng(7)
    n = 20_000
    xyz = np.column_stack([rng.uniform(X0, X0 + 200, n), rng.uniform(Y0, Y0 + 150, n), rng.uniform(100, 130, n)])
    path = tmp_path_factory.mktemp("copc") / "t.copc.laz"
    write_copc(path, xyz, classification=rng.choice([1, 2, 6], n).astype(np.uint8),
               intensity=rng.integers(0, 60000, n).astype(np.uint16), wkt=CRS.from_epsg(32632).to_wkt(), max_levels=5)
    return path


def _laspy_query(path, bounds=None, **kw):
    from laspy.copc import Bounds

    box = None
    if bounds is not None:
        b = np.asarray(bounds, float)
        k = len(b) // 2
        box = Bounds(mins=b[[0, 1, 4][:k]], maxs=b[[2, 3, 5][:k]])
    with laspy.CopcReader.open(str(path)) as r:
        return r.query(bounds=box, **kw)


def _same_points(cloud, rec):
    """The cloud holds exactly the records (same order: both come from the same node order)."""
    assert cloud.n == len(rec)
    np.testing.assert_array_equal(cloud.xyz, np.column_stack([rec.x, rec.y, rec.z]))
    np.testing.assert_array_equal(cloud.attrs["intensity"], rec.intensity)
    np.testing.assert_array_equal(cloud.attrs["classification"], rec.classification)


def test_detection_and_summary(copc_file, tmp_path):
    assert copc.is_copc(copc_file)
    s = copc.summary(copc_file)
    assert s["levels"] == 5 and s["points"] == 20_000 and sum(s["points_per_level"]) == 20_000
    assert s["nodes_per_level"][0] == 1 and s["spacing_per_level"][1] == pytest.approx(s["spacing"] / 2)
    plain = tmp_path / "plain.laz"
    write_cloud(read_cloud(copc_file), plain)
    assert not copc.is_copc(plain) and copc.summary(plain) is None


@pytest.mark.parametrize("bounds", [(X0 + 20, Y0 + 35, X0 + 61.5, Y0 + 70), (X0 + 150, Y0 - 10, X0 + 300, Y0 + 20),
                                    (X0 + 10, Y0 + 10, X0 + 120, Y0 + 90, 110, 120)])
def test_bounds_query_equals_copcreader(copc_file, bounds):
    got = read_cloud(copc_file, bounds=bounds)
    assert 0 < got.n < 20_000 and got.crs == "EPSG:32632"
    _same_points(got, _laspy_query(copc_file, bounds))


@pytest.mark.parametrize("kw, laspy_kw", [({"level": 0}, {"level": range(0, 1)}), ({"level": 2}, {"level": range(0, 3)}),
                                          ({"resolution": 6.0}, {"resolution": 6.0})])
def test_level_and_resolution_equal_copcreader(copc_file, kw, laspy_kw):
    got = read_cloud(copc_file, **kw)
    _same_points(got, _laspy_query(copc_file, **laspy_kw))
    assert got.n < 20_000


def test_bounds_and_level_together(copc_file):
    b = (X0 + 20, Y0 + 20, X0 + 150, Y0 + 100)
    got = read_cloud(copc_file, bounds=b, level=2)
    _same_points(got, _laspy_query(copc_file, b, level=range(0, 3)))


def test_copc_read_keeps_crs_and_no_copc_vlr(copc_file, caplog):
    c = read_cloud(copc_file)
    assert c.n == 20_000 and c.crs == "EPSG:32632"
    kept = c.meta["las"]["vlrs"] + c.meta["las"].get("evlrs", [])
    assert not [v for v in kept if v["user_id"] == "copc"]
    assert "could not be kept" not in caplog.text


def test_plain_laz_bounds_streamed_equal_copc(copc_file, tmp_path):
    """The same points from a plain LAZ copy (streamed in small chunks) as from the COPC query."""
    plain = tmp_path / "plain.laz"
    write_cloud(read_cloud(copc_file), plain)
    b = (X0 + 20, Y0 + 35, X0 + 61.5, Y0 + 70)
    a = read_cloud(copc_file, bounds=b)
    p = read_cloud(plain, bounds=b)
    chunks = list(iter_chunks(plain, 1000, bounds=b))
    assert len(chunks) == 20 and sum(ch.n for ch in chunks) == p.n == a.n
    key = lambda c: np.lexsort(c.xyz.T[::-1])  # noqa: E731 - one order for both
    np.testing.assert_array_equal(a.xyz[key(a)], p.xyz[key(p)])


def test_las_bounds_and_chunk_size_do_not_change_the_points(small_cloud, tmp_path):
    path = tmp_path / "a.las"
    write_cloud(small_cloud, path)
    b = (500020.0, 4e6 + 10, 500060.0, 4e6 + 80)
    full = read_cloud(path)
    x, y = full.xyz[:, 0], full.xyz[:, 1]
    inside = (x >= b[0]) & (x <= b[2]) & (y >= b[1]) & (y <= b[3])
    for size in (7, 1000):
        from workstation.io.las import read

        got = read(path, bounds=b, chunk_size=size)
        np.testing.assert_array_equal(got.xyz, full.xyz[inside])
        np.testing.assert_array_equal(got.attrs["gps_time"], full.attrs["gps_time"][inside])


@pytest.mark.parametrize("kw, field", [({"level": 1}, "--level"), ({"resolution": 2.0}, "--resolution")])
def test_level_and_resolution_refused_without_copc(small_cloud, tmp_path, kw, field):
    path = tmp_path / "a.laz"
    write_cloud(small_cloud, path)
    with pytest.raises(InvalidInputError, match="COPC") as e:
        read_cloud(path, **kw)
    assert e.value.field == field


def test_bad_bounds_and_empty_box(copc_file):
    with pytest.raises(InvalidInputError, match="xmin"):
        read_cloud(copc_file, bounds=(10, 0, 0, 10))
    with pytest.raises(InvalidInputError, match="4 or 6"):
        read_cloud(copc_file, bounds=(0, 0, 1))
    with pytest.raises(InvalidInputError, match="no points inside"):
        read_cloud(copc_file, bounds=(0, 0, 1, 1))
    with pytest.raises(InvalidInputError, match="together"):
        read_cloud(copc_file, level=1, resolution=1.0)


def test_text_file_bounds(small_cloud, tmp_path):
    path = tmp_path / "a.xyz"
    write_cloud(small_cloud, path)
    b = (500020.0, 4e6 + 10, 500060.0, 4e6 + 80)
    got = read_cloud(path, bounds=b)
    assert 0 < got.n < small_cloud.n
    assert (got.xyz[:, 0] >= b[0]).all() and (got.xyz[:, 1] <= b[3]).all()


@pytest.mark.parametrize("name", ["out.copc.laz", "OUT.COPC.LAZ"])
def test_copc_output_refused(small_cloud, tmp_path, name):
    with pytest.raises(InvalidInputError, match="cannot write COPC") as e:
        write_cloud(small_cloud, tmp_path / name)
    assert ".laz" in e.value.hint and not (tmp_path / name).exists()


def test_copc_to_laz_is_plain_laz(copc_file, tmp_path, caplog):
    out = tmp_path / "plain.laz"
    write_cloud(read_cloud(copc_file), out)
    with laspy.open(out) as r:
        ids = [(v.user_id, v.record_id) for v in r.header.vlrs] + [(v.user_id, v.record_id) for v in (r.evlrs or [])]
    assert not [i for i in ids if i[0] == "copc"]
    assert read_cloud(out).n == 20_000 and "could not be kept" not in caplog.text


def test_pipeline_read_copc_uses_the_same_query(copc_file):
    from workstation.pipeline.chunkio import read_copc

    box = (X0 + 20, Y0 + 35, X0 + 61.5, Y0 + 70)
    got = read_copc(copc_file, box)
    rec = _laspy_query(copc_file, box)
    half_open = (np.asarray(rec.x) < box[2]) & (np.asarray(rec.y) < box[3])
    assert got.n == int(half_open.sum())
