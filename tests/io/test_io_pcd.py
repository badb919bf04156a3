"""PCD reader/writer: round trips, packed colours, COUNT > 1, LZF, open3d cross-checks, bad input."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, UnsupportedFormatError
from workstation.io import pcd, read_cloud, write_cloud


def _cloud(seed: int, n: int) -> Cloud:
    rng = np.random.default_rng(seed)
    return Cloud(
        rng.normal(size=(n, 3)) * rng.choice([1e-3, 1.0, 1e6]),
        {
            "rgb": rng.integers(0, 256, (n, 3)) * 257,
            "normal": rng.normal(size=(n, 3)),
            "intensity": rng.integers(0, 65536, n),
            "classification": rng.integers(0, 256, n),
            "curvature": rng.normal(size=n).astype(np.float32),
            "fpfh": rng.normal(size=(n, 4)).astype(np.float32),
            "segment": rng.integers(-(2**40), 2**40, n),
        },
    )


def _same(a: Cloud, b: Cloud) -> None:
    np.testing.assert_array_equal(a.xyz, b.xyz)
    assert set(a.attrs) == set(b.attrs)
    for k in a.attrs:
        assert b.attrs[k].dtype == a.attrs[k].dtype, k
        np.testing.assert_array_equal(a.attrs[k], b.attrs[k], err_msg=k)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(0, 300), ascii=st.booleans())
def test_round_trip_is_exact(tmp_path, seed, n, ascii):
    c = _cloud(seed, n)
    p = tmp_path / f"rt_{seed}_{n}_{ascii}.pcd"
    pcd.write(c, p, ascii=ascii)
    _same(c, pcd.read(p))


def test_xyz_type_auto_float_and_double(tmp_path):
    f32 = Cloud(np.float32([[1.5, 2.25, 3.0]]))
    f64 = Cloud([[500000.123, 4e6, 1.0]])
    pcd.write(f32, tmp_path / "a.pcd")
    pcd.write(f64, tmp_path / "b.pcd")
    assert b"SIZE 4 4 4" in (tmp_path / "a.pcd").read_bytes()
    assert b"SIZE 8 8 8" in (tmp_path / "b.pcd").read_bytes()
    np.testing.assert_array_equal(pcd.read(tmp_path / "b.pcd").xyz, f64.xyz)


@pytest.mark.parametrize("ascii", [False, True])
def test_open3d_reads_what_we_write(tmp_path, ascii):
    """open3d's PCL-layout reader (float xyz) sees our coordinates, colours and normals."""
    o3d = pytest.importorskip("open3d")
    c = _cloud(7, 100).without_attrs("fpfh", "segment", "curvature")  # the fields open3d knows
    p = tmp_path / "o.pcd"
    write_cloud(c, p, ascii=ascii, xyz_type="float")
    o = o3d.io.read_point_cloud(str(p))
    np.testing.assert_allclose(np.asarray(o.points), c.xyz.astype(np.float32), rtol=1e-6)
    np.testing.assert_allclose(np.asarray(o.colors) * 255, c.attrs["rgb"] // 257, atol=1e-9)
    np.testing.assert_allclose(np.asarray(o.normals), c.attrs["normal"], rtol=1e-6)
    # double coordinates (F 8) through open3d's tensor reader
    write_cloud(c, tmp_path / "d.pcd", ascii=ascii)
    t = o3d.t.io.read_point_cloud(str(tmp_path / "d.pcd"))
    np.testing.assert_array_equal(t.point.positions.numpy(), c.xyz)


def test_open3d_binary_compressed(tmp_path):
    o3d = pytest.importorskip("open3d")
    rng = np.random.default_rng(3)
    n = 2000
    xyz = np.round(rng.normal(size=(n, 3)), 2).astype(np.float32).astype(np.float64)  # compressible
    cols = rng.integers(0, 256, (n, 3))
    p = o3d.geometry.PointCloud()
    p.points = o3d.utility.Vector3dVector(xyz)
    p.colors = o3d.utility.Vector3dVector(cols / 255.0)
    p.normals = o3d.utility.Vector3dVector(rng.normal(size=(n, 3)))
    path = tmp_path / "c.pcd"
    assert o3d.io.write_point_cloud(str(path), p, compressed=True)
    assert b"DATA binary_compressed" in path.read_bytes()[:400]
    assert path.stat().st_size < n * 28  # really compressed: back references are exercised
    c = pcd.read(path)
    assert c.meta["pcd"]["data"] == "binary_compressed"
    np.testing.assert_array_equal(c.xyz, xyz)
    np.testing.assert_array_equal(c.attrs["rgb"], cols * 257)
    np.testing.assert_array_equal(c.attrs["normal"], np.asarray(p.normals).astype(np.float32))


def test_lzf_overlapping_reference():
    # literal 'ab', then a back reference of length 9 at distance 2 (overlapping: a repeated pattern)
    assert pcd.lzf_decompress(bytes([1]) + b"ab" + bytes([(7 << 5) | 0, 0, 1]), 11) == b"ab" * 5 + b"a"
    with pytest.raises(ValueError):
        pcd.lzf_decompress(bytes([0x20, 5]), 3)


def test_lzf_c_and_python_decoders_agree(monkeypatch):
    """liblzf's C decoder (python-lzf) and the pure-Python fallback give the same bytes, and
    the same errors on corrupt streams."""
    lzf = pytest.importorskip("lzf")
    assert pcd._lzf_c is lzf
    rng = np.random.default_rng(7)
    fields = np.round(rng.normal(size=(3, 20000)), 2).astype(np.float32)  # column-major, compressible
    samples = [fields.tobytes(), b"ab" * 5000 + b"a", bytes(rng.integers(0, 256, 3000, dtype=np.uint8)),
               bytes(70000), b"x"]
    for raw in samples:
        comp = lzf.compress(raw, 2 * len(raw) + 16)  # room for incompressible data (literal runs)
        assert pcd.lzf_decompress_py(comp, len(raw)) == raw
        assert pcd.lzf_decompress(comp, len(raw)) == raw
    comp = lzf.compress(samples[0])
    for bad, n in [(bytes([0x20, 5]), 3), (comp[:-7], len(samples[0])), (comp, len(samples[0]) - 1),
                   (comp, len(samples[0]) + 1), (b"", 4)]:
        with pytest.raises(ValueError) as c_err:
            pcd.lzf_decompress(bad, n)
        with pytest.raises(ValueError) as py_err:
            pcd.lzf_decompress_py(bad, n)
        assert str(c_err.value) == str(py_err.value)
    monkeypatch.setattr(pcd, "_lzf_c", None)  # without python-lzf: the fallback alone
    assert pcd.lzf_decompress(comp, len(samples[0])) == samples[0]


PCL_ASCII = """# .PCD v0.7 - Point Cloud Data file format
VERSION 0.7
FIELDS x y z rgb label
SIZE 4 4 4 4 4
TYPE F F F F U
COUNT 1 1 1 1 1
WIDTH 3
HEIGHT 1
VIEWPOINT 1 2 3 1 0 0 0
POINTS 3
DATA ascii
0.5 1 2 4278190335 2
1 2 3 16711680 6
nan nan nan 0 0
"""


def test_pcl_style_ascii_packed_rgb_label_viewpoint_and_nan(tmp_path):
    p = tmp_path / "pcl.pcd"
    p.write_text(PCL_ASCII)
    c = pcd.read(p)
    assert c.n == 2 and c.meta["pcd"]["dropped_invalid"] == 1
    np.testing.assert_array_equal(c.attrs["rgb"], [[0, 0, 65535], [65535, 0, 0]])
    np.testing.assert_array_equal(c.attrs["classification"], [2, 6])
    assert c.meta["pcd"]["viewpoint"] == [1, 2, 3, 1, 0, 0, 0]
    pcd.write(c, tmp_path / "back.pcd")
    text = (tmp_path / "back.pcd").read_bytes()
    assert b"VIEWPOINT 1 2 3 1 0 0 0" in text and b"label" in text


def test_float_packed_rgb_in_ascii(tmp_path):
    # older writers print the float whose bits hold the colour
    packed = np.array([0x00FF8000], dtype=np.uint32).view(np.float32)[0]
    p = tmp_path / "f.pcd"
    p.write_text(PCL_ASCII.replace("POINTS 3", "POINTS 1").replace("WIDTH 3", "WIDTH 1").split("0.5 1 2")[0] + f"0 0 0 {float(packed)!r} 1\n")
    np.testing.assert_array_equal(pcd.read(p).attrs["rgb"], [[65535, 128 * 257, 0]])


def _hdr(points=2, data="ascii", fields="x y z", size="4 4 4", type_="F F F", count="1 1 1"):
    return (
        f"VERSION 0.7\nFIELDS {fields}\nSIZE {size}\nTYPE {type_}\nCOUNT {count}\nWIDTH {points}\n"
        f"HEIGHT 1\nPOINTS {points}\nDATA {data}\n"
    )


@pytest.mark.parametrize(
    "content,field,words",
    [
        ("hello world\n1 2 3\n", "magic", "not a PCD"),
        (_hdr(3) + "1 2 3\n4 5 6\n", "POINTS", "only 2"),
        (_hdr(fields="x y", size="4 4", type_="F F", count="1 1") + "1 2\n3 4\n", "z", "no 'z'"),
        (_hdr(size="4 4") + "1 2 3\n", "FIELDS", "SIZE/TYPE/COUNT"),
        (_hdr() + "1 2 3\n4 x 6\n", "DATA", "line 11"),
        (_hdr(type_="F F Q") + "1 2 3\n", "z", "unsupported TYPE"),
    ],
)
def test_bad_input_names_file(tmp_path, content, field, words):
    p = tmp_path / "bad.pcd"
    p.write_text(content)
    with pytest.raises(InvalidInputError) as e:
        read_cloud(p)
    assert str(p) in str(e.value) and e.value.field == field and words in str(e.value)


def test_truncated_binary_and_compressed(tmp_path):
    p = tmp_path / "t.pcd"
    pcd.write(_cloud(1, 10), p)
    p.write_bytes(p.read_bytes()[:-3])
    with pytest.raises(InvalidInputError, match="POINTS says 10") as e:
        pcd.read(p)
    assert str(p) in str(e.value)
    q = tmp_path / "z.pcd"
    q.write_bytes(_hdr(2, "binary_compressed").encode() + np.array([100, 24], "<u4").tobytes() + b"\x05abc")
    with pytest.raises(InvalidInputError, match="truncated"):
        pcd.read(q)


def test_unknown_data_mode(tmp_path):
    p = tmp_path / "u.pcd"
    p.write_text(_hdr(1, "zipped") + "1 2 3\n")
    with pytest.raises(UnsupportedFormatError, match="zipped"):
        pcd.read(p)


@pytest.mark.parametrize("ascii", [False, True])
def test_16bit_colour_kept_exactly(tmp_path, ascii):
    rgb = np.array([[1, 2, 255], [0, 17, 30]])  # 8-bit colour held in 16-bit fields, as in many LAS files
    c = Cloud(np.zeros((2, 3)), {"rgb": rgb})
    pcd.write(c, tmp_path / "c.pcd", ascii=ascii)
    back = pcd.read(tmp_path / "c.pcd")
    np.testing.assert_array_equal(back.attrs["rgb"], rgb)
    assert set(back.attrs) == {"rgb"}
    wide = c.with_attrs(rgb=[[65535, 300, 0], [1000, 2, 3]])
    pcd.write(wide, tmp_path / "w.pcd", ascii=ascii)
    np.testing.assert_array_equal(pcd.read(tmp_path / "w.pcd").attrs["rgb"], wide.attrs["rgb"])


def test_crs_kept_in_a_comment(tmp_path):
    c = Cloud(np.zeros((1, 3)), crs="EPSG:2056")
    pcd.write(c, tmp_path / "c.pcd")
    assert (tmp_path / "c.pcd").read_text().startswith("# .PCD")
    assert pcd.read(tmp_path / "c.pcd").crs == "EPSG:2056"
