"""`ws sfm IMAGES/ -o WORKDIR`: structure from motion with pycolmap, optional GCP georeferencing."""

from __future__ import annotations

import json
from pathlib import Path

import click

from workstation.cli.options import allow_outside_option

from workstation.cli.options import emit_json, json_option, overwrite_option
from workstation.cli.options import SentinelIntRange, positive_float, positive_int
from workstation.cli.options import RegistryChoice, bound, field_option, param_group
from workstation.photogrammetry.dense import DEVICES, DenseParams
from workstation.photogrammetry.georef import ADJUSTMENTS, georeference
from workstation.photogrammetry.sfm import CAMERA_SHARING, MAPPERS, MATCHERS, SfMParams
from workstation.core.jsonutil import json_clean


@click.command("sfm")
@click.argument("images", type=click.Path(file_okay=False))
@click.option("-o", "--output", "workdir", required=True, type=click.Path(file_okay=False), help="Work folder (COLMAP layout: database.db, sparse/0 = largest model).")
@click.option("--camera", "camera_file", type=click.Path(dir_okay=False), help="CAMERA.json from `ws calibrate`; intrinsics kept fixed unless --refine-intrinsics.")
@param_group("given", bound(SfMParams, "refine_intrinsics", "--refine-intrinsics", is_flag=True,
                            help="Refine the --camera intrinsics in the bundle adjustments."))
@click.option("--gcp", "gcp_file", type=click.Path(dir_okay=False), help="GCP.csv (schema in workstation.io.gcp): control points fix a 7-parameter similarity (then a bundle adjustment with GCP constraints), check points give the accuracy.")
@field_option(georeference, "adjustment", "--gcp-adjustment", type=RegistryChoice(ADJUSTMENTS), show_default=True, help="After the similarity: bundle adjustment with the control points' image observations and σ (auto = when ≥ 3 control points have ≥ 2 image observations), or the similarity alone.")
@click.option("--crs", help="CRS of the GCP coordinates (EPSG code or WKT), recorded on the georeferenced outputs.")
@param_group(
    "given",
    bound(SfMParams, "matcher", "--matcher", type=RegistryChoice(MATCHERS), show_default=True,
          help="Image pairing: auto = exhaustive up to 60 images, then spatial (GPS) or retrieval "
               "(sequential in name order plus each photo's 10 most similar photos, which closes loops)."),
    bound(SfMParams, "mapper", "--mapper", type=RegistryChoice(MAPPERS), show_default=True,
          help="Incremental (COLMAP) or global (GLOMAP) mapping."),
    bound(SfMParams, "max_image_size", "--max-image-size", type=SentinelIntRange(-1, min=1), show_default=True,
          help="Longest image side used for features, pixels (-1 = full size)."),
    bound(SfMParams, "max_features", "--max-features", type=positive_int, show_default=True,
          help="SIFT features per image."),
    bound(SfMParams, "camera_model", "--camera-model", show_default=True,
          help="COLMAP model for self-calibration (SIMPLE_RADIAL, RADIAL, OPENCV...)."),
    bound(SfMParams, "cameras", "--cameras", type=RegistryChoice(CAMERA_SHARING), show_default=True,
          help="Which photos share self-calibrated intrinsics: auto = one camera per group of one image size "
               "and one EXIF make, model and focal length (photos without EXIF: by size), single = one for "
               "all (same size only), per-image = one each (internet photos resized to one size)."),
)
@click.option("--no-principal-point", is_flag=True, help="Keep the principal point fixed in the final bundle adjustment.")
@click.option("--no-final-ba", is_flag=True, help="Skip the final robust bundle adjustment (plain COLMAP result).")
@field_option(georeference, "sigma_px", "--sigma-px", type=positive_float, show_default=True,
              help="A-priori GCP image measurement precision, pixels.")
