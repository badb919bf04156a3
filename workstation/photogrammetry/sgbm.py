"""Rectified pairwise semi-global matching: the fast CPU depth maps of ``ws dense``.

For each reference image and each of its source views (chosen by
:func:`workstation.photogrammetry.dense.select_sources`):

1. **Rectify** the pair with ``cv2.stereoRectify`` (Bouguet's method: each camera turns by
   half the relative rotation, then both turn so the baseline is an image axis). The result is
   turned in-plane so the baseline always runs along +x (vertical and right-to-left pairs
   included) and both images share one pinhole ``K_rect`` with the reference's focal length,
   so a disparity ``d`` (pixels) means rectified depth ``f · b / d``.
2. **Match** with ``cv2.StereoSGBM`` (Hirschmüller, *Stereo processing by semiglobal matching
   and mutual information*, IEEE TPAMI 30(2), 2008; OpenCV's variant with Birchfield–Tomasi
   costs over ``block × block`` windows): the disparity range comes from the depth range of
   the sparse points both images see (or the reference's depth range), the built-in
   left-right check (``disp12MaxDiff``), the uniqueness ratio and the speckle filter reject
   occlusions and ambiguous matches. A range wider than ``max_disparities`` is first matched
   at half size to narrow it (coarse to fine). The sub-pixel part is re-fitted on the window
   SSD (:func:`refine_subpixel`), which removes most of the pull towards whole pixels of
   OpenCV's own fit.
3. **Un-rectify**: every reference pixel is sent to the rectified grid (the same homography
   ``K_rect · R1 · K⁻¹``), the disparity there is read (bilinear, refused across a
   discontinuity) and turned into depth along the reference ray.
4. **Merge** the pairs' depth maps per pixel: the median of the depths that agree with the
   per-pixel median within ``max_rel_depth``; where two or more pairs measured a pixel, two
   must agree (a two-view consistency vote, as in Merrell et al., *Real-time
   visibility-based fusion of depth maps*, ICCV 2007).

The merged maps then go through the same multi-view geometric filter and COLMAP fusion as the
plane sweep (:func:`workstation.photogrammetry.dense.geometric_filter`, ``fuse``), so both
methods write the same workspace.

Cost: one SGBM pass per pair, ``O(w · h · numDisparities)`` time and ``O(w · numDisparities)``
memory (MODE_SGBM / SGBM_3WAY keep one image row of the cost volume), against the sweep's
``planes × sources`` warps and box filters.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError

MODES = ("3way", "sgbm", "hh4", "hh")


@dataclass(frozen=True)
class SGBMParams:
    """Semi-global matching options (OpenCV ``StereoSGBM``).

    Attributes
    ----------
    block : int
        Matching window side, pixels (odd, 3-11).
    p1, p2 : float
        Smoothness penalties per ``block²`` for a disparity change of one pixel (``p1``) and of
        more (``p2``), grey levels (0-255); OpenCV's suggested 8 and 32 (``P1 = 8·block²``).
    uniqueness : int
        Percent by which the best cost must beat the second best (``uniquenessRatio``).
    lr_max_diff : int
        Left-right check tolerance, pixels (``disp12MaxDiff``; < 0 turns it off).
    speckle_window : int
        Largest connected region (pixels) of similar disparity removed as a speckle (0: off).
    speckle_range : int
        Disparity step (pixels) that separates speckle regions.
    mode : str
        OpenCV's aggregation: "3way" (three paths, the fastest, about half the CPU time of
        "sgbm"), "sgbm" (five paths), "hh4" (four paths) or "hh" (eight paths; memory
        ``w · h · numDisparities · 2`` bytes).
    max_disparities : int
        Most disparities searched per pair, pixels; a wider range is matched at half
        resolution first and narrowed to what that finds (coarse to fine).
    max_rect_scale : float
        Largest rectified image side over the input side; pairs whose rectification would
        grow the image more (near-perpendicular views) are skipped.
    subpixel : bool
        Re-fit the sub-pixel disparity on the window SSD (:func:`refine_subpixel`) instead of
        keeping OpenCV's (biased towards whole pixels).
    """

    block: int = 5
    p1: float = 8.0
    p2: float = 32.0
    uniqueness: int = 10
    lr_max_diff: int = 1
    speckle_window: int = 100
    speckle_range: int = 2
    mode: str = "3way"
    max_disparities: int = 256
    max_rect_scale: float = 2.0
    subpixel: bool = True

    def __post_init__(self):
        if self.block < 1 or self.block % 2 == 0 or self.block > 11:
            raise InvalidInputError("sgbm block must be odd, 1-11 pixels", field="block")
        if self.mode not in MODES:
            raise InvalidInputError(f"sgbm mode must be one of {MODES}", field="mode")
        if not 0 <= self.uniqueness <= 100:
            raise InvalidInputError("sgbm uniqueness is a percentage (0-100)", field="uniqueness")
        if self.max_disparities < 16:
            raise InvalidInputError("sgbm max_disparities must be ≥ 16", field="max_disparities")
        if not 0 < self.p1 < self.p2:
            raise InvalidInputError("sgbm penalties need 0 < p1 < p2", field="p1")


@dataclass(frozen=True)
class Rectification:
    """A rectified stereo pair (reference left, source right, baseline along +x).

    Attributes
    ----------
    R1, R2 : (3, 3) float
        Rotations from the reference / source camera frame to the rectified frames.
    K : (3, 3) float
        Shared rectified pinhole matrix (pixel centres at integers), pixels.
    size : (int, int)
        Rectified image (width, height), pixels.
    baseline : float
        Distance between the camera centres, model units (> 0).
    """

    R1: np.ndarray
    R2: np.ndarray
    K: np.ndarray
    size: tuple
    baseline: float

    @property
    def focal(self) -> float:
        return float(self.K[0, 0])

    def disparity(self, z_rect: np.ndarray) -> np.ndarray:
        """Disparity (pixels) of rectified depth ``z_rect``."""
        return self.focal * self.baseline / np.asarray(z_rect, float)


def _relative(ref, src):
    """(R, T) with ``x_src = R · x_ref + T`` (camera frames)."""
    R = src.R @ ref.R.T
    return R, src.t - R @ ref.t


def _in_plane(R1: np.ndarray, R2: np.ndarray, ref, src) -> tuple[np.ndarray, np.ndarray]:
    """Turn both rectifying rotations about the optical axis so that the source centre lies
    on the rectified +x axis (``stereoRectify`` may put it on ±x or ±y)."""
    c = R1 @ (ref.R @ (src.center - ref.center))  # source centre in the rectified frame
    a = np.arctan2(c[1], c[0])
    ca, sa = np.cos(a), np.sin(a)
    Rz = np.array([[ca, sa, 0.0], [-sa, ca, 0.0], [0.0, 0.0, 1.0]])  # turns c onto +x
    return Rz @ R1, Rz @ R2


def rectify(ref, src, pad: float = 0.0, max_scale: float = 2.0) -> Rectification | None:
    """Rectify the pair (``ref`` left, ``src`` right) on a grid that holds every reference pixel.

    Parameters
    ----------
    ref, src : dense._View
        Pinhole views (``K``, ``R``, ``t``, size).
    pad : float
        Extra columns on the left of the reference pixels, pixels (the largest disparity, so
        the matcher can search every reference pixel).
    max_scale : float
        Refuse (return None) when the rectified grid would be more than this times the
        reference image on a side.
    """
    import cv2

    R, T = _relative(ref, src)
    size = (int(ref.width), int(ref.height))
    R1, R2, *_ = cv2.stereoRectify(ref.K, None, src.K, None, size, R, T.reshape(3, 1),
                                   flags=cv2.CALIB_ZERO_DISPARITY, alpha=-1)
    R1, R2 = _in_plane(np.asarray(R1, float), np.asarray(R2, float), ref, src)
    f = float(0.5 * (ref.K[0, 0] + ref.K[1, 1]))
    w, h = size
    u, v = np.meshgrid(np.linspace(-0.5, w - 0.5, 9), np.linspace(-0.5, h - 0.5, 9))
    r = np.stack([u.ravel(), v.ravel(), np.ones(u.size)], -1) @ np.linalg.inv(ref.K).T @ R1.T
    if np.any(r[:, 2] <= 1e-6):
        return None
    x, y = f * r[:, 0] / r[:, 2], f * r[:, 1] / r[:, 2]
    x0, y0 = np.floor(x.min()) - np.ceil(pad), np.floor(y.min())
    W, H = int(np.ceil(x.max()) - x0) + 1, int(np.ceil(y.max()) - y0) + 1
    if W - pad > max_scale * w or H > max_scale * h:
        return None
    K = np.array([[f, 0.0, -x0], [0.0, f, -y0], [0.0, 0.0, 1.0]])
    return Rectification(R1, R2, K, (W, H), float(np.linalg.norm(src.center - ref.center)))


def rectify_images(rect: Rectification, ref, src, ref_img: np.ndarray, src_img: np.ndarray):
    """Resample the reference and source images (any dtype) on the rectified grid (bilinear;
    0 outside an image)."""
    return _rectify_one(rect, ref, rect.R1, ref_img), _rectify_one(rect, src, rect.R2, src_img)


def _rectify_one(rect: Rectification, view, R: np.ndarray, img: np.ndarray) -> np.ndarray:
    import cv2

    mx, my = cv2.initUndistortRectifyMap(view.K, None, R, rect.K, rect.size, cv2.CV_32FC1)
    return cv2.remap(img, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT, borderValue=0)


def to_rectified(rect: Rectification, ref) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rectified coordinates (x, y) of every reference pixel, (h, w) float32 each, and the z
    component of the reference rays (``K⁻¹ [u v 1]``, depth 1) in the rectified frame."""
    u = np.arange(int(ref.width), dtype=np.float64)[None]
    v = np.arange(int(ref.height), dtype=np.float64)[:, None]
    H = rect.R1 @ np.linalg.inv(ref.K)
    r0, r1, z = (H[i, 0] * u + H[i, 1] * v + H[i, 2] for i in range(3))
    x = rect.K[0, 0] * r0 / z + rect.K[0, 2]
    y = rect.K[1, 1] * r1 / z + rect.K[1, 2]
    return x.astype(np.float32), y.astype(np.float32), z


