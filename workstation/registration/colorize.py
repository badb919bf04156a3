"""Colour a point cloud from oriented photos.

Every point is projected into every oriented image with the collinearity equations and
OpenCV's Brown-Conrady distortion (Brown 1971, "Close-range camera calibration"). Visibility
is a depth test: against the image's depth map when one is given (:func:`depth_map_visible`:
the point's 2 x 2 pixel cell must lie on one plane in inverse depth that the point is on, with
no nearer surface in the 4 x 4 block around it, so points just behind a silhouette edge are not
painted and no colour is mixed across an edge), else against a z-buffer rendered from the
cloud itself in cells a little larger than a point's footprint, so points behind a wall are
not painted with the wall's colour (the hidden-point problem of orthophoto-only colouring).
The z-buffer cannot know occluders that the cloud does not hold (objects the scanner did not
see, sparsely hit tree crowns): depth maps are the safe test. Each point keeps its
``max_views`` best views, weighted by the cosine of the viewing angle (when normals exist)
over the squared distance, and gets their bilinearly interpolated colours blended with those
weights. Points seen by no image keep their colour (or get black) and ``colorized == 0``.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Pose, Reconstruction
from workstation.io.images import read_image

log = get_logger(__name__)
STAGE = "colorize"
CREASE_SLACK = 0.5
ZBUFFER_SLOPE = 1.0


@dataclass(frozen=True)
class ColorizeParams:
    """Parameters of :func:`colorize`.

    Attributes
    ----------
    max_views : int
        Best views blended per point.
    point_spacing : float, optional
        Metres: nominal spacing of the cloud, sets the z-buffer cell (a point's footprint) and
        the depth tolerance; estimated from the data when None.
    depth_tolerance : float, optional
        Metres a point may lie behind the nearest surface and still count as seen; default
        ``3 * point_spacing``. A relative ``depth_tolerance_rel * depth`` is added.
    depth_tolerance_rel : float
        Share of the depth added to the tolerance (range noise grows with distance).
    min_cos : float
        Views seeing the surface at a cosine below this (grazing) are ignored (needs normals).
    border_px : float
        Pixels near the image border that are not used.
    fill_holes : bool
        Close one- or two-cell gaps of the z-buffer with a 3 x 3 median (see
        :func:`_zbuffer_visible`).
    depth_footprint_px : float
        Pixels: the depth maps hold the nearest depth within +- this distance of each pixel
        centre (a conservative depth map, which also shows occluders thinner than a pixel);
        0 for depth at the pixel centre (see :func:`depth_map_visible`).
    """

    max_views: int = 3
    point_spacing: float | None = None
    depth_tolerance: float | None = None
    depth_tolerance_rel: float = 0.005
    min_cos: float = 0.1
    border_px: float = 1.0
    fill_holes: bool = True
    depth_footprint_px: float = 0.0


def project(xyz: np.ndarray, camera: Camera, pose: Pose) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Project world points into an image (collinearity + OpenCV distortion k1, k2, p1, p2, k3).

    Parameters
    ----------
    xyz : (n, 3) float
        World coordinates.
    camera : Camera
    pose : Pose
        World -> camera: ``x_cam = R X + t``.

    Returns
    -------
    u, v : (n,) float64
        Pixel coordinates (pixel centres at integers, OpenCV).
    z : (n,) float64
        Depth along the optical axis (metres); <= 0 behind the camera.
    """
    from workstation.photogrammetry.collinearity import project as collinear

    uv, z = collinear(xyz, camera, pose, return_depth=True)
    return uv[:, 0], uv[:, 1], z


def bilinear(image: np.ndarray, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Bilinear samples (n, c) float64 of an (h, w, c) image at pixel coordinates u (col), v (row).

    Coordinates must satisfy ``0 <= u <= w - 1`` and ``0 <= v <= h - 1``.
    """
    img = image if image.ndim == 3 else image[:, :, None]
    h, w = img.shape[:2]
    x0 = np.clip(np.floor(u).astype(np.int64), 0, w - 2)
    y0 = np.clip(np.floor(v).astype(np.int64), 0, h - 2)
    fx = (u - x0)[:, None]
    fy = (v - y0)[:, None]
    a = img[y0, x0].astype(np.float64)
    b = img[y0, x0 + 1].astype(np.float64)
    c = img[y0 + 1, x0].astype(np.float64)
    d = img[y0 + 1, x0 + 1].astype(np.float64)
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy


def _corners(u: np.ndarray, v: np.ndarray, w: int, h: int):
    """Top-left corner (x0, y0) of the 2 x 2 pixel cell around each (u, v) and the bilinear
    weights (n, 4) of its corners in the order (x0, y0), (x0+1, y0), (x0, y0+1), (x0+1, y0+1)."""
    x0 = np.clip(np.floor(u).astype(np.int64), 0, w - 2)
    y0 = np.clip(np.floor(v).astype(np.int64), 0, h - 2)
    fx = u - x0
    fy = v - y0
    wts = np.column_stack([(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy])
    return x0, y0, wts


def sample_corners(image: np.ndarray, x0: np.ndarray, y0: np.ndarray, weights: np.ndarray) -> np.ndarray:
    """Weighted mean (n, c) float64 of the four corner pixels of each cell (weights (n, 4), rows
    summing to > 0): plain bilinear interpolation with the weights of :func:`_corners`, or a
    depth-aware one with the weights of corners on another surface set to 0."""
    img = image if image.ndim == 3 else image[:, :, None]
    acc = np.zeros((x0.size, img.shape[2]))
    for k, (dx, dy) in enumerate(((0, 0), (1, 0), (0, 1), (1, 1))):
        acc += weights[:, k:k + 1] * img[y0 + dy, x0 + dx].astype(np.float64)
    return acc / weights.sum(axis=1, keepdims=True)


def depth_map_visible(depth: np.ndarray, u: np.ndarray, v: np.ndarray, z: np.ndarray, tol: np.ndarray,
                      camera: Camera, min_cos: float = 0.0, footprint_px: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Depth test of projected points against a depth map, safe at depth discontinuities.

    A depth map holds the depth of the first surface at its pixel centres only; a point
    projects between them. Sampling the nearest pixel paints points just behind the silhouette
    edge of a nearer object (the nearest pixel centre happens to see past it), and bilinear
    colour there mixes the occluder's colour in. Here, with inverse depth ``w = 1 / depth``
    (an affine function of the pixel coordinates on a plane):

    1. the 2 x 2 cell of pixels around the point must lie on one plane (its twist
       ``w00 + w11 - w10 - w01`` below ``tol / z**2``), and the point's depth must be within
       ``tol`` (either side) of that plane's depth at the point (bilinear in ``w``);
    2. no pixel of the surrounding 4 x 4 block may be nearer than that plane extrapolated to it
       by more than ``tol``: a nearer object within a pixel and a half (whose edge may cover the
       point's exact position) hides the point; a farther one (background seen past the
       point's own edge) does not. A step edge inside the cell, which step 1 cannot tell from a
       steep plane, fails here on its near side;
    3. with ``min_cos > 0`` the plane must face the camera at a cosine of at least ``min_cos``
       (its normal follows from the inverse-depth gradient), so grazing views are dropped.

    Occluders thinner than the pixel spacing (leaves, wires) leave no trace in a depth map
    sampled at pixel centres and cannot be caught by any test on it; a depth map holding the
    nearest depth over each pixel's footprint (``footprint_px``) shows them, and its bias on a
    plane, ``footprint_px * (|dw/dx| + |dw/dy|)``, is removed before step 1.

    Parameters
    ----------
    depth : (h, w) float
        Depth along the optical axis (metres). ``inf``: the ray hit nothing (sky); 0 or NaN:
        unknown (no colour is taken from a cell with an unknown corner; unknown pixels around
        it are ignored).
    u, v, z : (n,) float
        Pixel coordinates and depth of the points (OpenCV convention, inside the image).
    tol : (n,) float
        Depth tolerance per point (metres).
    camera : Camera
    min_cos : float
        Smallest cosine between the viewing ray and the surface normal.
    footprint_px : float
        The depth map holds the nearest depth within +- this many pixels of each pixel centre
        (a conservative render: 0.5 for the whole pixel, 1/3 for the extreme rays of 3 x 3
        supersampling); 0: the depth at the pixel centre.

    Returns
    -------
    visible : (n,) bool
    x0, y0 : (n,) int64
        Top-left corners of the cells (see :func:`sample_corners`).
    weights : (n, 4) float64
        Bilinear weights of the cell's corners (all on the point's surface when visible).
    """
    D = np.asarray(depth, dtype=np.float64)
    h, w = D.shape
    with np.errstate(divide="ignore", invalid="ignore"):
        W = np.where(np.isnan(D) | (D <= 0), np.nan, 1.0 / D)  # inverse depth; sky = 0
    x0, y0, wts = _corners(u, v, w, h)
    P = _blocks(W, x0, y0)
    c, known, a, b, w0 = _cell_plane(P)
    tol_w = tol / z**2  # a depth step of tol at depth z, in inverse depth
    slack = tol_w + CREASE_SLACK * (np.abs(a) + np.abs(b))
    planar = np.abs(c[:, 0] + c[:, 3] - c[:, 1] - c[:, 2]) <= slack
    w_pt = np.einsum("nk,nk->n", wts, c)
    if footprint_px > 0:
        w_pt = w_pt - footprint_px * (np.abs(a) + np.abs(b))
    with np.errstate(divide="ignore"):
        z_s = np.where(w_pt > 0, 1.0 / np.maximum(w_pt, 1e-300), np.inf)
    vis = known & planar & (np.abs(z - z_s) <= tol)
    vis &= ~_nearer_in_block(P, w0, a, b, slack)
    if min_cos > 0:
        vis &= _facing_cos(u, v, w_pt, a, b, camera) >= min_cos
    return vis, x0, y0, wts


def _blocks(W: np.ndarray, x0: np.ndarray, y0: np.ndarray) -> np.ndarray:
    """(n, 4, 4) inverse depths of the block of rows ``y0-1 .. y0+2``, columns ``x0-1 .. x0+2``
    around each cell (NaN outside the image)."""
    Wp = np.pad(W, 1, mode="constant", constant_values=np.nan)
    return np.stack([Wp[y0 + dy, x0 + dx] for dy in range(4) for dx in range(4)], axis=1).reshape(-1, 4, 4)


def _cell_plane(P: np.ndarray):
    """The plane through each 2 x 2 cell of the blocks ``P``: ``(c, known, a, b, w0)`` with the
    corners ``c`` (n, 4) in the order (x0, y0), (x0+1, y0), (x0, y0+1), (x0+1, y0+1) (unknown
    ones set to 0), ``known`` where all four are known, the slopes ``a = dw/dx`` and
    ``b = dw/dy`` per pixel, and ``w0`` the plane's value at the cell centre."""
    c = P[:, 1:3, 1:3].reshape(-1, 4)
    known = np.isfinite(c).all(axis=1)
    c = np.where(np.isfinite(c), c, 0.0)
    a = 0.5 * (c[:, 1] - c[:, 0] + c[:, 3] - c[:, 2])  # dw / dx per pixel
    b = 0.5 * (c[:, 2] - c[:, 0] + c[:, 3] - c[:, 1])  # dw / dy per pixel
    w0 = c.mean(axis=1)  # plane value at the cell centre (x0 + 0.5, y0 + 0.5)
    return c, known, a, b, w0


def _nearer_in_block(P: np.ndarray, w0, a, b, slack) -> np.ndarray:
    """(n,) bool: a pixel of the 4 x 4 block is nearer than the cell's plane extrapolated to it
    by more than ``slack`` (inverse depth); unknown pixels are ignored."""
    off = np.arange(4) - 1.5
    pred = w0[:, None, None] + a[:, None, None] * off[None, None, :] + b[:, None, None] * off[None, :, None]
    with np.errstate(invalid="ignore"):
        return np.nan_to_num(P - pred, nan=-np.inf).reshape(-1, 16).max(axis=1) > slack


def _facing_cos(u, v, w_pt, a, b, camera: Camera) -> np.ndarray:
    """(n,) cosine between the viewing ray and the normal of the plane ``w = 1 / depth`` with
    value ``w_pt`` at the point and per-pixel gradient ``(a, b)``."""
    xn = (u - camera.cx) / camera.fx
    yn = (v - camera.cy) / camera.fy
    ga, gb = a * camera.fx, b * camera.fy  # gradient of w in normalised image coordinates
    cc = w_pt - ga * xn - gb * yn
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.abs(w_pt) / (np.sqrt(ga * ga + gb * gb + cc * cc) * np.sqrt(xn * xn + yn * yn + 1.0))


def _zbuffer_visible(u, v, z, footprint_px, w, h, tol: np.ndarray, fill_holes: bool = True,
                     f_px: float = 1.0, slope: float = ZBUFFER_SLOPE) -> np.ndarray:
    """Visibility of projected points by a z-buffer of the cloud with a splat per point.

    A point covers about ``footprint_px`` pixels (its local spacing seen from the camera);
    drawn as one pixel, a sparse surface leaves holes through which the points behind it are
    wrongly seen. Each point is therefore drawn into the level of a z-buffer pyramid whose
    cells (``2**level`` pixels) are at least its footprint (a splat of about its own size, as
    in surface splatting: Zwicker et al. 2001, "Surface splatting", SIGGRAPH), and each point is
    tested against the nearest depth over all levels at its position. With ``fill_holes`` each
    cell also takes the median depth of its 3 x 3 neighbourhood when that is nearer: a gap of
    one or two cells in a nearer surface is closed, while slopes and silhouette edges, where
    the median is the cell's own depth, are kept (screen-space hole filling in the spirit of
    Pintus, Gobbetti & Agus 2011, "Real-time rendering of massive unstructured raw point clouds
    using screen-space operators")."""
    from scipy.ndimage import median_filter

    level = np.clip(np.ceil(np.log2(np.maximum(footprint_px, 1.0))), 0, 6).astype(np.int64)
    bound = np.full(z.shape, np.inf)
    for lev in np.unique(level):
        cell = 1 << int(lev)
        cw = (w + cell - 1) // cell
        ch = (h + cell - 1) // cell
        cid = np.floor(v / cell).astype(np.int64) * cw + np.floor(u / cell).astype(np.int64)
        zb = np.full(cw * ch, np.inf)
        sel = level == lev
        np.minimum.at(zb, cid[sel], z[sel])
        if fill_holes:
            g = np.where(np.isfinite(zb), zb, 1e30).reshape(ch, cw)
            zb = np.minimum(g, median_filter(g, size=3, mode="nearest")).ravel()
        zc = zb[cid]
        # a splat of a surface seen obliquely spans a depth range: allow ``slope`` times its size
        bound = np.minimum(bound, zc * (1.0 + slope * cell / f_px))
    return z <= bound + tol


def _local_spacing(xyz: np.ndarray, nominal: float | None) -> np.ndarray:
    """Per-point spacing (n,) metres: the given nominal spacing, or the distance to the 8th
    nearest neighbour over sqrt(2) (the spacing on a square grid; on a scan pattern three
    times denser along the line than across, about the larger spacing), so a multi-station
    TLS cloud gets small splats near the scanners and large ones far away."""
    if nominal:
        return np.full(xyz.shape[0], float(nominal))
    from scipy.spatial import cKDTree

    d, _ = cKDTree(xyz).query(xyz, k=9, workers=-1)
    return d[:, 8] / np.sqrt(2.0)


def read_depth_maps(dense_dir, reconstruction: Reconstruction) -> dict[int, np.ndarray]:
    """Depth maps of a dense workspace (``ws sfm --dense``, COLMAP layout) for the images of
    ``reconstruction`` (its ``dense/sparse`` model): ``stereo/depth_maps/NAME.geometric.bin``,
    else ``NAME.photometric.bin``; (h, w) float32 metres along the optical axis, 0 = no depth.
    Images without a depth map are left out (they fall back to the z-buffer test)."""
    from workstation.photogrammetry.dense import read_array

    folder = Path(dense_dir) / "stereo" / "depth_maps"
    if not folder.is_dir():
        raise InvalidInputError("no depth maps in the dense workspace", "run ws sfm --dense first",
                                path=folder)
    out = {}
    for iid, im in reconstruction.images.items():
        for kind in ("geometric", "photometric"):
            f = folder / f"{im.name}.{kind}.bin"
            if f.exists():
                out[iid] = read_array(f)
                break
    if not out:
        raise InvalidInputError("no depth map matches an image of the model", path=folder)
    return out


def colorize(cloud: Cloud, reconstruction: Reconstruction, params: ColorizeParams = ColorizeParams(), *,
             images: Mapping[int, np.ndarray] | None = None, depth_maps: Mapping[int, np.ndarray] | None = None,
             image_root=None) -> Cloud:
    """Colour ``cloud`` from the oriented images of ``reconstruction``.

    Parameters
    ----------
    cloud : Cloud
        In the reconstruction's frame (register it first).
    reconstruction : Reconstruction
        Cameras and oriented images.
    params : ColorizeParams
    images : mapping of image id to (h, w, 3) uint8/uint16 array, optional
        Pixels of each image; read from ``Image.path`` (relative to ``image_root``) otherwise.
    depth_maps : mapping of image id to (h, w) float array, optional
        Depth along the optical axis (metres; ``inf`` = nothing hit, 0 or NaN = unknown);
        replaces the z-buffer test for that image (:func:`depth_map_visible`). Give
        ``params.depth_tolerance`` from the depth maps' accuracy (exact renders: the cloud's
        noise, a few cm; MVS maps: the default ``3 * spacing + 0.5 %`` of the depth).
    image_root : path, optional

    Returns
    -------
    Cloud
        With ``rgb`` (u16; u8 images are scaled by 257), ``colorized`` (u1: 1 painted, 0 not)
        and ``color_views`` (u1: views blended).
    """
    if not reconstruction.images:
        raise InvalidInputError("the reconstruction has no oriented images", field="reconstruction")
    if cloud.n == 0:
        raise InvalidInputError("the cloud is empty", field="xyz")
    from functools import cache

    from .preprocess import estimate_spacing

    spacing = params.point_spacing or (estimate_spacing(cloud.xyz) if cloud.n > 1 else 0.01)
    tol_abs = params.depth_tolerance if params.depth_tolerance is not None else 3.0 * spacing
    xyz = cloud.xyz
    normals = np.asarray(cloud.attrs["normal"], np.float64) if "normal" in cloud.attrs else None
    k = max(1, int(params.max_views))
    W = np.zeros((cloud.n, k))
    C = np.zeros((cloud.n, k, 3))
    local_spacing = cache(lambda: _local_spacing(xyz, params.point_spacing))  # only for the z-buffer test
    for iid, im in reconstruction.images.items():
        cam = reconstruction.cameras[im.camera_id]
        img = images[iid] if images is not None and iid in images else read_image(im, image_root)
        if img.shape[0] != cam.height or img.shape[1] != cam.width:
            raise InvalidInputError(f"image {im.name} is {img.shape[1]}x{img.shape[0]} but its camera says "
                                    f"{cam.width}x{cam.height}", field="images")
        dm = depth_maps[iid] if depth_maps is not None and iid in depth_maps else None
        seen_here = _visible_in_image(xyz, cam, im.pose, params, tol_abs, dm, local_spacing)
        if seen_here is None:
            continue
        idx, x0, y0, cw, wgt = _view_weights(xyz, normals, *seen_here, im.pose.center, params.min_cos)
        col = sample_corners(img, x0, y0, cw)[:, :3] * (257.0 if img.dtype == np.uint8 else 1.0)
        _keep_best_views(W, C, idx, wgt, col)
    seen = W.sum(axis=1) > 0
    rgb = (np.array(cloud.attrs["rgb"], dtype=np.float64) if "rgb" in cloud.attrs else np.zeros((cloud.n, 3)))
    blend = np.einsum("nk,nkc->nc", W[seen], C[seen]) / W[seen].sum(axis=1)[:, None]
    rgb[seen] = blend
    n_views = (W > 0).sum(axis=1)
    log.info("colorize: %d of %d points painted", int(seen.sum()), cloud.n)
    if not seen.any():
        raise StageError(STAGE, "no point is seen by any image",
                         "check that the cloud and the reconstruction share one frame (register them first)")
    out = cloud.with_attrs(rgb=np.clip(np.round(rgb), 0, 65535).astype(np.uint16),
                           colorized=seen.astype(np.uint8), color_views=n_views.astype(np.uint8))
    return out.with_history(STAGE, {"images": len(reconstruction.images), "max_views": k, "spacing": spacing,
                                    "depth_tolerance": tol_abs})


def _visible_in_image(xyz: np.ndarray, cam: Camera, pose: Pose, params: ColorizeParams, tol_abs: float,
                      depth_map: np.ndarray | None, local_spacing):
    """The points one image sees: projected inside the image (``params.border_px`` from its
    edges) in front of the camera, then visible by the depth-map test
    (:func:`depth_map_visible`) or, without a depth map, the cloud's own z-buffer
    (:func:`_zbuffer_visible`, splats sized by ``local_spacing()``, metres). The depth tolerance
    is ``tol_abs`` plus ``params.depth_tolerance_rel`` of the depth. Returns ``(idx, x0, y0,
    corner weights)`` of the visible points, or None when no point projects inside."""
    u, v, z = project(xyz, cam, pose)
    b = params.border_px
    inside = (z > 0) & (u >= b) & (u <= cam.width - 1 - b) & (v >= b) & (v <= cam.height - 1 - b)
    idx = np.flatnonzero(inside)
    if idx.size == 0:
        return None
    ui, vi, zi = u[idx], v[idx], z[idx]
    tol = tol_abs + params.depth_tolerance_rel * zi
    if depth_map is not None:
        vis, x0, y0, cw = depth_map_visible(depth_map, ui, vi, zi, tol, cam, params.min_cos, params.depth_footprint_px)
    else:
        fp = 2.0 * 0.5 * (cam.fx + cam.fy) * local_spacing()[idx] / zi
        vis = _zbuffer_visible(ui, vi, zi, fp, cam.width, cam.height, tol, params.fill_holes, 0.5 * (cam.fx + cam.fy))
        x0, y0, cw = _corners(ui, vi, cam.width, cam.height)
    return idx[vis], x0[vis], y0[vis], cw[vis]


def _view_weights(xyz: np.ndarray, normals, idx, x0, y0, cw, center: np.ndarray, min_cos: float):
    """Weight of each view: 1 / squared distance to the camera ``center``, times the cosine of
    the viewing angle when the cloud has normals (views below ``min_cos`` dropped). Returns
    ``(idx, x0, y0, corner weights, weight)`` of the views kept."""
    ray = xyz[idx] - center
    dist2 = np.einsum("ij,ij->i", ray, ray)
    wgt = 1.0 / np.maximum(dist2, 1e-12)
    if normals is not None:
        cosang = np.abs(np.einsum("ij,ij->i", normals[idx], ray)) / np.sqrt(np.maximum(dist2, 1e-24))
        good = cosang >= min_cos
        idx, x0, y0, cw, wgt = idx[good], x0[good], y0[good], cw[good], (wgt * cosang)[good]
    return idx, x0, y0, cw, wgt


def _keep_best_views(W: np.ndarray, C: np.ndarray, idx, wgt, col) -> None:
    """Keep the ``k`` best views per point in the slots of ``W`` (n, k) weights and ``C``
    (n, k, 3) colours: a new view replaces the weakest slot when it weighs more."""
    slot = np.argmin(W[idx], axis=1)
    better = wgt > W[idx, slot]
    W[idx[better], slot[better]] = wgt[better]
    C[idx[better], slot[better]] = col[better]
