import json

import laspy
import numpy as np
import pytest

from workstation.cli.main import main
from workstation.io import read_cloud, write_cloud


def _run(capsys, *args):
    rc = main(list(args))
    out, err = capsys.readouterr()
    return rc, out, err


def test_info_json_keys_and_values(tmp_path, capsys, small_cloud):
    p = tmp_path / "a.laz"
    write_cloud(small_cloud, p)
    rc, out, _ = _run(capsys, "info", str(p), "--json")
    assert rc == 0
    s = json.loads(out)
    for key in ("point_count", "bounds", "crs", "format", "dimensions", "classification", "returns", "density", "nps"):
        assert key in s
    assert s["point_count"] == small_cloud.n
    np.testing.assert_allclose(s["bounds"]["min"], small_cloud.xyz.min(axis=0))
    assert s["crs"]["epsg"] == 32632
    cls, cnt = np.unique(small_cloud.attrs["classification"], return_counts=True)
    assert s["classification"] == {str(k): int(v) for k, v in zip(cls, cnt)}
    assert s["dimensions"]["intensity"]["max"] == int(small_cloud.attrs["intensity"].max())
    assert sum(s["returns"].values()) == small_cloud.n
    # 1000 points spread over 100 m x 100 m: density over the footprint ~0.1 pts/m2
    assert 0.09 < s["density"]["density_footprint"] < 0.12
    assert s["nps"] == pytest.approx(np.sqrt(1 / s["density"]["density_occupied"]))


def test_info_human_output(tmp_path, capsys, small_cloud):
    p = tmp_path / "a.las"
    write_cloud(small_cloud, p)
    rc, out, _ = _run(capsys, "info", str(p))
    assert rc == 0
    assert "1,000" in out and "Ground" in out and "UTM zone 32N" in out


def test_convert_assign_and_reproject(tmp_path, capsys, small_cloud):
    src = tmp_path / "a.las"
    write_cloud(small_cloud.with_crs(None), src)
    assigned = tmp_path / "b.laz"
    rc, _, err = _run(capsys, "convert", str(src), str(assigned), "--crs", "EPSG:32632")
    assert rc == 0, err
    assert read_cloud(assigned).crs == "EPSG:32632"
    geo = tmp_path / "c.las"
    rc, _, err = _run(capsys, "convert", str(assigned), str(geo), "--to-crs", "EPSG:4326")
    assert rc == 0, err
    g = read_cloud(geo)
    assert g.crs == "EPSG:4326"
    # a tenth of the input's 1 mm in degrees (ws convert keeps the resolution; round trips stay < 1 mm)
    assert laspy.open(geo).header.scales[0] == pytest.approx(1e-10)
    # 500 km easting in zone 32N is the central meridian, 9 degrees east
    assert 8.99 < g.xyz[:, 0].min() < g.xyz[:, 0].max() < 9.01
    import pyproj

    tr = pyproj.Transformer.from_crs("EPSG:32632", "EPSG:4326", always_xy=True)
    lon, lat = tr.transform(small_cloud.xyz[:, 0], small_cloud.xyz[:, 1])
    np.testing.assert_allclose(g.xyz[:, 0], lon, atol=1e-7)
    np.testing.assert_allclose(g.xyz[:, 1], lat, atol=1e-7)


@pytest.mark.parametrize(
    "setup, args, message",
    [
        ("exists", ["--json"], "exists"),
        ("same", [], "same file"),
        ("badext", [], "unknown point cloud extension"),
        ("badcrs", ["--crs", "EPSG:99999999"], "not a CRS"),
    ],
)
def test_convert_user_errors_exit_1(tmp_path, capsys, small_cloud, setup, args, message):
    src = tmp_path / "a.las"
    write_cloud(small_cloud, src)
    dst = {"exists": tmp_path / "b.las", "same": src, "badext": tmp_path / "b.xyzw", "badcrs": tmp_path / "c.las"}[setup]
    if setup == "exists":
        dst.write_bytes(b"keep me")
    rc, out, err = _run(capsys, "convert", str(src), str(dst), *args)
    assert rc == 1
    assert message in err and "Traceback" not in err
    if setup == "exists":
        assert dst.read_bytes() == b"keep me"


