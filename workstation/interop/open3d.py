"""Conversions between :class:`~workstation.core.cloud.Cloud` and Open3D point clouds.

Open3D stores coordinates in float64 (legacy ``PointCloud``) or in a tensor of our choice
(``open3d.t.geometry.PointCloud``). Georeferenced coordinates (UTM eastings of 500 000 m,
northings of 5 000 000 m) lose millimetres in float32, so every conversion here subtracts an
explicit ``origin`` (a (3,) float64 vector, returned with the Open3D object) and the reverse
conversion adds it back. The default origin is the centre of the cloud's bounding box rounded
to whole units, so it is reproducible and visible in logs
(:func:`workstation.core.geometry.default_origin`). Colours go to Open3D as floats in [0, 1]
by :func:`workstation.core.color.rgb_to_unit` (the rule MeshLab and VTK get too) and come
back as 16-bit ``rgb``.

Open3D mutates in place (``transform``, ``estimate_normals``, ``paint_uniform_color``); the
helpers here always work on copies so a caller's object never changes behind its back.

Only this module touches Open3D objects; everything else passes ``Cloud`` and numpy arrays.
"""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_unit, unit_to_rgb16
from workstation.core.errors import InvalidInputError, MissingDependencyError
from workstation.core.geometry import default_origin


def require_open3d():
    """Import open3d or raise :class:`MissingDependencyError` with the install command."""
    try:
        import open3d as o3d
    except ImportError as e:  # pragma: no cover - open3d is a dependency
        raise MissingDependencyError(
            "open3d", "registration, normals and KD-trees",
            "pip install open3d (and apt-get install -y libusb-1.0-0 on Debian/Ubuntu)",
        ) from e
    return o3d


def _origin(cloud_xyz, origin) -> np.ndarray:
    if origin is None:
        return default_origin(cloud_xyz)
    o = np.asarray(origin, dtype=np.float64).reshape(-1)
    if o.shape != (3,):
        raise InvalidInputError(f"origin must be 3 numbers, got {o.shape}", field="origin")
    return o


def to_legacy(cloud: Cloud, origin=None, *, normals: bool = True, colors: bool = True):
    """A new legacy ``open3d.geometry.PointCloud`` holding ``cloud.xyz - origin``.

    Parameters
    ----------
    cloud : Cloud
    origin : (3,) array_like of float, optional
        Subtracted from every point (units of the cloud's CRS); :func:`default_origin` if None.
    normals, colors : bool
        Copy the ``normal`` and ``rgb`` attributes when present (rgb scaled to [0, 1]).

    Returns
    -------
    pcd : open3d.geometry.PointCloud
        Positions in float64, local to ``origin``.
    origin : (3,) float64
        The origin that was subtracted; pass it to :func:`from_legacy` to go back.
    """
    o3d = require_open3d()
    o = _origin(cloud.xyz, origin)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.ascontiguousarray(cloud.xyz - o)))
    if normals and "normal" in cloud.attrs:
        pcd.normals = o3d.utility.Vector3dVector(np.asarray(cloud.attrs["normal"], dtype=np.float64))
    if colors and "rgb" in cloud.attrs:
        pcd.colors = o3d.utility.Vector3dVector(rgb_to_unit(cloud.attrs["rgb"]))
    return pcd, o


def points_to_legacy(xyz: np.ndarray, normals: np.ndarray | None = None, colors: np.ndarray | None = None):
    """A legacy PointCloud from local (already origin-subtracted) float arrays; copies them."""
    o3d = require_open3d()
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.ascontiguousarray(xyz, dtype=np.float64)))
    if normals is not None:
        pcd.normals = o3d.utility.Vector3dVector(np.ascontiguousarray(normals, dtype=np.float64))
    if colors is not None:
        pcd.colors = o3d.utility.Vector3dVector(np.ascontiguousarray(colors, dtype=np.float64))
    return pcd


def from_legacy(pcd, origin, template: Cloud | None = None) -> Cloud:
    """A :class:`Cloud` from a legacy PointCloud, adding ``origin`` back.

    Normals become ``normal`` (f4), colours become ``rgb`` (u16). With ``template`` the CRS
    and metadata are taken from it (attributes are not: the point set may differ).
    """
    o = _origin(np.zeros((0, 3)), origin)
    xyz = np.asarray(pcd.points, dtype=np.float64) + o
    attrs = {}
    if pcd.has_normals():
        attrs["normal"] = np.asarray(pcd.normals, dtype=np.float32)
    if pcd.has_colors():
        attrs["rgb"] = unit_to_rgb16(np.asarray(pcd.colors))
    if template is None:
        return Cloud(xyz, attrs)
    return Cloud(xyz, attrs, crs=template.crs, meta=template.meta, history=template.history)


