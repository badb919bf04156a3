"""The reading options --bounds / --resolution / --level on the commands that read point files
besides one cloud (filter, thin, crop, tile, merge, register, strip-adjust, qc, evaluate,
publish): each must use exactly the points laspy's CopcReader returns for the selection."""

from __future__ import annotations

import json

import numpy as np
import pytest

pytest.importorskip("copclib")
from copc_synth import write_copc  # noqa: E402

from workstation.cli.main import main  # noqa: E402

X0, Y0 = 500_000.0, 4_000_000.0
BOX = (X0 + 10, Y0 + 5, X0 + 60, Y0 + 40)
BOX_TEXT = ",".join(map(str, BOX))


@pytest.fixture(scope="module")
def copc_file(tmp_path_factory):
    """8000 points over 100 m x 80 m in 4 octree levels, half ground (class 2), half class 1."""
    from pyproj import CRS

    rng = np.random.default_rng(5)
    n = 8000
    xyz = np.column_stack([rng.uniform(X0, X0 + 100, n), rng.uniform(Y0, Y0 + 80, n), rng.uniform(10, 20, n)])
    cls = np.where(rng.random(n) < 0.5, 2, 1).astype(np.uint8)
    path = tmp_path_factory.mktemp("copc") / "a.copc.laz"
    write_copc(path, xyz, classification=cls, intensity=rng.integers(0, 4000, n).astype(np.uint16),
               wkt=CRS.from_epsg(32632).to_wkt(), max_levels=4)
    return path


def level_count(path, level: int = 1) -> int:
    import laspy

    with laspy.CopcReader.open(str(path)) as rd:
        return len(rd.query(level=range(0, level + 1)))


def bounds_count(path, box=BOX) -> int:
    import laspy
    from laspy.copc import Bounds

    with laspy.CopcReader.open(str(path)) as rd:
        return len(rd.query(bounds=Bounds(mins=np.array(box[:2]), maxs=np.array(box[2:]))))


def points_of(path) -> int:
    import laspy

    with laspy.open(str(path)) as f:
        return int(f.header.point_count)


def ws(capsys, *args):
    """(exit code, stdout, stderr) of ``ws args``."""
    capsys.readouterr()
    rc = main([str(a) for a in args])
    out = capsys.readouterr()
    return rc, out.out, out.err


def test_filter_level_and_bounds(copc_file, tmp_path, capsys):
    rc, out, err = ws(capsys, "filter", copc_file, "-o", tmp_path / "l.laz", "--expr", "Z > 0", "--level", 1, "--json")
    assert rc == 0, err
    assert json.loads(out)["points_out"] == points_of(tmp_path / "l.laz") == level_count(copc_file)
    rc, out, err = ws(capsys, "filter", copc_file, "-o", tmp_path / "b.laz", "--expr", "Z > 0", "--bounds", BOX_TEXT,
                      "--pipeline-out", tmp_path / "b.json", "--json")
    assert rc == 0, err
    assert json.loads(out)["points_in"] == points_of(tmp_path / "b.laz") == bounds_count(copc_file)
    reader = json.loads((tmp_path / "b.json").read_text())[0]
    assert reader["type"] == "readers.copc" and "bounds" in reader


def test_filter_streams_plain_las_with_bounds_and_refuses_level(copc_file, tmp_path, capsys):
    import laspy

    plain = tmp_path / "p.laz"
    assert ws(capsys, "convert", copc_file, plain)[0] == 0
    las = laspy.read(str(plain))
    inside = (las.x >= BOX[0]) & (las.x <= BOX[2]) & (las.y >= BOX[1]) & (las.y <= BOX[3])
    rc, out, err = ws(capsys, "filter", plain, "-o", tmp_path / "f.las", "--expr", "Classification == 2",
                      "--bounds", BOX_TEXT, "--json")
    assert rc == 0, err
    assert json.loads(out)["points_out"] == points_of(tmp_path / "f.las") == int((inside & (las.classification == 2)).sum())
    rc, _, err = ws(capsys, "filter", plain, "-o", tmp_path / "g.las", "--expr", "Z > 0", "--level", 1)
    assert rc == 1 and "not COPC" in err and not (tmp_path / "g.las").exists()
    rc, _, err = ws(capsys, "filter", plain, "-o", tmp_path / "h.las", "--expr", "Z > 0", "--bounds", "0,0,1,1")
    assert rc == 1 and "no points inside --bounds" in err


def test_thin_level(copc_file, tmp_path, capsys):
    rc, out, err = ws(capsys, "thin", copc_file, "-o", tmp_path / "t.laz", "--voxel", 0.001, "--level", 1, "--json")
    assert rc == 0, err
    doc = json.loads(out)
    assert doc["points_in"] == doc["points_out"] == level_count(copc_file)


