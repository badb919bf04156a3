"""Synthetic photo rigs with exact ground truth: textured scene meshes seen by pinhole cameras.

A rig renders a scene of the LiDAR simulator (:func:`workstation.lidar.scene.build_scene`) by
ray casting (Open3D ``RaycastingScene``, as :mod:`workstation.raster.synthetic_aerial` does):
every pixel is the colour of the first surface hit by its exact pinhole ray (through the
distorted pixel when the camera has radial distortion), averaged over ``supersample²``
sub-pixel rays. The surface colour is the face's albedo times a procedural texture that is a
function of the 3-D hit point only (so it is the same in every view): multi-scale value noise
(2 m … 5 cm), stone courses with mortar joints on walls, and a fixed-sun Lambertian shade.
That gives SIFT plenty of texture and makes every product checkable against the true mesh.

Layouts (textbook advice for close range: convergent views 10-15° apart, Luhmann et al.,
*Close-Range Photogrammetry and 3D Imaging*, 2014, §7.3):

- ``ring``: cameras on a circle around the target at one height, looking at its centre;
- ``convergent``: two rings at two heights with the upper one offset by half a step;
- ``grid``: nadir aerial block with forward overlap and side-lap.

Each rig stores ``images/*.png``, ``cameras.json`` (core convention), a COLMAP text model
``sparse/0/{cameras,images,points3D}.txt`` with the true cameras, and the true mesh
``truth_mesh.npz`` (local coordinates, see :class:`RigResult`).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, fields
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Image, Pose, Reconstruction
from workstation.io.textfile import read_text

from .collinearity import camera_rays

log = get_logger(__name__)

LAYOUTS = ("ring", "convergent", "grid")


@dataclass(frozen=True)
class RigSpec:
    """A camera rig around (or above) a scene target.

    Attributes
    ----------
    layout : str
        "ring", "convergent" or "grid" (see the module docstring).
    n_images : int
        Images for "ring"/"convergent" (the step is 360° / images per ring).
    width, height : int
        Image size, pixels.
    focal_px : float
        Focal length, pixels.
    dist : tuple of float
        OpenCV distortion (k1, k2, p1, p2, k3) applied to every image (zeros: ideal pinhole).
    distance : float
        Camera distance from the target centre (ring) in metres; flying height above the
        target base for "grid".
    camera_height : float
        Camera height above the target base for "ring" (metres); the upper ring of
        "convergent" is at ``2 * camera_height``.
    look_height : float
        Height above the target base of the point the cameras look at, metres.
    forward_overlap, side_overlap : float
        Grid overlaps (0-1).
    terrain_radius : float
        Terrain faces farther than this from the target centre (metres) are dropped.
    context : bool
        Also keep the scene's other objects (buildings, trees, cars...) within
        ``terrain_radius``; by default only the target and the terrain are rendered.
    supersample : int
        Sub-pixel rays per pixel side.
    target : str
        Object kind of the scene that the rig looks at ("heritage_church").
    seed : int
        Scene seed.
    """

    layout: str = "convergent"
    n_images: int = 24
    width: int = 640
    height: int = 480
    focal_px: float = 560.0
    dist: tuple = (0.0, 0.0, 0.0, 0.0, 0.0)
    distance: float = 55.0
    camera_height: float = 10.0
    look_height: float = 10.0
    forward_overlap: float = 0.8
    side_overlap: float = 0.6
    terrain_radius: float = 40.0
    context: bool = False
    supersample: int = 2
    target: str = "heritage_church"
    seed: int = 0

    def __post_init__(self):
        if self.layout not in LAYOUTS:
            raise InvalidInputError(f"layout must be one of {LAYOUTS}", field="layout")
        if self.n_images < 2 or self.width < 8 or self.height < 8 or self.focal_px <= 0:
            raise InvalidInputError("a rig needs ≥ 2 images of ≥ 8×8 px and a positive focal length")

    def camera(self) -> Camera:
        d = tuple(float(x) for x in (list(self.dist) + [0.0] * 5)[:5])
        model = "OPENCV" if any(d) else "PINHOLE"
        return Camera(self.width, self.height, self.focal_px, self.focal_px, (self.width - 1) / 2,
                      (self.height - 1) / 2, 0.0, d, model)


@dataclass(frozen=True)
class RigResult:
    """A rendered rig.

    Attributes
    ----------
    folder : Path
    reconstruction : Reconstruction
        True cameras and poses (local frame: metres from ``origin``).
    vertices : (n, 3) float64
        True mesh vertices, local frame (metres).
    faces : (m, 3) int64
    origin : (3,) float64
        Map coordinates of the local origin.
    extent : float
        Diagonal of the target's bounding box, metres (the scale of the accuracy goals).
    target_faces : (m,) bool
        Faces of the target object (the rest is terrain and, with ``context``, other objects).
    """

    folder: Path
    reconstruction: Reconstruction
    vertices: np.ndarray
    faces: np.ndarray
    origin: np.ndarray
    extent: float
    target_faces: np.ndarray = field(repr=False, default=None)


def load_rig(path) -> tuple:
    """(SceneRecipe, RigSpec) of a rig recipe TOML: a ``[scene]`` table as for the simulator and
    a ``[rig]`` table of :class:`RigSpec` keys."""
    from workstation.lidar.scene import load_recipe

    p = Path(path)
    if not p.exists():
        p = Path(__file__).resolve().parents[2] / "datasets_synth" / f"{path}.toml"
    if not p.exists():
        raise InvalidInputError("rig recipe not found", "give a TOML path or a datasets_synth/rig_*.toml name", path=path)
    data = tomllib.loads(read_text(p))
    names = {f.name for f in fields(RigSpec)}
    kw = {}
    for k, v in data.get("rig", {}).items():
        if k not in names:
            raise InvalidInputError(f"unknown key '{k}' in [rig]", "keys: " + ", ".join(sorted(names)), field=k, path=p)
        kw[k] = tuple(v) if isinstance(v, list) else v
    return load_recipe(p), RigSpec(**kw)


# ---------------------------------------------------------------------------------------------
# texture
# ---------------------------------------------------------------------------------------------
def _hash3(i, j, k, salt: int) -> np.ndarray:
    """Deterministic pseudo-random values in [0, 1) on an integer lattice (int64 mixing)."""
    h = (i * 73856093) ^ (j * 19349663) ^ (k * 83492791) ^ (salt * 2654435761)
    h = (h ^ (h >> 13)) * 1274126177
    h = h ^ (h >> 16)
    return (h & 0xFFFFFF).astype(np.float64) / float(0x1000000)


def value_noise3(p: np.ndarray, spacing: float, salt: int) -> np.ndarray:
    """Smooth 3-D value noise in [0, 1] at points ``p`` (n, 3), lattice ``spacing`` metres."""
    q = p / spacing
    i0 = np.floor(q).astype(np.int64)
    f = q - i0
    f = f * f * (3 - 2 * f)
    out = np.zeros(len(p))
    for dx in (0, 1):
        wx = f[:, 0] if dx else 1 - f[:, 0]
        for dy in (0, 1):
            wy = f[:, 1] if dy else 1 - f[:, 1]
            for dz in (0, 1):
                wz = f[:, 2] if dz else 1 - f[:, 2]
                out += wx * wy * wz * _hash3(i0[:, 0] + dx, i0[:, 1] + dy, i0[:, 2] + dz, salt)
    return out


def surface_colour(p: np.ndarray, normal: np.ndarray, albedo: np.ndarray) -> np.ndarray:
    """RGB in 0-1 (n, 3) of surface points ``p`` (n, 3, metres) with unit face normals and
    albedo (n, 3) in 0-1: multi-scale noise, stone courses on steep faces, Lambertian shade."""
    n = (0.35 * value_noise3(p, 2.0, 1) + 0.3 * value_noise3(p, 0.5, 2) + 0.2 * value_noise3(p, 0.17, 3)
         + 0.15 * value_noise3(p, 0.06, 4))
    tex = 0.35 + 0.9 * n
    steep = np.abs(normal[:, 2]) < 0.5
    course = 0.35  # stone course height (m)
    row = np.floor(p[:, 2] / course)
    along = (p[:, 0] + p[:, 1]) / 0.7 + 0.5 * (row % 2)
    mortar = steep & ((p[:, 2] / course - row < 0.1) | (along - np.floor(along) < 0.06))
    tex = np.where(mortar, 0.45 + 0.2 * value_noise3(p, 0.1, 5), tex)
    sun = np.array([0.45, -0.35, 0.82])
    shade = 0.55 + 0.45 * np.abs(normal @ (sun / np.linalg.norm(sun)))
    tint = 0.9 + 0.2 * value_noise3(p, 1.0, 6)
    col = albedo * (tex * shade * tint)[:, None]
    return np.clip(col, 0, 1)


# ---------------------------------------------------------------------------------------------
# cameras
# ---------------------------------------------------------------------------------------------
def look_at(center: np.ndarray, target: np.ndarray, up=(0.0, 0.0, 1.0)) -> Pose:
    """World → camera pose of a camera at ``center`` looking at ``target`` (x right, y down, z
    forward)."""
    z = np.asarray(target, float) - np.asarray(center, float)
    z /= np.linalg.norm(z)
    x = np.cross(z, np.asarray(up, float))
    if np.linalg.norm(x) < 1e-9:  # looking straight down/up
        x = np.array([1.0, 0.0, 0.0])
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    R = np.vstack([x, y, z])
    return Pose(R, -R @ np.asarray(center, float))


def rig_poses(spec: RigSpec, centre: np.ndarray, size: np.ndarray) -> list[Pose]:
    """Poses of the rig's cameras around a target at ``centre`` (x, y, base z) of ``size``."""
    c = np.asarray(centre, float)
    look = c + [0.0, 0.0, spec.look_height]
    poses = []
    if spec.layout in ("ring", "convergent"):
        rings = [(spec.camera_height, 0.0)]
        if spec.layout == "convergent":
            rings = [(spec.camera_height, 0.0), (2.0 * spec.camera_height, 0.5)]
        per = math.ceil(spec.n_images / len(rings))
        k = 0
        for h, off in rings:
            for i in range(per):
                if k >= spec.n_images:
                    break
                a = 2 * math.pi * (i + off) / per
                C = c + [spec.distance * math.cos(a), spec.distance * math.sin(a), h]
                poses.append(look_at(C, look))
                k += 1
    else:
        fw = spec.distance * spec.width / spec.focal_px
        fh = spec.distance * spec.height / spec.focal_px
        dx, dy = (1 - spec.forward_overlap) * fw, (1 - spec.side_overlap) * fh
        nx = max(2, math.ceil((size[0] + fw * 0.5) / dx))
        ny = max(1, math.ceil((size[1] + fh * 0.5) / dy))
        Rn = np.diag([1.0, -1.0, -1.0])
        for j in range(ny):
            for i in range(nx):
                C = c + [(i - (nx - 1) / 2) * dx, (j - (ny - 1) / 2) * dy, spec.distance]
                poses.append(Pose(Rn, -Rn @ C))
    return poses


