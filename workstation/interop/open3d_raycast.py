"""Ray casting and closest-point queries against a triangle mesh with Open3D's
``t.geometry.RaycastingScene`` (Embree): the library's one place that builds such a scene.

The mesh's local coordinates (metres from a local origin, e.g. the scene origin of
:class:`workstation.lidar.scene.Scene` or the mesh's centre) are converted to float32 here;
callers pass rays and query points in that same local frame, never absolute map coordinates,
so float32 keeps sub-millimetre precision over a few kilometres.
"""

from __future__ import annotations

import numpy as np

from workstation.core.errors import MissingDependencyError


def _o3d():
    try:
        import open3d as o3d
    except ImportError:  # pragma: no cover - open3d is a dependency
        raise MissingDependencyError("open3d", "ray casting the LiDAR simulator") from None
    return o3d


class RaycastScene:
    """First-hit ray casting and closest-point queries against one triangle mesh.

    Parameters
    ----------
    vertices : (n, 3) float
        Local coordinates (m); converted to float32.
    faces : (m, 3) int
        Triangle indices.
    nthreads : int
        Embree threads (0 = all cores).
    """

    def __init__(self, vertices: np.ndarray, faces: np.ndarray, nthreads: int = 0):
        o3d = _o3d()
        self._o3c = o3d.core
        self.scene = o3d.t.geometry.RaycastingScene()
        v = o3d.core.Tensor(np.ascontiguousarray(vertices, np.float32))
        f = o3d.core.Tensor(np.ascontiguousarray(faces, np.uint32))
        self.scene.add_triangles(v, f)
        self.nthreads = int(nthreads)
        self.n_faces = int(len(faces))

    def cast(self, origins: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distance to the first hit and the hit triangle for each ray.

        Parameters
        ----------
        origins, directions : (n, 3) float
            Ray origins (local m) and unit directions.

        Returns
        -------
        t_hit : (n,) float32
            Range along the (unit) direction in metres; ``inf`` for a miss.
        prim : (n,) int64
            Hit triangle index; -1 for a miss.
        """
        rays = np.empty((len(origins), 6), np.float32)
        rays[:, :3] = origins
        rays[:, 3:] = directions
        return self.cast_rays(rays)

    def cast_rays(self, rays: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Like :meth:`cast` for a prepared (n, 6) float32 array [ox, oy, oz, dx, dy, dz]."""
        out = self.scene.cast_rays(self._o3c.Tensor.from_numpy(np.ascontiguousarray(rays, np.float32)),
                                   nthreads=self.nthreads)
        t = out["t_hit"].numpy()
        prim = out["primitive_ids"].numpy().astype(np.int64)
        prim[~np.isfinite(t)] = -1
        return t, prim

    def closest(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Nearest point of the mesh's surface to each query point, and its triangle.

        Parameters
        ----------
        points : (n, 3) float
            Query points (local m); converted to float32.

        Returns
        -------
        nearest : (n, 3) float32
            Closest surface point (local m).
        prim : (n,) int64
            Triangle holding it.
        """
        q = self._o3c.Tensor.from_numpy(np.ascontiguousarray(points, np.float32))
        out = self.scene.compute_closest_points(q, nthreads=self.nthreads)
        return out["points"].numpy(), out["primitive_ids"].numpy().astype(np.int64)

    def distance(self, points: np.ndarray) -> np.ndarray:
        """Unsigned distance (n,) float32 from each query point (n, 3) (local m; converted to
        float32) to the mesh's surface."""
        q = self._o3c.Tensor.from_numpy(np.ascontiguousarray(points, np.float32))
        return self.scene.compute_distance(q, nthreads=self.nthreads).numpy()
