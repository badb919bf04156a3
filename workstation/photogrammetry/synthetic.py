"""Synthetic photogrammetric scenes with known geometry, for tests, benchmarks and the demo.

Deterministic for a given ``numpy.random.Generator``. Numpy only.
"""

from __future__ import annotations

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Pose, Reconstruction, Tracks

from .collinearity import intersect, opk_to_matrix, pose_from_opk, project
from .georef import Similarity


def _frame_points(rng: np.random.Generator, cam: Camera, pose: Pose, n: int, dist: float, depth_range: float) -> np.ndarray:
    """The "frame" layout of :func:`dlt_case`: one point per cell of a grid over the central
    90 % of the image, depths stratified over ``dist · (1 ± depth_range)`` in random order."""
    w, h = cam.width, cam.height
    nx = int(np.ceil(np.sqrt(n * w / h)))
    ny = int(np.ceil(n / nx))
    cells = rng.permutation(nx * ny)[:n]
    ix, iy = cells % nx, cells // nx
    fill = 0.9
    u = (0.5 - fill / 2 + fill * (ix + rng.uniform(0, 1, n)) / nx) * w
    v = (0.5 - fill / 2 + fill * (iy + rng.uniform(0, 1, n)) / ny) * h
    z = dist * (1 + depth_range * (2 * (rng.permutation(n) + rng.uniform(0, 1, n)) / n - 1))
    rays = np.column_stack([(u - cam.cx) / cam.fx, (v - cam.cy) / cam.fy, np.ones(n)])
    return (rays * z[:, None]) @ np.asarray(pose.R) + pose.center


def _cube_points(rng: np.random.Generator, cam: Camera, pose: Pose, n: int, width: float) -> np.ndarray:
    """The "random" layout of :func:`dlt_case`: the first ``n`` points drawn uniformly in a
    cube of side ``width`` around the origin that fall in the image."""
    w, h = cam.width, cam.height
    kept = np.empty((0, 3))
    while kept.shape[0] < n:
        Xr = np.column_stack(
            [rng.uniform(-width / 2, width / 2, 4 * n), rng.uniform(-width / 2, width / 2, 4 * n), rng.uniform(-0.5, 0.5, 4 * n) * width]
        )
        uv, zc = project(Xr, cam, pose, return_depth=True)
        ok = (zc > 0) & np.all((uv >= 0) & (uv < [w, h]), axis=1)
        kept = np.vstack([kept, Xr[ok]])
    return kept[:n]


def dlt_case(
    rng: np.random.Generator,
    noise_px: float = 0.1,
    n: int = 20,
    layout: str = "frame",
    focal_range: tuple[float, float] = (2500.0, 3500.0),
    depth_range: float = 0.4,
):
    """A random camera looking at a 3-D control field, all points in view.

    Layouts:

    * ``"frame"`` — a textbook calibration control frame: the image is divided into a grid of
      about ``n`` cells over its central 90 %, one point per cell (jittered inside it), and
      the points' depths are stratified over ``distance · (1 ± depth_range)`` in random
      order, so near and far points are interleaved across the whole frame.
    * ``"random"`` — points drawn uniformly in a cube as deep as it is wide that fills 80 %
      of the frame (keeping those in view); 20 random points often leave parts of the image
      or of the depth range empty.

    Parameters
    ----------
    rng : numpy.random.Generator
    noise_px : float
        Gaussian noise per pixel coordinate.
    n : int
        Number of control points.
    layout : {"frame", "random"}
    focal_range : (float, float)
        Focal length drawn uniformly in this range, pixels (the image is 4000 px wide:
        2500–3500 px is a 77°–60° horizontal field of view, 22–31 mm in 35 mm terms).
    depth_range : float
        Half depth extent of the "frame" layout, relative to the object distance.

    Returns
    -------
    camera : Camera
        The true camera (4000 × 3000 px, fy = fx · U(0.995, 1.005), principal point within
        40 px of centre).
    pose : Pose
        The true pose.
    X : (n, 3) float
        Control points, metres.
    uv : (n, 2) float
        Their pixels with Gaussian noise of ``noise_px`` per coordinate.
    distance : float
        Object distance, metres.
    """
    if layout not in ("frame", "random"):
        raise InvalidInputError(f"layout must be 'frame' or 'random', got {layout!r}")
    w, h = 4000, 3000
    f = rng.uniform(*focal_range)
    cam = Camera(w, h, f, f * rng.uniform(0.995, 1.005), w / 2 + rng.uniform(-40, 40), h / 2 + rng.uniform(-40, 40))
    dist = rng.uniform(20, 60)
    width = dist * w / f * 0.8
    om, ph, ka = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-np.pi, np.pi)
    C = np.array([0.0, 0.0, dist]) + rng.normal(0, 0.5, 3)
    pose = pose_from_opk(om, ph, ka, C)
    if layout == "frame":
        X = _frame_points(rng, cam, pose, n, dist, depth_range)
    else:
        X = _cube_points(rng, cam, pose, n, width)
    uv = project(X, cam, pose)
    return cam, pose, X, uv + rng.normal(0, noise_px, uv.shape), dist


