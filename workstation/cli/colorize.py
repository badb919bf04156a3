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
from workstation.cli.options import field_option, positive_float, positive_int
from workstation.registration.colorize import ColorizeParams


@click.command("colorize")
@click.argument("cloud", type=click.Path(exists=True, dir_okay=False))
@click.option("--reconstruction", "workdir", required=True, type=click.Path(exists=True),
              help="COLMAP work folder (model in sparse/0, images in images/), or a cameras JSON "
                   "(or a folder holding cameras.json) as `ws ortho` reads.")
@output_option
@click.option("--images", "image_dir", type=click.Path(exists=True, file_okay=False), default=None,
              help="Folder of the images [default: the folder `ws sfm` recorded in WORKDIR, else WORKDIR/images].")
@field_option(ColorizeParams, "max_views", "--max-views", type=positive_int, show_default=True,
              help="Best views blended per point.")
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

    Adds rgb, colorized (1 painted, 0 seen by no image) and color_views. The photos are found
    from the record of `ws sfm` unless --images is given, and checked (with the model) before
    the cloud is read; the stage record WORKDIR/colorize_OUT.json is written when WORKDIR is
    a folder.
    """
    from pathlib import Path

    import numpy as np

    from workstation.cli.summary import count, emit_summary, percent
    from workstation.io import check_output, read_cloud, write_cloud
    from workstation.registration.colorize import colorize as run_colorize

    check_output(output, overwrite, inputs=[cloud])
    rec, depth_maps, image_dir = _read_views(workdir, image_dir, use_depth_maps)  # checked before the cloud is read
    c = read_cloud(cloud, **read_opts)
    params = ColorizeParams(max_views=max_views, depth_tolerance=depth_tolerance)
    out = run_colorize(c, rec, params, depth_maps=depth_maps)
    write_cloud(out, output, overwrite=overwrite, inputs=[cloud])
    n_painted = int(np.count_nonzero(np.asarray(out.attrs["colorized"]))) if "colorized" in out.attrs else 0
    emit_summary("colorize", count(out.n, "points"), output,
                 details=[f"painted {percent(n_painted, out.n)}", count(len(rec.images), "images")])
    doc = {"output": str(output), "points": out.n, "painted": n_painted, "images": len(rec.images)}
    if Path(workdir).is_dir():
        _write_record(doc, cloud, workdir, image_dir, params, use_depth_maps, output)
    if as_json:
        emit_json(doc)


def _read_views(workdir, image_dir, use_depth_maps: bool):
    """(reconstruction, depth maps or None, image folder): the photos of WORKDIR with the image
    folder from the `ws sfm` record unless --images is given, or with --depth-maps the
    undistorted images and depth maps of WORKDIR/dense; every image checked on disk."""
    from pathlib import Path

    from workstation.interop.pycolmap import read_model
    from workstation.io.reconstruction import check_image_files, resolve_image_dir
    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.registration.colorize import read_depth_maps

    if use_depth_maps:
        dense = Path(workdir) / "dense"
        rec = read_model(dense, image_dir)
        check_image_files(rec, image_dir, dense)
        return rec, read_depth_maps(dense, rec), image_dir
    image_dir = resolve_image_dir(workdir, image_dir)
    rec = read_reconstruction(workdir, image_dir)
    check_image_files(rec, image_dir, workdir)
    return rec, None, image_dir


def _write_record(doc: dict, cloud, workdir, image_dir, params, use_depth_maps: bool, output) -> None:
    """The colorize stage record WORKDIR/colorize_<OUT stem>.json."""
    import dataclasses
    from pathlib import Path

    from workstation.cli.summary import elapsed
    from workstation.io.reconstruction import stage_record, work_folder_of, write_stage_record

    rec = stage_record("colorize", doc, inputs={"cloud": cloud, "reconstruction": workdir, "image_dir": image_dir},
                       params={**dataclasses.asdict(params), "depth_maps": use_depth_maps}, outputs=[output],
                       seconds=elapsed())
    write_stage_record(rec, work_folder_of(workdir) / f"colorize_{Path(output).stem}.json", required=False)
