"""`ws report WORKDIR -o report.html|report.pdf`: the quality report of a work folder."""

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
@click.option("--pdf", is_flag=True,
              help="Also print the .html report to a PDF beside it (same name, .pdf) with headless Chromium; "
                   "-o report.pdf writes the PDF alone.")
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
def report(workdir, output, pdf, given, overwrite, as_json):
    """Write the quality report of WORKDIR as one self-contained HTML page (-o X.html) or a PDF
    (-o X.pdf, printed by headless Chromium).

    The summary comes first: what was processed (clouds and points, photos, rasters, inputs,
    CRS, area, dates), the key accuracies found in the folder's records (SfM reprojection error
    and registered images, GCP and check point RMSE, registration RMSE, ground-evaluation
    errors, DTM RMSE, classification F1) and the verdict of a `ws qc` result in the folder.
    Then previews (ortho, hillshades, DTM, density, renders), SfM figures (reprojection error
    histogram, cameras over the sparse cloud, GCP residuals), registration residuals, ground
    results and evaluations, clouds and meshes; the JSON records are in a collapsed appendix.
    """
    import time

    from workstation.render.report import write_report

    t0 = time.perf_counter()
    outs = write_report(workdir, output, overwrite=overwrite, params=ReportParams(**given), pdf=pdf)
    from workstation.cli.summary import emit_summary

    emit_summary("report", f"work folder {workdir}", outs, time.perf_counter() - t0,
                 details=", ".join(f"{p.name} {p.stat().st_size / 1e6:.1f} MB" for p in outs))
    if as_json:
        emit_json({"workdir": workdir, "output": str(outs[0]), "files": [str(p) for p in outs],
                   "bytes": sum(p.stat().st_size for p in outs), "seconds": time.perf_counter() - t0})
