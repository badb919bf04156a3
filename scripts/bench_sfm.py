"""Photogrammetry benchmarks: one JSON line per result on stdout.

Parts (``--part``, repeatable; default all):

* ``zhang``: Bouguet's calibration example (13×12 inner corners, 30 mm) against the published
  toolbox result fc = [657.46, 657.95], cc = [303.14, 242.57].
* ``dlt``: DLT on synthetic cameras, 20 control points, 0.1 px noise: a textbook control
  frame and a random cage, linear and refined, share of trials per focal length.
* ``gcp``: synthetic GCP scenes (undeformed, bent and scale-drifting SfM blocks, gross tie
  errors): check RMSE of the similarity alone and after the bundle adjustment with GCP
  constraints, against the noise-only expectation; the adjustment's run time.
* ``fountain``: Strecha fountain-P11 — plain pycolmap against ``run_sfm`` (self-calibrated and
  with the true intrinsics), camera errors after a 7-DoF alignment to the true centres, and
  run-time ratios measured in the same run (wall and process CPU time).
* ``sacre_coeur``: 10 internet photos of the Sacré-Cœur (YFCC, 10 cameras, 675–1083 px, no
  EXIF): COLMAP with one shared camera (what a single-camera default does with mixed sizes)
  against ``run_sfm``'s default (one camera per image size and EXIF camera), incremental and
  global, at full size and at ``max_image_size`` 640: registered images, points, mean
  reprojection error, wall and process CPU time.
* ``rig``: a simulated heritage rig of ``--images`` photos (default 200: two convergent rings
  around the church of ``datasets_synth/rig_heritage.toml``, 640×480, one ray per pixel)
  through ``ws sfm`` with its defaults, as a separate process: wall and CPU time, stage
  timings, the matcher chosen and the pairs matched, registered images, mean reprojection
  error, and camera-centre errors against the rig's true poses after a 7-DoF similarity.
  ``--matcher`` picks another pairing than ``auto``; ``--shuffled N`` runs instead ``N`` evenly
  spaced photos of the rig linked under random names (out of name order, as photos of several
  passes or renamed files are), where name-order pairing fails and retrieval pairs are needed.
* ``repeat``: ``run_sfm`` ``--runs`` times (default 8) with ``--matcher`` (default
  retrieval, as above 60 images) and ``--threads`` (default all cores) on a 30-photo strip
  that ends on a flat wall (``rigs.wall_strip``, 256x192 px, 23° field of view, the
  camera left to self-calibration), or on the photos of ``--photos DIR``, each run
  extracting afresh: registered images, camera-centre errors after a 7-DoF similarity (to
  the true centres; to the first run's with ``--photos``), and how many distinct models the
  runs gave.

Usage::

    PYTHONPATH=$PWD python scripts/bench_sfm.py [--data ../shared/data] [--part zhang ...]
    PYTHONPATH=$PWD python scripts/bench_sfm.py --part rig --images 200 --work /tmp/bench_sfm_rig [--reuse]
        [--matcher sequential] [--shuffled 80]
    PYTHONPATH=$PWD python scripts/bench_sfm.py --part repeat [--runs 8] [--threads 2] [--photos DIR --matcher auto]
"""

from __future__ import annotations

import argparse
import json
import shutil
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]


def emit(d):
    print(json.dumps(d), flush=True)


def part_zhang(data: Path):
    from workstation.photogrammetry.calibration import (
        ZhangParams,
        calibrate_zhang_images,
    )

    t = time.perf_counter()
    r = calibrate_zhang_images(data / "images/calibration/bouguet_calib_example", 13, 12, 30.0, ZhangParams())
    c = r.camera
    pub = {"fx": 657.46, "fy": 657.95, "cx": 303.14, "cy": 242.57}
    got = {"fx": c.fx, "fy": c.fy, "cx": c.cx, "cy": c.cy}
    emit(
        {
            "bench": "zhang_bouguet",
            **{k: round(v, 3) for k, v in got.items()},
            "max_abs_diff_px": round(max(abs(got[k] - pub[k]) for k in pub), 3),
            "rms_px": round(r.rms, 4),
            "views_used": len(r.per_image),
            "dropped": [d["name"] for d in r.dropped],
            "dist": [round(x, 5) for x in c.dist],
            "seconds": round(time.perf_counter() - t, 2),
        }
    )


