import struct

import laspy
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core import Cloud, InvalidInputError, OutputExistsError, UnsupportedFormatError
from workstation.io import iter_chunks, read_cloud, write_cloud
from workstation.io.las import _format_attrs, choose_point_format


def _random_cloud(fmt: int, n: int, seed: int, scale: float, offset: float) -> Cloud:
    rng = np.random.default_rng(seed)
    ints = rng.integers(-(2**30), 2**30, size=(n, 3))
    xyz = ints * scale + offset
    attrs = {}
    names = _format_attrs(fmt)
    rmax = 15 if fmt >= 6 else 7
    for name in sorted(names):
        if name == "rgb":
            attrs[name] = rng.integers(0, 65536, (n, 3))
        elif name in ("return_number", "number_of_returns"):
            attrs[name] = rng.integers(0, rmax + 1, n)
        elif name == "classification":
            attrs[name] = rng.integers(0, 256 if fmt >= 6 else 32, n)
        elif name in ("synthetic", "key_point", "withheld", "overlap", "scan_direction_flag", "edge_of_flight_line"):
            attrs[name] = rng.integers(0, 2, n)
        elif name == "scanner_channel":
            # lazrs 0.8 garbles wave packets in LAZ when the scanner channel changes between
            # points of formats 9/10 (an upstream codec bug; LAS is exact): one channel there.
            attrs[name] = rng.integers(0, 4, n) if fmt not in (9, 10) else np.full(n, rng.integers(0, 4))
        elif name == "scan_angle":
            attrs[name] = (rng.integers(-30000, 30001, n) * 0.006).astype(np.float32) if fmt >= 6 else rng.integers(-90, 91, n)
        elif name == "gps_time":
            attrs[name] = rng.uniform(0, 1e6, n)
        elif name in ("return_point_wave_location", "x_t", "y_t", "z_t"):
            attrs[name] = rng.normal(size=n).astype(np.float32)
        elif name in ("wavepacket_offset", "wavepacket_size"):
            # Waveform packets as a digitiser writes them: consecutive records in the
            # waveform file. (lazrs's wave-packet codec garbles arbitrary random jumps of
            # offset and size, which no real file has.)
            size = rng.integers(1, 2**16, n).astype(np.uint32)
            attrs["wavepacket_size"] = size
            attrs["wavepacket_offset"] = (60 + np.concatenate([[0], np.cumsum(size, dtype=np.uint64)])[:n]).astype(np.uint64)
        else:  # intensity, user_data, point_source_id, nir, wavepacket_index
            hi = 256 if name in ("user_data", "wavepacket_index") else 65536
            attrs[name] = rng.integers(0, hi, n)
    attrs["extra_f"] = rng.normal(size=n)
    attrs["extra_i"] = rng.integers(-5, 5, n).astype(np.int16)
    return Cloud(xyz, attrs, crs="EPSG:32632")


@pytest.mark.parametrize("fmt", range(11))
@settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(n=st.integers(0, 300), seed=st.integers(0, 2**31), scale=st.sampled_from([0.001, 0.01, 0.25]),
       offset=st.floats(-1e6, 1e6, allow_nan=False).map(round))
def test_every_point_format_round_trips_bit_exactly(tmp_path, fmt, n, seed, scale, offset):
    cloud = _random_cloud(fmt, n, seed, scale, offset)
    for ext in (".las", ".laz"):
        out = tmp_path / f"f{fmt}{ext}"
        write_cloud(cloud, out, overwrite=True, point_format=fmt, scales=[scale] * 3, offsets=[offset] * 3)
        back = read_cloud(out)
        assert back.meta["las"]["point_format"] == fmt
        np.testing.assert_array_equal(back.xyz, cloud.xyz)
        assert set(back.attrs) == set(cloud.attrs)
        for k, v in cloud.attrs.items():
            np.testing.assert_array_equal(back.attrs[k], v, err_msg=f"{k} format {fmt} {ext}")
        assert back.crs == "EPSG:32632"


def test_point_format_chosen_from_attributes(tmp_path, small_cloud):
    assert choose_point_format(small_cloud.attrs) == 6
    out = tmp_path / "a.las"
    write_cloud(small_cloud.with_attrs(rgb=np.zeros((small_cloud.n, 3))), out)
    h = laspy.open(out).header
    assert h.point_format.id == 7 and str(h.version) == "1.4"
    # a cloud read from a legacy file keeps its legacy format when attributes fit
    legacy = tmp_path / "legacy.las"
    write_cloud(small_cloud, legacy, point_format=1)
    again = tmp_path / "again.las"
    write_cloud(read_cloud(legacy), again)
    assert laspy.open(again).header.point_format.id == 1


