"""`ws contours DEM.tif -o OUT.geojson --interval I`: contour lines of a DEM."""

from __future__ import annotations

import math

import click

from workstation.raster.contours import ContourParams

from .options import emit_json, json_option, output_option, overwrite_option
from .options import require_suffix
from .options import Length, nonneg_int, positive_int, positive_length
from .options import bound, field_default, param_group


@click.command()
@click.argument("dem", type=click.Path(exists=True, dir_okay=False))
@output_option
@param_group(
    "given",
    bound(ContourParams, "interval", "--interval", type=positive_length,
          help="Contour interval in metres whatever the DEM's height unit (or with a unit: 2ft); "
               "default 3x the DEM's vertical RMSE (from its metadata) when known."),
    bound(ContourParams, "base", "--base", type=Length(min_m=-math.inf, open_min=False),
          default=f"{field_default(ContourParams, 'base'):g}", show_default=True,
          help="Levels are base + k * interval (metres, or with a unit)."),
    bound(ContourParams, "index_every", "--index-every", type=positive_int, show_default=True,
          help="Every n-th level is an index contour."),
    bound(ContourParams, "smooth", "--smooth", type=nonneg_int, show_default=True,
          help="Chaikin smoothing iterations (0 = none)."),
)
@overwrite_option
@json_option
def contours(dem, output, given, overwrite, as_json):
    """Trace contour lines of DEM (closed and open) and write them as GeoJSON LineStrings with
    'elevation', 'index' and 'closed' properties, in the DEM's CRS."""
    from workstation.io.geotiff import read_raster
    from workstation.raster.contours import contour_lines, write_geojson

    require_suffix(output, (".geojson", ".json"), what="GeoJSON")
    r = read_raster(dem, band=1)
    cs = contour_lines(r, ContourParams(**given))
    write_geojson(cs, output, overwrite=overwrite, inputs=[dem])
    from workstation.io.crs import raster_units

    click.echo(f"interval {raster_units(r).describe_v(cs.interval_m)} ({cs.reason}); {len(cs)} lines", err=True)
    from workstation.cli.summary import count, emit_summary

    emit_summary("contours", count(len(cs), "lines"), output,
                 details=[f"interval {cs.interval_m:g} m", count(int(cs.index.sum()), "index contours")])
    if as_json:
        emit_json({"output": output, "interval": cs.interval, "interval_m": cs.interval_m, "z_unit": cs.z_unit,
                   "interval_reason": cs.reason, "lines": len(cs),
                   "closed": int(cs.closed.sum()), "index": int(cs.index.sum()),
                   "levels": sorted(set(float(v) for v in cs.levels))})