DLT_CASES = (
    # (name, layout, focal range px, refine, trials)
    ("frame_f2500-3500_linear", "frame", (2500, 3500), False, 1000),
    ("frame_f2500-3500_refined", "frame", (2500, 3500), True, 1000),
    ("frame_f2500-4500_refined", "frame", (2500, 4500), True, 500),
    ("random_f2500-4500_linear", "random", (2500, 4500), False, 500),
    ("random_f2500-4500_refined", "random", (2500, 4500), True, 500),
)


def part_dlt(data: Path, trials_scale: float = 1.0):
    """DLT on synthetic cameras (4000×3000 px), 20 control points, 0.1 px noise.

    "frame": a textbook control frame (one point per cell of a 5×4 grid over 90 % of the
    image, depths stratified over ±40 % of the distance); "random": points uniform in a cube
    as deep as wide filling 80 % of the frame. Refined = collinearity refinement, skew 0.
    ``pp_norm_err_rms``: RMS of the principal-point errors divided by the refinement's own
    predicted σ (1 = the estimator reaches its Cramér–Rao bound).
    """
    from workstation.photogrammetry.calibration import DLTParams, calibrate_dlt
    from workstation.photogrammetry.synthetic import dlt_case

    for name, layout, frange, refine, trials in DLT_CASES:
        trials = max(10, int(trials * trials_scale))
        rng = np.random.default_rng(2024)
        f_true, pp, foc, cen, pstd, z = [], [], [], [], [], []
        t = time.process_time()
        for _ in range(trials):
            cam, pose, X, uv, dist = dlt_case(rng, 0.1, 20, layout=layout, focal_range=frange)
            r = calibrate_dlt(X, uv, (cam.width, cam.height), DLTParams(refine=refine, estimate_skew=not refine))
            c = r.camera
            f_true.append(cam.fx)
            pp.append(np.hypot(c.cx - cam.cx, c.cy - cam.cy))
            if refine:
                pstd.append(np.hypot(r.std["cx"], r.std["cy"]))
                z += [(c.cx - cam.cx) / r.std["cx"], (c.cy - cam.cy) / r.std["cy"]]
            foc.append(max(abs(c.fx / cam.fx - 1), abs(c.fy / cam.fy - 1)) * 100)
            cen.append(np.linalg.norm(next(iter(r.poses.values())).center - pose.center) / dist * 100)
        pp, f_true = np.array(pp), np.array(f_true)
        bins = {}
        for lo in range(int(frange[0]), int(frange[1]), 500):
            sel = (f_true >= lo) & (f_true < lo + 500)
            if sel.any():
                bins[f"{lo}-{lo + 500}"] = {"trials": int(sel.sum()), "pp_within_1px_pct": round(100 * float(np.mean(pp[sel] <= 1.0)), 1)}
        emit(
            {
                "bench": f"dlt_{name}",
                "layout": layout,
                "focal_range_px": list(frange),
                "refined": refine,
                "trials": trials,
                "points": 20,
                "noise_px": 0.1,
                "pp_err_px_median": round(float(np.median(pp)), 4),
                "pp_err_px_max": round(float(np.max(pp)), 4),
                "pp_within_1px_pct": round(100 * float(np.mean(pp <= 1.0)), 1),
                "pp_within_1px_by_focal": bins,
                **({"pp_predicted_radial_std_px_median": round(float(np.median(pstd)), 4),
                    "pp_norm_err_rms": round(float(np.sqrt(np.mean(np.square(z)))), 3)} if pstd else {}),
                "focal_err_pct_median": round(float(np.median(foc)), 4),
                "focal_err_pct_max": round(float(np.max(foc)), 4),
                "centre_err_pct_of_distance_median": round(float(np.median(cen)), 4),
                "centre_err_pct_of_distance_max": round(float(np.max(cen)), 4),
                "cpu_s_per_trial": round((time.process_time() - t) / trials, 4),
            }
        )


