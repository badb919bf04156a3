"""`ws ortho WORKDIR --dsm DSM.tif -o ORTHO.tif --resolution R`: true orthophoto."""

from __future__ import annotations

from pathlib import Path

import click

from workstation.cli.options import allow_outside_option
from workstation.raster.ortho import OrthoParams

from .options import emit_json, json_option, output_option, overwrite_option
from .options import GEOTIFF, require_suffix
from .options import FiniteFloatRange, field_option, nonneg_float, positive_float


@click.command()
@click.argument("workdir", type=click.Path(exists=True))
@click.option("--dsm", required=True, type=click.Path(exists=True, dir_okay=False), help="Surface model GeoTIFF (same CRS as the cameras).")
@output_option
@click.option("--resolution", type=positive_float, default=None, help="Ortho cell size in metres (default: the DSM's).")
@click.option("--images", "image_dir", type=click.Path(exists=True, file_okay=False), default=None,
              help="Image folder [default: the folder `ws sfm` recorded in WORKDIR, else WORKDIR/images].")
@field_option(OrthoParams, "blend_angle", "--blend-angle", type=FiniteFloatRange(0.0, 90.0), show_default=True,
              help="Degrees: views within about this of the most nadir one are blended across seams.")
@click.option("--no-occlusion", is_flag=True, help="Skip the visibility test (a conventional, not true, orthophoto).")
@click.option("--accuracy", "accuracy_out", type=click.Path(dir_okay=False), default=None,
              help="Also write the estimated planimetric accuracy (metres) as a GeoTIFF.")
@click.option("--dsm-rmse", type=nonneg_float, default=None, help="Vertical RMSE of the DSM in metres (accuracy estimate).")
@overwrite_option
@allow_outside_option
@json_option
def ortho(workdir, dsm, output, resolution, image_dir, blend_angle, no_occlusion, accuracy_out, dsm_rmse, overwrite, as_json):
    """True orthophoto of WORKDIR (COLMAP workdir/model folder, or a cameras JSON) over DSM:
    backward projection with distortion, occlusion test against the DSM, bilinear sampling,
    most-nadir view with seam blending. RGBA GeoTIFF, alpha 0 where no image sees the ground.

    The photos are found from the record of `ws sfm` unless --images is given and checked
    before any work; the stage record WORKDIR/ortho_OUT.json is written when WORKDIR is a folder."""
    from workstation.io.geotiff import read_raster, write_raster
    from workstation.photogrammetry.sfm import read_reconstruction
    from workstation.raster.ortho import true_ortho

    require_suffix(output, GEOTIFF, what="GeoTIFF")
    require_suffix(accuracy_out, GEOTIFF, "--accuracy", "GeoTIFF")
    from workstation.io import check_outputs
    from workstation.io.reconstruction import check_image_files, resolve_image_dir

    check_outputs([output, accuracy_out], overwrite, inputs=[dsm])
    image_dir = resolve_image_dir(workdir, image_dir)
    rec = read_reconstruction(workdir, image_dir)
    check_image_files(rec, image_dir, workdir)
    d = read_raster(dsm, band=1)
    res = true_ortho(rec, d, OrthoParams(resolution=resolution, blend_angle=blend_angle, occlusion=not no_occlusion,
                                         dsm_rmse=dsm_rmse))
    write_raster(res.ortho, output, overwrite=overwrite, inputs=[dsm], photometric="RGB")
    if accuracy_out:
        write_raster(res.accuracy, accuracy_out, overwrite=overwrite, inputs=[dsm])
    click.echo(f"coverage {100 * res.meta['coverage']:.1f} %, {res.meta['images_used']} images, "
               f"estimated accuracy {res.meta['accuracy_rms_m']:.3f} m RMS", err=True)
    from workstation.cli.summary import emit_summary, percent

    emit_summary("ortho", f"{res.ortho.shape[0]:,} x {res.ortho.shape[1]:,} cells", [output, accuracy_out],
                 details=[f"coverage {percent(res.meta['coverage'], 1)}", f"{res.meta['images_used']} images"])
    doc = {"output": output, **res.meta}
    if Path(workdir).is_dir():
        _write_record(doc, workdir, dsm, image_dir, output, accuracy_out,
                      {"resolution": resolution, "blend_angle": blend_angle, "occlusion": not no_occlusion,
                       "dsm_rmse": dsm_rmse})
    if as_json:
        emit_json(doc)


def _write_record(doc: dict, workdir, dsm, image_dir, output, accuracy_out, params: dict) -> None:
    """The ortho stage record WORKDIR/ortho_<OUT stem>.json."""
    from workstation.cli.summary import elapsed
    from workstation.io.reconstruction import stage_record, work_folder_of, write_stage_record

    rec = stage_record("ortho", doc, inputs={"reconstruction": workdir, "dsm": dsm, "image_dir": image_dir},
                       params=params, outputs=[output, accuracy_out], seconds=elapsed())
    write_stage_record(rec, work_folder_of(workdir) / f"ortho_{Path(output).stem}.json", required=False)
