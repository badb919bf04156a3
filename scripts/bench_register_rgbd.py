"""A real low-overlap indoor RGB-D pair (3DLoMatch, 7-scenes redkitchen fragments 21 and 34,
about 25 % overlap; issue 24): the figures of "Registration" in docs/benchmarks.md.

Four lines against the benchmark's true pose (`gt.txt`, p_21 = T p_34):
1. `register()` with defaults (refused, or the pose error);
2. `register(method="planes")` (coarse from matched planes, the sensors at the fragments'
   origins) with the point-to-plane and the point-to-point fine stage: pose error, CPU and
   wall seconds, and where the true pose ranks among its candidates;
3. Open3D's FPFH + RANSAC on its own (4 M iterations, 0.9999 confidence) at voxel sizes
   2.5, 4 and 5 cm: the hand-crafted baseline of the 3DLoMatch papers;
4. the fine stage (three ICP variants) started from the true pose: where it settles, and the
   share of source points within 1, 2 and 3 cm of the target at the truth and at that pose.

    PYTHONPATH=. .venv/bin/python scripts/bench_register_rgbd.py [--data ../shared/data]
    PYTHONPATH=. .venv/bin/python scripts/bench_register_rgbd.py --rooms 6 [--first SEED] [--ranks [--peaks N]]
    PYTHONPATH=. .venv/bin/python scripts/bench_register_rgbd.py --planes 2

``--rooms N`` runs the plane method instead on N simulated cluttered rooms
(`tests/registration/rooms.py`: two ray-cast views with 20-35 % overlap, random poses),
the check on data the method was not set on. ``--planes N`` prints line 2 alone, N rounds
(the timing check; the first round also loads the libraries).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from workstation.core.errors import StageError
from workstation.io import read_cloud
from workstation.registration.icp import QUICK_ICP, ICPParams, refine
from workstation.registration.register import RegisterParams, register

PAIR = Path("registration") / "3dlomatch_redkitchen_21_34"
#: 3DMatch fragments lie in the frame of their first camera: every point has z > 0 and lies
#: in the 3 m TSDF volume in front of the origin, so the origin is the sensor position.
SENSOR = (0.0, 0.0, 0.0)


def pose_error(M: np.ndarray, T: np.ndarray) -> tuple[float, float]:
    """(rotation error in degrees, translation error in metres) of M against T."""
    R = M[:3, :3] @ T[:3, :3].T
    return float(np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1)))), float(np.linalg.norm(M[:3, 3] - T[:3, 3]))


def fpfh_ransac(folder: Path, T: np.ndarray, voxel: float) -> str:
    """Open3D's FPFH + RANSAC alone at one voxel size, as the 3DLoMatch baselines run it."""
    import open3d as o3d

    reg = o3d.pipelines.registration
    clouds = []
    for name in ("cloud_bin_34.ply", "cloud_bin_21.ply"):
        c = o3d.io.read_point_cloud(str(folder / name)).voxel_down_sample(voxel)
        c.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=2 * voxel, max_nn=30))
        f = reg.compute_fpfh_feature(c, o3d.geometry.KDTreeSearchParamHybrid(radius=5 * voxel, max_nn=100))
        clouds.append((c, f))
    (s, fs), (t, ft) = clouds
    c0 = time.process_time()
    r = reg.registration_ransac_based_on_feature_matching(
        s, t, fs, ft, False, 1.5 * voxel, reg.TransformationEstimationPointToPoint(False), 3,
        [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(1.5 * voxel)],
        reg.RANSACConvergenceCriteria(4_000_000, 0.9999))
    rot, shift = pose_error(r.transformation, T)
    return f"{rot:.1f} deg {shift:.3f} m, fitness {r.fitness:.3f}, {time.process_time() - c0:.1f} s CPU"


def planes_line(src, tgt, T: np.ndarray, fine: str) -> str:
    """``register(method="planes")`` with one fine method: pose error, overlap, CPU and wall time."""
    c0, w0 = time.process_time(), time.perf_counter()
    try:
        r = register(src, tgt, RegisterParams(method="planes", fine=ICPParams(method=fine), viewpoint_source=SENSOR,
                                              viewpoint_target=SENSOR))
    except StageError as ex:
        return f"refused ({ex.args[0] if ex.args else ex}), {time.process_time() - c0:.1f} s CPU"
    rot, shift = pose_error(r.transform, T)
    return (f"{rot:.2f} deg {shift:.3f} m, fitness {r.fitness:.3f}, {time.process_time() - c0:.1f} s CPU, "
            f"{time.perf_counter() - w0:.1f} s wall (coarse {r.meta['seconds']['coarse']:.1f} s wall)")


