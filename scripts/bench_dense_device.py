"""Dense clouds of one image set by COLMAP PatchMatch on the GPU and by the CPU methods, side by
side on the same machine (the lent GPU machine of docs/benchmarks.md).

    python scripts/bench_dense_device.py --data DIR [--size 1536] [--methods cuda,sgbm,sweep]

DIR holds ``strecha_fountain-P11/images`` and ``strecha_fountain-P11/gt_dense_cameras`` (the
true cameras; the images may be downscaled copies whose camera files were scaled with them).
One JSON line per method (wall and CPU seconds, points, peak RSS) and one per pair of clouds:
for tolerances of 2 and 5 cm, the share of each cloud within the tolerance of the other
(precision and recall against the other cloud, and their F-score, as in Knapitsch et al.,
*Tanks and Temples*, 2017), with the median distance. Without a true surface the CUDA cloud
is the reference the CPU clouds are compared with.
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))


def _run(work: Path, folder: Path, cams: list, method: str, size: int) -> tuple[np.ndarray, dict]:
    from bench_dense import _true_workdir

    from workstation.photogrammetry.dense import DenseParams, run_dense

    wd = _true_workdir(work, f"fountain_{method}", cams)
    params = DenseParams(device="cuda" if method == "cuda" else "cpu", method="sgbm" if method == "cuda" else method,
                         depth_range=(3.0, 25.0), max_image_size=size)
    c0, t0 = time.process_time(), time.perf_counter()
    cloud, summary = run_dense(wd, folder / "images", params, overwrite=True)
    row = {"bench": "dense_device", "method": method, "images": len(cams), "size": size, "points": cloud.n,
           "wall_s": round(time.perf_counter() - t0, 1), "cpu_s": round(time.process_time() - c0, 1),
           "peak_gb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20, 2),
           "timings_s": summary["timings_s"]}
    return np.asarray(cloud.xyz), row


def _compare(a: np.ndarray, b: np.ndarray, name_a: str, name_b: str) -> dict:
    from scipy.spatial import cKDTree

    d_ab = cKDTree(b).query(a, workers=-1)[0]  # a's points to b
    d_ba = cKDTree(a).query(b, workers=-1)[0]
    row = {"bench": "dense_device_pair", "cloud": name_a, "reference": name_b,
           "median_m": round(float(np.median(d_ab)), 4)}
    for tol in (0.02, 0.05):
        p, r = float((d_ab < tol).mean()), float((d_ba < tol).mean())
        row[f"at_{int(tol * 100)}cm"] = {"precision": round(p, 3), "recall": round(r, 3),
                                         "f": round(2 * p * r / (p + r), 3) if p + r else 0.0}
    return row


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", required=True, type=Path)
    ap.add_argument("--work", default="/tmp/bench_dense_device", type=Path)
    ap.add_argument("--size", type=int, default=1536)
    ap.add_argument("--methods", default="cuda,sgbm,sweep")
    a = ap.parse_args()
    folder = a.data / "strecha_fountain-P11"
    from bench_dense import fountain_cameras

    cams = fountain_cameras(folder)
    clouds = {}
    for method in a.methods.split(","):
        try:
            clouds[method], row = _run(a.work, folder, cams, method, a.size)
        except Exception as e:  # noqa: BLE001 - one method failing must not lose the others' figures
            row = {"bench": "dense_device", "method": method, "error": f"{type(e).__name__}: {e}"[:500]}
        print(json.dumps(row), flush=True)
    names = list(clouds)
    ref = "cuda" if "cuda" in clouds else (names[0] if names else None)
    for name in names:
        if name != ref:
            print(json.dumps(_compare(clouds[name], clouds[ref], name, ref)), flush=True)


if __name__ == "__main__":
    main()
