"""`ws qc INPUT... -o REPORT_DIR`: check a LiDAR delivery against USGS or ASPRS specifications."""

from __future__ import annotations

import click

from .options import emit_json, json_option, nonneg_length, overwrite_option, positive_length, read_options


@click.command("qc")
@click.argument("inputs", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False))
@click.option("-o", "--output", "output", required=True, type=click.Path(file_okay=False),
              help="Report folder: report.html, qc.json and the maps (density, voids, DZ).")
@click.option("--spec", default="usgs-ql2", show_default=True,
              help="Specification: usgs-ql0, usgs-ql1, usgs-ql2, usgs-ql3 or asprs-<X>cm (e.g. asprs-10cm).")
@click.option("--checkpoints", type=click.Path(exists=True, dir_okay=False),
              help="Checkpoint CSV: id, x, y, z, land cover (in the delivery's CRS units).")
@click.option("--checkpoint-rmse", type=nonneg_length, default="0",
              help="The checkpoints' own vertical RMSE in metres (or with a unit), combined in as ASPRS Edition 2 asks.")
@click.option("--dem", type=click.Path(exists=True, dir_okay=False),
              help="A DEM GeoTIFF of the delivery: checked against the checkpoints and the 3× cell-size rules.")
@click.option("--surface-cell", type=positive_length, default=None,
              help="Cell of the ground surface the classification checks use, metres (default: 1 m or "
                   "twice the mean point spacing, the larger).")
@read_options
@overwrite_option
@json_option
def qc(inputs, output, spec, checkpoints, checkpoint_rmse, dem, surface_cell, read_opts, overwrite, as_json):
    """Check a delivery (LAS/LAZ/COPC tiles) as lasvalidate, lasoverlap and lascontrol do, against a
    USGS quality level or an ASPRS accuracy class: format, density and voids, swath separation,
    absolute accuracy, DEM accuracy and classification. Writes an HTML report with maps; the exit
    code is 0 whether the delivery passes or not (the report says which), 1 for unusable input."""
    import time
    from pathlib import Path

    from workstation.qc.run import QCParams, write_qc
    from workstation.qc.specs import get_spec

    get_spec(spec)  # an unknown name fails before any point is read
    params = QCParams(spec=spec, checkpoints=Path(checkpoints) if checkpoints else None,
                      checkpoint_rmse_m=float(checkpoint_rmse), dem=Path(dem) if dem else None,
                      surface_cell_m=surface_cell, read_opts=read_opts)
    t0 = time.perf_counter()
    doc = write_qc(inputs, output, params, overwrite=overwrite)
    _summary(doc, output, time.perf_counter() - t0)
    if as_json:
        emit_json(doc)


def _summary(doc: dict, output, seconds: float) -> None:
    from workstation.cli.summary import count, emit_summary

    v = doc["verdict"]
    word = "PASS" if v["pass"] else "FAIL"
    click.echo(f"{v['spec']}: {word}{'' if v['complete'] else ' (not every criterion measured)'}", err=True)
    emit_summary("qc", count(doc["points"], "points"), output, seconds,
                 details=[f"{v['spec']} {word}", count(len(doc["findings"]), "findings")])
