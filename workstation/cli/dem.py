"""`ws dem IN... -o OUT.tif --kind dsm|dtm|chm --resolution R|auto`: rasterise a cloud."""

from __future__ import annotations

import math

import click

from .options import emit_json, json_option, output_option, overwrite_option
from .options import GEOTIFF, require_suffix
from .options import positive_float, positive_int


def _resolution(ctx, param, value: str):
    """--resolution: a positive, finite cell size in metres, or None for 'auto'."""
    if value is None or value.lower() == "auto":
        return None
    try:
        r = float(value)
    except ValueError:
        raise click.BadParameter("a cell size in metres or 'auto'") from None
    if not (r > 0 and math.isfinite(r)):
        raise click.BadParameter("must be a positive, finite number of metres")
    return r


@click.command()
@click.argument("inputs", nargs=-1, required=True, type=click.Path(dir_okay=False))
@output_option
@click.option("--kind", type=click.Choice(["dsm", "dtm", "chm"]), default="dtm", show_default=True,
              help="Surface: DSM (highest returns), DTM (ground TIN), CHM (DSM - DTM).")
@click.option("--resolution", default="auto", show_default=True, callback=_resolution,
              help="Cell size in metres, or 'auto' (from the point spacing and the 3x vertical-RMSE rule).")
@click.option("--method", type=click.Choice(["tin", "nn", "idw", "highest"]), default=None,
              help="DTM: tin (default), nn (natural neighbour) or idw; DSM/CHM: highest (default) or tin (TIN of first returns).")
@click.option("--vertical-rmse", type=positive_float, default=None,
              help="Known vertical RMSE of the points in metres (3x rule for auto cells; contour default).")
@click.option("--max-edge", type=positive_float, default=None,
              help="Leave voids whose TIN triangles have an edge longer than this (metres) as nodata; default fill all.")
@click.option("--pit-free", is_flag=True, help="CHM by the pit-free algorithm (Khosravipour et al. 2014).")
@click.option("--ground-classes", default="2", show_default=True, help="Comma-separated classes used as ground.")
@click.option("--chunk-size", default=2_000_000, show_default=True, type=positive_int, help="Points read per chunk (memory bound).")
@overwrite_option
@json_option
def dem(inputs, output, kind, resolution, method, vertical_rmse, max_edge, pit_free, ground_classes, chunk_size, overwrite, as_json):
    """Grid INPUTS (one or more point cloud files, mosaicked) into a DSM, DTM or CHM GeoTIFF.

    Files are streamed in chunks; the output is a tiled, DEFLATE-compressed GeoTIFF with
    overviews, the input CRS and nodata -9999.
    """
    from workstation.core.errors import InvalidInputError
    from workstation.core.log import get_logger
    from workstation.io.geotiff import write_raster

    require_suffix(output, GEOTIFF, what="GeoTIFF")
    from workstation.raster.dem import DemParams, build_dem

    try:
        classes = tuple(int(c) for c in ground_classes.split(",") if c.strip())
    except ValueError:
        raise InvalidInputError("--ground-classes must be integers like 2,9", field="ground_classes") from None
    params = DemParams(kind=kind, resolution=resolution, method=method, vertical_rmse=vertical_rmse,
                       max_edge=max_edge, pit_free=pit_free, ground_classes=classes)
    from workstation.core.errors import doing

    with doing(f"gridding {', '.join(inputs)}"):
        r = build_dem(list(inputs), params, chunk_size=chunk_size)
    write_raster(r, output, overwrite=overwrite, inputs=inputs)
    click.echo(f"resolution {r.meta['resolution']:g} m ({r.meta['resolution_reason']})", err=True)
    get_logger(__name__).info("%s %s written: %d x %d cells", kind, output, *r.shape)
    if as_json:
        emit_json({"output": output, "rows": r.shape[0], "cols": r.shape[1], "transform": list(r.transform), "crs": r.crs,
                   **{k: v for k, v in r.meta.items() if k != "params"}})