def test_iter_chunks_streams_whole_file(tmp_path, small_cloud):
    out = tmp_path / "c.laz"
    write_cloud(small_cloud, out)
    chunks = list(iter_chunks(out, 300))
    assert [c.n for c in chunks] == [300, 300, 300, 100]
    whole = read_cloud(out)
    np.testing.assert_array_equal(np.vstack([c.xyz for c in chunks]), whole.xyz)
    np.testing.assert_allclose(whole.xyz, small_cloud.xyz, rtol=0, atol=5e-4)


@pytest.mark.parametrize("suffix", [".las", ".laz"])
def test_iter_chunks_reads_a_point_range(tmp_path, small_cloud, suffix):
    """``start``/``stop`` stream just that range (LAZ seeks into its compressed chunks); a
    range past the end is cut at the header's count."""
    from workstation.io.las import iter_chunks as las_chunks

    out = tmp_path / f"r{suffix}"
    write_cloud(small_cloud, out)
    whole = read_cloud(out)
    got = list(las_chunks(out, 120, start=250, stop=777))
    assert [c.n for c in got] == [120, 120, 120, 120, 47]
    np.testing.assert_array_equal(np.vstack([c.xyz for c in got]), whole.xyz[250:777])
    np.testing.assert_array_equal(np.concatenate([c.attrs["intensity"] for c in got]), whole.attrs["intensity"][250:777])
    assert sum(c.n for c in las_chunks(out, 500, start=900, stop=5000)) == whole.n - 900


def test_vlrs_and_crs_kept(tmp_path, small_cloud):
    out = tmp_path / "v.las"
    header = laspy.LasHeader(point_format=6, version="1.4")
    header.vlrs.append(laspy.VLR("my_user", 42, "custom", b"payload"))
    write_cloud(small_cloud, out)
    c = read_cloud(out)
    c = c.with_meta(las={**c.meta["las"], "vlrs": [*c.meta["las"]["vlrs"], {"user_id": "my_user", "record_id": 42, "description": "custom", "data": b"payload"}]})
    out2 = tmp_path / "v2.laz"
    write_cloud(c, out2)
    vl = [v for v in laspy.open(out2).header.vlrs if v.user_id == "my_user"]
    assert len(vl) == 1 and vl[0].record_data == b"payload"
    assert read_cloud(out2).crs == "EPSG:32632"


# ---- bad input --------------------------------------------------------------------------

def _las(tmp_path, small_cloud, name="good.las"):
    p = tmp_path / name
    write_cloud(small_cloud, p)
    return p


def test_wrong_magic_bytes(tmp_path, small_cloud):
    p = _las(tmp_path, small_cloud)
    data = bytearray(p.read_bytes())
    data[:4] = b"XXXX"
    bad = tmp_path / "bad.las"
    bad.write_bytes(bytes(data))
    with pytest.raises(InvalidInputError, match="LASF") as e:
        read_cloud(bad)
    assert "bad.las" in str(e.value)


