"""`ws tile IN... -o FOLDER --size S [--buffer B]`: square tiles named by their lower-left corner."""

from __future__ import annotations

import click

from workstation.ops.tile import TileParams

from .options import bound, json_option, nonneg_float, overwrite_option, param_group, positive_float, read_options
from .pipeline_out import pipeline_out_option


@click.command("tile")
@click.argument("inputs", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(file_okay=False), help="Output folder.")
@param_group(
    "given",
    bound(TileParams, "size", "--size", type=positive_float, required=True, default=None, help="Tile side in CRS units."),
    bound(TileParams, "buffer", "--buffer", type=nonneg_float, show_default=True,
          help="Also write the points this close (CRS units) outside a tile to it."),
)
@click.option("--format", "ext", type=click.Choice(["laz", "las"]), default="laz", show_default=True,
              help="Tile file format.")
@read_options
@pipeline_out_option
@overwrite_option
@json_option
def tile(inputs, output, given, ext, read_opts, pipeline_out, overwrite, as_json):
    """Cut IN... into tiles of --size aligned to multiples of it, written to FOLDER as
    <xmin>_<ymin>.laz; streamed, so any number of points fits in memory."""
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_outputs, format_of, work_folder
    from workstation.ops.tile import tile_files

    from .options import emit_json
    from .pipeline_out import save_pipeline

    t0 = time.perf_counter()
    for p in inputs:
        format_of(p)
    params = TileParams(**given, ext="." + ext)
    size, buffer = given["size"], given["buffer"]
    check_outputs([pipeline_out], overwrite, inputs=inputs)
    with work_folder(output) as folder:
        counts = tile_files(inputs, folder, params, overwrite=overwrite, read_opts=read_opts)
    if pipeline_out:
        from workstation.ops import pdal

        stages = pdal.read_stages(inputs, read_opts)
        stages.append({"type": "filters.splitter", "length": size, "origin_x": 0.0, "origin_y": 0.0, "buffer": buffer})
        # PDAL numbers the tiles (#); ws names them by their lower-left corner
        stages.append(pdal.writer(f"{output}/tile_#.{ext}", None))
        save_pipeline(pipeline_out, stages, overwrite, inputs)
    dt = time.perf_counter() - t0
    get_logger(__name__).info("wrote %d tiles (%d points) in %.2f s", len(counts), sum(counts.values()), dt)
    if as_json:
        emit_json({"inputs": list(inputs), "output": output, "tiles": counts, "seconds": dt})