@param_group(
    "given",
    bound(SfMParams, "seed", "--seed", type=SentinelIntRange(-1, min=0), show_default=True,
          help="Random seed (-1 = random)."),
    bound(SfMParams, "num_threads", "--threads", type=SentinelIntRange(-1, min=1), show_default=True,
          help="COLMAP threads (-1 = all cores). With one thread on the CPU a run repeats exactly; with "
               "more, two runs can differ a little (photo numbering and matching follow the threads)."),
)
@click.option("--upright/--no-upright", default=True, show_default=True, help="Turn the model upright: z up (from the photos' up direction and horizontal image rows, as COLMAP's model_orientation_aligner) and the main façade facing -y; a rotation about the cameras' centroid, no scale change.")
@click.option("--scale-bar", "scale_bars", multiple=True, metavar="'END ; END = LENGTH [UNIT]'", help="A known length between two points seen in the photos; each END is two or more IMAGE:x,y pixels (column, row), e.g. 'A.JPG:1520,1006 B.JPG:1498,1010 ; A.JPG:2210,1003 B.JPG:2187,1009 = 1.000 m'. Units m (default), cm, mm, km, in, ft, us-ft, yd. Repeatable (weighted mean; each bar's residual is reported).")
@click.option("--scale-distance", "scale_distances", multiple=True, metavar="'X,Y,Z ; X,Y,Z = LENGTH [UNIT]'", help="A known distance between two model points (e.g. picked in sparse.ply), e.g. '0.12,-1.5,3.2 ; 2.9,-1.4,3.3 = 4.25 m'.")
@click.option("--dense", "do_dense", is_flag=True, help="Then densify: depth maps and fusion into WORKDIR/dense/fused.ply (as `ws dense`).")
@field_option(DenseParams, "device", "--device", type=RegistryChoice(DEVICES), show_default=True, help="With --dense: COLMAP PatchMatch on CUDA, or the CPU semi-global matching (as `ws dense`).")
@overwrite_option
@allow_outside_option
@json_option
def sfm(images, workdir, camera_file, given, gcp_file, gcp_adjustment, crs, no_principal_point, no_final_ba, sigma_px,
        upright, scale_bars, scale_distances, do_dense, device, overwrite, as_json):
    """Orient the photos of IMAGES/ and build a sparse coloured cloud in WORKDIR.

    Writes WORKDIR/database.db, WORKDIR/sparse/0 (binary COLMAP model of the largest
    reconstruction; sparse/1... other models), WORKDIR/sparse.ply (coloured sparse cloud) and
    WORKDIR/summary.json (the stage record: the absolute image folder in inputs.image_dir and
    the camera settings in params, so `ws dense WORKDIR`, `ws mesh --reconstruction WORKDIR`,
    `ws colorize` and `ws ortho` find the photos without --images). With --gcp also
    WORKDIR/georef/0 (the model in the survey frame; bundle-adjusted with the control points
    when their image observations allow, intrinsics kept) and WORKDIR/georef_report.json
    (control and check residuals, RMSE before/after the adjustment, CE90/LE90, DEM cell size
    and contour interval supported). With --dense also WORKDIR/dense and its record
    WORKDIR/dense/summary.json, as `ws dense` writes them.

    The model is turned upright (z up, main façade facing -y) unless --no-upright, and scaled
    to metres by --scale-bar / --scale-distance; without them (or GCPs) its lengths are in
    arbitrary units and the record says "scaled": false.
    """
    from workstation.io.atomic import work_folder
    from workstation.io.reconstruction import SFM_RECORD, write_stage_record
    from workstation.photogrammetry.sfm import orient_photos

    camera, gcps, bars = _read_inputs(images, camera_file, gcp_file, scale_bars, scale_distances)
    if do_dense:
        from workstation.photogrammetry.dense import resolve_device

        device = resolve_device(device)  # --device cuda without CUDA fails before the long SfM run
    params = SfMParams(**given, refine_principal_point=not no_principal_point, final_ba=not no_final_ba)
    with work_folder(workdir):  # a failed run removes what it wrote
        result, out = orient_photos(images, workdir, camera, params, upright=upright, scale_bars=bars,
                                    sigma_px=sigma_px, overwrite=overwrite)
        wd = Path(workdir)
        _echo_result(result, wd)
        if gcps is not None:
            out["georef"] = _georeference(wd, images, gcps, sigma_px, crs, gcp_adjustment)
        if do_dense:
            out["dense"] = _densify(wd, images, device, overwrite)
        out = _record(out, images, camera_file, gcp_file, params, upright, gcp_adjustment, crs, sigma_px, wd)
        write_stage_record(out, wd / SFM_RECORD)
        from workstation.cli.summary import count, emit_summary

        s = result.summary
        emit_summary("sfm", f"{s['registered']}/{count(s['images'], 'images')} registered, {count(s['points'], 'points')}",
                     [wd / "sparse" / "0", wd / "sparse.ply", wd / "summary.json"],
                     details=[f"reprojection {s['mean_reprojection_error_px']:.3f} px",
                              "georeferenced" if gcps is not None else "", "dense" if do_dense else ""])
        if as_json:
            emit_json(out)


def _read_inputs(images, camera_file, gcp_file, scale_bars, scale_distances):
    """Read and check the inputs before the long run, so a bad file fails early: the camera
    (or None), the GCPs (or None; at least 3 control points for the 7-parameter similarity),
    the image folder's existence, and the scale bars (none allowed with GCPs)."""
    from workstation.core.errors import InvalidInputError

    camera = None
    if camera_file:
        from workstation.io.camera import read_camera

        camera = read_camera(camera_file)
    gcps = None
    if gcp_file:
        from workstation.io.gcp import read_gcp

        gcps = read_gcp(gcp_file)  # read before the long run: fail early on a bad file
        if sum(g.role == "control" for g in gcps) <= 2:
            raise InvalidInputError(
                f"{sum(g.role == 'control' for g in gcps)} control point(s) in the GCP file: a 7-parameter "
                "similarity needs at least 3 not on one line (2 leave the rotation about their line free)",
                "add control points or mark fewer points as check",
                path=gcp_file,
            )
    if not Path(images).is_dir():
        raise InvalidInputError("image folder not found", path=images)
    from workstation.photogrammetry.scale import parse_scale_texts

    bars = parse_scale_texts(scale_bars, scale_distances)
    if bars and gcps is not None:
        raise click.UsageError("--scale-bar/--scale-distance with --gcp: the control points already fix the scale")
    return camera, gcps, bars


