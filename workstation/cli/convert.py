"""`ws convert IN OUT`: any supported cloud format to any other, with CRS assignment or reprojection."""

from __future__ import annotations

import click

from .options import emit_json, overwrite_option


@click.command()
@click.argument("src", metavar="IN", type=click.Path(dir_okay=False))
@click.argument("dst", metavar="OUT", type=click.Path(dir_okay=False))
@click.option("--crs", default=None, help="Assign this CRS to the input (EPSG:code or WKT); no coordinate change.")
@click.option("--to-crs", default=None, help="Reproject the coordinates into this CRS (pyproj).")
@click.option("--columns", default=None, help="Column spec for a text input, e.g. x,y,z,label.")
@click.option("--out-columns", default=None, help="Column spec for a text output.")
@click.option("--point-format", type=click.IntRange(0, 10), default=None, help="LAS point format of a LAS/LAZ output.")
@click.option("--las-version", type=click.Choice(["1.0", "1.1", "1.2", "1.3", "1.4"]), default=None,
              help="LAS version of a LAS/LAZ output (raised to what the point format needs).")
@overwrite_option
@click.option("--json", "as_json", is_flag=True, help="Print a summary as JSON on stdout.")
def convert(src, dst, crs, to_crs, columns, out_columns, point_format, las_version, overwrite, as_json):
    """Convert IN to OUT (LAS, LAZ, PLY, PCD, XYZ/TXT/CSV, E57), choosing formats by extension."""
    import time

    from workstation.core.log import get_logger
    from workstation.io import check_output, format_of, read_cloud, write_cloud
    from workstation.io.crs import parse_crs, reproject

    log = get_logger(__name__)
    t0 = time.perf_counter()
    format_of(src)
    format_of(dst)
    check_output(dst, overwrite, inputs=[src])
    if columns and format_of(src)[0] not in ("xyz", "txt", "csv", "pts"):
        raise click.UsageError("--columns applies to text inputs (.xyz, .txt, .csv, .pts) only")
    cloud = read_cloud(src, **({"columns": columns} if columns else {}))
    if crs:
        parse_crs(crs, "crs")
        cloud = cloud.with_crs(crs).with_history("assign_crs", {"crs": crs})
    if to_crs:
        cloud = reproject(cloud, to_crs)
    opts = {}
    out_fmt = format_of(dst)[0]
    if out_fmt in ("las", "laz"):
        if point_format is not None:
            opts["point_format"] = point_format
        if las_version is not None:
            opts["version"] = las_version
    elif point_format is not None or las_version is not None:
        raise click.UsageError("--point-format and --las-version apply to LAS/LAZ outputs only")
    if out_columns:
        if out_fmt not in ("xyz", "txt", "csv", "pts"):
            raise click.UsageError("--out-columns applies to text outputs only")
        opts["columns"] = out_columns
    write_cloud(cloud, dst, overwrite=overwrite, inputs=[src], **opts)
    dt = time.perf_counter() - t0
    log.info("wrote %s (%d points) in %.2f s", dst, cloud.n, dt)
    if as_json:
        emit_json({"input": src, "output": dst, "point_count": cloud.n, "crs": cloud.crs, "seconds": dt})
