"""Synthetic aerial photos with exact ground truth, for orthophoto tests and demos.

A scene is a terrain height field with box buildings; its colour is a procedural texture
``colour(X, Y)`` (smooth value noise + stripes + checker, rich enough for matching and for
measuring shifts), roofs carry their own tinted texture and walls a dark grey. Cameras fly a
grid at a given height with 60 % forward and 30 % side overlap, looking down with small
random tilts, and every image pixel is the colour of the first surface its ray hits (Open3D
``RaycastingScene``), averaged over 2×2 sub-pixel rays. The true orthophoto is the texture
seen from straight above (roof colour inside footprints), and the true DSM the first hit of a
vertical ray, both at any cell size: every product has an exact reference.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from workstation.core.products import Camera, Image, Pose, Raster, Reconstruction
from workstation.io.reconstruction import write_reconstruction_json
from workstation.photogrammetry.collinearity import camera_rays

from .grid import GridSpec


@dataclass(frozen=True)
class AerialScene:
    """A terrain with box buildings and a procedural texture.

    Attributes
    ----------
    size : float
        Side of the square scene in metres (origin at ``origin``).
    origin : (float, float)
        World (X, Y) of the south-west corner (e.g. UTM metres).
    buildings : tuple of (x0, y0, x1, y1, height)
        Footprints (metres, relative to the origin) and heights above the terrain centre.
    seed : int
    base_height : float
        Mean terrain height in metres.
    """

    size: float = 120.0
    origin: tuple = (500_000.0, 5_000_000.0)
    buildings: tuple = ((30.0, 35.0, 52.0, 55.0, 12.0), (70.0, 60.0, 90.0, 92.0, 18.0), (40.0, 80.0, 55.0, 95.0, 8.0))
    seed: int = 0
    base_height: float = 100.0
    crs: str = "EPSG:32632"

    # terrain ---------------------------------------------------------------
    def terrain(self, X, Y) -> np.ndarray:
        """Ground height (m) at world X, Y: a gentle tilt and two long waves."""
        x = np.asarray(X) - self.origin[0]
        y = np.asarray(Y) - self.origin[1]
        return self.base_height + 0.02 * x - 0.01 * y + 1.2 * np.sin(x / 25.0) * np.cos(y / 31.0)

    def footprints(self, X, Y) -> np.ndarray:
        """Index of the building whose footprint holds (X, Y), -1 elsewhere."""
        x = np.asarray(X) - self.origin[0]
        y = np.asarray(Y) - self.origin[1]
        out = np.full(np.shape(x), -1, np.int64)
        for k, (x0, y0, x1, y1, _) in enumerate(self.buildings):
            out[(x >= x0) & (x < x1) & (y >= y0) & (y < y1)] = k
        return out

    def roof_height(self, k: int) -> float:
        x0, y0, x1, y1, h = self.buildings[k]
        cx, cy = self.origin[0] + (x0 + x1) / 2, self.origin[1] + (y0 + y1) / 2
        return float(self.terrain(cx, cy)) + h

    # texture ---------------------------------------------------------------
    def _noise_grid(self, k: int, spacing: float) -> np.ndarray:
        rng = np.random.default_rng(self.seed * 1000 + k)
        n = int(self.size / spacing) + 3
        return rng.uniform(0, 1, (n, n))

    def _value_noise(self, x, y, k: int, spacing: float) -> np.ndarray:
        g = self._noise_grid(k, spacing)
        u = np.clip(x / spacing + 1, 0, g.shape[1] - 1.001)
        v = np.clip(y / spacing + 1, 0, g.shape[0] - 1.001)
        j, i = np.floor(u).astype(int), np.floor(v).astype(int)
        fu, fv = u - j, v - i
        fu, fv = fu * fu * (3 - 2 * fu), fv * fv * (3 - 2 * fv)  # smoothstep
        return (g[i, j] * (1 - fu) * (1 - fv) + g[i, j + 1] * fu * (1 - fv) + g[i + 1, j] * (1 - fu) * fv
                + g[i + 1, j + 1] * fu * fv)

    def ground_colour(self, X, Y) -> np.ndarray:
        """RGB in 0-1, shape (..., 3): fields of value noise, stripes and a checker of paths."""
        x = np.asarray(X, float) - self.origin[0]
        y = np.asarray(Y, float) - self.origin[1]
        n1 = self._value_noise(x, y, 1, 6.0)
        n2 = self._value_noise(x, y, 2, 2.5)
        stripes = 0.5 + 0.5 * np.sin(2 * np.pi * (0.6 * x + 0.8 * y) / 7.0)
        check = ((np.floor(x / 15.0) + np.floor(y / 15.0)) % 2)
        r = 0.25 + 0.45 * n1 + 0.2 * stripes * check
        g = 0.30 + 0.35 * n2 + 0.25 * (1 - check) * n1
        b = 0.15 + 0.30 * stripes * (1 - check) + 0.2 * n2
        return np.clip(np.stack([r, g, b], -1), 0, 1)

    def roof_colour(self, X, Y) -> np.ndarray:
        x = np.asarray(X, float) - self.origin[0]
        y = np.asarray(Y, float) - self.origin[1]
        n = self._value_noise(x, y, 3, 3.0)
        tiles = 0.5 + 0.5 * np.sin(2 * np.pi * y / 4.0)
        return np.clip(np.stack([0.75 + 0.2 * n, 0.05 + 0.1 * tiles, 0.1 + 0.1 * n], -1), 0, 1)

    WALL = (0.35, 0.35, 0.38)

    # geometry ---------------------------------------------------------------
    def mesh(self, spacing: float = 1.0):
        """(vertices (n, 3), triangles (m, 3), kind (m,) with 0 terrain, 1 roof, 2 wall)."""
        n = int(round(self.size / spacing)) + 1
        xs = self.origin[0] + np.linspace(-5, self.size + 5, n + 10)
        ys = self.origin[1] + np.linspace(-5, self.size + 5, n + 10)
        X, Y = np.meshgrid(xs, ys)
        V = np.column_stack([X.ravel(), Y.ravel(), self.terrain(X, Y).ravel()])
        nx = len(xs)
        i, j = np.mgrid[0 : len(ys) - 1, 0 : nx - 1]
        a = (i * nx + j).ravel()
        T = np.vstack([np.column_stack([a, a + 1, a + nx + 1]), np.column_stack([a, a + nx + 1, a + nx])])
        kinds = [np.zeros(len(T), np.int64)]
        verts, tris = [V], [T]
        base = len(V)
        for k, (x0, y0, x1, y1, _) in enumerate(self.buildings):
            ztop = self.roof_height(k)
            zb = float(self.terrain(self.origin[0] + np.array([x0, x1]), self.origin[1] + np.array([y0, y1])).min()) - 3.0
            ox, oy = self.origin
            c = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]) + [ox, oy]
            bv = np.vstack([np.column_stack([c, np.full(4, zb)]), np.column_stack([c, np.full(4, ztop)])])
            roof = np.array([[4, 5, 6], [4, 6, 7]])
            walls = np.array([[0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]])
            verts.append(bv)
            tris.append(np.vstack([roof, walls]) + base)
            kinds.append(np.r_[np.ones(2, np.int64), np.full(8, 2, np.int64)])
            base += 8
        return np.vstack(verts), np.vstack(tris), np.concatenate(kinds)

    def _raycaster(self):
        from workstation.interop.open3d_raycast import RaycastScene

        V, T, kind = self.mesh()
        # origin subtracted in float64, then cast: float32 steps are 0.5 m at a northing of 5e6
        return RaycastScene((V - self._o32().astype(np.float64)).astype(np.float32), T), kind

    def _o32(self) -> np.ndarray:
        """Origin subtracted before float32 ray casting (Open3D works in float32)."""
        return np.array([self.origin[0], self.origin[1], self.base_height], np.float32)

    def cast(self, origins: np.ndarray, dirs: np.ndarray, scene=None):
        """First hits of rays: (points (n, 3) world, kind (n,) 0/1/2, -1 for a miss)."""
        if scene is None:
            scene = self._raycaster()
        sc, kind = scene
        o = (origins - self._o32().astype(float)).astype(np.float32)
        t, prim = sc.cast_rays(np.hstack([o, dirs.astype(np.float32)]))
        t = t.astype(float)
        hit = np.isfinite(t)
        pts = origins + dirs * np.where(hit, t, 0)[:, None]
        k = np.full(len(t), -1, np.int64)
        k[hit] = kind[prim[hit]]
        return pts, k

    def colour_at(self, pts: np.ndarray, kind: np.ndarray) -> np.ndarray:
        """RGB 0-1 of surface points by their kind (terrain / roof / wall; miss = black)."""
        col = np.zeros((len(pts), 3))
        g = kind == 0
        col[g] = self.ground_colour(pts[g, 0], pts[g, 1])
        r = kind == 1
        col[r] = self.roof_colour(pts[r, 0], pts[r, 1])
        col[kind == 2] = self.WALL
        return col

    # references ---------------------------------------------------------------
    def grid(self, res: float) -> GridSpec:
        return GridSpec(self.origin[0], self.origin[1] + self.size, res, int(round(self.size / res)), int(round(self.size / res)))

    def true_dsm(self, res: float, scene=None) -> Raster:
        """First hit of a vertical ray at each cell centre (float32, metres)."""
        g = self.grid(res)
        X, Y = Raster(np.zeros(g.shape), g.transform).cell_centers()
        o = np.column_stack([X.ravel(), Y.ravel(), np.full(X.size, self.base_height + 500.0)])
        d = np.tile([0.0, 0.0, -1.0], (X.size, 1))
        pts, _ = self.cast(o, d, scene)
        return Raster(pts[:, 2].reshape(g.shape).astype(np.float32), g.transform, self.crs, -9999.0,
                      {"kind": "dsm", "source": "synthetic_aerial.true_dsm", "vertical_rmse": 0.0})

    def true_ortho(self, res: float) -> np.ndarray:
        """(rows, cols, 3) uint8: the texture seen from straight above at cell centres."""
        g = self.grid(res)
        X, Y = Raster(np.zeros(g.shape), g.transform).cell_centers()
        fp = self.footprints(X, Y)
        col = np.where((fp >= 0)[..., None], self.roof_colour(X, Y), self.ground_colour(X, Y))
        return np.round(col * 255).astype(np.uint8)


@dataclass(frozen=True)
class AerialRig:
    """A camera block flown over the scene.

    Attributes
    ----------
    height : float
        Flying height above the mean terrain in metres.
    width, height_px : int
        Image size in pixels.
    focal_px : float
        Focal length in pixels.
    forward_overlap, side_overlap : float
        Overlap fractions along and across track (0.6 / 0.3).
    tilt_deg : float
        Standard deviation of random roll/pitch in degrees.
    dist : tuple
        OpenCV distortion (k1, k2, p1, p2, k3) of every camera.
    supersample : int
        Rays per pixel side (2 -> 4 rays averaged per pixel).
    """

    height: float = 80.0
    width: int = 320
    height_px: int = 240
    focal_px: float = 300.0
    forward_overlap: float = 0.6
    side_overlap: float = 0.3
    tilt_deg: float = 1.5
    dist: tuple = (-0.05, 0.01, 0.0005, -0.0003, 0.0)
    supersample: int = 2
    seed: int = 0
    extra: dict = field(default_factory=dict)

    def camera(self) -> Camera:
        return Camera(self.width, self.height_px, self.focal_px, self.focal_px, (self.width - 1) / 2 + 3.0,
                      (self.height_px - 1) / 2 - 2.0, 0.0, tuple(self.dist), "OPENCV")

    def poses(self, scene: AerialScene) -> list[Pose]:
        """Camera poses on a grid covering the scene (flight lines along X)."""
        rng = np.random.default_rng(self.seed)
        fw = self.height * self.width / self.focal_px  # ground footprint along X (m)
        fh = self.height * self.height_px / self.focal_px  # across track (Y)
        dx = (1 - self.forward_overlap) * fw
        dy = (1 - self.side_overlap) * fh
        nx = max(1, math.ceil((scene.size - fw) / dx) + 1) if scene.size > fw else 1
        ny = max(1, math.ceil((scene.size - fh) / dy) + 1) if scene.size > fh else 1
        xs = scene.origin[0] + scene.size / 2 + (np.arange(nx) - (nx - 1) / 2) * dx
        ys = scene.origin[1] + scene.size / 2 + (np.arange(ny) - (ny - 1) / 2) * dy
        Rn = np.diag([1.0, -1.0, -1.0])  # camera x east, y south, z down
        poses = []
        for y in ys:
            for x in xs:
                a, b, c = np.radians(rng.normal(0, self.tilt_deg, 3))
                Rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
                Ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
                Rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
                R = Rx @ Ry @ Rz @ Rn
                C = np.array([x, y, scene.base_height + self.height])
                poses.append(Pose(R, -R @ C))
        return poses


def render_image(scene: AerialScene, camera: Camera, pose: Pose, supersample: int = 2, caster=None, rays=None) -> np.ndarray:
    """(h, w, 3) uint8 photo of the scene by ray casting (sub-pixel rays averaged).

    ``rays``: :func:`workstation.photogrammetry.collinearity.camera_rays` of the camera, to
    reuse across images.
    """
    d_cam = camera_rays(camera, supersample) if rays is None else rays
    flat = d_cam.reshape(-1, 3) @ np.asarray(pose.R)  # R^T d for each row: camera -> world
    c = pose.center
    pts, kind = scene.cast(np.broadcast_to(c, flat.shape), flat, caster)
    col = scene.colour_at(pts, kind).reshape(camera.height, supersample, camera.width, supersample, 3).mean((1, 3))
    return np.round(col * 255).astype(np.uint8)


def make_dataset(outdir, scene: AerialScene = AerialScene(), rig: AerialRig = AerialRig()) -> Path:
    """Render the rig's images into ``outdir/images`` and write ``outdir/cameras.json``.

    Returns
    -------
    Path
        The cameras JSON (readable by :func:`workstation.photogrammetry.sfm.read_reconstruction`).
    """
    import cv2

    from workstation.io import atomic_path

    out = Path(outdir)
    (out / "images").mkdir(parents=True, exist_ok=True)
    cam = rig.camera()
    caster = scene._raycaster()
    rays = camera_rays(cam, rig.supersample)
    images = {}
    for k, pose in enumerate(rig.poses(scene), start=1):
        img = render_image(scene, cam, pose, rig.supersample, caster, rays)
        name = f"img_{k:03d}.png"
        with atomic_path(out / "images" / name, overwrite=True) as tmp:
            cv2.imwrite(str(tmp), img[:, :, ::-1])
        images[k] = Image(name, 1, pose, str(Path("images") / name))
    rec = Reconstruction({1: cam}, images, crs=scene.crs, meta={"reprojection_rmse_px": 0.0, "synthetic": True})
    return write_reconstruction_json(rec, out / "cameras.json", overwrite=True)


__all__ = ["AerialScene", "AerialRig", "render_image", "make_dataset"]