def _echo_result(result, wd: Path) -> None:
    """Print the SfM outcome on stderr: registered images, points, reprojection error, track
    length, then the images not registered and the disconnected models."""
    s = result.summary
    click.echo(
        f"registered {s['registered']}/{s['images']} images, {s['points']} points, mean reprojection error "
        f"{s['mean_reprojection_error_px']:.3f} px, mean track length {s['mean_track_length']:.2f} -> {wd / 'sparse' / '0'}",
        err=True,
    )
    if result.unregistered:
        click.echo("not registered: " + ", ".join(result.unregistered), err=True)
    for o in result.other_models:
        click.echo(f"disconnected model sparse/{o['index']}: " + ", ".join(o["images"]), err=True)


def _densify(wd: Path, images, device: str, overwrite: bool) -> dict:
    """--dense: depth maps and fusion into WORKDIR/dense with its record, as `ws dense` writes
    them; returns the dense summary."""
    from workstation.cli.dense import write_dense_record
    from workstation.photogrammetry.dense import DenseParams, run_dense

    dense_params = DenseParams(device=device)
    _, dense_summary = run_dense(wd, images, dense_params, overwrite=overwrite)
    write_dense_record(wd, images, dense_params, dense_summary)
    click.echo(f"dense: {dense_summary['points']} points ({dense_summary['device']}) -> {dense_summary['fused']}", err=True)
    return dense_summary


def _record(out: dict, images, camera_file, gcp_file, params, upright: bool, gcp_adjustment: str, crs, sigma_px: float,
            wd: Path) -> dict:
    """The sfm stage record (WORKDIR/summary.json, :func:`~workstation.photogrammetry.sfm.sfm_record`):
    the --json document plus the absolute image folder and the camera settings (model,
    intrinsics shared, per image or per camera group, image size, matcher), with the GCP
    settings when there are GCPs."""
    from workstation.cli.summary import elapsed
    from workstation.photogrammetry.sfm import sfm_record

    outputs = [wd / "sparse" / "0", wd / "sparse.ply", wd / "georef" / "0" if gcp_file else None,
               (out.get("dense") or {}).get("fused")]
    gcp = {"gcp_adjustment": gcp_adjustment, "crs": crs, "sigma_px": sigma_px} if gcp_file else None
    return sfm_record(out, images, wd, params, upright=upright, outputs=outputs, seconds=elapsed(),
                      camera_file=camera_file, gcp_file=gcp_file, gcp_settings=gcp)


def _georeference(wd: Path, images, gcps, sigma_px: float, crs, gcp_adjustment: str) -> dict:
    """Move sparse/0 into the GCPs' frame: WORKDIR/georef/0 and georef_report.json; print the
    check-point accuracy; return the report."""
    import pycolmap

    from workstation.interop.pycolmap import (
        apply_similarity,
        reconstruction_from_pycolmap,
        set_poses_and_points,
        write_model,
    )
    from workstation.io.atomic import atomic_path
    from workstation.photogrammetry.georef import georeference

    rec = pycolmap.Reconstruction(str(wd / "sparse" / "0"))
    core = reconstruction_from_pycolmap(rec, images, with_tracks=gcp_adjustment != "similarity")
    geo = georeference(gcps, core, sigma_px=sigma_px, crs=crs, adjustment=gcp_adjustment)
    apply_similarity(rec, geo.similarity)
    if geo.meta.get("adjustment") == "bundle":
        set_poses_and_points(rec, geo.reconstruction)
    write_model(rec, wd / "georef" / "0")
    rep = geo.to_dict()
    with atomic_path(wd / "georef_report.json", overwrite=True) as tmp:
        Path(tmp).write_text(json.dumps(json_clean(rep), indent=2) + "\n")
    m = geo.report.metrics
    if geo.meta.get("adjustment") == "bundle" and m.get("check_n"):
        click.echo(
            f"bundle adjustment: check RMSE 3D {m['similarity_check_rmse_3d']:.4f} with the similarity alone -> "
            f"{m['check_rmse_3d']:.4f}",
            err=True,
        )
    if m.get("check_n"):
        click.echo(
            f"check points {m['check_n']}: RMSE X {m['check_rmse_x']:.4f} Y {m['check_rmse_y']:.4f} Z {m['check_rmse_z']:.4f} "
            f"H {m['check_rmse_h']:.4f} 3D {m['check_rmse_3d']:.4f}; CE90 {m['check_ce90']:.4f} LE90 {m['check_le90']:.4f}; "
            f"DEM cell >= {m['check_dem_cell_size_min']:.3f}, contour interval >= {m['check_contour_interval_min']:.3f}",
            err=True,
        )
    for note in geo.report.notes:
        click.echo("note: " + note, err=True)
    return rep
