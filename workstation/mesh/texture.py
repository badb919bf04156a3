"""Texture a mesh from oriented photos: per-face view selection, a per-triangle atlas, resampling.

MeshLab's own route (``compute_texcoord_parametrization_and_texture_from_registered_rasters``)
needs rasters loaded with their cameras and an OpenGL context for its projections (the filter
family that crashes headless, PyMeshLab #214), so the texture is built here with numpy and
Open3D ray casting, and works on any machine:

1. **View selection per face** (Allène, Pons & Keriven, "Seamless image-based texture atlases
   using multi-band blending", ICPR 2008; Waechter, Moehrle & Goesele, "Let there be color!",
   ECCV 2014, without their MRF smoothing term): a view is a candidate for a face when the
   face lies wholly inside the image, faces the camera (cosine of the viewing angle above
   ``min_cos``) and is visible: rays from the camera centre to the face centroid and to three
   points near its corners reach the face before any other surface (Open3D
   ``RaycastingScene``). Among the candidates the face takes the ``max_views`` with the
   largest projected area in pixels (closest and most frontal views, sharpest texture).
2. **Atlas**: each pair of triangles shares a square cell of the texture, each triangle
   mapped affinely onto one half as a right isosceles triangle (MeshLab's "trivial per-triangle
   parametrization"), with the longest edge on the hypotenuse and one texel of separation so
   bilinear filtering never mixes two faces. Cell sides are powers of two chosen, by default,
   from the face's footprint in its best view: the smallest cell whose texels span at most
   one photo pixel in any direction (the largest singular value of the face's legs projected
   into the photo), so that the texture keeps all the photo resolves wherever the face lies
   (a uniform ``texel_size`` in metres is the alternative), within a texture-size budget
   (all cells shrink by one factor until the atlas fits); cells are shelf-packed class by
   class.
3. **Resampling**: every texel centre is mapped back to its 3-D point on the face
   (barycentric coordinates) and projected into the face's views with the collinearity
   equations and lens distortion (the same projection as ``ws colorize`` and the orthophoto,
   :func:`workstation.registration.colorize.project`). A sensor pixel records the mean of the
   scene over its square, so the photo is taken as squares of constant colour and each texel
   gets their mean over its own footprint (the texel's square projected into the photo, a
   box prefilter; a texel well inside one pixel takes that pixel), blended with the view
   weights. Bilinear interpolation of the photo (``resample="bilinear"``) would spread each
   pixel over its neighbours' squares, a blur that the renderer's own bilinear lookup of the
   texture then doubles. Faces textured from last-resort views (step 6), seen grazing or
   partly hidden, whose pixels mix the face with the surfaces around it, take the bilinear
   interpolation, which evens those mixed pixels out.

4. **Exposure balance** (Brown & Lowe, "Automatic panoramic image stitching using invariant
   features", IJCV 2007, section 6): photos taken with different exposure or white balance
   leave colour seams where the chosen view changes from face to face. One gain per photo and
   channel is found by least squares: over the faces two photos both see, their mean colours
   times their gains should agree (error sigma ``sigma_n`` = 10 grey levels), and each gain
   stays near 1 (sigma ``sigma_g`` = 0.1), the paper's values; each photo is multiplied by
   its gains when sampled.

5. **Photo consistency** (Waechter, Moehrle & Goesele 2014, section 4.1): the mesh-based
   visibility test cannot see an occluder the mesh lacks (a branch, a passer-by, a car in front
   of a façade), so its colour would be painted onto the face from every photo it hides the
   face in. Each face's candidate views (up to ``CONSISTENCY_VIEWS``) are compared by their
   gain-corrected mean colours of the face (16 samples spread over it); a mean shift finds the
   dominant colour, and views farther from it than the paper's kernel radius (3.2 times the
   colour noise, estimated robustly from all faces' view pairs) are dropped before the best
   views are taken. Every view votes however few pixels the face covers (a sub-pixel face's
   colour is that of its surroundings, which still shows an occluder). A face with fewer than
   three full views has no majority of its own, so the votes are also pooled in each photo: an
   occluder is one connected blob in a photo, and where, over a small box of pixels, the votes
   of the faces behind it reject that photo more often than they keep it, the photo's view of
   any face with a sample point there is rejected too (an occlusion mask per photo,
   :func:`~workstation.mesh.texture_colour.occluded_views`), and the faces vote again without
   those views. A face then takes the full views it keeps; if none, its last-resort views
   (step 6) outside the masks; if none, its rejected full views, else its rejected last-resort
   views (a face some photo sees stays textured; it never mixes full and last-resort views).
   The check runs first on the photos as they are (exposure gains estimated over
   views of an occluder would carry its colour into every photo's gain), then the gains are
   estimated without the rejected views, the check runs again on the balanced colours and the
   gains are estimated once more.

6. **Last resort** (``last_resort``): a face no view sees frontally enough and whole gets a
   grazing view or one that sees its centroid but not all its corners (step 1), and so does a
   face whose full views step 5 all rejects; such views blend other surfaces, so they take no
   part in the exposure balance nor in the vote of step 5 (only its occlusion masks).

Faces seen by no photo get their vertex colours (or grey) and ``texture_view = -1``.
The textured mesh has one vertex per face corner (``uv`` per vertex, as OBJ and glTF store
texture coordinates) and its image in ``meta["texture"]`` (see :mod:`workstation.io.mesh`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Mesh, Reconstruction

from .steps import StepRecord, Timer
from .texture_colour import (BALANCE_VIEWS, CONSISTENCY_VIEWS, colour_noise, consistent_views, exposure_gains,
                             face_colours, occluded_views)

log = get_logger(__name__)
STAGE = "texture"
#: Ways a texel takes its colour from a photo (:class:`TextureParams` ``resample``).
RESAMPLE = ("footprint", "bilinear")


@dataclass(frozen=True)
class TextureParams:
    """Parameters of :func:`texture_from_photos`.

    Attributes
    ----------
    texel_size : float or None
        Size of one texel on the surface, in mesh (CRS) units, for all faces; None = per face,
        from its footprint in its best view: its texels span at most one photo pixel in any
        direction (faces no photo sees: the median ground sample distance, depth / focal
        length, of the seen faces' best views).
    max_texture_size : int
        Largest side of the texture image, pixels; the texel size grows until the atlas fits.
    max_cell : int
        Largest cell side for a pair of triangles, texels (a power of two, >= 4).
    max_views : int
        Views blended per face, weighted by their projected area (1 = the sharpest view only).
    min_cos : float
        Views seeing a face at a cosine of the viewing angle below this are not used.
    border_px : float
        Image margin, pixels, that a face must keep clear of.
    depth_tolerance : float or None
        How far, in mesh units, a ray may stop short of the face and still count it visible;
        None = 5 % of the median edge length (plus 1e-4 of the distance for float32 ray casting).
    fallback_rgb : (int, int, int)
        Colour of faces seen by no photo when the mesh has no vertex colours (0-255).
    exposure_balance : bool
        Balance the photos' exposure and white balance by per-photo gains (True; step 4
        of the module description).
    photo_consistency : bool
        Drop the views whose colour of a face disagrees with most others, or that fall in a
        photo's region where the neighbouring faces' views do (an occluder missing from the
        mesh: a tree, a passer-by), before choosing the face's views (True; step 5 of the
        module description).
    last_resort : bool
        A face with no view passing ``min_cos`` and the four-probe visibility test may take a
        grazing view (cosine above 0) or one that sees its centroid but not all its corners
        (True; see :func:`select_views`).
    resample : str
        How a texel takes its colour from a photo: "footprint" (default), the mean of the
        photo's pixels, as squares of constant colour, over the texel's footprint (on faces
        textured from full views; last-resort views are interpolated bilinearly); "bilinear",
        the photo interpolated bilinearly at the texel's centre (step 3 of the module
        description).
    """

    texel_size: float | None = None
    max_texture_size: int = 4096
    max_cell: int = 64
    max_views: int = 1
    min_cos: float = 0.2
    border_px: float = 2.0
    depth_tolerance: float | None = None
    fallback_rgb: tuple = (128, 128, 128)
    exposure_balance: bool = True
    photo_consistency: bool = True
    last_resort: bool = True
    resample: str = "footprint"

    def __post_init__(self):
        if self.texel_size is not None and not self.texel_size > 0:
            raise InvalidInputError("texel_size must be positive", field="texel_size")
        if not 16 <= self.max_texture_size <= 32768:
            raise InvalidInputError("max_texture_size must be in 16..32768 pixels", field="max_texture_size")
        if self.max_cell < 4 or self.max_cell & (self.max_cell - 1):
            raise InvalidInputError("max_cell must be a power of two >= 4", field="max_cell")
        if self.max_views < 1:
            raise InvalidInputError("max_views must be >= 1", field="max_views")
        if not 0.0 <= self.min_cos < 1.0:
            raise InvalidInputError("min_cos must be in [0, 1)", field="min_cos")
        if self.resample not in RESAMPLE:
            raise InvalidInputError(f"resample must be one of {RESAMPLE}", field="resample")


# ------------------------------------------------------------------------------ view selection
def _corner_order(tri: np.ndarray) -> np.ndarray:
    """(m, 3) permutation of each face's corners: the corner opposite the longest edge first."""
    e = np.stack([np.linalg.norm(tri[:, 1] - tri[:, 2], axis=1), np.linalg.norm(tri[:, 2] - tri[:, 0], axis=1),
                  np.linalg.norm(tri[:, 0] - tri[:, 1], axis=1)], axis=1)  # edge opposite corner i
    r = np.argmax(e, axis=1)
    return np.stack([r, (r + 1) % 3, (r + 2) % 3], axis=1)


