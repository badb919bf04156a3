"""--pipeline-out: every emitted stage and option is one PDAL documents.

The table below was written from PDAL's stage documentation, one page per stage:
https://pdal.io/en/stable/stages/<stage>.html (source: github.com/PDAL/PDAL doc/stages/<stage>.md).
Options common to every reader ("override_srs", doc/stages/reader_opts.md) are listed with
each reader.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import write_cloud

DOCUMENTED = {
    # https://pdal.io/en/stable/stages/readers.las.html (+ reader_opts.md: override_srs, default_srs, count)
    "readers.las": {"filename", "override_srs", "default_srs", "count", "extra_dims", "nosrs"},
    # https://pdal.io/en/stable/stages/readers.ply.html, readers.pcd.html, readers.text.html
    "readers.ply": {"filename", "override_srs", "default_srs", "count"},
    "readers.pcd": {"filename", "override_srs", "default_srs", "count"},
    "readers.text": {"filename", "override_srs", "default_srs", "count", "header", "separator", "skip"},
    # https://pdal.io/en/stable/stages/filters.crop.html
    "filters.crop": {"bounds", "polygon", "outside", "point", "distance", "a_srs", "ogr"},
    # https://pdal.io/en/stable/stages/filters.expression.html
    "filters.expression": {"expression"},
    # https://pdal.io/en/stable/stages/filters.reprojection.html
    "filters.reprojection": {"in_srs", "out_srs", "in_axis_ordering", "out_axis_ordering", "error_on_failure"},
    # https://pdal.io/en/stable/stages/filters.voxeldownsize.html (mode: center | first)
    "filters.voxeldownsize": {"cell", "mode"},
    # https://pdal.io/en/stable/stages/filters.voxelcentroidnearestneighbor.html
    "filters.voxelcentroidnearestneighbor": {"cell"},
    # https://pdal.io/en/stable/stages/filters.voxelcenternearestneighbor.html
    "filters.voxelcenternearestneighbor": {"cell"},
    # https://pdal.io/en/stable/stages/filters.sort.html (order: ASC | DESC)
    "filters.sort": {"dimension", "order"},
    # https://pdal.io/en/stable/stages/filters.sample.html
    "filters.sample": {"radius", "cell", "origin_x", "origin_y", "origin_z", "dimension"},
    # https://pdal.io/en/stable/stages/filters.splitter.html
    "filters.splitter": {"length", "origin_x", "origin_y", "buffer"},
    # https://pdal.io/en/stable/stages/filters.merge.html
    "filters.merge": set(),
    # https://pdal.io/en/stable/stages/filters.elm.html, filters.smrf.html, filters.pmf.html, filters.csf.html
    "filters.elm": {"cell", "class", "threshold", "where", "where_merge"},
    "filters.smrf": {"cell", "classbits", "cut", "dir", "ignore", "returns", "scalar", "slope", "threshold", "window",
                     "where", "where_merge"},
    "filters.pmf": {"cell_size", "exponential", "ignore", "initial_distance", "max_distance", "max_window_size",
                    "returns", "slope", "where", "where_merge"},
    "filters.csf": {"resolution", "ignore", "returns", "threshold", "hdiff", "smooth", "step", "rigidness",
                    "iterations", "where", "where_merge"},
    # https://pdal.io/en/stable/stages/writers.las.html
    # https://pdal.io/en/stable/stages/writers.copc.html
    "writers.copc": {"filename", "forward", "vlrs", "a_srs", "pipeline", "scale_x", "scale_y", "scale_z", "offset_x",
                     "offset_y", "offset_z", "extra_dims", "threads", "fixed_seed"},
    "writers.las": {"filename", "forward", "minor_version", "software_id", "creation_doy", "creation_year",
                    "dataformat_id", "system_id", "a_srs", "global_encoding", "project_id", "compression",
                    "scale_x", "scale_y", "scale_z", "offset_x", "offset_y", "offset_z", "filesource_id",
                    "discard_high_return_numbers", "extra_dims", "pdal_metadata", "vlrs"},
    # https://pdal.io/en/stable/stages/writers.ply.html, writers.text.html
    # https://pdal.io/en/stable/stages/readers.copc.html (+ reader_opts.md)
    "readers.copc": {"filename", "override_srs", "default_srs", "count", "bounds", "polygon", "ogr", "requests",
                     "resolution", "header", "query", "vlr", "keep_alive", "fix_dims", "srs_vlr_order", "nosrs"},
    # https://pdal.io/en/stable/stages/filters.range.html, filters.assign.html (+ filter_opts.md: where)
    "filters.range": {"limits", "where", "where_merge"},
    "filters.assign": {"assignment", "condition", "value", "where", "where_merge"},
    # https://pdal.io/en/stable/stages/filters.hag_delaunay.html, filters.delaunay.html
    "filters.hag_delaunay": {"count", "allow_extrapolation", "where", "where_merge"},
    "filters.delaunay": {"where", "where_merge"},
    # https://pdal.io/en/stable/stages/filters.faceraster.html
    "filters.faceraster": {"resolution", "nodata", "mesh", "origin_x", "origin_y", "width", "height",
                           "max_triangle_edge_length", "where", "where_merge"},
    # https://pdal.io/en/stable/stages/writers.gdal.html (bounds or origin_x/origin_y/width/height, not both)
    "writers.gdal": {"filename", "binmode", "resolution", "radius", "power", "gdaldriver", "gdalopts", "data_type",
                     "nodata", "output_type", "window_size", "dimension", "bounds", "origin_x", "origin_y", "width",
                     "height", "override_srs", "default_srs", "metadata", "pdal_metadata"},
    # https://pdal.io/en/stable/stages/writers.raster.html
    "writers.raster": {"filename", "gdaldriver", "gdalopts", "rasters", "data_type", "nodata"},
    "writers.ply": {"filename", "storage_mode", "dims", "faces", "sized_types", "precision"},
    "writers.text": {"filename", "format", "order", "keep_unspecified", "jscode", "quote_header", "write_header",
                     "newline", "delimiter", "precision"},
}
ENUMS = {("filters.voxeldownsize", "mode"): {"center", "first"}, ("filters.sort", "order"): {"ASC", "DESC"},
         ("writers.gdal", "output_type"): {"min", "max", "mean", "idw", "count", "stdev", "all"},
         ("writers.gdal", "binmode"): {"true", "false"}}


def _check(stages):
    assert isinstance(stages, list) and stages
    assert stages[0]["type"].startswith("readers.") and stages[-1]["type"].startswith("writers.")
    for s in stages:
        assert s["type"] in DOCUMENTED, s["type"]
        assert set(s) - {"type"} <= DOCUMENTED[s["type"]], (s["type"], set(s) - DOCUMENTED[s["type"]])
        for (kind, opt), allowed in ENUMS.items():
            if s["type"] == kind and opt in s:
                assert s[opt] in allowed
    return [s["type"] for s in stages]


def test_module_table_is_documented():
    from workstation.ops.pdal import STAGE_OPTIONS

    for stage, opts in STAGE_OPTIONS.items():
        if stage in ("readers.e57", "writers.pcd", "writers.e57"):
            continue  # formats without a stage page checked here
        assert opts <= DOCUMENTED[stage], stage


@pytest.fixture
def src(tmp_path):
    rng = np.random.default_rng(4)
    c = Cloud(np.round(rng.uniform(0, 50, (2000, 3)) + [480000, 5450000, 0], 2),
              {"classification": rng.integers(1, 7, 2000), "return_number": np.ones(2000)}, crs="EPSG:32632")
    write_cloud(c, tmp_path / "in.laz")
    return tmp_path / "in.laz"


@pytest.mark.parametrize("args, types", [
    (["convert", "{src}", "{out}", "--to-crs", "EPSG:4326"], ["readers.las", "filters.reprojection", "writers.las"]),
    (["convert", "{src}", "{tmp}/o.ply", "--crs", "EPSG:32632"], ["readers.las", "writers.ply"]),
    (["crop", "{src}", "-o", "{out}", "--bounds", "480010,5450010,480030,5450030,0,20"],
     ["readers.las", "filters.crop", "writers.las"]),
    (["filter", "{src}", "-o", "{out}", "--expr", "Classification == 2 && ReturnNumber == 1"],
     ["readers.las", "filters.expression", "writers.las"]),
    (["thin", "{src}", "-o", "{out}", "--voxel", "1", "--keep", "centroid"],
     ["readers.las", "filters.voxelcentroidnearestneighbor", "writers.las"]),
    (["thin", "{src}", "-o", "{out}", "--voxel", "1", "--keep", "center"],
     ["readers.las", "filters.voxelcenternearestneighbor", "writers.las"]),
    (["thin", "{src}", "-o", "{out}", "--poisson", "2"], ["readers.las", "filters.sample", "writers.las"]),
    (["tile", "{src}", "-o", "{tmp}/tiles", "--size", "25", "--buffer", "1"], ["readers.las", "filters.splitter", "writers.las"]),
    (["merge", "{src}", "{src}", "-o", "{out}"], ["readers.las", "readers.las", "filters.merge", "writers.las"]),
])
def test_pipelines_use_documented_stages(tmp_path, src, args, types):
    fill = {"src": str(src), "out": str(tmp_path / "o.laz"), "tmp": str(tmp_path)}
    argv = [a.format(**fill) for a in args] + ["--pipeline-out", str(tmp_path / "p.json")]
    assert main(argv) == 0
    stages = json.loads((tmp_path / "p.json").read_text())
    assert _check(stages) == types
    w = stages[-1]
    if w["type"] == "writers.las" and "#" not in w["filename"]:
        from workstation.io.las import read_header

        h = read_header(tmp_path / "o.laz")  # the writer stage carries the layout really written
        assert [w["scale_x"], w["scale_y"], w["scale_z"]] == h["scales"]
        assert [w["offset_x"], w["offset_y"], w["offset_z"]] == h["offsets"]
        assert w["compression"] == "true" and w["dataformat_id"] == h["point_format"]


def test_pipeline_out_is_checked_before_work(tmp_path, src, capsys):
    (tmp_path / "p.json").write_text("{}")
    assert main(["filter", str(src), "-o", str(tmp_path / "o.laz"), "--expr", "Z > 0",
                 "--pipeline-out", str(tmp_path / "p.json")]) == 1
    assert not (tmp_path / "o.laz").exists()


# --------------------------------------------------------------------------- ws dem
def _range_keeps(limits: str, dim: str, values) -> np.ndarray:
    """Which ``values`` of ``dim`` pass PDAL ``filters.range`` limits (closed ``[a:b]`` ranges of
    one dimension ORed, as documented)."""
    import re

    keep = np.zeros(len(values), bool)
    for name, a, b in re.findall(r"(\w+)\[(\d*):(\d*)\]", limits):
        if name == dim:
            keep |= (values >= (float(a) if a else -np.inf)) & (values <= (float(b) if b else np.inf))
    return keep


def _grid_of(stage, raster):
    """The writer/faceraster grid equals the raster written (origin = lower-left corner, CRS units)."""
    a, _, c, _, e, f = raster.transform
    rows, cols = raster.array.shape
    assert stage["resolution"] == a and stage["origin_x"] == c and stage["origin_y"] == f + e * rows
    assert (stage["width"], stage["height"]) == (cols, rows)
    assert "bounds" not in stage  # PDAL: bounds or origin/width/height, not both


@pytest.mark.parametrize("args, types", [
    (["--kind", "dsm"], ["readers.las", "filters.range", "writers.gdal"]),
    (["--kind", "dsm", "--method", "tin"],
     ["readers.las", "filters.range", "filters.delaunay", "filters.faceraster", "writers.raster"]),
    (["--kind", "dtm", "--max-edge", "5"],
     ["readers.las", "filters.range", "filters.delaunay", "filters.faceraster", "writers.raster"]),
    (["--kind", "dtm", "--method", "idw"], ["readers.las", "filters.range", "writers.gdal"]),
    (["--kind", "chm", "--ground-classes", "2,9"],
     ["readers.las", "filters.assign", "filters.hag_delaunay", "filters.range", "writers.gdal"]),
    (["--kind", "dsm", "--bounds", "480010,5450010,480030,5450030"],
     ["readers.las", "filters.crop", "filters.range", "writers.gdal"]),
])
def test_dem_pipeline(tmp_path, src, args, types):
    from workstation.core.classes import NOISE
    from workstation.io.geotiff import read_raster

    out = tmp_path / "d.tif"
    assert main(["dem", str(src), "-o", str(out), "--resolution", "1", *args, "--pipeline-out", str(tmp_path / "p.json")]) == 0
    stages = json.loads((tmp_path / "p.json").read_text())
    assert _check(stages) == types
    r = read_raster(out)
    last = stages[-1]
    assert last["filename"] == str(out) and last["nodata"] == -9999.0 and last["data_type"] == "float"
    _grid_of(stages[-2] if last["type"] == "writers.raster" else last, r)
    codes = np.arange(256)
    keep = _range_keeps(next(s for s in stages if s["type"] == "filters.range")["limits"], "Classification", codes)
    if "dtm" in args:
        assert list(codes[keep]) == [2]
        face = [s for s in stages if s["type"] == "filters.faceraster"]
        assert not face or face[0]["max_triangle_edge_length"] == 5.0
        if "idw" in args:
            assert last["output_type"] == "idw" and last["power"] == 2.0
    else:  # every class but the noise classes (7 and 18)
        assert list(codes[~keep]) == sorted(int(c) for c in NOISE)
        assert last["type"] != "writers.gdal" or last["output_type"] == "max"
    if "chm" in args:
        assert last["dimension"] == "HeightAboveGround"
        assert stages[1]["value"] == ["Classification = 2 WHERE Classification == 9"]
    if "--bounds" in args:
        assert stages[1]["bounds"] == "([480010.0, 480030.0], [5450010.0, 5450030.0])"


def test_dem_pipeline_feet_resolution_in_crs_units(tmp_path):
    """--resolution is metres; the pipeline, like the raster, is in the CRS's unit (US feet)."""
    rng = np.random.default_rng(5)
    xyz = rng.uniform(0, 300, (3000, 3)) + [2_000_000, 600_000, 0]
    c = Cloud(xyz, {"classification": np.full(3000, 2, np.uint8)}, crs="EPSG:2994")
    write_cloud(c, tmp_path / "ft.laz")
    assert main(["dem", str(tmp_path / "ft.laz"), "-o", str(tmp_path / "d.tif"), "--kind", "dsm", "--resolution", "3",
                 "--pipeline-out", str(tmp_path / "p.json")]) == 0
    w = json.loads((tmp_path / "p.json").read_text())[-1]
    assert w["resolution"] == pytest.approx(3 / 0.3048)


