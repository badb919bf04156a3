"""Texel sizes from each face's footprint in its photo, and the photos resampled over the
texels' footprints (workstation.mesh.texture, steps 2 and 3 of its description)."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Mesh, Reconstruction
from workstation.mesh.texture import (TextureParams, _corner_order, _footprint_legs, _footprint_mean, _texel_axes,
                                      _texels_of, build_atlas)
from workstation.photogrammetry.rigs import look_at
from workstation.registration.colorize import project


def _camera_at_origin(f: float = 100.0) -> Reconstruction:
    """One 200 x 150 px camera at the origin looking along +y (f pixels)."""
    cam = Camera(200, 150, f, f, 99.5, 74.5)
    return Reconstruction({1: cam}, {1: Image("a.png", 1, look_at(np.zeros(3), np.array([0.0, 10.0, 0.0])))})


def _tilted_wall(n: int = 9) -> Mesh:
    """A 6 x 4 m wall of n x n vertices, its plane y = 10 + 1.5 x (seen obliquely from the
    origin, 5.5-14.5 m away)."""
    x, z = np.meshgrid(np.linspace(-3, 3, n), np.linspace(-2, 2, n), indexing="xy")
    V = np.column_stack([x.ravel(), 10.0 + 1.5 * x.ravel(), z.ravel()])
    i = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.concatenate([np.column_stack([i, i + 1, i + n + 1]), np.column_stack([i, i + n + 1, i + n])])
    return Mesh(V, F)


def _pixel_steps(mesh: Mesh, rec: Reconstruction, atlas, corners: np.ndarray) -> np.ndarray:
    """(m,) pixels spanned by one texel step (the longer of the two atlas axes) at each face's
    centroid, in the reconstruction's only photo."""
    axes = _texel_axes(mesh, corners, atlas, np.arange(mesh.n_faces))
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    im = rec.images[1]
    u, v, _ = project(np.concatenate([cen, cen + axes[:, 0], cen + axes[:, 1]]), rec.cameras[1], im.pose)
    q = np.stack([u, v], axis=1).reshape(3, -1, 2)
    return np.maximum(np.linalg.norm(q[1] - q[0], axis=1), np.linalg.norm(q[2] - q[0], axis=1))


def test_texel_axes_are_the_step_between_neighbouring_texels():
    """For every face, the 3-D points of two texels side by side (as the atlas maps them,
    :func:`_texels_of`) differ by the face's texel step along that atlas axis, in both halves
    of the cells."""
    rng = np.random.default_rng(4)
    V = rng.normal(size=(40, 3))
    F = np.array([rng.choice(40, 3, replace=False) for _ in range(61)])
    mesh = Mesh(V, F)
    atlas = build_atlas(mesh, 0.05, TextureParams(max_cell=32))
    corners = np.take_along_axis(F, _corner_order(V[F]), axis=1)
    axes = _texel_axes(mesh, corners, atlas, np.arange(len(F)))
    owner = np.full((atlas.height, atlas.width), -1)
    point = np.zeros((atlas.height, atlas.width, 3))
    for c in np.unique(atlas.cell):
        f, x, y, w = _texels_of(int(c), np.flatnonzero(atlas.cell == c), atlas)
        inside = w.min(axis=1) > 0  # barycentrics not clipped: the affine map itself
        owner[y[inside], x[inside]] = f[inside]
        point[y[inside], x[inside]] = np.einsum("nk,nkd->nd", w[inside], V[corners[f[inside]]])
    checked = set()
    for axis, (dy, dx) in enumerate(((0, 1), (1, 0))):
        a = owner[: owner.shape[0] - dy, : owner.shape[1] - dx]
        b = owner[dy:, dx:]
        pair = (a >= 0) & (a == b)
        step = point[dy:, dx:][pair] - point[: point.shape[0] - dy, : point.shape[1] - dx][pair]
        assert np.allclose(step, axes[a[pair], axis], atol=1e-9)
        checked |= set(a[pair].tolist())
    assert len(checked) > 0.9 * len(F) and {0, 1} <= set(atlas.half[list(checked)].tolist())