GCP_CASES = (
    # (name, noise px, tie points, bend m, scale drift, gross tie errors share)
    ("undeformed", 0.3, 300, 0.0, 0.0, 0.0),
    ("undeformed", 1.0, 300, 0.0, 0.0, 0.0),
    ("bent_0.3m_drift_0.5pct", 0.5, 300, 0.3, 0.005, 0.0),
    ("bent_1m_drift_1pct", 0.5, 300, 1.0, 0.01, 0.0),
    ("bent_0.3m_drift_0.5pct_3pct_gross", 0.5, 300, 0.3, 0.005, 0.03),
)


def part_gcp(data: Path, seeds: int = 10):
    """Synthetic aerial block (3×3 nadir images, GSD 3.4 cm), 6 control + 20 check points;
    the similarity alone against the bundle adjustment with GCP constraints, over ``seeds``
    scenes each; and the adjustment's run time on a large block of tie points."""
    from workstation.core.products import Reconstruction, Tracks
    from workstation.photogrammetry.georef import georeference
    from workstation.photogrammetry.synthetic import gcp_scene

    for name, noise, n_tie, bend, drift, gross in GCP_CASES:
        rows = []
        for seed in range(seeds):
            rec, gcps, expected = gcp_scene(np.random.default_rng(seed), noise_px=noise, n_control=6, n_check=20,
                                            n_tie=n_tie, bend=bend, scale_drift=drift)
            if gross:
                rng = np.random.default_rng(100 + seed)
                uv = rec.tracks.uv.copy()
                bad = rng.choice(uv.shape[0], int(gross * uv.shape[0]), replace=False)
                uv[bad] += rng.normal(0, 40.0, (bad.shape[0], 2))
                rec = Reconstruction(rec.cameras, rec.images, rec.points, None, None, rec.meta, Tracks(rec.tracks.point, rec.tracks.image, uv))
            t = time.process_time()
            res = georeference(gcps, rec, sigma_px=noise)
            cpu = time.process_time() - t
            m, st = res.report.metrics, res.meta["bundle"]
            rows.append([m["similarity_check_rmse_h"], m["similarity_check_rmse_z"], m["check_rmse_h"], m["check_rmse_z"],
                         expected["rmse_h"], expected["rmse_z"], st["rms_px_before"], st["rms_px_after"], cpu,
                         st["rejected_observations"]])
        a = np.array(rows)

        def q(col, a=a):  # RMSE pooled over the seeds (root mean of squares)
            return round(float(np.sqrt(np.mean(a[:, col] ** 2))), 4)

        emit(
            {
                "bench": "gcp_bundle_synthetic",
                "case": name,
                "noise_px": noise,
                "seeds": seeds,
                "control": 6,
                "check": 20,
                "tie_points": n_tie,
                "similarity_check_rmse_h": q(0),
                "similarity_check_rmse_z": q(1),
                "bundle_check_rmse_h": q(2),
                "bundle_check_rmse_z": q(3),
                "expected_rmse_h": q(4),
                "expected_rmse_z": q(5),
                "bundle_better_or_equal_3d_pct": round(100 * float(np.mean(np.hypot(a[:, 2], a[:, 3]) <= 1.05 * np.hypot(a[:, 0], a[:, 1]))), 1),
                "image_rms_px_before_median": round(float(np.median(a[:, 6])), 3),
                "image_rms_px_after_median": round(float(np.median(a[:, 7])), 3),
                "rejected_observations_median": float(np.median(a[:, 9])),
                "cpu_s_per_run_median": round(float(np.median(a[:, 8])), 3),
            }
        )
    # the SfM camera with k1 = 0.03 where the lens has none (a dome): intrinsics refined or not
    from workstation.core.products import Camera
    from workstation.photogrammetry.bundle import BundleParams

    rows = []
    for seed in range(seeds):
        rec, gcps, expected = gcp_scene(np.random.default_rng(seed), noise_px=0.5, n_control=8, n_check=20, n_tie=400)
        c = rec.cameras[1]
        wrong = Camera(c.width, c.height, c.fx, c.fy, c.cx, c.cy, 0.0, (0.03, 0.0, 0.0, 0.0, 0.0), "OPENCV")
        rec = Reconstruction({1: wrong}, rec.images, rec.points, None, None, rec.meta, rec.tracks)
        fixed = georeference(gcps, rec, sigma_px=0.5).report.metrics
        res = georeference(gcps, rec, sigma_px=0.5, bundle=BundleParams(refine_intrinsics=True))
        m, cam = res.report.metrics, res.reconstruction.cameras[1]
        rows.append([m["similarity_check_rmse_z"], fixed["check_rmse_z"], m["check_rmse_h"], m["check_rmse_z"],
                     expected["rmse_h"], expected["rmse_z"], cam.dist[0], cam.fx / c.fx - 1])
    a = np.array(rows)

    def rms(col):
        return round(float(np.sqrt(np.mean(a[:, col] ** 2))), 4)

    emit(
        {
            "bench": "gcp_bundle_wrong_k1",
            "seeds": seeds,
            "control": 8,
            "check": 20,
            "tie_points": 400,
            "camera_k1_given": 0.03,
            "similarity_check_rmse_z": rms(0),
            "bundle_fixed_intrinsics_check_rmse_z": rms(1),
            "bundle_refined_intrinsics_check_rmse_h": rms(2),
            "bundle_refined_intrinsics_check_rmse_z": rms(3),
            "expected_rmse_h": rms(4),
            "expected_rmse_z": rms(5),
            "refined_k1_abs_max": round(float(np.max(np.abs(a[:, 6]))), 5),
            "refined_fx_rel_err_pct_max": round(100 * float(np.max(np.abs(a[:, 7]))), 3),
        }
    )
    # run time on a large block: tie points observed ~5 times each
    for n_tie in (2000, 20000):
        rec, gcps, expected = gcp_scene(np.random.default_rng(1), noise_px=0.5, n_control=6, n_check=20, n_tie=n_tie, bend=0.3, scale_drift=0.005)
        t, w = time.process_time(), time.perf_counter()
        res = georeference(gcps, rec, sigma_px=0.5)
        st, m = res.meta["bundle"], res.report.metrics
        emit(
            {
                "bench": "gcp_bundle_runtime",
                "tie_points": n_tie,
                "observations": st["observations"],
                "parameters": st["parameters"],
                "evaluations": st["evaluations"],
                "bundle_seconds_wall": round(st["seconds"], 2),
                "georeference_cpu_s": round(time.process_time() - t, 2),
                "georeference_wall_s": round(time.perf_counter() - w, 2),
                "similarity_check_rmse_z": round(m["similarity_check_rmse_z"], 4),
                "bundle_check_rmse_z": round(m["check_rmse_z"], 4),
                "expected_rmse_z": round(expected["rmse_z"], 4),
            }
        )


