"""PLY reader/writer: round trips, CRLF, other elements, bad input, the Stanford bunny scans."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud
from workstation.io import ply


def _cloud(seed: int, n: int) -> Cloud:
    rng = np.random.default_rng(seed)
    xyz = rng.normal(size=(n, 3)) * rng.choice([1e-3, 1.0, 1e6])
    return Cloud(
        xyz,
        {
            "rgb": rng.integers(0, 65536, (n, 3)),
            "normal": rng.normal(size=(n, 3)),
            "intensity": rng.integers(0, 65536, n),
            "classification": rng.integers(0, 256, n),
            "gps_time": rng.uniform(0, 1e6, n),
            "curvature": rng.normal(size=n).astype(np.float32),
            "segment": rng.integers(-(2**31), 2**31 - 1, n).astype(np.int32),
        },
    )


def _same(a: Cloud, b: Cloud) -> None:
    np.testing.assert_array_equal(a.xyz, b.xyz)
    assert set(a.attrs) == set(b.attrs)
    for k in a.attrs:
        assert b.attrs[k].dtype == a.attrs[k].dtype, k
        np.testing.assert_array_equal(a.attrs[k], b.attrs[k], err_msg=k)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(0, 300), mode=st.sampled_from(["binary", "ascii", "big"]))
def test_round_trip_is_exact(tmp_path, seed, n, mode):
    c = _cloud(seed, n)
    out = tmp_path / f"rt_{mode}_{seed}_{n}.ply"
    ply.write(c, out, ascii=mode == "ascii", big_endian=mode == "big")
    _same(c, ply.read(out))


def test_float_coordinates_option(tmp_path):
    c = _cloud(1, 50)
    ply.write(c, tmp_path / "f.ply", xyz_type="float")
    back = ply.read(tmp_path / "f.ply")
    np.testing.assert_array_equal(back.xyz, c.xyz.astype(np.float32).astype(np.float64))
    assert back.meta["ply"]["types"]["xyz"][1] == "float"


def test_registry_round_trip_and_no_overwrite(tmp_path):
    c = _cloud(2, 20)
    out = write_cloud(c, tmp_path / "r.ply")
    _same(c, read_cloud(out))
    with pytest.raises(FileExistsError):
        write_cloud(c, out)


CRLF_PLY = (
    "ply\r\nformat ascii 1.0\r\ncomment made in a test\r\nobj_info scanner x\r\n"
    "element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
    "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
    "element face 2\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
    "1.5 2.25 -3 255 0 10 \r\n4 5 6.125 1 2 3 \r\n-7 8e-3 9 0 0 0 \r\n3 0 1 2\r\n4 0 1 2 0\r\n"
)


def test_crlf_ascii_with_faces(tmp_path):
    p = tmp_path / "crlf.ply"
    p.write_bytes(CRLF_PLY.encode())
    c = ply.read(p)
    np.testing.assert_array_equal(c.xyz, [[1.5, 2.25, -3], [4, 5, 6.125], [-7, 8e-3, 9]])
    np.testing.assert_array_equal(c.attrs["rgb"], np.array([[255, 0, 10], [1, 2, 3], [0, 0, 0]]) * 257)
    assert c.meta["ply"]["comments"] == ["made in a test"]
    assert c.meta["ply"]["elements"] == {"vertex": 3, "face": 2}
    # uchar colours are written back as uchar, exactly
    ply.write(c, tmp_path / "back.ply")
    assert b"property uchar red" in (tmp_path / "back.ply").read_bytes()[:400]
    _same(c, ply.read(tmp_path / "back.ply"))


@pytest.mark.parametrize("endian", ["<", ">"])
def test_binary_lists_before_vertex_are_skipped(tmp_path, endian):
    """A face element with lists of varying length before the vertices (walked), then uniform ones."""
    fmt = {"<": "binary_little_endian", ">": "binary_big_endian"}[endian]
    head = (
        f"ply\nformat {fmt} 1.0\nelement face 3\nproperty list uchar int vertex_indices\n"
        "element tri 2\nproperty list uchar uint idx\n"
        "element vertex 2\nproperty double x\nproperty double y\nproperty double z\nproperty ushort intensity\n"
        "end_header\n"
    ).encode()
    body = b""
    for k in (3, 4, 3):
        body += np.array([k], "u1").tobytes() + np.arange(k, dtype=endian + "i4").tobytes()
    for _ in range(2):
        body += np.array([3], "u1").tobytes() + np.arange(3, dtype=endian + "u4").tobytes()
    v = np.array([(1.0, 2.0, 3.0, 7), (4.0, 5.0, 6.0, 65535)], dtype=[("x", endian + "f8"), ("y", endian + "f8"), ("z", endian + "f8"), ("i", endian + "u2")])
    p = tmp_path / "lists.ply"
    p.write_bytes(head + body + v.tobytes())
    c = ply.read(p)
    np.testing.assert_array_equal(c.xyz, [[1, 2, 3], [4, 5, 6]])
    np.testing.assert_array_equal(c.attrs["intensity"], [7, 65535])


def test_ascii_lists_before_vertex(tmp_path):
    p = tmp_path / "a.ply"
    p.write_text(
        "ply\nformat ascii 1.0\nelement face 2\nproperty list uchar int v\nelement vertex 2\n"
        "property float x\nproperty float y\nproperty float z\nend_header\n3 0 1 2\n4 0 1 2 3\n1 2 3\n4 5 6\n"
    )
    np.testing.assert_array_equal(ply.read(p).xyz, [[1, 2, 3], [4, 5, 6]])


def test_property_mapping(tmp_path):
    p = tmp_path / "m.ply"
    p.write_text(
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
        "property float scalar_intensity\nproperty int label\nproperty float nx\nproperty float ny\nproperty float nz\n"
        "property float quality\nend_header\n0 0 0 0.25 1 0 0 1 0.5\n1 1 1 0.75 6 0 1 0 0.25\n"
    )
    c = ply.read(p)
    # a float intensity in 0..1 does not fit u16: kept under its own name, unchanged
    assert "intensity" not in c.attrs
    np.testing.assert_array_equal(c.attrs["scalar_intensity"], np.float32([0.25, 0.75]))
    np.testing.assert_array_equal(c.attrs["classification"], [1, 6])
    assert c.attrs["classification"].dtype == np.uint8
    np.testing.assert_array_equal(c.attrs["normal"], [[0, 0, 1], [0, 1, 0]])
    np.testing.assert_array_equal(c.attrs["quality"], np.float32([0.5, 0.25]))
    ply.write(c, tmp_path / "m2.ply")
    text = (tmp_path / "m2.ply").read_bytes()[:600]
    assert b"property int label" in text and b"property float scalar_intensity" in text


def _header(n=2, fmt="ascii", props=("x", "y", "z")):
    return f"ply\nformat {fmt} 1.0\nelement vertex {n}\n" + "".join(f"property float {p}\n" for p in props) + "end_header\n"


@pytest.mark.parametrize(
    "name,content,field,words",
    [
        ("magic", "plx\nformat ascii 1.0\nend_header\n", "magic", "not a PLY"),
        ("format", "ply\nformat binary_middle_endian 1.0\nelement vertex 1\nend_header\n", "format", "unknown format"),
        ("truncated", _header(3) + "1 2 3\n4 5 6\n", "vertex", "only 2"),
        ("toomany", _header(1) + "1 2 3\n4 5 6\n", "vertex", "header declares 1"),
        ("missing_z", _header(1, props=("x", "y")) + "1 2\n", "z", "no 'z'"),
        ("nonnumeric", _header(2) + "1 2 3\n4 abc 6\n", "vertex", "(line 9)"),
        ("nan", _header(2) + "1 2 3\nnan 5 6\n", "xyz", "NaN"),
        ("noend", "ply\nformat ascii 1.0\nelement vertex 1\n", "header", "end_header"),
        ("dup", _header(1, props=("x", "y", "z", "y")) + "1 2 3 4\n", "y", "appears twice"),
        ("badtype", _header(1).replace("float z", "float128 z") + "1 2 3\n", "z", "unknown property type"),
    ],
)
def test_bad_input_names_file_and_field(tmp_path, name, content, field, words):
    p = tmp_path / f"{name}.ply"
    p.write_bytes(content.encode())
    with pytest.raises(InvalidInputError) as e:
        read_cloud(p)
    assert str(p) in str(e.value) and e.value.field == field and words in str(e.value)


def test_truncated_binary(tmp_path):
    p = tmp_path / "tb.ply"
    c = _cloud(3, 10)
    ply.write(c, p)
    p.write_bytes(p.read_bytes()[:-5])
    with pytest.raises(InvalidInputError, match="declares 10 vertices") as e:
        ply.read(p)
    assert e.value.field == "vertex" and str(p) in str(e.value)


@pytest.mark.realdata
@pytest.mark.parametrize("name", ["bun000", "bun045", "bun090"])
def test_stanford_bunny_crlf(shared_data, name):
    path = shared_data / "registration" / f"{name}.ply"
    raw = path.read_bytes()
    assert b"\r\n" in raw[:20]
    lines = raw.decode("ascii").splitlines()
    n = int(next(l.split()[2] for l in lines if l.startswith("element vertex")))
    start = lines.index("end_header") + 1
    plain = np.array([[float(v) for v in l.split()] for l in lines[start : start + n]])
    c = read_cloud(path)
    assert c.n == n
    np.testing.assert_array_equal(c.bounds[0], plain.min(axis=0))
    np.testing.assert_array_equal(c.bounds[1], plain.max(axis=0))
    np.testing.assert_array_equal(c.xyz, plain)


@pytest.mark.parametrize("ascii", [False, True])
def test_open3d_interchange(tmp_path, ascii):
    """Files open3d writes read back here, and open3d reads what we write."""
    o3d = pytest.importorskip("open3d")
    rng = np.random.default_rng(11)
    n = 200
    xyz = rng.normal(size=(n, 3)) * 100
    cols8 = rng.integers(0, 256, (n, 3))
    normals = rng.normal(size=(n, 3))
    p = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(xyz))
    p.colors = o3d.utility.Vector3dVector(cols8 / 255.0)
    p.normals = o3d.utility.Vector3dVector(normals)
    theirs = tmp_path / "o3d.ply"
    assert o3d.io.write_point_cloud(str(theirs), p, write_ascii=ascii)
    c = ply.read(theirs)
    np.testing.assert_allclose(c.xyz, xyz, rtol=1e-12 if not ascii else 1e-5)  # open3d ascii: 6 digits
    np.testing.assert_array_equal(c.attrs["rgb"], cols8 * 257)
    np.testing.assert_allclose(c.attrs["normal"], normals.astype(np.float32), rtol=1e-5 if ascii else 1e-7, atol=1e-6 if ascii else 0)
    ours = tmp_path / "ours.ply"
    ply.write(c, ours, ascii=ascii)
    q = o3d.io.read_point_cloud(str(ours))
    np.testing.assert_array_equal(np.asarray(q.points), c.xyz)
    np.testing.assert_allclose(np.asarray(q.colors) * 255, cols8, atol=1e-9)


def test_trimesh_mesh_ply_with_faces(tmp_path):
    trimesh = pytest.importorskip("trimesh")
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=3.0)
    path = tmp_path / "mesh.ply"
    mesh.export(path)  # binary, vertex element then a face list element
    c = ply.read(path)
    np.testing.assert_allclose(c.xyz, mesh.vertices, rtol=1e-6)
    assert c.meta["ply"]["elements"]["face"] == len(mesh.faces)


def test_crs_kept_in_a_comment(tmp_path):
    wkt = 'PROJCRS["WGS 84 / UTM zone 32N",\n  BASEGEOGCRS["WGS 84"]]'
    for crs in ("EPSG:32632", wkt):
        c = Cloud(np.zeros((1, 3)), crs=crs)
        ply.write(c, tmp_path / "c.ply")
        assert ply.read(tmp_path / "c.ply").crs == " ".join(crs.split())