def select_views(mesh: Mesh, rec: Reconstruction, params: TextureParams = TextureParams(), k: int | None = None):
    """The ``k`` (default ``params.max_views``) best views of every face: (views, weights, gsd)
    of :func:`ranked_views`, without its ``full`` mask."""
    return ranked_views(mesh, rec, params, k)[:3]


def _face_probes(mesh: Mesh, params: TextureParams):
    """Per face: corners (m, 3, 3), centroid, unit normal, twice the area, the four probe points
    (m, 4, 3: the centroid and three points 20 % of the way from each corner to it) and the
    depth tolerance of the visibility test (mesh units)."""
    tri = mesh.vertices[mesh.faces]
    cen = tri.mean(axis=1)
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nlen = np.linalg.norm(nrm, axis=1)
    nrm = nrm / np.maximum(nlen, 1e-300)[:, None]
    edges = np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2)
    tol_abs = params.depth_tolerance if params.depth_tolerance is not None else 0.05 * float(np.median(edges))
    probes = np.concatenate([cen[:, None], 0.8 * tri + 0.2 * cen[:, None]], axis=1)
    return tri, cen, nrm, nlen, probes, tol_abs


def ranked_views(mesh: Mesh, rec: Reconstruction, params: TextureParams = TextureParams(), k: int | None = None,
                 keep_last_resort: bool = False):
    """The ``k`` (default ``params.max_views``) best views of every face.

    A view is a full candidate when the face is wholly inside the image, faces the camera at a
    cosine of at least ``params.min_cos`` and all four probe points are visible; with
    ``params.last_resort`` a face that has no full candidate may still take a view that sees it
    at a grazing angle (cosine above 0) or sees its centroid while up to three corner probes
    are hidden (a face cut by another part of the mesh, such as a wall running into a roof).
    Full candidates always rank before last-resort views; within each group, views rank by the
    face's visible projected area. A face with a full candidate keeps no last-resort view,
    unless ``keep_last_resort`` (then they fill the slots after its full candidates, for when
    the photo-consistency check rejects all of those).

    Returns
    -------
    views : (m, k) int64
        Image ids, best first; -1 where fewer than k views see the face.
    weights : (m, k) float64
        Visible projected area of the face in each view, pixels²: its projected area times
        the share of its probe points that are visible (0 where no view).
    gsd : (m,) float64
        Ground sample distance of the best view at the face (mesh units per pixel; NaN if none).
    full : (m, k) bool
        Whether each view is a full candidate (False for last-resort views and empty slots).
    """
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.interop.pymeshlab import default_origin
    from workstation.registration.colorize import project

    V, F = mesh.vertices, mesh.faces
    m = len(F)
    k = int(params.max_views if k is None else k)
    origin = default_origin(V)
    tri, cen, nrm, nlen, probes, tol_abs = _face_probes(mesh, params)
    caster = RaycastScene(V - origin, F)
    views = np.full((m, k), -1, dtype=np.int64)
    rank = np.zeros((m, k))  # _view_rank of the slot's view: full candidates first, then by weight
    weight = np.zeros((m, k))  # projected area of the face in the slot's view (pixels²)
    gsd_slot = np.full((m, k), np.nan)
    for iid, im in rec.images.items():
        cam = rec.cameras[im.camera_id]
        u, v, z = project(tri.reshape(-1, 3), cam, im.pose)
        u, v, z = u.reshape(m, 3), v.reshape(m, 3), z.reshape(m, 3)
        b = params.border_px
        ok = ((z > 0) & (u >= b) & (u <= cam.width - 1 - b) & (v >= b) & (v <= cam.height - 1 - b)).all(axis=1)
        C = np.asarray(im.pose.center, dtype=np.float64)
        ray = C - cen
        dist = np.linalg.norm(ray, axis=1)
        cosang = np.abs(np.einsum("ij,ij->i", nrm, ray)) / np.maximum(dist, 1e-300)
        ok &= (cosang > 0 if params.last_resort else cosang >= params.min_cos) & (nlen > 0)
        idx = np.flatnonzero(ok)
        if idx.size == 0:
            continue
        p = probes[idx].reshape(-1, 3)
        d = p - C
        dl = np.linalg.norm(d, axis=1)
        t, _ = caster.cast(np.broadcast_to(C - origin, d.shape), d / dl[:, None])
        vis = (t >= dl - (tol_abs + 1e-4 * dl)).reshape(-1, 4)
        full = vis.all(axis=1) & (cosang[idx] >= params.min_cos)
        keep = full | (params.last_resort & vis[:, 0])
        idx, full, share = idx[keep], full[keep], vis[keep].mean(axis=1)
        if idx.size == 0:
            continue
        area = 0.5 * np.abs((u[idx, 1] - u[idx, 0]) * (v[idx, 2] - v[idx, 0])
                            - (u[idx, 2] - u[idx, 0]) * (v[idx, 1] - v[idx, 0])) * share
        r = _view_rank(area, full)
        slot = np.argmin(rank[idx], axis=1)
        better = r > rank[idx, slot]
        j, s = idx[better], slot[better]
        views[j, s] = iid
        rank[j, s] = r[better]
        weight[j, s] = area[better]
        gsd_slot[j, s] = z[j].mean(axis=1) / (0.5 * (cam.fx + cam.fy))
    order = np.argsort(-rank, axis=1, kind="stable")
    views = np.take_along_axis(views, order, axis=1)
    full_slot = np.take_along_axis(rank, order, axis=1) >= FULL_VIEW_RANK
    # a face keeps its last-resort views only when it has no full candidate (or when asked)
    drop = full_slot[:, :1] & ~full_slot & (not keep_last_resort)
    views[drop] = -1
    weights = np.where(drop | (views < 0), 0.0, np.take_along_axis(weight, order, axis=1))
    gsd = np.take_along_axis(gsd_slot, order, axis=1)[:, 0]
    return views, weights, gsd, full_slot


