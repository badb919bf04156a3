"""`ws info FILE`: header, counts, bounds, CRS, dimensions, classes, returns, density."""

from __future__ import annotations

import click

from .options import emit_json
from .options import positive_float


def _fmt(v) -> str:
    if v is None:
        return "-"
    if isinstance(v, float):
        return f"{v:.10g}"
    if isinstance(v, list):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    return str(v)


@click.command()
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--columns", default=None, help="Column spec for text files, e.g. x,y,z,label.")
@click.option("--density-cell", default=1.0, show_default=True, type=positive_float,
              help="Cell size for the occupied-cell density, in metres.")
@click.option("--json", "as_json", is_flag=True, help="Print the result as JSON on stdout.")
def info(file, columns, density_cell, as_json):
    """Header, point count, bounds, CRS, dimensions (min/max), class and return histograms,
    point density (points/m² over occupied cells and over the footprint) and nominal point
    spacing of FILE."""
    from workstation.qc.summary import summarize

    from workstation.io import format_of

    if columns and format_of(file)[0] not in ("xyz", "txt", "csv", "pts"):
        raise click.UsageError("--columns applies to text inputs (.xyz, .txt, .csv, .pts) only")
    opts = {"columns": columns} if columns else {}
    from click.core import ParameterSource

    given = click.get_current_context().get_parameter_source("density_cell") is not ParameterSource.DEFAULT
    s = summarize(file, density_cell_m=density_cell, density_strict=given, **opts)
    if as_json:
        emit_json(s)
        return
    from rich.console import Console
    from rich.table import Table

    con = Console()
    con.print(f"[bold]{s['file']}[/bold]  {s['format_version']}")
    con.print(f"points      {s['point_count']:,}")
    if s["bounds"]:
        con.print(f"min         {_fmt(s['bounds']['min'])}")
        con.print(f"max         {_fmt(s['bounds']['max'])}")
    crs = s["crs"]
    con.print("crs         " + ("none" if not crs else f"{crs['name']} (EPSG:{crs['epsg'] or '-'}, {crs['unit']})"))
    d = s["density"]
    if d:
        con.print(
            f"density     {d['density_occupied']:.3f} pts/m² over {d['occupied_cells']:,} occupied "
            f"{density_cell:g} m cells, {d['density_footprint']:.3f} pts/m² over the footprint "
            f"({d['footprint_area_m2']:.0f} m²)"
        )
        con.print(f"nps         {d['nps_m']:.3f} m")
    t = Table("dimension", "dtype", "min", "max", title="dimensions", title_justify="left")
    for k, v in s["dimensions"].items():
        t.add_row(k, v["dtype"], _fmt(v["min"]), _fmt(v["max"]))
    con.print(t)
    if s["classification"]:
        t = Table("class", "name", "points", "%", title="classification", title_justify="left")
        n = max(s["point_count"], 1)
        for code, cnt in s["classification"].items():
            t.add_row(code, s["classification_names"][code], f"{cnt:,}", f"{100 * cnt / n:.2f}")
        con.print(t)
    if s["returns"]:
        con.print("returns     " + "  ".join(f"{k}: {v:,}" for k, v in s["returns"].items()))
