"""Triangle primitives for synthetic scenes (numpy only).

Each function returns ``(vertices (n, 3) float64, faces (m, 3) int64)`` with outward-facing
counter-clockwise triangles where the shape is closed. Coordinates are metres in the scene's
local frame (x east, y north, z up).
"""

from __future__ import annotations

import numpy as np


def rot_z(yaw: float) -> np.ndarray:
    """(3, 3) rotation about +z by ``yaw`` radians (counter-clockwise seen from above)."""
    c, s = np.cos(yaw), np.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def place(v: np.ndarray, center, yaw: float = 0.0) -> np.ndarray:
    """Rotate local vertices about z by ``yaw`` and translate them to ``center`` (3,)."""
    return v @ rot_z(yaw).T + np.asarray(center, dtype=float)


def grid(nx: int, ny: int) -> np.ndarray:
    """Faces of a regular (ny, nx) vertex grid in row-major order, two triangles per cell."""
    i = np.arange((ny - 1) * (nx - 1))
    r, c = np.divmod(i, nx - 1)
    a = r * nx + c
    b, d, e = a + 1, a + nx, a + nx + 1
    return np.concatenate([np.stack([a, b, e], 1), np.stack([a, e, d], 1)])


def box(lx: float, ly: float, lz: float, bottom: bool = False):
    """Axis-aligned box centred on x, y with its base at z = 0."""
    x, y = lx / 2, ly / 2
    v = np.array([[-x, -y, 0], [x, -y, 0], [x, y, 0], [-x, y, 0], [-x, -y, lz], [x, -y, lz], [x, y, lz], [-x, y, lz]], float)
    f = [[4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
    if bottom:
        f += [[0, 2, 1], [0, 3, 2]]
    return v, np.array(f, np.int64)


def prism(poly: np.ndarray, z0: float, z1: float, top: bool = True):
    """Vertical walls of a closed counter-clockwise polygon (k, 2) from z0 to z1 (+ fan top)."""
    k = len(poly)
    lo = np.column_stack([poly, np.full(k, z0)])
    hi = np.column_stack([poly, np.full(k, z1)])
    v = np.vstack([lo, hi])
    i = np.arange(k)
    j = (i + 1) % k
    f = np.concatenate([np.stack([i, j, j + k], 1), np.stack([i, j + k, i + k], 1)])
    if top:
        f = np.concatenate([f, np.stack([np.full(k - 2, k), np.arange(k + 1, 2 * k - 1), np.arange(k + 2, 2 * k)], 1)])
    return v, f


def frustum(bx: float, by: float, tx: float, ty: float, h: float):
    """A square frustum: base bx x by at z = 0, top tx x ty at z = h, closed on top."""
    v = np.array(
        [[-bx / 2, -by / 2, 0], [bx / 2, -by / 2, 0], [bx / 2, by / 2, 0], [-bx / 2, by / 2, 0],
         [-tx / 2, -ty / 2, h], [tx / 2, -ty / 2, h], [tx / 2, ty / 2, h], [-tx / 2, ty / 2, h]], float)
    f = [[4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]]
    return v, np.array(f, np.int64)


def pyramid(bx: float, by: float, h: float):
    """A four-sided pyramid with base bx x by at z = 0 and apex at z = h."""
    v = np.array([[-bx / 2, -by / 2, 0], [bx / 2, -by / 2, 0], [bx / 2, by / 2, 0], [-bx / 2, by / 2, 0], [0, 0, h]], float)
    return v, np.array([[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]], np.int64)


def gable_roof(lx: float, ly: float, rise: float, overhang: float = 0.0):
    """Gabled roof over lx (ridge direction x) by ly, eaves at z = 0, ridge at z = rise.

    The roof planes extend ``overhang`` metres beyond the walls (the eaves drop with the same
    slope); the two gable triangles close the ends over the wall line.
    """
    x = lx / 2 + overhang
    y = ly / 2
    slope = rise / y
    yo = y + overhang
    zo = -overhang * slope
    v = np.array([[-x, -yo, zo], [x, -yo, zo], [x, 0, rise], [-x, 0, rise], [x, yo, zo], [-x, yo, zo],
                  [-lx / 2, -y, 0], [-lx / 2, y, 0], [-lx / 2, 0, rise], [lx / 2, -y, 0], [lx / 2, y, 0], [lx / 2, 0, rise]], float)
    f = np.array([[0, 1, 2], [0, 2, 3], [3, 2, 4], [3, 4, 5], [6, 7, 8][::-1], [9, 11, 10][::-1]], np.int64)
    return v, f


def hip_roof(lx: float, ly: float, rise: float, overhang: float = 0.0):
    """Hipped roof over lx >= ly: four planes, ridge of length lx - ly along x."""
    x = lx / 2 + overhang
    y = ly / 2 + overhang
    slope = rise / (ly / 2)
    zo = -overhang * slope
    r = max(lx - ly, 0.0) / 2
    v = np.array([[-x, -y, zo], [x, -y, zo], [x, y, zo], [-x, y, zo], [-r, 0, rise], [r, 0, rise]], float)
    f = np.array([[0, 1, 5], [0, 5, 4], [1, 2, 5], [2, 3, 4], [2, 4, 5], [3, 0, 4]], np.int64)
    return v, f


def flat_plate(lx: float, ly: float, z: float = 0.0):
    """A horizontal rectangle (two triangles, facing up) centred on x, y at height z."""
    x, y = lx / 2, ly / 2
    return np.array([[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z]], float), np.array([[0, 1, 2], [0, 2, 3]], np.int64)


def disc(radius: float, z: float = 0.0, sides: int = 24, rx: float | None = None):
    """A horizontal ellipse (radius in y, ``rx`` in x) as a triangle fan facing up."""
    rx = radius if rx is None else rx
    a = np.linspace(0, 2 * np.pi, sides, endpoint=False)
    v = np.vstack([[0, 0, z], np.column_stack([rx * np.cos(a), radius * np.sin(a), np.full(sides, z)])])
    i = np.arange(sides)
    return v, np.stack([np.zeros(sides, np.int64), 1 + i, 1 + (i + 1) % sides], 1)


def tube(path: np.ndarray, radius: float, sides: int = 6, caps: bool = False):
    """A tube of circular cross-section (``sides``-gon) along a polyline ``path`` (k, 3).

    Used for trunks, columns and power-line conductors. Cross-sections are perpendicular to the
    local path direction.
    """
    path = np.asarray(path, float)
    k = len(path)
    tang = np.gradient(path, axis=0)
    tang /= np.linalg.norm(tang, axis=1, keepdims=True)
    ref = np.where(np.abs(tang[:, 2:3]) < 0.9, np.array([[0, 0, 1.0]]), np.array([[1.0, 0, 0]]))
    u = np.cross(tang, ref)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    w = np.cross(tang, u)
    a = np.linspace(0, 2 * np.pi, sides, endpoint=False)
    ring = np.cos(a)[None, :, None] * u[:, None, :] + np.sin(a)[None, :, None] * w[:, None, :]
    v = (path[:, None, :] + radius * ring).reshape(-1, 3)
    seg = np.arange(k - 1)[:, None]
    s = np.arange(sides)[None, :]
    a0 = seg * sides + s
    a1 = seg * sides + (s + 1) % sides
    b0, b1 = a0 + sides, a1 + sides
    f = np.concatenate([np.stack([a0, a1, b1], -1).reshape(-1, 3), np.stack([a0, b1, b0], -1).reshape(-1, 3)])
    if caps:
        c0, c1 = len(v), len(v) + 1
        v = np.vstack([v, path[0], path[-1]])
        i = np.arange(sides)
        f = np.concatenate([f, np.stack([np.full(sides, c0), (i + 1) % sides, i], 1),
                            np.stack([np.full(sides, c1), (k - 1) * sides + i, (k - 1) * sides + (i + 1) % sides], 1)])
    return v, f


def leaf_cloud(rng: np.random.Generator, centers: np.ndarray, size: float):
    """Randomly oriented small triangles (``size`` metres across) at ``centers`` (k, 3).

    A crown built from many such leaf clusters is porous: part of a laser footprint passes
    between them, so a beam with several sub-rays gives multiple returns.
    """
    k = len(centers)
    d = rng.normal(size=(k, 3, 3))
    d /= np.linalg.norm(d, axis=2, keepdims=True)
    v = (centers[:, None, :] + 0.5 * size * d).reshape(-1, 3)
    return v, np.arange(3 * k, dtype=np.int64).reshape(k, 3)
