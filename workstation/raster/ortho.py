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

import json
import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.budget import check_grid
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Image, Pose, Raster, Reconstruction

from workstation.io.textfile import read_text

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
    from workstation.photogrammetry.collinearity import project

    uv, z, xy = project(X, camera, pose, return_depth=True, return_normalized=True)
    return uv, z, (xy * xy).sum(axis=1)


def undistort(camera: Camera, uv: np.ndarray, iterations: int = 20) -> np.ndarray:
    """Normalised image coordinates (n, 2) of distorted pixels (fixed-point inversion of the
    OpenCV model, as ``cv2.undistortPoints``; converges for the moderate distortion of
    mapping cameras)."""
    k1, k2, p1, p2, k3 = (tuple(camera.dist) + (0.0,) * 5)[:5]
    yd = (uv[:, 1] - camera.cy) / camera.fy
    xd = (uv[:, 0] - camera.cx - camera.skew * yd) / camera.fx
    x, y = xd.copy(), yd.copy()
    for _ in range(iterations):
        r2 = x * x + y * y
        radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3))
        dx = 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
        dy = p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
        x = (xd - dx) / radial
        y = (yd - dy) / radial
    return np.column_stack([x, y])


def _max_radius2(camera: Camera) -> float:
    """Squared normalised radius of the farthest image border point: beyond it the distortion
    polynomial may fold points back into the image, so they are treated as unseen."""
    w, h = camera.width - 1, camera.height - 1
    t = np.linspace(0, 1, 9)
    border = np.vstack([np.column_stack([t * w, np.zeros(9)]), np.column_stack([t * w, np.full(9, h)]),
                        np.column_stack([np.zeros(9), t * h]), np.column_stack([np.full(9, w), t * h])])
    xy = undistort(camera, border)
    return float((xy ** 2).sum(1).max())


# --------------------------------------------------------------------------- reconstruction IO
def _camera_to_dict(c: Camera) -> dict:
    return {"width": c.width, "height": c.height, "fx": c.fx, "fy": c.fy, "cx": c.cx, "cy": c.cy,
            "skew": c.skew, "dist": list(c.dist), "model": c.model}


def write_reconstruction_json(rec: Reconstruction, path, overwrite: bool = False) -> Path:
    """Write cameras and oriented images as JSON (pixel centres at integers, x_cam = R X + t)."""
    from workstation.io import atomic_path

    doc = {
        "convention": "x_cam = R @ X_world + t; pixel centres at integer coordinates; dist = OpenCV k1 k2 p1 p2 k3",
        "crs": rec.crs,
        "cameras": {str(k): _camera_to_dict(c) for k, c in rec.cameras.items()},
        "images": {str(k): {"name": im.name, "camera_id": im.camera_id, "R": np.asarray(im.pose.R).tolist(),
                            "t": np.asarray(im.pose.t).tolist(), "path": im.path} for k, im in rec.images.items()},
        "meta": {k: v for k, v in dict(rec.meta).items() if isinstance(v, (int, float, str, bool))},
    }
    with atomic_path(path, overwrite=overwrite) as tmp:
        tmp.write_text(json.dumps(doc, indent=1))
    return Path(path)


def _read_json(path: Path) -> Reconstruction:
    from workstation.io.paths import resolve_inside

    try:
        doc = json.loads(read_text(path))
        cams = {int(k): Camera(int(c["width"]), int(c["height"]), float(c["fx"]), float(c.get("fy", c["fx"])),
                               float(c["cx"]), float(c["cy"]), float(c.get("skew", 0.0)),
                               tuple(float(d) for d in (list(c.get("dist", [])) + [0.0] * 5)[:5]), c.get("model", "OPENCV"))
                for k, c in doc["cameras"].items()}
        imgs = {}
        for k, im in doc["images"].items():
            p = str(resolve_inside(im.get("path") or im["name"], path.parent, source=path, field=f"images.{k}.path"))
            imgs[int(k)] = Image(im["name"], int(im["camera_id"]), Pose(np.array(im["R"], float), np.array(im["t"], float)), p)
    except (KeyError, TypeError, ValueError, json.JSONDecodeError) as e:
        raise InvalidInputError(f"not a cameras JSON ({e})", "see write_reconstruction_json for the layout", path=path) from None
    return Reconstruction(cams, imgs, crs=doc.get("crs"), meta=doc.get("meta", {}))


