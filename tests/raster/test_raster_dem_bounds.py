"""``ws dem --bounds`` / ``--level`` and ``ws render --bounds``: the grid covers the box, only the
points inside are read (a LAS/LAZ file filtered chunk by chunk, a COPC file queried), and the DEM
equals the whole DEM cut to the box cell for cell."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import write_cloud
from workstation.io.geotiff import read_raster
from workstation.raster.dem import DemParams, build_dem

X0, Y0 = 480_000.0, 5_450_000.0
BOX = (X0 + 20, Y0 + 10, X0 + 60, Y0 + 50)  # on whole metres: the 1 m grid is the box exactly


@pytest.fixture(scope="module")
def tilted(tmp_path_factory):
    """30,000 points over 100 x 80 m: half ground on a tilted plane, half up to 10 m above it."""
    rng = np.random.default_rng(1)
    n = 30_000
    x, y = rng.uniform(0, 100, n) + X0, rng.uniform(0, 80, n) + Y0
    cls = np.where(rng.random(n) < 0.5, 2, 1).astype(np.uint8)
    z = 100 + 0.05 * (x - X0) + 0.02 * (y - Y0) + rng.normal(0, 0.05, n) + np.where(cls == 1, rng.uniform(0, 10, n), 0)
    c = Cloud(np.column_stack([x, y, z]), {"classification": cls, "return_number": np.ones(n, np.uint8)},
              crs="EPSG:32632")
    path = tmp_path_factory.mktemp("dem_bounds") / "in.laz"
    write_cloud(c, path)
    return path


def _dem(tmp_path, src, kind, *extra):
    out = tmp_path / f"{kind}{len(extra)}.tif"
    argv = ["dem", str(src), "-o", str(out), "--kind", kind, "--resolution", "1", "--chunk-size", "4000",
            "--json", *extra]
    assert main(argv) == 0
    return read_raster(out)


def _cut(whole, part):
    """The cells of ``whole`` that ``part`` covers (same cell size, aligned grids)."""
    res = whole.transform[0]
    c0 = round((part.transform[2] - whole.transform[2]) / res)
    r0 = round((whole.transform[5] - part.transform[5]) / res)
    assert c0 >= 0 and r0 >= 0
    return whole.array[r0 : r0 + part.array.shape[0], c0 : c0 + part.array.shape[1]]


def test_dsm_bounds_equals_whole_dsm_cut_to_the_box(tmp_path, tilted, capsys):
    whole = _dem(tmp_path, tilted, "dsm")
    part = _dem(tmp_path, tilted, "dsm", "--bounds", ",".join(map(str, BOX)))
    # the grid is the box: 40 x 40 one-metre cells from its north-west corner
    assert part.array.shape == (40, 40)
    assert part.transform == (1.0, 0.0, BOX[0], 0.0, -1.0, BOX[3])
    cut = _cut(whole, part)
    # every cell holding points has the same highest point; an empty cell is filled from its
    # neighbours, which near the edge lie beyond the box in the whole DSM only
    from workstation.io import read_cloud

    xy = read_cloud(tilted).xyz[:, :2]
    held, _, _ = np.histogram2d(BOX[3] - xy[:, 1], xy[:, 0] - BOX[0], bins=40, range=[[0, 40], [0, 40]])
    assert (held == 0).any() and (held > 0).sum() > 1500
    np.testing.assert_array_equal(part.array[held > 0], cut[held > 0])
    np.testing.assert_array_equal(part.array[2:-2, 2:-2], cut[2:-2, 2:-2])


def test_dtm_bounds_equals_whole_dtm_away_from_the_edge(tmp_path, tilted):
    whole = _dem(tmp_path, tilted, "dtm")
    part = _dem(tmp_path, tilted, "dtm", "--bounds", ",".join(map(str, BOX)))
    cut = _cut(whole, part)
    assert np.isfinite(part.array[1:-1, 1:-1]).all()
    # a TIN cell depends on its neighbours (and voids on their rims): near the edge the whole DTM
    # sees points beyond the box, two cells in it does not
    np.testing.assert_array_equal(part.array[2:-2, 2:-2], cut[2:-2, 2:-2])
    assert np.nanmax(np.abs(part.array - cut)) < 0.2


def test_points_read_are_those_inside_the_box(tmp_path, tilted, capsys):
    from workstation.io import read_cloud

    c = read_cloud(tilted)
    x, y = c.xyz[:, 0], c.xyz[:, 1]
    inside = int(((x >= BOX[0]) & (x <= BOX[2]) & (y >= BOX[1]) & (y <= BOX[3])).sum())
    capsys.readouterr()
    _dem(tmp_path, tilted, "dsm", "--bounds", ",".join(map(str, BOX)))
    doc = json.loads(capsys.readouterr().out)
    assert doc["points"] == inside < c.n
    assert doc["read"]["bounds"] == list(BOX)


def test_tiled_and_cloud_sources_honour_the_box(tilted):
    """The out-of-core path and an in-memory cloud read the same points as the streamed one."""
    from workstation.io import read_cloud

    p = DemParams(kind="dsm", resolution=1.0)
    opts = {"bounds": BOX}
    one = build_dem(tilted, p, chunk_size=5000, read_opts=opts, tile_cells=0)
    tiled = build_dem(tilted, p, chunk_size=5000, read_opts=opts, tile_cells=16, buffer_cells=4)
    mem = build_dem(read_cloud(tilted), p, read_opts=opts)
    assert one.meta["points"] == mem.meta["points"]  # (tiles count their overlaps too)
    np.testing.assert_array_equal(one.array, tiled.array)
    np.testing.assert_array_equal(one.array, mem.array)


def test_box_without_points_is_an_input_error(tmp_path, tilted, capsys):
    out = tmp_path / "none.tif"
    rc = main(["dem", str(tilted), "-o", str(out), "--kind", "dsm", "--resolution", "1",
               "--bounds", f"{X0 - 500},{Y0 - 500},{X0 - 400},{Y0 - 400}"])
    assert rc == 1 and not out.exists()
    assert "--bounds" in capsys.readouterr().err


@pytest.fixture(scope="module")
def copc_file(tmp_path_factory):
    pytest.importorskip("copclib")
    from copc_synth import write_copc
    from pyproj import CRS

    rng = np.random.default_rng(3)
    n = 20_000
    xyz = np.column_stack([rng.uniform(X0, X0 + 100, n), rng.uniform(Y0, Y0 + 80, n), rng.uniform(100, 110, n)])
    path = tmp_path_factory.mktemp("copc") / "t.copc.laz"
    write_copc(path, xyz, classification=rng.choice([1, 2], n).astype(np.uint8),
               wkt=CRS.from_epsg(32632).to_wkt(), max_levels=4)
    return path


def _copc_count(path, bounds=None, level=None) -> int:
    import laspy
    from laspy.copc import Bounds

    box = None if bounds is None else Bounds(mins=np.asarray(bounds[:2], float), maxs=np.asarray(bounds[2:4], float))
    with laspy.CopcReader.open(str(path)) as r:
        return len(r.query(bounds=box, level=None if level is None else range(0, level + 1)))


@pytest.mark.parametrize("extra, level", [(["--bounds", ",".join(map(str, BOX))], None),
                                          (["--bounds", ",".join(map(str, BOX)), "--level", "1"], 1),
                                          (["--level", "0"], 0)])
def test_copc_dem_reads_only_the_queried_points(tmp_path, copc_file, capsys, extra, level):
    capsys.readouterr()
    _dem(tmp_path, copc_file, "dsm", *extra)
    doc = json.loads(capsys.readouterr().out)
    want = _copc_count(copc_file, BOX if "--bounds" in extra else None, level)
    assert doc["points"] == want < 20_000


def test_copc_level_is_refused_on_plain_files(tmp_path, tilted, capsys):
    rc = main(["dem", str(tilted), "-o", str(tmp_path / "x.tif"), "--resolution", "1", "--level", "1"])
    assert rc != 0 and not (tmp_path / "x.tif").exists()
    assert "COPC" in capsys.readouterr().err


def test_render_bounds_draws_only_the_points_inside(tmp_path, tilted, monkeypatch):
    import workstation.render as wr

    seen = []
    real = wr.render

    def spy(obj, params, **kw):
        seen.append(obj)
        return real(obj, params, **kw)

    monkeypatch.setattr(wr, "render", spy)
    out = tmp_path / "r.png"
    assert main(["render", str(tilted), "-o", str(out), "--view", "top", "--size", "64x48",
                 "--bounds", ",".join(map(str, BOX))]) == 0
    assert out.exists() and len(seen) == 1
    lo, hi = seen[0].xyz.min(0), seen[0].xyz.max(0)
    assert lo[0] >= BOX[0] and lo[1] >= BOX[1] and hi[0] <= BOX[2] and hi[1] <= BOX[3]
    assert seen[0].n > 1000


def test_render_bounds_refused_on_a_mesh(tmp_path, capsys):
    from workstation.render.load import load_product

    ply = tmp_path / "m.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    from workstation.core.errors import InvalidInputError

    with pytest.raises(InvalidInputError, match="mesh"):
        load_product(ply, bounds=(0, 0, 1, 1))
    assert load_product(ply).faces.shape == (1, 3)