def _warp(X: np.ndarray, centre: np.ndarray, half: float, bend: float, scale_drift: float):
    """A smooth deformation of survey coordinates and its Jacobian: a scale that drifts along x
    (local scale ``1 + scale_drift · x / half``) and a dome that lowers points by
    ``bend · (r / half)²`` at horizontal distance r from ``centre``."""
    q = np.asarray(X, dtype=float) - centre
    out = np.asarray(X, dtype=float).copy()
    out[:, 0] += scale_drift * q[:, 0] ** 2 / (2 * half)
    out[:, 2] -= bend * (q[:, 0] ** 2 + q[:, 1] ** 2) / half**2
    J = np.repeat(np.eye(3)[None], q.shape[0], axis=0)
    J[:, 0, 0] += scale_drift * q[:, 0] / half
    J[:, 2, 0] -= 2 * bend * q[:, 0] / half**2
    J[:, 2, 1] -= 2 * bend * q[:, 1] / half**2
    return out, J


def _terrain_points(rng: np.random.Generator, lo, hi, z0: float, n: int) -> np.ndarray:
    """``n`` points uniform in the (x, y) box ``lo``-``hi`` on the rolling terrain of
    :func:`gcp_scene` (base height ``z0``, plus up to 3 m of random relief)."""
    xy = rng.uniform(lo, hi, (n, 2))
    z = z0 + 5 * np.sin(xy[:, 0] / 40.0) * np.cos(xy[:, 1] / 55.0) + rng.uniform(0, 3, n)
    return np.column_stack([xy, z])


def _observed_gcps(rng: np.random.Generator, Xw: np.ndarray, cam: Camera, poses_w: list, images: dict, n_control: int,
                   noise_px: float, gcp_sigma):
    """GCPs at the survey points ``Xw`` (the first ``n_control`` control, the rest check),
    observed with noise in every image that sees them, and the check-point RMSE expected from
    the noise alone (see :func:`gcp_scene`)."""
    from workstation.io.gcp import GCP

    gcps = []
    var_h, var_z = [], []
    for i in range(Xw.shape[0]):
        obs, cs, ps = [], [], []
        for k, p in enumerate(poses_w, 1):
            uv, d = project(Xw[i : i + 1], cam, p, return_depth=True)
            u, v = uv[0]
            if d[0] > 0 and 0 <= u < cam.width and 0 <= v < cam.height:
                un, vn = uv[0] + rng.normal(0, noise_px, 2)
                obs.append((images[k].name, float(un), float(vn)))
                cs.append(cam)
                ps.append(p)
        role = "control" if i < n_control else "check"
        gcps.append(GCP(f"{'GCP' if role == 'control' else 'CHK'}{i + 1:02d}", Xw[i], role, gcp_sigma, tuple(obs)))
        if role == "check" and len(obs) >= 2:
            uv_exact = np.vstack([project(Xw[i : i + 1], c, q) for c, q in zip(cs, ps)])
            res = intersect(uv_exact, cs, ps, sigma_px=noise_px, a_posteriori=False)
            var_h.append(res.covariance[0, 0] + res.covariance[1, 1])
            var_z.append(res.covariance[2, 2])
    return gcps, {"rmse_h": float(np.sqrt(np.mean(var_h))), "rmse_z": float(np.sqrt(np.mean(var_z)))}


def _tie_tracks(rng: np.random.Generator, Tw: np.ndarray, cam: Camera, poses_w: list, noise_px: float) -> Tracks:
    """Observations with noise of the tie points ``Tw`` in every image (id 1, 2, ...) that sees them."""
    t_pt, t_img, t_uv = [], [], []
    for k, p in enumerate(poses_w, 1):
        uv, d = project(Tw, cam, p, return_depth=True)
        ok = np.flatnonzero((d > 0) & np.all((uv >= 0) & (uv < [cam.width, cam.height]), axis=1))
        t_pt.append(ok)
        t_img.append(np.full(ok.shape[0], k))
        t_uv.append(uv[ok] + rng.normal(0, noise_px, (ok.shape[0], 2)))
    return Tracks(np.concatenate(t_pt), np.concatenate(t_img), np.vstack(t_uv))