# ---------------------------------------------------------------------------------------------
# rendering
# ---------------------------------------------------------------------------------------------
def _target_scene(recipe, spec: RigSpec):
    """(vertices, faces, albedo 0-1 per face, target mask, origin) cropped around the target."""
    from workstation.lidar.scene import build_scene

    scene = build_scene(recipe, spec.seed)
    ids = [int(k) for k, v in scene.meta.get("objects", {}).items() if v == spec.target]
    if not ids:
        raise InvalidInputError(f"the scene has no '{spec.target}' object",
                                "use a recipe with heritage = true (or another target kind)", field="target")
    tmask = np.isin(scene.object_id, ids)
    V = scene.vertices
    tv = V[np.unique(scene.faces[tmask])]
    centre = np.r_[(tv.min(0)[:2] + tv.max(0)[:2]) / 2, tv[:, 2].min()]
    cen = V[scene.faces].mean(1)
    near = np.hypot(*(cen[:, :2] - centre[:2]).T) < spec.terrain_radius
    keep = tmask | (near & ((scene.object_id == 0) | bool(spec.context)))
    faces = scene.faces[keep]
    used, inv = np.unique(faces, return_inverse=True)
    faces = inv.reshape(-1, 3).astype(np.int64)
    return V[used], faces, scene.face_rgb[keep] / 255.0, tmask[keep], scene.origin, centre, tv.max(0) - tv.min(0)


