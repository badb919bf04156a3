"""The PDAL pipeline equivalent to a run of ``ws convert``, ``crop``, ``filter``, ``thin``, ``tile``
or ``merge`` (``--pipeline-out FILE.json``), so a PDAL user can check or replay what was done.

A pipeline is a JSON list of stages (https://pdal.io/en/stable/pipeline.html): readers, then
filters, then a writer, each ``{"type": "<kind>.<name>", option: value, ...}``. Only the stage
names and options documented by PDAL are emitted (see ``STAGE_OPTIONS``); option values are
strings or numbers as in PDAL's own examples. The writer carries the exact scales and offsets
this run wrote (PDAL's ``writers.las`` would otherwise default to 0.01 and 0).
"""

from __future__ import annotations

import json
from pathlib import Path

from workstation.io import atomic_path

# stage -> options this module may emit, each as documented at https://pdal.io/en/stable/stages/<stage>.html
STAGE_OPTIONS: dict[str, set[str]] = {
    "readers.las": {"filename", "override_srs"},
    "readers.ply": {"filename", "override_srs"},
    "readers.pcd": {"filename", "override_srs"},
    "readers.text": {"filename", "override_srs"},
    "readers.e57": {"filename", "override_srs"},
    "filters.crop": {"bounds", "polygon", "outside", "a_srs"},
    "filters.expression": {"expression"},
    "filters.reprojection": {"in_srs", "out_srs"},
    "filters.voxeldownsize": {"cell", "mode"},
    "filters.voxelcentroidnearestneighbor": {"cell"},
    "filters.voxelcenternearestneighbor": {"cell"},
    "filters.sort": {"dimension", "order"},
    "filters.sample": {"radius"},
    "filters.splitter": {"length", "origin_x", "origin_y", "buffer"},
    "filters.merge": set(),
    "writers.las": {"filename", "minor_version", "dataformat_id", "a_srs", "compression", "extra_dims",
                    "scale_x", "scale_y", "scale_z", "offset_x", "offset_y", "offset_z"},
    "writers.ply": {"filename"},
    "writers.pcd": {"filename"},
    "writers.text": {"filename"},
    "writers.e57": {"filename"},
}

_KINDS = {"las": "las", "laz": "las", "ply": "ply", "pcd": "pcd", "xyz": "text", "txt": "text", "csv": "text",
          "pts": "text", "e57": "e57"}


def _kind(path) -> str:
    from workstation.io import format_of

    return _KINDS[format_of(path)[0]]


def reader(path, crs: str | None = None) -> dict:
    """The reader stage of ``path`` (``override_srs`` when a CRS is assigned, as ``--crs`` does)."""
    stage = {"type": f"readers.{_kind(path)}", "filename": str(path)}
    if crs:
        stage["override_srs"] = crs
    return stage


def las_layout(path) -> dict:
    """Point format, version, scales, offsets and CRS of a written LAS/LAZ file (its header)."""
    from workstation.io.las import read_header

    h = read_header(path)
    return {"point_format": h["point_format"], "version": h["version"], "scales": h["scales"],
            "offsets": h["offsets"], "crs": h["crs"]}


def writer(path, layout: dict | None = None, filename: str | None = None) -> dict:
    """The writer stage of ``path``; for LAS/LAZ with the written header's layout (see :func:`las_layout`)."""
    kind = _kind(path)
    stage = {"type": f"writers.{kind}", "filename": filename or str(path)}
    if kind == "las" and layout:
        stage["minor_version"] = int(str(layout["version"]).split(".")[1])
        stage["dataformat_id"] = int(layout["point_format"])
        for axis, s, o in zip("xyz", layout["scales"], layout["offsets"]):
            stage[f"scale_{axis}"] = float(s)
            stage[f"offset_{axis}"] = float(o)
        if layout.get("crs"):
            stage["a_srs"] = layout["crs"]
        stage["extra_dims"] = "all"
    if kind == "las" and Path(filename or path).suffix.lower() == ".laz":
        stage["compression"] = "true"
    return stage


def crop_stage(bounds=None, polygons=None, invert: bool = False) -> dict:
    """``filters.crop`` with PDAL's bounds text ``([xmin, xmax], [ymin, ymax][, [zmin, zmax]])`` or a WKT polygon."""
    stage: dict = {"type": "filters.crop"}
    if bounds is not None:
        b = [float(v) for v in bounds]
        parts = [f"[{b[0]}, {b[2]}]", f"[{b[1]}, {b[3]}]"] + ([f"[{b[4]}, {b[5]}]"] if len(b) == 6 else [])
        stage["bounds"] = "(" + ", ".join(parts) + ")"
    else:
        stage["polygon"] = polygons.to_wkt()
        if polygons.crs:
            stage["a_srs"] = polygons.crs
    if invert:
        stage["outside"] = True
    return stage


def thin_stages(voxel: float | None = None, keep: str = "first", poisson: float | None = None) -> list[dict]:
    """The PDAL stages of ``ws thin``: voxel rules map to PDAL's voxel filters (lowest/highest as
    a sort on Z then the first point of each voxel), Poisson to ``filters.sample``."""
    if poisson is not None:
        return [{"type": "filters.sample", "radius": float(poisson)}]
    if keep == "centroid":
        return [{"type": "filters.voxelcentroidnearestneighbor", "cell": float(voxel)}]
    if keep == "center":
        return [{"type": "filters.voxelcenternearestneighbor", "cell": float(voxel)}]
    stages = []
    if keep in ("lowest", "highest"):
        stages.append({"type": "filters.sort", "dimension": "Z", "order": "ASC" if keep == "lowest" else "DESC"})
    return stages + [{"type": "filters.voxeldownsize", "cell": float(voxel), "mode": "first"}]


def write_pipeline(stages: list[dict], path, overwrite: bool = False, inputs=()) -> Path:
    """Write the pipeline JSON (a list of stages) atomically."""
    with atomic_path(path, overwrite, inputs) as tmp:
        tmp.write_text(json.dumps(stages, indent=2) + "\n")
    return Path(path)