def gcp_scene(
    rng: np.random.Generator,
    noise_px: float = 0.5,
    n_control: int = 6,
    n_check: int = 12,
    flying_height: float = 120.0,
    n_tie: int = 0,
    bend: float = 0.0,
    scale_drift: float = 0.0,
    gcp_sigma: float | None = None,
):
    """An aerial block in a local model frame, with surveyed GCPs observed in its images.

    A 3 × 3 grid of nadir images (4000 × 3000 px, f = 3500 px, 60 % overlap) over a 150 m
    square of gently rolling terrain; the reconstruction is expressed in a model frame (scale
    1/25, rotated, shifted from the survey frame, as SfM would return it). Each GCP is observed
    in every image that sees it, with Gaussian pixel noise ``noise_px``.

    With ``n_tie`` > 0 the reconstruction also carries that many tie points with their tracks
    (observed in every image that sees them, same noise). ``bend`` and ``scale_drift`` deform
    the SfM model the way a self-calibrated block often is: camera centres and tie points are
    moved by a dome of ``bend`` metres at the block's half-width and a scale drifting by
    ``scale_drift`` (relative) across it, and each camera is turned by the local rotation of
    that deformation (so the model stays nearly self-consistent). The image observations are
    always the true projections plus noise.

    Returns
    -------
    reconstruction : Reconstruction
        Oriented images in the model frame (exact poses unless deformed).
    gcps : list of GCP
        Survey coordinates (UTM-like, metres), role control/check, image observations, σ
        ``gcp_sigma`` (None: not given).
    expected : dict
        ``rmse_h`` and ``rmse_z`` the check points should show from the image noise alone
        (root mean of the intersection variances with exact poses, metres).
    """
    cam = Camera(4000, 3000, 3500.0, 3500.0, 1999.5, 1499.5, model="PINHOLE")
    gsd = flying_height / cam.fx
    foot_x, foot_y = cam.width * gsd, cam.height * gsd
    origin = np.array([500000.0, 4100000.0, 200.0])
    poses_w = []
    for j in range(3):
        for i in range(3):
            C = origin + [i * 0.4 * foot_x, j * 0.4 * foot_y, flying_height]
            poses_w.append(pose_from_opk(rng.normal(0, 0.01), rng.normal(0, 0.01), rng.normal(0, 0.02), C))
    lo = origin[:2] - [0.1 * foot_x, 0.1 * foot_y]
    hi = origin[:2] + [0.9 * foot_x, 0.9 * foot_y]
    Xw = _terrain_points(rng, lo, hi, origin[2], n_control + n_check)
    # survey -> model similarity (what SfM would produce), and its inverse for the poses
    Rm = opk_to_matrix(0.3, -0.2, 1.1)
    to_model = Similarity(1 / 25.0, Rm, -Rm @ (origin + [60, 40, 0]) / 25.0)
    cams = {1: cam}
    centre = origin + [0.4 * foot_x, 0.4 * foot_y, 0.0]
    half = 0.5 * max(hi - lo)
    deformed = bend != 0 or scale_drift != 0
    images = {}
    for k, p in enumerate(poses_w, 1):
        if deformed:
            Cw, J = _warp(p.center[None], centre, half, bend, scale_drift)
            U, _, Vt = np.linalg.svd(J[0])
            Rd = p.R @ (U @ Vt).T
            p = Pose(Rd, -Rd @ Cw[0])
        images[k] = Image(f"IMG_{k:04d}.JPG", 1, to_model.apply_pose(p))
    rec = Reconstruction(cams, images, to_model.apply(Xw), None, None, {"synthetic": True})
    gcps, expected = _observed_gcps(rng, Xw, cam, poses_w, images, n_control, noise_px, gcp_sigma)
    if n_tie > 0:
        Tw = _terrain_points(rng, lo, hi, origin[2], n_tie)
        Tm = _warp(Tw, centre, half, bend, scale_drift)[0] if deformed else Tw
        rec = Reconstruction(cams, images, to_model.apply(Tm), None, None, {"synthetic": True},
                             _tie_tracks(rng, Tw, cam, poses_w, noise_px))
    return rec, gcps, expected
