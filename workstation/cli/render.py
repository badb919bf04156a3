"""`ws render IN -o OUT.png`: an off-screen picture of a cloud or mesh (no display needed)."""

from __future__ import annotations

import click

from workstation.cli.options import allow_outside_option
from workstation.render.render import VIEWS, RenderParams

from .options import emit_json, json_option, output_option, overwrite_option
from .options import nonneg_float, nonneg_int, read_options
from .options import RegistryChoice, bound, field_default, param_group


def _size(ctx, param, value):
    """--size WIDTHxHEIGHT: two pixel counts in the renderer's range (16..8192)."""
    try:
        w, h = (int(v) for v in value.lower().split("x"))
    except ValueError:
        raise click.BadParameter("give WIDTHxHEIGHT in pixels, e.g. 1920x1080") from None
    if not (16 <= w <= 8192 and 16 <= h <= 8192):
        raise click.BadParameter(f"{w}x{h}: each side must be 16..8192 pixels")
    return w, h


def _background(ctx, param, value):
    """--background: a colour pyvista knows (a name or #rrggbb), checked before any work."""
    import difflib

    import pyvista as pv

    try:
        pv.Color(value)
    except ValueError:
        from pyvista.plotting.colors import hex_colors

        near = difflib.get_close_matches(value.lower(), list(hex_colors), n=6, cutoff=0.5)
        raise click.BadParameter(f"unknown colour {value!r}; use #rrggbb or a name such as "
                                 + ", ".join(near or ["white", "black", "lightgray", "navy", "beige"])) from None
    return value


@click.command()
@click.argument("src", metavar="IN", type=click.Path(exists=True, dir_okay=False))
@output_option
@param_group(
    "given",
    bound(RenderParams, "color", "--color", show_default=True,
          help="auto, rgb, class, elevation, intensity, hag, uniform, or any attribute name."),
    bound(RenderParams, "view", "--view", type=RegistryChoice(VIEWS), show_default=True,
          help="top: orthographic, north up, scale bar; front: looking north; iso: from the south-east."),
    bound(RenderParams, "size", "--size", default="x".join(map(str, field_default(RenderParams, "size"))),
          show_default=True, callback=_size, help="Image size WIDTHxHEIGHT in pixels."),
    bound(RenderParams, "background", "--background", show_default=True, callback=_background,
          help="Background colour (name or #rrggbb)."),
    bound(RenderParams, "point_size", "--point-size", type=nonneg_float, show_default=True,
          help="Point diameter in pixels (0 = from the point density)."),
    bound(RenderParams, "edl", "--edl", is_flag=True, help="Eye-dome lighting for clouds (shades depth edges)."),
)
@click.option("--no-legend", is_flag=True, help="No class legend or scalar bar.")
@param_group("given", bound(RenderParams, "max_points", "--max-points", type=nonneg_int, show_default=True,
                            help="Draw a seeded random subset of at most this many points (0 = all)."))
@click.option("--turntable", type=click.IntRange(0, 720), default=0, show_default=True,
              help="Frames of a turntable orbit: OUT.gif is an animation, OUT.png a numbered PNG sequence.")
@click.option("--reconstruction", "workdir", type=click.Path(exists=True), default=None,
              help="COLMAP work folder (or model folder, or cameras.json) holding the camera of --camera.")
@click.option("--camera", "camera_ref", default=None, metavar="IMAGE",
              help="Render through the camera of this image (name or id) of --reconstruction: its intrinsics, "
                   "pose and image size (replaces --view and --size), so the render overlays the photo.")
@read_options
@overwrite_option
@allow_outside_option
@json_option
def render(src, output, given, no_legend, turntable, workdir, camera_ref, read_opts, overwrite, as_json):
    """Render the cloud or mesh IN to OUT (.png, or .gif with --turntable); --bounds renders only
    the points inside a box (a COPC file queried, --level/--resolution a coarser cloud)."""
    import time
    from pathlib import Path

    from workstation.core.errors import InvalidInputError
    from workstation.io import check_output
    from workstation.render import save_gif, save_png
    from workstation.render import render as render_image
    from workstation.render import turntable as turntable_frames
    from workstation.render.load import load_product

    out = Path(output)
    if out.suffix.lower() not in (".png", ".gif"):
        raise InvalidInputError("the output must be .png or .gif", path=out)
    if out.suffix.lower() == ".gif" and not turntable:
        raise InvalidInputError("a .gif output needs --turntable N", path=out)
    if (workdir is None) != (camera_ref is None):
        raise InvalidInputError("--camera and --reconstruction go together",
                                "give the reconstruction and the image whose camera to use")
    if camera_ref is not None and turntable:
        raise InvalidInputError("--turntable orbits its own camera", "leave out --camera or --turntable")
    check_output(out, overwrite, inputs=[src])
    t0 = time.perf_counter()
    view_camera, size, color = None, given["size"], given["color"]
    if camera_ref is not None:
        from workstation.photogrammetry.sfm import read_reconstruction
        from workstation.render.render import find_image, reconstruction_view

        rec = read_reconstruction(workdir)
        view_camera = reconstruction_view(rec, find_image(rec, camera_ref))
        size = (view_camera[0].width, view_camera[0].height)
    obj = load_product(src, **read_opts)
    params = RenderParams(**{**given, "size": size}, legend=not no_legend)
    files = []
    if turntable:
        frames = turntable_frames(obj, params, frames=turntable)
        if out.suffix.lower() == ".gif":
            save_gif(frames, out, overwrite=overwrite, inputs=[src])
            files.append(str(out))
        else:
            for i, f in enumerate(frames):
                p = out.with_name(f"{out.stem}_{i:03d}.png")
                save_png(f, p, overwrite=overwrite, inputs=[src])
                files.append(str(p))
    else:
        save_png(render_image(obj, params, camera=view_camera), out, overwrite=overwrite, inputs=[src])
        files.append(str(out))
    from workstation.cli.summary import count, emit_summary

    emit_summary("render", count(len(files), "images"), files if len(files) <= 3 else [files[0], "..."],
                 time.perf_counter() - t0, details=[f"{size[0]}x{size[1]} px", f"colour {color}"])
    if as_json:
        emit_json({"input": src, "files": files, "size": list(size), "color": color,
                   "view": f"camera {camera_ref}" if camera_ref is not None else given["view"],
                   "seconds": time.perf_counter() - t0})
