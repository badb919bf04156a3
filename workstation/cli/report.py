"""`ws report WORKDIR -o report.html`: one self-contained page of a work folder."""

from __future__ import annotations

import click

from .options import emit_json, json_option, output_option, overwrite_option
from .options import positive_int


@click.command()
@click.argument("workdir", type=click.Path(exists=True, file_okay=False))
@output_option
@click.option("--render-size", default="640x480", show_default=True, help="Size of each render, WIDTHxHEIGHT pixels.")
@click.option("--max-points", type=positive_int, default=2_000_000, show_default=True,
              help="Points drawn per cloud render (seeded subset above).")
@overwrite_option
@json_option
def report(workdir, output, render_size, max_points, overwrite, as_json):
    """Write an HTML report of WORKDIR: products, stage parameters and timings, renders and plots."""
    import time

    from workstation.render.report import ReportParams, write_report

    try:
        w, h = (int(v) for v in render_size.lower().split("x"))
    except ValueError:
        raise click.BadParameter("give WIDTHxHEIGHT, e.g. 640x480", param_hint="--render-size") from None
    t0 = time.perf_counter()
    out = write_report(workdir, output, overwrite=overwrite, params=ReportParams(render_size=(w, h), max_points=max_points))
    from workstation.cli.summary import emit_summary

    emit_summary("report", f"work folder {workdir}", out, time.perf_counter() - t0,
                 details=f"{out.stat().st_size / 1e6:.1f} MB")
    if as_json:
        emit_json({"workdir": workdir, "output": str(out), "bytes": out.stat().st_size,
                   "seconds": time.perf_counter() - t0})
