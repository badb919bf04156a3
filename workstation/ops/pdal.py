"""The PDAL pipeline equivalent to a run of ``ws convert``, ``crop``, ``filter``, ``thin``, ``tile``,
``merge``, ``dem`` or ``ground`` (``--pipeline-out FILE.json``), so a PDAL user can check or replay what was done.

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
    "readers.copc": {"filename", "override_srs", "bounds", "resolution"},
    "filters.range": {"limits"},
    "filters.assign": {"value"},
    "filters.hag_delaunay": set(),
    "filters.delaunay": set(),
    "filters.faceraster": {"resolution", "origin_x", "origin_y", "width", "height", "max_triangle_edge_length"},
    "writers.gdal": {"filename", "resolution", "output_type", "dimension", "binmode", "power", "data_type",
                     "nodata", "gdaldriver", "gdalopts", "origin_x", "origin_y", "width", "height"},
    "writers.raster": {"filename", "data_type", "nodata", "gdaldriver", "gdalopts"},
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
    "filters.elm": {"cell", "class", "threshold"},
    "filters.smrf": {"cell", "slope", "window", "threshold", "scalar", "returns", "ignore"},
    "filters.pmf": {"cell_size", "slope", "max_window_size", "initial_distance", "max_distance", "exponential",
                    "returns", "ignore"},
    "filters.csf": {"resolution", "rigidness", "threshold", "iterations", "smooth", "step", "returns", "ignore"},
    "writers.las": {"filename", "minor_version", "dataformat_id", "a_srs", "compression", "extra_dims",
                    "scale_x", "scale_y", "scale_z", "offset_x", "offset_y", "offset_z"},
    "writers.copc": {"filename", "a_srs", "extra_dims", "scale_x", "scale_y", "scale_z", "offset_x", "offset_y",
                     "offset_z"},
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


def _bounds_text(bounds) -> str:
    """PDAL's bounds text ``([xmin, xmax], [ymin, ymax][, [zmin, zmax]])``."""
    return crop_stage(bounds)["bounds"]


def _copc_reader(path, read_opts: dict) -> dict:
    """``readers.copc`` with the query of ``read_opts``: ``bounds``, and ``resolution`` (CRS
    units); a ``level`` L becomes the resolution of that level (root spacing / 2**L), which
    selects the same levels 0..L."""
    from workstation.io import copc

    stage = {"type": "readers.copc", "filename": str(path)}
    if read_opts.get("bounds") is not None:
        stage["bounds"] = _bounds_text(read_opts["bounds"])
    res = read_opts.get("resolution")
    if read_opts.get("level") is not None:
        res = copc.read_info(path).spacing / 2.0 ** int(read_opts["level"])
    if res is not None:
        stage["resolution"] = float(res)
    return stage


def read_stages(inputs, read_opts: dict | None = None) -> list[dict]:
    """Readers of ``inputs`` (merged when several) that read what ``read_opts`` selects
    (``--bounds``/``--resolution``/``--level``): a COPC file is queried by ``readers.copc``,
    other files are read whole and cropped (``filters.crop``)."""
    from workstation.io import copc

    opts = {k: v for k, v in (read_opts or {}).items() if v is not None}
    stages = [_copc_reader(p, opts) if opts and copc.is_copc(p) else reader(p) for p in inputs]
    plain = any(s["type"] != "readers.copc" for s in stages)
    if len(stages) > 1:
        stages.append({"type": "filters.merge"})
    if plain and opts.get("bounds") is not None:
        stages.append(crop_stage(opts["bounds"]))
    return stages


def class_limits(codes) -> str:
    """``filters.range`` limits keeping the classification codes ``codes`` (ranges of one
    dimension are ORed by PDAL)."""
    return ",".join(f"Classification[{int(c)}:{int(c)}]" for c in sorted(set(codes)))


def not_class_limits(codes) -> str:
    """``filters.range`` limits keeping every code 0..255 except ``codes`` (as the ORed ranges
    between them: PDAL ORs ranges of one dimension, so negated ranges cannot be combined)."""
    out, start = [], 0
    for c in sorted(set(int(c) for c in codes)):
        if c > start:
            out.append(f"Classification[{start}:{c - 1}]")
        start = c + 1
    if start <= 255:
        out.append(f"Classification[{start}:255]")
    return ",".join(out)


def _raster_grid(raster) -> dict:
    """The grid ``raster`` covers as PDAL's ``resolution`` (CRS units), ``origin_x``/``origin_y``
    (lower-left corner) and ``width``/``height`` (cells)."""
    a, _, c, _, e, f = raster.transform
    rows, cols = raster.array.shape[-2:]
    return {"resolution": float(a), "origin_x": float(c), "origin_y": float(f + e * rows),
            "width": int(cols), "height": int(rows)}


def _ground_as_class2(classes) -> list[dict]:
    """``filters.assign`` making ``classes`` the class 2 that ``filters.hag_delaunay`` takes as
    ground (nothing when the ground is class 2 alone; a class 2 not listed becomes 1)."""
    classes = sorted(set(int(c) for c in classes))
    if classes == [2]:
        return []
    value = [] if 2 in classes else ["Classification = 1 WHERE Classification == 2"]
    return [{"type": "filters.assign", "value": value + [f"Classification = 2 WHERE Classification == {c}"
                                                        for c in classes if c != 2]}]


#: GeoTIFF layout of ``ws dem`` outputs (float32, nodata -9999, tiled, DEFLATE).
_GTIFF = {"data_type": "float", "nodata": -9999.0, "gdaldriver": "GTiff", "gdalopts": "TILED=YES,COMPRESS=DEFLATE"}