def near_shares(src: np.ndarray, tgt: np.ndarray, M: np.ndarray) -> str:
    """Shares of source points within 1, 2 and 3 cm of the target under M."""
    from scipy.spatial import cKDTree

    d, _ = cKDTree(tgt).query(src @ M[:3, :3].T + M[:3, 3])
    return " / ".join(f"{(d < r).mean():.3f}" for r in (0.01, 0.02, 0.03))


def within(M: np.ndarray, T: np.ndarray, degrees: float, metres: float) -> bool:
    """Whether M lies within ``degrees`` and ``metres`` of T."""
    rot, shift = pose_error(M, T)
    return rot < degrees and shift < metres


def ranking(src: np.ndarray, tgt: np.ndarray, T: np.ndarray, vs, vt, peaks: int | None = None) -> str:
    """Where the true pose ``T`` stands among the plane method's candidates (``peaks``
    shifts per turn, the default when None), prepared as ``register`` prepares them: the
    agreement rank of the first raw hypothesis within 6 deg / 30 cm and where the short ICP
    takes it; the rank of the first verified (coarse) pose within 10 deg / 20 cm; the consistency,
    free-space share and verified fitness of the true pose (after the same short ICP) against
    the winner's."""
    from workstation.core.geometry import default_origin
    from workstation.interop.open3d import local_transform
    from workstation.registration.planes import (PlaneCoarseParams, free_space_violations, plane_hypotheses,
                                                 range_images, verify_plane_hypotheses)
    from workstation.registration.preprocess import Radii, estimate_voxel_size, prepare
    from workstation.registration.register import consistency

    origin = default_origin(tgt)
    radii = Radii(estimate_voxel_size(tgt - origin))
    v, P = radii.voxel, PlaneCoarseParams() if peaks is None else PlaneCoarseParams(peaks=peaks)
    vps = tuple(None if p is None else np.asarray(p) - origin for p in (vs, vt))
    ps, pt = (prepare(x - origin, radii, features=False, viewpoint=p) for x, p in ((src, vps[0]), (tgt, vps[1])))
    TL = local_transform(T, origin, origin)
    images = range_images(ps, pt, (ps.viewpoint, pt.viewpoint), P)  # the positions the prepared clouds carry
    scores, Ts, _, _ = plane_hypotheses(ps, pt, P, images=images)  # what plane_registration does, in its two steps
    if not len(Ts):
        return "raw rank - of 0 (no plane pair gives a pose)"
    raw = [k for k, M in enumerate(Ts) if within(M, TL, 6, 0.3)]
    icp = ""
    if raw:
        e0 = pose_error(Ts[raw[0]], TL)
        e1 = pose_error(refine(ps.down, pt.down, v, Ts[raw[0]], QUICK_ICP, information=False).transform, TL)
        icp = f" ({e0[0]:.1f} deg {e0[1]:.2f} m, after the short ICP {e1[0]:.1f} deg {e1[1]:.2f} m)"
    r = verify_plane_hypotheses(ps, pt, scores, Ts, P, images)
    m = r.meta
    ok = [k for k, M in enumerate(m["hypotheses"]) if within(M, TL, 10, 0.2)]
    q = refine(ps.down, pt.down, v, TL, QUICK_ICP, information=False)
    free = free_space_violations(ps.down, pt.down, q.transform, images, P.free_margin * v)
    return (f"raw rank {raw[0] if raw else '-'} of {len(Ts)}{icp}, verified rank {ok[0] if ok else '-'} of "
            f"{len(m['hypotheses'])}; truth: consistency {consistency(ps.down, pt.down, q.transform, v):.3f} "
            f"free {free:.3f} fitness {q.fitness:.3f}; winner ({pose_error(m['hypotheses'][0], TL)[0]:.0f} deg): "
            f"consistency {m['consistency'][0]:.3f} free {m['free_space'][0]:.3f} fitness {r.fitness:.3f}")


