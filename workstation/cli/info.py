"""`ws info FILE`: header, counts, bounds, CRS, dimensions, classes, returns, density."""

from __future__ import annotations

import click

from .options import emit_json
from .options import positive_float
from .options import read_options


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
@click.option("--summary", is_flag=True,
              help="Header only (no point is read, milliseconds): format, counts by return, bounds, "
                   "scale/offset, CRS, VLRs, COPC octree. LAS/LAZ/COPC.")
@click.option("--metadata", is_flag=True,
              help="The header as a JSON document shaped like `pdal info --metadata` (no point is read).")
@read_options
@click.option("--json", "as_json", is_flag=True, help="Print the result as JSON on stdout.")
def info(file, columns, density_cell, summary, metadata, read_opts, as_json):
    """Header, point count, bounds, CRS, dimensions (min/max), class and return histograms,
    point density (points/m² over occupied cells and over the footprint) and nominal point
    spacing of FILE. COPC files show their octree; --bounds/--level/--resolution restrict the
    statistics to the points read."""
    from workstation.qc.summary import summarize

    from workstation.io import format_of

    if columns and format_of(file)[0] not in ("xyz", "txt", "csv", "pts"):
        raise click.UsageError("--columns applies to text inputs (.xyz, .txt, .csv, .pts) only")
    if summary or metadata:
        _header_only(file, summary, metadata, read_opts, as_json)
        return
    opts = {"columns": columns} if columns else {}
    opts.update({k: v for k, v in read_opts.items() if v is not None})
    from click.core import ParameterSource

    given = click.get_current_context().get_parameter_source("density_cell") is not ParameterSource.DEFAULT
    from workstation.io.registry import crs_checked

    crs_checked(file)  # the report shows the CRS warnings itself
    s = summarize(file, density_cell_m=density_cell, density_strict=given, **opts)
    if as_json:
        emit_json(s)
        return
    from rich.console import Console
    from rich.table import Table

    con = Console()
    _print_head(con, s)
    if s.get("copc"):
        _print_copc(con, s["copc"])
    if s["bounds"]:
        con.print(f"min         {_fmt(s['bounds']['min'])}")
        con.print(f"max         {_fmt(s['bounds']['max'])}")
    crs = s["crs"]
    con.print("crs         " + ("none (lengths taken as metres)" if not crs else f"{crs['name']} (EPSG:{crs['epsg'] or '-'}, {crs['unit']}"
                                  + (f"; heights in {crs['vertical_unit']}" if crs.get("vertical_unit", crs["unit"]) != crs["unit"] else "")
                                  + ")"))
    for w in s.get("crs_warnings", []):
        con.print(f"[yellow]warning[/yellow]     {w}", markup=True, highlight=False)
    d = s["density"]
    if d:
        con.print(
            f"density     {d['density_occupied']:.3f} pts/m² over {d['occupied_cells']:,} occupied "
            f"{density_cell:g} m cells, {d['density_footprint']:.4g} pts/m² over the footprint "
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


def _print_copc(con, c: dict) -> None:
    """The COPC octree: levels, nodes, points and spacing per level."""
    con.print(f"copc        {c['version']}: {c['levels']} levels, {c['nodes']:,} nodes, root spacing {c['spacing']:.4g}")
    for lev, (n, nodes, sp) in enumerate(zip(c["points_per_level"], c["nodes_per_level"], c["spacing_per_level"])):
        con.print(f"  level {lev:<3} {n:>14,} points {nodes:>8,} nodes  spacing {sp:.4g}")


def _header_only(file, summary: bool, metadata: bool, read_opts: dict, as_json: bool) -> None:
    """``--summary`` / ``--metadata``: the header, no point read."""
    if summary and metadata:
        raise click.UsageError("--summary and --metadata are two views of the header; give one")
    if any(v is not None for v in read_opts.values()):
        raise click.UsageError("--summary and --metadata read the header only; --bounds, --resolution and "
                               "--level select points (use them without --summary)")
    from workstation.qc.header import header_summary, pdal_metadata

    if metadata:
        emit_json(pdal_metadata(file))
        return
    s = header_summary(file)
    if as_json:
        emit_json(s)
        return
    from rich.console import Console

    con = Console()
    _print_head(con, s)
    if s["points_by_return"]:
        con.print("by return   " + "  ".join(f"{k}: {v:,}" for k, v in s["points_by_return"].items()))
    con.print(f"min         {_fmt(s['bounds']['min'])}")
    con.print(f"max         {_fmt(s['bounds']['max'])}")
    con.print(f"scale       {_fmt(s['scales'])}")
    con.print(f"offset      {_fmt(s['offsets'])}")
    crs = s["crs"]
    con.print("crs         " + ("none" if not crs else f"{crs['name']} (EPSG:{crs['epsg'] or '-'}, "
                                 f"{crs['unit']}, heights in {crs['vertical_unit'] or crs['unit']})"))
    for kind in ("vlrs", "evlrs"):
        for v in s[kind]:
            size = "-" if v["size"] is None else f"{v['size']:,} B"
            con.print(f"{kind[:-1]:<11} {v['user_id']}/{v['record_id']}  {v['description']}  ({size})")
    if s["copc"]:
        _print_copc(con, s["copc"])
    else:
        con.print("copc        no")


def _print_head(con, s: dict) -> None:
    """The first two lines of every ``ws info`` view: file, format, point count."""
    con.print(f"[bold]{s['file']}[/bold]  {s['format_version']}")
    con.print(f"points      {s['point_count']:,}")