def render(vertices, faces, albedo, camera: Camera, pose: Pose, supersample: int = 2, caster=None, rays=None) -> np.ndarray:
    """(h, w, 3) uint8 image of a textured mesh by ray casting (first hit, sub-pixel average).

    ``rays``: camera-frame unit rays (h·s, w·s, 3) from
    :func:`workstation.photogrammetry.collinearity.camera_rays`; background (misses) is sky grey.
    """
    from workstation.interop.open3d_raycast import RaycastScene

    caster = caster or RaycastScene(vertices, faces)
    d_cam = camera_rays(camera, supersample) if rays is None else rays
    d = d_cam.reshape(-1, 3) @ np.asarray(pose.R)
    o = np.broadcast_to(pose.center, d.shape)
    t, prim = caster.cast(o, d)
    hit = prim >= 0
    col = np.empty((len(d), 3))
    col[:] = (0.72, 0.8, 0.9)
    p = o[hit] + d[hit] * t[hit, None].astype(float)
    tri = vertices[faces[prim[hit]]]
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1, keepdims=True) + 1e-12
    col[hit] = surface_colour(p, nrm, albedo[prim[hit]])
    s = supersample
    img = col.reshape(camera.height, s, camera.width, s, 3).mean((1, 3))
    return np.round(img * 255).astype(np.uint8)