def dem_stages(inputs, output, raster, read_opts: dict | None = None) -> list[dict]:
    """The PDAL pipeline of a ``ws dem`` run that wrote ``raster`` (its ``meta``: kind, method,
    params) to ``output``, on the exact grid written (resolution in CRS units).

    * DSM ``highest``: noise classes (7, 18) left out, ``writers.gdal`` ``output_type=max`` with
      ``binmode`` (points inside each cell only); ``tin``: first returns, ``filters.delaunay``
      then ``filters.faceraster`` and ``writers.raster``.
    * DTM ``tin``: the ground classes (``filters.range``), a Delaunay TIN rasterised by
      ``filters.faceraster`` (``max_triangle_edge_length`` = ``--max-edge`` in CRS units);
      ``idw``: ``writers.gdal`` ``output_type=idw`` with the same power (PDAL weights the points
      within its radius, ws the k nearest cell representatives).
    * CHM: ground classes as class 2 (``filters.assign``), ``filters.hag_delaunay``, noise left
      out, the highest ``HeightAboveGround`` per cell (``writers.gdal``).

    Natural neighbour (``nn``) and the pit-free CHM have no PDAL stage: see :func:`dem_equivalent`.
    """
    from workstation.core.classes import NOISE

    meta = raster.meta
    kind, method, p = meta["kind"], meta["method"], meta["params"]
    grid = _raster_grid(raster)
    stages = read_stages(inputs, read_opts)
    if kind == "dtm":
        stages.append({"type": "filters.range", "limits": class_limits(p["ground_classes"])})
    else:
        if kind == "chm":
            stages += _ground_as_class2(p["ground_classes"]) + [{"type": "filters.hag_delaunay"}]
        first = "ReturnNumber[0:1]," if (kind == "dsm" and method == "tin") else ""
        stages.append({"type": "filters.range", "limits": first + not_class_limits(NOISE)})
    if method == "tin" and kind != "chm":
        face = {"type": "filters.faceraster", **grid}
        if p.get("max_edge"):
            from workstation.core.units import Units

            units = Units.from_dict(meta.get("units")) or Units()
            face["max_triangle_edge_length"] = float(units.h_from_m(p["max_edge"]))
        return stages + [{"type": "filters.delaunay"}, face,
                         {"type": "writers.raster", "filename": str(output), **_GTIFF}]
    gdal = {"type": "writers.gdal", "filename": str(output), **grid, **_GTIFF}
    if kind == "chm":
        gdal["dimension"] = "HeightAboveGround"
    if method == "idw":
        gdal.update(output_type="idw", power=float(p.get("idw_power", 2.0)))
    else:
        gdal.update(output_type="max", binmode="true")
    return stages + [gdal]


def dem_equivalent(method: str | None, kind: str, pit_free: bool) -> str | None:
    """Why a ``ws dem`` run has no PDAL pipeline (None when it has one): PDAL has no
    natural-neighbour interpolation and no pit-free CHM."""
    if pit_free:
        return "the pit-free CHM has no PDAL stage"
    if kind == "dtm" and method == "nn":
        return "natural-neighbour interpolation has no PDAL stage (use --method tin or idw)"
    return None


def write_pipeline(stages: list[dict], path, overwrite: bool = False, inputs=()) -> Path:
    """Write the pipeline JSON (a list of stages) atomically."""
    with atomic_path(path, overwrite, inputs) as tmp:
        tmp.write_text(json.dumps(stages, indent=2) + "\n")
    return Path(path)


#: ``ws ground`` methods with a PDAL filter of the same method.
GROUND_FILTERS = ("smrf", "pmf", "csf")


def ground_equivalent(method: str) -> str | None:
    """Why a ``ws ground`` method has no PDAL pipeline (None when it has one)."""
    if method in GROUND_FILTERS:
        return None
    return f"--method {method} has no PDAL filter (PDAL has filters.smrf, filters.pmf and filters.csf)"


def ground_stages(src, output, method: str, params, units, layout: dict | None = None) -> list[dict]:
    """The PDAL pipeline of a ``ws ground`` run: the reader, ``filters.elm`` for the low-noise
    step (low points to class 7, as ``params.noise`` does), the method's PDAL filter with the
    same parameters in CRS units (``returns`` "last,only" unless every return may be ground),
    and the writer. Only ``smrf``, ``pmf`` and ``csf`` (see :func:`ground_equivalent`)."""
    h = units.h_from_m
    stages = [reader(src)]
    if getattr(params, "noise", False):
        n = params.noise_params
        stages.append({"type": "filters.elm", "cell": float(h(n.cell)), "threshold": float(units.v_from_m(n.depth)),
                       "class": 7})
    common = {"returns": "last,only"} if getattr(params, "last_returns_only", True) else {}
    common["ignore"] = "Classification[7:7]"
    if method == "smrf":
        f = {"type": "filters.smrf", "cell": float(h(params.cell)), "slope": float(params.slope),
             "window": float(h(params.window)), "threshold": float(units.v_from_m(params.threshold)),
             "scalar": float(params.scalar)}
    elif method == "pmf":
        f = {"type": "filters.pmf", "cell_size": float(h(params.cell)), "slope": float(params.slope),
             "max_window_size": float(h(params.max_window)),
             "initial_distance": float(units.v_from_m(params.initial_distance)),
             "max_distance": float(units.v_from_m(params.max_distance)), "exponential": bool(params.exponential)}
    else:
        f = {"type": "filters.csf", "resolution": float(h(params.cloth_resolution)), "rigidness": int(params.rigidness),
             "threshold": float(units.v_from_m(params.class_threshold)), "iterations": int(params.iterations),
             "smooth": bool(params.slope_smooth), "step": float(params.time_step)}
    return stages + [{**f, **common}, writer(output, layout)]