def to_tensor(cloud: Cloud, origin=None, *, dtype: str = "float32", attrs: tuple[str, ...] | None = None, device: str = "CPU:0"):
    """A new ``open3d.t.geometry.PointCloud`` with positions ``cloud.xyz - origin`` in ``dtype``.

    Parameters
    ----------
    cloud : Cloud
    origin : (3,) array_like of float, optional
        Subtracted before the cast (default :func:`default_origin`), so float32 keeps
        sub-millimetre precision for georeferenced coordinates.
    dtype : {"float32", "float64"}
        Dtype of positions, normals and colours.
    attrs : tuple of str, optional
        Attributes to copy (default: all). ``rgb`` becomes ``colors`` in [0, 1], ``normal``
        becomes ``normals``, ``intensity`` becomes ``intensities``; others keep their names.
    device : str
        Open3D device, ``"CPU:0"`` or ``"CUDA:0"``.

    Returns
    -------
    pcd : open3d.t.geometry.PointCloud
    origin : (3,) float64
    """
    o3d = require_open3d()
    if dtype not in ("float32", "float64"):
        raise InvalidInputError(f"dtype must be float32 or float64, got {dtype}", field="dtype")
    o = _origin(cloud.xyz, origin)
    dev = o3d.core.Device(device)
    fdt = np.dtype(dtype)
    pcd = o3d.t.geometry.PointCloud(dev)
    pcd.point.positions = o3d.core.Tensor(np.ascontiguousarray((cloud.xyz - o).astype(fdt)), device=dev)
    names = cloud.dims if attrs is None else [a for a in attrs if a in cloud.attrs]
    for name in names:
        a = np.asarray(cloud.attrs[name])
        if name == "rgb":
            pcd.point.colors = o3d.core.Tensor(rgb_to_unit(a).astype(fdt), device=dev)
        elif name == "normal":
            pcd.point.normals = o3d.core.Tensor(np.ascontiguousarray(a.astype(fdt)), device=dev)
        else:
            key = "intensities" if name == "intensity" else name
            a2 = a.reshape(a.shape[0], -1)
            if a2.dtype == np.uint16:  # open3d tensors have no u16 arithmetic everywhere: widen
                a2 = a2.astype(np.int32)
            elif a2.dtype == np.bool_:
                a2 = a2.astype(np.uint8)
            pcd.point[key] = o3d.core.Tensor(np.ascontiguousarray(a2), device=dev)
    return pcd, o


def from_tensor(pcd, origin, template: Cloud | None = None) -> Cloud:
    """A :class:`Cloud` from an Open3D tensor PointCloud, adding ``origin`` back in float64.

    ``colors`` become ``rgb`` (u16), ``normals`` become ``normal``, ``intensities`` become
    ``intensity``; other attributes keep their names (1-column ones become 1-D).
    """
    o = _origin(np.zeros((0, 3)), origin)
    xyz = pcd.point.positions.cpu().numpy().astype(np.float64) + o
    attrs = {}
    for key in pcd.point:
        if key == "positions":
            continue
        a = pcd.point[key].cpu().numpy()
        if key == "colors":
            attrs["rgb"] = unit_to_rgb16(a)
        elif key == "normals":
            attrs["normal"] = a.astype(np.float32)
        else:
            name = "intensity" if key == "intensities" else key
            attrs[name] = a[:, 0] if a.ndim == 2 and a.shape[1] == 1 else a
    if template is None:
        return Cloud(xyz, attrs)
    return Cloud(xyz, attrs, crs=template.crs, meta=template.meta, history=template.history)


def transformed_copy(pcd, transform: np.ndarray):
    """A transformed copy of a legacy or tensor PointCloud (Open3D's ``transform`` is in place)."""
    o3d = require_open3d()
    T = np.asarray(transform, dtype=np.float64)
    if T.shape != (4, 4):
        raise InvalidInputError(f"transform must be 4x4, got {T.shape}", field="transform")
    if isinstance(pcd, o3d.geometry.PointCloud):
        out = o3d.geometry.PointCloud(pcd)
        return out.transform(T)
    out = pcd.clone()
    return out.transform(o3d.core.Tensor(T))


def with_normals(pcd, radius: float, max_nn: int = 30):
    """A copy of a legacy PointCloud with normals estimated in a hybrid radius/k neighbourhood.

    ``radius`` is in the cloud's units; normals are oriented towards the local origin's
    positive side consistently only in the sense Open3D gives (use the sign for display only).
    """
    o3d = require_open3d()
    out = o3d.geometry.PointCloud(pcd)
    out.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(radius=float(radius), max_nn=int(max_nn)))
    return out


def local_transform(transform: np.ndarray, origin_source: np.ndarray, origin_target: np.ndarray) -> np.ndarray:
    """Express a world-frame transform in local frames: ``x_t_local = L @ x_s_local``.

    With ``x_world = x_local + origin``, a world transform ``T`` (``y = T x``) becomes
    ``L = Tr(-o_t) @ T @ Tr(o_s)``.
    """
    Ts = np.eye(4)
    Ts[:3, 3] = origin_source
    Tt = np.eye(4)
    Tt[:3, 3] = -np.asarray(origin_target)
    return Tt @ np.asarray(transform, dtype=np.float64) @ Ts


def world_transform(local: np.ndarray, origin_source: np.ndarray, origin_target: np.ndarray) -> np.ndarray:
    """Inverse of :func:`local_transform`: ``T = Tr(o_t) @ L @ Tr(-o_s)``."""
    Ts = np.eye(4)
    Ts[:3, 3] = -np.asarray(origin_source)
    Tt = np.eye(4)
    Tt[:3, 3] = origin_target
    return Tt @ np.asarray(local, dtype=np.float64) @ Ts