# ------------------------------------------------------------------------------------------
def gt_cameras(folder: Path):
    out = {}
    for f in sorted(folder.glob("*.camera")):
        v = np.array(f.read_text().split(), dtype=float)
        K = v[0:9].reshape(3, 3)
        R_cw = v[12:21].reshape(3, 3)
        C = v[21:24]
        out[f.name[: -len(".camera")]] = (K, R_cw.T, C, int(v[24]), int(v[25]))
    return out


def camera_errors(model_dir: Path, gt: dict):
    import pycolmap

    from workstation.interop.pycolmap import pose_from_pycolmap
    from workstation.photogrammetry.collinearity import rotation_angle_deg
    from workstation.photogrammetry.georef import fit_similarity

    rec = pycolmap.Reconstruction(str(model_dir))
    names, Ce, Re, Cg, Rg = [], [], [], [], []
    for im in rec.images.values():
        if not im.has_pose or im.name not in gt:
            continue
        p = pose_from_pycolmap(im)
        names.append(im.name)
        Ce.append(p.center)
        Re.append(p.R)
        Rg.append(gt[im.name][1])
        Cg.append(gt[im.name][2])
    Ce, Cg = np.array(Ce), np.array(Cg)
    sim = fit_similarity(Ce, Cg)
    ce = np.linalg.norm(sim.apply(Ce) - Cg, axis=1)
    re = np.array([rotation_angle_deg(Re[i] @ sim.R.T, Rg[i]) for i in range(len(names))])
    return {
        "registered": len(names),
        "median_centre_err_mm": round(float(np.median(ce)) * 1000, 3),
        "max_centre_err_mm": round(float(np.max(ce)) * 1000, 3),
        "median_rot_err_deg": round(float(np.median(re)), 4),
        "max_rot_err_deg": round(float(np.max(re)), 4),
    }


