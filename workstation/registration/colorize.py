"""Colour a point cloud from oriented photos.

Every point is projected into every oriented image with the collinearity equations and
OpenCV's Brown-Conrady distortion (Brown 1971, "Close-range camera calibration"). Visibility
is a depth test: against the image's depth map when one is given, else against a z-buffer
rendered from the cloud itself in cells a little larger than a point's footprint, so points
behind a wall are not painted with the wall's colour (the hidden-point problem of
orthophoto-only colouring). Each point keeps its ``max_views`` best views, weighted by the
cosine of the viewing angle (when normals exist) over the squared distance, and gets their
bilinearly interpolated colours blended with those weights. Points seen by no image keep
their colour (or get black) and ``colorized == 0``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Mapping

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Pose, Reconstruction

log = get_logger(__name__)
STAGE = "colorize"


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
    """

    max_views: int = 3
    point_spacing: float | None = None
    depth_tolerance: float | None = None
    depth_tolerance_rel: float = 0.005
    min_cos: float = 0.1
    border_px: float = 1.0
    fill_holes: bool = True


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
    R = np.asarray(pose.R, dtype=np.float64)
    t = np.asarray(pose.t, dtype=np.float64)
    xc = np.asarray(xyz, dtype=np.float64) @ R.T + t
    z = xc[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        x = xc[:, 0] / z
        y = xc[:, 1] / z
    k1, k2, p1, p2, k3 = (tuple(camera.dist) + (0.0,) * 5)[:5]
    r2 = x * x + y * y
    radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
    xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x)
    yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y
    u = camera.fx * xd + camera.skew * yd + camera.cx
    v = camera.fy * yd + camera.cy
    return u, v, z


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


def _zbuffer_visible(u, v, z, idx, w, h, cell: int, tol: np.ndarray, fill_holes: bool = True) -> np.ndarray:
    """Visibility of the projected points ``idx`` by a z-buffer of ``cell``-pixel cells.

    With ``fill_holes`` each cell takes the median depth of its 3 x 3 neighbourhood when that is
    nearer: a gap of one or two cells in a nearer surface (where a farther surface shows
    through between sparse points) is closed, while slopes and silhouette edges, where the
    median is the cell's own depth, are kept (screen-space hole filling in the spirit of
    Pintus, Gobbetti & Agus 2011, "Real-time rendering of massive unstructured raw point
    clouds using screen-space operators")."""
    cw = (w + cell - 1) // cell
    ch = (h + cell - 1) // cell
    cid = (np.floor(v / cell).astype(np.int64) * cw + np.floor(u / cell).astype(np.int64))
    zb = np.full(cw * ch, np.inf)
    np.minimum.at(zb, cid, z)
    if fill_holes:
        from scipy.ndimage import median_filter

        g = np.where(np.isfinite(zb), zb, 1e30).reshape(ch, cw)
        zb = np.minimum(g, median_filter(g, size=3, mode="nearest")).ravel()
    return z <= zb[cid] + tol


def _load_image(img, root) -> np.ndarray:
    p = Path(img.path) if img.path else Path(img.name)
    if root is not None and not p.is_absolute():
        p = Path(root) / p
    if not p.exists():
        raise InvalidInputError("image file not found", "give the image folder (--images)", path=p)
    import cv2

    a = cv2.imread(str(p), cv2.IMREAD_UNCHANGED)
    if a is None:
        raise InvalidInputError("could not read image", path=p)
    if a.ndim == 2:
        a = np.repeat(a[:, :, None], 3, axis=2)
    return a[:, :, 2::-1] if a.shape[2] >= 3 else a


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
        Depth along the optical axis (metres, 0 or NaN = unknown); replaces the z-buffer test
        for that image.
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
    from .preprocess import estimate_spacing

    spacing = params.point_spacing or (estimate_spacing(cloud.xyz) if cloud.n > 1 else 0.01)
    tol_abs = params.depth_tolerance if params.depth_tolerance is not None else 3.0 * spacing
    xyz = cloud.xyz
    normals = np.asarray(cloud.attrs["normal"], np.float64) if "normal" in cloud.attrs else None
    k = max(1, int(params.max_views))
    W = np.zeros((cloud.n, k))
    C = np.zeros((cloud.n, k, 3))
    scale16 = None
    for iid, im in reconstruction.images.items():
        cam = reconstruction.cameras[im.camera_id]
        img = images[iid] if images is not None and iid in images else _load_image(im, image_root)
        if img.shape[0] != cam.height or img.shape[1] != cam.width:
            raise InvalidInputError(f"image {im.name} is {img.shape[1]}x{img.shape[0]} but its camera says "
                                    f"{cam.width}x{cam.height}", field="images")
        s = 257.0 if img.dtype == np.uint8 else 1.0
        scale16 = s if scale16 is None else scale16
        u, v, z = project(xyz, cam, im.pose)
        b = params.border_px
        inside = (z > 0) & (u >= b) & (u <= cam.width - 1 - b) & (v >= b) & (v <= cam.height - 1 - b)
        idx = np.flatnonzero(inside)
        if idx.size == 0:
            continue
        ui, vi, zi = u[idx], v[idx], z[idx]
        tol = tol_abs + params.depth_tolerance_rel * zi
        if depth_maps is not None and iid in depth_maps:
            dm = np.asarray(depth_maps[iid], dtype=np.float64)
            dz = dm[np.round(vi).astype(np.int64), np.round(ui).astype(np.int64)]
            vis = np.isfinite(dz) & (dz > 0) & (zi <= dz + tol)
        else:
            f = 0.5 * (cam.fx + cam.fy)
            cell = int(np.clip(np.ceil(2.0 * f * spacing / np.median(zi)), 1, 64))
            vis = _zbuffer_visible(ui, vi, zi, idx, cam.width, cam.height, cell, tol, params.fill_holes)
        idx, ui, vi = idx[vis], ui[vis], vi[vis]
        ray = xyz[idx] - im.pose.center
        dist2 = np.einsum("ij,ij->i", ray, ray)
        wgt = 1.0 / np.maximum(dist2, 1e-12)
        if normals is not None:
            cosang = np.abs(np.einsum("ij,ij->i", normals[idx], ray)) / np.sqrt(np.maximum(dist2, 1e-24))
            good = cosang >= params.min_cos
            idx, ui, vi, wgt = idx[good], ui[good], vi[good], (wgt * cosang)[good]
        col = bilinear(img, ui, vi)[:, :3] * s
        # keep the k best views per point: replace the weakest slot when the new view is better
        slot = np.argmin(W[idx], axis=1)
        better = wgt > W[idx, slot]
        W[idx[better], slot[better]] = wgt[better]
        C[idx[better], slot[better]] = col[better]
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
