"""Dense reconstruction: undistortion, depth/normal maps per image, fusion into a dense cloud.

Two depth-map back ends write the same COLMAP workspace (``WORKDIR/dense/stereo``), so one
fusion (``pycolmap.stereo_fusion``, CPU) turns either into ``WORKDIR/dense/fused.ply``:

- ``cuda``: COLMAP PatchMatch stereo (Schönberger et al., *Pixelwise View Selection for
  Unstructured Multi-View Stereo*, ECCV 2016) through ``pycolmap.patch_match_stereo``; needs a
  CUDA build of pycolmap (``pycolmap.has_cuda``). Geometric consistency is on, so it writes
  the same ``*.geometric.bin`` maps the CPU path writes; source views come from
  ``stereo/patch-match.cfg`` (COLMAP's ``__auto__, 20`` for an SfM model; for a model without
  sparse points, e.g. true rig cameras, the CPU path's selection and ``depth_range``).
- ``cpu``, ``method="sgbm"`` (the default): rectified pairwise semi-global matching
  (Hirschmüller, TPAMI 2008, through ``cv2.StereoSGBM``) of the reference image with each
  source view, the pairs' depths merged per pixel (:mod:`workstation.photogrammetry.sgbm`).
- ``cpu``, ``method="sweep"``: our plane-sweep stereo (Collins, *A space-sweep approach to
  true multi-image matching*, CVPR 1996; Gallup et al., *Real-time plane-sweeping stereo with
  multiple sweeping directions*, CVPR 2007): for each reference image, fronto-parallel planes
  uniformly spaced in inverse depth are swept through the scene; every source view is warped
  onto each plane by its homography (``cv2.warpPerspective``), scored by zero-mean NCC over a
  square window (box filters), the best ``k`` source scores are averaged (robust to
  occlusion), the best plane wins and a parabola through its neighbours refines the depth
  below the plane spacing.

Both CPU methods end with the same geometric consistency check (forward-backward
reprojection, as in COLMAP's geometric stage and Furukawa & Hernández, *Multi-View Stereo: A
Tutorial*, 2015, §3; Merrell et al., *Real-time visibility-based fusion of depth maps*, ICCV
2007): a depth is kept when at least ``min_consistent`` source depth maps agree with it.
Normals come from the depth map's local plane (cross product of back-projected neighbours).

Memory is bounded by the image size: SGBM holds one rectified pair and a few rows of its cost
volume per worker, the sweep a handful of float32 arrays of one reference image and its
sources at a time, and fusion reads the maps through COLMAP's cached workspace
(``fusion_cache_gb``) instead of loading all of them, so the image count adds only the fused
points.

Depth and normal maps use COLMAP's array format: a text header ``width&height&channels&``
followed by float32 data in column-major (width, height, channels) order (COLMAP's
``read_array``/``write_array``); depth 0 marks an invalid pixel.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import (
    InvalidInputError,
    MissingDependencyError,
    StageError,
)
from workstation.core.log import get_logger
from workstation.photogrammetry.sgbm import SGBMParams

log = get_logger(__name__)

DEVICES = ("auto", "cpu", "cuda")
METHODS = ("sgbm", "sweep")
#: source views per reference image when ``DenseParams.num_sources`` is None, by CPU method
DEFAULT_SOURCES = {"sgbm": 3, "sweep": 5}


@dataclass(frozen=True)
class DenseParams:
    """Options of :func:`run_dense`.

    Attributes
    ----------
    device : str
        "auto" (COLMAP PatchMatch when pycolmap has CUDA, else the CPU ``method``), "cpu", "cuda".
    method : str
        CPU depth maps: "sgbm" (rectified pairwise semi-global matching,
        :mod:`workstation.photogrammetry.sgbm`) or "sweep" (multi-view plane sweep).
    sgbm : SGBMParams
        Matching options of the "sgbm" method.
    max_image_size : int
        Longest side of the undistorted images used for stereo, pixels (-1: full size).
    num_sources : int, optional
        Source views per reference image (best by shared sparse points and triangulation
        angle); None: ``DEFAULT_SOURCES[method]`` (3 for "sgbm", each source a full two-view
        match; 5 for "sweep").
    top_k : int
        Best source NCC scores averaged per pixel and plane ("sweep").
    window : int
        NCC window side, pixels (odd).
    min_ncc : float
        Smallest aggregated NCC (-1..1) kept.
    max_planes : int
        Most depth planes per reference image; the count is set so neighbouring planes move
        the farthest source pixel by about ``plane_step_px``.
    plane_step_px : float
        Target disparity step between planes, pixels.
    min_angle_deg, max_angle_deg : float
        Median triangulation angle range (degrees) for a source view to be chosen.
    min_consistent : int
        Source depth maps that must agree with a depth (geometric consistency).
    max_reproj_px : float
        Forward-backward reprojection tolerance of the consistency check, pixels.
    max_rel_depth : float
        Relative depth tolerance of the consistency check (and of the agreement between the
        pairs of one reference image, "sgbm").
    min_texture : float
        Smallest grey-level standard deviation (0-255 scale) in the window; flatter pixels
        (sky, saturated areas) get no depth.
    depth_range : (float, float), optional
        (near, far) depth in model units for every image; by default from the sparse points
        seen by each image (needed when the model has no 3-D points, e.g. true rig cameras).
    fusion_min_pixels : int
        ``StereoFusionOptions.min_num_pixels``: pixels (in different images) that must agree
        for a fused point; itself a multi-view consistency check.
    fusion_cache_gb : float
        Fusion keeps at most this many GB of images, depth and normal maps in memory (COLMAP's
        cached workspace, least recently used out first); 0 loads every map at once (faster
        for a few images, but memory grows with the image count).
    num_threads : int
        OpenCV / fusion threads, and reference images matched at once by "sgbm" (-1: all
        cores).
    """

    device: str = "auto"
    method: str = "sgbm"
    sgbm: SGBMParams = SGBMParams()
    max_image_size: int = 1600
    num_sources: int | None = None
    top_k: int = 2
    window: int = 7
    min_ncc: float = 0.4
    max_planes: int = 192
    plane_step_px: float = 1.0
    min_angle_deg: float = 2.0
    max_angle_deg: float = 45.0
    min_consistent: int = 1
    max_reproj_px: float = 1.0
    max_rel_depth: float = 0.01
    min_texture: float = 2.0
    fusion_min_pixels: int = 2
    fusion_cache_gb: float = 1.0
    num_threads: int = -1
    depth_range: tuple | None = None

    def __post_init__(self):
        if self.device not in DEVICES:
            raise InvalidInputError(f"device must be one of {DEVICES}", field="device")
        if self.method not in METHODS:
            raise InvalidInputError(f"method must be one of {METHODS}", field="method")
        if self.window < 3 or self.window % 2 == 0:
            raise InvalidInputError("window must be an odd number ≥ 3", field="window")
        if self.fusion_cache_gb < 0:
            raise InvalidInputError("fusion_cache_gb must be ≥ 0 (0: no cache)", field="fusion_cache_gb")
        if self.sources < 1 or not 1 <= self.top_k <= self.sources:
            raise InvalidInputError("need num_sources ≥ 1 and 1 ≤ top_k ≤ num_sources", field="top_k")

    @property
    def sources(self) -> int:
        """Source views per reference image: ``num_sources`` or the method's default."""
        return DEFAULT_SOURCES[self.method] if self.num_sources is None else int(self.num_sources)


