"""`ws filter IN -o OUT --expr "..."`: keep the points matching a PDAL expression (filters.expression)."""

from __future__ import annotations

import click

from .options import json_option, output_option, overwrite_option, read_options
from .pipeline_out import pipeline_out_option


@click.command("filter")
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@output_option
@click.option("--expr", "expression", required=True,
              help='PDAL expression, e.g. "Classification == 2 && ReturnNumber == 1" (== != < <= > >= && || ! + - * / ( )).')
@read_options
@pipeline_out_option
@overwrite_option
@json_option
def filter_cmd(src, output, expression, read_opts, pipeline_out, overwrite, as_json):
    """Keep the points of IN for which the expression holds; write OUT, streamed chunk by chunk.

    Dimension names as PDAL spells them (X Y Z Intensity ReturnNumber NumberOfReturns
    Classification ScanAngleRank UserData PointSourceId GpsTime Red Green Blue Infrared ...),
    canonical names (return_number) or extra-byte names; an unknown name lists the valid ones.
    """
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_outputs, format_of
    from workstation.ops.expression import compile_expression
    from workstation.ops.stream import stream_select

    from .options import emit_json
    from .pipeline_out import save_pipeline

    t0 = time.perf_counter()
    format_of(src)
    format_of(output)
    check_outputs([output, pipeline_out], overwrite, inputs=[src])
    mask = compile_expression(expression)  # a syntax error stops here, before any reading
    total, kept = stream_select(src, output, mask, stage="filter", overwrite=overwrite,
                                hint="check the dimension values with ws info", read_opts=read_opts)
    if pipeline_out:
        from workstation.ops import pdal

        layout = pdal.las_layout(output) if format_of(output)[0] in ("las", "laz") else None
        save_pipeline(pipeline_out, [*pdal.read_stages([src], read_opts),
                                     {"type": "filters.expression", "expression": expression},
                                     pdal.writer(output, layout)], overwrite, [src])
    dt = time.perf_counter() - t0
    get_logger(__name__).info("kept %d of %d points in %.2f s", kept, total, dt)
    if as_json:
        emit_json({"input": src, "output": output, "points_in": total, "points_out": kept, "seconds": dt})
