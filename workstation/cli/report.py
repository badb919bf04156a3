"""`ws report WORKDIR -o report.html`: one self-contained page of a work folder."""

from __future__ import annotations

import click

from workstation.render.report import ReportParams

from .options import emit_json, json_option, output_option, overwrite_option
from .options import bound, field_default, param_group, positive_int


def _size(ctx, param, value):
    """--render-size WIDTHxHEIGHT as two pixel counts (a tuple default passes through)."""
    if isinstance(value, tuple):
        return value
    try:
        w, h = (int(v) for v in value.lower().split("x"))
    except ValueError:
        raise click.BadParameter("give WIDTHxHEIGHT, e.g. 640x480", param_hint="--render-size") from None
    return w, h


@click.command()
@click.argument("workdir", type=click.Path(exists=True, file_okay=False))
@output_option
@param_group(
    "given",
    bound(ReportParams, "render_size", "--render-size", callback=_size, show_default=True,
          default="x".join(map(str, field_default(ReportParams, "render_size"))),
          help="Size of each render, WIDTHxHEIGHT pixels."),
    bound(ReportParams, "max_points", "--max-points", type=positive_int, show_default=True,
          help="Points drawn per cloud render (seeded subset above)."),
)
@overwrite_option
@json_option
def report(workdir, output, given, overwrite, as_json):
    """Write an HTML report of WORKDIR: products, stage parameters and timings, renders and plots."""
    import time

    from workstation.render.report import write_report

    t0 = time.perf_counter()
    out = write_report(workdir, output, overwrite=overwrite, params=ReportParams(**given))
    from workstation.cli.summary import emit_summary

    emit_summary("report", f"work folder {workdir}", out, time.perf_counter() - t0,
                 details=f"{out.stat().st_size / 1e6:.1f} MB")
    if as_json:
        emit_json({"workdir": workdir, "output": str(out), "bytes": out.stat().st_size,
                   "seconds": time.perf_counter() - t0})