# ---------------------------------------------------------------------------------------------
# COLMAP array format
# ---------------------------------------------------------------------------------------------
def write_array(array: np.ndarray, path) -> Path:
    """Write a (h, w) or (h, w, c) array in COLMAP's format (header + column-major float32)."""
    a = np.asarray(array, np.float32)
    if a.ndim == 2:
        a = a[:, :, None]
    if a.ndim != 3:
        raise InvalidInputError(f"a depth/normal map is (h, w) or (h, w, c), got shape {array.shape}")
    h, w, c = a.shape
    p = Path(path)
    with open(p, "wb") as f:
        f.write(f"{w}&{h}&{c}&".encode())
        f.write(np.transpose(a, (1, 0, 2)).reshape(-1, order="F").astype("<f4").tobytes())
    return p


def read_array(path) -> np.ndarray:
    """Read a COLMAP depth/normal map: (h, w) for one channel, else (h, w, c) float32."""
    raw = Path(path).read_bytes()
    header, pos = [], 0
    for _ in range(3):
        j = raw.index(b"&", pos)
        header.append(int(raw[pos:j]))
        pos = j + 1
    w, h, c = header
    data = np.frombuffer(raw, "<f4", count=w * h * c, offset=pos)
    a = data.reshape((w, h, c), order="F").transpose(1, 0, 2)
    return a[:, :, 0].copy() if c == 1 else a.copy()


# ---------------------------------------------------------------------------------------------
# views
# ---------------------------------------------------------------------------------------------
@dataclass
class _View:
    name: str
    K: np.ndarray  # 3x3 (pixel centres at integers)
    R: np.ndarray
    t: np.ndarray
    width: int
    height: int
    near: float
    far: float

    @property
    def center(self) -> np.ndarray:
        return -self.R.T @ self.t


def _load_views(rec, depth_range=None, max_points: int = 200_000):
    """(views by image id, sparse points (n, 3), their track image ids, point indices per image)."""
    views, obs = {}, {}
    pts, ids = [], []
    for p in rec.points3D.values():
        pts.append(p.xyz)
        ids.append([el.image_id for el in p.track.elements])
        if len(pts) >= max_points:
            break
    pts = np.asarray(pts, float).reshape(-1, 3)
    for iid, im in rec.images.items():
        if not im.has_pose:
            continue
        cam = rec.cameras[im.camera_id]
        fx, fy, cx, cy = (list(np.asarray(cam.params, float)) + [0, 0, 0, 0])[:4]
        if str(cam.model_name) == "SIMPLE_PINHOLE":
            fx, fy, cx, cy = cam.params[0], cam.params[0], cam.params[1], cam.params[2]
        elif str(cam.model_name) != "PINHOLE":
            raise InvalidInputError(f"dense stereo needs undistorted PINHOLE cameras, got {cam.model_name}")
        K = np.array([[fx, 0, cx - 0.5], [0, fy, cy - 0.5], [0, 0, 1.0]])
        T = im.cam_from_world() if callable(im.cam_from_world) else im.cam_from_world
        views[int(iid)] = _View(im.name, K, np.asarray(T.rotation.matrix(), float), np.asarray(T.translation, float),
                                int(cam.width), int(cam.height), 0.0, 0.0)
        obs[int(iid)] = []
    for k, track in enumerate(ids):
        for i in set(track):
            if i in obs:
                obs[i].append(k)
    for iid, v in views.items():
        if depth_range is not None:
            v.near, v.far = float(depth_range[0]), float(depth_range[1])
            continue
        idx = np.asarray(obs[iid], np.int64)
        if idx.size < 3:
            raise StageError("dense", f"image {v.name} sees {idx.size} sparse points",
                             "re-run SfM (dense needs a sparse model) or give DenseParams.depth_range")
        z = (pts[idx] @ v.R.T + v.t)[:, 2]
        z = z[z > 0]
        v.near, v.far = float(np.percentile(z, 1) * 0.8), float(np.percentile(z, 99) * 1.25)
    return views, pts, ids, obs