def test_crop_level_with_its_own_bounds(copc_file, tmp_path, capsys):
    big = f"{X0 - 1},{Y0 - 1},{X0 + 200},{Y0 + 200}"
    rc, out, err = ws(capsys, "crop", copc_file, "-o", tmp_path / "c.laz", "--bounds", big, "--level", 1, "--json")
    assert rc == 0, err
    assert json.loads(out)["points_out"] == points_of(tmp_path / "c.laz") == level_count(copc_file)
    rc, out, _ = ws(capsys, "crop", "--help")
    assert rc == 0 and "--level" in out and "--resolution" in out and out.count("--bounds") == 1  # its own only


def test_tile_bounds(copc_file, tmp_path, capsys):
    rc, out, err = ws(capsys, "tile", copc_file, "-o", tmp_path / "tiles", "--size", 50, "--bounds", BOX_TEXT, "--json")
    assert rc == 0, err
    counts = json.loads(out)["tiles"]
    assert sum(counts.values()) == bounds_count(copc_file)
    assert sum(points_of(p) for p in (tmp_path / "tiles").iterdir()) == bounds_count(copc_file)


def test_merge_applies_the_selection_to_each_input(copc_file, tmp_path, capsys):
    import shutil

    other = tmp_path / "b.copc.laz"
    shutil.copyfile(copc_file, other)
    rc, out, err = ws(capsys, "merge", copc_file, other, "-o", tmp_path / "m.laz", "--level", 1, "--json")
    assert rc == 0, err
    assert json.loads(out)["points_per_input"] == [level_count(copc_file)] * 2
    rc, out, err = ws(capsys, "merge", copc_file, other, "-o", tmp_path / "v.laz", "--voxel-size", 0.001,
                      "--bounds", BOX_TEXT, "--json")
    assert rc == 0, err
    assert json.loads(out)["points"] == bounds_count(copc_file)  # the copy's points fall in the same voxels


def test_register_reads_the_selection_of_both(copc_file, tmp_path, capsys):
    init = tmp_path / "eye.txt"
    np.savetxt(init, np.eye(4))
    rc, out, err = ws(capsys, "register", copc_file, copc_file, "-o", tmp_path / "r.laz", "--method", "icp",
                      "--init", init, "--level", 1, "--json")
    assert rc == 0, err
    assert points_of(tmp_path / "r.laz") == level_count(copc_file)
    assert json.loads(out)["fitness"] == pytest.approx(1.0)


def test_strip_adjust_bounds(tmp_path, capsys):
    from adjust.synth import calibration_lines, fly, plates

    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud

    xyz, attrs, _ = fly(calibration_lines(120.0), plates(np.random.default_rng(1), n=40),
                        line_shift={2: (0.1, -0.05, 0.08)})
    las = tmp_path / "in" / "lines.las"
    las.parent.mkdir()
    write_cloud(Cloud(xyz, attrs, crs="EPSG:32632"), las)
    src = tmp_path / "in" / "lines.copc.laz"
    assert ws(capsys, "convert", las, src)[0] == 0
    lo, hi = xyz.min(0), xyz.max(0)
    box = (lo[0] + 10, lo[1] + 10, hi[0] - 10, hi[1] - 10)
    rc, out, err = ws(capsys, "strip-adjust", src, "-o", tmp_path / "adj", "--bounds", ",".join(map(str, box)), "--json")
    assert rc == 0, err
    assert points_of(tmp_path / "adj" / "lines.laz") == bounds_count(src, box) < len(xyz)


def test_qc_level(copc_file, tmp_path, capsys):
    rc, out, err = ws(capsys, "qc", copc_file, "-o", tmp_path / "qc", "--level", 1, "--json")
    assert rc == 0, err
    assert json.loads(out)["points"] == level_count(copc_file)
    rc, out, err = ws(capsys, "qc", copc_file, "-o", tmp_path / "qcb", "--bounds", BOX_TEXT, "--json")
    assert rc == 0, err
    assert json.loads(out)["points"] == bounds_count(copc_file)


def test_evaluate_bounds_on_both(copc_file, capsys):
    rc, out, err = ws(capsys, "evaluate", copc_file, "--reference", copc_file, "--bounds", BOX_TEXT, "--json")
    assert rc == 0, err
    doc = json.loads(out)
    assert sum(doc["counts"].values()) == bounds_count(copc_file) and doc["total_error"] == 0


def test_publish_level(copc_file, tmp_path, capsys):
    rc, out, err = ws(capsys, "publish", copc_file, "-o", tmp_path / "site", "--level", 1, "--json")
    assert rc == 0, err
    assert json.loads(out)["points"] == level_count(copc_file)
    rc, _, err = ws(capsys, "publish", copc_file, "-o", tmp_path / "s2", "--level", 1, "--3d-tiles")
    assert rc == 2 and "--3d-tiles" in err