#: Lowest rank of a full candidate (:func:`_view_rank`): last-resort views rank below it.
FULL_VIEW_RANK = 2.0


def _view_rank(area: np.ndarray, full: np.ndarray) -> np.ndarray:
    """Rank of views by (full candidate, projected area): ``2 full + a / (1 + a)``, increasing
    in both and exact in float64 for any area (a full candidate always outranks a last-resort
    view, whatever their areas)."""
    return FULL_VIEW_RANK * full + area / (1.0 + area)


# ------------------------------------------------------------------------------------- atlas
@dataclass(frozen=True)
class Atlas:
    """A per-triangle atlas.

    Attributes
    ----------
    width, height : int
        Texture size, pixels.
    cell : (m,) int64
        Cell side of each face's pair, texels.
    x0, y0 : (m,) int64
        Upper-left texel of each face's cell (x right, y down).
    half : (m,) int8
        0: the face is the cell's lower-left half, 1: its upper-right half.
    texel_size : float
        Mesh units per texel used for the cell sizes.
    """

    width: int
    height: int
    cell: np.ndarray
    x0: np.ndarray
    y0: np.ndarray
    half: np.ndarray
    texel_size: float


def _half_corners(c: np.ndarray, half: np.ndarray) -> np.ndarray:
    """(m, 3, 2) texel coordinates (cell-local, pixel centres at +0.5) of the right-angle corner
    and the two others, for cells of side ``c`` and halves ``half``.

    The lower half covers texel centres with a + b <= c - 1 (hypotenuse x + y = c - 1), the
    upper half a + b >= c (hypotenuse x + y = c + 2): bilinear lookups inside one half never
    touch a texel of the other."""
    c = c.astype(np.float64)
    lower = np.stack([np.stack([np.full_like(c, 0.5), np.full_like(c, 0.5)], 1),
                      np.stack([c - 1.5, np.full_like(c, 0.5)], 1),
                      np.stack([np.full_like(c, 0.5), c - 1.5], 1)], axis=1)
    upper = np.stack([np.stack([c - 0.5, c - 0.5], 1),
                      np.stack([np.full_like(c, 2.5), c - 0.5], 1),
                      np.stack([c - 0.5, np.full_like(c, 2.5)], 1)], axis=1)
    return np.where((half == 1)[:, None, None], upper, lower)