def _pair_point(vi: _View, vj: _View) -> np.ndarray:
    """A scene point that view ``i`` and view ``j`` both look at, for a model without sparse
    points: on ``i``'s optical axis, at the depth where it passes closest to ``j``'s axis
    (two converging views aim at the scene), clamped to ``i``'s ``[near, far]``; where the
    axes are within about 2° of parallel or meet behind a camera (nadir strips, diverging
    views), the axis point at the harmonic mean of ``near`` and ``far``.

    The harmonic mean alone is not enough: with a loose depth range (e.g. 5-120 m for a
    building 50 m away) it lies far in front of the scene, where a neighbouring view does
    not see it, and no source view would be chosen.
    """
    di, dj = vi.R[2], vj.R[2]
    w0 = vi.center - vj.center
    b, d, e = float(di @ dj), float(di @ w0), float(dj @ w0)
    den = 1.0 - b * b
    s = 2.0 / (1.0 / vi.near + 1.0 / vi.far)
    if den > 1e-3:
        si, sj = (b * e - d) / den, (e - b * d) / den  # closest points: Ci + si·di, Cj + sj·dj
        if si > 0 and sj > 0:
            s = float(np.clip(si, vi.near, vi.far))
    return vi.center + di * s


def select_sources(views, pts, obs, params: DenseParams) -> dict[int, list[int]]:
    """Source views per image: most shared sparse points whose median triangulation angle is in
    [min_angle_deg, max_angle_deg] (the view-selection heuristic of Goesele et al., *Multi-View
    Stereo for Community Photo Collections*, ICCV 2007, simplified). Without sparse points
    (given cameras) a candidate must see the pair's :func:`_pair_point` in frame, at a
    triangulation angle in that range."""
    sets = {i: set(v) for i, v in obs.items()}
    out = {}
    for i, vi in views.items():
        cand = []
        for j, vj in views.items():
            if j == i:
                continue
            if len(pts) == 0:  # no sparse points: where the two optical axes meet
                P = _pair_point(vi, vj)
                xj = vj.K @ (vj.R @ P + vj.t)
                if xj[2] <= 0 or not (0 <= xj[0] / xj[2] < vj.width and 0 <= xj[1] / xj[2] < vj.height):
                    continue
                a, b = (P - vi.center)[None], (P - vj.center)[None]
                cosang = np.sum(a * b, 1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
                ang = float(np.degrees(np.arccos(np.clip(cosang[0], -1, 1))))
                if params.min_angle_deg <= ang <= params.max_angle_deg:
                    cand.append((1.0 / (1.0 + abs(ang - 15.0)), j))  # prefer ~15° (the rig step)
                continue
            shared = np.fromiter(sets[i] & sets[j], np.int64)
            if shared.size < 5:
                continue
            a = pts[shared] - vi.center
            b = pts[shared] - vj.center
            cosang = np.sum(a * b, 1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
            ang = float(np.degrees(np.median(np.arccos(np.clip(cosang, -1, 1)))))
            if params.min_angle_deg <= ang <= params.max_angle_deg:
                w = min(1.0, ang / 5.0)  # penalise tiny baselines (poor depth precision)
                cand.append((shared.size * w, j))
        cand.sort(reverse=True)
        out[i] = [j for _, j in cand[: params.sources]]
    return out


# ---------------------------------------------------------------------------------------------
# plane sweep
# ---------------------------------------------------------------------------------------------
def _grey(path, size, dtype=np.float32) -> np.ndarray:
    import cv2

    img = cv2.imread(str(path), cv2.IMREAD_GRAYSCALE)
    if img is None:
        raise InvalidInputError("cannot read image", path=path)
    if (img.shape[1], img.shape[0]) != size:
        img = cv2.resize(img, size, interpolation=cv2.INTER_AREA)
    return img.astype(dtype, copy=False)


def _box(a, r):
    import cv2

    return cv2.boxFilter(a, -1, (2 * r + 1, 2 * r + 1), borderType=cv2.BORDER_REFLECT)


def _plane_inverse_depths(shape: tuple, srcs: list[_View], rel: list, Kinv: np.ndarray, near: float, far: float,
                          params: DenseParams) -> np.ndarray:
    """Inverse depths of the sweep planes, uniform from ``1/near`` to ``1/far``; their count is
    the largest disparity range of the centre of the (h, w) reference image among the sources
    over ``plane_step_px`` (16 to ``max_planes``)."""
    h, w = shape
    ray = Kinv @ np.array([w / 2, h / 2, 1.0])
    span = 0.0
    for s, (Rrel, trel) in zip(srcs, rel):
        p0 = s.K @ (Rrel @ (ray * near) + trel)
        p1 = s.K @ (Rrel @ (ray * far) + trel)
        span = max(span, float(np.hypot(*(p0[:2] / p0[2] - p1[:2] / p1[2]))))
    n_planes = int(np.clip(np.ceil(span / params.plane_step_px), 16, params.max_planes))
    return np.linspace(1.0 / near, 1.0 / far, n_planes)


def _plane_ncc(ref_img, mr, sr, src_imgs, srcs: list[_View], rel: list, Kinv: np.ndarray, d: float, r: int) -> np.ndarray:
    """(sources, h, w) windowed NCC of the reference image with each source image warped onto
    it through the fronto-parallel plane at depth ``d`` (-1 where the source has no pixel).
    ``mr``/``sr``: windowed mean and standard deviation of the reference image."""
    import cv2

    h, w = ref_img.shape
    eps = 1e-3
    n = np.array([0.0, 0.0, 1.0])
    scores = np.empty((len(srcs), h, w), np.float32)
    for si, (s, img) in enumerate(zip(srcs, src_imgs)):
        Rrel, trel = rel[si]
        H = s.K @ (Rrel + np.outer(trel, n) / d) @ Kinv  # ref pixel -> source pixel
        warped = cv2.warpPerspective(img, H, (w, h), flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP,
                                     borderMode=cv2.BORDER_CONSTANT, borderValue=-1.0)
        valid = warped >= 0  # border value -1 marks pixels outside the source image
        ms = _box(warped, r)
        vs = np.maximum(_box(warped * warped, r) - ms * ms, 0)
        cov = _box(ref_img * warped, r) - mr * ms
        ncc = cov / (sr * np.sqrt(vs) + eps)
        ncc[~valid] = -1.0
        scores[si] = ncc
    return scores


def _subplane_depth(inv, best, best_k, s_prev, s_next, textured, params: DenseParams) -> np.ndarray:
    """Depth from the best plane refined by a parabola through the scores of planes k-1, k,
    k+1 (in inverse depth); 0 where the score, the texture or the plane index is unusable."""
    n_planes = len(inv)
    interior = (best_k > 0) & (best_k < n_planes - 1)
    den = s_prev - 2 * best + s_next
    off = np.where(interior & (den < -1e-6), 0.5 * (s_prev - s_next) / np.where(den < -1e-6, den, -1), 0.0)
    off = np.clip(off, -0.5, 0.5)
    kf = best_k + off
    step = (inv[-1] - inv[0]) / max(n_planes - 1, 1)
    invd = inv[0] + kf * step
    return np.where((best >= params.min_ncc) & textured & interior & (invd > 0), 1.0 / np.maximum(invd, 1e-12), 0.0)


def plane_sweep(ref_img, ref: _View, src_imgs, srcs: list[_View], params: DenseParams, near=None, far=None):
    """Winner-take-all plane-sweep depth of one reference image.

    Parameters
    ----------
    ref_img : (h, w) float32
        Grey reference image (0-255).
    ref : _View
    src_imgs : list of (h', w') float32
    srcs : list of _View
    params : DenseParams
    near, far : float, optional
        Depth range, metres (default: the view's sparse range).

    Returns
    -------
    depth : (h, w) float32
        Depth along the optical axis (0 = none), model units.
    score : (h, w) float32
        Aggregated NCC of the chosen plane.
    """
    near = ref.near if near is None else near
    far = ref.far if far is None else far
    h, w = ref_img.shape
    r = params.window // 2
    mr = _box(ref_img, r)
    sr = np.sqrt(np.maximum(_box(ref_img * ref_img, r) - mr * mr, 0))
    textured = sr >= params.min_texture
    Kinv = np.linalg.inv(ref.K)
    rel = [(s.R @ ref.R.T, s.t - s.R @ ref.R.T @ ref.t) for s in srcs]
    inv = _plane_inverse_depths((h, w), srcs, rel, Kinv, near, far, params)
    n_planes = len(inv)
    best = np.full((h, w), -2.0, np.float32)
    best_k = np.full((h, w), -1, np.int32)
    s_prev = np.zeros((h, w), np.float32)
    s_next = np.zeros((h, w), np.float32)
    prev = np.full((h, w), -2.0, np.float32)
    k_top = min(params.top_k, len(srcs))
    for k, invd in enumerate(inv):
        scores = _plane_ncc(ref_img, mr, sr, src_imgs, srcs, rel, Kinv, 1.0 / invd, r)
        if k_top == 1:
            agg = scores.max(0)
        else:
            agg = -np.partition(-scores, k_top - 1, axis=0)[:k_top].mean(0)
        # the plane after the current best gives the right neighbour of the parabola
        upd_next = best_k == k - 1
        s_next[upd_next] = agg[upd_next]
        better = agg > best
        best[better] = agg[better]
        best_k[better] = k
        s_prev[better] = prev[better]
        prev = agg
    depth = _subplane_depth(inv, best, best_k, s_prev, s_next, textured, params)
    return depth.astype(np.float32), best


def depth_normals(depth: np.ndarray, K: np.ndarray) -> np.ndarray:
    """(h, w, 3) float32 unit normals (camera frame, facing the camera) from a depth map by the
    cross product of the differences of back-projected neighbours along the rows and along the
    columns; 0 where undefined. Each difference is central where both neighbours have a depth
    and one-sided where only one has, so a depth needs one neighbour along each image axis:
    requiring all four would also drop every depth on the rim of a hole or of a patch (many,
    on the speckled maps of obliquely seen surfaces), and fusion needs a normal for each
    depth it uses. The points are computed in the precision of ``depth`` and ``K`` together
    (float64 for a float64 ``K``): neighbouring points differ by about z / f, which float32
    would resolve to only about 1e-4 of that."""
    h, w = depth.shape
    u = np.arange(w, dtype=np.float32)[None, :]
    v = np.arange(h, dtype=np.float32)[:, None]
    P = np.empty((h, w, 3), np.result_type(np.float32, depth.dtype, K.dtype))
    P[..., 0] = (u - K[0, 2]) / K[0, 0] * depth
    P[..., 1] = (v - K[1, 2]) / K[1, 1] * depth
    P[..., 2] = depth
    ok = depth > 0
    dx, okx = _difference(P, ok, axis=1)
    dy, oky = _difference(P, ok, axis=0)
    nrm = np.empty_like(P)  # dx × dy, by component (np.cross holds several (h, w, 3) temporaries)
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        nrm[..., i] = dx[..., j] * dy[..., k]
        nrm[..., i] -= dx[..., k] * dy[..., j]
    del dx, dy
    ln = np.linalg.norm(nrm, axis=-1, keepdims=True)
    good = okx & oky & (ln[..., 0] > 0)  # a difference needs the pixel's own depth
    nrm /= np.maximum(ln, 1e-12)
    nrm[~good] = 0
    # make normals face the camera: n · P <= 0
    flip = nrm[..., 0] * P[..., 0] + nrm[..., 1] * P[..., 1] + nrm[..., 2] * P[..., 2] > 0
    nrm[flip] *= -1
    return nrm.astype(np.float32)


def _difference(P: np.ndarray, ok: np.ndarray, axis: int) -> tuple[np.ndarray, np.ndarray]:
    """Difference (h, w, 3) of the points ``P`` along image ``axis`` (1: columns, 0: rows) per
    unit step, and where one was found (h, w) bool. The forward differences between ``ok``
    neighbours are added to both pixels of each pair and divided by their number at each pixel:
    (next - previous) / 2 where both neighbours are ``ok``, next - self or self - previous where
    one is, 0 where none is."""
    lo = (slice(None),) * axis + (slice(0, -1),)
    hi = (slice(None),) * axis + (slice(1, None),)
    okf = ok[hi] & ok[lo]
    f = P[hi] - P[lo]
    f[~okf] = 0  # also clears the NaN of a point without a depth
    d = np.zeros_like(P)
    d[lo] += f
    d[hi] += f
    del f
    n = np.zeros(ok.shape, np.uint8)
    n[lo] += okf
    n[hi] += okf
    d /= np.maximum(n, 1)[..., None]
    return d, n > 0


def geometric_filter(depth: np.ndarray, ref: _View, src_depths, srcs: list[_View], params: DenseParams) -> np.ndarray:
    """Keep depths that ``min_consistent`` source depth maps confirm (forward-backward
    reprojection within ``max_reproj_px`` and relative depth within ``max_rel_depth``).

    For each source, a reference pixel's point goes into the source camera (relative pose),
    takes the source depth at its sub-pixel projection (:func:`_sample_depth`), goes back
    along that source ray at that depth into the reference camera, and counts as confirmed
    when it lands within ``max_reproj_px`` of the pixel it started from at a depth within
    ``max_rel_depth`` of the reference depth. Only the valid pixels are processed, in float32.
    """
    h, w = depth.shape
    idx = np.flatnonzero(depth > 0)
    v, u = np.divmod(idx, w)
    u, v = u.astype(np.float32), v.astype(np.float32)
    z = depth.reshape(-1)[idx].astype(np.float32)
    P = _unproject(np.linalg.inv(ref.K), u, v, z)
    count = np.zeros(idx.size, np.int32)
    for s, ds in zip(srcs, src_depths):
        Rr = s.R @ ref.R.T
        tr = s.t - Rr @ ref.t
        Xs = _transform(Rr, tr, P)
        us, vs, zs = _project(s.K, Xs)
        dsamp = _sample_depth(ds, us, vs)
        Xb = _transform(Rr.T, -Rr.T @ tr, _unproject(np.linalg.inv(s.K), us, vs, dsamp))
        ub, vb, zb = _project(ref.K, Xb)
        with np.errstate(divide="ignore", invalid="ignore"):
            err = np.hypot(ub - u, vb - v)
            rel = np.abs(zb - z) / z
        count += (zs > 0) & (dsamp > 0) & (zb > 0) & (err <= params.max_reproj_px) & (rel <= params.max_rel_depth)
    out = np.zeros(h * w, np.float32)
    keep = count >= params.min_consistent
    out[idx[keep]] = z[keep]
    return out.reshape(h, w)


def _sample_depth(depth: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Depth (float32, 0 = none) of the map ``depth`` at sub-pixel positions (u, v): the
    bilinear interpolation of inverse depth over the four surrounding pixels where the position
    lies between pixel centres of the map and all four have a depth (inverse depth is affine in
    the pixel coordinates over a plane, so a planar patch is sampled exactly however obliquely
    it is seen); else the nearest pixel's depth (0 outside the map). Four pixels that all have
    a depth are interpolated even when they straddle a depth edge."""
    h, w = depth.shape
    ui, vi = np.rint(u), np.rint(v)
    inside = (ui >= 0) & (ui < w) & (vi >= 0) & (vi < h)
    yi, xi = np.where(inside, vi, 0).astype(np.int64), np.where(inside, ui, 0).astype(np.int64)
    near = np.where(inside, depth[yi, xi], 0)
    u0, v0 = np.floor(u), np.floor(v)
    box = (u0 >= 0) & (u0 < w - 1) & (v0 >= 0) & (v0 < h - 1)
    x0, y0 = np.where(box, u0, 0).astype(np.int64), np.where(box, v0, 0).astype(np.int64)
    x1, y1 = np.minimum(x0 + 1, w - 1), np.minimum(y0 + 1, h - 1)  # in the map when h or w is 1
    q = np.stack([depth[y0, x0], depth[y0, x1], depth[y1, x0], depth[y1, x1]])
    full = box & np.all(q > 0, axis=0)
    a, b = (u - u0).astype(np.float32), (v - v0).astype(np.float32)
    inv = 1.0 / np.where(q > 0, q, 1.0)
    inv = (1 - b) * ((1 - a) * inv[0] + a * inv[1]) + b * ((1 - a) * inv[2] + a * inv[3])
    return np.where(full, 1.0 / inv, near).astype(np.float32)


def _unproject(Kinv: np.ndarray, u, v, z) -> tuple:
    """Camera-frame points (x, y, z) of pixels (u, v) at depths z (float32 arrays)."""
    k = Kinv.astype(np.float32)
    return ((k[0, 0] * u + k[0, 1] * v + k[0, 2]) * z, (k[1, 1] * v + k[1, 2]) * z, z)


def _transform(R: np.ndarray, t: np.ndarray, P: tuple) -> tuple:
    """``R · P + t`` for points given as a tuple of coordinate arrays."""
    R, t = R.astype(np.float32), t.astype(np.float32)
    return tuple(R[i, 0] * P[0] + R[i, 1] * P[1] + R[i, 2] * P[2] + t[i] for i in range(3))


def _project(K: np.ndarray, P: tuple) -> tuple:
    """Pixels (u, v) and depth of camera-frame points; points behind the camera get (-1, -1)."""
    K = K.astype(np.float32)
    z = P[2]
    front = z > 0
    zz = np.where(front, z, 1)
    u = np.where(front, (K[0, 0] * P[0] + K[0, 1] * P[1]) / zz + K[0, 2], -1).astype(np.float32)
    v = np.where(front, K[1, 1] * P[1] / zz + K[1, 2], -1).astype(np.float32)
    return u, v, z


# ---------------------------------------------------------------------------------------------
# driver
# ---------------------------------------------------------------------------------------------
def resolve_device(device: str) -> str:
    """"cpu" or "cuda" for a requested device; "cuda" needs a CUDA build of pycolmap."""
    from workstation.interop.pycolmap import import_pycolmap

    has_cuda = bool(getattr(import_pycolmap(), "has_cuda", False))
    if device == "cuda" and not has_cuda:
        raise MissingDependencyError("pycolmap (CUDA build)", "COLMAP PatchMatch stereo on the GPU",
                                     "install a CUDA wheel of pycolmap on a machine with an NVIDIA GPU, or use --device cpu")
    if device == "auto":
        device = "cuda" if has_cuda else "cpu"
        log.info("dense device: %s (pycolmap.has_cuda = %s)", device, has_cuda)
    return device


def find_model(workdir) -> Path:
    """The sparse model folder of a workdir (``sparse/0``, ``sparse``) or the folder itself."""
    w = Path(workdir)
    for c in (w / "sparse" / "0", w / "sparse", w):
        if (c / "cameras.bin").exists() or (c / "cameras.txt").exists():
            return c
    raise InvalidInputError("no COLMAP model found", "give an SfM workdir (ws sfm -o WORKDIR) with sparse/0", path=w)


def undistort(workdir, image_dir, max_image_size: int = -1, overwrite: bool = False, num_src_images: int = 20) -> Path:
    """Undistort the images of the workdir's model into ``WORKDIR/dense`` (COLMAP layout:
    ``images/``, ``sparse/``, ``stereo/``) with ``pycolmap.undistort_images``.

    ``num_src_images`` goes to ``stereo/patch-match.cfg`` (``__auto__, N``: COLMAP PatchMatch
    picks the N images sharing most sparse points; 20 is COLMAP's command-line default).
    """
    from workstation.interop.pycolmap import import_pycolmap

    pycolmap = import_pycolmap()
    out = Path(workdir) / "dense"
    if out.exists() and any(out.iterdir()):
        if not overwrite:
            from workstation.core.errors import OutputExistsError

            raise OutputExistsError(out)
        import shutil

        shutil.rmtree(out)
    opt = pycolmap.UndistortCameraOptions()
    opt.max_image_size = int(max_image_size)
    pycolmap.undistort_images(str(out), str(find_model(workdir)), str(image_dir),
                              num_patch_match_src_images=int(num_src_images), undistort_options=opt)
    return out


def patch_match_options(params: DenseParams):
    """``pycolmap.PatchMatchOptions`` for the CUDA path: geometric consistency on (so that
    ``stereo_fusion`` reads ``*.geometric.bin`` as on the CPU path), the same image size, NCC
    window and depth range as the CPU path; COLMAP's defaults for the rest."""
    from workstation.interop.pycolmap import import_pycolmap

    opt = import_pycolmap().PatchMatchOptions()
    opt.geom_consistency = True
    opt.max_image_size = int(params.max_image_size)
    opt.window_radius = int(params.window // 2)
    if params.depth_range is not None:
        opt.depth_min, opt.depth_max = float(params.depth_range[0]), float(params.depth_range[1])
    return opt


def write_patch_match_config(dense_dir, views, sources) -> Path:
    """Write ``stereo/patch-match.cfg`` naming the source images of every reference image
    (COLMAP's format: the reference name on one line, its comma-separated sources on the next),
    replacing the ``__auto__`` lines that need shared sparse points."""
    path = Path(dense_dir) / "stereo" / "patch-match.cfg"
    lines = []
    for i in sorted(views):
        if sources.get(i):
            lines += [views[i].name, ", ".join(views[j].name for j in sources[i])]
    path.write_text("\n".join(lines) + "\n")
    return path


def prepare_patch_match(dense_dir, params: DenseParams) -> dict[int, list[int]] | None:
    """Make an undistorted workspace whose model has no sparse points (true rig cameras) ready
    for COLMAP PatchMatch: source views chosen as on the CPU path and written to
    ``stereo/patch-match.cfg``, and one overlap point per (image, source) pair in ``sparse/``
    for fusion. Returns the sources by image id, or None when the model has points (COLMAP's
    ``__auto__`` selection and depth ranges are then used as they are)."""
    from workstation.interop.pycolmap import import_pycolmap

    d = Path(dense_dir)
    rec = import_pycolmap().Reconstruction(str(d / "sparse"))
    if rec.num_points3D() > 0:
        return None
    if params.depth_range is None:
        raise InvalidInputError("the model has no sparse points", "give a depth range (--depth-range NEAR FAR)",
                                field="depth_range")
    views, pts, _, obs = _load_views(rec, params.depth_range)
    sources = select_sources(views, pts, obs, params)
    _add_overlap_points(rec, views, sources, d / "sparse")
    write_patch_match_config(d, views, sources)
    return sources


def _patch_match_cuda(dense_dir, params: DenseParams) -> dict:
    """COLMAP PatchMatch stereo (CUDA) on an undistorted workspace, writing the same
    ``stereo/{depth,normal}_maps/*.geometric.bin`` as :func:`compute_depth_maps`."""
    from workstation.interop.pycolmap import import_pycolmap

    d = Path(dense_dir)
    prepare_patch_match(d, params)
    import_pycolmap().patch_match_stereo(str(d), options=patch_match_options(params))
    maps = sorted((d / "stereo" / "depth_maps").glob("*.geometric.bin"))
    if not maps:
        raise StageError("dense", "COLMAP PatchMatch wrote no geometric depth maps",
                         "check stereo/patch-match.cfg and the depth range")
    return {"depth_maps": len(maps)}


def _add_overlap_points(rec, views, sources, sparse_dir) -> None:
    """Give a point-less model one 3-D point per (image, source) pair so COLMAP's fusion, which
    finds overlapping images from shared sparse points, knows which images overlap."""
    from workstation.interop.pycolmap import import_pycolmap

    pycolmap = import_pycolmap()
    obs = {i: [] for i in views}
    tracks = []
    for i, srcs in sources.items():
        for j in srcs:  # the point select_sources judged the pair at: both views see it
            P = _pair_point(views[i], views[j])
            els = []
            for k in (i, j):
                x = views[k].K @ (views[k].R @ P + views[k].t)
                els.append((k, len(obs[k])))
                obs[k].append(x[:2] / x[2] + 0.5)  # COLMAP pixel convention (corner origin)
            tracks.append((P, els))
    for i, xy in obs.items():
        rec.images[i].points2D = pycolmap.Point2DList([pycolmap.Point2D(np.asarray(p, float)) for p in xy])
    for P, els in tracks:
        t = pycolmap.Track()
        for k, j in els:
            t.add_element(int(k), int(j))
        rec.add_point3D(np.asarray(P, float), t, np.array([128, 128, 128], np.uint8))
    rec.write_binary(str(sparse_dir))


def compute_depth_maps(dense_dir, params: DenseParams = DenseParams()) -> dict:
    """CPU depth and normal maps (``params.method``: "sgbm" or "sweep") for every image of an
    undistorted workspace, then the multi-view geometric filter and normals.

    Writes ``stereo/depth_maps/NAME.{photometric,geometric}.bin`` and
    ``stereo/normal_maps/NAME.geometric.bin``. Returns per-image statistics.
    """
    import cv2

    from workstation.interop.pycolmap import import_pycolmap

    pycolmap = import_pycolmap()
    if params.num_threads > 0:
        cv2.setNumThreads(params.num_threads)
    d = Path(dense_dir)
    rec = pycolmap.Reconstruction(str(d / "sparse"))
    views, pts, _, obs = _load_views(rec, params.depth_range)
    sources = select_sources(views, pts, obs, params)
    if not any(sources.values()):
        raise StageError("dense", f"no image has a source view (overlap and a triangulation angle of "
                         f"{params.min_angle_deg:g}-{params.max_angle_deg:g}°)",
                         "check the camera poses and DenseParams.depth_range")
    if len(pts) == 0:
        _add_overlap_points(rec, views, sources, d / "sparse")
    dm, nm = d / "stereo" / "depth_maps", d / "stereo" / "normal_maps"
    dm.mkdir(parents=True, exist_ok=True)
    nm.mkdir(parents=True, exist_ok=True)
    stats = {"images": len(views), "method": params.method}
    t0 = time.perf_counter()
    stats["valid_photometric"] = _photometric_maps(d, views, sources, pts, obs, params)
    stats["photometric_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    stats["valid_geometric"] = _geometric_maps(d, views, sources, params)
    stats["geometric_s"] = time.perf_counter() - t0
    if stats["valid_geometric"] == 0:
        raise StageError("dense", "no depth survived the consistency check",
                         "check the cameras (SfM residuals), lower min_ncc or min_consistent")
    return stats


def _photometric_maps(d: Path, views, sources, pts, obs, params: DenseParams) -> int:
    """Write ``NAME.photometric.bin`` for every view (plane sweep or SGBM); valid pixels.

    SGBM works on ``num_threads`` reference images at a time (threads: OpenCV and numpy
    release the GIL), so memory holds that many references with their sources; the sweep
    goes one reference at a time (OpenCV's own threads inside).
    """
    import os
    from concurrent.futures import ThreadPoolExecutor

    from workstation.core.progress import track

    sgbm = params.method == "sgbm"
    workers = params.num_threads if params.num_threads > 0 else (os.cpu_count() or 1)
    sets = {i: set(o) for i, o in obs.items()}
    ids = sorted(views)
    label = "SGBM" if sgbm else "plane sweep"

    def one(iid) -> int:
        return _photometric_map(d, views, sources[iid], iid, pts, sets, params)

    if sgbm and workers > 1 and len(ids) > 1:
        import cv2

        cv_threads = cv2.getNumThreads()
        cv2.setNumThreads(1)  # the parallelism is over reference images: no nested pools
        try:
            with ThreadPoolExecutor(max_workers=workers) as ex:
                return sum(track(ex.map(one, ids), label, total=len(ids), unit="views"))
        finally:
            cv2.setNumThreads(cv_threads)
    return sum(one(i) for i in track(ids, label, unit="views"))


def _photometric_map(d: Path, views, src_ids: list, iid: int, pts, sets, params: DenseParams) -> int:
    """Depth map of one reference image by ``params.method``, written to
    ``stereo/depth_maps/NAME.photometric.bin``; returns its valid pixels."""
    from workstation.photogrammetry.sgbm import sgbm_depth

    v = views[iid]
    out = d / "stereo" / "depth_maps" / f"{v.name}.photometric.bin"
    if not src_ids:
        log.warning("%s: no source view in the angle range; no depth map", v.name)
        write_array(np.zeros((v.height, v.width), np.float32), out)
        return 0
    sgbm = params.method == "sgbm"
    dtype = np.uint8 if sgbm else np.float32
    ref = _grey(d / "images" / v.name, (v.width, v.height), dtype)
    srcs = [views[j] for j in src_ids]
    imgs = [_grey(d / "images" / s.name, (s.width, s.height), dtype) for s in srcs]
    ti = time.perf_counter()
    if sgbm:
        shared = [pts[np.fromiter(sets[iid] & sets[j], np.int64)] if len(pts) else None for j in src_ids]
        depth = sgbm_depth(ref, v, imgs, srcs, params.sgbm, params.max_rel_depth, params.min_texture,
                           params.window, shared)
    else:
        depth, _ = plane_sweep(ref, v, imgs, srcs, params)
    write_array(depth, out)
    log.info("depth map %s: %.0f %% of pixels, %d sources, %.1f s", v.name, 100.0 * float((depth > 0).mean()),
             len(srcs), time.perf_counter() - ti)
    return int((depth > 0).sum())


def _geometric_maps(d: Path, views, sources, params: DenseParams) -> int:
    """Geometric filter of every photometric map against its sources' maps, normals; writes
    ``NAME.geometric.bin`` depth and normal maps and returns the valid pixels."""
    from workstation.core.progress import track

    dm, nm = d / "stereo" / "depth_maps", d / "stereo" / "normal_maps"
    valid = 0
    for iid in track(sorted(views), "consistency", unit="views"):
        v = views[iid]
        depth = read_array(dm / f"{v.name}.photometric.bin")
        srcs = [views[j] for j in sources[iid]]
        sd = [read_array(dm / f"{s.name}.photometric.bin") for s in srcs]
        geo = geometric_filter(depth, v, sd, srcs, params)
        nrm = depth_normals(geo, v.K)
        geo = np.where(np.any(nrm != 0, -1), geo, 0).astype(np.float32)
        write_array(geo, dm / f"{v.name}.geometric.bin")
        write_array(nrm, nm / f"{v.name}.geometric.bin")
        valid += int((geo > 0).sum())
    return valid


def fuse(dense_dir, params: DenseParams = DenseParams()):
    """Fuse the geometric depth/normal maps into ``dense_dir/fused.ply`` (pycolmap.stereo_fusion)
    and return it as a :class:`~workstation.core.cloud.Cloud` (``rgb``, ``normal``)."""
    from workstation.interop.pycolmap import import_pycolmap
    from workstation.io import read_cloud

    pycolmap = import_pycolmap()
    d = Path(dense_dir)
    opt = pycolmap.StereoFusionOptions()
    opt.min_num_pixels = int(params.fusion_min_pixels)
    opt.num_threads = int(params.num_threads)
    if params.fusion_cache_gb > 0:
        opt.use_cache = True
        opt.cache_size = float(params.fusion_cache_gb)
    out = d / "fused.ply"
    pycolmap.stereo_fusion(str(out), str(d), input_type="geometric", options=opt, output_type="PLY")
    if not out.exists():
        raise StageError("dense", "fusion wrote no fused.ply", "check the depth maps in stereo/depth_maps")
    cloud = read_cloud(out)
    if cloud.n == 0:
        raise StageError("dense", "fusion produced an empty cloud", "lower fusion_min_pixels or check the depth maps")
    return cloud


def run_dense(workdir, image_dir=None, params: DenseParams = DenseParams(), overwrite: bool = False):
    """Undistort, compute depth/normal maps (CUDA PatchMatch, or on the CPU ``params.method``:
    pairwise SGBM or the plane sweep), fuse.

    Parameters
    ----------
    workdir : path
        SfM workdir (``sparse/0``) or a rig folder with ``sparse/0`` and ``images/``.
    image_dir : path, optional
        The original images (default ``WORKDIR/images``).
    params : DenseParams
    overwrite : bool
        Replace an existing ``WORKDIR/dense``.

    Returns
    -------
    cloud : Cloud
        Fused points (model frame) with ``rgb`` and ``normal``.
    summary : dict
        Device, method ("sgbm", "sweep" or "patch_match"), timings (s), image count, points.
    """
    workdir = Path(workdir)
    image_dir = Path(image_dir) if image_dir is not None else workdir / "images"
    if not image_dir.is_dir():
        raise InvalidInputError("image folder not found", "pass the folder of the original images (--images)", path=image_dir)
    device = resolve_device(params.device)
    t = {}
    t0 = time.perf_counter()
    dense_dir = undistort(workdir, image_dir, params.max_image_size, overwrite)
    t["undistort"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    if device == "cuda":
        stats = {"method": "patch_match", **_patch_match_cuda(dense_dir, params)}
    else:
        stats = compute_depth_maps(dense_dir, params)
    t["depth_maps"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    cloud = fuse(dense_dir, params)
    t["fusion"] = time.perf_counter() - t0
    summary = {"device": device, "points": cloud.n, "timings_s": {k: round(v, 2) for k, v in t.items()},
               "fused": str(dense_dir / "fused.ply"), **stats}
    log.info("dense (%s): %d points in %.1f s", device, cloud.n, sum(t.values()))
    hist = {"device": device, "method": summary.get("method", "patch_match"), "max_image_size": params.max_image_size}
    return cloud.with_history("dense", hist, sum(t.values())), summary


def evaluate(points: np.ndarray, vertices: np.ndarray, faces: np.ndarray, extent: float, samples: np.ndarray) -> dict:
    """Accuracy and completeness of a dense cloud against a true mesh (Seitz et al., *A
    Comparison and Evaluation of Multi-View Stereo Reconstruction Algorithms*, CVPR 2006).

    Parameters
    ----------
    points : (n, 3) float
        Dense points (same frame as the mesh).
    vertices, faces : true mesh.
    extent : float
        Scene extent (m) the relative figures are quoted against.
    samples : (k, 3) float
        Points on the true surface (e.g. the visible part) for completeness.

    Returns
    -------
    dict
        ``accuracy_median`` (m, point-to-mesh), ``accuracy_rel`` (of extent), ``accuracy_p90``,
        ``completeness`` (share of samples with a dense point within 1 % of the extent).
    """
    from scipy.spatial import cKDTree

    from workstation.interop.open3d_raycast import RaycastScene

    off = vertices.mean(0)
    dist = RaycastScene(vertices - off, faces).distance(points - off)
    nn, _ = cKDTree(points).query(samples, k=1)
    return {"points": len(points), "accuracy_median": float(np.median(dist)),
            "accuracy_rel": float(np.median(dist) / extent), "accuracy_p90": float(np.percentile(dist, 90)),
            "completeness": float(np.mean(nn <= 0.01 * extent)), "extent": float(extent)}


__all__ = [
    "DEVICES",
    "METHODS",
    "DenseParams",
    "compute_depth_maps",
    "depth_normals",
    "evaluate",
    "fuse",
    "geometric_filter",
    "patch_match_options",
    "plane_sweep",
    "prepare_patch_match",
    "read_array",
    "resolve_device",
    "run_dense",
    "select_sources",
    "undistort",
    "write_array",
    "write_patch_match_config",
]