def test_dem_pipeline_two_inputs_merged(tmp_path, src):
    assert main(["dem", str(src), str(src), "-o", str(tmp_path / "d.tif"), "--kind", "dsm", "--resolution", "2",
                 "--pipeline-out", str(tmp_path / "p.json")]) == 0
    stages = json.loads((tmp_path / "p.json").read_text())
    assert _check(stages)[:3] == ["readers.las", "readers.las", "filters.merge"]


@pytest.mark.parametrize("args", [["--kind", "dtm", "--method", "nn"], ["--kind", "chm", "--pit-free"]])
def test_dem_pipeline_refused_without_a_pdal_equivalent(tmp_path, src, args, capsys):
    out = tmp_path / "d.tif"
    rc = main(["dem", str(src), "-o", str(out), "--resolution", "1", *args, "--pipeline-out", str(tmp_path / "p.json")])
    assert rc == 2 and not out.exists() and not (tmp_path / "p.json").exists()
    assert "PDAL" in capsys.readouterr().err


def test_dem_pipeline_copc_query(tmp_path):
    """A COPC input is queried by readers.copc: bounds as PDAL text, --level as that level's resolution."""
    pytest.importorskip("copclib")
    from copc_synth import write_copc

    from workstation.io import copc

    rng = np.random.default_rng(2)
    xyz = rng.uniform(0, 60, (5000, 3)) + [480000, 5450000, 0]
    path = tmp_path / "c.copc.laz"
    write_copc(path, xyz, max_levels=4)
    assert main(["dem", str(path), "-o", str(tmp_path / "d.tif"), "--kind", "dsm", "--resolution", "2",
                 "--bounds", "480010,5450010,480040,5450040", "--level", "2",
                 "--pipeline-out", str(tmp_path / "p.json")]) == 0
    stages = json.loads((tmp_path / "p.json").read_text())
    assert _check(stages) == ["readers.copc", "filters.range", "writers.gdal"]
    r = stages[0]
    assert r["bounds"] == "([480010.0, 480040.0], [5450010.0, 5450040.0])"
    assert r["resolution"] == pytest.approx(copc.read_info(path).spacing / 4)
    assert copc.level_range(r["resolution"], None, copc.read_info(path).spacing) == range(0, 3)



