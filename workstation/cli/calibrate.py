"""`ws calibrate {zhang,dlt}`: camera calibration to CAMERA.json."""

from __future__ import annotations

import re
from pathlib import Path

import click

from workstation.cli.options import emit_json, json_option, output_option, overwrite_option
from workstation.cli.options import FiniteFloatRange, field_option, positive_float
from workstation.core.errors import InvalidInputError
from workstation.photogrammetry.calibration import ZhangParams


def _pair(text: str, what: str, cast=int):
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*[xX×,]\s*(\d+(?:\.\d+)?)\s*", text or "")
    if not m:
        raise InvalidInputError(f"{what} must look like 13x12, got {text!r}")
    return cast(float(m.group(1))), cast(float(m.group(2)))


def _report(result, out: Path, as_json: bool) -> None:
    from workstation.core.log import get_logger

    log = get_logger("workstation.cli.calibrate")
    c = result.camera
    for d in result.dropped:
        log.warning("dropped %s: %s", d["name"], d["reason"])
    from workstation.cli.summary import emit_summary

    emit_summary(f"calibrate {result.method}", f"camera fx {c.fx:.2f} fy {c.fy:.2f} cx {c.cx:.2f} cy {c.cy:.2f} "
                 f"skew {c.skew:.3f} px, dist {', '.join(f'{v:.5f}' for v in c.dist)}", out,
                 details=[f"RMS {result.rms:.3f} px", f"{len(result.per_image)} image(s) used",
                          f"{len(result.dropped)} dropped"])
    if as_json:
        emit_json(result.to_dict())


@click.group("calibrate")
def calibrate():
    """Calibrate a camera: Zhang's planar method or the DLT from 3-D control points.

    Writes CAMERA.json (schema in workstation.io.camera: model, width, height, fx, fy, cx, cy,
    skew, dist = [k1, k2, p1, p2, k3], rms, std, per_image, dropped, extrinsics), which
    `ws sfm --camera` accepts.
    """


@calibrate.command("zhang")
@click.argument("images", required=False, type=click.Path(file_okay=False))
@click.option("--board", help="Checkerboard inner corners COLSxROWS, e.g. 13x12.")
@click.option("--square", type=positive_float, help="Checkerboard square size (its unit is the unit of the extrinsics, e.g. mm).")
@click.option("--model", "model_file", type=click.Path(dir_okay=False), help="Target model text file (x y pairs) for other targets.")
@click.option("--corners", "corners_dir", type=click.Path(file_okay=False), help="Folder of per-image corner text files (x y pairs, same order as the model).")
@click.option("--image-size", help="Image size WIDTHxHEIGHT in pixels (needed with --corners when the folder has no images).")
@click.option("--free-k3", is_flag=True, help="Also estimate the 6th-order radial term k3 (wide-angle lenses).")
@click.option("--no-tangential", is_flag=True, help="Hold the tangential terms p1, p2 at 0.")
@click.option("--skew", "estimate_skew", is_flag=True, help="Also estimate the skew K[0,1] in pixels (joint refinement after OpenCV).")
@field_option(ZhangParams, "outlier_factor", "--outlier-factor", type=FiniteFloatRange(min=1.0), show_default=True, help="Drop images whose RMS exceeds this multiple of the median per-image RMS.")
@output_option
@overwrite_option
@json_option
def zhang(images, board, square, model_file, corners_dir, image_size, free_k3, no_tangential, estimate_skew, outlier_factor, output, overwrite, as_json):
    """Zhang's method from >= 3 views of a planar target.

    Either IMAGES/ with --board COLSxROWS --square SIZE (checkerboard found by OpenCV and refined
    to sub-pixel), or --model MODEL.txt --corners DIR (Zhang's own text layout).
    """
    from workstation.io.atomic import check_output
    from workstation.io.camera import write_camera
    from workstation.photogrammetry.calibration import (
        calibrate_zhang,
        calibrate_zhang_images,
        list_images,
        read_corner_files,
    )

    check_output(output, overwrite)
    params = ZhangParams(fix_k3=not free_k3, fix_tangential=no_tangential, outlier_factor=outlier_factor, estimate_skew=estimate_skew)
    if model_file or corners_dir:
        if not (model_file and corners_dir):
            raise InvalidInputError("--model and --corners go together")
        model, views = read_corner_files(model_file, corners_dir)
        if image_size:
            size = _pair(image_size, "--image-size")
        else:
            folder = Path(images) if images else Path(corners_dir)
            try:
                first = list_images(folder)[0]
            except InvalidInputError:
                raise InvalidInputError(
                    "the image size is unknown", "pass --image-size WIDTHxHEIGHT", path=folder
                ) from None
            import cv2

            img = cv2.imread(str(first), cv2.IMREAD_UNCHANGED)
            if img is None:
                raise InvalidInputError("cannot read the image", "pass --image-size WIDTHxHEIGHT", path=first)
            size = (img.shape[1], img.shape[0])
        result = calibrate_zhang(model, views, size, params)
    else:
        if not images or not board or square is None:
            raise InvalidInputError(
                "give IMAGES/ with --board COLSxROWS and --square SIZE, or --model and --corners",
                "e.g. ws calibrate zhang photos/ --board 9x6 --square 25 -o camera.json",
            )
        cols, rows = _pair(board, "--board")
        if square <= 0:
            raise InvalidInputError("--square must be positive", field="square")
        result = calibrate_zhang_images(images, cols, rows, square, params)
    write_camera(result, output, overwrite=overwrite)
    _report(result, Path(output), as_json)


@calibrate.command("dlt")
@click.argument("points", type=click.Path(dir_okay=False))
@click.option("--image-size", required=True, help="Image size WIDTHxHEIGHT in pixels.")
@click.option("--refine", is_flag=True, help="Refine the DLT camera on the collinearity equations (gives standard deviations).")
@click.option("--distortion", type=click.Choice(["0", "2", "5"]), default="0", show_default=True, help="Distortion terms estimated by --refine: 0, 2 (k1 k2) or 5 (k1 k2 p1 p2 k3).")
@click.option("--no-skew", is_flag=True, help="Hold the skew at 0 in --refine.")
@output_option
@overwrite_option
@json_option
def dlt(points, image_size, refine, distortion, no_skew, output, overwrite, as_json):
    """11-parameter DLT from >= 6 non-coplanar control points.

    POINTS: CSV or text with columns name X Y Z u v (object units; pixels with the origin at the
    centre of the top-left pixel).
    """
    from workstation.io.atomic import check_output
    from workstation.io.camera import write_camera
    from workstation.photogrammetry.calibration import DLTParams, calibrate_dlt, read_control_points

    check_output(output, overwrite, inputs=[points])
    names, X, uv = read_control_points(points)
    size = _pair(image_size, "--image-size")
    result = calibrate_dlt(
        X, uv, size, DLTParams(refine=refine, distortion=int(distortion), estimate_skew=not no_skew), name=Path(points).stem
    )
    write_camera(result, output, overwrite=overwrite, inputs=[points])
    _report(result, Path(output), as_json)
