"""Synthetic shapes for the registration tests (imported by file name, no package)."""

from __future__ import annotations

import numpy as np


def shape_points(n: int = 6000, seed: int = 0) -> np.ndarray:
    """Points on an asymmetric union of a box, a cylinder and a sphere (about 1 m across)."""
    import trimesh

    parts = [
        trimesh.creation.box(extents=(1.0, 0.6, 0.4)),
        trimesh.creation.cylinder(radius=0.15, height=0.5, transform=trimesh.transformations.translation_matrix((0.3, 0.1, 0.4))),
        trimesh.creation.icosphere(subdivisions=3, radius=0.18).apply_translation((-0.35, -0.15, 0.3)),
        trimesh.creation.box(extents=(0.2, 0.5, 0.2), transform=trimesh.transformations.translation_matrix((-0.1, 0.45, -0.1))),
    ]
    mesh = trimesh.util.concatenate(parts)
    pts, _ = trimesh.sample.sample_surface(mesh, n, seed=seed)
    return np.asarray(pts, dtype=np.float64)


def wavy_scene(n: int = 20000, seed: int = 0, size: float = 20.0) -> np.ndarray:
    """A terrain-like surface with two box buildings (metres), for multi-scan tests."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, size, n)
    y = rng.uniform(0, size, n)
    z = 0.6 * np.sin(x / 2.5) * np.cos(y / 3.0) + 0.2 * np.sin(x * y / 15.0)
    b1 = (np.abs(x - 6) < 2) & (np.abs(y - 7) < 3)
    b2 = (np.abs(x - 14) < 2.5) & (np.abs(y - 13) < 1.5)
    z = np.where(b1, 3.0, z)
    z = np.where(b2, 5.0 + 0.3 * (x - 14), z)
    return np.column_stack([x, y, z])