def _cell_sides(leg: np.ndarray, max_cell: int) -> np.ndarray:
    """Cell side (texels) of faces whose legs must span ``leg`` texels: the smallest power of
    two that leaves the upper half's legs (side - 3) that long, within 4..``max_cell``."""
    c = 2 ** np.ceil(np.log2(np.maximum(leg + 3.0, 4.0)))
    return np.clip(c, 4, max_cell).astype(np.int64)


def _pack(cell: np.ndarray, width: int):
    """Shelf packing of square cells (two faces per cell, power-of-two sides), largest first.

    Returns (x0, y0, half, height)."""
    m = len(cell)
    order = np.lexsort((np.arange(m), -cell))
    x0 = np.zeros(m, np.int64)
    y0 = np.zeros(m, np.int64)
    half = np.zeros(m, np.int8)
    y = 0
    start = 0
    for c in np.unique(cell)[::-1]:
        n = int((cell == c).sum())
        faces = order[start:start + n]
        start += n
        j = np.arange(n)
        pair = j // 2
        per_row = width // int(c)
        x0[faces] = (pair % per_row) * c
        y0[faces] = y + (pair // per_row) * c
        half[faces] = (j % 2).astype(np.int8)
        y += int(math.ceil(math.ceil(n / 2) / per_row)) * int(c)
    return x0, y0, half, y


def build_atlas(mesh: Mesh, texel_size: float, params: TextureParams = TextureParams(),
                legs: np.ndarray | None = None) -> Atlas:
    """Cells and their places for every face, within the texture-size budget.

    Each face's cell gives its legs (the right isosceles triangle's, the longest edge on the
    hypotenuse) at least ``legs`` (m,) texels; by default longest edge / (sqrt(2)
    ``texel_size``), one texel size for all faces. When the packed atlas exceeds
    ``max_texture_size`` on a side, all legs shrink by one factor (the square root of the
    overflow) until it fits. ``Atlas.texel_size``: ``texel_size`` times that factor (by
    default the texel size used), or with ``legs`` the median over faces of mesh units per
    texel along the hypotenuse before the cells are rounded up.
    """
    tri = mesh.vertices[mesh.faces]
    longest = np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2).max(axis=1)
    limit = int(params.max_texture_size)
    texel = float(texel_size)
    leg0 = None if legs is None else np.asarray(legs, np.float64)
    grow = 1.0
    for _ in range(40):
        cell = _cell_sides(longest / (math.sqrt(2.0) * texel) if leg0 is None else leg0 / grow, params.max_cell)
        area = float((cell.astype(np.float64) ** 2).sum() / 2.0)
        width = int(min(limit, max(int(cell.max()), 2 ** math.ceil(math.log2(max(math.sqrt(area), 1.0))))))
        x0, y0, half, height = _pack(cell, width)
        if height <= limit:
            height = max(4, int(math.ceil(height / 4.0)) * 4)
            size = texel if legs is None else _median_texel(longest, leg0, grow, texel)
            return Atlas(width, height, cell, x0, y0, half, size)
        if int(cell.max()) == 4:
            break
        step = max(1.05, math.sqrt(height / limit))
        grow *= step
        texel *= step
    raise StageError(STAGE, f"{mesh.n_faces} faces do not fit a {limit} px texture at 4 texels per face pair",
                     "raise the texture size or decimate the mesh (--target-faces)")


def atlas_uv(mesh: Mesh, atlas: Atlas) -> np.ndarray:
    """(m, 3, 2) texture coordinates of every face corner, in [0, 1], v up (OBJ/glTF)."""
    order = _corner_order(mesh.vertices[mesh.faces])
    loc = _half_corners(atlas.cell, atlas.half)  # corners in the order (right angle, p, q)
    xy = np.empty((mesh.n_faces, 3, 2))
    rows = np.arange(mesh.n_faces)[:, None]
    xy[rows, order] = loc + np.stack([atlas.x0, atlas.y0], 1)[:, None, :]
    uv = np.empty_like(xy)
    uv[..., 0] = xy[..., 0] / atlas.width
    uv[..., 1] = 1.0 - xy[..., 1] / atlas.height
    return uv


