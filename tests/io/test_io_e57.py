"""E57 through pye57: poses, invalid points, spherical scans, scaling, round trips, the pump scan."""

from __future__ import annotations

import uuid

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import e57, read_cloud, write_cloud

pye57 = pytest.importorskip("pye57")


def _pye57_points(path, index):
    d = pye57.E57(str(path)).read_scan(index, intensity=True, colors=True, ignore_missing_fields=True)
    return np.column_stack([d["cartesianX"], d["cartesianY"], d["cartesianZ"]]), d


def _two_posed_scans(path, rng):
    """Two scans written by pye57 itself, with poses and invalid points."""
    f = pye57.E57(str(path), mode="w")
    truth = []
    for k, (q, t) in enumerate([((1.0, 0, 0, 0), (0, 0, 0)), ((np.cos(0.4), 0.1, -0.2, np.sin(0.4)), (100.0, -50.0, 3.0))]):
        q = np.array(q) / np.linalg.norm(q)
        n = 500
        state = rng.choice([0, 0, 0, 1, 2], n).astype(np.int8)
        data = {
            "cartesianX": rng.normal(size=n) * 10,
            "cartesianY": rng.normal(size=n) * 10,
            "cartesianZ": rng.normal(size=n),
            "intensity": rng.uniform(0.2, 0.9, n).astype(np.float32),
            "colorRed": rng.integers(0, 256, n).astype(np.uint8),
            "colorGreen": rng.integers(0, 256, n).astype(np.uint8),
            "colorBlue": rng.integers(0, 256, n).astype(np.uint8),
            "cartesianInvalidState": state,
        }
        f.write_scan_raw(data, name=f"s{k}", rotation=q, translation=np.array(t))
        truth.append(data)
    f.close()
    return truth


def test_poses_invalid_points_and_scan_ids(tmp_path):
    rng = np.random.default_rng(5)
    path = tmp_path / "posed.e57"
    truth = _two_posed_scans(path, rng)
    c = read_cloud(path)
    ref = [_pye57_points(path, i) for i in range(2)]
    np.testing.assert_allclose(c.xyz, np.vstack([r[0] for r in ref]), rtol=0, atol=1e-9)
    valid = [t["cartesianInvalidState"] == 0 for t in truth]
    assert c.n == sum(int(v.sum()) for v in valid)
    np.testing.assert_array_equal(c.attrs["point_source_id"], np.repeat([0, 1], [int(v.sum()) for v in valid]))
    # the second scan really moved: its points are not the raw coordinates
    raw1 = np.column_stack([truth[1][f"cartesian{a}"] for a in "XYZ"])[valid[1]]
    assert np.abs(c.xyz[c.attrs["point_source_id"] == 1] - raw1).max() > 1.0
    # colour 0..255 -> x 257; intensity scaled over the scan's limits (data min..max as pye57 writes them)
    np.testing.assert_array_equal(c.attrs["rgb"][: int(valid[0].sum()), 0], truth[0]["colorRed"][valid[0]].astype(np.uint16) * 257)
    i0 = truth[0]["intensity"].astype(np.float64)
    expect = np.round((i0 - i0.min()) / (i0.max() - i0.min()) * 65535)[valid[0]]
    np.testing.assert_allclose(c.attrs["intensity"][: int(valid[0].sum())], expect, atol=1)
    only = e57.read(path, scans=[1])
    np.testing.assert_allclose(only.xyz, ref[1][0], atol=1e-9)
    assert set(only.attrs["point_source_id"].tolist()) == {1}
    assert [s["index"] for s in only.meta["e57"]["scans"]] == [1]


