"""`ws publish WORK_OR_PRODUCTS... -o SITE [--serve]`: a static web viewer of the products."""

from __future__ import annotations

from pathlib import Path

import click

from .options import emit_json, json_option, overwrite_option, read_options


@click.command()
@click.argument("inputs", nargs=-1, required=True, type=click.Path(exists=True))
@click.option("-o", "--output", "output", type=click.Path(file_okay=False), default=None,
              help="Site folder to write (index.html, site.json, clouds/, rasters/, viewer/). "
                   "Optional with --serve when INPUT is already a published site.")
@click.option("--title", default=None, help="Page title (default: the name of the first input).")
@click.option("--preview-size", type=click.IntRange(min=16), default=2048, show_default=True,
              help="Longest side of the raster preview PNGs, pixels.")
@click.option("--3d-tiles", "tiles3d", is_flag=True,
              help="Also write 3D Tiles 1.1 (CesiumJS) of every cloud and mesh (OBJ, PLY with faces) in "
                   "SITE/3dtiles/NAME/tileset.json, georeferenced (ECEF) when the data has a CRS.")
@click.option("--serve", is_flag=True, help="Then serve the site on localhost (with HTTP Range support) until Ctrl-C.")
@click.option("--port", type=click.IntRange(0, 65535), default=8000, show_default=True,
              help="Port of --serve (0 picks a free one).")
@click.option("--host", default="127.0.0.1", show_default=True, help="Address --serve listens on.")
@read_options
@overwrite_option
@json_option
def publish(inputs, output, title, preview_size, tiles3d, serve, port, host, read_opts, overwrite, as_json):
    """Publish INPUTS (work or product folders, or cloud/raster files) as a static web site.

    LAS/LAZ clouds become COPC files streamed by level of detail; hillshade, DTM and ortho
    GeoTIFFs become map previews; cameras.json / COLMAP models become camera frusta. The
    folder works on any static web server that supports HTTP Range requests, with no network
    access (the JavaScript is vendored, with its licences, in SITE/viewer/). With --3d-tiles,
    clouds and meshes are also written as 3D Tiles tilesets for CesiumJS and other 3D Tiles
    viewers. --bounds/--resolution/--level publish only the points they select from each cloud
    (not with --3d-tiles, whose tilesets are built from the whole clouds).
    """
    from workstation.cli.summary import count, emit_summary
    from workstation.publish.site import PublishParams, publish_site

    if output is None:
        if not (serve and len(inputs) == 1 and (Path(inputs[0]) / "site.json").is_file()):
            raise click.UsageError("give -o SITE (or --serve with a published site as the only input)")
        return _serve(Path(inputs[0]), host, port)
    if tiles3d and any(v is not None for v in read_opts.values()):
        raise click.UsageError("--3d-tiles tiles the whole clouds: leave out --bounds, --resolution and --level")
    res = publish_site(list(inputs), output, overwrite=overwrite,
                       params=PublishParams(title=title, preview_px=preview_size, tiles3d=tiles3d,
                                                           read_opts=read_opts))
    doc = res.doc
    emit_summary("publish", f"{count(res.points, 'points')} in {count(len(doc['clouds']), 'clouds')}", res.site / "index.html",
                 res.seconds, details=[count(len(doc["rasters"]), "rasters"), count(len(doc["cameras"]), "cameras"),
                                       *([count(len(doc["tilesets"]), "3D Tiles tilesets")]
                                         if "tilesets" in doc else [])])
    if as_json:
        emit_json({"site": str(res.site), "index": str(res.site / "index.html"), "points": res.points,
                   "clouds": [{k: c[k] for k in ("name", "url", "points", "levels", "nodes")} for c in doc["clouds"]],
                   "rasters": [{k: r[k] for k in ("name", "kind", "url")} for r in doc["rasters"]],
                   "cameras": len(doc["cameras"]), "tilesets": doc.get("tilesets", []), "seconds": res.seconds})
    if serve:
        _serve(res.site, host, port)


def _serve(site: Path, host: str, port: int) -> None:
    """Serve ``site`` until Ctrl-C (which the error boundary turns into exit code 130)."""
    from workstation.publish.site import make_server

    server = make_server(site, host, port)
    h, p = server.server_address[:2]
    click.echo(f"Serving {site} at http://{h}:{p}/ (Ctrl-C to stop)", err=True)
    try:
        server.serve_forever()
    finally:
        server.server_close()
