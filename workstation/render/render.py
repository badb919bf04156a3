"""Off-screen renders of clouds and meshes with pyvista/VTK (no display needed).

Colour by RGB, ASPRS classification (standard palette and a legend), elevation, intensity,
height above ground or any attribute; eye-dome lighting for clouds (Boucheny, "Interactive
scientific visualization of large datasets", PhD thesis 2009); views ``top`` (orthographic,
north up, scale bar), ``front`` (looking north), ``iso`` (30° above the horizon, from the
south-east, facing the longer vertical side of the bounding box: 30° off its normal), or an
exact pinhole camera (:class:`~workstation.core.products.Camera` + ``Pose``), the projection
matrix being built from the intrinsics so a world point lands on the pixel ``K [R|t]`` gives.
Renders are deterministic for a given input, view and size.

The fitted views frame the model's bounding box, stray points left out
(:func:`framing_bounds`): floating outliers of a photogrammetric cloud, far from the model,
would otherwise shrink it to a small blob in the middle of the frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from workstation.core.classes import CLASS_COLORS, class_colors, class_name
from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_u8
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Mesh, Pose, Reconstruction
from workstation.io.crs import crs_units

log = get_logger(__name__)

VIEWS = ("top", "front", "iso")
NAMED_COLORS = ("auto", "texture", "rgb", "class", "classification", "elevation", "intensity", "hag", "uniform")


@dataclass(frozen=True)
class RenderParams:
    """Render settings.

    Attributes
    ----------
    size : (int, int)
        Image width and height in pixels.
    color : str
        ``auto`` (a mesh's texture, else rgb, else classification, else elevation),
        ``texture`` (a textured mesh's image, unlit), ``rgb``, ``class``,
        ``elevation``, ``intensity``, ``hag``, ``uniform`` or the name of any attribute.
    view : {"top", "front", "iso"}
        Ignored when a camera is given.
    background : str
        Colour name or ``#rrggbb``.
    point_size : float
        Point diameter in pixels (clouds); 0 = from the density, so that points about cover
        the object's footprint (1-8 px).
    edl : bool
        Eye-dome lighting for clouds: shades depth discontinuities so shapes read without
        normals (best on dense clouds seen from the side; on sparse clouds it outlines every
        point).
    legend : bool
        Class legend (class colouring) or scalar bar (scalar colouring).
    scale_bar : bool
        Scale bar and north mark in the ``top`` view.
    cmap : str or None
        Matplotlib colour map for scalars (None: ``viridis``; ``gray`` for intensity).
    clip_percent : float
        Scalar colour range clipped to [p, 100 - p] percentiles (percent).
    max_points : int
        Clouds above this are drawn from a seeded random subset (count; 0 = all).
    margin : float
        Space around the object in ``top``/``front``/``iso`` views (fraction of its size).
    stray_share : float
        Framing (``top``/``front``/``iso`` and turntables) leaves out groups of points holding
        less than this share of the points (fraction) that an empty gap separates from the
        rest (:func:`framing_bounds`); 0 frames every point.
    """

    size: tuple[int, int] = (1024, 768)
    color: str = "auto"
    view: str = "iso"
    background: str = "white"
    point_size: float = 0.0
    edl: bool = False
    legend: bool = True
    scale_bar: bool = True
    cmap: str | None = None
    clip_percent: float = 2.0
    max_points: int = 0
    margin: float = 0.05
    stray_share: float = 0.005

    def __post_init__(self):
        w, h = self.size
        if not (16 <= int(w) <= 8192 and 16 <= int(h) <= 8192):
            raise InvalidInputError(f"size {self.size} out of 16..8192 pixels", field="size")
        if self.view not in VIEWS:
            raise InvalidInputError(f"unknown view '{self.view}'", "use " + ", ".join(VIEWS), field="view")
        if not 0 <= self.clip_percent < 50:
            raise InvalidInputError("clip_percent must be in [0, 50)", field="clip_percent")
        if not 0 <= self.stray_share < 0.5:
            raise InvalidInputError("stray_share must be in [0, 0.5)", field="stray_share")


def _nice_length(x: float) -> float:
    """Largest 1, 2 or 5 × 10^k not above x."""
    if x <= 0:
        return 0.0
    e = math.floor(math.log10(x))
    for m in (5, 2, 1):
        if m * 10 ** e <= x:
            return m * 10 ** e
    return 10 ** e


def _metre_label(units) -> str:
    """Unit label of lengths shown in metres: "m", or "m, no CRS" when metres are assumed."""
    return "m" if units.known else "m, no CRS"


def scale_bar(units_per_px: float, width_px: int, units, centre_y: float = 0.0) -> tuple[float, str]:
    """Length of a top-view scale bar in world (CRS) units and its label, in round metres.

    About a quarter of the image width, rounded down to 1, 2 or 5 × 10^k metres and drawn as
    that many metres in the CRS's unit: a 50 m bar on a US-feet CRS spans 164.04 ft. On a
    geographic CRS the eastward metres per degree shrink with cos(latitude).

    Examples
    --------
    >>> from workstation.core.units import Units, US_SURVEY_FOOT
    >>> w, label = scale_bar(1.0, 800, Units(US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot"))
    >>> label, round(w, 2)
    ('50 m', 164.04)
    """
    per_unit = units.h * (math.cos(math.radians(centre_y)) if units.geographic else 1.0)
    length_m = _nice_length(0.25 * width_px * units_per_px * per_unit)
    return length_m / per_unit if length_m > 0 else 0.0, f"{length_m:g} {_metre_label(units)}"


def _scalar_colors(obj, params: RenderParams):
    """(name of colouring, rgb (n,3) u8 or None, scalars (n,) or None, legend entries or title)."""
    attrs = obj.attrs if isinstance(obj, Cloud) else obj.vertex_attrs
    xyz = obj.xyz if isinstance(obj, Cloud) else obj.vertices
    c = params.color
    textured = isinstance(obj, Mesh) and "uv" in attrs and obj.meta.get("texture") is not None
    if c == "texture" and not textured:
        raise InvalidInputError("the mesh has no texture", "use --color rgb or elevation", field="texture")
    if c == "auto" and textured:
        c = "texture"
    if c == "texture":
        return c, None, None, None
    if c == "auto":
        if "rgb" in attrs:
            c = "rgb"
        elif "classification" in attrs and isinstance(obj, Cloud):
            c = "class"
        else:
            c = "elevation" if isinstance(obj, Cloud) else "uniform"
    if c == "classification":
        c = "class"
    if c == "rgb":
        if "rgb" not in attrs:
            raise InvalidInputError("no rgb colours to render", "use --color elevation or class", field="rgb")
        return c, rgb_to_u8(np.asarray(attrs["rgb"])), None, None
    if c == "class":
        face_cls = isinstance(obj, Mesh) and "classification" in obj.face_attrs
        if "classification" not in attrs and not face_cls:
            raise InvalidInputError("no classification to colour by", "use --color elevation", field="classification")
        codes = np.asarray(obj.face_attrs["classification"] if face_cls else attrs["classification"])
        present = np.unique(codes)
        entries = [(f"{int(k)} {class_name(int(k))}", tuple(v / 255 for v in CLASS_COLORS.get(int(k), (128,) * 3)))
                   for k in present]
        return ("class-face" if face_cls else "class"), class_colors(codes), None, entries
    if c == "uniform":
        return c, None, None, None
    if c == "elevation":  # heights shown in metres whatever the CRS's vertical unit
        u = crs_units(getattr(obj, "crs", None))
        return c, None, u.v_to_m(np.asarray(xyz[:, 2], dtype=np.float64)), f"Elevation ({_metre_label(u)})"
    if c not in attrs:
        raise InvalidInputError(f"--color {c}: neither a colouring nor an attribute of this data",
                                "use one of " + ", ".join(NAMED_COLORS) + "; attributes here: "
                                + (", ".join(sorted(attrs)) or "none"), field="color")
    a = np.asarray(attrs[c])
    if a.ndim == 2 and a.shape[1] == 3:
        return "rgb", rgb_to_u8(a), None, None
    if a.ndim != 1:
        raise InvalidInputError(f"attribute '{c}' has shape {a.shape}: not a scalar", field=c)
    a = a.astype(np.float64)
    if c == "hag":  # heights above ground are in the CRS's vertical unit: shown in metres
        u = crs_units(getattr(obj, "crs", None))
        return c, None, u.v_to_m(a), f"Height above ground ({_metre_label(u)})"
    title = {"intensity": "Intensity"}.get(c, c)
    return c, None, a, title


def _point_size(params: RenderParams, lo: np.ndarray, hi: np.ndarray, n: int, size) -> float:
    """Point diameter in pixels: given, or about sqrt(footprint pixels / points)."""
    if params.point_size > 0:
        return float(params.point_size)
    ext = hi - lo
    w, h = size
    # share of the frame the XY footprint fills in a fitted view (an upper bound for others)
    aspect = max(ext[0], 1e-9) / max(ext[1], 1e-9)
    fill = (aspect / (w / h)) if aspect < w / h else ((w / h) / aspect)
    footprint_px = w * h * fill * 0.8
    return float(np.clip(1.5 * math.sqrt(footprint_px / max(n, 1)), 1.0, 8.0))


def _subset(cloud: Cloud, max_points: int) -> Cloud:
    if max_points and cloud.n > max_points:
        idx = np.sort(np.random.default_rng(0).choice(cloud.n, max_points, replace=False))
        return cloud[idx]
    return cloud


def projection_matrix(camera: Camera, near: float, far: float) -> np.ndarray:
    """OpenGL projection matrix (4, 4) of a pinhole camera (pixel centres at integers).

    Maps eye coordinates (x right, y up, looking down -z) so that the image pixel (u, v) of
    ``K @ [R|t] X`` in OpenCV convention (v down) is where X is drawn.
    """
    w, h = float(camera.width), float(camera.height)
    fx, fy, cx, cy, s = camera.fx, camera.fy, camera.cx, camera.cy, camera.skew
    m = np.zeros((4, 4))
    m[0] = [2 * fx / w, -2 * s / w, 1 - 2 * (cx + 0.5) / w, 0]
    m[1] = [0, 2 * fy / h, 2 * (cy + 0.5) / h - 1, 0]
    m[2] = [0, 0, -(far + near) / (far - near), -2 * far * near / (far - near)]
    m[3] = [0, 0, -1, 0]
    return m


def _vtk_matrix(m: np.ndarray):
    import vtk

    vm = vtk.vtkMatrix4x4()
    for i in range(4):
        for j in range(4):
            vm.SetElement(i, j, float(m[i, j]))
    return vm


def _set_pinhole(pl, camera: Camera, pose: Pose, origin: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    R = np.asarray(pose.R, dtype=np.float64)
    C = np.asarray(pose.center, dtype=np.float64) - origin
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])
    depth = (corners - C) @ R[2]
    if depth.max() <= 0:
        raise InvalidInputError("the object is behind the camera", "check the pose (world -> camera)", field="pose")
    # clipping planes from the bounding box (the camera may stand inside it)
    far = float(depth.max()) * 1.05
    near = max(float(depth.min()) * 0.95, far * 1e-4)
    cam = pl.camera
    cam.position = tuple(C)
    cam.focal_point = tuple(C + R[2])
    cam.up = tuple(-R[1])
    vcam = pl.renderer.GetActiveCamera()
    vcam.SetClippingRange(near, far)
    vcam.SetExplicitProjectionTransformMatrix(_vtk_matrix(projection_matrix(camera, near, far)))
    vcam.SetUseExplicitProjectionTransformMatrix(True)


def _stray_mask(P: np.ndarray, share: float, cell: float) -> np.ndarray:
    """Points of the 26-connected voxel components (voxels of ``cell``) holding at least
    ``share`` of ``P`` (all True when none does)."""
    from scipy import ndimage

    idx = np.floor((P - P.min(axis=0)) / cell).astype(np.int64)
    grid = np.zeros(tuple(idx.max(axis=0) + 1), dtype=bool)
    grid[tuple(idx.T)] = True
    labels, _ = ndimage.label(grid, structure=np.ones((3, 3, 3), dtype=bool))
    lab = labels[tuple(idx.T)]
    good = np.bincount(lab)[lab] >= share * P.shape[0]
    return good if good.any() else np.ones(P.shape[0], dtype=bool)


def framing_bounds(xyz: np.ndarray, stray_share: float = 0.005, max_points: int = 200_000,
                   cells: int = 64) -> tuple[np.ndarray, np.ndarray]:
    """Bounding box (lo (3,), hi (3,)) of a cloud for framing a view, stray points left out.

    The points are binned in voxels of ``max(diagonal / cells, 3 × median nearest-neighbour
    distance)`` (the second keeps a surface sampled at the typical spacing connected); a
    26-connected component of voxels holding less than ``stray_share`` of the points is left
    out: a floating outlier is isolated from the model by empty space, while a spire joins the
    roof below it. Rounds repeat on what is left (finer voxels: strays nested at smaller
    scales) until one drops nothing. Larger clouds are thinned to ``max_points`` by taking
    every k-th point.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> model = rng.uniform(0, 10, (10000, 3))
    >>> strays = np.array([[500.0, 5, 5], [5, -300.0, 5], [5, 5, 90.0]])
    >>> lo, hi = framing_bounds(np.vstack([model, strays]))
    >>> bool(np.all(lo > -0.01) and np.all(hi < 10.01)), np.round(hi - lo).tolist()
    (True, [10.0, 10.0, 10.0])
    """
    from scipy.spatial import cKDTree

    P = np.asarray(xyz, dtype=np.float64)
    if stray_share <= 0 or P.shape[0] < 3:
        return P.min(axis=0), P.max(axis=0)
    if P.shape[0] > max_points:
        P = P[:: -(-P.shape[0] // max_points)]
    q = P[:: max(1, P.shape[0] // 10_000)]
    spacing = float(np.median(cKDTree(P).query(q, k=2)[0][:, 1]))
    for _ in range(4):
        diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))
        if not diag > 0:
            break
        keep = _stray_mask(P, stray_share, max(diag / cells, 3.0 * spacing))
        if keep.all():
            break
        P = P[keep]
    return P.min(axis=0), P.max(axis=0)


def iso_direction(lo: np.ndarray, hi: np.ndarray, elevation_deg: float = 30.0,
                  off_normal_deg: float = 30.0) -> np.ndarray:
    """Unit direction from the model's centre to the ``iso`` camera.

    The camera stands ``elevation_deg`` above the horizon, on the side of the longer vertical
    face of the bounding box (the south side, normal -y, when x is the longer extent, else
    the east side, normal +x), turned ``off_normal_deg`` towards the south-east corner so that
    the other side shows too.
    """
    ext = np.asarray(hi, float) - np.asarray(lo, float)
    normal_az = -90.0 if ext[0] >= ext[1] else 0.0
    az = math.radians(normal_az + (off_normal_deg if normal_az < 0 else -off_normal_deg))
    el = math.radians(elevation_deg)
    return np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])


def _fit_view(pl, view: str, bounds_min: np.ndarray, bounds_max: np.ndarray, size, margin: float) -> float | None:
    """Place the camera; returns world units per pixel for the top view."""
    w, h = size
    centre = 0.5 * (bounds_min + bounds_max)
    ext = np.maximum(bounds_max - bounds_min, 1e-9)
    diag = float(np.linalg.norm(ext))
    cam = pl.camera
    if view == "top":
        pl.enable_parallel_projection()
        cam.focal_point = tuple(centre)
        cam.position = tuple(centre + [0, 0, diag * 2 + 1])
        cam.up = (0.0, 1.0, 0.0)
        half_h = max(ext[1] / 2, ext[0] / 2 * h / w) * (1 + 2 * margin)
        cam.parallel_scale = float(half_h)
        pl.renderer.ResetCameraClippingRange()
        return 2 * half_h / h
    direction = np.array([0.0, -1.0, 0.0]) if view == "front" else iso_direction(bounds_min, bounds_max)
    view_angle = 30.0
    tan_h = math.tan(math.radians(view_angle / 2))
    tan_w = tan_h * w / h
    # camera axes: forward = -direction, up = world Z made orthogonal, right = forward x up
    fwd = -direction
    up = np.array([0.0, 0.0, 1.0]) - fwd[2] * fwd
    up /= np.linalg.norm(up)
    right = np.cross(fwd, up)
    corners = np.array([[x, y, z] for x in (bounds_min[0], bounds_max[0]) for y in (bounds_min[1], bounds_max[1])
                        for z in (bounds_min[2], bounds_max[2])]) - centre
    corners = corners * (1 + 2 * margin)
    # distance so every corner of the bounding box projects inside the frame
    depth = corners @ fwd
    dist = float(np.max(np.concatenate([np.abs(corners @ right) / tan_w - depth, np.abs(corners @ up) / tan_h - depth])))
    dist = max(dist, 1e-6 * diag + 1e-9)
    cam.focal_point = tuple(centre)
    cam.up = tuple(up)
    cam.view_angle = view_angle
    cam.position = tuple(centre + direction * dist)
    pl.renderer.ResetCameraClippingRange()
    return None


def _draw_scale_bar(pl, pv, units_per_px: float, size, centre, zmax, units, bg_dark: bool) -> None:
    w, h = size
    length, label = scale_bar(units_per_px, w, units, float(centre[1]))
    if length <= 0:
        return
    x0_px, y0_px, thick_px = 20, 20, max(4, h // 120)
    # world position of the bar's lower-left corner (orthographic top view, north up)
    wx = centre[0] + (x0_px - w / 2) * units_per_px
    wy = centre[1] + (y0_px - h / 2) * units_per_px
    z = zmax + 1e-3 * max(units_per_px * w, 1.0)
    fg = "white" if bg_dark else "black"
    half = length / 2
    for i, col in enumerate((fg, "gray")):
        x = wx + i * half
        quad = pv.Rectangle([[x, wy, z], [x + half, wy, z], [x + half, wy + thick_px * units_per_px, z]])
        pl.add_mesh(quad, color=col, lighting=False, show_edges=False)
    pl.add_text(label, position=(x0_px, y0_px + thick_px + 4), font_size=max(8, h // 70), color=fg)
    pl.add_text("N ^", position=(x0_px, h - 20 - max(8, h // 70) * 2), font_size=max(8, h // 70), color=fg)


def render(obj, params: RenderParams = RenderParams(), camera: tuple[Camera, Pose] | None = None) -> np.ndarray:
    """Render a cloud or mesh off-screen.

    Parameters
    ----------
    obj : Cloud or Mesh
    params : RenderParams
    camera : (Camera, Pose), optional
        Exact pinhole camera; ``params.size`` is then the camera's image size.

    Returns
    -------
    (height, width, 3) uint8 image, row 0 at the top.
    """
    from workstation.interop.pyvista import cloud_to_polydata, mesh_to_polydata, pyvista_offscreen

    if not isinstance(obj, (Cloud, Mesh)):
        raise InvalidInputError(f"cannot render a {type(obj).__name__}", "pass a Cloud or a Mesh")
    is_cloud = isinstance(obj, Cloud)
    if (obj.n if is_cloud else obj.n_faces) == 0:
        raise InvalidInputError("nothing to render: empty cloud or mesh")
    pv = pyvista_offscreen()
    size = (int(camera[0].width), int(camera[0].height)) if camera else (int(params.size[0]), int(params.size[1]))
    if is_cloud:
        obj = _subset(obj, params.max_points)
    colors = _scalar_colors(obj, params)
    xyz = obj.xyz if is_cloud else obj.vertices
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)  # once, in float64
    origin = np.round(0.5 * (lo + hi))
    lo, hi = lo - origin, hi - origin
    if camera is None:  # fitted views frame the model without its stray points
        flo, fhi = framing_bounds(xyz, params.stray_share)
        flo, fhi = flo - origin, fhi - origin
    else:
        flo, fhi = lo, hi
    poly, _ = cloud_to_polydata(obj, origin) if is_cloud else mesh_to_polydata(obj, origin)
    n_points = obj.n if is_cloud else obj.n_vertices
    pl = pv.Plotter(off_screen=True, window_size=list(size), lighting=None if is_cloud else "light kit")
    try:
        pl.set_background(params.background)
        bg = np.asarray(pv.Color(params.background).float_rgb)
        kw = dict(lighting=not is_cloud, show_scalar_bar=False)
        if is_cloud:
            kw.update(style="points", point_size=_point_size(params, flo, fhi, n_points, size), render_points_as_spheres=False)
        else:
            kw.update(smooth_shading=True)
        _add_model(pl, pv, poly, obj, colors, kw, params, bg, size)
        if camera is not None:
            _set_pinhole(pl, camera[0], camera[1], origin, lo, hi)
        else:
            upp = _fit_view(pl, params.view, flo, fhi, size, params.margin)
            if params.view == "top" and params.scale_bar and upp:
                _draw_scale_bar(pl, pv, upp, size, 0.5 * (flo + fhi), float(hi[2]), crs_units(obj.crs),
                                bg.mean() < 0.5)
        if is_cloud and params.edl:
            pl.enable_eye_dome_lighting()
        img = pl.screenshot(return_img=True)
    finally:
        pl.close()
    if img is None or img.shape[:2] != (size[1], size[0]):
        raise StageError("render", "VTK returned no image", "check the OpenGL (EGL/OSMesa) libraries")
    return np.ascontiguousarray(img[:, :, :3])


def _add_model(pl, pv, poly, obj, colors: tuple, kw: dict, params: RenderParams, bg: np.ndarray, size) -> None:
    """Add the model to the plotter coloured as :func:`_scalar_colors` decided: its texture
    (unlit: the photos' own shading is in it), per-point or per-face RGB, a scalar with a
    colour map (and scalar bar), or plain grey; then the class legend for class colourings."""
    kind, rgb, scalars, legend = colors
    if kind == "texture":
        poly.active_texture_coordinates = np.asarray(obj.vertex_attrs["uv"], dtype=np.float32)
        tex = pv.Texture(np.ascontiguousarray(np.asarray(obj.meta["texture"], dtype=np.uint8)[:, :, :3]))
        tex.interpolate = True
        # the photos' own shading is in the texture: draw it unlit, as seen
        pl.add_mesh(poly, texture=tex, **{**kw, "lighting": False, "smooth_shading": False})
    elif rgb is not None:
        if kind == "class-face":
            poly.cell_data["_rgb"] = rgb
        else:
            poly.point_data["_rgb"] = rgb
        pl.add_mesh(poly, scalars="_rgb", rgb=True, **kw)
    elif scalars is not None:
        _add_scalars(pl, poly, kind, scalars, legend, kw, params, bg, size)
    else:
        pl.add_mesh(poly, color="lightgray", **kw)
    if kind.startswith("class") and params.legend and legend:
        lw, lh = 0.34, min(0.055 * len(legend), 0.6)
        actor = pl.add_legend(labels=[[name, col] for name, col in legend], bcolor=tuple(bg), border=True,
                              loc="upper right", size=(lw, lh), face="rectangle")
        actor.SetPosition(1 - lw - 0.01, 1 - lh - 0.01)  # pyvista places it as if 0.2 wide


def _add_scalars(pl, poly, kind: str, scalars: np.ndarray, legend, kw: dict, params: RenderParams, bg: np.ndarray,
                 size) -> None:
    """Add the model coloured by a scalar: the colour range spans the ``clip_percent`` to
    ``100 - clip_percent`` percentiles of the finite values (of a fixed random sample of 10^6
    when there are more), so a few outliers do not wash out the map; a scalar bar when
    ``params.legend``."""
    sample = scalars if scalars.size <= 1_000_000 else scalars[
        np.random.default_rng(0).choice(scalars.size, 1_000_000, replace=False)]
    finite = sample[np.isfinite(sample)]
    vmin, vmax = (np.percentile(finite, [params.clip_percent, 100 - params.clip_percent]) if finite.size
                  else (0.0, 1.0))
    if vmax <= vmin:
        vmax = vmin + 1.0
    poly.point_data["_s"] = scalars
    cmap = params.cmap or ("gray" if kind == "intensity" else "viridis")
    pl.add_mesh(poly, scalars="_s", cmap=cmap, clim=[float(vmin), float(vmax)], **kw)
    if params.legend:
        fg = "white" if bg.mean() < 0.5 else "black"
        pl.add_scalar_bar(title=str(legend), color=fg, vertical=True, position_x=0.8, position_y=0.1,
                          width=0.05, height=0.7, n_labels=5, fmt="%.4g",
                          title_font_size=max(6, size[1] // 40), label_font_size=max(6, size[1] // 45))


def find_image(rec: Reconstruction, ref) -> int:
    """Id of the image of ``rec`` named ``ref`` (file name, or its stem), or with id ``ref``."""
    s = str(ref)
    for iid, im in rec.images.items():
        if s in (im.name, im.name.rsplit("/", 1)[-1], im.name.rsplit("/", 1)[-1].rsplit(".", 1)[0]):
            return int(iid)
    if s.isdigit() and int(s) in rec.images:
        return int(s)
    names = ", ".join(im.name for im in list(rec.images.values())[:10])
    raise InvalidInputError(f"no image '{s}' in the reconstruction", f"give a name or id, e.g. {names}",
                            field="camera")


def reconstruction_view(rec: Reconstruction, image_id: int) -> tuple[Camera, Pose]:
    """The (Camera, Pose) of one oriented image of a reconstruction, for ``render(camera=...)``.

    The render then matches the photo pixel for pixel (distortion aside: renders are ideal
    pinhole images; undistort the photo to compare).
    """
    if image_id not in rec.images:
        raise InvalidInputError(f"image {image_id} is not in the reconstruction",
                                "ids: " + ", ".join(str(k) for k in sorted(rec.images)[:20]), field="image_id")
    im = rec.images[image_id]
    if im.camera_id not in rec.cameras:
        raise InvalidInputError(f"camera {im.camera_id} of image {image_id} is missing", field="cameras")
    cam = rec.cameras[im.camera_id]
    if any(abs(float(d)) > 0 for d in cam.dist):
        log.warning("camera %d has lens distortion: the render is the ideal pinhole image "
                    "(compare it with the undistorted photo)", im.camera_id)
    return cam, im.pose


def turntable(obj, params: RenderParams = RenderParams(), frames: int = 36, elevation_deg: float = 25.0):
    """Frames (list of (h, w, 3) uint8) of the camera orbiting the object once.

    The camera circles the bounding-box centre at ``elevation_deg`` above the horizon,
    starting from the south, counter-clockwise seen from above, ``frames`` equal steps.
    """
    if frames < 1:
        raise InvalidInputError("frames must be >= 1", field="frames")
    xyz = obj.xyz if isinstance(obj, Cloud) else obj.vertices
    lo, hi = framing_bounds(xyz, params.stray_share)
    centre = 0.5 * (lo + hi)
    r = 0.5 * float(np.linalg.norm(hi - lo)) * (1 + 2 * params.margin)
    w, h = params.size
    half = math.radians(15)
    dist = r / math.sin(min(half, math.atan(math.tan(half) * w / h)))
    f = (h / 2) / math.tan(half)  # 30 degree vertical field of view
    cam = Camera(int(w), int(h), f, f, (w - 1) / 2, (h - 1) / 2)
    out = []
    el = math.radians(elevation_deg)
    for i in range(frames):
        az = 2 * math.pi * i / frames - math.pi / 2
        C = centre + dist * np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
        fwd = centre - C
        fwd /= np.linalg.norm(fwd)
        right = np.cross(fwd, [0.0, 0.0, 1.0])
        right /= np.linalg.norm(right)
        down = np.cross(fwd, right)
        R = np.vstack([right, down, fwd])
        out.append(render(obj, params, camera=(cam, Pose(R, -R @ C))))
    return out


def save_png(img: np.ndarray, path, overwrite: bool = False, inputs=()):
    """Write an (h, w, 3|4) uint8 image as PNG atomically."""
    from PIL import Image as PILImage

    from workstation.io import atomic_path

    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        PILImage.fromarray(np.asarray(img, dtype=np.uint8)).save(tmp, format="PNG", optimize=True)
    return path


def save_gif(frames, path, fps: float = 12.0, overwrite: bool = False, inputs=()):
    """Write frames as a looping GIF atomically (adaptive palette per frame)."""
    from PIL import Image as PILImage

    from workstation.io import atomic_path

    if not frames:
        raise InvalidInputError("no frames to write")
    ims = [PILImage.fromarray(np.asarray(f, dtype=np.uint8)) for f in frames]
    with atomic_path(path, overwrite=overwrite, inputs=inputs) as tmp:
        ims[0].save(tmp, format="GIF", save_all=True, append_images=ims[1:], duration=int(1000 / fps), loop=0)
    return path
