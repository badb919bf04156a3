"""Planning a project run without running it: the catalog from headers, the chunk grid and its
buffers, and the per-chunk bins of plain LAZ files."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from pipeline_synth import CRS, TILE, X0, Y0, write_project, write_tiles

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.io import read_cloud, write_cloud
from workstation.io.catalog import Catalog, TileInfo, build_catalog
from workstation.pipeline.chunkio import index_file, read_bins
from workstation.pipeline.chunks import Chunk, chunk_grid
from workstation.pipeline.manifest import Manifest

pytestmark = pytest.mark.timeout(60)


def box_tile(path, x0, y0, x1, y1, crs=CRS, n=300, seed=0):
    """A small LAZ tile whose header bounds are exactly (x0, y0, x1, y1): its corners are points."""
    rng = np.random.default_rng(seed)
    xy = np.vstack([[[x0, y0], [x1, y1], [x0, y1], [x1, y0]],
                    np.column_stack([rng.uniform(x0, x1, n), rng.uniform(y0, y1, n)])])
    xyz = np.round(np.column_stack([xy, rng.uniform(100, 110, len(xy))]), 2)
    m = len(xyz)
    write_cloud(Cloud(xyz, {"classification": np.ones(m, np.uint8), "intensity": np.arange(m, dtype=np.uint16)},
                      crs=crs), path, overwrite=True)
    return path


@pytest.fixture(scope="module")
def survey(tmp_path_factory):
    """The 2 x 2 tiles of the run tests (40,500 points each)."""
    folder = tmp_path_factory.mktemp("survey")
    return write_tiles(folder / "tiles")


# ----------------------------------------------------------------------------- catalog
def test_catalog_counts_bounds_and_crs_from_headers(survey):
    cat = build_catalog(survey)
    clouds = [read_cloud(p) for p in survey]
    assert len(cat.tiles) == 4
    assert cat.point_count == sum(c.n for c in clouds) == 4 * 40_500
    allxyz = np.vstack([c.xyz for c in clouds])
    assert cat.bounds == pytest.approx((*allxyz[:, :2].min(axis=0), *allxyz[:, :2].max(axis=0)), abs=1e-6)
    assert cat.bounds == pytest.approx((X0, Y0, X0 + 2 * TILE, Y0 + 2 * TILE), abs=0.02)
    for t, c in zip(cat.tiles, clouds):
        assert t.point_count == c.n and t.point_format == c.meta["las"]["point_format"] and not t.copc
        assert t.bounds == pytest.approx((*c.xyz.min(axis=0), *c.xyz.max(axis=0)), abs=1e-6)
    assert cat.crs == CRS
    # adjacent tiles only share edges: no overlap, no gap
    assert cat.overlaps() == []
    assert cat.gap_area() < 0.01 * TILE * TILE
    s = cat.summary()
    assert s["files"] == 4 and s["points"] == cat.point_count and s["crs"] == CRS and s["overlaps"] == []


def test_catalog_reads_no_point(survey, monkeypatch):
    import laspy

    import workstation.io.las as las

    def boom(*a, **k):
        raise AssertionError("a point was read while planning")

    for name in ("read", "iter_chunks", "raw_records"):
        monkeypatch.setattr(las, name, boom)
    for name in ("read", "read_points", "chunk_iterator"):
        monkeypatch.setattr(laspy.LasReader, name, boom)
    cat = build_catalog(survey)
    assert cat.point_count == 4 * 40_500 and len(cat.tiles) == 4


def test_catalog_overlaps_and_gaps(tmp_path):
    s = 100.0
    a = box_tile(tmp_path / "a.laz", 0, 0, s, s)
    b = box_tile(tmp_path / "b.laz", s, 0, 2 * s, s)
    c = box_tile(tmp_path / "c.laz", 0, s, s, 2 * s)
    # 2 x 2 grid with the north-east tile missing: a gap of one tile
    cat = build_catalog([a, b, c])
    assert cat.bounds == (0.0, 0.0, 2 * s, 2 * s)
    assert cat.overlaps() == []
    assert cat.gap_area() == pytest.approx(s * s, rel=0.02)
    # a tile shifted half a tile over its neighbour: overlaps a (50 x 40 m) and b (50 x 40 m)
    d = box_tile(tmp_path / "d.laz", 50, 60, 150, 140)
    cat = build_catalog([a, b, c, d])
    ov = {(x, y): area for x, y, area in cat.overlaps()}
    assert set(ov) == {("a.laz", "d.laz"), ("b.laz", "d.laz"), ("c.laz", "d.laz")}
    assert ov[("a.laz", "d.laz")] == pytest.approx(50 * 40)
    assert ov[("b.laz", "d.laz")] == pytest.approx(50 * 40)
    assert ov[("c.laz", "d.laz")] == pytest.approx(50 * 40)
    # d covers part of the missing north-east quarter (50 x 40 m of it)
    assert cat.gap_area() == pytest.approx(s * s - 50 * 40, rel=0.02)


def test_catalog_refuses_two_crs_naming_the_file(tmp_path):
    a = box_tile(tmp_path / "a.laz", 500000, 4000000, 500100, 4000100, crs="EPSG:32633")
    b = box_tile(tmp_path / "b.laz", 500100, 4000000, 500200, 4000100, crs="EPSG:32633")
    c = box_tile(tmp_path / "zone34.laz", 500200, 4000000, 500300, 4000100, crs="EPSG:32634")
    with pytest.raises(InvalidInputError) as e:
        build_catalog([a, b, c])
    assert "zone34.laz" in str(e.value) and e.value.path == str(c)
    assert "32634" in e.value.message and "32633" in e.value.message
    # the project's CRS is the reference: a tile in another one is refused, naming it
    with pytest.raises(InvalidInputError) as e:
        build_catalog([a, b], crs="EPSG:32634")
    assert "a.laz" in str(e.value)
    # tiles without a CRS take the project's
    n = box_tile(tmp_path / "nocrs.laz", 500300, 4000000, 500400, 4000100, crs=None)
    assert build_catalog([n], crs="EPSG:32633").crs == "EPSG:32633"
    assert build_catalog([a, n]).crs == "EPSG:32633"


# ----------------------------------------------------------------------------- chunks
def test_chunk_grid_alignment_ownership_and_buffers(survey):
    cat = build_catalog(survey)
    grid = chunk_grid(cat, 100.0, 30.0)
    assert grid.size == 100.0 and grid.buffer == 30.0
    # the survey spans x 500020-500200, y 4000020-4000200: chunks 5000-5001 x 40000-40001
    assert {(c.ix, c.iy) for c in grid.chunks} == {(5000, 40000), (5000, 40001), (5001, 40000), (5001, 40001)}
    assert list(grid.chunks) == sorted(grid.chunks)
    for c in grid.chunks:
        x0, y0, x1, y1 = c.bounds
        assert x0 % 100.0 == 0 and y0 % 100.0 == 0 and x1 - x0 == 100.0 and y1 - y0 == 100.0
        assert c.buffered == (x0 - 30, y0 - 30, x1 + 30, y1 + 30)
        assert c.name == f"{x0:.0f}_{y0:.0f}"
        assert len(c.neighbours()) == 9 and c in c.neighbours()
    xy = np.vstack([read_cloud(p).xyz[:, :2] for p in survey])
    # points exactly on chunk edges belong to the chunk to their north/east (half-open cores)
    edges = np.array([[500100.0, 4000050.0], [500050.0, 4000100.0], [500100.0, 4000100.0], [500020.0, 4000020.0]])
    xy = np.vstack([xy, edges])
    owners = np.zeros(len(xy), int)
    for c in grid.chunks:
        m = c.core_mask(xy)
        owners += m
        x0, y0, x1, y1 = c.bounds
        inside = xy[m]
        assert np.all((inside[:, 0] >= x0) & (inside[:, 0] < x1) & (inside[:, 1] >= y0) & (inside[:, 1] < y1))
    assert np.all(owners == 1), "every point is owned by exactly one chunk"
    ix, iy = grid.chunk_ids(edges)
    assert ix.tolist() == [5001, 5000, 5001, 5000] and iy.tolist() == [40000, 40001, 40001, 40000]
    assert set(grid.by_index()) == {(c.ix, c.iy) for c in grid.chunks}


def test_chunk_grid_converts_metres_to_feet(tmp_path):
    ft = 0.3048
    size_ft = 100.0 / ft
    # a 700 x 400 ft tile in Oregon Lambert (international feet)
    t = box_tile(tmp_path / "feet.laz", 1_000_100.0, 500_050.0, 1_000_800.0, 500_450.0, crs="EPSG:2994")
    cat = build_catalog([t])
    assert cat.crs is not None and "2994" in cat.crs
    grid = chunk_grid(cat, 100.0, 30.0)
    assert grid.size == pytest.approx(size_ft) and grid.buffer == pytest.approx(30.0 / ft)
    xs = range(math.floor(1_000_100.0 / size_ft), math.floor(1_000_800.0 / size_ft) + 1)
    ys = range(math.floor(500_050.0 / size_ft), math.floor(500_450.0 / size_ft) + 1)
    assert {(c.ix, c.iy) for c in grid.chunks} == {(i, j) for i in xs for j in ys}
    c = grid.chunks[0]
    assert c.bounds[2] - c.bounds[0] == pytest.approx(328.0839895)
    assert c.buffered[0] == pytest.approx(c.bounds[0] - 98.4251969)
    # the same catalog built by hand (no file) gives the same grid
    hand = Catalog((TileInfo(t, cat.tiles[0].bounds, 10, 6, "EPSG:2994", False),), "EPSG:2994")
    assert chunk_grid(hand, 100.0, 30.0) == grid
    # and a metric CRS is left alone
    assert chunk_grid(Catalog(hand.tiles, CRS), 100.0, 30.0).size == 100.0


# ----------------------------------------------------------------------------- bins
def test_index_bins_give_the_points_of_a_full_read(survey, tmp_path):
    path = survey[0]  # t_0_0: x 500020-500110, y 4000020-4000110: four chunks
    full = read_cloud(path)
    dest = tmp_path / "cache" / "idx"
    counts = index_file(path, 100.0, dest, CRS, chunk_points=7_000)  # several pieces per bin
    assert sum(counts.values()) == full.n
    ix = np.floor(full.xyz[:, 0] / 100.0).astype(int)
    iy = np.floor(full.xyz[:, 1] / 100.0).astype(int)
    expect = {f"{a}_{b}": int(np.sum((ix == a) & (iy == b))) for a, b in set(zip(ix.tolist(), iy.tolist()))}
    assert counts == expect and len(counts) == 4
    assert json.loads((dest / "counts.json").read_text()) == counts
    # the folder was renamed into place: nothing else is left beside it
    assert [p.name for p in dest.parent.iterdir()] == ["idx"]

    def sort(c):
        o = np.lexsort((c.xyz[:, 2], c.xyz[:, 1], c.xyz[:, 0]))
        return c.xyz[o], {k: np.asarray(v)[o] for k, v in c.attrs.items()}

    chunk = Chunk(5001, 40000, 100.0, 30.0)
    names = [f"{c.ix}_{c.iy}" for c in chunk.neighbours()]
    for box in (chunk.buffered, chunk.bounds, (500060.0, 4000030.0, 500105.5, 4000101.25)):
        got = read_bins(dest, names, box)
        keep = ((full.xyz[:, 0] >= box[0]) & (full.xyz[:, 0] < box[2]) & (full.xyz[:, 1] >= box[1])
                & (full.xyz[:, 1] < box[3]))
        assert got is not None and got.n == int(keep.sum()) > 0
        gx, ga = sort(got)
        fx, fa = sort(full[keep])
        np.testing.assert_array_equal(gx, fx)
        assert set(ga) == set(fa)
        for k in fa:
            assert ga[k].dtype == fa[k].dtype, k
            np.testing.assert_array_equal(ga[k], fa[k], err_msg=k)
        assert got.crs == full.crs
        assert got.meta["las"]["point_format"] == full.meta["las"]["point_format"]
        assert got.meta["las"]["scales"] == full.meta["las"]["scales"]
    # a box no point of the file is in
    assert read_bins(dest, names, (0.0, 0.0, 10.0, 10.0)) is None
    # indexing again replaces the folder with the same bins
    before = {p.name: p.read_bytes() for p in dest.iterdir()}
    assert index_file(path, 100.0, dest, CRS) == counts
    assert {p.name: p.read_bytes() for p in dest.iterdir()} == before


def test_manifest_survives_unreadable_run_json(tmp_path):
    p = tmp_path / "run.json"
    for junk in (b"\x89PNG\r\n\x1a\n" + bytes(range(256)), b'{"format": 1, "tasks": {"a": ', b"[1, 2]", b"null"):
        p.write_bytes(junk)
        m = Manifest(p)
        assert m.tasks == {} and m.files == {}
        assert not m.is_done("points/0_0", "k")


# ----------------------------------------------------------------------------- what re-runs
def test_plan_reruns_a_lost_chunk_and_only_the_rasters_that_read_it(tmp_path):
    from workstation.pipeline.plan import forced_phases
    from workstation.pipeline.runner import RunOptions, _todo, prepare

    (tmp_path / "tiles").mkdir()
    for i in range(3):
        for j in range(3):  # 3 x 3 tiles inside 3 x 3 chunks of 100 m
            x, y = 500000 + 100 * i, 4000000 + 100 * j
            box_tile(tmp_path / "tiles" / f"t{i}{j}.laz", x + 1, y + 1, x + 99, y + 99, n=50, seed=3 * i + j)
    write_project(tmp_path)
    _, plan, _, grid, _, manifest, tasks = prepare(tmp_path / "project.toml", RunOptions(out=tmp_path / "out"))
    assert len(grid.chunks) == 9
    by_id = {t.id: t for t in tasks}
    assert {t.phase for t in tasks} == {"index", "points", "rasters", "mosaic"} and len(tasks) == 9 + 9 + 9 + 2
    present = tmp_path / "present"
    present.write_text("x")
    for t in tasks:
        manifest.record(t.id, {"key": t.key, "status": "done", "outputs": [str(present)]})
    assert _todo(tasks, manifest, set()) == []

    def near(c, others):
        return {o.name for o in others if abs(o.ix - c.ix) <= 1 and abs(o.iy - c.iy) <= 1}

    corner, centre = grid.chunks[0], grid.chunks[4]
    assert (corner.ix, corner.iy) == (5000, 40000) and (centre.ix, centre.iy) == (5001, 40001)
    # a corner chunk's LAZ is gone: that chunk, the four raster tasks whose buffer reads it, the mosaics
    manifest.tasks[f"points/{corner.name}"]["outputs"] = [str(tmp_path / "gone.laz")]
    todo = {t.id for t in _todo(tasks, manifest, set())}
    assert todo == ({f"points/{corner.name}"} | {f"rasters/{n}" for n in near(corner, grid.chunks)}
                    | {"mosaic/dtm", "mosaic/dsm"})
    assert len(todo) == 1 + 4 + 2
    # the centre chunk is read by every raster task
    manifest.tasks[f"points/{corner.name}"]["outputs"] = [str(present)]
    manifest.tasks[f"points/{centre.name}"]["status"] = "failed"
    assert {t.id for t in _todo(tasks, manifest, set())} == ({f"points/{centre.name}"}
                                                            | {f"rasters/{c.name}" for c in grid.chunks}
                                                            | {"mosaic/dtm", "mosaic/dsm"})
    manifest.tasks[f"points/{centre.name}"]["status"] = "done"
    # a changed tile (its index key differs): the chunks whose buffer reaches it, then their readers
    manifest.tasks["index/t00.laz"]["key"] = "old"
    todo = [t for t in _todo(tasks, manifest, set())]
    assert {t.id for t in todo if t.phase == "index"} == {"index/t00.laz"}
    assert {t.chunk for t in todo if t.phase == "points"} == near(corner, grid.chunks)
    assert all("index/t00.laz" in by_id[f"points/{n}"].deps for n in near(corner, grid.chunks))
    manifest.tasks["index/t00.laz"]["key"] = by_id["index/t00.laz"].key
    # --rerun-from dem: every raster task and the mosaics, no point task
    forced = {t.id for t in _todo(tasks, manifest, forced_phases(plan, "dem"))}
    assert forced == {t.id for t in tasks if t.phase in ("rasters", "mosaic")}
    assert {t.id for t in _todo(tasks, manifest, forced_phases(plan, "ground"))} == {
        t.id for t in tasks if t.phase != "index"}


@pytest.mark.slow
@pytest.mark.timeout(300)
def test_a_large_file_is_indexed_in_parts_with_the_same_result(tmp_path, monkeypatch):
    """A file of more than INDEX_PART_POINTS points is binned by several index tasks (each
    seeks to its own point range); the chunks read back the same points as with one task."""
    from pipeline_synth import write_project, write_tiles

    from workstation.io import read_cloud
    from workstation.pipeline import tasks as T
    from workstation.pipeline.runner import RunOptions, run_project

    write_tiles(tmp_path / "tiles", cells=((0, 0), (1, 0)))
    write_project(tmp_path)
    one = run_project(tmp_path / "project.toml", RunOptions(out=tmp_path / "one", workers=1))
    monkeypatch.setattr(T, "INDEX_PART_POINTS", 15_000)  # 40,500-point tiles: 3 parts each
    three = run_project(tmp_path / "project.toml", RunOptions(out=tmp_path / "three", workers=2))
    assert one.complete and three.complete
    assert one.summary["phases"]["index"]["total"] == 2 and three.summary["phases"]["index"]["total"] == 6
    names = sorted(p.name for p in (tmp_path / "one" / "ground").glob("*.laz"))
    assert names == sorted(p.name for p in (tmp_path / "three" / "ground").glob("*.laz"))
    for n in names:
        a, b = read_cloud(tmp_path / "one" / "ground" / n), read_cloud(tmp_path / "three" / "ground" / n)
        np.testing.assert_array_equal(a.xyz, b.xyz)
        np.testing.assert_array_equal(a.attrs["classification"], b.attrs["classification"])