def disparity_to_depth(disp: np.ndarray, rect: Rectification, ref) -> np.ndarray:
    """Reference depth map (h, w) float32 (0 = none) from a rectified disparity map (NaN =
    none). A depth is read bilinearly, unless its four neighbours span more than one pixel of
    disparity (a discontinuity), and is ``f·b / (d · r_z)`` along the reference ray ``r``."""
    import cv2

    mx, my, rz = to_rectified(rect, ref)
    lin = cv2.remap(disp, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT, borderValue=np.nan)
    near = cv2.remap(disp, mx, my, cv2.INTER_NEAREST, borderMode=cv2.BORDER_CONSTANT, borderValue=np.nan)
    ok = np.isfinite(lin) & (np.abs(lin - near) <= 1.0) & (lin > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        depth = rect.focal * rect.baseline / (lin * rz)
    return np.where(ok & (depth > 0), depth, 0.0).astype(np.float32)


def scaled_view(view, s: float):
    """A copy of a view whose images are ``s`` times the size (pixel centres at integers)."""
    from dataclasses import replace

    S = np.diag([s, s, 1.0])
    K = S @ view.K
    K[:2, 2] += 0.5 * s - 0.5
    return replace(view, K=K, width=max(1, round(view.width * s)), height=max(1, round(view.height * s)))


def disparity_range(rect: Rectification, ref, points: np.ndarray | None = None) -> tuple[float, float]:
    """(smallest, largest) disparity of the pair, pixels: from the sparse points both views
    see (1st and 99th percentile of their rectified depth, widened by the factors 0.8 and 1.25
    that :func:`dense._load_views` uses), else from the reference's ``near``/``far`` along rays
    through a 9 × 9 grid of its pixels."""
    if points is not None and len(points) >= 20:
        z = ((np.asarray(points, float) @ ref.R.T + ref.t) @ rect.R1.T)[:, 2]
        z = z[z > 0]
        if z.size >= 20:
            near, far = np.percentile(z, 1) * 0.8, np.percentile(z, 99) * 1.25
            return float(rect.disparity(far)), float(rect.disparity(near))
    u, v = np.meshgrid(np.linspace(0, ref.width - 1, 9), np.linspace(0, ref.height - 1, 9))
    rz = (np.stack([u.ravel(), v.ravel(), np.ones(u.size)], -1) @ np.linalg.inv(ref.K).T @ rect.R1.T)[:, 2]
    rz = rz[rz > 0]
    return float(rect.disparity(ref.far * rz).min()), float(rect.disparity(ref.near * rz).max())


def sgbm_disparity(left: np.ndarray, right: np.ndarray, min_disp: int, num_disp: int, sp: SGBMParams) -> np.ndarray:
    """Disparity (pixels, float32, NaN where none) of the rectified uint8 pair by
    ``cv2.StereoSGBM`` searching ``[min_disp, min_disp + num_disp)`` (``num_disp`` a multiple
    of 16)."""
    import cv2

    modes = {"3way": cv2.STEREO_SGBM_MODE_SGBM_3WAY, "sgbm": cv2.STEREO_SGBM_MODE_SGBM,
             "hh4": cv2.STEREO_SGBM_MODE_HH4, "hh": cv2.STEREO_SGBM_MODE_HH}
    b2 = sp.block * sp.block
    m = cv2.StereoSGBM_create(minDisparity=int(min_disp), numDisparities=int(num_disp), blockSize=sp.block,
                              P1=int(sp.p1 * b2), P2=int(sp.p2 * b2), disp12MaxDiff=sp.lr_max_diff,
                              uniquenessRatio=sp.uniqueness, speckleWindowSize=sp.speckle_window,
                              speckleRange=sp.speckle_range, mode=modes[sp.mode])
    raw = m.compute(left, right)
    disp = raw.astype(np.float32) / 16.0
    disp[raw < min_disp * 16] = np.nan  # OpenCV marks "none" with (min_disp - 1) · 16
    return disp


def _search(d_lo: float, d_hi: float) -> tuple[int, int]:
    """(minDisparity, numDisparities) covering ``[d_lo, d_hi]``: a multiple of 16 wide."""
    lo = int(np.floor(max(d_lo, 0.0)))
    return lo, int(16 * np.ceil(max(d_hi - lo, 1.0) / 16))


def match_pair(ref_img: np.ndarray, src_img: np.ndarray, ref, src, sp: SGBMParams,
               d_range: tuple[float, float] | None = None, points: np.ndarray | None = None,
               coarse: bool = False) -> np.ndarray:
    """Depth map (h, w) float32 of the reference image (0 = none) from one source view.

    ``ref_img``/``src_img``: uint8 grey images of the views' sizes. The disparity range is
    ``d_range`` or :func:`disparity_range`; when it is wider than ``sp.max_disparities`` the
    pair is first matched at half size and the range narrowed to the 0.5–99.5 % of the
    disparities found there (± 2 full-size pixels), recursively (coarse to fine; ``coarse``
    marks such a range-finding pass, which skips the sub-pixel and border steps).
    """
    import cv2

    rect = rectify(ref, src, max_scale=sp.max_rect_scale)
    if rect is None:
        return np.zeros((ref.height, ref.width), np.float32)
    lo, hi = d_range if d_range is not None else disparity_range(rect, ref, points)
    if hi - lo > sp.max_disparities and min(ref.width, ref.height) >= 64:
        small = [cv2.resize(im, None, fx=0.5, fy=0.5, interpolation=cv2.INTER_AREA) for im in (ref_img, src_img)]
        sr, ss = scaled_view(ref, small[0].shape[1] / ref.width), scaled_view(src, small[1].shape[1] / src.width)
        dc = match_pair(small[0], small[1], sr, ss, sp, (lo * 0.5, hi * 0.5), coarse=True)
        if np.count_nonzero(dc) > 100:
            rc = rectify(sr, ss, max_scale=sp.max_rect_scale)
            rz = to_rectified(rc, sr)[2]
            d = rc.focal * rc.baseline / (dc[dc > 0] * rz[dc > 0]) * (rect.focal / rc.focal)
            lo, hi = max(lo, np.percentile(d, 0.5) - 2), min(hi, np.percentile(d, 99.5) + 2)
    min_d, num_d = _search(lo, hi)
    rect = rectify(ref, src, pad=min_d + num_d, max_scale=sp.max_rect_scale)
    if rect is None:
        return np.zeros((ref.height, ref.width), np.float32)
    left, right = rectify_images(rect, ref, src, ref_img, src_img)
    disp = sgbm_disparity(left, right, min_d, num_d, sp)
    if not coarse:
        if sp.subpixel:
            disp = refine_subpixel(left, right, disp, sp.block)
        inside = _rectify_one(rect, src, rect.R2, np.full(src_img.shape[:2], 255, np.uint8))
        disp[~_matched_inside(disp, inside)] = np.nan
    return disparity_to_depth(disp, rect, ref)


def refine_subpixel(left: np.ndarray, right: np.ndarray, disp: np.ndarray, block: int) -> np.ndarray:
    """Sub-pixel disparity by a parabola through the window SSD at the integer disparities
    ``round(d) - 1, round(d), round(d) + 1`` (integer shifts: no interpolation).

    OpenCV's own sub-pixel step fits a parabola to the aggregated absolute-difference costs,
    which pulls disparities towards integers ("pixel locking", Shimizu & Okutomi, *Sub-pixel
    estimation error cancellation on area-based matching*, IJCV 63(3), 2005); the SSD of a
    smooth image is close to quadratic in the shift, so its parabola has far less of that bias.
    Where the middle cost is not the smallest the SGBM value is kept.
    """
    import cv2

    h, w = disp.shape
    L = left.astype(np.float32)
    R = right.astype(np.float32)
    di = np.rint(np.nan_to_num(disp, nan=0.0))
    rows = np.broadcast_to(np.arange(h, dtype=np.float32)[:, None], (h, w))
    x = np.arange(w, dtype=np.float32)[None] - di.astype(np.float32)
    cost = []
    for k in (-1, 0, 1):  # whole-pixel shifts: nearest sampling is exact
        Rk = cv2.remap(R, x - k, rows, cv2.INTER_NEAREST, borderMode=cv2.BORDER_REPLICATE)
        diff = L - Rk
        cost.append(cv2.boxFilter(diff * diff, -1, (block, block), normalize=False, borderType=cv2.BORDER_REFLECT))
    cm, c0, cp = cost
    den = cm - 2 * c0 + cp
    ok = np.isfinite(disp) & (den > 1e-3) & (c0 <= cm) & (c0 <= cp)
    off = np.where(ok, 0.5 * (cm - cp) / np.where(ok, den, 1.0), 0.0)
    return np.where(ok, di + off, disp).astype(np.float32)


def _matched_inside(disp: np.ndarray, inside: np.ndarray) -> np.ndarray:
    """True where the match ``x - d`` of a rectified pixel lies on the source image (not on
    the zero border the rectification adds), with a margin of one pixel."""
    import cv2

    h, w = disp.shape
    x = np.arange(w, dtype=np.float32)[None] - np.nan_to_num(disp, nan=0.0)
    rows = np.broadcast_to(np.arange(h, dtype=np.float32)[:, None], (h, w))
    hit = cv2.remap(inside, x, rows, cv2.INTER_NEAREST, borderMode=cv2.BORDER_CONSTANT, borderValue=0)
    return (hit == 255) & np.isfinite(disp)


def merge_depths(depths: np.ndarray, max_rel: float) -> np.ndarray:
    """Merge (k, h, w) pairwise depth maps (0 = none) of one reference image into one (h, w)
    float32 map: per pixel, the median of the depths within ``max_rel`` (relative) of the
    median of all; a pixel two or more pairs measured needs two that agree."""
    D = np.where(depths > 0, depths, np.nan).astype(np.float32)
    n = np.isfinite(D).sum(0)
    med = _nan_median(D, n)
    cons = np.abs(D - med) <= max_rel * med
    c = cons.sum(0)
    out = _nan_median(np.where(cons, D, np.nan), c)
    keep = (c >= np.minimum(n, 2)) & (c > 0)
    return np.where(keep, out, 0.0).astype(np.float32)


def _nan_median(D: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Median over axis 0 of (k, h, w) values with NaN for none (``n`` finite per pixel)."""
    s = np.sort(D, axis=0)  # NaN last
    lo = np.clip((n - 1) // 2, 0, None)[None]
    hi = np.clip(n // 2, 0, None)[None]
    hi = np.minimum(hi, D.shape[0] - 1)
    m = 0.5 * (np.take_along_axis(s, lo, 0)[0] + np.take_along_axis(s, hi, 0)[0])
    return np.where(n > 0, m, np.nan)


def sgbm_depth(ref_img: np.ndarray, ref, src_imgs: list, srcs: list, sp: SGBMParams, max_rel: float,
               min_texture: float = 0.0, window: int = 7, points: list | None = None, workers: int = 1) -> np.ndarray:
    """Depth map (h, w) float32 (0 = none) of one reference image from its source views:
    :func:`match_pair` per source (``workers`` pairs at a time in threads; OpenCV releases
    the GIL; :func:`dense.compute_depth_maps` runs reference images in parallel instead),
    :func:`merge_depths`, then pixels whose grey-level standard deviation over a ``window``
    square is below ``min_texture`` (0-255 scale: sky, saturated areas) are dropped.

    ``points``: per source, the sparse points (n, 3) both views see, or None.
    """
    import cv2

    pts = points if points is not None else [None] * len(srcs)

    def one(k):
        return match_pair(ref_img, src_imgs[k], ref, srcs[k], sp, points=pts[k])

    if workers > 1 and len(srcs) > 1:
        from concurrent.futures import ThreadPoolExecutor

        with ThreadPoolExecutor(max_workers=min(workers, len(srcs))) as ex:
            depths = list(ex.map(one, range(len(srcs))))
    else:
        depths = [one(k) for k in range(len(srcs))]
    depth = merge_depths(np.stack(depths), max_rel)
    if min_texture > 0:
        a = ref_img.astype(np.float32)
        k = (window, window)
        m = cv2.boxFilter(a, -1, k, borderType=cv2.BORDER_REFLECT)
        sd = np.sqrt(np.maximum(cv2.boxFilter(a * a, -1, k, borderType=cv2.BORDER_REFLECT) - m * m, 0))
        depth[sd < min_texture] = 0.0
    return depth


__all__ = [
    "MODES",
    "Rectification",
    "SGBMParams",
    "disparity_range",
    "disparity_to_depth",
    "match_pair",
    "merge_depths",
    "rectify",
    "rectify_images",
    "refine_subpixel",
    "scaled_view",
    "sgbm_depth",
    "sgbm_disparity",
    "to_rectified",
]