def plain_pycolmap(images: Path, work: Path, K=None, seed: int = 0):
    """COLMAP's pipeline with default options, as a user of pycolmap would run it."""
    import pycolmap

    pycolmap.set_random_seed(seed)
    db = work / "database.db"
    ro = pycolmap.ImageReaderOptions()
    if K is not None:
        ro.camera_model = "PINHOLE"
        ro.camera_params = ",".join(repr(float(x)) for x in K)
    names = sorted(p.name for p in images.iterdir() if p.suffix.lower() in (".jpg", ".png", ".tif"))
    pycolmap.extract_features(db, images, image_names=names, camera_mode=pycolmap.CameraMode.SINGLE, reader_options=ro)
    pycolmap.match_exhaustive(db)
    opts = pycolmap.IncrementalPipelineOptions()
    opts.random_seed = seed
    if K is not None:
        opts.ba_refine_focal_length = False
        opts.ba_refine_extra_params = False
        opts.ba_refine_principal_point = False
        opts.mapper.abs_pose_refine_focal_length = False
        opts.mapper.abs_pose_refine_extra_params = False
    (work / "sparse").mkdir()
    recs = pycolmap.incremental_mapping(db, images, work / "sparse", opts)
    best = max(recs, key=lambda k: recs[k].num_reg_images())
    return work / "sparse" / str(best)


def timed(fn):
    t0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - t0, time.process_time() - c0