def read_reconstruction(path, image_dir=None) -> Reconstruction:
    """Oriented cameras from a cameras JSON or a COLMAP workdir/model folder.

    ``path`` may be the JSON file, a folder holding ``cameras.json``, a COLMAP model folder
    (``cameras.bin``/``.txt``), or a workdir with ``sparse/0`` or ``sparse``.
    """
    p = Path(path)
    if p.is_file():
        return _read_json(p)
    if not p.is_dir():
        raise InvalidInputError("not found", "give a COLMAP workdir or a cameras JSON", path=p)
    if (p / "cameras.json").is_file():
        return _read_json(p / "cameras.json")
    from workstation.interop.pycolmap import find_model, read_model

    if find_model(p) is not None:
        return read_model(p, image_dir)
    raise InvalidInputError("no cameras.json and no COLMAP model (cameras.bin/.txt) found",
                            "run ws sfm first or give the model folder", path=p)


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


def _bilinear_sample(img: np.ndarray, uv: np.ndarray) -> np.ndarray:
    import cv2

    m = uv.astype(np.float32)
    out = cv2.remap(img, m[:, 0].reshape(-1, 1), m[:, 1].reshape(-1, 1), cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
    return out.reshape(len(uv), -1).astype(np.float32)


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
    dsm_a = np.asarray(dsm.array, dtype=np.float64)
    if dsm_a.ndim == 3:
        dsm_a = dsm_a[0]
    if dsm.nodata is not None and not np.isnan(dsm.nodata):
        dsm_a = np.where(dsm_a == dsm.nodata, np.nan, dsm_a)
    if not np.isfinite(dsm_a).any():
        raise InvalidInputError("the DSM has no valid cell", field="dsm")
    dgrid = GridSpec.from_transform(dsm.transform, dsm_a.shape)
    res = params.resolution or dgrid.res
    xmin, ymin, xmax, ymax = dgrid.bounds
    # RGBA bytes, the float64 ground coordinates and per-view weights of each cell
    check_grid(max(1.0, round((ymax - ymin) / res)), max(1.0, round((xmax - xmin) / res)), what="the orthophoto",
               option="--resolution", cell=res, bytes_per_cell=64)
    og = GridSpec(xmin, ymax, res, max(1, int(round((ymax - ymin) / res))), max(1, int(round((xmax - xmin) / res))))
    zmax = float(np.nanmax(dsm_a))
    dsm_occ = np.where(np.isnan(dsm_a), -np.inf, dsm_a)
    dsm_r = Raster(dsm_a, dsm.transform)
    from .dem import sample_bilinear

    sigma_z = params.dsm_rmse if params.dsm_rmse is not None else (dsm.meta.get("vertical_rmse") if dsm.meta else None)
    if sigma_z is None:
        sigma_z = dgrid.res
    sigma_px = params.orientation_px if params.orientation_px is not None else float(rec.meta.get("reprojection_rmse_px", 0.5) or 0.0)
    rgb = np.zeros((3, og.rows, og.cols), np.uint8)
    alpha = np.zeros((og.rows, og.cols), np.uint8)
    acc = np.full((og.rows, og.cols), np.nan, np.float32)
    used = set()
    cache: dict = dict(images or {})
    centres = {k: im.pose.center for k, im in rec.images.items()}
    rmax2 = {cid: _max_radius2(cam) for cid, cam in rec.cameras.items()}
    cos_max = math.cos(math.radians(params.max_off_nadir))
    T = params.tile
    for r0 in range(0, og.rows, T):
        for c0 in range(0, og.cols, T):
            rr = np.arange(r0, min(r0 + T, og.rows))
            cc = np.arange(c0, min(c0 + T, og.cols))
            CC, RR = np.meshgrid(cc, rr)
            X = og.x0 + (CC.ravel() + 0.5) * res
            Y = og.y1 - (RR.ravel() + 0.5) * res
            Z = sample_bilinear(dsm_r, X, Y)
            ok = np.isfinite(Z)
            idx = np.flatnonzero(ok)
            if len(idx) == 0:
                continue
            P = np.column_stack([X[idx], Y[idx], Z[idx]])
            box = np.array([[x, y, z] for x in (P[:, 0].min(), P[:, 0].max()) for y in (P[:, 1].min(), P[:, 1].max())
                            for z in (P[:, 2].min(), P[:, 2].max())])
            views = []
            for k, im in rec.images.items():
                cam = rec.cameras[im.camera_id]
                if _misses(cam, im.pose, box):
                    continue
                uv, depth, r2 = _project(cam, im.pose, P)
                C = centres[k]
                d = C[None, :] - P
                cos_t = d[:, 2] / np.linalg.norm(d, axis=1)
                vis = (depth > 0) & (uv[:, 0] >= 0) & (uv[:, 0] <= cam.width - 1) & (uv[:, 1] >= 0) & (uv[:, 1] <= cam.height - 1)
                vis &= (cos_t >= cos_max) & (r2 <= 1.1 * rmax2[im.camera_id])
                if not vis.any():
                    continue
                sel = np.flatnonzero(vis)
                if params.occlusion:
                    occ = _occluded(P[sel], C, dsm_occ, dgrid, zmax, params.occlusion_tolerance)
                    sel = sel[~occ]
                if len(sel) == 0:
                    continue
                theta = np.degrees(np.arccos(np.clip(cos_t[sel], -1, 1)))
                views.append((k, sel, uv[sel], theta, depth[sel] / cam.fx))
            if not views:
                continue
            best = np.full(len(P), np.inf)
            gsd_best = np.zeros(len(P))
            for k, sel, uv, theta, gsd in views:
                better = theta < best[sel]
                best[sel[better]] = theta[better]
                gsd_best[sel[better]] = gsd[better]
            num = np.zeros((len(P), 3))
            den = np.zeros(len(P))
            for k, sel, uv, theta, gsd in views:
                dth = theta - best[sel]
                if params.blend_angle > 0:
                    w = np.exp(-dth / params.blend_angle)
                    w[dth > 3 * params.blend_angle] = 0.0
                else:
                    w = (dth <= 1e-9).astype(float)
                m = w > 0
                if not m.any():
                    continue
                if k not in cache:
                    cache[k] = _load_image(rec.images[k])
                col = _bilinear_sample(cache[k], uv[m])
                num[sel[m]] += w[m, None] * col[:, :3]
                den[sel[m]] += w[m]
                used.add(k)
            seen = den > 0
            colour = np.zeros((len(P), 3))
            colour[seen] = num[seen] / den[seen, None]
            flat = np.zeros((len(X), 3))
            flat[idx] = colour
            a = np.zeros(len(X), np.uint8)
            a[idx[seen]] = 255
            th = np.radians(np.where(seen, best, np.nan))
            sig = np.sqrt((sigma_z * np.tan(th)) ** 2 + (sigma_px * gsd_best) ** 2)
            accf = np.full(len(X), np.nan)
            accf[idx] = sig
            sl = (slice(r0, r0 + len(rr)), slice(c0, c0 + len(cc)))
            rgb[(slice(None),) + sl] = np.round(flat).clip(0, 255).astype(np.uint8).reshape(len(rr), len(cc), 3).transpose(2, 0, 1)
            alpha[sl] = a.reshape(len(rr), len(cc))
            acc[sl] = accf.reshape(len(rr), len(cc))
    coverage = float((alpha > 0).mean())
    if coverage == 0:
        raise StageError("ortho", "no DSM cell is seen by any image",
                         "check that the DSM and the reconstruction share a CRS and overlap")
    valid_acc = acc[np.isfinite(acc)]
    meta = {
        "kind": "ortho", "resolution": res, "coverage": coverage, "images_used": len(used), "images": len(rec.images),
        "true_ortho": params.occlusion, "blend_angle_deg": params.blend_angle,
        "accuracy_rms_m": float(np.sqrt(np.mean(valid_acc ** 2))), "accuracy_max_m": float(valid_acc.max()),
        "dsm_rmse_m": float(sigma_z), "orientation_px": float(sigma_px), "seconds": round(time.perf_counter() - t0, 3),
    }
    ortho = Raster(np.concatenate([rgb, alpha[None]]), og.transform, dsm.crs or rec.crs, None, meta)
    accr = Raster(acc, og.transform, dsm.crs or rec.crs, -9999.0, {"kind": "ortho_accuracy", "units": "m"})
    return OrthoResult(ortho, accr, meta)
