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
    # https://pdal.io/en/stable/stages/writers.las.html
    "writers.las": {"filename", "forward", "minor_version", "software_id", "creation_doy", "creation_year",
                    "dataformat_id", "system_id", "a_srs", "global_encoding", "project_id", "compression",
                    "scale_x", "scale_y", "scale_z", "offset_x", "offset_y", "offset_z", "filesource_id",
                    "discard_high_return_numbers", "extra_dims", "pdal_metadata", "vlrs"},
    # https://pdal.io/en/stable/stages/writers.ply.html, writers.text.html
    "writers.ply": {"filename", "storage_mode", "dims", "faces", "sized_types", "precision"},
    "writers.text": {"filename", "format", "order", "keep_unspecified", "jscode", "quote_header", "write_header",
                     "newline", "delimiter", "precision"},
}
ENUMS = {("filters.voxeldownsize", "mode"): {"center", "first"}, ("filters.sort", "order"): {"ASC", "DESC"}}


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