def test_footprint_mean_averages_the_pixels_under_the_texel():
    """A texel spanning 2 x 2 pixels, centred on a pixel corner, takes the mean of those four
    pixels; a texel far below a pixel takes the pixel that holds its centre (not a bilinear
    mix of its neighbours)."""
    rec = _camera_at_origin()  # 0.1 m per pixel at 10 m
    cam, pose = rec.cameras[1], rec.images[1].pose
    R = np.asarray(pose.R)  # rows: the camera's x (right), y (down) and z (forward) axes
    photo = np.random.default_rng(1).integers(0, 256, size=(150, 200, 3)).astype(np.uint8)

    def at(u, v):  # the point 10 m ahead that projects to pixel (u, v)
        return np.asarray(pose.center) + 10 * R[2] + (u - cam.cx) / 10 * R[0] + (v - cam.cy) / 10 * R[1]

    P = at(50.5, 40.5)[None]
    assert np.allclose(np.column_stack(project(P, cam, pose)[:2]), [[50.5, 40.5]])
    two_px = np.stack([0.2 * R[0], 0.2 * R[1]])[None]
    got = _footprint_mean(photo, cam, pose, P, np.array([0]), P, two_px)
    assert np.allclose(got, photo[40:42, 50:52].reshape(-1, 3).mean(axis=0))
    P = at(50.3, 40.2)[None]
    got = _footprint_mean(photo, cam, pose, P, np.array([0]), P, 0.01 * two_px)
    assert np.array_equal(got[0], photo[40, 50].astype(float))


def test_footprint_texels_span_at_most_a_pixel_on_an_oblique_wall():
    """Cells sized from each face's footprint in its photo give texels spanning at most one
    pixel (at the face's centroid; a few per cent over for the perspective across a face) and
    more than 0.3 of one (cells are powers of two), on a wall seen obliquely from 5.5-14.5 m;
    one texel size for all faces (the median ground sample distance) leaves the near faces'
    texels well over a pixel. Under a tight budget the atlas fits by shrinking the cells, no
    face's texels getting finer."""
    rec = _camera_at_origin()
    mesh = _tilted_wall()
    corners = np.take_along_axis(mesh.faces, _corner_order(mesh.vertices[mesh.faces]), axis=1)
    view = np.ones(mesh.n_faces, np.int64)
    depth = project(mesh.vertices[mesh.faces].mean(axis=1), rec.cameras[1], rec.images[1].pose)[2]
    gsd = float(np.median(depth)) / 100.0
    legs = _footprint_legs(mesh, rec, view, corners, gsd)
    atlas = build_atlas(mesh, gsd, TextureParams(), legs)
    steps = _pixel_steps(mesh, rec, atlas, corners)
    assert steps.max() <= 1.03 and steps.min() > 0.3
    uniform = _pixel_steps(mesh, rec, build_atlas(mesh, gsd, TextureParams()), corners)
    assert uniform.max() > 1.2
    small = build_atlas(mesh, gsd, TextureParams(max_texture_size=64), legs)
    assert small.width <= 64 and small.height <= 64
    assert np.all(small.cell <= atlas.cell) and _pixel_steps(mesh, rec, small, corners).max() > 2.0


def test_resample_must_be_known():
    with pytest.raises(InvalidInputError) as e:
        TextureParams(resample="cubic")
    assert e.value.field == "resample"


def test_median_texel_ignores_faces_without_texels():
    # a face whose corners coincide has no texels (legs 0); it must not make the size NaN
    from workstation.mesh.texture import _median_texel

    longest = np.array([2.0, 0.0, 4.0])
    legs = np.array([10.0, 0.0, 20.0])
    assert _median_texel(longest, legs, 1.0, 0.05) == pytest.approx(2.0 / (np.sqrt(2.0) * 10.0))
    assert _median_texel(np.zeros(2), np.zeros(2), 1.0, 0.05) == 0.05