def rooms(n: int, first: int = 0, ranks: bool = False, peaks: int | None = None) -> None:
    """The plane method (point-to-point fine stage) on ``n`` simulated room view pairs (seeds
    ``first`` on), the sensor positions given; with ``ranks``, where the true pose ranks
    (among the candidates of ``peaks`` shifts per turn, the default when None)."""
    import sys

    from workstation.core.cloud import Cloud
    from workstation.registration.transforms import apply_transform, invert, make_transform, random_rotation

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "registration"))
    from rooms import view_pair_with_sensors

    right = 0
    for seed in range(first, first + n):
        rng = np.random.default_rng(seed)
        a, b, overlap, pa, pb = view_pair_with_sensors(seed)
        Ta = make_transform(random_rotation(rng), rng.uniform(-2, 2, 3))
        Tb = make_transform(random_rotation(rng), rng.uniform(-2, 2, 3))
        src, tgt, T = apply_transform(Ta, a), apply_transform(Tb, b), Tb @ invert(Ta)
        vs, vt = apply_transform(Ta, pa[None])[0], apply_transform(Tb, pb[None])[0]
        params = RegisterParams(method="planes", min_fitness=0.0, min_plane_inliers=0.0,
                                fine=ICPParams(method="point_to_point"), viewpoint_source=tuple(vs),
                                viewpoint_target=tuple(vt))
        c0, w0 = time.process_time(), time.perf_counter()
        r = register(Cloud(src), Cloud(tgt), params)
        rot, shift = pose_error(r.transform, T)
        right += rot < 5 and shift < 0.1
        print(f"room {seed}: overlap {overlap:.2f}, {len(a)}/{len(b)} points: {rot:.2f} deg {shift:.3f} m, "
              f"{time.process_time() - c0:.1f} s CPU, {time.perf_counter() - w0:.1f} s wall", flush=True)
        if ranks:
            print(f"  {ranking(src, tgt, T, vs, vt, peaks)}", flush=True)
    print(f"right (< 5 deg, < 10 cm): {right} of {n}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", default="../shared/data")
    ap.add_argument("--rooms", type=int, default=0, help="run the plane method on this many simulated rooms instead")
    ap.add_argument("--first", type=int, default=0, help="seed of the first simulated room")
    ap.add_argument("--ranks", action="store_true", help="with --rooms: where the true pose ranks among the candidates")
    ap.add_argument("--peaks", type=int, default=None,
                    help="with --ranks: in-plane shifts kept per turn for the ranking (the method's default if unset)")
    ap.add_argument("--planes", type=int, default=0, help="only line 2 (the plane method), this many rounds")
    args = ap.parse_args()
    if args.rooms:
        return rooms(args.rooms, args.first, args.ranks, args.peaks)
    folder = Path(args.data) / PAIR
    T = np.loadtxt(folder / "gt.txt")
    src, tgt = read_cloud(folder / "cloud_bin_34.ply"), read_cloud(folder / "cloud_bin_21.ply")
    for k in range(args.planes):
        for fine in ("point_to_plane", "point_to_point"):
            print(f"round {k + 1}, register (planes, fine {fine}): {planes_line(src, tgt, T, fine)}", flush=True)
    if args.planes:
        return
    c0 = time.process_time()
    try:
        r = register(src, tgt)
        rot, shift = pose_error(r.transform, T)
        print(f"register (defaults): {rot:.2f} deg {shift:.3f} m, fitness {r.fitness:.3f}, {time.process_time() - c0:.1f} s CPU")
    except StageError as ex:
        print(f"register (defaults): refused, {time.process_time() - c0:.1f} s CPU ({ex.args[0] if ex.args else ex})")
    for fine in ("point_to_plane", "point_to_point"):
        print(f"register (planes, fine {fine}): {planes_line(src, tgt, T, fine)}")
    print(f"planes ranking: {ranking(src.xyz, tgt.xyz, T, np.zeros(3), np.zeros(3))}")
    for voxel in (0.025, 0.04, 0.05):
        print(f"open3d fpfh+ransac, voxel {voxel} m: {fpfh_ransac(folder, T, voxel)}")
    print(f"source points within 1/2/3 cm of the target at the true pose: {near_shares(src.xyz, tgt.xyz, T)}")
    for fine in ("point_to_plane", "point_to_point", "generalized"):
        r = register(src, tgt, RegisterParams(min_fitness=0.0, min_plane_inliers=0.0, fine=ICPParams(method=fine)), init=T)
        rot, shift = pose_error(r.transform, T)
        print(f"fine stage ({fine}) from the true pose: {rot:.2f} deg {shift:.3f} m; "
              f"within 1/2/3 cm: {near_shares(src.xyz, tgt.xyz, r.transform)}")


if __name__ == "__main__":
    main()