@pytest.mark.parametrize("method,flt", [("smrf", "filters.smrf"), ("pmf", "filters.pmf"), ("csf", "filters.csf")])
def test_ground_pipeline_carries_the_filter_and_its_parameters(tmp_path, src, method, flt):
    out, pj = tmp_path / "g.laz", tmp_path / "p.json"
    assert main(["ground", str(src), "-o", str(out), "--method", method, "--pipeline-out", str(pj)]) == 0
    stages = json.loads(pj.read_text())
    assert _check(stages) == ["readers.las", "filters.elm", flt, "writers.las"]
    f = stages[2]
    assert f["returns"] == "last,only" and f["ignore"] == "Classification[7:7]"
    assert stages[1]["class"] == 7 and stages[1]["threshold"] == 1.0
    if method == "smrf":
        assert (f["slope"], f["window"], f["threshold"], f["scalar"]) == (0.15, 18.0, 0.5, 1.25)


def test_ground_pipeline_in_feet_and_without_the_noise_step(tmp_path):
    """Lengths are metres on the command line and CRS units (US feet) in the pipeline."""
    rng = np.random.default_rng(6)
    xyz = rng.uniform(0, 300, (3000, 3)) + [2_000_000, 600_000, 0]
    write_cloud(Cloud(xyz, crs="EPSG:2994"), tmp_path / "ft.laz")
    pj = tmp_path / "p.json"
    assert main(["ground", str(tmp_path / "ft.laz"), "-o", str(tmp_path / "g.laz"), "--window", "30",
                 "--no-noise-step", "--all-returns", "--pipeline-out", str(pj)]) == 0
    stages = json.loads(pj.read_text())
    assert _check(stages) == ["readers.las", "filters.smrf", "writers.las"]
    assert stages[1]["window"] == pytest.approx(30 / 0.3048) and "returns" not in stages[1]


@pytest.mark.parametrize("method", ["ptd", "auto"])
def test_ground_pipeline_refused_without_a_pdal_filter(tmp_path, src, method, capsys):
    out = tmp_path / "g.laz"
    rc = main(["ground", str(src), "-o", str(out), "--method", method, "--pipeline-out", str(tmp_path / "p.json")])
    assert rc == 2 and not out.exists() and not (tmp_path / "p.json").exists()
    assert "PDAL" in capsys.readouterr().err
