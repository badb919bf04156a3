"""Demo step of photogrammetry: DLT calibration, space resection and intersection, and GCP
georeferencing with an independent check-point report, and a bundle adjustment with GCP
constraints that straightens a bent block, all on synthetic scenes (no SfM run)."""

from __future__ import annotations

import json

import numpy as np

from workstation.io import atomic_path


def step(ctx) -> dict:
    from workstation.io.camera import write_camera
    from workstation.photogrammetry.calibration import DLTParams, calibrate_dlt
    from workstation.photogrammetry.collinearity import intersect, opk_from_pose, resect
    from workstation.photogrammetry.georef import georeference
    from workstation.photogrammetry.synthetic import dlt_case, gcp_scene

    rng = np.random.default_rng(ctx.seed)
    out = ctx.outdir

    # 1. DLT on a 3-D control field, 20 points, 0.1 px noise
    cam, pose, X, uv, dist = dlt_case(rng, noise_px=0.1, n=20)
    dlt = calibrate_dlt(X, uv, (cam.width, cam.height), DLTParams(refine=True, estimate_skew=False), name="cage")
    cam_json = out / "photo_camera_dlt.json"
    write_camera(dlt, cam_json, overwrite=True)

    # 2. resection of an aerial image from its GCPs, then intersection of every GCP
    rec, gcps, expected = gcp_scene(rng, noise_px=0.5, n_control=6, n_check=12)
    img = rec.images[5]
    obs = [(g, o) for g in gcps for o in g.observations if o[0] == img.name]
    Xm = rec.points[[gcps.index(g) for g, _ in obs]]
    res = resect(Xm, np.array([[o[1], o[2]] for _, o in obs]), rec.cameras[img.camera_id])
    names = {im.name: im for im in rec.images.values()}
    inter = intersect(
        np.array([[u, v] for _, u, v in gcps[0].observations]),
        [rec.cameras[names[o[0]].camera_id] for o in gcps[0].observations],
        [names[o[0]].pose for o in gcps[0].observations],
    )

    # 3. similarity from control points, accuracy from check points
    geo = georeference(gcps, rec)

    # 4. a bent SfM block (0.3 m dome, 0.5 % scale drift) with tie points: the similarity
    #    leaves the bend, the bundle adjustment with the control points removes it
    rec_b, gcps_b, expected_b = gcp_scene(rng, noise_px=0.5, n_control=6, n_check=12, n_tie=200, bend=0.3, scale_drift=0.005)
    geo_b = georeference(gcps_b, rec_b, sigma_px=0.5)
    report = {
        "dlt": {
            "true": {"fx": cam.fx, "fy": cam.fy, "cx": cam.cx, "cy": cam.cy},
            "estimated": {k: getattr(dlt.camera, k) for k in ("fx", "fy", "cx", "cy")},
            "rms_px": dlt.rms,
            "centre_error_pct_of_distance": float(
                100 * np.linalg.norm(dlt.poses["cage"].center - pose.center) / dist
            ),
        },
        "resection": {
            "image": img.name,
            "points": len(obs),
            "centre_error_model": float(np.linalg.norm(res.centre - img.pose.center)),
            "angles_deg": [float(np.degrees(a)) for a in opk_from_pose(res.pose)],
            **res.to_dict(),
        },
        "intersection": {"point": gcps[0].name, "rays": len(gcps[0].observations), "std_model": inter.std.tolist(),
                         "rms_px": inter.rms_px},
        "georeference": geo.to_dict(),
        "expected_check_rmse_from_image_noise": expected,
        "bent_block": {
            "georeference": geo_b.to_dict(),
            "expected_check_rmse_from_image_noise": expected_b,
        },
    }
    rep = out / "photo_gcp_report.json"
    with atomic_path(rep, overwrite=True) as tmp:
        tmp.write_text(json.dumps(report, indent=2, default=float))
    m = geo.report.metrics
    ctx.summaries["photogrammetry"] = {
        "dlt_rms_px": dlt.rms,
        "check_rmse_h": m["check_rmse_h"],
        "check_rmse_z": m["check_rmse_z"],
        "ce90": m["check_ce90"],
        "le90": m["check_le90"],
        "bent_block_check_rmse_z_similarity": geo_b.report.metrics.get("similarity_check_rmse_z"),
        "bent_block_check_rmse_z_bundle": geo_b.report.metrics["check_rmse_z"],
    }
    return {"camera_dlt": cam_json, "gcp_report": rep}
