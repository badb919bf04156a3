"""Text point clouds (XYZ/TXT/CSV/PTS): column specs, detection, round trips, bad input, ISPRS."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud
from workstation.io import text


def _cloud(seed: int, n: int) -> Cloud:
    rng = np.random.default_rng(seed)
    return Cloud(
        rng.normal(size=(n, 3)) * rng.choice([1.0, 1e3, 1e6]),
        {
            "intensity": rng.integers(0, 65536, n),
            "rgb": rng.integers(0, 256, (n, 3)) * 257,
            "normal": rng.normal(size=(n, 3)),
            "classification": rng.integers(0, 256, n),
            "gps_time": rng.uniform(0, 1e6, n),
            "hag": rng.normal(size=n).astype(np.float32),
        },
    )


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 200), ext=st.sampled_from([".csv", ".txt", ".xyz"]))
def test_round_trip_exact_precision(tmp_path, seed, n, ext):
    c = _cloud(seed, n)
    p = tmp_path / f"rt_{seed}_{n}{ext}"
    text.write(c, p, precision="exact", header=True)
    back = text.read(p)
    np.testing.assert_array_equal(back.xyz, c.xyz)
    assert set(back.attrs) == set(c.attrs)
    for k in c.attrs:
        assert back.attrs[k].dtype == c.attrs[k].dtype, k
        np.testing.assert_array_equal(back.attrs[k], c.attrs[k], err_msg=k)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), precision=st.integers(0, 8))
def test_round_trip_fixed_decimals(tmp_path, seed, precision):
    rng = np.random.default_rng(seed)
    c = Cloud(rng.uniform(-1e5, 1e5, (50, 3)))
    p = tmp_path / f"fx_{seed}_{precision}.xyz"
    text.write(c, p, precision=precision)
    back = text.read(p)
    assert np.abs(back.xyz - c.xyz).max() <= 0.5 * 10.0**-precision * (1 + 1e-6) + 1e-10


def test_precision_from_las_scale(tmp_path):
    c = Cloud([[1.23456, 2.0, 3.0]], meta={"las": {"scales": [0.01, 0.01, 0.001]}})
    text.write(c, tmp_path / "s.xyz")
    assert (tmp_path / "s.xyz").read_text() == "1.235 2.000 3.000\n"


@pytest.mark.parametrize(
    "ncols,expect",
    [(3, []), (4, ["intensity"]), (6, ["rgb"]), (7, ["intensity", "rgb"])],
)
def test_default_spec_by_column_count(tmp_path, ncols, expect):
    row = "1 2 3 " + " ".join({3: [], 4: ["100"], 6: ["255", "0", "10"], 7: ["100", "255", "0", "10"]}[ncols])
    p = tmp_path / "d.xyz"
    p.write_text(row + "\n" + row + "\n")
    c = text.read(p)
    assert sorted(c.attrs) == sorted(expect)
    if "rgb" in expect:
        np.testing.assert_array_equal(c.attrs["rgb"][0], [65535, 0, 2570])
    if "intensity" in expect:
        assert c.attrs["intensity"][0] == 100


@pytest.mark.parametrize("sep", [",", ";", "\t", " ", "  \t "])
def test_delimiter_detection_and_crlf(tmp_path, sep):
    p = tmp_path / "x.txt"
    p.write_bytes(("1.5{0}2{0}3\r\n4{0}5{0}6.25\r\n".format(sep)).encode())
    np.testing.assert_array_equal(text.read(p).xyz, [[1.5, 2, 3], [4, 5, 6.25]])


def test_header_names_columns(tmp_path):
    p = tmp_path / "h.csv"
    p.write_text("//X,Y,Z,Intensity,treeID,Classification\n1,2,3,7,12.5,2\n4,5,6,8,13.5,6\n")
    c = text.read(p)
    np.testing.assert_array_equal(c.attrs["intensity"], [7, 8])
    np.testing.assert_array_equal(c.attrs["treeID"], [12.5, 13.5])
    np.testing.assert_array_equal(c.attrs["classification"], [2, 6])


def test_spec_skip_and_label_kept_raw(tmp_path):
    p = tmp_path / "s.txt"
    p.write_text("9 1 2 3 0\n9 4 5 6 1\n")
    c = text.read(p, columns="skip,x,y,z,label")
    np.testing.assert_array_equal(c.xyz, [[1, 2, 3], [4, 5, 6]])
    np.testing.assert_array_equal(c.attrs["label"], [0, 1])
    assert "classification" not in c.attrs


def test_fractional_intensity_kept_as_free(tmp_path):
    p = tmp_path / "f.xyz"
    p.write_text("1 2 3 0.5\n4 5 6 0.25\n")
    c = text.read(p)
    assert "intensity" not in c.attrs
    np.testing.assert_array_equal(c.attrs["intensity_raw"], [0.5, 0.25])


def test_rgb_16bit_written_and_read_exactly(tmp_path):
    c = Cloud(np.zeros((3, 3)), {"rgb": [[1, 2, 3], [65535, 0, 256], [300, 400, 500]]})
    text.write(c, tmp_path / "c.csv")
    np.testing.assert_array_equal(text.read(tmp_path / "c.csv").attrs["rgb"], c.attrs["rgb"])


def test_pts_count_line(tmp_path):
    c = Cloud(np.arange(21.0).reshape(7, 3), {"intensity": np.arange(7), "rgb": np.full((7, 3), 257)})
    write_cloud(c, tmp_path / "a.pts")
    assert (tmp_path / "a.pts").read_text().splitlines()[0] == "7"
    back = read_cloud(tmp_path / "a.pts")
    np.testing.assert_array_equal(back.xyz, c.xyz)
    np.testing.assert_array_equal(back.attrs["rgb"], c.attrs["rgb"])


def test_writer_columns_option(tmp_path):
    c = Cloud([[1.0, 2.0, 3.0]], {"classification": [6], "intensity": [9]})
    text.write(c, tmp_path / "w.csv", columns="x,y,z,classification", precision=1)
    assert (tmp_path / "w.csv").read_text() == "x,y,z,classification\n1.0,2.0,3.0,6\n"


@pytest.mark.parametrize(
    "content,opts,field,words",
    [
        ("1 2 3\n4 5 6\n", {"columns": "x,y,z,label"}, "label", "missing column 'label' (file has 3 columns)"),
        ("1 2 3\n4 5 6\n", {"columns": "x,y,zz"}, "zz", "unknown column name 'zz'"),
        ("1 2 3\n4 five 6\n", {}, "columns", "line 2"),
        ("1 2 3\n4 5 6\n7 8\n", {}, "columns", "line 3"),
        ("1 2 3 4 5\n", {}, "columns", "cannot guess"),
        ("1 2 3\n", {"columns": "x,y,skip"}, "z", "no 'z' column"),
        ("1 2 3\nnan 5 6\n", {}, "xyz", "NaN"),
    ],
)
def test_bad_input_names_file(tmp_path, content, opts, field, words):
    p = tmp_path / "bad.txt"
    p.write_text(content)
    with pytest.raises(InvalidInputError) as e:
        read_cloud(p, **opts)
    assert str(p) in str(e.value) and e.value.field == field and words in str(e.value)


@pytest.mark.realdata
def test_isprs_samp11(shared_data):
    path = shared_data / "isprs" / "samp11.txt"
    c = read_cloud(path, columns="x,y,z,label")
    assert c.n == 38010
    assert set(np.unique(c.attrs["label"]).tolist()) == {0, 1}
    plain = np.array([[float(v) for v in line.split()] for line in path.read_text().splitlines() if line.strip()])
    np.testing.assert_array_equal(c.xyz, plain[:, :3])
    np.testing.assert_array_equal(c.attrs["label"], plain[:, 3])


def test_headerless_default_reads_back(tmp_path):
    c = Cloud([[1.0, 2.0, 3.0]], {"intensity": [5], "rgb": [[257, 514, 771]], "classification": [2]})
    text.write(c, tmp_path / "n.xyz")
    assert (tmp_path / "n.xyz").read_text() == "1.0000 2.0000 3.0000 5 1 2 3\n"
    back = text.read(tmp_path / "n.xyz")
    np.testing.assert_array_equal(back.attrs["rgb"], c.attrs["rgb"])
    assert back.attrs["intensity"][0] == 5 and "classification" not in back.attrs


def test_16bit_colours_below_256_read_back_exactly(tmp_path):
    """LAS files often hold 8-bit values in the 16-bit fields: the header must say 16-bit."""
    c = Cloud(np.zeros((2, 3)), {"rgb": [[1, 2, 255], [0, 17, 30]]})
    text.write(c, tmp_path / "c.csv")
    assert (tmp_path / "c.csv").read_text().splitlines()[0] == "x,y,z,r16,g16,b16"
    np.testing.assert_array_equal(text.read(tmp_path / "c.csv").attrs["rgb"], c.attrs["rgb"])
