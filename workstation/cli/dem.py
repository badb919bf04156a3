"""`ws dem IN... -o OUT.tif --kind dsm|dtm|chm --resolution R|auto`: rasterise a cloud."""

from __future__ import annotations

import click

from workstation.raster.dem import KINDS, METHODS, DemParams, build_dem

from .options import emit_json, json_option, output_option, overwrite_option
from .options import GEOTIFF, require_suffix
from .options import Length, positive_int, positive_length, read_options
from .options import IntTuple, RegistryChoice, bound, field_option, param_group
from .pipeline_out import pipeline_out_option


@click.command()
@click.argument("inputs", nargs=-1, required=True, type=click.Path(dir_okay=False))
@output_option
@param_group(
    "given",
    bound(DemParams, "kind", "--kind", type=RegistryChoice(KINDS), show_default=True,
          help="Surface: DSM (highest returns), DTM (ground TIN), CHM (DSM - DTM)."),
    bound(DemParams, "resolution", "--resolution", default="auto", show_default=True, type=Length(auto=True),
          help="Cell size in metres whatever the CRS unit (or with a unit: 3ft, 1m), or 'auto' "
               "(from the point spacing and the 3x vertical-RMSE rule)."),
    bound(DemParams, "method", "--method", type=RegistryChoice(METHODS),
          help="DTM: tin (default), nn (natural neighbour) or idw; DSM/CHM: highest (default) or tin (TIN of first returns)."),
    bound(DemParams, "vertical_rmse", "--vertical-rmse", type=positive_length,
          help="Known vertical RMSE of the points in metres (3x rule for auto cells; contour default)."),
    bound(DemParams, "max_edge", "--max-edge", type=positive_length,
          help="Leave voids whose TIN triangles have an edge longer than this (metres) as nodata; default fill all."),
    bound(DemParams, "pit_free", "--pit-free", is_flag=True, help="CHM by the pit-free algorithm (Khosravipour et al. 2014)."),
    bound(DemParams, "ground_classes", "--ground-classes", type=IntTuple("ground_classes"), show_default=True,
          help="Comma-separated classes used as ground."),
)
@field_option(build_dem, "chunk_size", "--chunk-size", show_default=True, type=positive_int,
              help="Points read per chunk (memory bound).")
@read_options(resolution_flag="--copc-resolution")
@pipeline_out_option
@overwrite_option
@json_option
def dem(inputs, output, given, chunk_size, read_opts, pipeline_out, overwrite, as_json):
    """Grid INPUTS (one or more point cloud files, mosaicked) into a DSM, DTM or CHM GeoTIFF.

    Files are streamed in chunks; the output is a tiled, DEFLATE-compressed GeoTIFF with
    overviews, the input CRS and nodata -9999. With --bounds only the points inside the box are
    read and the grid covers the box (cells aligned to multiples of the cell size).
    """
    from workstation.core.log import get_logger
    from workstation.io.geotiff import write_raster

    require_suffix(output, GEOTIFF, what="GeoTIFF")
    if pipeline_out:
        from workstation.io import check_outputs
        from workstation.ops.pdal import dem_equivalent

        why = dem_equivalent(given["method"], given["kind"], given["pit_free"])
        if why:
            raise click.UsageError(f"--pipeline-out: {why}")
        check_outputs([output, pipeline_out], overwrite, inputs=inputs)
    params = DemParams(**given)
    from workstation.core.errors import doing

    with doing(f"gridding {', '.join(inputs)}"):
        r = build_dem(list(inputs), params, chunk_size=chunk_size, read_opts=read_opts)
    write_raster(r, output, overwrite=overwrite, inputs=inputs)
    if pipeline_out:
        from workstation.ops.pdal import dem_stages

        from .pipeline_out import save_pipeline

        save_pipeline(pipeline_out, dem_stages(inputs, output, r, read_opts), overwrite, inputs)
    from workstation.core.units import Units

    units = Units.from_dict(r.meta.get("units")) or Units()
    click.echo(f"resolution {units.describe_h(r.meta['resolution_m'])} ({r.meta['resolution_reason']})", err=True)
    kind = given["kind"]
    get_logger(__name__).info("%s %s written: %d x %d cells", kind, output, *r.shape)
    from workstation.cli.summary import count, emit_summary

    emit_summary("dem", f"{kind} {r.shape[0]:,} x {r.shape[1]:,} cells", output,
                 details=[f"cell {r.meta['resolution_m']:g} m", count(r.meta.get("points", 0), "points")])
    if as_json:
        emit_json({"output": output, "rows": r.shape[0], "cols": r.shape[1], "transform": list(r.transform), "crs": r.crs,
                   **{k: v for k, v in r.meta.items() if k != "params"}})
