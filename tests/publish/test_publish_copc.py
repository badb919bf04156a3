"""COPC writer: laspy's CopcReader and copc-lib (an independent C++ reader, test dependency
only) read back exactly the points written; queries by box and by level return exactly the
right points; the octree is a grid sampling; attributes, extra bytes and CRS survive; empty,
one-point and all-duplicate clouds; a streamed input gives the same file; ``ws convert``."""

from __future__ import annotations

import json

import numpy as np
import pytest

laspy = pytest.importorskip("laspy")

from workstation.core.cloud import Cloud  # noqa: E402
from workstation.core.errors import InvalidInputError  # noqa: E402
from workstation.io import copc as io_copc  # noqa: E402
from workstation.io import iter_chunks, read_cloud, write_cloud  # noqa: E402
from workstation.publish.copc import CopcParams, assign_levels, save_copc, write_copc, write_copc_chunks  # noqa: E402

X0, Y0 = 500_000.0, 4_000_000.0
PARAMS = CopcParams(max_points=2_000, cells=16)  # small nodes: several levels from 20,000 points
N = 20_000


def _cloud(n=N, seed=5, rgb=True):
    """A terrain-like cloud on a 1 mm grid with unique GPS times, RGB and an extra dimension."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, [120.0, 90.0], (n, 2))
    z = 100 + 5 * np.sin(xy[:, 0] / 15) + rng.normal(0, 0.3, n)
    xyz = np.round(np.column_stack([xy[:, 0] + X0, xy[:, 1] + Y0, z]), 3)
    rn = rng.integers(1, 4, n)
    attrs = {
        "intensity": rng.integers(0, 65535, n).astype(np.uint16),
        "return_number": rn.astype(np.uint8),
        "number_of_returns": np.maximum(rn, rng.integers(1, 4, n)).astype(np.uint8),
        "classification": rng.choice([1, 2, 5, 6], n).astype(np.uint8),
        "gps_time": rng.permutation(n) * 1e-3 + 1000.0,
        "point_source_id": rng.integers(1, 4, n).astype(np.uint16),
        "hag": rng.normal(0, 2, n).astype(np.float32),
    }
    if rgb:
        attrs["rgb"] = rng.integers(0, 65535, (n, 3)).astype(np.uint16)
    return Cloud(xyz, attrs, crs="EPSG:32632")


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    cloud = _cloud()
    path = tmp_path_factory.mktemp("copc") / "w.copc.laz"
    result = write_copc(cloud, path, PARAMS)
    return cloud, path, result


def _by_time(c: Cloud) -> Cloud:
    return c[np.argsort(c.attrs["gps_time"], kind="stable")]


def _query(path, bounds=None, level=None):
    from laspy.copc import Bounds

    box = None if bounds is None else Bounds(mins=np.asarray(bounds[0], float), maxs=np.asarray(bounds[1], float))
    with laspy.CopcReader.open(str(path)) as r:
        return r.query(bounds=box, level=level)


def test_laspy_copc_reader_reads_back_identical_points(written):
    cloud, path, result = written
    assert result.points == N and result.point_format == 7 and result.levels >= 3
    rec = _query(path)
    order = np.argsort(np.asarray(rec.gps_time))
    ref = _by_time(cloud)
    ints = np.round((ref.xyz - rec.offsets) / rec.scales).astype(np.int64)  # the stored integers
    np.testing.assert_array_equal(np.column_stack([rec.X, rec.Y, rec.Z])[order], ints)
    for las_name, attr in (("intensity", "intensity"), ("classification", "classification"),
                           ("return_number", "return_number"), ("point_source_id", "point_source_id"),
                           ("hag", "hag")):
        np.testing.assert_array_equal(np.asarray(rec[las_name])[order], ref.attrs[attr], err_msg=las_name)
    np.testing.assert_array_equal(np.column_stack([rec.red, rec.green, rec.blue])[order], ref.attrs["rgb"])


def test_every_attribute_crs_and_extra_bytes_round_trip(written):
    cloud, path, _ = written
    back = _by_time(read_cloud(path))
    ref = _by_time(cloud)
    assert back.crs == "EPSG:32632"
    np.testing.assert_allclose(back.xyz, ref.xyz, rtol=0, atol=1e-9)  # X * scale + offset in float
    for name, values in ref.attrs.items():
        np.testing.assert_array_equal(back.attrs[name], values, err_msg=name)
    with laspy.open(str(path)) as r:
        h = r.header
        assert h.version.minor == 4 and h.global_encoding.wkt
        assert (h.vlrs[0].user_id, h.vlrs[0].record_id) == io_copc.COPC_INFO
        assert any(type(v).__name__ == "WktCoordinateSystemVlr" for v in h.vlrs)
        assert not any(type(v).__name__ == "GeoKeyDirectoryVlr" for v in h.vlrs)


def test_hierarchy_counts_sum_to_the_header_count(written):
    _, path, result = written
    s = io_copc.summary(path)
    with laspy.open(str(path)) as r:
        assert r.header.point_count == N
    assert s["points"] == N == sum(result.points_per_level)
    assert s["nodes"] == result.nodes and s["levels"] == result.levels
    info = io_copc.read_info(path)
    assert info.gps_min == pytest.approx(1000.0) and info.gps_max == pytest.approx(1000.0 + (N - 1) * 1e-3)


@pytest.mark.parametrize("box", [
    ((X0 + 10.0005, Y0 + 20.0005, 90.0), (X0 + 70.0005, Y0 + 55.0005, 110.0)),  # crosses node planes
    ((X0 + 59.9995, Y0 - 1.0, 90.0), (X0 + 60.5005, Y0 + 100.0, 103.0005)),  # a thin slab, z cut
    ((X0 - 5.0, Y0 - 5.0, 0.0), (X0 + 0.5005, Y0 + 0.5005, 200.0)),  # a corner
])
def test_bounds_query_returns_exactly_the_points_inside(written, box):
    cloud, path, _ = written
    lo, hi = np.asarray(box[0]), np.asarray(box[1])
    inside = np.all((cloud.xyz >= lo) & (cloud.xyz <= hi), axis=1)  # bounds sit between mm grid values
    rec = _query(path, bounds=box)
    assert inside.sum() > 0
    assert sorted(np.asarray(rec.gps_time).tolist()) == sorted(cloud.attrs["gps_time"][inside].tolist())
    got = read_cloud(path, bounds=(lo[0], lo[1], hi[0], hi[1], lo[2], hi[2]))  # io.copc.read
    assert sorted(got.attrs["gps_time"].tolist()) == sorted(cloud.attrs["gps_time"][inside].tolist())


def test_level_queries_follow_the_hierarchy_and_are_a_grid_sampling(written):
    cloud, path, result = written
    info = io_copc.read_info(path)
    corner = np.asarray(info.center) - info.halfsize
    seen = []
    for level in range(result.levels):
        rec = _query(path, level=level)
        assert len(rec) == result.points_per_level[level]
        seen.extend(np.asarray(rec.gps_time).tolist())
        cum = _query(path, level=range(0, level + 1))
        assert len(cum) == sum(result.points_per_level[: level + 1])
    assert sorted(seen) == sorted(cloud.attrs["gps_time"].tolist())  # each point at exactly one level
    # the root keeps one point in each occupied cell of side `spacing`: unique cells, all covered
    root = _query(path, level=0)
    cells = lambda xyz: np.unique(np.floor((xyz - corner) / info.spacing).astype(np.int64), axis=0)  # noqa: E731
    root_cells = cells(np.column_stack([root.x, root.y, root.z]))
    assert len(root_cells) == len(root)
    assert len(root_cells) == len(cells(cloud.xyz))


def test_copclib_reads_the_same_nodes_and_points(written):
    copclib = pytest.importorskip("copclib")
    cloud, path, result = written
    reader = copclib.FileReader(str(path))
    nodes = reader.GetAllNodes()
    ours = io_copc.hierarchy(path, io_copc.read_info(path))
    assert sorted((n.key.d, n.key.x, n.key.y, n.key.z, n.point_count) for n in nodes) == sorted(
        zip(*(ours[k].tolist() for k in ("level", "x", "y", "z", "point_count"))))
    assert len(nodes) == result.nodes and sum(n.point_count for n in nodes) == N
    info = io_copc.read_info(path)
    side = 2 * info.halfsize
    corner = np.asarray(info.center) - info.halfsize
    for n in nodes:  # every node's points lie inside the node's cube (from the COPC info)
        pts = reader.GetPoints(n)
        xyz = np.column_stack([pts.x, pts.y, pts.z])
        lo = corner + np.array([n.key.x, n.key.y, n.key.z]) * side / 2**n.key.d
        assert len(xyz) == n.point_count
        assert np.all((xyz >= lo) & (xyz <= lo + side / 2**n.key.d))
    assert len(reader.GetAllPoints()) == N


def test_leaves_hold_at_most_max_points(written):
    _, path, _ = written
    e = io_copc.hierarchy(path, io_copc.read_info(path))
    keys = set(zip(e["level"].tolist(), e["x"].tolist(), e["y"].tolist(), e["z"].tolist()))
    parents = {(lv - 1, x // 2, y // 2, z // 2) for lv, x, y, z in keys if lv > 0}
    assert parents <= keys  # every node's parent exists (readers walk down from the root)
    leaf = np.array([(lv, x, y, z) not in parents for lv, x, y, z in zip(e["level"], e["x"], e["y"], e["z"])])
    assert e["point_count"][leaf].max() <= PARAMS.max_points
    assert e["point_count"][~leaf].min() >= 1


@pytest.mark.parametrize("extra, fmt", [({}, 6), ({"rgb"}, 7), ({"rgb", "nir"}, 8)])
def test_point_format_follows_the_attributes(tmp_path, extra, fmt):
    n = 50
    attrs = {"intensity": np.arange(n, dtype=np.uint16)}
    if "rgb" in extra:
        attrs["rgb"] = np.full((n, 3), 7, np.uint16)
    if "nir" in extra:
        attrs["nir"] = np.arange(n, dtype=np.uint16)
    r = write_copc(Cloud(np.arange(3.0 * n).reshape(n, 3), attrs), tmp_path / "f.copc.laz")
    assert r.point_format == fmt
    back = read_cloud(tmp_path / "f.copc.laz")
    if "nir" in extra:
        np.testing.assert_array_equal(np.sort(back.attrs["nir"]), np.arange(n))


@pytest.mark.parametrize("n", [0, 1])
def test_empty_and_one_point_clouds(tmp_path, n):
    path = tmp_path / "e.copc.laz"
    r = write_copc(Cloud(np.full((n, 3), 7.25), {"intensity": np.full(n, 9, np.uint16)}), path)
    assert r.points == n and io_copc.is_copc(path)
    assert len(_query(path)) == n and io_copc.summary(path)["points"] == n
    back = read_cloud(path)
    assert back.n == n and (n == 0 or back.xyz.tolist() == [[7.25, 7.25, 7.25]])


def test_duplicate_points_stop_at_the_deepest_level(tmp_path):
    cloud = Cloud(np.tile([[1.0, 2.0, 3.0]], (3000, 1)), {"gps_time": np.arange(3000.0)})
    r = write_copc(cloud, tmp_path / "d.copc.laz", CopcParams(max_points=100, cells=16))
    assert r.points == 3000 and r.levels == 21 - 4 + 1 and len(_query(tmp_path / "d.copc.laz")) == 3000


def test_assign_levels_keeps_one_point_per_cell():
    codes = np.sort(np.random.default_rng(1).integers(0, 2**63, 5000, dtype=np.uint64))
    lev = assign_levels(codes, CopcParams(max_points=500, cells=4))
    root_cells = codes >> np.uint64(3 * (21 - 2))  # 4 cells a side at the root: top 6 bits
    assert np.array_equal(np.unique(root_cells[lev == 0]), np.unique(root_cells))
    assert (lev == 0).sum() == len(np.unique(root_cells))


def test_streamed_chunks_give_the_same_file(tmp_path):
    cloud = _cloud(6000, seed=9)
    src = tmp_path / "in.laz"
    write_cloud(cloud, src)
    whole, streamed = tmp_path / "a.copc.laz", tmp_path / "b.copc.laz"
    write_copc(read_cloud(src), whole, CopcParams(max_points=1000, cells=16))
    with laspy.open(str(src)) as r:
        bounds = (np.asarray(r.header.mins), np.asarray(r.header.maxs))
    write_copc_chunks(iter_chunks(src, 1700), streamed, CopcParams(max_points=1000, cells=16), bounds=bounds)
    assert whole.read_bytes() == streamed.read_bytes()
    assert io_copc.summary(streamed)["levels"] >= 2


def test_on_octree_sees_the_octree_that_is_written(tmp_path):
    cloud = _cloud(6000, seed=9)
    params = CopcParams(max_points=1000, cells=16)
    plain, hooked = tmp_path / "a.copc.laz", tmp_path / "b.copc.laz"
    write_copc(cloud, plain, params)
    seen = []

    def look(staged):  # the records are only valid during the call
        seen.append((staged.tree, np.sort(np.asarray(staged.records["gps_time"])[staged.tree.src[:100]]),
                     staged.header.point_count, staged.crs, staged.params))

    res = write_copc_chunks(iter([cloud]), hooked, params, on_octree=look)
    assert plain.read_bytes() == hooked.read_bytes()  # the callback changes nothing in the file
    ((tree, gps, count, crs, got_params),) = seen
    assert count == cloud.n and crs == cloud.crs and got_params == params
    assert np.array_equal(np.sort(tree.src), np.arange(cloud.n))  # every record once
    assert len(tree.starts) == res.nodes and tree.level.max() + 1 == res.levels
    sizes = np.diff(np.r_[tree.starts, len(tree.src)])
    assert np.bincount(tree.level, weights=sizes).astype(int).tolist() == list(res.points_per_level)
    assert set(gps.tolist()) <= set(cloud.attrs["gps_time"].tolist())


def test_save_copc_is_atomic_and_other_writers_refuse_copc_names(tmp_path):
    cloud = _cloud(500)
    out = tmp_path / "s.copc.laz"
    save_copc(cloud, out)
    with pytest.raises(Exception, match="exists"):
        save_copc(cloud, out)
    save_copc(cloud, out, overwrite=True)
    assert io_copc.is_copc(out) and sorted(p.name for p in tmp_path.iterdir()) == ["s.copc.laz"]
    with pytest.raises(InvalidInputError, match="cannot write COPC"):
        write_cloud(cloud, tmp_path / "plain.copc.laz")
    with pytest.raises(InvalidInputError, match="point format"):
        write_copc(cloud, tmp_path / "x.copc.laz", point_format=3)


def test_ws_convert_writes_copc_that_ws_info_reports(tmp_path, capsys):
    from workstation.cli.main import main

    cloud = _cloud(3000, seed=2, rgb=False)
    src = tmp_path / "in.laz"
    write_cloud(cloud, src)
    out = tmp_path / "out.copc.laz"
    assert main(["convert", str(src), str(out), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["point_count"] == 3000 and doc["copc"]["point_format"] == 6 and doc["crs"] == "EPSG:32632"
    assert main(["info", str(out), "--summary", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["format"] == "copc" and s["copc"]["points"] == 3000 and s["point_count"] == 3000
    ply = tmp_path / "in.ply"  # a non-LAS input goes through the whole-cloud path
    write_cloud(cloud, ply)
    assert main(["convert", str(ply), str(tmp_path / "p.copc.laz"), "--crs", "EPSG:32632"]) == 0
    assert read_cloud(tmp_path / "p.copc.laz").n == 3000
    assert main(["convert", str(src), str(tmp_path / "q.copc.laz"), "--point-format", "3"]) == 2


def test_mixed_axis_scales_keep_points_inside_their_nodes(tmp_path):
    copclib = pytest.importorskip("copclib")
    cloud = _cloud(4000, seed=4)
    path = tmp_path / "m.copc.laz"
    write_copc(cloud, path, CopcParams(max_points=300, cells=8), scales=[0.01, 0.01, 0.001])
    info = io_copc.read_info(path)
    side, corner = 2 * info.halfsize, np.asarray(info.center) - info.halfsize
    reader = copclib.FileReader(str(path))
    assert len(reader.GetAllNodes()) > 8
    for n in reader.GetAllNodes():
        pts = reader.GetPoints(n)
        xyz = np.column_stack([pts.x, pts.y, pts.z])
        lo = corner + np.array([n.key.x, n.key.y, n.key.z]) * side / 2**n.key.d
        assert np.all((xyz > lo) & (xyz < lo + side / 2**n.key.d))  # strictly: no point on a node plane
    box = ((X0 + 30.005, Y0 + 20.005, 0.0), (X0 + 95.005, Y0 + 70.005, 200.0))
    x = np.round(cloud.xyz[:, :2], 2)  # the stored coordinates at 1 cm
    inside = np.all((x >= box[0][:2]) & (x <= box[1][:2]), axis=1)
    assert len(_query(path, bounds=box)) == inside.sum() > 0


@pytest.mark.realdata
@pytest.mark.slow
@pytest.mark.parametrize("name", ["lidarhd_extra_bytes.laz", "autzen_trim.las"])
def test_real_files_convert_to_copc_with_every_point_and_attribute(shared_data, tmp_path, name):
    from workstation.cli.main import main

    src = shared_data / "lidar" / name
    out = tmp_path / "r.copc.laz"
    assert main(["convert", str(src), str(out)]) == 0
    from pyproj import CRS

    a, b = read_cloud(src), read_cloud(out)
    assert b.n == a.n and CRS(b.crs) == CRS(a.crs) and io_copc.summary(out)["points"] == a.n  # WKT names normalised
    ka, kb = (np.lexsort((c.xyz[:, 2], c.xyz[:, 1], c.xyz[:, 0], c.attrs["gps_time"])) for c in (a, b))
    np.testing.assert_allclose(b.xyz[kb], a.xyz[ka], rtol=0, atol=1e-6)
    for attr, values in a.attrs.items():
        if attr == "scan_angle":  # LAS 1.4 stores 0.006 degree steps (PDRF 3 -> 7 for autzen)
            np.testing.assert_allclose(b.attrs[attr][kb], values[ka], rtol=0, atol=0.003 + 1e-6)
        else:
            np.testing.assert_array_equal(b.attrs[attr][kb], values[ka], err_msg=attr)
    with laspy.CopcReader.open(str(out)) as r:
        assert len(r.query(level=0)) == io_copc.summary(out)["points_per_level"][0]
