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
    """A terrain of Gaussian hills with six box buildings of different sizes and heights
    (metres); the geometry is fixed, ``seed`` only changes the sampling."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, size, n)
    y = rng.uniform(0, size, n)
    geo = np.random.default_rng(1234)
    z = np.zeros(n)
    for _ in range(8):
        cx, cy = geo.uniform(0, size, 2)
        h, s = geo.uniform(-1.0, 1.5), geo.uniform(1.5, 4.0)
        z += h * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s))
    for cx, cy, hx, hy, h in [(4, 5, 1.5, 2.5, 3.0), (14, 4, 2.5, 1.0, 5.0), (10, 11, 1.0, 1.0, 7.0),
                              (5, 15, 2.0, 1.2, 4.0), (16, 15, 1.2, 2.2, 2.5), (9, 2, 0.8, 0.8, 6.0)]:
        inside = (np.abs(x - cx) < hx) & (np.abs(y - cy) < hy)
        z = np.where(inside, h + 0.15 * (x - cx), z)
    return np.column_stack([x, y, z])


def block_mesh():
    """A small built-up block as one triangle mesh: ground 80 m x 60 m, six buildings, a tower."""
    import trimesh

    T = trimesh.transformations.translation_matrix
    parts = [trimesh.creation.box(extents=(80, 60, 0.2), transform=T((40, 30, -0.1)))]
    for (x, y, lx, ly, h, yaw) in [(15, 12, 10, 7, 8, 0.0), (32, 10, 6, 12, 12, 0.3), (50, 14, 14, 6, 6, -0.2),
                                   (20, 40, 8, 12, 15, 0.1), (45, 42, 10, 10, 9, 0.6), (62, 30, 6, 16, 5, 0.0)]:
        M = trimesh.transformations.rotation_matrix(yaw, (0, 0, 1))
        M[:3, 3] = (x, y, h / 2)
        parts.append(trimesh.creation.box(extents=(lx, ly, h), transform=M))
    parts.append(trimesh.creation.cylinder(radius=1.5, height=20, transform=T((36, 27, 10))))
    return trimesh.util.concatenate(parts)


def tls_station(mesh, position, step_deg: float = 0.5, max_range: float = 60.0, noise: float = 0.003,
                seed: int = 0, azimuth_deg=(0.0, 360.0), elevation_deg=(-60.0, 60.0)) -> np.ndarray:
    """Points a terrestrial scanner at ``position`` sees on ``mesh`` (Open3D ray casting) over
    the given azimuth and elevation ranges (degrees), with Gaussian range noise (metres)."""
    import open3d as o3d

    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.core.Tensor(np.asarray(mesh.vertices, np.float32)),
                        o3d.core.Tensor(np.asarray(mesh.faces, np.uint32)))
    az, el = np.meshgrid(np.radians(np.arange(*azimuth_deg, step_deg)), np.radians(np.arange(*elevation_deg, step_deg)))
    d = np.column_stack([(np.cos(el) * np.cos(az)).ravel(), (np.cos(el) * np.sin(az)).ravel(), np.sin(el).ravel()])
    rays = np.hstack([np.tile(np.asarray(position, np.float32), (d.shape[0], 1)), d]).astype(np.float32)
    t = scene.cast_rays(o3d.core.Tensor(rays))["t_hit"].numpy()
    ok = np.isfinite(t) & (t < max_range)
    rng = np.random.default_rng(seed)
    r = t[ok] + rng.normal(0, noise, ok.sum())
    return np.asarray(position, float) + d[ok] * r[:, None]