def _texels_of(cell_c: int, faces: np.ndarray, atlas: Atlas):
    """Texels of the faces (all of side ``cell_c``): (face, x, y, barycentric (n, 3) in the
    (right angle, p, q) corner order)."""
    c = int(cell_c)
    a, b = np.meshgrid(np.arange(c), np.arange(c), indexing="xy")
    a, b = a.ravel(), b.ravel()
    lower = a + b <= c - 1
    out_f, out_x, out_y, out_w = [], [], [], []
    for h, sel in ((0, lower), (1, ~lower)):
        fs = faces[atlas.half[faces] == h]
        if fs.size == 0:
            continue
        aa, bb = a[sel].astype(np.float64) + 0.5, b[sel].astype(np.float64) + 0.5
        if h == 0:
            beta, gamma = (aa - 0.5) / (c - 2), (bb - 0.5) / (c - 2)
        else:
            beta, gamma = (c - 0.5 - aa) / (c - 3), (c - 0.5 - bb) / (c - 3)
        w = np.stack([1.0 - beta - gamma, beta, gamma], axis=1)
        w = np.clip(w, 0.0, None)
        w /= w.sum(axis=1, keepdims=True)
        n = sel.sum()
        out_f.append(np.repeat(fs, n))
        out_x.append((atlas.x0[fs][:, None] + a[sel][None, :]).ravel())
        out_y.append((atlas.y0[fs][:, None] + b[sel][None, :]).ravel())
        out_w.append(np.tile(w, (fs.size, 1)))
    return np.concatenate(out_f), np.concatenate(out_x), np.concatenate(out_y), np.concatenate(out_w)


# ----------------------------------------------------------------------------------- texture
def texture_from_photos(mesh: Mesh, rec: Reconstruction, params: TextureParams = TextureParams(), *,
                        images: Mapping[int, np.ndarray] | None = None, image_root=None) -> tuple[Mesh, StepRecord]:
    """Texture ``mesh`` from the oriented photos of ``rec`` (same frame and units).

    Parameters
    ----------
    mesh : Mesh
    rec : Reconstruction
        Cameras and oriented images.
    params : TextureParams
    images : mapping of image id to (h, w, 3) uint8 array, optional
        Pixels of each image; read from ``Image.path`` (relative to ``image_root``) otherwise.
    image_root : path, optional

    Returns
    -------
    (Mesh, StepRecord)
        One vertex per face corner with ``uv`` (3m, 2) float32 (v up), the input's ``normal``
        and ``rgb`` carried per corner, ``face_attrs["texture_view"]`` (m,) int32 (best image
        id, -1 unseen) and the texture (h, w, 3) uint8 in ``meta["texture"]``.
    """
    if mesh.n_faces == 0:
        raise InvalidInputError("the mesh has no faces", field="faces")
    if not rec.images:
        raise InvalidInputError("the reconstruction has no oriented images", field="reconstruction")
    with Timer() as t:
        photos = _PhotoCache(rec, images, image_root)
        views, weights, gsd, gains, check, full = _candidate_views(mesh, rec, params, photos)
        seen = views[:, 0] >= 0
        if not seen.any():
            raise StageError(STAGE, "no face is seen by any photo",
                             "check that the mesh and the reconstruction share one frame and unit")
        texel = params.texel_size if params.texel_size is not None else float(np.nanmedian(gsd[seen]))
        order = _corner_order(mesh.vertices[mesh.faces])
        corners = np.take_along_axis(mesh.faces, order, axis=1)  # (right angle, p, q) vertex ids
        legs = None
        if params.texel_size is None:
            legs = _footprint_legs(mesh, rec, views[:, 0], corners, texel)
        atlas = build_atlas(mesh, texel, params, legs)
        # last-resort views see a face grazing or partly hidden: pixels that mix it with the
        # surfaces around it, which the interpolation of neighbouring pixels evens out
        sharp = full & (params.resample == "footprint")
        tex = _blend_photos(mesh, rec, views, weights, seen, atlas, corners, photos, gains, sharp)
        _paint_unseen(tex, mesh, seen, atlas, corners, params)
        texture = np.clip(np.round(tex), 0, 255).astype(np.uint8)
        out = _textured_mesh(mesh, atlas, views, texture)
    step = _texture_record(mesh, rec, params, atlas, views, seen, seen & ~full, t.seconds, gains, check)
    log.info("texture: %dx%d px, texel %.4g, %d of %d faces seen", atlas.width, atlas.height, atlas.texel_size,
             int(seen.sum()), mesh.n_faces)
    return out, step


def _median_texel(longest: np.ndarray, legs: np.ndarray, grow: float, texel: float) -> float:
    """The median surface size of a texel (CRS units) over the faces with texels (``legs`` > 0),
    each face's longest edge over its diagonal in texels; ``texel`` when no face has any."""
    ok = legs > 0
    return grow * float(np.median(longest[ok] / (math.sqrt(2.0) * legs[ok]))) if ok.any() else texel


def _footprint_legs(mesh: Mesh, rec: Reconstruction, view: np.ndarray, corners: np.ndarray,
                    texel: float) -> np.ndarray:
    """(m,) legs, in texels, that make each face's texels no larger than the pixels of its
    view (``view`` (m,) image ids, -1: none) in any direction: the largest singular value of
    the 2 x 2 matrix whose columns are the face's legs (right-angle corner to the two others,
    ``corners`` order) projected into the photo, in pixels (the atlas maps each leg onto that
    many texels, so one texel step spans at most one pixel). A face seen obliquely, or farther
    than the median, gets texels to match; faces without a view: longest edge / (sqrt(2)
    ``texel``), the uniform texel size."""
    from workstation.registration.colorize import project

    tri = mesh.vertices[corners]
    legs = np.linalg.norm(tri - np.roll(tri, 1, axis=1), axis=2).max(axis=1) / (math.sqrt(2.0) * texel)
    for iid in np.unique(view[view >= 0]):
        f = np.flatnonzero(view == iid)
        im = rec.images[int(iid)]
        u, v, _ = project(tri[f].reshape(-1, 3), rec.cameras[im.camera_id], im.pose)
        px = np.stack([u, v], axis=1).reshape(-1, 3, 2)
        M = np.stack([px[:, 1] - px[:, 0], px[:, 2] - px[:, 0]], axis=2)
        legs[f] = np.linalg.svd(M, compute_uv=False)[:, 0]
    return legs


