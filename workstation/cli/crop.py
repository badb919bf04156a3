"""`ws crop IN -o OUT (--bounds ... | --polygon FILE)`: keep the points inside a box or polygons (PDAL filters.crop)."""

from __future__ import annotations

import click

from .options import json_option, output_option, overwrite_option, read_options
from .pipeline_out import pipeline_out_option


@click.command("crop")
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@output_option
@click.option("--bounds", default=None,
              help="xmin,ymin,xmax,ymax[,zmin,zmax] in CRS units, bounds included (or PDAL's ([xmin,xmax],[ymin,ymax])).")
@click.option("--polygon", "polygon_path", type=click.Path(dir_okay=False), default=None,
              help="Polygons (holes and multipolygons too) from a .geojson or .gpkg file.")
@click.option("--layer", default=None, help="GeoPackage layer (default: the first feature table).")
@click.option("--polygon-crs", default=None,
              help="CRS of the polygons when the file does not say (default: the cloud's); they are moved into the cloud's CRS.")
@click.option("--invert", is_flag=True, help="Keep the points outside instead (PDAL's outside).")
@read_options(with_bounds=False)
@pipeline_out_option
@overwrite_option
@json_option
def crop(src, output, bounds, polygon_path, layer, polygon_crs, invert, read_opts, pipeline_out, overwrite,
         as_json):
    """Crop IN to a box or polygons and write OUT, streamed chunk by chunk (bounded memory)."""
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_outputs, format_of
    from workstation.ops.crop import CropParams, crop_mask, parse_bounds
    from workstation.ops.stream import stream_select

    from .options import emit_json
    from .pipeline_out import save_pipeline

    t0 = time.perf_counter()
    if (bounds is None) == (polygon_path is None):
        raise click.UsageError("give exactly one of --bounds and --polygon")
    if layer and not polygon_path:
        raise click.UsageError("--layer applies to --polygon")
    format_of(src)
    format_of(output)
    check_outputs([output, pipeline_out], overwrite, inputs=[src, *([polygon_path] if polygon_path else [])])
    polygons = None
    if polygon_path:
        from workstation.ops.vector import PolygonSet, read_polygons

        polygons = read_polygons(polygon_path, layer)
        if polygon_crs:
            from workstation.io.crs import parse_crs

            parse_crs(polygon_crs, "polygon_crs")
            polygons = PolygonSet(polygons.polygons, polygon_crs)
    params = CropParams(bounds=parse_bounds(bounds) if bounds else None, polygons=polygons, invert=invert)
    total, kept = stream_select(src, output, lambda c: crop_mask(c, params), stage="crop", overwrite=overwrite,
                                hint="check that the area overlaps the data (ws info) and is in its CRS (--polygon-crs)",
                                read_opts=read_opts)
    if pipeline_out:
        from workstation.ops import pdal

        layout = pdal.las_layout(output) if format_of(output)[0] in ("las", "laz") else None
        save_pipeline(pipeline_out, [*pdal.read_stages([src], read_opts),
                                     pdal.crop_stage(params.bounds, polygons, invert),
                                     pdal.writer(output, layout)], overwrite, [src])
    dt = time.perf_counter() - t0
    get_logger(__name__).info("kept %d of %d points in %.2f s", kept, total, dt)
    if as_json:
        emit_json({"input": src, "output": output, "points_in": total, "points_out": kept, "seconds": dt})
