"""`ws convert IN OUT`: any supported cloud format to any other, with CRS assignment or reprojection."""

from __future__ import annotations

import click

from .options import emit_json, overwrite_option, read_options
from .pipeline_out import parse_triple, pipeline_out_option, save_pipeline


@click.command()
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@click.argument("dst", metavar="OUT", type=click.Path(dir_okay=False))
@click.option("--crs", default=None, help="Assign this CRS to the input (EPSG:code or WKT); no coordinate change.")
@click.option("--to-crs", default=None, help="Reproject the coordinates into this CRS (pyproj).")
@click.option("--columns", default=None, help="Column spec for a text input, e.g. x,y,z,label.")
@click.option("--out-columns", default=None, help="Column spec for a text output.")
@click.option("--point-format", type=click.IntRange(0, 10), default=None, help="LAS point format of a LAS/LAZ output.")
@click.option("--las-version", type=click.Choice(["1.0", "1.1", "1.2", "1.3", "1.4"]), default=None,
              help="LAS version of a LAS/LAZ output (raised to what the point format needs).")
@click.option("--scale", default=None,
              help="LAS/LAZ output scale: one value or x,y,z (default: the input's, or one that keeps its "
                   "resolution in the new CRS: 1e-7 degree or finer, 0.001/0.01 m).")
@click.option("--offset", default=None,
              help="LAS/LAZ output offset: x,y,z or 'auto' (the data's rounded centre; the default when the "
                   "input's offsets do not fit).")
@pipeline_out_option
@overwrite_option
@read_options
@click.option("--json", "as_json", is_flag=True, help="Print a summary as JSON on stdout.")
def convert(src, dst, crs, to_crs, columns, out_columns, point_format, las_version, scale, offset, pipeline_out,
            overwrite, read_opts, as_json):
    """Convert IN to OUT (LAS, LAZ, COPC, PLY, PCD, XYZ/TXT/CSV, E57), choosing formats by extension.

    An OUT ending .copc.laz is written as COPC 1.0 (an octree of LAZ chunks that viewers
    stream by area and level of detail; point format 6, 7 with RGB, 8 with NIR); a LAS/LAZ
    input is streamed, so the cloud need not fit in memory.

    Reprojecting to degrees (--to-crs EPSG:4326) writes LAS coordinates at a tenth of the input's
    ground resolution (1e-9 degree for a 1 cm input) around the data's rounded centre, and back
    to metres at the matching power of ten, so a round trip returns every point within 1 mm.
    Heights are not changed unless a CRS with a vertical datum is asked."""
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_outputs, format_of, read_cloud, write_cloud
    import numpy as np

    from workstation.io.las import auto_scales, fitted_scales
    from workstation.io.crs import parse_crs, reproject

    log = get_logger(__name__)
    t0 = time.perf_counter()
    format_of(src)
    format_of(dst)
    scales = parse_triple(scale, "--scale", positive=True)
    offsets = parse_triple(offset, "--offset", allow_auto=True)
    from workstation.io.copc import is_copc_name

    if is_copc_name(dst):
        return _to_copc(src, dst, crs, to_crs, columns, out_columns, point_format, las_version, scales, offsets,
                        pipeline_out, overwrite, read_opts, as_json, t0)
    check_outputs([dst, pipeline_out], overwrite, inputs=[src])
    if columns and format_of(src)[0] not in ("xyz", "txt", "csv", "pts"):
        raise click.UsageError("--columns applies to text inputs (.xyz, .txt, .csv, .pts) only")
    cloud = read_cloud(src, **read_opts, **({"columns": columns} if columns else {}))
    if crs:
        parse_crs(crs, "crs")
        cloud = cloud.with_crs(crs).with_history("assign_crs", {"crs": crs})
    source_crs, source_scales = cloud.crs, cloud.meta.get("las", {}).get("scales")
    if to_crs:
        cloud = reproject(cloud, to_crs)
        if scales is None:  # keep the input's resolution in the new unit
            lo, hi = cloud.bounds if cloud.n else (np.zeros(3), np.zeros(3))
            scales = fitted_scales(lo, hi, auto_scales(cloud.crs, source_scales, source_crs)).tolist()
        offsets = "auto" if offsets is None else offsets
    opts = {}
    out_fmt = format_of(dst)[0]
    if out_fmt in ("las", "laz"):
        if point_format is not None:
            opts["point_format"] = point_format
        if las_version is not None:
            opts["version"] = las_version
        if scales is not None:
            opts["scales"] = scales
        if offsets is not None:
            opts["offsets"] = offsets
    elif point_format is not None or las_version is not None or scale or offset:
        raise click.UsageError("--point-format, --las-version, --scale and --offset apply to LAS/LAZ outputs only")
    if out_columns:
        if out_fmt not in ("xyz", "txt", "csv", "pts"):
            raise click.UsageError("--out-columns applies to text outputs only")
        opts["columns"] = out_columns
    write_cloud(cloud, dst, overwrite=overwrite, inputs=[src], **opts)
    if pipeline_out:
        from workstation.ops import pdal

        stages = [pdal.reader(src, crs)]
        if to_crs:
            stages.append({"type": "filters.reprojection", "in_srs": source_crs, "out_srs": to_crs})
        layout = pdal.las_layout(dst) if out_fmt in ("las", "laz") else None
        save_pipeline(pipeline_out, stages + [pdal.writer(dst, layout)], overwrite, [src])
    dt = time.perf_counter() - t0
    log.info("wrote %s (%d points) in %.2f s", dst, cloud.n, dt)
    from workstation.cli.summary import count, emit_summary

    emit_summary("convert", count(cloud.n, "points"), dst, dt, f"CRS {cloud.crs}" if cloud.crs else "no CRS")
    if as_json:
        emit_json({"input": src, "output": dst, "point_count": cloud.n, "crs": cloud.crs, "seconds": dt})


