"""Core types -> pyvista ``PolyData`` (and the off-screen setup of VTK).

VTK renders in float32, so coordinates are shifted by an explicit ``origin`` (by default the
rounded bounding-box centre) before conversion; every camera position handed to VTK must be
shifted by the same origin.

pyvista is imported inside the functions, never at module import.
"""

from __future__ import annotations

import os

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import MissingDependencyError
from workstation.core.geometry import default_origin
from workstation.core.products import Mesh


def pyvista_offscreen():
    """Import pyvista, with VTK set up for rendering without a display.

    VTK 9.4+ wheels pick the window at run time (X, then EGL, then OSMesa). Without a
    ``DISPLAY`` the X attempt only prints a warning before falling back, so the EGL window
    (Mesa's llvmpipe on a machine without GPU, the GPU's EGL driver where there is one) is
    asked for directly unless the user chose one with ``VTK_DEFAULT_OPENGL_WINDOW``.

    pyvista's global ``pyvista.OFF_SCREEN`` is left as the user set it: the render functions
    open their own ``Plotter(off_screen=True)``, so a notebook's interactive plots still show.
    """
    if not os.environ.get("DISPLAY") and "VTK_DEFAULT_OPENGL_WINDOW" not in os.environ:
        os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = "vtkEGLRenderWindow"
    try:
        import pyvista as pv
    except ImportError as e:  # pragma: no cover - declared dependency
        raise MissingDependencyError("pyvista", "off-screen rendering", "pip install pyvista") from e
    return pv


def cloud_to_polydata(cloud: Cloud, origin=None, attrs=()):
    """A cloud as vertex-only ``PolyData`` (float32 points relative to ``origin``).

    Parameters
    ----------
    cloud : Cloud
    origin : (3,) float, optional
        Subtracted from the coordinates (:func:`default_origin` when None).
    attrs : iterable of str
        Attributes copied to ``point_data`` under the same names.

    Returns
    -------
    (pyvista.PolyData, (3,) float64 origin)
    """
    pv = pyvista_offscreen()
    origin = default_origin(cloud.xyz) if origin is None else np.asarray(origin, dtype=np.float64)
    pts = (cloud.xyz - origin).astype(np.float32)
    n = len(pts)
    # one poly-vertex cell per chunk is far cheaper than one vertex cell per point
    poly = pv.PolyData(pts, verts=np.concatenate([[n], np.arange(n)]).astype(np.int64) if n else None)
    for a in attrs:
        poly.point_data[a] = np.asarray(cloud.attrs[a])
    return poly, origin


def mesh_to_polydata(mesh: Mesh, origin=None, attrs=()):
    """A mesh as triangle ``PolyData`` relative to ``origin``; ``attrs`` vertex attributes
    go to ``point_data``, face attributes named with a ``face:`` prefix to ``cell_data``.

    Returns
    -------
    (pyvista.PolyData, (3,) float64 origin)
    """
    pv = pyvista_offscreen()
    origin = default_origin(mesh.vertices) if origin is None else np.asarray(origin, dtype=np.float64)
    faces = np.column_stack([np.full(mesh.n_faces, 3, dtype=np.int64), mesh.faces]).ravel()
    poly = pv.PolyData((mesh.vertices - origin).astype(np.float32), faces)
    for a in attrs:
        if a.startswith("face:"):
            poly.cell_data[a[5:]] = np.asarray(mesh.face_attrs[a[5:]])
        else:
            poly.point_data[a] = np.asarray(mesh.vertex_attrs[a])
    return poly, origin