def _candidate_views(mesh: Mesh, rec: Reconstruction, params: TextureParams, photos: "_PhotoCache"):
    """The ``params.max_views`` views of every face (best first), after the exposure balance
    and the photo-consistency check (module description, steps 1, 4 and 5) when asked.

    Returns (views (m, k), weights (m, k), gsd (m,), gains, check, full (m,)): ``gains`` image
    id -> (3,) (empty without the balance), ``check`` a summary of the consistency check (empty
    when off), ``full`` whether the face is textured from full candidate views (False:
    last-resort views or none; a face never mixes the two, :func:`ranked_views` and
    :func:`_preferred_views`)."""
    k, check_on, balance_on = params.max_views, params.photo_consistency, params.exposure_balance
    kc = max(k, CONSISTENCY_VIEWS if check_on else BALANCE_VIEWS)
    # the last-resort views of faces with full ones are kept only for the check to fall back on
    views, weights, gsd, full = ranked_views(mesh, rec, params, kc if check_on or balance_on else k,
                                             keep_last_resort=check_on)
    if not (check_on or balance_on):
        return views, weights, gsd, {}, {}, full.any(axis=1)
    colour = face_colours(mesh, rec, views, photos)
    if not check_on:
        # last-resort views (grazing, partly hidden) blend other surfaces: no part in the balance
        gains = exposure_gains(np.where(full, views, -1)[:, :BALANCE_VIEWS], colour[:, :BALANCE_VIEWS])
        return views[:, :k], weights[:, :k], gsd, gains, {}, full.any(axis=1)
    # the check runs first on the photos as they are (gains estimated over views that show an
    # occluder would spread its colour into every photo's gain), then the gains over the views
    # kept, the check again with them, and the gains once more
    gains = {}
    for _ in range(2 if balance_on else 1):
        g = np.stack([np.ones(3)] + [gains.get(int(i), np.ones(3)) for i in range(int(views.max()) + 1)])
        keep, occluded, check = _consistency_check(mesh, rec, views, full, colour * g[views + 1])
        if balance_on:  # the gains without the occluded views
            good = np.where(keep & full & ~occluded, views, -1)
            gains = exposure_gains(good[:, :BALANCE_VIEWS], colour[:, :BALANCE_VIEWS])
    views, weights, face_full = _preferred_views(views, weights, full, keep, occluded)
    return views[:, :k], weights[:, :k], gsd, gains, check, face_full


def _consistency_check(mesh: Mesh, rec: Reconstruction, views: np.ndarray, full: np.ndarray, balanced: np.ndarray):
    """The photo-consistency check (module description, step 5) on the faces' view colours
    ``balanced`` (m, k, 3, after the current gains): the vote among each face's full views
    (:func:`consistent_views`), the photos' occlusion masks from its outcome
    (:func:`occluded_views`), and the vote again without the views the masks reject.

    Returns (keep (m, k): views the votes keep, occluded (m, k): views the masks reject, check:
    the summary for the step record)."""
    sigma = colour_noise(np.where(full[..., None], balanced, np.nan))
    keep = consistent_views(views, balanced, sigma, eligible=full)
    voted = full & (((views >= 0) & full).sum(axis=1, keepdims=True) >= 3)
    occluded = occluded_views(mesh, rec, views, voted, voted & ~keep)
    keep = consistent_views(views, balanced, sigma, eligible=full & ~occluded) & ~occluded
    dropped = (views >= 0) & ~keep
    check = {"colour_sigma": round(sigma, 3), "views_dropped": int((dropped & full).sum()),
             "views_occluded": int(occluded.sum()), "faces_with_dropped_views": int((dropped & full).any(axis=1).sum())}
    return keep, occluded, check


def _preferred_views(views: np.ndarray, weights: np.ndarray, full: np.ndarray, keep: np.ndarray,
                     occluded: np.ndarray):
    """Each face's views after the photo-consistency check, best first, from the first of these
    tiers that holds one: the full views it keeps; its last-resort views outside the occlusion
    masks; (so that a face some photo sees stays textured) its rejected full views; its
    rejected last-resort views. Within the tier by weight; the views of the other tiers are
    dropped, so a face never mixes full and last-resort views. Returns (views, weights, full
    (m,): whether the face is textured from full views)."""
    tier = np.where(views < 0, 0, np.where(full, np.where(keep, 4, 2), np.where(occluded, 1, 3)))
    best = tier.max(axis=1, keepdims=True)
    use = (tier == best) & (views >= 0)
    views = np.where(use, views, -1)
    weights = np.where(use, weights, 0.0)
    order = np.argsort(-(weights + 1.0) * use, axis=1, kind="stable")
    first = order[:, 0]
    rows = np.arange(len(views))
    return (np.take_along_axis(views, order, axis=1), np.take_along_axis(weights, order, axis=1),
            full[rows, first] & use[rows, first])


class _PhotoCache:
    """The photos' pixels as (h, w, 3) uint8, loaded once each on first use: from ``images``
    when given there, else read from disk; 16-bit photos are scaled to 8 bits (/257)."""

    def __init__(self, rec: Reconstruction, images: Mapping[int, np.ndarray] | None, image_root):
        self.rec, self.images, self.image_root = rec, images, image_root
        self.cache: dict[int, np.ndarray] = {}

    def __call__(self, iid: int) -> np.ndarray:
        from workstation.io.images import read_image

        if iid not in self.cache:
            im = self.rec.images[iid]
            cam = self.rec.cameras[im.camera_id]
            a = self.images[iid] if self.images is not None and iid in self.images else read_image(im, self.image_root)
            if a.shape[0] != cam.height or a.shape[1] != cam.width:
                raise InvalidInputError(f"image {im.name} is {a.shape[1]}x{a.shape[0]} but its camera says "
                                        f"{cam.width}x{cam.height}", field="images")
            if a.dtype != np.uint8:
                a = np.round(a.astype(np.float64) / 257.0).clip(0, 255).astype(np.uint8)
            self.cache[iid] = a[:, :, :3]
        return self.cache[iid]


