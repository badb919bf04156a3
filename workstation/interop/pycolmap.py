"""Core types <-> pycolmap objects (checked against pycolmap 4.2.1).

Pixel conventions differ: COLMAP puts the origin at the *corner* of the top-left pixel (its
centre is (0.5, 0.5)), OpenCV and :class:`~workstation.core.products.Camera` at its *centre*.
Conversions therefore shift the principal point by 0.5 px.

pycolmap's API changed across versions (``Image.cam_from_world`` became a method,
``Reconstruction.write`` etc.); the helpers below accept both spellings where they differ.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, MissingDependencyError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Image, Pose, Reconstruction, Tracks

log = get_logger(__name__)

_HALF = 0.5


def import_pycolmap():
    """Import pycolmap or raise :class:`MissingDependencyError` with the install command."""
    try:
        import pycolmap
    except ImportError:  # pragma: no cover - a dependency
        raise MissingDependencyError("pycolmap", "structure from motion", "pip install pycolmap") from None
    import logging

    # COLMAP logs every step through glog on stderr; keep its INFO lines for -v (DEBUG) only,
    # so progress bars and our own messages stay readable.
    if not logging.getLogger("workstation").isEnabledFor(logging.DEBUG):
        pycolmap.logging.minloglevel = max(int(pycolmap.logging.minloglevel), 1)
    return pycolmap


def camera_to_colmap_params(camera: Camera) -> tuple[str, list[float]]:
    """(COLMAP model name, parameter list) for a core camera.

    PINHOLE when there is no distortion, OPENCV (k1, k2, p1, p2) when k3 = 0, FULL_OPENCV
    otherwise. COLMAP has no skew: a skew above 1e-6·fx is refused.
    """
    if abs(camera.skew) > 1e-6 * camera.fx:
        raise InvalidInputError(
            f"COLMAP camera models have no skew (skew = {camera.skew:.4g} px)",
            "recalibrate without skew (Zhang's method estimates none) or set skew to 0",
            field="skew",
        )
    k1, k2, p1, p2, k3 = (list(camera.dist) + [0.0] * 5)[:5]
    base = [camera.fx, camera.fy, camera.cx + _HALF, camera.cy + _HALF]
    if not any((k1, k2, p1, p2, k3)):
        return "PINHOLE", base
    if k3 == 0:
        return "OPENCV", base + [k1, k2, p1, p2]
    return "FULL_OPENCV", base + [k1, k2, p1, p2, k3, 0.0, 0.0, 0.0]


def camera_to_pycolmap(camera: Camera, camera_id: int = 1):
    """A ``pycolmap.Camera`` for a core camera."""
    pycolmap = import_pycolmap()
    model, params = camera_to_colmap_params(camera)
    cam = pycolmap.Camera.create_from_model_name(camera_id, model, float(camera.fx), int(camera.width), int(camera.height))
    cam.params = np.asarray(params, dtype=float)
    return cam


def camera_from_pycolmap(cam) -> Camera:
    """A core camera from a ``pycolmap.Camera`` (perspective models only)."""
    name = str(cam.model_name)
    p = [float(x) for x in np.asarray(cam.params).ravel()]
    dist = [0.0] * 5
    if name == "SIMPLE_PINHOLE":
        fx = fy = p[0]
        cx, cy = p[1], p[2]
    elif name == "PINHOLE":
        fx, fy, cx, cy = p[:4]
    elif name == "SIMPLE_RADIAL":
        fx = fy = p[0]
        cx, cy = p[1], p[2]
        dist[0] = p[3]
    elif name == "RADIAL":
        fx = fy = p[0]
        cx, cy = p[1], p[2]
        dist[0], dist[1] = p[3], p[4]
    elif name == "OPENCV":
        fx, fy, cx, cy = p[:4]
        dist[:4] = p[4:8]
    elif name == "FULL_OPENCV":
        fx, fy, cx, cy = p[:4]
        dist[:4] = p[4:8]
        dist[4] = p[8]
        if any(abs(v) > 0 for v in p[9:12]):
            log.warning("FULL_OPENCV rational terms k4-k6 dropped in the core camera")
    else:
        raise InvalidInputError(f"camera model {name} has no OpenCV equivalent in the core Camera", field="model")
    return Camera(
        width=int(cam.width),
        height=int(cam.height),
        fx=fx,
        fy=fy,
        cx=cx - _HALF,
        cy=cy - _HALF,
        skew=0.0,
        dist=tuple(dist),
        model=name,
    )


def _cam_from_world(im):
    T = im.cam_from_world
    return T() if callable(T) else T


def pose_from_pycolmap(im) -> Pose:
    """World -> camera pose of a registered ``pycolmap.Image``."""
    T = _cam_from_world(im)
    return Pose(np.asarray(T.rotation.matrix(), dtype=float), np.asarray(T.translation, dtype=float))


def tracks_from_pycolmap(rec, point_ids: np.ndarray) -> Tracks:
    """The image observations of a ``pycolmap.Reconstruction``'s 3-D points as :class:`Tracks`.

    ``point_ids`` gives the point3D id of each row of the core ``points`` array; pixels are
    moved to OpenCV's convention (−0.5 px).
    """
    row = {int(pid): k for k, pid in enumerate(np.asarray(point_ids).tolist())}
    pts, imgs, uv = [], [], []
    for iid, im in rec.images.items():
        if not im.has_pose:
            continue
        obs = im.get_observation_points2D()
        pts.extend(row[int(p2.point3D_id)] for p2 in obs)
        imgs.extend([int(iid)] * len(obs))
        uv.extend(p2.xy for p2 in obs)
    uv_a = np.asarray(uv, dtype=float).reshape(-1, 2) - _HALF
    return Tracks(np.asarray(pts, dtype=np.int64), np.asarray(imgs, dtype=np.int64), uv_a)


def reconstruction_from_pycolmap(rec, image_dir=None, with_tracks: bool = False) -> Reconstruction:
    """Core :class:`Reconstruction` of a ``pycolmap.Reconstruction`` (registered images only).

    ``meta`` holds ``point_errors`` (reprojection error per point, px), ``track_lengths`` and
    ``point_ids`` (COLMAP point3D id of each row). ``with_tracks`` also loads the image
    observations (:func:`tracks_from_pycolmap`), needed by a bundle adjustment.
    """
    from workstation.io.paths import resolve_inside

    cameras = {int(cid): camera_from_pycolmap(c) for cid, c in rec.cameras.items()}
    images = {}
    for iid, im in rec.images.items():
        if not im.has_pose:
            continue
        path = None if image_dir is None else str(
            resolve_inside(im.name, image_dir, source=image_dir, field=f"name of model image {iid}"))
        images[int(iid)] = Image(im.name, int(im.camera_id), pose_from_pycolmap(im), path)
    n = rec.num_points3D()
    pts = np.empty((n, 3))
    cols = np.empty((n, 3), dtype=np.uint8)
    err = np.empty(n)
    tl = np.empty(n, dtype=np.int64)
    ids = np.empty(n, dtype=np.int64)
    for i, (pid, p) in enumerate(rec.points3D.items()):
        pts[i] = p.xyz
        cols[i] = p.color
        err[i] = p.error
        tl[i] = p.track.length()
        ids[i] = pid
    tracks = tracks_from_pycolmap(rec, ids) if with_tracks else None
    return Reconstruction(cameras, images, pts, cols, None, {"point_errors": err, "track_lengths": tl, "point_ids": ids}, tracks)


def set_poses_and_points(rec, core: Reconstruction) -> None:
    """Write the poses and point positions of a core reconstruction into a ``pycolmap.Reconstruction``
    in place (a fresh copy should be passed), e.g. after a bundle adjustment.

    Images are matched by id, points by ``core.meta["point_ids"]`` (as made by
    :func:`reconstruction_from_pycolmap`); intrinsics are left as they are.
    """
    pycolmap = import_pycolmap()
    ids = core.meta.get("point_ids")
    if ids is None or core.points is None or len(ids) != core.points.shape[0]:
        raise InvalidInputError("the core reconstruction has no point ids matching its points", "read it with reconstruction_from_pycolmap")
    for iid, im in core.images.items():
        T = pycolmap.Rigid3d(pycolmap.Rotation3d(np.asarray(im.pose.R, dtype=float)), np.asarray(im.pose.t, dtype=float))
        pim = rec.images[int(iid)]
        frame = rec.frames[pim.frame_id]
        if hasattr(frame, "set_cam_from_world"):
            frame.set_cam_from_world(int(pim.camera_id), T)
        else:  # pragma: no cover - older pycolmap
            pim.cam_from_world = T
    for pid, X in zip(np.asarray(ids).tolist(), np.asarray(core.points, dtype=float)):
        rec.points3D[int(pid)].xyz = X


def find_model(path) -> Path | None:
    """The COLMAP model folder of a work folder: ``path``, ``path/sparse/0`` or ``path/sparse``."""
    p = Path(path)
    for cand in (p, p / "sparse" / "0", p / "sparse"):
        if (cand / "cameras.bin").is_file() or (cand / "cameras.txt").is_file():
            return cand
    return None


def read_model(path, image_dir=None, with_tracks: bool = False) -> Reconstruction:
    """Core :class:`Reconstruction` of a COLMAP model (binary or text) in a work folder.

    ``path`` is a model folder or an SfM work folder (``sparse/0`` or ``sparse``). Image paths
    point into ``image_dir``, by default the work folder's ``images/`` when it exists.
    Principal points follow OpenCV's convention (pixel centres at integers).
    """
    model = find_model(path)
    if model is None:
        raise InvalidInputError("no COLMAP model (cameras.bin/.txt) found", "give the SfM work folder (ws sfm -o)", path=path)
    if image_dir is None:
        for cand in (Path(path) / "images", model.parent.parent / "images", model.parent / "images"):
            if cand.is_dir():
                image_dir = cand
                break
    pycolmap = import_pycolmap()
    return reconstruction_from_pycolmap(pycolmap.Reconstruction(str(model)), image_dir, with_tracks)


def cloud_from_reconstruction(rec: Reconstruction):
    """Sparse coloured :class:`~workstation.core.cloud.Cloud` (rgb u16 = u8 · 257)."""
    from workstation.core.cloud import Cloud

    if rec.points is None:
        raise InvalidInputError("the reconstruction has no 3-D points")
    attrs = {}
    if rec.colors is not None:
        attrs["rgb"] = np.asarray(rec.colors, dtype=np.uint16) * 257
    return Cloud(np.asarray(rec.points, dtype=float), attrs, crs=rec.crs)


def write_model(rec, folder) -> None:
    """Write a pycolmap reconstruction as a binary COLMAP model into ``folder`` (created)."""
    Path(folder).mkdir(parents=True, exist_ok=True)
    if hasattr(rec, "write_binary"):
        rec.write_binary(str(folder))
    else:  # pragma: no cover - older pycolmap
        rec.write(str(folder))


def apply_similarity(rec, sim) -> None:
    """Move a pycolmap reconstruction in place by a similarity (a fresh copy should be passed)."""
    pycolmap = import_pycolmap()
    rot = pycolmap.Rotation3d(np.asarray(sim.R, dtype=float))
    rec.transform(pycolmap.Sim3d(float(sim.scale), rot, np.asarray(sim.t, dtype=float)))