def test_truncated_input_is_a_clear_error(tmp_path, capsys, small_cloud):
    src = tmp_path / "a.laz"
    write_cloud(small_cloud, src)
    cut = tmp_path / "cut.laz"
    cut.write_bytes(src.read_bytes()[:400])
    rc, _, err = _run(capsys, "info", str(cut))
    assert rc == 1 and "cut.laz" in err


def test_usage_error_exit_2(capsys):
    rc, _, _ = _run(capsys, "convert")
    assert rc == 2
    rc, _, _ = _run(capsys, "nosuchcommand")
    assert rc == 2


@pytest.mark.realdata
@pytest.mark.parametrize("name", ["Topography.laz", "MixedConifer.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las",
                                  "warsaw_small.las", "lidarhd_extra_bytes.laz", "sample_c.las", "vegetation_1_3.las",
                                  "fullwave.laz", "TreeLS_pine.laz"])
def test_info_matches_laspy_on_real_files(shared_data, capsys, name):
    src = shared_data / "lidar" / name
    ref = laspy.read(src)
    rc, out, _ = _run(capsys, "info", str(src), "--json")
    assert rc == 0
    s = json.loads(out)
    assert s["point_count"] == len(ref.points)
    np.testing.assert_allclose(s["bounds"]["min"], [ref.x.min(), ref.y.min(), ref.z.min()])
    np.testing.assert_allclose(s["bounds"]["max"], [ref.x.max(), ref.y.max(), ref.z.max()])
    cls, cnt = np.unique(np.asarray(ref.classification), return_counts=True)
    assert s["classification"] == {str(k): int(v) for k, v in zip(cls, cnt)}


def test_columns_rejected_for_non_text_input(tmp_path, capsys, small_cloud):
    src = tmp_path / "a.las"
    write_cloud(small_cloud, src)
    rc, _, err = _run(capsys, "convert", str(src), str(tmp_path / "b.ply"), "--columns", "x,y,z")
    assert rc == 2 and "text inputs" in err
    rc, _, err = _run(capsys, "info", str(src), "--columns", "x,y,z")
    assert rc == 2


def test_text_input_with_nan_and_missing_column(tmp_path, capsys):
    bad = tmp_path / "nan.xyz"
    bad.write_text("1 2 3\n4 nan 6\n")
    rc, _, err = _run(capsys, "info", str(bad))
    assert rc == 1 and "nan.xyz" in err and "Traceback" not in err
    ok = tmp_path / "three.txt"
    ok.write_text("1 2 3\n4 5 6\n")
    rc, _, err = _run(capsys, "convert", str(ok), str(tmp_path / "o.las"), "--columns", "x,y,z,label")
    assert rc == 1 and "label" in err
    assert not (tmp_path / "o.las").exists()


@pytest.mark.realdata
def test_convert_isprs_text_to_laz_keeps_labels(shared_data, tmp_path, capsys):
    out = tmp_path / "samp11.laz"
    rc, _, err = _run(capsys, "convert", str(shared_data / "isprs" / "samp11.txt"), str(out), "--columns", "x,y,z,label")
    assert rc == 0, err
    c = read_cloud(out)
    ref = np.loadtxt(shared_data / "isprs" / "samp11.txt")
    assert c.n == 38010
    np.testing.assert_allclose(c.xyz, ref[:, :3], atol=5e-4)
    np.testing.assert_array_equal(c.attrs["label"], ref[:, 3])


@pytest.mark.realdata
def test_info_e57_matches_pye57(shared_data, capsys):
    import pye57

    src = shared_data / "lidar" / "pumpAVisualReferenceImage.e57"
    rc, out, _ = _run(capsys, "info", str(src), "--json")
    assert rc == 0
    s = json.loads(out)
    e = pye57.E57(str(src))
    total = 0
    for i in range(e.scan_count):
        d = e.read_scan(i, ignore_missing_fields=True)
        total += len(d["cartesianX"])
    assert s["point_count"] == total
