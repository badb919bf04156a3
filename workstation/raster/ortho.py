"""True orthophotos by backward projection over a DSM, with occlusion and seam-aware blending.

Method (Kraus, *Photogrammetry* vol. 1, §6.6 "differential rectification", and the true-ortho
literature: Amhar et al. 1998; Rau, Chen & Chen 2002; Habib et al. 2007):

1. Every ortho cell takes its ground point (X, Y, Z) from the DSM (bilinear).
2. The point is projected into each oriented image by the collinearity equations with
   OpenCV lens distortion (:func:`project_points`).
3. Visibility: a ray is marched from the ground point towards the camera centre over the DSM
   (half-cell steps, nearest-cell heights) until it rises above the highest DSM value; the
   point is hidden when the DSM rises above the ray. Hidden cells are not coloured from that
   image, so buildings do not lean and their ghosts do not appear beside them (a *true*
   orthophoto). Cells no image sees are nodata (alpha 0).
4. The colour is the bilinear interpolation of the image at the projected point. Among the
   images that see a cell the most nadir view wins (smallest off-nadir angle, least relief
   displacement); images within ``blend_angle`` degrees of the best are blended with weights
   ``exp(-(θ - θ_min)/blend_angle)``, which is 1 for the best image and feathers the seams
   between nadir regions instead of cutting them.
5. Accuracy: the planimetric error of a cell from a DSM height error σ_z is σ_z · tan θ (the
   relief displacement of the lecture: dr = dZ · r / (Z0 − Z)); orientation errors add
   σ_px · depth / f on the ground; the two are independent, so they add in quadrature
   (``accuracy`` raster and its RMS in ``meta``).

Projection uses the collinearity equations of
:func:`workstation.photogrammetry.collinearity.project`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.budget import check_grid
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Image, Pose, Raster, Reconstruction
from workstation.photogrammetry.collinearity import pixels_to_normalized, project

from .grid import GridSpec

log = get_logger(__name__)


# --------------------------------------------------------------------------- projection
def project_points(camera: Camera, pose: Pose, X: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Project world points into an image (collinearity equations + OpenCV distortion).

    Parameters
    ----------
    camera : Camera
        Pinhole intrinsics, distortion (k1, k2, p1, p2, k3); pixel centres at integers.
    pose : Pose
        World-to-camera rotation R and translation t (x_cam = R X + t).
    X : (n, 3) float64
        World points.

    Returns
    -------
    uv : (n, 2) float64
        Pixel coordinates (column, row).
    depth : (n,) float64
        Depth along the optical axis (positive in front of the camera).

    Examples
    --------
    >>> import numpy as np
    >>> cam = Camera(100, 100, 50.0, 50.0, 49.5, 49.5)
    >>> pose = Pose(np.diag([1.0, -1.0, -1.0]), np.array([0.0, 0.0, 10.0]))  # 10 m above origin
    >>> uv, d = project_points(cam, pose, np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]))
    >>> uv.round(2).tolist(), d.tolist()
    ([[49.5, 49.5], [59.5, 49.5]], [10.0, 10.0])
    """
    uv, z, _ = _project(camera, pose, X)
    return uv, z


def _project(camera: Camera, pose: Pose, X: np.ndarray):
    """:func:`project_points` plus the squared radius of the undistorted normalised point."""
    uv, z, xy = project(X, camera, pose, return_depth=True, return_normalized=True)
    return uv, z, (xy * xy).sum(axis=1)


def _max_radius2(camera: Camera) -> float:
    """Squared normalised radius of the farthest image border point: beyond it the distortion
    polynomial may fold points back into the image, so they are treated as unseen."""
    w, h = camera.width - 1, camera.height - 1
    t = np.linspace(0, 1, 9)
    border = np.vstack([np.column_stack([t * w, np.zeros(9)]), np.column_stack([t * w, np.full(9, h)]),
                        np.column_stack([np.zeros(9), t * h]), np.column_stack([np.full(9, w), t * h])])
    xy = pixels_to_normalized(border, camera)
    return float((xy ** 2).sum(1).max())


