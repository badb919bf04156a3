"""Core types <-> pymeshlab objects (``Mesh``/``MeshSet``).

Coordinates go to MeshLab with an explicit ``origin`` subtracted (MeshLab keeps float
coordinates; projected coordinates of 10^6 m would lose millimetres), and come back with it
added (:func:`workstation.core.geometry.default_origin` by default). Colours travel as
MeshLab's RGBA floats in [0, 1] (:func:`workstation.core.color.rgb_to_unit`); the core types
keep ``rgb`` as integers (u16 for clouds, u8 for meshes).

pymeshlab is imported inside the functions, never at module import.
"""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_u8, rgb_to_unit, unit_to_rgb16  # noqa: F401 - rgb_to_u8 re-exported
from workstation.core.errors import MissingDependencyError
from workstation.core.geometry import default_origin
from workstation.core.products import Mesh


def import_pymeshlab():
    try:
        import pymeshlab
    except ImportError as e:  # pragma: no cover - pymeshlab is a declared dependency
        raise MissingDependencyError("pymeshlab", "meshing filters", "pip install pymeshlab") from e
    return pymeshlab


def cloud_to_pymeshlab(cloud: Cloud, origin=None):
    """A point cloud as a face-less ``pymeshlab.Mesh``.

    Parameters
    ----------
    cloud : Cloud
        Its ``normal`` (n, 3) and ``rgb`` (n, 3) attributes travel when present.
    origin : (3,) float, optional
        Subtracted from the coordinates; :func:`default_origin` when None.

    Returns
    -------
    (pymeshlab.Mesh, (3,) float64 origin)
    """
    pml = import_pymeshlab()
    origin = default_origin(cloud.xyz) if origin is None else np.asarray(origin, dtype=np.float64)
    kw = {}
    if "normal" in cloud.attrs:
        kw["v_normals_matrix"] = np.ascontiguousarray(cloud.attrs["normal"], dtype=np.float64)
    if "rgb" in cloud.attrs:
        c = np.ones((cloud.n, 4))
        c[:, :3] = rgb_to_unit(cloud.attrs["rgb"])
        kw["v_color_matrix"] = c
    return pml.Mesh(np.ascontiguousarray(cloud.xyz - origin), **kw), origin


def mesh_to_pymeshlab(mesh: Mesh, origin=None):
    """A core :class:`Mesh` as a ``pymeshlab.Mesh`` (vertex rgb, normals and ``quality`` travel).

    Returns
    -------
    (pymeshlab.Mesh, (3,) float64 origin)
    """
    pml = import_pymeshlab()
    origin = default_origin(mesh.vertices) if origin is None else np.asarray(origin, dtype=np.float64)
    kw = {}
    va = mesh.vertex_attrs
    if "normal" in va:
        kw["v_normals_matrix"] = np.ascontiguousarray(va["normal"], dtype=np.float64)
    if "rgb" in va:
        c = np.ones((mesh.n_vertices, 4))
        c[:, :3] = rgb_to_unit(va["rgb"])
        kw["v_color_matrix"] = c
    if "quality" in va:
        kw["v_scalar_array"] = np.ascontiguousarray(va["quality"], dtype=np.float64)
    m = pml.Mesh(
        np.ascontiguousarray(mesh.vertices - origin),
        np.ascontiguousarray(mesh.faces, dtype=np.int32).reshape(-1, 3),
        **kw,
    )
    return m, origin


def meshset_with(*meshes):
    """A new ``MeshSet`` holding the given ``pymeshlab.Mesh`` objects (ids 0, 1, ...)."""
    pml = import_pymeshlab()
    ms = pml.MeshSet()
    ms.set_verbosity(False)
    for m in meshes:
        ms.add_mesh(m)
    return ms


def pymeshlab_to_mesh(m, origin, crs: str | None = None, meta=None, quality_name: str | None = "quality") -> Mesh:
    """A ``pymeshlab.Mesh`` back to a core :class:`Mesh` (origin added back).

    Vertex colours become ``rgb`` (n, 3) uint8, normals ``normal`` (n, 3) float32 and the
    MeshLab per-vertex quality (Poisson density, distances...) ``quality_name`` float32.
    """
    v = np.asarray(m.vertex_matrix(), dtype=np.float64) + np.asarray(origin, dtype=np.float64)
    f = np.asarray(m.face_matrix(), dtype=np.int64).reshape(-1, 3)
    attrs = {}
    if m.vertex_number():
        if m.has_vertex_color():
            attrs["rgb"] = np.round(np.clip(m.vertex_color_matrix()[:, :3], 0, 1) * 255).astype(np.uint8)
        n = np.asarray(m.vertex_normal_matrix(), dtype=np.float32)
        if n.shape == v.shape and np.any(n):
            attrs["normal"] = n
        if quality_name and m.has_vertex_scalar():
            attrs[quality_name] = np.asarray(m.vertex_scalar_array(), dtype=np.float32)
    return Mesh(v, f, attrs, crs=crs, meta=dict(meta or {}))


def pymeshlab_to_cloud(m, origin, template: Cloud | None = None) -> Cloud:
    """A ``pymeshlab.Mesh`` (its vertices) as a :class:`Cloud` with normals (and rgb)."""
    v = np.asarray(m.vertex_matrix(), dtype=np.float64) + np.asarray(origin, dtype=np.float64)
    attrs = {"normal": np.asarray(m.vertex_normal_matrix(), dtype=np.float32)}
    if m.has_vertex_color():
        attrs["rgb"] = unit_to_rgb16(m.vertex_color_matrix()[:, :3])
    return Cloud(v, attrs, crs=None if template is None else template.crs)
