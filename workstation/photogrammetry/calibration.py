"""Camera calibration: Zhang's planar method (through OpenCV) and the 11-parameter DLT.

* Zhang, Z. (2000). A flexible new technique for camera calibration. IEEE TPAMI 22(11).
  Checkerboard corners come from OpenCV's detector refined to sub-pixel (``cornerSubPix``);
  the adjustment is ``cv2.calibrateCameraExtended`` (Bouguet's model: fx, fy, cx, cy, k1, k2,
  p1, p2, k3) which also gives parameter standard deviations and per-view errors.
* Abdel-Aziz, Y. I. & Karara, H. M. (1971). Direct linear transformation from comparator
  coordinates into object space coordinates in close-range photogrammetry. With Hartley's
  normalisation (Hartley & Zisserman 2004, §7.1 and §4.4) and an RQ decomposition of the
  3×3 left block into K and R (§6.2.4).

All pixel coordinates follow OpenCV (origin at the centre of the top-left pixel).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Sequence

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Pose

from workstation.core.geometry import affine_dimension

from workstation.io.textfile import read_text

from .collinearity import opk_from_pose, points_and_pixels, project

log = get_logger(__name__)

IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".tif", ".tiff", ".bmp", ".gif", ".pgm", ".ppm")


def natural_key(name: str):
    """Sort key that orders 'Image2' before 'Image10'."""
    return [int(t) if t.isdigit() else t.lower() for t in re.split(r"(\d+)", str(name))]


def list_images(folder) -> list[Path]:
    """Image files of a folder in natural order (non-image files are ignored)."""
    d = Path(folder)
    if not d.is_dir():
        raise InvalidInputError("not a folder of images", path=d)
    files = sorted((p for p in d.iterdir() if p.suffix.lower() in IMAGE_SUFFIXES), key=lambda p: natural_key(p.name))
    if not files:
        raise InvalidInputError("no image files (png, jpg, tif, ...) in the folder", path=d)
    return files


# --------------------------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class CalibrationResult:
    """A calibrated camera with its quality figures.

    Attributes
    ----------
    camera : Camera
    rms : float
        Root mean square reprojection error over all used corners, pixels.
    method : str
        "zhang" or "dlt".
    std : mapping of str to float
        Standard deviations of the estimated parameters (fx, fy, cx, cy in pixels, distortion
        coefficients unitless; for DLT also omega/phi/kappa in degrees and X/Y/Z in object units).
    per_image : list of dict
        ``{"name", "rms_px", "n_points"}`` for each used image.
    dropped : list of dict
        ``{"name", "reason"}`` for each image not used.
    poses : mapping of str to Pose
        Per-image exterior orientation (target/object frame -> camera).
    meta : mapping
    """

    camera: Camera
    rms: float
    method: str
    std: Mapping[str, float] = field(default_factory=dict)
    per_image: list = field(default_factory=list)
    dropped: list = field(default_factory=list)
    poses: Mapping[str, Pose] = field(default_factory=dict)
    meta: Mapping[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict:
        """The CAMERA.json document (see :mod:`workstation.io.camera`)."""
        from workstation.io.camera import camera_to_dict

        ext = []
        for name, p in self.poses.items():
            om, ph, ka = opk_from_pose(p)
            ext.append(
                {
                    "name": name,
                    "R": np.asarray(p.R).tolist(),
                    "t": np.asarray(p.t).tolist(),
                    "centre": np.asarray(p.center).tolist(),
                    "omega_deg": float(np.degrees(om)),
                    "phi_deg": float(np.degrees(ph)),
                    "kappa_deg": float(np.degrees(ka)),
                }
            )
        d = camera_to_dict(self.camera)
        d.update(
            {
                "rms": float(self.rms),
                "method": self.method,
                "std": {k: float(v) for k, v in self.std.items()},
                "per_image": list(self.per_image),
                "dropped": list(self.dropped),
                "extrinsics": ext,
            }
        )
        d.update({k: v for k, v in self.meta.items() if k not in d})
        return d


# --------------------------------------------------------------------------------------------
# Zhang
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ZhangParams:
    """Options of Zhang's calibration.

    Attributes
    ----------
    fix_k3 : bool
        Hold the sixth-order radial term k3 at 0 (Bouguet's 5-parameter default model has it 0;
        free k3 suits wide-angle lenses).
    fix_tangential : bool
        Hold p1 = p2 = 0.
    fix_aspect : bool
        Estimate one focal length (fx = fy).
    outlier_factor : float
        An image is an outlier when its RMS error exceeds ``max(outlier_factor × median,
        median + 5 × 1.4826 × MAD)`` of the per-image RMS errors; outliers are dropped and the
        calibration repeated (at most ``max_rounds`` times).
    max_rounds : int
    subpix_window : int
        Half-size of the ``cornerSubPix`` search window, pixels.
    min_views : int
        Fewest usable views accepted (Zhang's method needs at least 3 for a full K).
    estimate_skew : bool
        After OpenCV (which has no skew), refine all parameters with the skew K[0, 1] free by
        Levenberg–Marquardt on the collinearity equations (Zhang 2000, §3.3).
    """

    fix_k3: bool = True
    fix_tangential: bool = False
    fix_aspect: bool = False
    outlier_factor: float = 3.0
    max_rounds: int = 3
    subpix_window: int = 5
    min_views: int = 3
    estimate_skew: bool = False


def board_points(cols: int, rows: int, square: float) -> np.ndarray:
    """(cols·rows, 3) target coordinates of a checkerboard's inner corners (z = 0), in the unit
    of ``square``; row-major as OpenCV returns the corners."""
    gx, gy = np.meshgrid(np.arange(cols), np.arange(rows))
    return np.column_stack([gx.ravel() * square, gy.ravel() * square, np.zeros(cols * rows)])


def detect_checkerboard(images: Sequence[Path], cols: int, rows: int, subpix_window: int = 5):
    """Find the inner corners of a cols × rows checkerboard in each image, refined to sub-pixel
    (OpenCV ``findChessboardCornersSB``, then ``cornerSubPix`` with a ``subpix_window`` half-size).

    Returns
    -------
    found : list of (name, (cols·rows, 2) float64) for images where the board was found
    missing : list of dict {"name", "reason"}
    size : (width, height) of the images
    """
    import cv2

    from workstation.core.progress import track

    found, missing = [], []
    size = None
    crit = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 100, 1e-4)
    for path in track(list(images), "detect corners", unit="images"):
        img = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE)
        if img is None:
            missing.append({"name": Path(path).name, "reason": "cannot be read as an image"})
            continue
        if size is None:
            size = (img.shape[1], img.shape[0])
        elif size != (img.shape[1], img.shape[0]):
            missing.append({"name": Path(path).name, "reason": f"size {img.shape[1]}x{img.shape[0]} differs from {size}"})
            continue
        # the sector-based detector (Duda & Frese, BMVC 2018) finds boards the classic
        # quad detector misses (8 of Bouguet's 20 images); the classic one is the fallback
        ok, corners = cv2.findChessboardCornersSB(img, (cols, rows), flags=cv2.CALIB_CB_EXHAUSTIVE + cv2.CALIB_CB_ACCURACY)
        if not ok:
            flags = cv2.CALIB_CB_ADAPTIVE_THRESH + cv2.CALIB_CB_NORMALIZE_IMAGE
            ok, corners = cv2.findChessboardCorners(img, (cols, rows), flags=flags)
        if not ok:
            missing.append({"name": Path(path).name, "reason": f"{cols}x{rows} board not found"})
            continue
        w = int(subpix_window)
        corners = cv2.cornerSubPix(img, corners.astype(np.float32), (w, w), (-1, -1), crit)
        found.append((Path(path).name, corners.reshape(-1, 2).astype(np.float64)))
    return found, missing, size


def read_corner_files(model_file, corners_dir) -> tuple[np.ndarray, list[tuple[str, np.ndarray]]]:
    """Read a target model and per-image corner files in Zhang's text layout.

    Every file holds whitespace-separated numbers read as consecutive (x, y) pairs, any number
    per line. The model file gives the planar target coordinates; each corner file (one per
    image, files of ``corners_dir`` in natural order, ``*.txt``) gives the pixel coordinates of
    the same corners in the same order.

    Returns
    -------
    model : (n, 3) float64 (z = 0)
    views : list of (file name, (n, 2) float64)
    """
    model_file, corners_dir = Path(model_file), Path(corners_dir)
    if not model_file.is_file():
        raise InvalidInputError("model file not found", path=model_file)
    if not corners_dir.is_dir():
        raise InvalidInputError("corner folder not found", path=corners_dir)

    def pairs(p: Path) -> np.ndarray:
        try:
            v = np.array(read_text(p).split(), dtype=float)
        except ValueError:
            raise InvalidInputError("non-numeric text in a corner file", path=p) from None
        if v.size % 2:
            raise InvalidInputError(f"odd count of numbers ({v.size}): not x y pairs", path=p)
        return v.reshape(-1, 2)

    m = pairs(model_file)
    model = np.column_stack([m, np.zeros(len(m))])
    files = sorted(
        (p for p in corners_dir.iterdir() if p.is_file() and p.suffix.lower() == ".txt" and p.resolve() != model_file.resolve()),
        key=lambda p: natural_key(p.name),
    )
    views = []
    for p in files:
        c = pairs(p)
        if len(c) != len(model):
            raise InvalidInputError(f"{len(c)} corners but the model has {len(model)}", path=p)
        views.append((p.name, c))
    return model, views


def _require_views(nv: int, params: ZhangParams, dropped: list) -> None:
    """Refuse fewer than ``params.min_views`` views (naming the first dropped images)."""
    if nv < params.min_views:
        raise InvalidInputError(
            f"Zhang's method needs at least {params.min_views} views of the target, {nv} usable"
            + (f" ({len(dropped)} dropped: " + ", ".join(f"{d['name']}: {d['reason']}" for d in dropped[:5]) + ")" if dropped else ""),
            "take more photos of the board from different angles (ideally 10-20)",
        )


def _opencv_flags(params: ZhangParams) -> int:
    """``cv2.calibrateCamera`` flags of the parameters held fixed."""
    import cv2

    flags = 0
    if params.fix_k3:
        flags |= cv2.CALIB_FIX_K3
    if params.fix_tangential:
        flags |= cv2.CALIB_ZERO_TANGENT_DIST
    if params.fix_aspect:
        flags |= cv2.CALIB_FIX_ASPECT_RATIO
    return flags


def _calibrate_without_outliers(objs: list, views: list, image_size, params: ZhangParams, dropped: list):
    """OpenCV's calibration (``calibrateCameraExtended``), repeated without the outlier views
    (:class:`ZhangParams` ``outlier_factor``) at most ``max_rounds`` times; dropped views are
    appended to ``dropped``.

    Returns the views and target points used, the number of rounds and OpenCV's
    (rms, K, dist, rvecs, tvecs, std of the intrinsics, per-view RMS).
    """
    import cv2

    flags = _opencv_flags(params)
    crit = (cv2.TERM_CRITERIA_COUNT + cv2.TERM_CRITERIA_EPS, 200, 1e-12)
    rounds = 0
    while True:
        rounds += 1
        op = [o.astype(np.float32) for o in objs]
        ip = [v[1].astype(np.float32).reshape(-1, 1, 2) for v in views]
        K0 = np.eye(3) if params.fix_aspect else None  # FIX_ASPECT_RATIO keeps the ratio of K0 (1)
        rms, K, dist, rvecs, tvecs, std_in, std_ex, per_view = cv2.calibrateCameraExtended(
            op, ip, tuple(int(s) for s in image_size), K0, None, flags=flags, criteria=crit
        )
        per_view = np.asarray(per_view).ravel()
        med = float(np.median(per_view))
        mad = float(np.median(np.abs(per_view - med)))
        limit = max(params.outlier_factor * med, med + 5 * 1.4826 * mad)
        bad = np.nonzero(per_view > limit)[0]
        if len(bad) == 0 or rounds > params.max_rounds or len(views) - len(bad) < params.min_views:
            break
        for i in bad:
            dropped.append({"name": views[i][0], "reason": f"outlier: RMS {per_view[i]:.3f} px > limit {limit:.3f} px"})
            log.warning("dropping %s: reprojection RMS %.3f px > %.3f px", views[i][0], per_view[i], limit)
        keep = [i for i in range(len(views)) if i not in set(bad.tolist())]
        views = [views[i] for i in keep]
        objs = [objs[i] for i in keep]
        _require_views(len(views), params, dropped)
    return views, objs, rounds, (rms, K, dist, rvecs, tvecs, std_in, per_view)


def _view_table(views, objs, rvecs, tvecs, per_view) -> tuple[list, dict]:
    """Per-image rows ``{"name", "rms_px", "n_points"}`` and poses by image name."""
    import cv2

    per_image, poses = [], {}
    for (name, pts), o, rv, tv, e in zip(views, objs, rvecs, tvecs, per_view):
        R, _ = cv2.Rodrigues(rv)
        poses[name] = Pose(R, np.asarray(tv, dtype=float).ravel())
        per_image.append({"name": name, "rms_px": float(e), "n_points": int(len(pts))})
    return per_image, poses


def calibrate_zhang(
    object_points: np.ndarray | Sequence[np.ndarray],
    views: Sequence[tuple[str, np.ndarray]],
    image_size: tuple[int, int],
    params: ZhangParams = ZhangParams(),
    dropped: Sequence[Mapping] = (),
) -> CalibrationResult:
    """Zhang's calibration from ≥ 3 views of a planar target.

    Parameters
    ----------
    object_points : (n, 3) float or list of them (one per view)
        Target coordinates (z = 0); their unit is the unit of the extrinsics.
    views : list of (name, (n, 2) float)
        Measured pixels of the target points in each image.
    image_size : (width, height)
    params : ZhangParams
    dropped : list of dict
        Images already rejected (board not found), carried into the result.

    Returns
    -------
    CalibrationResult

    Raises
    ------
    InvalidInputError
        Fewer than ``params.min_views`` usable views.
    """
    dropped = [dict(d) for d in dropped]
    views = list(views)
    objs = object_points if isinstance(object_points, (list, tuple)) else [object_points] * len(views)
    objs = [np.asarray(o, dtype=np.float64) for o in objs]
    _require_views(len(views), params, dropped)
    views, objs, rounds, (rms, K, dist, rvecs, tvecs, std_in, per_view) = _calibrate_without_outliers(
        objs, views, image_size, params, dropped
    )
    dist = np.asarray(dist, dtype=float).ravel()
    d5 = np.zeros(5)
    d5[: min(5, dist.size)] = dist[:5]
    skew = 0.0
    s_in = np.asarray(std_in, dtype=float).ravel()
    std_skew = None
    if params.estimate_skew:
        K, skew, d5, rvecs, tvecs, rms, per_view, s_in, std_skew = _refine_with_skew(
            objs, [v[1] for v in views], K, d5, rvecs, tvecs, params
        )
    cam = Camera(
        width=int(image_size[0]),
        height=int(image_size[1]),
        fx=float(K[0, 0]),
        fy=float(K[1, 1]),
        cx=float(K[0, 2]),
        cy=float(K[1, 2]),
        skew=float(skew),
        dist=tuple(float(x) for x in d5),
        model="OPENCV",
    )
    names = ["fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2", "k3"]
    std = {n: float(s_in[i]) for i, n in enumerate(names) if i < s_in.size}
    if std_skew is not None:
        std["skew"] = float(std_skew)
    per_image, poses = _view_table(views, objs, rvecs, tvecs, per_view)
    result = CalibrationResult(
        camera=cam,
        rms=float(rms),
        method="zhang",
        std=std,
        per_image=per_image,
        dropped=dropped,
        poses=poses,
        meta={"views_used": len(views), "rounds": rounds, "fix_k3": params.fix_k3, "skew_estimated": params.estimate_skew},
    )
    if not np.isfinite(rms) or cam.fx <= 0 or cam.fy <= 0:
        raise StageError("calibrate", "OpenCV returned an invalid camera", "check the board size and corner order")
    return result


def _refine_with_skew(objs, pix, K, d5, rvecs, tvecs, params: ZhangParams):
    """Joint LM refinement of fx, fy, cx, cy, skew, the free distortion terms and every view's
    pose, started from OpenCV's solution (scipy ``least_squares``, MINPACK Levenberg–Marquardt)."""
    from scipy.optimize import least_squares

    from .collinearity import rotvec_to_matrix

    free_d = [0, 1] + ([] if params.fix_tangential else [2, 3]) + ([] if params.fix_k3 else [4])
    ni = 5 + len(free_d)
    V = len(objs)
    x0 = [K[0, 0], K[1, 1], K[0, 2], K[1, 2], 0.0] + [d5[i] for i in free_d]
    for rv, tv in zip(rvecs, tvecs):
        x0 += list(np.ravel(rv)) + list(np.ravel(tv))
    x0 = np.array(x0, dtype=float)
    counts = [len(o) for o in objs]

    def unpack(x):
        d = np.zeros(5)
        d[free_d] = x[5:ni]
        return Camera(1, 1, x[0], x[1], x[2], x[3], x[4], tuple(d))

    def resid(x):
        cam = unpack(x)
        out = []
        for k in range(V):
            p = x[ni + 6 * k : ni + 6 * k + 6]
            pose = Pose(rotvec_to_matrix(p[:3]), p[3:])
            out.append((project(objs[k], cam, pose) - pix[k]).ravel())
        return np.concatenate(out)

    m = 2 * sum(counts)
    if params.fix_aspect:
        raise InvalidInputError("fix_aspect and estimate_skew cannot be combined", field="estimate_skew")
    sol = least_squares(resid, x0, method="lm", xtol=1e-10, ftol=1e-10, max_nfev=200 * (ni + 6 * V))
    x = sol.x
    r = sol.fun
    J = sol.jac.toarray() if hasattr(sol.jac, "toarray") else np.asarray(sol.jac)
    dof = max(m - len(x), 1)
    s0 = r @ r / dof
    try:
        sd = np.sqrt(np.clip(np.diag(s0 * np.linalg.inv(J.T @ J)), 0, None))
    except np.linalg.LinAlgError:
        sd = np.full(len(x), np.nan)
    Kn = np.array([[x[0], x[4], x[2]], [0, x[1], x[3]], [0, 0, 1.0]])
    d = np.zeros(5)
    d[free_d] = x[5:ni]
    s_in = np.zeros(9)
    s_in[:4] = sd[:4]
    order = [4, 5, 6, 7, 8]  # k1 k2 p1 p2 k3 slots after fx fy cx cy
    for j, i in enumerate(free_d):
        s_in[order[i]] = sd[5 + j]
    rv = [x[ni + 6 * k : ni + 6 * k + 3] for k in range(V)]
    tv = [x[ni + 6 * k + 3 : ni + 6 * k + 6] for k in range(V)]
    per_view, r0 = [], 0
    for c in counts:
        rr = r[r0 : r0 + 2 * c].reshape(-1, 2)
        per_view.append(float(np.sqrt(np.mean(np.sum(rr**2, axis=1)))))
        r0 += 2 * c
    rms = float(np.sqrt(np.mean(r.reshape(-1, 2) ** 2) * 2))
    return Kn, float(x[4]), d, rv, tv, rms, np.array(per_view), s_in, float(sd[4])


def calibrate_zhang_images(
    folder, cols: int, rows: int, square: float, params: ZhangParams = ZhangParams()
) -> CalibrationResult:
    """Detect a cols × rows inner-corner checkerboard (square size ``square`` in the target unit)
    in every image of ``folder`` and run :func:`calibrate_zhang`.

    Tries the board both as cols × rows and rows × cols when no image shows it.
    """
    files = list_images(folder)
    found, missing, size = detect_checkerboard(files, cols, rows, params.subpix_window)
    if not found and cols != rows:
        found2, missing2, size2 = detect_checkerboard(files, rows, cols, params.subpix_window)
        if found2:
            log.warning("board found as %dx%d, not %dx%d", rows, cols, cols, rows)
            found, missing, size, cols, rows = found2, missing2, size2, rows, cols
    for m in missing:
        log.warning("skipping %s: %s", m["name"], m["reason"])
    obj = board_points(cols, rows, square)
    res = calibrate_zhang(obj, found, size, params, dropped=missing)
    meta = dict(res.meta)
    meta.update({"board": [cols, rows], "square": square, "images": len(files)})
    return CalibrationResult(res.camera, res.rms, res.method, res.std, res.per_image, res.dropped, res.poses, meta)


# --------------------------------------------------------------------------------------------
# DLT
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class DLTParams:
    """Options of the DLT.

    Attributes
    ----------
    refine : bool
        Refine the decomposed camera by Levenberg–Marquardt on the collinearity equations.
    distortion : int
        Distortion terms estimated in the refinement: 0 (none), 2 (k1, k2), 5 (k1, k2, p1, p2, k3).
    estimate_skew : bool
        Keep the skew free in the refinement (the linear DLT always has it).
    planarity_ratio : float
        The control points count as coplanar when the smallest singular value of their centred
        coordinates is below this fraction of the largest.
    """

    refine: bool = False
    distortion: int = 0
    estimate_skew: bool = True
    planarity_ratio: float = 0.02


def _normalise(pts: np.ndarray):
    c = pts.mean(axis=0)
    d = np.sqrt(np.mean(np.sum((pts - c) ** 2, axis=1)))
    s = np.sqrt(pts.shape[1]) / d if d > 0 else 1.0
    T = np.eye(pts.shape[1] + 1)
    T[:-1, :-1] *= s
    T[:-1, -1] = -s * c
    return T


def dlt_matrix(X: np.ndarray, uv: np.ndarray, planarity_ratio: float = 0.02) -> np.ndarray:
    """The 3×4 DLT projection matrix (11 independent parameters, ``P[2, 3]``-free scale) from ≥ 6
    non-coplanar control points, by normalised linear least squares.

    Parameters
    ----------
    X : (n, 3) float
        Object coordinates, n ≥ 6.
    uv : (n, 2) float
        Pixel coordinates.
    planarity_ratio : float
        See :class:`DLTParams`.

    Returns
    -------
    (3, 4) float64, scaled so that the last row's rotation part has unit norm.

    Raises
    ------
    InvalidInputError
        Fewer than 6 points, or coplanar / collinear points (DLT is singular for a plane).

    Examples
    --------
    >>> from workstation.photogrammetry.collinearity import pose_from_opk
    >>> cam = Camera(1000, 800, 1500.0, 1500.0, 500.0, 400.0)
    >>> pose = pose_from_opk(0.1, 0.05, -0.2, [1.0, 2.0, 30.0])
    >>> X = np.random.default_rng(0).uniform(-5, 5, (10, 3))
    >>> P = dlt_matrix(X, project(X, cam, pose))
    >>> K, R, C = decompose_projection(P)
    >>> np.round([K[0, 0], K[1, 1], K[0, 2], K[1, 2]], 4).tolist(), np.round(C, 4).tolist()
    ([1500.0, 1500.0, 500.0, 400.0], [1.0, 2.0, 30.0])
    """
    X, uv = points_and_pixels(X, uv)
    n = X.shape[0]
    if not (np.isfinite(X).all() and np.isfinite(uv).all()):
        raise InvalidInputError("a control point has a non-finite coordinate or pixel", "check the point file")
    if n < 6:
        raise InvalidInputError(f"DLT needs at least 6 control points, got {n}", "measure more control points")
    distinct = len(np.unique(X, axis=0))
    if distinct < 6:  # 11 parameters need 6 different points, not 6 rows
        raise InvalidInputError(f"DLT needs at least 6 distinct control points, got {distinct} (of {n} rows)",
                                "remove repeated rows and measure more control points")
    dim = affine_dimension(uv)
    if dim < 2:
        raise InvalidInputError(
            f"the {n} image points are {'all the same pixel' if dim == 0 else 'on one line'}",
            "check the u v columns of the point file")
    sv = np.linalg.svd(X - X.mean(axis=0), compute_uv=False)
    if sv[0] <= 0 or sv[2] < planarity_ratio * sv[0]:
        raise InvalidInputError(
            f"the control points are coplanar (thickness {sv[2] / max(sv[0], 1e-300):.2e} of their extent): "
            "the DLT is singular for a planar target",
            "use Zhang's method (ws calibrate zhang) for a planar target, or add control points off the plane",
        )
    T3 = _normalise(X)
    T2 = _normalise(uv)
    Xh = (T3 @ np.column_stack([X, np.ones(n)]).T).T
    xh = (T2 @ np.column_stack([uv, np.ones(n)]).T).T
    A = np.zeros((2 * n, 12))
    A[0::2, 0:4] = Xh
    A[0::2, 8:12] = -xh[:, 0:1] * Xh
    A[1::2, 4:8] = Xh
    A[1::2, 8:12] = -xh[:, 1:2] * Xh
    _, s, Vt = np.linalg.svd(A)
    Pn = Vt[-1].reshape(3, 4)
    P = np.linalg.inv(T2) @ Pn @ T3
    P = P / np.linalg.norm(P[2, :3])
    return P


def _check_dlt_camera(cam: Camera, rms: float) -> None:
    """Refuse a DLT camera no physical camera can be: a focal length that is not a positive
    number of pixels, a principal point outside the image, or residuals as large as the image
    (the pixels do not belong to the points)."""
    diag = float(np.hypot(cam.width, cam.height))
    bad = []
    if not (np.isfinite([cam.fx, cam.fy]).all() and min(cam.fx, cam.fy) >= 1.0):
        bad.append(f"focal length {cam.fx:.3g} x {cam.fy:.3g} px")
    if not (0.0 <= cam.cx <= cam.width and 0.0 <= cam.cy <= cam.height):
        bad.append(f"principal point ({cam.cx:.1f}, {cam.cy:.1f}) outside the {cam.width} x {cam.height} image")
    if rms > 0.1 * diag:
        bad.append(f"RMS residual {rms:.3g} px ({rms / diag:.0%} of the image diagonal)")
    if bad:
        raise StageError("calibrate", "the DLT camera is not physical: " + "; ".join(bad),
                         "check that the u v pixels match the X Y Z points row by row, their units and the image size")


def decompose_projection(P: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Split P = K [R | -R C] into K (upper triangular, positive diagonal, K[2,2] = 1), a proper
    rotation R and the centre C (Hartley & Zisserman 2004, §6.2.4, RQ decomposition)."""
    P = np.asarray(P, dtype=float)
    M = P[:, :3]
    if np.linalg.det(M) < 0:
        P = -P
        M = -M
    C = -np.linalg.solve(M, P[:, 3])
    # RQ via QR of the flipped transpose
    Fl = np.flipud(np.eye(3))
    Q, Rr = np.linalg.qr((Fl @ M).T)
    K = Fl @ Rr.T @ Fl
    R = Fl @ Q.T
    S = np.diag(np.sign(np.diag(K)))
    K = K @ S
    R = S @ R
    if np.linalg.det(R) < 0:
        R = -R
    K = K / K[2, 2]
    return K, R, C


def _camera_from_vector(v: np.ndarray, base: Camera, dist_terms: int, skew: bool) -> Camera:
    fx, fy, cx, cy = v[:4]
    i = 4
    sk = 0.0
    if skew:
        sk = v[i]
        i += 1
    d = np.zeros(5)
    if dist_terms == 2:
        d[:2] = v[i : i + 2]
    elif dist_terms == 5:
        d[:] = v[i : i + 5]
    return Camera(base.width, base.height, float(fx), float(fy), float(cx), float(cy), float(sk), tuple(d.tolist()), base.model)


def _levenberg_marquardt(resid, x: np.ndarray, steps: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimise ``|resid(x)|²`` by Levenberg–Marquardt with a central-difference Jacobian
    (parameter steps ``steps``); stops when no damping gives a lower cost or every update is
    below 1e-3 of its step. Returns the parameters and their residuals."""
    from .collinearity import numeric_jacobian

    r = resid(x)
    lam = 1e-3
    for _ in range(100):
        J = numeric_jacobian(lambda d: resid(x + d), len(x), steps)
        A = J.T @ J
        g = J.T @ r
        ok = False
        for _ in range(20):
            try:
                dx = np.linalg.solve(A + lam * np.diag(np.diag(A) + 1e-12), -g)
            except np.linalg.LinAlgError:
                lam *= 10
                continue
            rn = resid(x + dx)
            if rn @ rn <= r @ r:
                x, r, lam, ok = x + dx, rn, max(lam / 10, 1e-12), True
                break
            lam *= 10
        if not ok or np.max(np.abs(dx) / steps) < 1e-3:
            break
    return x, r


def _refine_dlt(X: np.ndarray, uv: np.ndarray, cam: Camera, R: np.ndarray, C: np.ndarray, params: DLTParams):
    """Refine the decomposed DLT camera and pose (and ``params.distortion`` terms) on the
    collinearity equations. Returns (camera, pose, standard deviations by name)."""
    from .collinearity import numeric_jacobian, rotvec_to_matrix

    dt = int(params.distortion)
    if dt not in (0, 2, 5):
        raise InvalidInputError("distortion terms must be 0, 2 or 5", field="distortion")
    v0 = [cam.fx, cam.fy, cam.cx, cam.cy] + ([cam.skew] if params.estimate_skew else []) + [0.0] * dt
    ni = len(v0)
    x0 = np.array(v0 + [0, 0, 0] + list(C), dtype=float)
    R0 = R.copy()
    scale = float(np.mean(np.linalg.norm(X - C, axis=1)))

    def unpack(x):
        c = _camera_from_vector(x[:ni], cam, dt, params.estimate_skew)
        Rn = R0 @ rotvec_to_matrix(x[ni : ni + 3]).T
        return c, Pose(Rn, -Rn @ x[ni + 3 : ni + 6])

    def resid(x):
        c, p = unpack(x)
        return (uv - project(X, c, p)).ravel()

    steps = np.concatenate([np.full(ni, 1e-6), np.full(3, 1e-8), np.full(3, 1e-8 * scale)])
    steps[:4] = 1e-6 * max(cam.fx, 1.0)
    if params.estimate_skew:
        steps[4] = 1e-6 * max(cam.fx, 1.0)
    x, r = _levenberg_marquardt(resid, x0.copy(), steps)
    refined, pose = unpack(x)
    J = numeric_jacobian(lambda d: resid(x + d), len(x), steps)
    n = X.shape[0]
    dof = 2 * n - len(x)
    if dof <= 0:
        raise InvalidInputError(
            f"{n} points cannot fix {len(x)} refined parameters", "add control points or estimate fewer distortion terms"
        )
    s0 = float(r @ r / dof)
    try:
        cov = s0 * np.linalg.inv(J.T @ J)
        sd = np.sqrt(np.clip(np.diag(cov), 0, None))
    except np.linalg.LinAlgError:
        sd = np.full(len(x), np.nan)
    names = ["fx", "fy", "cx", "cy"] + (["skew"] if params.estimate_skew else []) + (
        ["k1", "k2"] if dt == 2 else (["k1", "k2", "p1", "p2", "k3"] if dt == 5 else [])
    )
    std = {nm: float(sd[i]) for i, nm in enumerate(names)}
    std.update({"rot_x_deg": float(np.degrees(sd[ni])), "rot_y_deg": float(np.degrees(sd[ni + 1])), "rot_z_deg": float(np.degrees(sd[ni + 2]))})
    std.update({"X": float(sd[ni + 3]), "Y": float(sd[ni + 4]), "Z": float(sd[ni + 5])})
    return refined, pose, std


def calibrate_dlt(
    X: np.ndarray,
    uv: np.ndarray,
    image_size: tuple[int, int],
    params: DLTParams = DLTParams(),
    name: str = "image",
) -> CalibrationResult:
    """Calibrate and orient one camera from ≥ 6 non-coplanar control points by the DLT.

    The linear solution is decomposed into principal point, fx, fy, skew, rotation (ω, φ, κ)
    and centre; with ``params.refine`` all of them (and optionally distortion) are refined by
    Levenberg–Marquardt on the collinearity equations, which also yields standard deviations.

    Parameters
    ----------
    X : (n, 3) float
        Control points in object units.
    uv : (n, 2) float
        Measured pixels.
    image_size : (width, height)
    params : DLTParams
    name : str
        Image name used in the per-image table.

    Returns
    -------
    CalibrationResult
    """
    X = np.asarray(X, dtype=float)
    uv = np.asarray(uv, dtype=float)
    P = dlt_matrix(X, uv, params.planarity_ratio)
    K, R, C = decompose_projection(P)
    w, h = int(image_size[0]), int(image_size[1])
    cam = Camera(w, h, float(K[0, 0]), float(K[1, 1]), float(K[0, 2]), float(K[1, 2]), float(K[0, 1]), model="OPENCV")
    pose = Pose(R, -R @ C)
    std: dict[str, float] = {}
    n = X.shape[0]
    if params.refine:
        cam, pose, std = _refine_dlt(X, uv, cam, R, C, params)
    res = uv - project(X, cam, pose)
    rms = float(np.sqrt(np.mean(np.sum(res**2, axis=1))))
    if not np.isfinite(rms):
        raise StageError("calibrate", "DLT produced a non-finite camera", "check the control points")
    _check_dlt_camera(cam, rms)
    return CalibrationResult(
        camera=cam,
        rms=rms,
        method="dlt",
        std=std,
        per_image=[{"name": name, "rms_px": rms, "n_points": int(n)}],
        dropped=[],
        poses={name: pose},
        meta={
            "refined": bool(params.refine),
            "distortion_terms": int(params.distortion) if params.refine else 0,
            "dlt_parameters": (P / P[2, 3]).ravel()[:11].tolist() if abs(P[2, 3]) > 1e-300 else None,
            "residuals_px": res.tolist(),
        },
    )


def read_control_points(path) -> tuple[list[str], np.ndarray, np.ndarray]:
    """Read DLT control points: CSV or whitespace text with columns ``name X Y Z u v`` (a header
    line and ``#`` comments are allowed; the name column may be omitted: ``X Y Z u v``).

    Returns names, (n, 3) object coordinates and (n, 2) pixels.
    """
    p = Path(path)
    if not p.is_file():
        raise InvalidInputError("control point file not found", path=p)
    names, xs, us = [], [], []
    for lineno, line in enumerate(read_text(p).splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = [t for t in re.split(r"[,\s;]+", line) if t]
        try:
            vals = [float(t) for t in parts[-5:]]
        except ValueError:
            if not xs:  # header
                continue
            raise InvalidInputError(f"line {lineno}: expected name X Y Z u v", path=p) from None
        if len(parts) not in (5, 6):
            raise InvalidInputError(f"line {lineno}: expected name X Y Z u v, got {len(parts)} fields", path=p)
        names.append(parts[0] if len(parts) == 6 else f"p{len(names) + 1}")
        xs.append(vals[:3])
        us.append(vals[3:])
    if not xs:
        raise InvalidInputError("no control points in the file", path=p)
    return names, np.array(xs), np.array(us)