def write_colmap_text(rec: Reconstruction, folder) -> Path:
    """Write the true cameras as a COLMAP text model (``cameras/images/points3D.txt``) through
    pycolmap."""
    from workstation.interop.pycolmap import camera_to_pycolmap, import_pycolmap

    pycolmap = import_pycolmap()
    r = pycolmap.Reconstruction()
    for cid, cam in rec.cameras.items():
        r.add_camera_with_trivial_rig(camera_to_pycolmap(cam, int(cid)))
    for iid, im in rec.images.items():
        pim = pycolmap.Image()
        pim.image_id = int(iid)
        pim.camera_id = int(im.camera_id)
        pim.name = im.name
        T = pycolmap.Rigid3d(pycolmap.Rotation3d(np.asarray(im.pose.R, float)), np.asarray(im.pose.t, float))
        r.add_image_with_trivial_frame(pim, T)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    r.write_text(str(folder))
    return folder


def make_rig(recipe, spec: RigSpec, outdir, overwrite: bool = False) -> RigResult:
    """Render a rig into ``outdir`` (``images/``, ``cameras.json``, ``sparse/0`` text model,
    ``truth_mesh.npz``). Deterministic for a recipe and spec.

    Returns
    -------
    RigResult
    """
    import cv2

    from workstation.core.progress import track
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.io import atomic_path
    from workstation.io.reconstruction import write_reconstruction_json

    out = Path(outdir)
    if (out / "images").exists() and any((out / "images").iterdir()) and not overwrite:
        from workstation.core.errors import OutputExistsError

        raise OutputExistsError(out / "images")
    (out / "images").mkdir(parents=True, exist_ok=True)
    V, F, alb, tmask, origin, centre, size = _target_scene(recipe, spec)
    cam = spec.camera()
    caster = RaycastScene(V, F)
    rays = camera_rays(cam, spec.supersample)
    images = {}
    for k, pose in enumerate(track(rig_poses(spec, centre, size), "render rig", unit="views"), start=1):
        img = render(V, F, alb, cam, pose, spec.supersample, caster, rays)
        name = f"img_{k:03d}.png"
        with atomic_path(out / "images" / name, overwrite=True) as tmp:
            if not cv2.imwrite(str(tmp), img[:, :, ::-1]):
                raise StageError("rigs", f"could not write {name}")
        images[k] = Image(name, 1, pose, str(Path("images") / name))
    tv = V[np.unique(F[tmask])]
    extent = float(np.linalg.norm(tv.max(0) - tv.min(0)))
    rec = Reconstruction({1: cam}, images, meta={"synthetic": True, "extent_m": extent})
    write_reconstruction_json(rec, out / "cameras.json", overwrite=True)
    write_colmap_text(rec, out / "sparse" / "0")
    with atomic_path(out / "truth_mesh.npz", overwrite=True) as tmp, open(tmp, "wb") as fh:
        np.savez_compressed(fh, vertices=V, faces=F, target=tmask, origin=origin, extent=extent)
    log.info("rig %s: %d images %dx%d, target extent %.1f m", spec.layout, len(images), cam.width, cam.height, extent)
    return RigResult(out, rec, V, F, origin, extent, tmask)


