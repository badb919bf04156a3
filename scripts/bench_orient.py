"""Upright models (issue 24): the vertical recovered from SfM cameras against the true one.

    python scripts/bench_orient.py fountain    # Strecha fountain-P11, ws SfM at 1536 px
    python scripts/bench_orient.py heritage    # synthetic heritage rig (datasets_synth/rig_heritage)

Each runs ``run_sfm`` on the photos, estimates the up vector in the SfM frame
(:func:`workstation.photogrammetry.orient.estimate_orientation`), maps it into the true
frame by the similarity between the SfM and the true camera centres (Umeyama), and prints
the angle to the true up (fountain-P11: the ground-truth frame's -z; the rig: +z), with the
plain consensus mean of the image up axes (COLMAP's estimate without the horizon refinement)
for comparison. One JSON line per result. Options: --work DIR (scratch, default
/tmp/bench_orient), --reuse (keep a rendered rig and SfM work folder), --max-image-size PX.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

DATA = Path(os.environ.get("WS_SHARED_DATA", "/work/shared/data")) / "images" / "sfm"


def angle_deg(a, b) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    return math.degrees(math.acos(float(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1))))


def fountain_truth() -> dict:
    """name -> camera centre of fountain-P11's true cameras (metres, GT frame)."""
    from bench_dense import fountain_cameras

    return {name: -pose.R.T @ pose.t for name, _, pose in fountain_cameras(DATA / "strecha_fountain-P11")}


def sfm(images: Path, work: Path, reuse: bool, max_image_size: int):
    from workstation.photogrammetry.sfm import SfMParams, read_reconstruction, run_sfm

    t0 = time.perf_counter()
    if reuse and (work / "sparse" / "0").exists():
        return read_reconstruction(work / "sparse" / "0", images), 0.0
    res = run_sfm(images, work, params=SfMParams(max_image_size=max_image_size), overwrite=True)
    return res.reconstruction, time.perf_counter() - t0


def evaluate(name: str, rec, truth_centres: dict, true_up: np.ndarray, seconds_sfm: float) -> dict:
    from workstation.photogrammetry.georef import fit_similarity
    from workstation.photogrammetry.orient import consensus_axis, estimate_orientation

    common = [im for im in rec.images.values() if im.name in truth_centres]
    src = np.stack([im.pose.center for im in common])
    dst = np.stack([truth_centres[im.name] for im in common])
    to_true = fit_similarity(src, dst)
    t0 = time.perf_counter()
    o = estimate_orientation(rec)
    seconds = time.perf_counter() - t0
    down, _ = consensus_axis(np.stack([np.asarray(im.pose.R)[1] for im in rec.images.values()]))
    resid = to_true.apply(src) - dst
    return {"bench": "orient", "data": name, "images": len(truth_centres), "registered": len(rec.images),
            "points": 0 if rec.points is None else int(rec.points.shape[0]),
            "vertical_error_deg": round(angle_deg(to_true.R @ o.up, true_up), 3),
            "plain_mean_up_error_deg": round(angle_deg(to_true.R @ -down, true_up), 3),
            "method": o.method, "facade": o.facade_source, "inliers": o.inliers,
            "centre_fit_rms_m": round(float(np.sqrt(np.mean(np.sum(resid**2, axis=1)))), 4),
            "seconds_orient": round(seconds, 3), "seconds_sfm": round(seconds_sfm, 1)}


def run_fountain(args) -> dict:
    rec, s = sfm(DATA / "strecha_fountain-P11" / "images", args.work / "fountain", args.reuse, args.max_image_size)
    return evaluate("fountain-P11", rec, fountain_truth(), np.array([0.0, 0.0, -1.0]), s)


def run_heritage(args) -> dict:
    from workstation.io.reconstruction import read_reconstruction_json
    from workstation.photogrammetry.rigs import load_rig, make_rig

    folder = args.work / "heritage_rig"
    if not (args.reuse and (folder / "cameras.json").exists()):
        recipe, spec = load_rig("rig_heritage")
        make_rig(recipe, spec, folder, overwrite=True)
    truth = read_reconstruction_json(folder / "cameras.json")
    centres = {im.name: im.pose.center for im in truth.images.values()}
    rec, s = sfm(folder / "images", args.work / "heritage_sfm", args.reuse, -1)
    return evaluate("rig_heritage", rec, centres, np.array([0.0, 0.0, 1.0]), s)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", choices=["fountain", "heritage"])
    ap.add_argument("--work", type=Path, default=Path("/tmp/bench_orient"))
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--max-image-size", type=int, default=1536)
    args = ap.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    print(json.dumps({"fountain": run_fountain, "heritage": run_heritage}[args.case](args)), flush=True)


if __name__ == "__main__":
    main()
