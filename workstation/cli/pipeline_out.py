"""``--pipeline-out FILE.json`` shared by the everyday-operation commands, and the ``--scale`` /
``--offset`` parsing of LAS outputs."""

from __future__ import annotations

import math

import click

pipeline_out_option = click.option(
    "--pipeline-out", type=click.Path(dir_okay=False), default=None,
    help="Also write the equivalent PDAL pipeline (JSON) of this run.")


def save_pipeline(path, stages, overwrite: bool, inputs) -> None:
    """Write the stages as a PDAL pipeline JSON when ``--pipeline-out`` was given."""
    if path:
        from workstation.ops.pdal import write_pipeline

        write_pipeline(stages, path, overwrite, inputs)


def parse_triple(text, option: str, positive: bool = False, allow_auto: bool = False):
    """One number (for x, y and z) or three comma-separated ones; 'auto' where allowed.

    Examples
    --------
    >>> parse_triple("0.01", "--scale", positive=True), parse_triple("1e-7,1e-7,0.001", "--scale")
    ([0.01, 0.01, 0.01], [1e-07, 1e-07, 0.001])
    """
    if text is None:
        return None
    if allow_auto and text.strip().lower() == "auto":
        return "auto"
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise click.BadParameter(f"'{text}' is not a number or x,y,z", param_hint=f"'{option}'") from None
    if len(vals) == 1:
        vals *= 3
    if len(vals) != 3 or not all(math.isfinite(v) for v in vals) or (positive and min(vals) <= 0):
        need = "three positive numbers" if positive else "three finite numbers"
        raise click.BadParameter(f"'{text}': give one value or {need} x,y,z" + (" or 'auto'" if allow_auto else ""),
                                 param_hint=f"'{option}'")
    return vals