def box_wall_scene(boxes: tuple[float, ...] = (0.0,)) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A compact test scene: a 16 × 12 m textured wall at y = 12 m and 2 m boxes in front of it
    (y 8-10 m), centred at x = ``boxes`` (one, at 0, by default), z up. Returns (vertices
    (n, 3), faces (m, 3), albedo (m, 3) in 0-1)."""
    V = [[-8, 12, -5], [8, 12, -5], [8, 12, 7], [-8, 12, 7]]
    F = [[0, 1, 2], [0, 2, 3]]
    corners = np.array([[x, y, z] for z in (-1, 1) for y in (8, 10) for x in (-1, 1)], float)
    for cx in boxes:
        o = len(V)
        V = np.vstack([V, corners + [cx, 0.0, 0.0]])
        for a, bb, c, dd in [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]:
            F += [[o + a, o + bb, o + c], [o + a, o + c, o + dd]]
    F = np.asarray(F, np.int64)
    return np.asarray(V, float), F, np.full((len(F), 3), 0.8)


def wall_strip(folder, names: list[str], boxes: tuple[float, ...] = (0.0,)) -> tuple[Camera, dict]:
    """Render :func:`box_wall_scene` (boxes at x = ``boxes``) from ``len(names)`` cameras
    evenly spaced along a 12 m strip (x -6 to 6 m, every other one 0.4 m higher), each looking
    straight at the wall 12 m away through a 256x192 px, 23° view (4.8 m of wall), into
    ``folder/NAME``, the k-th camera of the strip under ``names[k]``. Views more than 11 places
    apart see no common wall; with the one central box the views at either end see only the
    flat wall, where a narrow view barely tells a sideways step from a turn. Returns the
    camera and each name's true centre."""
    import cv2

    V, F, alb = box_wall_scene(boxes)
    cam = Camera(256, 192, 640.0, 640.0, 127.5, 95.5, 0.0, (0.0,) * 5, "PINHOLE")
    rays = camera_rays(cam, 1)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    centres = {}
    for k, (x, name) in enumerate(zip(np.linspace(-6.0, 6.0, len(names)), names)):
        c = np.array([x, 0.0, 0.4 * (k % 2)])
        image = render(V, F, alb, cam, look_at(c, c + [0.0, 12.0, 0.0]), 1, rays=rays)
        cv2.imwrite(str(folder / name), image[:, :, ::-1])
        centres[name] = c
    return cam, centres


def box_wall_rig(folder, n: int = 5, width: int = 160, height: int = 120, focal_px: float = 150.0,
                 dist=(0.0, 0.0, 0.0, 0.0, 0.0)) -> Reconstruction:
    """Render :func:`box_wall_scene` from ``n`` cameras on a 5 m baseline looking at the box into
    ``folder/images`` and write the true cameras as ``folder/sparse/0`` (a tiny rig for tests
    and the demo; depth range 5-20 m). ``dist``: OpenCV (k1, k2, p1, p2, k3) applied to the
    images (the model is then OPENCV)."""
    import cv2

    V, F, alb = box_wall_scene()
    d = tuple(float(x) for x in (list(dist) + [0.0] * 5)[:5])
    cam = Camera(width, height, focal_px, focal_px, (width - 1) / 2, (height - 1) / 2, 0.0, d,
                 "OPENCV" if any(d) else "PINHOLE")
    rays = camera_rays(cam, 2)
    folder = Path(folder)
    (folder / "images").mkdir(parents=True, exist_ok=True)
    images = {}
    for k, x in enumerate(np.linspace(-2.5, 2.5, n), start=1):
        pose = look_at(np.array([x, 0.0, 0.5 * ((k - 1) % 2)]), np.array([0.0, 10.0, 0.0]))
        cv2.imwrite(str(folder / "images" / f"im{k}.png"), render(V, F, alb, cam, pose, 2, rays=rays)[:, :, ::-1])
        images[k] = Image(f"im{k}.png", 1, pose)
    rec = Reconstruction({1: cam}, images)
    write_colmap_text(rec, folder / "sparse" / "0")
    return rec


def load_truth(folder) -> dict:
    """The true mesh of a rendered rig: ``vertices``, ``faces``, ``target``, ``origin``, ``extent``."""
    with np.load(Path(folder) / "truth_mesh.npz") as z:
        return {k: z[k] for k in z.files}


__all__ = [
    "LAYOUTS",
    "RigResult",
    "RigSpec",
    "box_wall_rig",
    "box_wall_scene",
    "wall_strip",
    "load_rig",
    "load_truth",
    "look_at",
    "make_rig",
    "render",
    "rig_poses",
    "surface_colour",
    "value_noise3",
    "write_colmap_text",
]