def part_fountain(data: Path, which=("self", "camera")):
    from workstation.core.products import Camera
    from workstation.io.camera import write_camera
    from workstation.photogrammetry.sfm import SfMParams, run_sfm

    root = data / "images/sfm/strecha_fountain-P11"
    images = root / "images"
    gt = gt_cameras(root / "gt_dense_cameras")
    K, _, _, w, h = next(iter(gt.values()))
    tmp = Path(tempfile.mkdtemp(prefix="bench_sfm_"))
    try:
        for mode in which:
            Kp = None
            cam = None
            if mode == "camera":
                # the GT K is taken in OpenCV's pixel convention; COLMAP's is +0.5 px
                cam = Camera(w, h, K[0, 0], K[1, 1], K[0, 2], K[1, 2])
                Kp = [K[0, 0], K[1, 1], K[0, 2] + 0.5, K[1, 2] + 0.5]
                write_camera(cam, tmp / "camera.json")
            wp = tmp / f"plain_{mode}"
            wp.mkdir()
            model, wall_p, cpu_p = timed(lambda: plain_pycolmap(images, wp, Kp))
            res_p = camera_errors(model, gt)
            emit({"bench": f"fountain_plain_pycolmap_{mode}", **res_p, "wall_s": round(wall_p, 1), "cpu_s": round(cpu_p, 1)})
            wo = tmp / f"ws_{mode}"
            r, wall_o, cpu_o = timed(lambda: run_sfm(images, wo, cam, SfMParams()))
            res_o = camera_errors(wo / "sparse" / "0", gt)
            emit(
                {
                    "bench": f"fountain_ws_sfm_{mode}",
                    **res_o,
                    "points": r.summary["points"],
                    "mean_reprojection_error_px": round(r.summary["mean_reprojection_error_px"], 4),
                    "mean_track_length": round(r.summary["mean_track_length"], 3),
                    "wall_s": round(wall_o, 1),
                    "cpu_s": round(cpu_o, 1),
                    "ratio_wall": round(wall_o / wall_p, 3),
                    "ratio_cpu": round(cpu_o / cpu_p, 3),
                    "timings_s": {k: round(v, 1) for k, v in r.summary["timings_s"].items()},
                }
            )
            shutil.rmtree(wp, ignore_errors=True)
            shutil.rmtree(wo, ignore_errors=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _shared_camera_colmap(images: Path, work: Path) -> dict:
    """COLMAP's pipeline with one camera for all images (CameraMode.SINGLE): the images whose
    size differs from the first one's are not imported."""
    import pycolmap

    pycolmap.set_random_seed(0)
    db = work / "database.db"
    names = sorted(p.name for p in images.iterdir() if p.suffix.lower() in (".jpg", ".png", ".tif"))
    pycolmap.extract_features(db, images, image_names=names, camera_mode=pycolmap.CameraMode.SINGLE)
    pycolmap.match_exhaustive(db)
    with pycolmap.Database.open(str(db)) as d:
        imported = d.num_images()
    (work / "sparse").mkdir()
    opts = pycolmap.IncrementalPipelineOptions()
    opts.random_seed = 0
    recs = pycolmap.incremental_mapping(db, images, work / "sparse", opts)
    best = max(recs.values(), key=lambda r: r.num_reg_images(), default=None)
    return {"images": len(names), "imported": imported, "registered": best.num_reg_images() if best else 0,
            "points": best.num_points3D() if best else 0,
            "mean_reprojection_error_px": round(best.compute_mean_reprojection_error(), 4) if best else None}


SACRE_COEUR_RUNS = (
    # (name, SfMParams overrides)
    ("auto_incremental", {}),
    ("auto_global", {"mapper": "global"}),
    ("auto_incremental_640px", {"max_image_size": 640}),
    ("auto_global_640px", {"mapper": "global", "max_image_size": 640}),
)


def part_sacre_coeur(data: Path):
    from workstation.photogrammetry.sfm import SfMParams, run_sfm

    images = data / "images/sfm/sacre_coeur_yfcc"
    tmp = Path(tempfile.mkdtemp(prefix="bench_sfm_sc_"))
    try:
        (tmp / "single").mkdir()
        res, wall, cpu = timed(lambda: _shared_camera_colmap(images, tmp / "single"))
        emit({"bench": "sacre_coeur_colmap_single_camera", **res, "wall_s": round(wall, 1), "cpu_s": round(cpu, 1)})
        for name, over in SACRE_COEUR_RUNS:
            r, wall, cpu = timed(lambda over=over, name=name: run_sfm(images, tmp / name, params=SfMParams(**over)))
            s = r.summary
            emit({"bench": f"sacre_coeur_ws_sfm_{name}", "images": s["images"], "registered": s["registered"],
                  "cameras": s["camera_count"], "camera_sharing": s["camera_sharing"], "points": s["points"],
                  "mean_reprojection_error_px": round(s["mean_reprojection_error_px"], 4),
                  "mean_track_length": round(s["mean_track_length"], 3), "wall_s": round(wall, 1),
                  "cpu_s": round(cpu, 1), "timings_s": {k: round(v, 1) for k, v in s["timings_s"].items()}})
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def _rig_images(folder: Path, images: int, reuse: bool) -> dict:
    """Render the rig (unless ``reuse`` finds it) and return the true camera centres by name."""
    import dataclasses

    from workstation.io.reconstruction import read_reconstruction_json
    from workstation.photogrammetry.rigs import load_rig, make_rig

    if not (reuse and (folder / "cameras.json").exists()):
        recipe, spec = load_rig("rig_heritage")
        make_rig(recipe, dataclasses.replace(spec, n_images=images, supersample=1), folder, overwrite=True)
    truth = read_reconstruction_json(folder / "cameras.json")
    return {im.name: im.pose.center for im in truth.images.values()}


def _centre_errors(model_dir: Path, centres: dict) -> dict:
    """Camera-centre errors of a model against true centres after a 7-DoF similarity (metres
    of the true frame; the rig's ring is 50 m from the church)."""
    import pycolmap

    rec = pycolmap.Reconstruction(str(model_dir))
    return _errors_of({im.name: np.asarray(im.projection_center()) for im in rec.images.values() if im.has_pose},
                      centres)


def _errors_of(got: dict, centres: dict) -> dict:
    """Errors of the camera centres ``got`` against ``centres`` (both by name), as
    :func:`_centre_errors`."""
    from workstation.photogrammetry.georef import fit_similarity

    names = sorted(set(got) & set(centres))
    if len(names) < 3:  # a similarity needs 3 centres
        return {"median_centre_err_m": None, "max_centre_err_m": None, "rms_centre_err_m": None}
    est, true = np.array([got[n] for n in names]), np.array([centres[n] for n in names])
    err = np.linalg.norm(fit_similarity(est, true).apply(est) - true, axis=1)
    return {"median_centre_err_m": round(float(np.median(err)), 4), "max_centre_err_m": round(float(err.max()), 4),
            "rms_centre_err_m": round(float(np.sqrt(np.mean(err ** 2))), 4)}


def _shuffled_subset(folder: Path, centres: dict, n: int, out: Path, seed: int = 7) -> tuple[Path, dict]:
    """``n`` evenly spaced photos of ``folder/images`` linked into ``out/images`` under random
    names; returns that folder and the true centres by the new names."""
    files = sorted((folder / "images").iterdir())
    pick = [files[i] for i in np.round(np.linspace(0, len(files) - 1, n)).astype(int)]
    names = [f"p{x:04d}{f.suffix}" for x, f in zip(np.random.default_rng(seed).choice(10000, n, replace=False), pick)]
    if out.exists():
        shutil.rmtree(out)
    (out / "images").mkdir(parents=True)
    for f, name in zip(pick, names):
        (out / "images" / name).symlink_to(f.resolve())
    return out / "images", {name: centres[f.name] for f, name in zip(pick, names)}


def part_rig(data: Path, images: int = 200, work: Path | None = None, reuse: bool = False, matcher: str = "auto",
             shuffled: int = 0):
    import os
    import resource
    import subprocess
    import sys

    work = Path(work or tempfile.mkdtemp(prefix="bench_sfm_rig_"))
    folder = work / f"rig{images}"
    centres = _rig_images(folder, images, reuse)
    image_dir, tag = folder / "images", f"rig{images}"
    if shuffled:
        image_dir, centres = _shuffled_subset(folder, centres, shuffled, work / f"shuffled{shuffled}")
        tag = f"rig{images}_shuffled{shuffled}"
    out = work / f"sfm_{tag}_{matcher}"
    cmd = [sys.executable, "-c", "import sys; from workstation.cli.main import main; sys.exit(main())",
           "sfm", str(image_dir), "-o", str(out), "--overwrite", "--json", "--matcher", matcher]
    env = {**os.environ, "PYTHONPATH": str(REPO)}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode:
        raise SystemExit(f"ws sfm failed with exit code {proc.returncode}")
    doc = json.loads(proc.stdout)
    with open("/proc/loadavg") as fh:
        load = fh.read().split()[:3]
    emit({"bench": f"{tag}_ws_sfm", "images": doc["images"], "registered": doc["registered"],
          "registered_pct": round(100 * doc["registered"] / doc["images"], 1), "points": doc["points"],
          "matcher": doc["matcher"], "matched_pairs": doc["matched_pairs"], "mean_reprojection_error_px": round(doc["mean_reprojection_error_px"], 4),
          **_centre_errors(out / "sparse" / "0", centres), "wall_s": round(wall, 1),
          "cpu_s": round(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 1),
          "cores": os.cpu_count(), "load_avg": load,
          "timings_s": {k: round(v, 1) for k, v in doc["timings_s"].items()}})


def part_repeat(runs: int = 8, matcher: str = "retrieval", threads: int = -1, images: Path | None = None):
    """``run_sfm`` ``runs`` times on the same photos, each run from a fresh work folder: 30
    photos of a 12 m strip ending on a flat wall (:func:`rigs.wall_strip`, one central box),
    errors against the true centres; or the photos in ``images``, errors against the first
    run's centres. One line a run (registered, pairs, centre errors) and one for the whole
    (distinct models, the range of the largest centre error)."""
    import hashlib

    from workstation.photogrammetry.rigs import wall_strip
    from workstation.photogrammetry.sfm import SfMParams, run_sfm

    tmp = Path(tempfile.mkdtemp(prefix="bench_sfm_repeat_"))
    try:
        if images is None:
            images = tmp / "images"
            _, centres = wall_strip(images, [f"photo_{k:02d}.png" for k in range(30)])
        else:
            centres = None  # the first run's
        params = SfMParams(matcher=matcher, num_threads=threads)
        errs, models = [], set()
        for k in range(runs):
            res = run_sfm(images, tmp / f"work{k}", params=params)
            got = {im.name: np.asarray(im.pose.center) for im in res.reconstruction.images.values()
                   if im.pose is not None}
            centres = got if centres is None else centres
            e = _errors_of(got, centres)
            models.add(hashlib.sha1(np.round([got[n] for n in sorted(got)], 9).tobytes()).hexdigest())
            errs.append(e["max_centre_err_m"])
            emit({"bench": "repeat_run", "run": k, "registered": res.summary["registered"],
                  "matched_pairs": res.summary["matched_pairs"], **e})
            shutil.rmtree(tmp / f"work{k}")
        c = np.array(list(centres.values()))
        emit({"bench": "repeat", "images": str(images) if images.parent != tmp else "wall_strip", "matcher": matcher,
              "threads": threads, "runs": runs, "distinct_models": len(models), "max_centre_err_m": [min(errs), max(errs)],
              "reference": "truth" if images.parent == tmp else "run 0",
              "reference_extent": round(float(np.linalg.norm(c.max(axis=0) - c.min(axis=0))), 3)})
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", type=Path, default=REPO.parent / "shared" / "data")
    ap.add_argument("--part", action="append", choices=["zhang", "dlt", "gcp", "fountain", "sacre_coeur", "rig", "repeat"])
    ap.add_argument("--fountain-mode", action="append", choices=["self", "camera"])
    ap.add_argument("--images", type=int, default=200, help="rig: photos in the simulated rig")
    ap.add_argument("--work", type=Path, help="rig: folder for the rendered rig and the work folder (default: a temporary one)")
    ap.add_argument("--reuse", action="store_true", help="rig: reuse a rig rendered earlier in --work")
    ap.add_argument("--matcher", help="rig: ws sfm --matcher (default auto); repeat: the matcher (default retrieval)")
    ap.add_argument("--runs", type=int, default=8, help="repeat: runs of the same photos")
    ap.add_argument("--threads", type=int, default=-1, help="repeat: threads (-1: all cores)")
    ap.add_argument("--photos", type=Path, help="repeat: this folder of photos instead of the strip (errors against the first run)")
    ap.add_argument("--shuffled", type=int, default=0,
                    help="rig: run this many evenly spaced photos of the rig under random names instead")
    a = ap.parse_args(argv)
    parts = a.part or ["zhang", "dlt", "gcp", "fountain", "sacre_coeur", "rig", "repeat"]
    for p in parts:
        if p == "fountain":
            part_fountain(a.data, tuple(a.fountain_mode or ("self", "camera")))
        elif p == "rig":
            part_rig(a.data, a.images, a.work, a.reuse, a.matcher or "auto", a.shuffled)
        elif p == "repeat":
            part_repeat(a.runs, a.matcher or "retrieval", a.threads, a.photos)
        else:
            globals()[f"part_{p}"](a.data)


if __name__ == "__main__":
    main()