def _texel_axes(mesh: Mesh, corners: np.ndarray, atlas: Atlas, faces: np.ndarray) -> np.ndarray:
    """(n, 2, 3) the 3-D step of one texel along the atlas's x and y axes on each face of
    ``faces`` (the inverse of the affine map of :func:`_texels_of`)."""
    tri = mesh.vertices[corners[faces]]
    upper = atlas.half[faces] == 1
    leg = atlas.cell[faces].astype(np.float64) - np.where(upper, 3.0, 2.0)
    sign = np.where(upper, -1.0, 1.0) / leg
    return np.stack([tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]], axis=1) * sign[:, None, None]


#: Most sample points per side of a texel's footprint in :func:`_footprint_mean` (a texel
#: spanning more than FOOTPRINT_SAMPLES / 2 pixels is averaged over that many points per side).
FOOTPRINT_SAMPLES = 8
#: Footprint sample points handled at once by :func:`_footprint_mean` (bounds its memory).
FOOTPRINT_CHUNK = 1 << 21


def _footprint_mean(photo: np.ndarray, cam, pose, P: np.ndarray, faces: np.ndarray, cen: np.ndarray,
                    axes: np.ndarray) -> np.ndarray:
    """(n, c) mean colour of a photo over the footprints of texels (centres ``P`` (n, 3) on
    ``faces`` (n,)): the photo is taken as what the sensor recorded, each pixel the mean of the
    scene over its square, so its pixels are squares of constant colour, and each texel gets
    their mean over its own square on the surface (an area-weighted, box-filtered resampling;
    bilinear interpolation would blur every pixel over its neighbours' squares once more).

    The texel's square (one step of ``axes`` (m, 2, 3) along each atlas axis, around its
    centre) maps into the photo as a parallelogram, the projection's derivative at the face's
    centroid (``cen`` (m, 3)) times the steps; it is sampled on a k x k grid, k twice the
    largest pixel offset, along u or v, of either side (1 to ``FOOTPRINT_SAMPLES``), each point taking the pixel it
    falls in. A texel far below a pixel takes the pixel holding its centre."""
    from workstation.registration.colorize import project

    uf, inv = np.unique(faces, return_inverse=True)
    c = cen[uf]
    u, v, _ = project(np.concatenate([c, c + axes[uf, 0], c + axes[uf, 1]]), cam, pose)
    q = np.stack([u, v], axis=1).reshape(3, len(uf), 2)
    jx, jy = (q[1] - q[0])[inv], (q[2] - q[0])[inv]
    u, v, _ = project(P, cam, pose)
    centre = np.stack([u, v], axis=1)
    span = np.maximum(np.abs(jx).max(axis=1), np.abs(jy).max(axis=1))
    # the 1e-6 keeps rounding noise from turning a step of exactly 2 px into k = 5
    k = np.clip(np.ceil(2.0 * span - 1e-6), 1, FOOTPRINT_SAMPLES).astype(np.int64)
    out = np.empty((len(P), photo.shape[2]))
    h, w = photo.shape[:2]
    for kk in np.unique(k):
        t = (np.arange(kk) + 0.5) / kk - 0.5
        gx, gy = (g.reshape(1, -1, 1) for g in np.meshgrid(t, t))
        rows = np.flatnonzero(k == kk)
        per = max(1, FOOTPRINT_CHUNK // int(kk * kk))  # points sampled at once
        for sel in (rows[a:a + per] for a in range(0, rows.size, per)):
            p = centre[sel, None, :] + gx * jx[sel, None, :] + gy * jy[sel, None, :]
            x = np.clip(np.rint(p[..., 0]), 0, w - 1).astype(np.int64)
            y = np.clip(np.rint(p[..., 1]), 0, h - 1).astype(np.int64)
            out[sel] = photo[y, x].astype(np.float64).mean(axis=1)
    return out


def _sample_photo(photo: np.ndarray, cam, pose, P: np.ndarray, faces: np.ndarray, sharp: np.ndarray,
                  cen: np.ndarray, axes: np.ndarray) -> np.ndarray:
    """(n, 3) colours of one photo for the texels at ``P`` (n, 3) on ``faces`` (n,): the mean
    over each texel's footprint (:func:`_footprint_mean`) on the faces ``sharp`` (m,) holds,
    the photo interpolated bilinearly at the texel's centre on the others."""
    from workstation.registration.colorize import bilinear, project

    col = np.empty((len(P), 3))
    box = sharp[faces]
    if box.any():
        col[box] = _footprint_mean(photo, cam, pose, P[box], faces[box], cen, axes)[:, :3]
    if not box.all():
        u, v, _ = project(P[~box], cam, pose)
        col[~box] = bilinear(photo, np.clip(u, 0, cam.width - 1), np.clip(v, 0, cam.height - 1))[:, :3]
    return col


def _blend_photos(mesh: Mesh, rec: Reconstruction, views: np.ndarray, weights: np.ndarray, seen: np.ndarray,
                  atlas: Atlas, corners: np.ndarray, photos: _PhotoCache, gains: Mapping[int, np.ndarray],
                  sharp: np.ndarray) -> np.ndarray:
    """The texture (h, w, 3) float32 of the seen faces: each texel's 3-D point projected into
    the face's selected views, the photos sampled there (:func:`_sample_photo`: the pixels'
    mean over the texel's footprint on the faces ``sharp`` (m,) holds, bilinear interpolation
    at its centre on the others), times their ``gains`` (image id -> (3,); 1 when absent), and
    blended with the views' weights; texels of unseen faces stay 0. Faces are processed per
    atlas cell size in chunks of about 2 million texels to bound memory."""
    tex = np.zeros((atlas.height, atlas.width, 3), dtype=np.float32)
    tex_w = np.zeros((atlas.height, atlas.width), dtype=np.float32)
    chunk = 2_000_000
    axes = _texel_axes(mesh, corners, atlas, np.arange(mesh.n_faces))
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    for c in np.unique(atlas.cell):
        faces_c = np.flatnonzero((atlas.cell == c) & seen)
        per = max(1, chunk // int(c * c))
        for s0 in range(0, faces_c.size, per):
            f, x, y, w = _texels_of(int(c), faces_c[s0:s0 + per], atlas)
            P = np.einsum("nk,nkd->nd", w, mesh.vertices[corners[f]])
            for slot in range(views.shape[1]):
                vid = views[f, slot]
                for iid in np.unique(vid[vid >= 0]):
                    sel = np.flatnonzero(vid == iid)
                    im = rec.images[int(iid)]
                    cam = rec.cameras[im.camera_id]
                    col = _sample_photo(photos(int(iid)), cam, im.pose, P[sel], f[sel], sharp, cen, axes)
                    col *= gains.get(int(iid), 1.0)
                    wt = weights[f[sel], slot]
                    # a texel belongs to one face: indices are unique within one call
                    tex_w[y[sel], x[sel]] += wt
                    tex[y[sel], x[sel]] += col * wt[:, None]
    filled = tex_w > 0
    tex[filled] /= tex_w[filled][:, None]
    return tex


def _paint_unseen(tex: np.ndarray, mesh: Mesh, seen: np.ndarray, atlas: Atlas, corners: np.ndarray,
                  params: TextureParams) -> None:
    """Fill the texels of faces no photo sees (in place): the mesh's vertex colours
    interpolated across the face when it has ``rgb``, else ``params.fallback_rgb``."""
    unseen = np.flatnonzero(~seen)
    if not unseen.size:
        return
    rgb = None
    if "rgb" in mesh.vertex_attrs:
        from workstation.interop.pymeshlab import rgb_to_u8

        rgb = rgb_to_u8(np.asarray(mesh.vertex_attrs["rgb"])).astype(np.float64)
    for c in np.unique(atlas.cell[unseen]):
        f, x, y, w = _texels_of(int(c), unseen[atlas.cell[unseen] == c], atlas)
        if rgb is not None:
            tex[y, x] = np.einsum("nk,nkd->nd", w, rgb[corners[f]])
        else:
            tex[y, x] = np.asarray(params.fallback_rgb, dtype=np.float64)


def _textured_mesh(mesh: Mesh, atlas: Atlas, views: np.ndarray, texture: np.ndarray) -> Mesh:
    """The output mesh: one vertex per face corner (so each corner has its own ``uv``), the
    input's ``normal`` and ``rgb`` carried per corner, face attributes plus ``texture_view``
    and the texture image in ``meta["texture"]``."""
    uv = atlas_uv(mesh, atlas).reshape(-1, 2).astype(np.float32)
    wedge = mesh.faces.reshape(-1)
    vattrs = {"uv": uv}
    for name in ("normal", "rgb"):
        if name in mesh.vertex_attrs:
            vattrs[name] = np.asarray(mesh.vertex_attrs[name])[wedge]
    fattrs = {k: np.asarray(a) for k, a in mesh.face_attrs.items()}
    fattrs["texture_view"] = views[:, 0].astype(np.int32)
    meta = dict(mesh.meta)
    meta["texture"] = texture
    return Mesh(mesh.vertices[wedge], np.arange(3 * mesh.n_faces, dtype=np.int64).reshape(-1, 3), vattrs,
                fattrs, crs=mesh.crs, meta=meta)


def _texture_record(mesh: Mesh, rec: Reconstruction, params: TextureParams, atlas: Atlas, views: np.ndarray,
                    seen: np.ndarray, last: np.ndarray, seconds: float, gains: Mapping[int, np.ndarray],
                    check: Mapping) -> StepRecord:
    """The step record: texel size (mesh units) used and requested, limits, texture size (px),
    faces and area fraction textured (of them, from last-resort views: ``last``), number of
    images and of views used, the range of the exposure gains and the photo-consistency
    check's colour noise and dropped views."""
    area = mesh.face_areas()
    g = np.array(list(gains.values())) if gains else np.ones((1, 3))
    return StepRecord(
        STAGE,
        {"texel_size": atlas.texel_size, "texel_size_requested": params.texel_size,
         "max_texture_size": params.max_texture_size, "max_views": params.max_views, "min_cos": params.min_cos,
         "exposure_balance": params.exposure_balance, "photo_consistency": params.photo_consistency,
         "last_resort": params.last_resort, "resample": params.resample},
        seconds,
        {"texture_width": atlas.width, "texture_height": atlas.height, "images": len(rec.images),
         "faces_textured": int(seen.sum()), "faces": int(mesh.n_faces),
         "area_textured_fraction": float(area[seen].sum() / max(area.sum(), 1e-300)),
         "faces_last_resort": int(last.sum()),
         "area_last_resort_fraction": float(area[last].sum() / max(area.sum(), 1e-300)),
         "views_used": int(np.unique(views[seen, 0]).size),
         "exposure_gain_range": [round(float(g.min()), 4), round(float(g.max()), 4)],
         "photo_consistency": dict(check)},
    )