def _to_copc(src, dst, crs, to_crs, columns, out_columns, point_format, las_version, scales, offsets, pipeline_out,
             overwrite, read_opts, as_json, t0):
    """``ws convert IN OUT.copc.laz``: a LAS/LAZ input without reprojection is streamed chunk by
    chunk into the COPC writer; any other input is read whole (and reprojected) first."""
    import time

    from workstation.io import check_outputs, format_of, read_cloud
    from workstation.io.copc import copc_output
    from workstation.publish.copc import COPC_FORMATS, save_copc

    if point_format is not None and point_format not in COPC_FORMATS:
        raise click.BadParameter(f"COPC stores point formats 6, 7 and 8, not {point_format}",
                                 param_hint="'--point-format'")
    if las_version not in (None, "1.4"):
        raise click.BadParameter("COPC is LAS 1.4", param_hint="'--las-version'")
    if out_columns:
        raise click.UsageError("--out-columns applies to text outputs only")
    if columns and format_of(src)[0] not in ("xyz", "txt", "csv", "pts"):
        raise click.UsageError("--columns applies to text inputs (.xyz, .txt, .csv, .pts) only")
    with copc_output():
        check_outputs([dst, pipeline_out], overwrite, inputs=[src])
    opts = {"point_format": point_format, "scales": scales, "offsets": offsets}
    if format_of(src)[0] in ("las", "laz") and not to_crs:
        source = _las_chunks(src, crs, read_opts)
        result = save_copc(source, dst, overwrite=overwrite, inputs=[src], bounds=_las_bounds(src), **opts)
        out_crs = crs or _first_crs(src)
    else:
        cloud = read_cloud(src, **read_opts, **({"columns": columns} if columns else {}))
        source_crs = crs or cloud.crs
        cloud = _assign_and_reproject(cloud, crs, to_crs, opts)
        result = save_copc(cloud, dst, overwrite=overwrite, inputs=[src], **opts)
        out_crs = cloud.crs
    if pipeline_out:
        _save_copc_pipeline(src, dst, crs, (source_crs, to_crs) if to_crs else None, pipeline_out, overwrite)
    dt = time.perf_counter() - t0
    from workstation.cli.summary import count, emit_summary
    from workstation.core.log import get_logger

    get_logger(__name__).info("wrote %s (%d points, %d octree nodes) in %.2f s", dst, result.points, result.nodes, dt)
    emit_summary("convert", count(result.points, "points"), dst, dt,
                 f"COPC {result.levels} levels, {result.nodes} nodes" + (f", CRS {out_crs}" if out_crs else ""))
    if as_json:
        emit_json({"input": src, "output": dst, "point_count": result.points, "crs": out_crs, "seconds": dt,
                   "copc": {k: v for k, v in result.to_dict().items() if k != "path"}})


def _las_chunks(src, crs, read_opts):
    """The chunks of a LAS/LAZ input (``--crs`` assigned to each)."""
    from workstation.io import iter_chunks

    for chunk in iter_chunks(src, 1_048_576, **read_opts):
        yield chunk.with_crs(crs) if crs else chunk


def _las_bounds(src):
    """(mins, maxs) of a LAS/LAZ input from its header: the automatic offsets then fit every chunk."""
    import laspy
    import numpy as np

    with laspy.open(str(src)) as r:
        return np.asarray(r.header.mins, float), np.asarray(r.header.maxs, float)


def _first_crs(src):
    from workstation.io.las import read_header

    return read_header(src)["crs"]


def _assign_and_reproject(cloud, crs, to_crs, opts):
    """``--crs`` then ``--to-crs`` on a whole cloud; a reprojection sets scales that keep the
    input's resolution and automatic offsets, unless given (``opts`` is updated)."""
    import numpy as np

    from workstation.io.crs import parse_crs, reproject
    from workstation.io.las import auto_scales, fitted_scales

    if crs:
        parse_crs(crs, "crs")
        cloud = cloud.with_crs(crs).with_history("assign_crs", {"crs": crs})
    if to_crs:
        source_crs, source_scales = cloud.crs, cloud.meta.get("las", {}).get("scales")
        cloud = reproject(cloud, to_crs)
        if opts["scales"] is None:
            lo, hi = cloud.bounds if cloud.n else (np.zeros(3), np.zeros(3))
            opts["scales"] = fitted_scales(lo, hi, auto_scales(cloud.crs, source_scales, source_crs)).tolist()
        opts["offsets"] = "auto" if opts["offsets"] is None else opts["offsets"]
    return cloud


def _save_copc_pipeline(src, dst, crs, reprojection, pipeline_out, overwrite):
    """The PDAL pipeline of the conversion: reader, reprojection (``(in_srs, out_srs)`` or
    None), ``writers.copc`` with the written header's scales, offsets and CRS."""
    from workstation.ops import pdal

    layout = pdal.las_layout(dst)
    stages = [pdal.reader(src, crs)]
    if reprojection:
        stages.append({"type": "filters.reprojection", "in_srs": reprojection[0], "out_srs": reprojection[1]})
    writer = {"type": "writers.copc", "filename": str(dst), "extra_dims": "all"}
    for axis, s, o in zip("xyz", layout["scales"], layout["offsets"]):
        writer[f"scale_{axis}"], writer[f"offset_{axis}"] = float(s), float(o)
    if layout.get("crs"):
        writer["a_srs"] = layout["crs"]
    save_pipeline(pipeline_out, stages + [writer], overwrite, [src])
