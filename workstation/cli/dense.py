"""``ws dense``: dense cloud from an SfM workdir (depth maps + fusion)."""

from __future__ import annotations

from pathlib import Path

import click

from workstation.cli.options import allow_outside_option

from workstation.cli.options import emit_json, json_option, overwrite_option
from workstation.cli.options import FiniteFloatRange, SentinelIntRange, nonneg_float, nonneg_int, positive_float, positive_int
from workstation.cli.options import RegistryChoice, bound, param_group
from workstation.photogrammetry.dense import DEVICES, METHODS, DenseParams


@click.command()
@click.argument("workdir", type=click.Path(file_okay=False, exists=True))
@click.option("--images", "image_dir", type=click.Path(file_okay=False, exists=True), help="Folder of the original images [default: the folder `ws sfm` recorded in WORKDIR/summary.json, else WORKDIR/images].")
@click.option("-o", "--output", "output", type=click.Path(dir_okay=False), help="Also write the cloud here (.las, .laz, .ply).")
@param_group(
    "given",
    bound(DenseParams, "device", "--device", type=RegistryChoice(DEVICES), show_default=True,
          help="auto: COLMAP PatchMatch when pycolmap has CUDA, else the CPU --method."),
    bound(DenseParams, "method", "--method", type=RegistryChoice(METHODS), show_default=True,
          help="CPU depth maps: sgbm (rectified pairwise semi-global matching, fast) or sweep (multi-view plane sweep)."),
    bound(DenseParams, "max_image_size", "--max-image-size", type=SentinelIntRange(-1, min=1), show_default=True,
          help="Longest side of the images used for stereo, pixels (-1 = full size)."),
    bound(DenseParams, "num_sources", "--sources", "num_sources", type=positive_int,
          help="Source views per reference image (CPU path; default 3 for sgbm, 5 for sweep)."),
    bound(DenseParams, "min_ncc", "--min-ncc", type=FiniteFloatRange(-1.0, 1.0), show_default=True,
          help="Smallest aggregated NCC (-1..1) kept (sweep)."),
    bound(DenseParams, "min_consistent", "--min-consistent", type=nonneg_int, show_default=True,
          help="Source depth maps that must confirm a depth (CPU path)."),
    bound(DenseParams, "fusion_cache_gb", "--fusion-cache-gb", type=nonneg_float, show_default=True,
          help="GB of images and depth/normal maps fusion keeps in memory (0 = load all: faster for a few images, "
               "memory grows with the image count)."),
    bound(DenseParams, "depth_range", "--depth-range", nargs=2, type=positive_float,
          help="NEAR FAR depth in model units for every image (needed when the model has no sparse points, e.g. true rig cameras)."),
)
@overwrite_option
@allow_outside_option
@json_option
def dense(workdir, image_dir, output, given, overwrite, as_json):
    """Dense reconstruction of WORKDIR (from `ws sfm`, or a synthetic rig folder).

    Undistorts the images into WORKDIR/dense (COLMAP layout), computes depth and normal maps
    (stereo/depth_maps, stereo/normal_maps) and fuses them into WORKDIR/dense/fused.ply
    (points in the model frame with colours and normals). The photos are found without
    --images from the record of `ws sfm`; the model, the image folder and every image the
    model names are checked before any work. Writes the stage record WORKDIR/dense/summary.json
    (shown by `ws report WORKDIR`). --overwrite replaces WORKDIR/dense and the -o file.
    """
    from workstation.io.reconstruction import check_image_files, resolve_image_dir
    from workstation.photogrammetry.dense import resolve_device, run_dense

    if output is not None and Path(output).suffix.lower() not in (".las", ".laz", ".ply"):
        from workstation.core.errors import InvalidInputError

        raise InvalidInputError("output must be .las, .laz or .ply", path=output)
    from workstation.io import check_outputs, work_folder

    check_outputs([output], overwrite, inputs=[])
    _check_dense_folder(Path(workdir) / "dense", overwrite)
    resolve_device(given["device"])  # every input checked before the long run
    names = _model_image_names(workdir)
    image_dir = resolve_image_dir(workdir, image_dir) or Path(workdir) / "images"
    check_image_files(names, image_dir, workdir)
    depth_range = given["depth_range"]
    params = DenseParams(**{**given, "depth_range": tuple(depth_range) if depth_range else None},
                         top_k=min(2, given["num_sources"] or 2))
    with work_folder(Path(workdir) / "dense"):  # a failed run removes what it wrote
        cloud, summary = run_dense(workdir, image_dir, params, overwrite=overwrite)
    if output is not None:
        from workstation.io import write_cloud

        write_cloud(cloud, output, overwrite=overwrite, inputs=[summary["fused"]])
        summary["output"] = str(output)
    from workstation.cli.summary import count, emit_summary

    write_dense_record(workdir, image_dir, params, summary, output)
    emit_summary("dense", count(summary["points"], "points"), [summary["fused"], output], details=summary["device"])
    if as_json:
        emit_json(summary)


def _check_dense_folder(dense_dir: Path, overwrite: bool) -> None:
    """Refuse an existing, non-empty WORKDIR/dense without --overwrite (before any work)."""
    if dense_dir.is_dir() and any(dense_dir.iterdir()) and not overwrite:
        from workstation.core.errors import OutputExistsError

        raise OutputExistsError(dense_dir)


def _model_image_names(workdir) -> list[str]:
    """Names of the registered images of the workdir's COLMAP model (read by pycolmap, no
    per-point conversion, so the check is quick on large models)."""
    from workstation.interop.pycolmap import import_pycolmap
    from workstation.photogrammetry.dense import find_model

    rec = import_pycolmap().Reconstruction(str(find_model(workdir)))
    return [im.name for im in rec.images.values() if im.has_pose]


def write_dense_record(workdir, image_dir, params, summary: dict, output=None) -> Path:
    """The dense stage record WORKDIR/dense/summary.json: the run's summary (device, points,
    timings), the image folder, the DenseParams and the outputs (shown by `ws report`)."""
    import dataclasses

    from workstation.cli.summary import elapsed
    from workstation.io.reconstruction import stage_record, write_stage_record

    rec = stage_record("dense", summary, inputs={"workdir": workdir, "image_dir": image_dir},
                       params=dataclasses.asdict(params), outputs=[summary["fused"], output], seconds=elapsed())
    return write_stage_record(rec, Path(workdir) / "dense" / "summary.json")
