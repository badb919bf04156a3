"""`ws contours DEM.tif -o OUT.geojson --interval I`: contour lines of a DEM."""

from __future__ import annotations

import click

from .options import emit_json, json_option, output_option, overwrite_option
from .options import require_suffix
from .options import finite_float, nonneg_int, positive_float, positive_int


@click.command()
@click.argument("dem", type=click.Path(exists=True, dir_okay=False))
@output_option
@click.option("--interval", type=positive_float, default=None,
              help="Contour interval in metres; default 3x the DEM's vertical RMSE (from its metadata) when known.")
@click.option("--base", type=finite_float, default=0.0, show_default=True, help="Levels are base + k * interval (metres).")
@click.option("--index-every", type=positive_int, default=5, show_default=True, help="Every n-th level is an index contour.")
@click.option("--smooth", type=nonneg_int, default=0, show_default=True, help="Chaikin smoothing iterations (0 = none).")
@overwrite_option
@json_option
def contours(dem, output, interval, base, index_every, smooth, overwrite, as_json):
    """Trace contour lines of DEM (closed and open) and write them as GeoJSON LineStrings with
    'elevation', 'index' and 'closed' properties, in the DEM's CRS."""
    from workstation.io.geotiff import read_raster
    from workstation.raster.contours import ContourParams, contour_lines, write_geojson

    require_suffix(output, (".geojson", ".json"), what="GeoJSON")
    r = read_raster(dem, band=1)
    cs = contour_lines(r, ContourParams(interval, base, index_every, smooth))
    write_geojson(cs, output, overwrite=overwrite, inputs=[dem])
    click.echo(f"interval {cs.interval:g} m ({cs.reason}); {len(cs)} lines", err=True)
    if as_json:
        emit_json({"output": output, "interval": cs.interval, "interval_reason": cs.reason, "lines": len(cs),
                   "closed": int(cs.closed.sum()), "index": int(cs.index.sum()),
                   "levels": sorted(set(float(v) for v in cs.levels))})