# --------------------------------------------------------------------------- ortho
@dataclass(frozen=True)
class OrthoParams:
    """Parameters of :func:`true_ortho`.

    Attributes
    ----------
    resolution : float or None
        Ortho cell size in CRS units (metres); default the DSM cell size.
    blend_angle : float
        Degrees: images whose off-nadir angle is within about this of the most nadir one are
        blended (seam feathering); 0 takes the most nadir image only.
    occlusion : bool
        Test visibility against the DSM (a true orthophoto). False gives a conventional
        orthophoto (buildings lean).
    occlusion_tolerance : float
        Metres the DSM may rise above the ray before the point counts as hidden.
    max_off_nadir : float
        Degrees; views more oblique than this are not used.
    dsm_rmse : float or None
        Vertical RMSE of the DSM in metres for the accuracy estimate (default the DSM's
        ``vertical_rmse`` meta, else one DSM cell).
    orientation_px : float or None
        RMS orientation/reprojection error in pixels (default the reconstruction's
        ``reprojection_rmse_px`` meta, else 0.5 px).
    tile : int
        Ortho tile size in cells (bounds memory); images that cannot see a tile are skipped.
    """

    resolution: float | None = None
    blend_angle: float = 2.0
    occlusion: bool = True
    occlusion_tolerance: float = 0.1
    max_off_nadir: float = 45.0
    dsm_rmse: float | None = None
    orientation_px: float | None = None
    tile: int = 512


@dataclass(frozen=True)
class OrthoResult:
    """An orthophoto, its per-cell accuracy and figures.

    Attributes
    ----------
    ortho : Raster
        (4, rows, cols) uint8 RGBA; alpha 0 where no image sees the cell.
    accuracy : Raster
        (rows, cols) float32 estimated planimetric error in metres (NaN where invisible).
    meta : dict
        ``coverage`` (share of cells coloured), ``images_used``, ``accuracy_rms_m``, ...
    """

    ortho: Raster
    accuracy: Raster
    meta: dict


def _load_image(im: Image) -> np.ndarray:
    import cv2

    if not im.path or not Path(im.path).is_file():
        raise InvalidInputError("image file not found", "check the image folder of the reconstruction", path=im.path or im.name)
    a = cv2.imread(str(im.path), cv2.IMREAD_COLOR)
    if a is None:
        raise InvalidInputError("unreadable image", path=im.path)
    return a[:, :, ::-1].copy()


def _occluded(P: np.ndarray, C: np.ndarray, dsm: np.ndarray, grid: GridSpec, zmax: float, tol: float) -> np.ndarray:
    """Ray marching from points P (n, 3) towards camera centre C over the DSM (nearest cell)."""
    n = len(P)
    occ = np.zeros(n, bool)
    d = C[None, :] - P
    h = np.hypot(d[:, 0], d[:, 1])
    step = 0.5 * grid.res
    with np.errstate(divide="ignore", invalid="ignore"):
        climb = d[:, 2] / h  # metres of rise per metre of horizontal travel
        ux, uy = d[:, 0] / h, d[:, 1] / h
    smax = np.where(h > 1e-9, np.minimum((zmax - P[:, 2]) / np.maximum(climb, 1e-9), h), 0.0)
    active = np.flatnonzero(smax > step)
    k = 1
    R, Cc = dsm.shape
    while len(active):
        s = k * step
        a = active
        x = P[a, 0] + ux[a] * s
        y = P[a, 1] + uy[a] * s
        zr = P[a, 2] + climb[a] * s
        col = np.floor((x - grid.x0) / grid.res).astype(np.int64)
        row = np.floor((grid.y1 - y) / grid.res).astype(np.int64)
        inside = (row >= 0) & (row < R) & (col >= 0) & (col < Cc)
        zs = np.full(len(a), -np.inf)
        zs[inside] = dsm[row[inside], col[inside]]
        hit = zs > zr + tol
        occ[a[hit]] = True
        keep = ~hit & (s + step < smax[a])
        active = a[keep]
        k += 1
    return occ