def test_truncated_las_and_laz(tmp_path, small_cloud):
    for ext in (".las", ".laz"):
        p = _las(tmp_path, small_cloud, "t" + ext)
        data = p.read_bytes()
        cut = tmp_path / ("cut" + ext)
        cut.write_bytes(data[: len(data) * 2 // 3])
        with pytest.raises(InvalidInputError) as e:
            read_cloud(cut)
        assert "cut" + ext in str(e.value)


def test_header_count_disagrees_with_data(tmp_path, small_cloud):
    p = _las(tmp_path, small_cloud)
    data = bytearray(p.read_bytes())
    # LAS 1.4: legacy count at 107 (u32) and 64-bit count at 247; claim fewer points
    struct.pack_into("<I", data, 107, small_cloud.n - 10)
    struct.pack_into("<Q", data, 247, small_cloud.n - 10)
    bad = tmp_path / "count.las"
    bad.write_bytes(bytes(data))
    with pytest.raises(InvalidInputError, match="header says 990") as e:
        read_cloud(bad)
    assert e.value.field == "point_count"


def test_empty_file_and_unknown_extension(tmp_path):
    empty = tmp_path / "empty.laz"
    empty.write_bytes(b"")
    with pytest.raises(InvalidInputError, match="empty"):
        read_cloud(empty)
    odd = tmp_path / "cloud.abc"
    odd.write_text("1 2 3\n")
    with pytest.raises(UnsupportedFormatError, match=r"\.abc"):
        read_cloud(odd)
    with pytest.raises(InvalidInputError, match="not found"):
        read_cloud(tmp_path / "missing.las")


def test_output_exists_and_same_file(tmp_path, small_cloud):
    p = _las(tmp_path, small_cloud)
    before = p.read_bytes()
    with pytest.raises(OutputExistsError):
        write_cloud(small_cloud, p)
    with pytest.raises(InvalidInputError, match="same file"):
        write_cloud(small_cloud, p, overwrite=True, inputs=[p])
    assert p.read_bytes() == before


def test_failed_write_leaves_nothing(tmp_path, small_cloud):
    out = tmp_path / "fail.las"
    bad = small_cloud.with_attrs(classification=np.full(small_cloud.n, 40))
    with pytest.raises(InvalidInputError, match="point format 6"):
        write_cloud(bad, out, point_format=1)
    assert list(tmp_path.iterdir()) == []


def test_class_code_too_large_for_legacy_format_names_field(tmp_path, small_cloud):
    with pytest.raises(InvalidInputError) as e:
        write_cloud(small_cloud.with_attrs(classification=np.full(small_cloud.n, 40)), tmp_path / "x.las", point_format=3)
    assert e.value.field == "classification"


# ---- real data -----------------------------------------------------------------------------

LIDAR_FILES = ["Topography.laz", "MixedConifer.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las", "warsaw_small.las",
               "lidarhd_extra_bytes.laz", "sample_c.las", "vegetation_1_3.las", "fullwave.laz", "TreeLS_pine.laz"]


@pytest.mark.realdata
@pytest.mark.parametrize("name", LIDAR_FILES)
def test_real_file_matches_laspy_and_round_trips(shared_data, tmp_path, name):
    src = shared_data / "lidar" / name
    ref = laspy.read(src)
    c = read_cloud(src)
    assert c.n == len(ref.points)
    np.testing.assert_array_equal(c.xyz[:, 0], np.asarray(ref.x))
    np.testing.assert_array_equal(c.attrs["classification"], np.asarray(ref.classification))
    for extra in ref.point_format.extra_dimension_names:
        np.testing.assert_array_equal(c.attrs[extra], np.asarray(ref[extra]))
    laz = tmp_path / "a.laz"
    las = tmp_path / "b.las"
    write_cloud(c, laz)
    write_cloud(read_cloud(laz), las)
    back = read_cloud(las)
    np.testing.assert_array_equal(back.xyz, c.xyz)
    assert set(back.attrs) == set(c.attrs)
    for k in c.attrs:
        np.testing.assert_array_equal(back.attrs[k], c.attrs[k])
    assert back.crs == c.crs
    h0, h1 = laspy.open(src).header, laspy.open(las).header
    assert h1.point_format.id == h0.point_format.id and h1.version == h0.version
    np.testing.assert_array_equal(h1.scales, h0.scales)


def test_outputs_get_normal_permissions(tmp_path, small_cloud):
    import os
    import stat

    out = tmp_path / "perm.laz"
    write_cloud(small_cloud, out)
    mask = os.umask(0o022)
    os.umask(mask)
    assert stat.S_IMODE(out.stat().st_mode) == 0o666 & ~mask


@pytest.mark.parametrize("ext", ["las", "laz"])
def test_extended_vlrs_survive_a_write(tmp_path, ext):
    """EVLRs (where copc-lib keeps the CRS) are written after the points, not dropped."""
    import numpy as np

    from workstation.core.cloud import Cloud
    from workstation.io import read_cloud, write_cloud

    rec = {"user_id": "test", "record_id": 7, "description": "x", "data": b"hello"}
    c = Cloud(np.arange(30.0).reshape(10, 3), {}, crs="EPSG:32632").with_meta(las={"evlrs": [rec]})
    write_cloud(c, tmp_path / f"a.{ext}")
    back = read_cloud(tmp_path / f"a.{ext}")
    assert back.meta["las"]["evlrs"] == [rec] and back.n == 10
