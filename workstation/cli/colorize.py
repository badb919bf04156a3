"""`ws colorize CLOUD --reconstruction WORKDIR -o OUT`: colour a cloud from oriented photos."""

from __future__ import annotations

import click

from workstation.cli.options import allow_outside_option, read_options

from workstation.cli.options import (
    emit_json,
    json_option,
    output_option,
    overwrite_option,
)
from workstation.cli.options import positive_float, positive_int


@click.command("colorize")
@click.argument("cloud", type=click.Path(exists=True, dir_okay=False))
@click.option("--reconstruction", "workdir", required=True, type=click.Path(exists=True),
              help="COLMAP work folder (model in sparse/0, images in images/), or a cameras JSON "
                   "(or a folder holding cameras.json) as `ws ortho` reads.")
@output_option
@click.option("--images", "image_dir", type=click.Path(exists=True, file_okay=False), default=None,
              help="Folder of the images (default WORKDIR/images).")
@click.option("--max-views", type=positive_int, default=3, show_default=True, help="Best views blended per point.")
@click.option("--depth-maps", "use_depth_maps", is_flag=True,
              help="Test visibility against the MVS depth maps of WORKDIR/dense (ws sfm --dense) and colour from "
                   "its undistorted images, instead of a z-buffer of the cloud (also catches occluders the cloud "
                   "does not hold; pixels without a depth are not used).")
@click.option("--depth-tolerance", type=positive_float, default=None,
              help="Metres a point may lie behind the visible surface and still be painted (default 3 x spacing).")
@overwrite_option
@allow_outside_option
@read_options
@json_option
def colorize(cloud, workdir, output, image_dir, max_views, use_depth_maps, depth_tolerance, overwrite, read_opts,
             as_json):
    """Colour CLOUD from the oriented photos of a reconstruction; occluded points are not painted.

    Adds rgb, colorized (1 painted, 0 seen by no image) and color_views.
    """
    from pathlib import Path

    from workstation.interop.pycolmap import read_model
    from workstation.io import check_output, read_cloud, write_cloud
    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.registration.colorize import ColorizeParams, read_depth_maps
    from workstation.registration.colorize import colorize as run_colorize

    check_output(output, overwrite, inputs=[cloud])
    c = read_cloud(cloud, **read_opts)
    depth_maps = None
    if use_depth_maps:
        dense = Path(workdir) / "dense"
        rec = read_model(dense, image_dir)
        depth_maps = read_depth_maps(dense, rec)
    else:  # a COLMAP work folder or a cameras JSON
        rec = read_reconstruction(workdir, image_dir)
    out = run_colorize(c, rec, ColorizeParams(max_views=max_views, depth_tolerance=depth_tolerance),
                       depth_maps=depth_maps)
    write_cloud(out, output, overwrite=overwrite, inputs=[cloud])
    import numpy as np

    from workstation.cli.summary import count, emit_summary, percent

    n_painted = int(np.count_nonzero(np.asarray(out.attrs["colorized"]))) if "colorized" in out.attrs else 0
    emit_summary("colorize", count(out.n, "points"), output,
                 details=[f"painted {percent(n_painted, out.n)}", count(len(rec.images), "images")])
    if as_json:
        painted = int(out.attrs["colorized"].sum())
        emit_json({"output": str(output), "points": out.n, "painted": painted, "images": len(rec.images)})