def test_spherical_scan_becomes_cartesian(tmp_path):
    from pye57 import libe57

    path = tmp_path / "sph.e57"
    f = pye57.E57(str(path), mode="w")
    imf = f.image_file
    scan = libe57.StructureNode(imf)
    scan.set("guid", libe57.StringNode(imf, "{%s}" % uuid.uuid4()))
    proto = libe57.StructureNode(imf)
    for name in ("sphericalRange", "sphericalAzimuth", "sphericalElevation"):
        proto.set(name, libe57.FloatNode(imf, 0.0, libe57.E57_DOUBLE))
    proto.set("sphericalInvalidState", libe57.IntegerNode(imf, 0, 0, 2))
    points = libe57.CompressedVectorNode(imf, proto, libe57.VectorNode(imf, True))
    scan.set("points", points)
    f.data3d.append(scan)
    arrays = {
        "sphericalRange": np.array([2.0, 1.0, 3.0]),
        "sphericalAzimuth": np.array([0.0, np.pi / 2, 0.0]),
        "sphericalElevation": np.array([0.0, 0.0, np.pi / 2]),
        "sphericalInvalidState": np.array([0.0, 0.0, 2.0]),
    }
    bufs = libe57.VectorSourceDestBuffer()
    for k, a in arrays.items():
        bufs.append(libe57.SourceDestBuffer(imf, k, a, 3, True, True))
    w = points.writer(bufs)
    w.write(3)
    w.close()
    f.close()
    c = e57.read(path)
    np.testing.assert_allclose(c.xyz, [[2, 0, 0], [0, 1, 0]], atol=1e-12)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(1, 300), eight_bit=st.booleans())
def test_round_trip_is_exact(tmp_path, seed, n, eight_bit):
    rng = np.random.default_rng(seed)
    rgb = rng.integers(0, 256, (n, 3)) * 257 if eight_bit else rng.integers(0, 65536, (n, 3))
    c = Cloud(rng.normal(size=(n, 3)) * 1e5 + 5e5, {"intensity": rng.integers(0, 65536, n), "rgb": rgb})
    p = tmp_path / f"rt_{seed}_{n}_{eight_bit}.e57"
    e57.write(c, p)
    back = e57.read(p)
    np.testing.assert_array_equal(back.xyz, c.xyz)
    np.testing.assert_array_equal(back.attrs["intensity"], c.attrs["intensity"])
    np.testing.assert_array_equal(back.attrs["rgb"], c.attrs["rgb"])
    if eight_bit:  # pye57's own reader sees the same file (it expects 8-bit colour)
        xyz, d = _pye57_points(p, 0)
        np.testing.assert_array_equal(xyz, c.xyz)
        np.testing.assert_array_equal(d["colorGreen"].astype(np.uint16) * 257, c.attrs["rgb"][:, 1])


def test_registry_write(tmp_path):
    c = Cloud([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    out = write_cloud(c, tmp_path / "w.e57")
    np.testing.assert_array_equal(read_cloud(out).xyz, c.xyz)


def test_bad_input(tmp_path):
    p = tmp_path / "bad.e57"
    p.write_bytes(b"not an e57 file at all" * 100)
    with pytest.raises(InvalidInputError) as e:
        read_cloud(p)
    assert str(p) in str(e.value) and e.value.field == "magic"
    good = tmp_path / "g.e57"
    e57.write(Cloud([[0.0, 0.0, 0.0]]), good)
    with pytest.raises(InvalidInputError, match="scan 3 does not exist") as e:
        e57.read(good, scans=[3])
    assert e.value.field == "scans"


@pytest.mark.realdata
def test_pump_scan_matches_pye57(shared_data):
    path = shared_data / "lidar" / "pumpAVisualReferenceImage.e57"
    c = read_cloud(path)
    f = pye57.E57(str(path))
    ref_xyz = []
    for i in range(f.scan_count):
        xyz, d = _pye57_points(path, i)
        ref_xyz.append(xyz)
    ref = np.vstack(ref_xyz)
    assert c.n == ref.shape[0] == 155201
    np.testing.assert_array_equal(c.bounds[0], ref.min(axis=0))
    np.testing.assert_array_equal(c.bounds[1], ref.max(axis=0))
    np.testing.assert_array_equal(c.xyz, ref)
    np.testing.assert_array_equal(c.attrs["rgb"][:, 0], d["colorRed"].astype(np.uint16) * 257)
    # intensity limits 0..1 in the header: u16 = round(i * 65535)
    np.testing.assert_allclose(c.attrs["intensity"], np.round(d["intensity"].astype(np.float64) * 65535), atol=1)
