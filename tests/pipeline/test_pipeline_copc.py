"""COPC inputs: a chunk is read by a spatial query of the octree, and a project mixes COPC and
plain LAZ tiles. The COPC file is written with copc-lib (a test dependency): laspy reads COPC
but does not write it."""

from __future__ import annotations

import numpy as np
import pytest
from pipeline_synth import CRS, tile_cloud, write_tiles

copc = pytest.importorskip("copclib")


def write_copc(cloud, path) -> None:
    """``cloud`` as a two-level COPC file: every 10th point in the root node, the others in the
    eight children of the octree's cube, as PDRF 6 records with the cloud's class and intensity."""
    import laspy
    from pyproj import CRS as PCRS

    x, y, z = cloud.xyz.T
    lo, hi = cloud.xyz.min(0), cloud.xyz.max(0)
    las = laspy.LasData(laspy.LasHeader(point_format=6, version="1.4"))
    las.header.offsets, las.header.scales = np.floor(lo), [0.001] * 3
    las.x, las.y, las.z = x, y, z
    las.classification = cloud.attrs["classification"]
    las.intensity = cloud.attrs["intensity"]
    las.return_number = np.ones(len(x), np.uint8)
    las.number_of_returns = np.ones(len(x), np.uint8)
    rec = las.points.array
    cfg = copc.CopcConfigWriter(6, copc.Vector3(0.001, 0.001, 0.001), copc.Vector3(*np.floor(lo)),
                                PCRS.from_user_input(CRS).to_wkt())
    cfg.las_header.min, cfg.las_header.max = copc.Vector3(*lo), copc.Vector3(*hi)
    centre, half = (lo + hi) / 2, float((hi - lo).max() / 2) + 0.01
    info = cfg.copc_info
    info.center_x, info.center_y, info.center_z = centre
    info.halfsize, info.spacing = half, half / 8
    w = copc.FileWriter(str(path), cfg)
    root = np.arange(len(x)) % 10 == 0
    w.AddNode(copc.VoxelKey(0, 0, 0, 0), copc.VectorChar(np.frombuffer(rec[root].tobytes(), np.int8)))
    octant = np.clip(np.floor((cloud.xyz - (centre - half)) / half).astype(int), 0, 1)
    for a, b, c in np.ndindex(2, 2, 2):
        m = ~root & (octant[:, 0] == a) & (octant[:, 1] == b) & (octant[:, 2] == c)
        if m.any():
            w.AddNode(copc.VoxelKey(1, a, b, c), copc.VectorChar(np.frombuffer(rec[m].tobytes(), np.int8)))
    w.Close()


def test_copc_query_equals_a_full_read_inside_the_box(tmp_path):
    from workstation.io import read_cloud
    from workstation.io.catalog import read_tile_info
    from workstation.pipeline.chunkio import read_copc

    cloud = tile_cloud(0, 0)
    write_copc(cloud, tmp_path / "t.copc.laz")
    assert read_tile_info(tmp_path / "t.copc.laz").copc
    full = read_cloud(tmp_path / "t.copc.laz")
    lo = full.xyz.min(0)
    box = (lo[0] + 20.0, lo[1] + 35.0, lo[0] + 61.5, lo[1] + 70.0)  # crosses the octants' planes
    got = read_copc(tmp_path / "t.copc.laz", box)
    inside = ((full.xyz[:, 0] >= box[0]) & (full.xyz[:, 0] < box[2]) & (full.xyz[:, 1] >= box[1])
              & (full.xyz[:, 1] < box[3]))
    assert 0 < got.n == int(inside.sum()) < full.n
    key = lambda c: np.lexsort(c.xyz.T[::-1])  # noqa: E731 - the same order for both
    a, b = got[key(got)], full[inside][key(full[inside])]
    np.testing.assert_array_equal(a.xyz, b.xyz)
    for name in ("classification", "intensity"):
        np.testing.assert_array_equal(a.attrs[name], b.attrs[name])
    assert read_copc(tmp_path / "t.copc.laz", (lo[0] - 500, lo[1] - 500, lo[0] - 400, lo[1] - 400)) is None


@pytest.mark.slow
@pytest.mark.timeout(300)
def test_project_with_a_copc_tile_among_laz_tiles(tmp_path):
    from workstation.core.cloud import concatenate
    from workstation.io import read_cloud
    from workstation.pipeline.runner import RunOptions, run_project

    write_tiles(tmp_path / "tiles", cells=((0, 0), (1, 0), (1, 1)))
    write_copc(tile_cloud(0, 1), tmp_path / "tiles" / "t_0_1.copc.laz")
    (tmp_path / "project.toml").write_text('[inputs]\nclouds = ["tiles/*.laz"]\n[chunks]\nsize = 100.0\nbuffer = 30.0\n'
                                           '[stages.ground]\nmethod = "smrf"\n[stages.dem]\nkinds = ["dtm"]\n')
    res = run_project(tmp_path / "project.toml", RunOptions(workers=1))
    assert res.complete and res.summary["catalog"]["copc_files"] == 1
    assert res.summary["phases"]["index"]["total"] == 3  # the COPC tile needs no bins
    out = concatenate([read_cloud(p) for p in sorted((tmp_path / "ground").glob("*.laz"))])
    copc_tile = tile_cloud(0, 1)
    assert out.n == sum(tile_cloud(ix, iy).n for ix, iy in ((0, 0), (1, 0), (1, 1))) + copc_tile.n
    # every point of the COPC tile is written once, with its intensity
    mine = np.isin(np.round(out.xyz[:, 0] * 1000).astype(np.int64) * 10**9 + np.round(out.xyz[:, 1] * 1000).astype(np.int64),
                   np.round(copc_tile.xyz[:, 0] * 1000).astype(np.int64) * 10**9
                   + np.round(copc_tile.xyz[:, 1] * 1000).astype(np.int64))
    assert mine.sum() == copc_tile.n
    assert np.array_equal(np.sort(out.attrs["intensity"][mine]), np.sort(copc_tile.attrs["intensity"]))
    assert (tmp_path / "dem" / "dtm.tif").exists()