def _misses(cam: Camera, pose: Pose, box: np.ndarray) -> bool:
    """True when the 8 corners of a tile's (X, Y, Z) box all project to one side outside the
    image (the tile cannot be seen); False when unsure (a corner behind the camera)."""
    uv, depth = project_points(cam, pose, box)
    if (depth <= 0).any():
        return False
    u, v = uv[:, 0], uv[:, 1]
    return bool((u < 0).all() or (u > cam.width - 1).all() or (v < 0).all() or (v > cam.height - 1).all())


#: Sample positions per cv2.remap row; OpenCV refuses maps with a side of 32,767 or more.
_REMAP_WIDTH = 4096
_REMAP_ROWS = 32_000


def _bilinear_sample(img: np.ndarray, uv: np.ndarray) -> np.ndarray:
    """``img`` sampled bilinearly at the (n, 2) pixel positions ``uv`` (edges replicated):
    (n, channels) float32. The positions are laid out as rows of a 2-D map, in blocks, since
    each remap result depends only on its own position."""
    import cv2

    n = len(uv)
    m = uv.astype(np.float32)
    out = []
    block = _REMAP_WIDTH * _REMAP_ROWS
    for s in range(0, max(n, 1), block):
        part = m[s : s + block]
        k = len(part)
        w = min(_REMAP_WIDTH, max(k, 1))
        rows = -(-k // w) if k else 0
        pad = np.pad(part, ((0, rows * w - k), (0, 0)), mode="edge") if k else part
        r = cv2.remap(img, pad[:, 0].reshape(rows, w), pad[:, 1].reshape(rows, w), cv2.INTER_LINEAR,
                      borderMode=cv2.BORDER_REPLICATE) if k else np.empty((0, 1), img.dtype)
        out.append(r.reshape(rows * w, -1)[:k] if k else r.reshape(0, img.shape[2] if img.ndim == 3 else 1))
    return np.concatenate(out).astype(np.float32)


def _dsm_heights(dsm: Raster) -> np.ndarray:
    """The DSM's first band as float64 with nodata as NaN; refuses a DSM without a valid cell."""
    dsm_a = np.asarray(dsm.array, dtype=np.float64)
    if dsm_a.ndim == 3:
        dsm_a = dsm_a[0]
    if dsm.nodata is not None and not np.isnan(dsm.nodata):
        dsm_a = np.where(dsm_a == dsm.nodata, np.nan, dsm_a)
    if not np.isfinite(dsm_a).any():
        raise InvalidInputError("the DSM has no valid cell", field="dsm")
    return dsm_a


def _ortho_grid(dgrid: GridSpec, res: float) -> GridSpec:
    """The ortho grid over the DSM's bounds at cell size ``res`` (refused when too large)."""
    xmin, ymin, xmax, ymax = dgrid.bounds
    # RGBA bytes, the float64 ground coordinates and per-view weights of each cell
    check_grid(max(1.0, round((ymax - ymin) / res)), max(1.0, round((xmax - xmin) / res)), what="the orthophoto",
               option="--resolution", cell=res, bytes_per_cell=64)
    return GridSpec(xmin, ymax, res, max(1, int(round((ymax - ymin) / res))), max(1, int(round((xmax - xmin) / res))))


class _OrthoBuilder:
    """The state of one :func:`true_ortho` run: inputs, the output arrays, the image cache.

    A view of a tile is ``(image id, indices of the tile's ground points it sees, their
    pixels, off-nadir angles in degrees, ground size of a pixel at each point)``.
    """

    def __init__(self, rec: Reconstruction, dsm: Raster, dsm_a: np.ndarray, dgrid: GridSpec, og: GridSpec,
                 params: OrthoParams, images: dict | None):
        self.rec, self.params, self.og, self.dgrid = rec, params, og, dgrid
        self.zmax = float(np.nanmax(dsm_a))
        self.dsm_occ = np.where(np.isnan(dsm_a), -np.inf, dsm_a)
        self.dsm_r = Raster(dsm_a, dsm.transform)
        sigma_z = params.dsm_rmse if params.dsm_rmse is not None else (dsm.meta.get("vertical_rmse") if dsm.meta else None)
        self.sigma_z = dgrid.res if sigma_z is None else sigma_z
        self.sigma_px = params.orientation_px if params.orientation_px is not None else float(rec.meta.get("reprojection_rmse_px", 0.5) or 0.0)
        self.rgb = np.zeros((3, og.rows, og.cols), np.uint8)
        self.alpha = np.zeros((og.rows, og.cols), np.uint8)
        self.acc = np.full((og.rows, og.cols), np.nan, np.float32)
        self.used = set()
        self.cache: dict = dict(images or {})
        self.centres = {k: im.pose.center for k, im in rec.images.items()}
        self.rmax2 = {cid: _max_radius2(cam) for cid, cam in rec.cameras.items()}
        self.cos_max = math.cos(math.radians(params.max_off_nadir))

    def tile(self, r0: int, c0: int) -> None:
        """Colour the ortho cells of the tile whose upper-left cell is (r0, c0)."""
        from .dem import sample_bilinear

        og, T, res = self.og, self.params.tile, self.og.res
        rr = np.arange(r0, min(r0 + T, og.rows))
        cc = np.arange(c0, min(c0 + T, og.cols))
        CC, RR = np.meshgrid(cc, rr)
        X = og.x0 + (CC.ravel() + 0.5) * res
        Y = og.y1 - (RR.ravel() + 0.5) * res
        Z = sample_bilinear(self.dsm_r, X, Y)
        idx = np.flatnonzero(np.isfinite(Z))
        if len(idx) == 0:
            return
        P = np.column_stack([X[idx], Y[idx], Z[idx]])
        views = self.views(P)
        if not views:
            return
        colour, seen, best, gsd_best = self.colours(views, len(P))
        flat = np.zeros((len(X), 3))
        flat[idx] = colour
        a = np.zeros(len(X), np.uint8)
        a[idx[seen]] = 255
        th = np.radians(np.where(seen, best, np.nan))
        sig = np.sqrt((self.sigma_z * np.tan(th)) ** 2 + (self.sigma_px * gsd_best) ** 2)
        accf = np.full(len(X), np.nan)
        accf[idx] = sig
        sl = (slice(r0, r0 + len(rr)), slice(c0, c0 + len(cc)))
        self.rgb[(slice(None),) + sl] = np.round(flat).clip(0, 255).astype(np.uint8).reshape(len(rr), len(cc), 3).transpose(2, 0, 1)
        self.alpha[sl] = a.reshape(len(rr), len(cc))
        self.acc[sl] = accf.reshape(len(rr), len(cc))

    def views(self, P: np.ndarray) -> list:
        """The views of the ground points ``P`` (n, 3) of one tile, one per image that sees any."""
        box = np.array([[x, y, z] for x in (P[:, 0].min(), P[:, 0].max()) for y in (P[:, 1].min(), P[:, 1].max())
                        for z in (P[:, 2].min(), P[:, 2].max())])
        views = []
        for k, im in self.rec.images.items():
            cam = self.rec.cameras[im.camera_id]
            if _misses(cam, im.pose, box):
                continue
            view = self._view(k, im, cam, P)
            if view is not None:
                views.append(view)
        return views

    def _view(self, k, im: Image, cam: Camera, P: np.ndarray):
        """Image ``k``'s view of the points ``P``: in the frame, in front, within the off-nadir
        limit, not folded back by distortion and (with occlusion) not hidden by the DSM."""
        params = self.params
        uv, depth, r2 = _project(cam, im.pose, P)
        C = self.centres[k]
        d = C[None, :] - P
        cos_t = d[:, 2] / np.linalg.norm(d, axis=1)
        vis = (depth > 0) & (uv[:, 0] >= 0) & (uv[:, 0] <= cam.width - 1) & (uv[:, 1] >= 0) & (uv[:, 1] <= cam.height - 1)
        vis &= (cos_t >= self.cos_max) & (r2 <= 1.1 * self.rmax2[im.camera_id])
        if not vis.any():
            return None
        sel = np.flatnonzero(vis)
        if params.occlusion:
            occ = _occluded(P[sel], C, self.dsm_occ, self.dgrid, self.zmax, params.occlusion_tolerance)
            sel = sel[~occ]
        if len(sel) == 0:
            return None
        theta = np.degrees(np.arccos(np.clip(cos_t[sel], -1, 1)))
        return (k, sel, uv[sel], theta, depth[sel] / cam.fx)

    def colours(self, views: list, n: int):
        """Blend the views of a tile's ``n`` points (module docstring, step 4).

        Returns the colours (n, 3), which points are seen, the smallest off-nadir angle and the
        pixel ground size in the most nadir view of each point.
        """
        best = np.full(n, np.inf)
        gsd_best = np.zeros(n)
        for k, sel, uv, theta, gsd in views:
            better = theta < best[sel]
            best[sel[better]] = theta[better]
            gsd_best[sel[better]] = gsd[better]
        num = np.zeros((n, 3))
        den = np.zeros(n)
        blend_angle = self.params.blend_angle
        for k, sel, uv, theta, gsd in views:
            dth = theta - best[sel]
            if blend_angle > 0:
                w = np.exp(-dth / blend_angle)
                w[dth > 3 * blend_angle] = 0.0
            else:
                w = (dth <= 1e-9).astype(float)
            m = w > 0
            if not m.any():
                continue
            if k not in self.cache:
                self.cache[k] = _load_image(self.rec.images[k])
            col = _bilinear_sample(self.cache[k], uv[m])
            num[sel[m]] += w[m, None] * col[:, :3]
            den[sel[m]] += w[m]
            self.used.add(k)
        seen = den > 0
        colour = np.zeros((n, 3))
        colour[seen] = num[seen] / den[seen, None]
        return colour, seen, best, gsd_best


def true_ortho(rec: Reconstruction, dsm: Raster, params: OrthoParams = OrthoParams(), images: dict | None = None) -> OrthoResult:
    """Build a true orthophoto from oriented images over a DSM.

    Parameters
    ----------
    rec : Reconstruction
        Cameras and oriented images (paths to the image files) in the DSM's CRS.
    dsm : Raster
        Surface heights (metres), north-up, square cells; NaN where unknown.
    params : OrthoParams
    images : dict, optional
        Image id -> (h, w, 3) uint8 arrays, to skip reading files.

    Returns
    -------
    OrthoResult

    Raises
    ------
    StageError
        When no cell is seen by any image (wrong CRS, DSM outside the block).
    """
    t0 = time.perf_counter()
    dsm_a = _dsm_heights(dsm)
    dgrid = GridSpec.from_transform(dsm.transform, dsm_a.shape)
    res = params.resolution or dgrid.res
    og = _ortho_grid(dgrid, res)
    b = _OrthoBuilder(rec, dsm, dsm_a, dgrid, og, params, images)
    for r0 in range(0, og.rows, params.tile):
        for c0 in range(0, og.cols, params.tile):
            b.tile(r0, c0)
    coverage = float((b.alpha > 0).mean())
    if coverage == 0:
        raise StageError("ortho", "no DSM cell is seen by any image",
                         "check that the DSM and the reconstruction share a CRS and overlap")
    valid_acc = b.acc[np.isfinite(b.acc)]
    meta = {
        "kind": "ortho", "resolution": res, "coverage": coverage, "images_used": len(b.used), "images": len(rec.images),
        "true_ortho": params.occlusion, "blend_angle_deg": params.blend_angle,
        "accuracy_rms_m": float(np.sqrt(np.mean(valid_acc ** 2))), "accuracy_max_m": float(valid_acc.max()),
        "dsm_rmse_m": float(b.sigma_z), "orientation_px": float(b.sigma_px), "seconds": round(time.perf_counter() - t0, 3),
    }
    ortho = Raster(np.concatenate([b.rgb, b.alpha[None]]), og.transform, dsm.crs or rec.crs, None, meta)
    accr = Raster(b.acc, og.transform, dsm.crs or rec.crs, -9999.0, {"kind": "ortho_accuracy", "units": "m"})
    return OrthoResult(ortho, accr, meta)
