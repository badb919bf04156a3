"""`ws colorize CLOUD --reconstruction WORKDIR -o OUT`: colour a cloud from oriented photos."""

from __future__ import annotations

from pathlib import Path

import click

from workstation.cli.options import emit_json, json_option, output_option, overwrite_option


def read_colmap(workdir):
    """A :class:`~workstation.core.products.Reconstruction` from a COLMAP model (text or binary).

    Looks for the model in ``WORKDIR/sparse/0``, ``WORKDIR/sparse`` or ``WORKDIR``; image paths
    are ``WORKDIR/images/<name>``. (Kept here until the photogrammetry interop reader lands.)
    """
    import numpy as np

    from workstation.core.errors import InvalidInputError, MissingDependencyError
    from workstation.core.products import Camera, Image, Pose, Reconstruction

    try:
        import pycolmap
    except ImportError as e:  # pragma: no cover
        raise MissingDependencyError("pycolmap", "reading COLMAP reconstructions") from e
    w = Path(workdir)
    model = next((d for d in (w / "sparse" / "0", w / "sparse", w)
                  if (d / "cameras.bin").exists() or (d / "cameras.txt").exists()), None)
    if model is None:
        raise InvalidInputError("no COLMAP model (cameras.bin/.txt) found", "give the SfM work folder", path=w)
    rec = pycolmap.Reconstruction(str(model))
    cams = {}
    for cid, c in rec.cameras.items():
        p = list(c.params)
        name = c.model_name if hasattr(c, "model_name") else str(c.model)
        if name in ("SIMPLE_PINHOLE", "SIMPLE_RADIAL", "RADIAL"):
            f, cx, cy = p[:3]
            k = (p[3:] + [0.0, 0.0])[:2]
            cams[cid] = Camera(c.width, c.height, f, f, cx, cy, dist=(k[0], k[1], 0.0, 0.0, 0.0), model=name)
        elif name in ("PINHOLE", "OPENCV", "FULL_OPENCV"):
            fx, fy, cx, cy = p[:4]
            d = (p[4:] + [0.0] * 5)[:4] + [p[8] if name == "FULL_OPENCV" else 0.0]
            cams[cid] = Camera(c.width, c.height, fx, fy, cx, cy, dist=tuple(d), model=name)
        else:
            raise InvalidInputError(f"camera model {name} is not supported", "undistort the images first")
    images = {}
    for iid, im in rec.images.items():
        if hasattr(im, "has_pose") and not im.has_pose:
            continue
        cfw = im.cam_from_world() if callable(im.cam_from_world) else im.cam_from_world
        M = np.asarray(cfw.matrix())
        images[iid] = Image(im.name, im.camera_id, Pose(M[:3, :3], M[:3, 3]), str(w / "images" / im.name))
    return Reconstruction(cams, images)


@click.command("colorize")
@click.argument("cloud", type=click.Path(exists=True, dir_okay=False))
@click.option("--reconstruction", "workdir", required=True, type=click.Path(exists=True, file_okay=False),
              help="COLMAP work folder (model in sparse/0, images in images/).")
@output_option
@click.option("--images", "image_dir", type=click.Path(exists=True, file_okay=False), default=None,
              help="Folder of the images (default WORKDIR/images).")
@click.option("--max-views", type=int, default=3, show_default=True, help="Best views blended per point.")
@click.option("--depth-tolerance", type=float, default=None,
              help="Metres a point may lie behind the visible surface and still be painted (default 3 x spacing).")
@overwrite_option
@json_option
def colorize(cloud, workdir, output, image_dir, max_views, depth_tolerance, overwrite, as_json):
    """Colour CLOUD from the oriented photos of a reconstruction; occluded points are not painted.

    Adds rgb, colorized (1 painted, 0 seen by no image) and color_views.
    """
    from dataclasses import replace

    from workstation.core.products import Image, Reconstruction
    from workstation.io import check_output, read_cloud, write_cloud
    from workstation.registration.colorize import ColorizeParams
    from workstation.registration.colorize import colorize as run_colorize

    check_output(output, overwrite, inputs=[cloud])
    c = read_cloud(cloud)
    rec = read_colmap(workdir)
    if image_dir:
        rec = Reconstruction(rec.cameras, {k: replace(v, path=str(Path(image_dir) / v.name)) for k, v in rec.images.items()},
                             rec.points, rec.colors, rec.crs, rec.meta)
    out = run_colorize(c, rec, ColorizeParams(max_views=max_views, depth_tolerance=depth_tolerance))
    write_cloud(out, output, overwrite=overwrite, inputs=[cloud])
    if as_json:
        painted = int(out.attrs["colorized"].sum())
        emit_json({"output": str(output), "points": out.n, "painted": painted, "images": len(rec.images)})
