"""Texture from oriented photos: a synthetic rig with true cameras, texture vs the true surface
colour, atlas invariants and the textured exports (OBJ + MTL + PNG, GLB)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.core.products import Camera, Image, Mesh, Reconstruction
from workstation.mesh.simplify import subdivide_midpoint
from workstation.mesh.texture import TextureParams, build_atlas, atlas_uv, texture_from_photos


@pytest.fixture(scope="module")
def rig():
    """The box-and-wall scene (16 x 12 m wall, 2 m box in front) seen by 5 true pinhole
    cameras 8-12 m away, rendered by ray casting with the procedural surface colour."""
    from workstation.photogrammetry.rigs import box_wall_scene, look_at, render

    V, F, alb = box_wall_scene()
    cam = Camera(200, 150, 190.0, 185.0, 101.0, 73.5)  # fx != fy, off-centre principal point
    images, pix = {}, {}
    for k, x in enumerate(np.linspace(-2.5, 2.5, 5), start=1):
        pose = look_at(np.array([x, 0.0, 0.5 * ((k - 1) % 2)]), np.array([0.0, 10.0, 0.0]))
        images[k] = Image(f"im{k}.png", 1, pose)
        pix[k] = render(V, F, alb, cam, pose, 1)
    Vs, Fs, As = subdivide_midpoint(np.asarray(V, float), F, alb, times=3)
    return Reconstruction({1: cam}, images), pix, Mesh(Vs, Fs), As


def sample_texture(mesh: Mesh, n: int, seed: int = 0):
    """Random points inside the textured faces: (face ids, 3-D points, texture colours)."""
    from workstation.registration.colorize import bilinear

    tex = mesh.meta["texture"]
    h, w = tex.shape[:2]
    rng = np.random.default_rng(seed)
    faces = rng.choice(np.flatnonzero(mesh.face_attrs["texture_view"] >= 0), n)
    bary = rng.dirichlet([2.0, 2.0, 2.0], n)
    P = np.einsum("nk,nkd->nd", bary, mesh.vertices[mesh.faces[faces]])
    uv = np.einsum("nk,nkd->nd", bary, np.asarray(mesh.vertex_attrs["uv"], float)[mesh.faces[faces]])
    return faces, P, bilinear(tex, uv[:, 0] * w - 0.5, (1.0 - uv[:, 1]) * h - 0.5)


def true_colour(mesh: Mesh, faces, P, albedo):
    from workstation.photogrammetry.rigs import surface_colour

    t = mesh.vertices[mesh.faces[faces]]
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    return 255.0 * surface_colour(P, n / np.linalg.norm(n, axis=1, keepdims=True), albedo)


def only_faces(mesh: Mesh, sel) -> Mesh:
    """The textured mesh with ``texture_view`` set to -1 outside ``sel`` (for sample_texture)."""
    return Mesh(mesh.vertices, mesh.faces, mesh.vertex_attrs,
                {"texture_view": np.where(sel, mesh.face_attrs["texture_view"], -1)}, meta=mesh.meta)


def test_texture_matches_true_surface_colour(rig):
    """Texture colour at random points of the faces textured from full candidate views vs the
    scene's true colour there: median absolute error <= 3 and mean <= 8 (of 255; the photos
    blur the 6 cm noise and 1 cm mortar lines the true colour function has, so single points
    differ near edges)."""
    from workstation.mesh.texture import ranked_views

    rec, pix, mesh, albedo = rig
    out, step = texture_from_photos(mesh, rec, TextureParams(), images=pix)
    assert out.n_faces == mesh.n_faces and out.n_vertices == 3 * mesh.n_faces
    assert out.meta["texture"].dtype == np.uint8
    s = step.summary
    assert s["views_used"] >= 3
    assert s["area_textured_fraction"] > 0.5  # the wall's front, the box's visible sides
    full = ranked_views(mesh, rec, TextureParams(), 1)[3][:, 0]
    out = only_faces(out, full)
    faces, P, col = sample_texture(out, 20000)
    err = np.abs(col - true_colour(mesh, faces, P, albedo[faces]))
    assert np.median(err) <= 3.0
    assert err.mean() <= 8.0
    # the same check fails for a texture read upside down (v not flipped)
    tex = out.meta["texture"][::-1]
    flipped = Mesh(out.vertices, out.faces, out.vertex_attrs, out.face_attrs, meta={**out.meta, "texture": tex})
    _, _, col_bad = sample_texture(flipped, 20000)
    assert np.abs(col_bad - true_colour(mesh, faces, P, albedo[faces])).mean() > 2 * err.mean()


def test_footprint_resampling_sharper_than_bilinear_interpolation(rig):
    """The photos resampled over the texels' footprints (the default) keep the texture closer
    to the true colour than the photos interpolated bilinearly at the texel centres (which the
    lookup of the texture blurs once more): median error on the faces with full views at most
    0.9 times the bilinear one, and a lower mean (without the exposure balance and the
    photo-consistency check, which this rig does not need)."""
    from workstation.mesh.texture import ranked_views

    rec, pix, mesh, albedo = rig
    full = ranked_views(mesh, rec, TextureParams(), 1)[3][:, 0]
    errors = {}
    for resample in ("footprint", "bilinear"):
        params = TextureParams(resample=resample, exposure_balance=False, photo_consistency=False)
        out, step = texture_from_photos(mesh, rec, params, images=pix)
        assert step.params["resample"] == resample
        faces, P, col = sample_texture(only_faces(out, full), 20000)
        errors[resample] = np.abs(col - true_colour(mesh, faces, P, albedo[faces]))
    assert np.median(errors["footprint"]) <= 0.9 * np.median(errors["bilinear"])
    assert errors["footprint"].mean() < errors["bilinear"].mean()


def test_texture_hidden_faces_not_painted(rig):
    """The wall behind the box is hidden from every camera (|x| < 0.7 m, |z| < 1 m on the wall,
    from the cameras at x = -2.5..2.5 m): faces there get no view, and the box's back face
    (facing away from all cameras) neither."""
    rec, pix, mesh, _ = rig
    out, _ = texture_from_photos(mesh, rec, TextureParams(), images=pix)
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    view = out.face_attrs["texture_view"]
    behind_box = (np.abs(cen[:, 1] - 12) < 1e-9) & (np.abs(cen[:, 0]) < 0.7) & (np.abs(cen[:, 2]) < 1.0)
    box_back = (np.abs(cen[:, 1] - 10) < 1e-9) & (np.abs(cen[:, 0]) < 1) & (np.abs(cen[:, 2]) < 1)
    assert behind_box.sum() > 0 and box_back.sum() > 0
    assert np.all(view[behind_box] == -1)
    assert np.all(view[box_back] == -1)
    box_front = (np.abs(cen[:, 1] - 8) < 1e-9) & (np.abs(cen[:, 0]) < 1) & (np.abs(cen[:, 2]) < 1)
    assert np.all(view[box_front] >= 1)


def test_last_resort_views_texture_grazing_faces(rig):
    """The box's sides are seen only at grazing angles (cosine < 0.2, min_cos) by the cameras
    beside it: without last-resort views they stay untextured, with them (the default) they
    take a grazing view, with a bounded error (median <= 8 of 255: each pixel spans up to six
    times its frontal footprint there); the faces with full views keep their views, and the
    faces hidden from every camera stay untextured."""
    from workstation.mesh.texture import ranked_views

    rec, pix, mesh, albedo = rig
    strict, s_step = texture_from_photos(mesh, rec, TextureParams(last_resort=False), images=pix)
    out, step = texture_from_photos(mesh, rec, TextureParams(), images=pix)
    assert s_step.summary["faces_last_resort"] == 0 and step.summary["faces_last_resort"] > 0
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    box_side = (np.abs(np.abs(cen[:, 0]) - 1) < 1e-9) & (np.abs(cen[:, 1] - 9) < 1) & (np.abs(cen[:, 2]) < 1)
    assert box_side.sum() > 0
    assert np.all(strict.face_attrs["texture_view"][box_side] == -1)
    assert (out.face_attrs["texture_view"][box_side] >= 1).mean() > 0.9
    full = ranked_views(mesh, rec, TextureParams(), 1)[3][:, 0]
    assert np.array_equal(out.face_attrs["texture_view"][full], strict.face_attrs["texture_view"][full])
    assert np.all(out.face_attrs["texture_view"][strict.face_attrs["texture_view"] >= 0] >= 1)
    faces, P, col = sample_texture(only_faces(out, box_side), 20000)
    assert np.median(np.abs(col - true_colour(mesh, faces, P, albedo[faces]))) <= 8.0
    behind_box = (np.abs(cen[:, 1] - 12) < 1e-9) & (np.abs(cen[:, 0]) < 0.7) & (np.abs(cen[:, 2]) < 1.0)
    assert np.all(out.face_attrs["texture_view"][behind_box] == -1)


def test_texture_blending_two_views(rig):
    """Two views blended per face: the faces with full views keep a median error <= 3."""
    from workstation.mesh.texture import ranked_views

    rec, pix, mesh, albedo = rig
    out, _ = texture_from_photos(mesh, rec, TextureParams(max_views=2), images=pix)
    full = ranked_views(mesh, rec, TextureParams(), 1)[3][:, 0]
    faces, P, col = sample_texture(only_faces(out, full), 20000, seed=1)
    assert np.median(np.abs(col - true_colour(mesh, faces, P, albedo[faces]))) <= 3.0


def test_exposure_balance_evens_out_unequal_photos(rig):
    """Photos with per-channel gains from U(0.8, 1.2): the estimated gains undo most of their
    spread (the product true x estimated gain varies 3x less than the true gains), and the
    texture, up to one global gain per channel, is closer to the true colour than without the
    balance. On equal photos the gains stay within 1 % of 1."""
    from workstation.mesh.texture import _PhotoCache, select_views
    from workstation.mesh.texture_colour import exposure_gains, face_colours

    rec, pix, mesh, albedo = rig
    views, _, _ = select_views(mesh, rec, TextureParams(last_resort=False), 4)  # as the texture's balance uses
    equal = exposure_gains(views, face_colours(mesh, rec, views, _PhotoCache(rec, pix, None)))
    assert np.abs(np.array(list(equal.values())) - 1).max() < 0.01
    g = {k: np.random.default_rng(3).uniform(0.8, 1.2, 3) * (1 + 0.05 * k) for k in pix}
    uneven = {k: np.clip(np.round(v * g[k]), 0, 255).astype(np.uint8) for k, v in pix.items()}
    est = exposure_gains(views, face_colours(mesh, rec, views, _PhotoCache(rec, uneven, None)))
    G, E = np.array([g[k] for k in sorted(g)]), np.array([est[k] for k in sorted(g)])
    spread = lambda a: (a.std(axis=0) / a.mean(axis=0)).mean()
    assert spread(G * E) < spread(G) / 3
    errors = []
    for balance in (False, True):
        out, _ = texture_from_photos(mesh, rec, TextureParams(exposure_balance=balance), images=uneven)
        faces, P, col = sample_texture(out, 20000)
        truth = true_colour(mesh, faces, P, albedo[faces])
        errors.append(np.median(np.abs(col * (col * truth).sum(0) / (col * col).sum(0) - truth)))
    assert errors[1] < 0.75 * errors[0], errors


def test_consistent_views_drops_the_odd_colour_out():
    """Five views of a face, one of them far off (an occluder): it alone is dropped, whatever
    slot it holds; a face with two views keeps both; views within the radius stay."""
    from workstation.mesh.texture_colour import consistent_views

    rng = np.random.default_rng(0)
    colour = 120 + rng.normal(0, 1, (6, 5, 3))
    colour[np.arange(5), np.arange(5)] = [60, 150, 30]  # face i: view slot i shows a green branch
    views = np.tile(np.arange(1, 6), (6, 1))
    views[5, 2:] = -1  # face 5: two views only (both kept, the first odd)
    keep = consistent_views(views, colour, sigma=1.0)
    expect = np.ones((6, 5), bool)
    expect[np.arange(5), np.arange(5)] = False
    expect[5, 2:] = False
    assert np.array_equal(keep, expect)


def _photos_with_green_box(rec):
    """The box rig's photos with a green box (not in the mesh) in front of the wall, and the
    box's vertices and faces."""
    from workstation.photogrammetry.rigs import box_wall_scene, render

    V, F, alb = box_wall_scene()
    cube = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], float)
    bv, bf = np.array([1.0, 5.0, 1.0]) + 0.5 * cube * [0.8, 0.4, 0.6], F[2:] - 4
    Vo, Fo = np.vstack([V, bv]), np.vstack([F, bf + len(V)])
    Ao = np.vstack([alb, np.tile([0.25, 0.55, 0.1], (len(bf), 1))])
    return {k: render(Vo, Fo, Ao, rec.cameras[1], im.pose, 1) for k, im in rec.images.items()}, (bv, bf)


def test_photo_consistency_removes_an_occluder_missing_from_the_mesh(rig):
    """The rig's photos taken with a green box (a "branch", 0.8 x 0.4 x 0.6 m, 5 m in front of
    the cameras) that the textured mesh lacks: on the wall faces it hides from some of their
    views the branch's colour is painted without the check (mean error > 15 of 255) and mostly
    gone with it (error < 1/3 of that, near the plain rig's); on the plain rig's photos the check
    costs nothing (mean error within 2 % of that without it)."""
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.mesh.texture import select_views
    rec, pix, mesh, albedo = rig
    occluded, (bv, bf) = _photos_with_green_box(rec)
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    views, _, _ = select_views(mesh, rec, TextureParams(last_resort=False), 5)  # faces with full views
    hidden = np.zeros(mesh.n_faces, bool)
    for iid, im in rec.images.items():  # faces whose centroid the branch hides from a view of theirs
        d = cen - im.pose.center
        dl = np.linalg.norm(d, axis=1)
        t, _ = RaycastScene(bv, bf).cast(np.broadcast_to(im.pose.center, d.shape), d / dl[:, None])
        hidden |= (t < dl) & (views == iid).any(axis=1)
    assert hidden.sum() >= 8

    def mean_error(photos, check, sel):
        out, step = texture_from_photos(mesh, rec, TextureParams(photo_consistency=check), images=photos)
        m = Mesh(out.vertices, out.faces, out.vertex_attrs,
                 {"texture_view": np.where(sel, out.face_attrs["texture_view"], -1)}, meta=out.meta)
        faces, P, col = sample_texture(m, 20000)
        return np.abs(col - true_colour(mesh, faces, P, albedo[faces])).mean(), step.summary

    off, _ = mean_error(occluded, False, hidden)
    on, summary = mean_error(occluded, True, hidden)
    assert summary["photo_consistency"]["views_dropped"] > 0
    assert off > 15 and on < off / 3, (off, on)
    everywhere = np.ones(mesh.n_faces, bool)
    plain_off, _ = mean_error(pix, False, everywhere)
    plain_on, _ = mean_error(pix, True, everywhere)
    assert plain_on <= 1.02 * plain_off, (plain_off, plain_on)


def test_occlusion_mask_spreads_the_votes_to_faces_without_a_majority():
    """A wall seen frontally by one photo in which an occluder (a disc 1 m across, a tree's
    crown) hides some faces: the voting faces lose that view inside the disc. Faces with too
    few views to vote (every third face) are rejected there too, and so is a face one of whose
    sample points lies on the disc; faces away from it keep the view whether they voted or not."""
    from workstation.mesh.texture_colour import occluded_views
    from workstation.photogrammetry.rigs import look_at

    x, z = np.meshgrid(np.linspace(-4, 4, 41), np.linspace(-3, 3, 31), indexing="xy")
    V = np.column_stack([x.ravel(), np.full(x.size, 10.0), z.ravel()])
    i = (np.arange(30)[:, None] * 41 + np.arange(40)[None, :]).ravel()
    F = np.concatenate([np.column_stack([i, i + 1, i + 42]), np.column_stack([i, i + 42, i + 41])])
    mesh = Mesh(V, F)
    rec = Reconstruction({1: Camera(200, 150, 190.0, 185.0, 100.0, 75.0)},
                         {1: Image("a.png", 1, look_at(np.zeros(3), np.array([0.0, 10.0, 0.0])))})
    tri = V[F]
    cen = tri.mean(axis=1)
    r_in = np.linalg.norm(cen[:, [0, 2]] - [1.0, 0.5], axis=1)
    r_far = np.linalg.norm(tri[:, :, [0, 2]] - [1.0, 0.5], axis=2).min(axis=1)  # nearest corner
    views = np.ones((len(F), 1), np.int64)
    voted = (np.arange(len(F)) % 3 != 0)[:, None]
    dropped = voted & (r_in < 1.0)[:, None]
    occ = occluded_views(mesh, rec, views, voted, dropped)[:, 0]
    inside, outside = r_in < 0.8, r_far > 1.6  # 1.6 m: beyond the 9 px pooling box (0.47 m here)
    assert (inside & ~voted[:, 0]).sum() > 10 and (outside & ~voted[:, 0]).sum() > 100
    assert occ[inside].all()
    assert not occ[outside].any()
    straddle = (r_in > 1.0) & (r_far < 0.9)  # centroid outside the disc, a corner well inside
    assert straddle.any() and occ[straddle].all()
    assert not occluded_views(mesh, rec, views, voted, np.zeros_like(voted)).any()


def test_occluder_colour_kept_off_faces_without_a_majority(rig):
    """The rig's photos with the green "branch" of the test above: no face is textured from a
    view in which the branch hides its centroid, including the faces the branch hides that have
    fewer than three full views (seen only at grazing angles), which cannot vote on their own
    and take their colour from the occlusion masks of their neighbours' votes."""
    from workstation.interop.open3d_raycast import RaycastScene
    from workstation.mesh.texture import select_views
    rec, pix, mesh, albedo = rig
    photos, (bv, bf) = _photos_with_green_box(rec)
    out, step = texture_from_photos(mesh, rec, TextureParams(), images=photos)
    view = out.face_attrs["texture_view"]
    cen = mesh.vertices[mesh.faces].mean(axis=1)
    full = (select_views(mesh, rec, TextureParams(last_resort=False), 8)[0] >= 0).sum(axis=1)
    hides = np.zeros((mesh.n_faces, 6), bool)  # [face, image id]: the branch hides the centroid
    for iid, im in rec.images.items():
        d = cen - im.pose.center
        dl = np.linalg.norm(d, axis=1)
        hides[:, iid] = RaycastScene(bv, bf).cast(np.broadcast_to(im.pose.center, d.shape), d / dl[:, None])[0] < dl
    seen = view >= 1
    few = seen & (full < 3) & hides[:, 1:].any(axis=1)
    assert few.sum() >= 2 and step.summary["photo_consistency"]["views_occluded"] > 0
    assert not hides[np.flatnonzero(seen), view[seen]].any()


def test_atlas_cells_disjoint_and_in_bounds():
    """Every face's texels lie inside the texture, and no texel belongs to two faces."""
    from workstation.mesh.texture import _texels_of

    rng = np.random.default_rng(3)
    V = rng.normal(size=(60, 3))
    F = np.array([rng.choice(60, 3, replace=False) for _ in range(101)])
    mesh = Mesh(V, F)
    atlas = build_atlas(mesh, 0.05, TextureParams(max_cell=32))
    owner = np.full((atlas.height, atlas.width), -1)
    for c in np.unique(atlas.cell):
        f, x, y, w = _texels_of(int(c), np.flatnonzero(atlas.cell == c), atlas)
        assert x.max() < atlas.width and y.max() < atlas.height and x.min() >= 0 and y.min() >= 0
        assert np.all(owner[y, x] == -1)
        owner[y, x] = f
        assert np.allclose(w.sum(axis=1), 1.0) and w.min() >= 0
    assert set(np.unique(owner[owner >= 0])) == set(range(len(F)))
    uv = atlas_uv(mesh, atlas)
    assert uv.min() > 0 and uv.max() < 1
    # each corner's texture point lies inside its own face's texels (bilinear never crosses)
    xy = np.stack([uv[..., 0] * atlas.width, (1 - uv[..., 1]) * atlas.height], -1)
    for f in range(len(F)):
        cx = np.floor(xy[f, :, 0] - 0.5).astype(int)
        cy = np.floor(xy[f, :, 1] - 0.5).astype(int)
        for dx in (0, 1):
            for dy in (0, 1):
                x = np.clip(cx + dx, 0, atlas.width - 1)
                y = np.clip(cy + dy, 0, atlas.height - 1)
                # a neighbour with a non-zero bilinear weight must be the face's own texel
                wx = np.abs(xy[f, :, 0] - 0.5 - (cx + dx)) < 1 - 1e-9
                wy = np.abs(xy[f, :, 1] - 0.5 - (cy + dy)) < 1 - 1e-9
                used = wx & wy
                assert np.all(owner[y[used], x[used]] == f)


def test_atlas_respects_budget():
    rng = np.random.default_rng(0)
    V = rng.uniform(0, 10, size=(3000, 3))
    F = rng.integers(0, 3000, size=(4000, 3))
    F = F[(F[:, 0] != F[:, 1]) & (F[:, 1] != F[:, 2]) & (F[:, 0] != F[:, 2])]
    atlas = build_atlas(Mesh(V, F), 0.001, TextureParams(max_texture_size=512))
    assert atlas.width <= 512 and atlas.height <= 512
    assert atlas.texel_size > 0.001


def test_textured_exports_roundtrip(rig, tmp_path):
    """OBJ (+ MTL + PNG) and GLB keep the texture coordinates and the image: the colour looked
    up through the file's UVs equals the colour looked up in memory."""
    from workstation.io.mesh import read_mesh, write_mesh

    rec, pix, mesh, _ = rig
    out, _ = texture_from_photos(mesh, rec, TextureParams(), images=pix)
    faces = np.flatnonzero(out.face_attrs["texture_view"] >= 0)[:500]
    for ext in ("obj", "glb"):
        path = write_mesh(out, tmp_path / f"textured.{ext}")
        back = read_mesh(path)
        assert back.n_faces == out.n_faces
        assert back.meta["texture"].shape == out.meta["texture"].shape
        # vertices may be reordered by the reader: match faces by their centroids
        from scipy.spatial import cKDTree

        cen_b = back.vertices[back.faces].mean(axis=1)
        cen_o = out.vertices[out.faces].mean(axis=1)
        d, j = cKDTree(cen_b).query(cen_o[faces])
        assert d.max() < 1e-5
        vo = out.vertices[out.faces[faces]]
        vb = back.vertices[back.faces[j]]
        perm = np.argmin(np.linalg.norm(vo[:, :, None] - vb[:, None], axis=3), axis=2)  # corner i of o -> of b
        uv_b = np.asarray(back.vertex_attrs["uv"], float)[back.faces[j]]
        uv_b = np.take_along_axis(uv_b, perm[:, :, None], axis=1)
        uv_o = np.asarray(out.vertex_attrs["uv"], float)[out.faces[faces]]
        assert np.abs(uv_b - uv_o).max() < 1e-5
        assert np.array_equal(back.meta["texture"], out.meta["texture"])
    assert (tmp_path / "textured.mtl").exists()
    assert any(p.suffix == ".png" for p in tmp_path.iterdir())


def test_ws_mesh_with_reconstruction_writes_textured_obj_and_glb(tmp_path, capsys):
    """`ws mesh CLOUD --method delaunay25d --reconstruction WORKDIR -o OUT.obj`: a terrain patch
    seen by three near-nadir cameras (COLMAP text model + PNG photos); the texture read back
    from OUT.obj matches the true ground colour, and a PLY output is refused."""
    import cv2

    from workstation.cli.main import main
    from workstation.core.cloud import Cloud
    from workstation.io import write_cloud
    from workstation.io.mesh import read_mesh
    from workstation.photogrammetry.rigs import look_at, render, write_colmap_text

    x, y = np.meshgrid(np.linspace(-10, 10, 41), np.linspace(-10, 10, 41))
    z = 0.4 * np.sin(x / 3.0) + 0.2 * np.cos(y / 4.0)
    V = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    i = np.arange(40 * 40)
    r, c = np.divmod(i, 40)
    a = r * 41 + c
    F = np.concatenate([np.stack([a, a + 1, a + 42], 1), np.stack([a, a + 42, a + 41], 1)])
    albedo = np.full((len(F), 3), [0.8, 0.7, 0.5])
    cam = Camera(160, 120, 110.0, 110.0, 79.5, 59.5)
    (tmp_path / "work" / "images").mkdir(parents=True)
    images = {}
    for k, cx in enumerate((-4.0, 0.0, 4.0), start=1):
        pose = look_at(np.array([cx, -1.0, 16.0]), np.array([cx * 0.5, 0.0, 0.0]))
        cv2.imwrite(str(tmp_path / "work" / "images" / f"im{k}.png"), render(V, F, albedo, cam, pose, 1)[:, :, ::-1])
        images[k] = Image(f"im{k}.png", 1, pose)
    write_colmap_text(Reconstruction({1: cam}, images), tmp_path / "work" / "sparse" / "0")
    write_cloud(Cloud(V), tmp_path / "ground.ply")
    out = tmp_path / "ground_tex.obj"
    rc = main(["mesh", str(tmp_path / "ground.ply"), "-o", str(out), "--method", "delaunay25d", "--no-quality",
               "--reconstruction", str(tmp_path / "work"), "--json"])
    assert rc == 0
    doc = json.loads(capsys.readouterr().out)
    tex_step = next(s for s in doc["steps"] if s["name"] == "texture")
    assert tex_step["summary"]["faces_textured"] > 0.5 * len(F)
    back = read_mesh(out)
    assert (tmp_path / "ground_tex.mtl").exists() and "texture" in back.meta
    m = Mesh(back.vertices, back.faces, back.vertex_attrs,
             {"texture_view": np.zeros(back.n_faces, np.int32)}, meta=back.meta)
    faces, P, col = sample_texture(m, 5000)
    tri = m.vertices[m.faces[faces]]
    # keep samples on faces that a photo saw whole (inside the central, overlapped area)
    inner = np.abs(P[:, :2]).max(axis=1) < 5
    from workstation.photogrammetry.rigs import surface_colour

    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    n *= np.sign(n[:, 2:3]) / np.linalg.norm(n, axis=1, keepdims=True)
    truth = 255 * surface_colour(P, n, np.full((len(P), 3), [0.8, 0.7, 0.5]))
    err = np.abs(col - truth)[inner]
    assert inner.sum() > 1000 and np.median(err) <= 4.0
    rc = main(["mesh", str(tmp_path / "ground.ply"), "-o", str(tmp_path / "g.glb"), "--method", "delaunay25d",
               "--no-quality", "--reconstruction", str(tmp_path / "work")])
    assert rc == 0 and "texture" in read_mesh(tmp_path / "g.glb").meta
    rc = main(["mesh", str(tmp_path / "ground.ply"), "-o", str(tmp_path / "g.ply"), "--method", "delaunay25d",
               "--reconstruction", str(tmp_path / "work")])
    assert rc == 1 and not (tmp_path / "g.ply").exists()


def test_textured_render_through_a_photo_camera_reproduces_the_photo(rig):
    """The textured mesh rendered off-screen through camera 3 (unlit texture) gives back photo 3
    where the surface is textured: mean absolute difference <= 8 of 255 (texel resampling,
    the render's own filtering); an untextured render differs far more."""
    from workstation.render import RenderParams, render

    rec, pix, mesh, _ = rig
    out, _ = texture_from_photos(mesh, rec, TextureParams(), images=pix)
    view = (rec.cameras[1], rec.images[3].pose)
    img = render(out, RenderParams(background="black"), camera=view).astype(float)
    seen = Mesh(out.vertices, out.faces[out.face_attrs["texture_view"] >= 0])
    mask = render(seen, RenderParams(background="black", color="uniform"), camera=view).max(axis=2) > 0
    from scipy.ndimage import binary_erosion

    mask = binary_erosion(mask, iterations=2)  # away from silhouette and seam edges
    assert mask.mean() > 0.3
    diff = np.abs(img - pix[3].astype(float))[mask].mean()
    assert diff <= 8.0
    plain = render(mesh, RenderParams(background="black", color="uniform"), camera=view).astype(float)
    assert np.abs(plain - pix[3].astype(float))[mask].mean() > 2 * diff


def test_faces_far_below_a_pixel_keep_their_weight(rig):
    """A face covering a small fraction of a pixel still weighs its projected area: every slot
    holding a view has a positive weight (a rank that adds a large offset to the area rounds
    such areas to zero, and the blend then paints the face black). The rig's cameras at a
    quarter of their size (40 x 30 pixels), the mesh subdivided 64-fold."""
    from dataclasses import replace

    from workstation.core.products import Reconstruction
    from workstation.mesh.simplify import subdivide_midpoint
    from workstation.mesh.texture import ranked_views

    rec, _, mesh, _ = rig
    small = {cid: replace(c, width=c.width // 4, height=c.height // 4, fx=c.fx / 4, fy=c.fy / 4,
                          cx=(c.cx + 0.5) / 4 - 0.5, cy=(c.cy + 0.5) / 4 - 0.5) for cid, c in rec.cameras.items()}
    V, F = subdivide_midpoint(mesh.vertices, mesh.faces, times=3)[:2]
    views, weights, _, full = ranked_views(Mesh(V, F), Reconstruction(small, rec.images), TextureParams(), 2)
    held = views >= 0
    assert held.any() and (weights[held] > 0).all()
    assert (weights[full] < 1 / 16).any()  # faces well under a pixel


def _frontal_wall(n_x: int = 41, n_z: int = 31):
    """A 8 x 6 m wall of n_x x n_z vertices 10 m in front of one 200 x 150 px camera looking at
    it frontally: (mesh, reconstruction)."""
    from workstation.photogrammetry.rigs import look_at

    x, z = np.meshgrid(np.linspace(-4, 4, n_x), np.linspace(-3, 3, n_z), indexing="xy")
    V = np.column_stack([x.ravel(), np.full(x.size, 10.0), z.ravel()])
    i = (np.arange(n_z - 1)[:, None] * n_x + np.arange(n_x - 1)[None, :]).ravel()
    F = np.concatenate([np.column_stack([i, i + 1, i + n_x + 1]), np.column_stack([i, i + n_x + 1, i + n_x])])
    rec = Reconstruction({1: Camera(200, 150, 190.0, 185.0, 100.0, 75.0)},
                         {1: Image("a.png", 1, look_at(np.zeros(3), np.array([0.0, 10.0, 0.0])))})
    return Mesh(V, F), rec


def test_occlusion_mask_counts_votes_exactly_and_spares_ties():
    """Every face votes, dropped and kept alternating in a fine checkerboard, so that many
    pixels' boxes hold exactly as many dropped as kept votes: the mask equals the one from an
    integer reference count (a 9 x 9 box of ones convolved with the per-pixel votes), in which
    a view is occluded only where the dropped votes strictly outnumber the kept ones at one of
    its sample points; ties, present by the hundred (420 sample points), are never occluded."""
    from scipy.signal import convolve2d

    from workstation.mesh.texture_colour import OCCLUSION_WINDOW, occluded_views, view_samples

    mesh, rec = _frontal_wall(81, 61)
    m = mesh.n_faces
    views = np.ones((m, 1), np.int64)
    voted = np.ones((m, 1), bool)
    rng = np.random.default_rng(5)
    dropped = (rng.random((m, 1)) < 0.5) & voted
    cam = rec.cameras[1]
    (f, s, u, v), = view_samples(mesh, rec, views, 1)
    x, y = np.rint(u).astype(int), np.rint(v).astype(int)
    count = np.zeros((2, cam.height, cam.width), np.int64)
    for c, sel in enumerate((dropped[f, s], ~dropped[f, s])):
        np.add.at(count[c], (y[sel].ravel(), x[sel].ravel()), 1)
    box = np.ones((OCCLUSION_WINDOW, OCCLUSION_WINDOW), np.int64)
    dr, kept = (convolve2d(c, box, mode="same") for c in count)
    ties = (dr == kept) & (dr > 0)
    assert ties[y, x].sum() > 200
    expect = np.zeros((m, 1), bool)
    expect[f, s] = (dr > kept)[y, x].any(axis=1)
    occ = occluded_views(mesh, rec, views, voted, dropped)
    assert 0 < expect.sum() < m
    assert np.array_equal(occ, expect)


@pytest.mark.parametrize("max_views", [3, 8])
def test_faces_with_full_views_never_blend_last_resort_views(rig, max_views):
    """With the photo-consistency check on (for any ``max_views``, also at or above the check's
    8 candidate views), every face is textured either from full candidate views only or from
    last-resort views only, and the flag ``full`` says which."""
    from workstation.mesh.texture import _PhotoCache, _candidate_views, ranked_views

    rec, pix, mesh, _ = rig
    params = TextureParams(max_views=max_views)
    views, weights, _, _, check, full = _candidate_views(mesh, rec, params, _PhotoCache(rec, pix, None))
    assert check and views.shape[1] == max_views
    candidates = ranked_views(mesh, rec, TextureParams(last_resort=False), 8)[0]
    used = views >= 0
    is_full = (views[:, :, None] == candidates[:, None, :]).any(axis=2) & used
    assert (used.sum(axis=1) >= 2).sum() > 100 and (used & ~is_full).any()
    assert np.array_equal(is_full.sum(axis=1), np.where(full, used.sum(axis=1), 0))
    assert np.all(weights[used] > 0) and np.all(weights[~used] == 0)


def test_preferred_views_tiers_never_mix_full_and_last_resort_views():
    """Each face takes the first non-empty tier: full views kept, last-resort views outside the
    masks, rejected full views, rejected last-resort views; best weight first, nothing else."""
    from workstation.mesh.texture import _preferred_views

    views = np.array([[1, 2, 3], [1, 2, 3], [1, 2, 3], [1, 2, -1]])
    weights = np.array([[5.0, 9.0, 7.0], [5.0, 9.0, 7.0], [5.0, 9.0, 7.0], [5.0, 9.0, 0.0]])
    full = np.array([[True, True, False]] * 3 + [[False, False, False]])
    keep = np.array([[True, False, True], [False, False, True], [False, False, True], [True, True, False]])
    occluded = np.array([[False, False, False], [False, False, False], [False, False, True], [True, False, False]])
    v, w, f = _preferred_views(views, weights, full, keep, occluded)
    assert v.tolist() == [[1, -1, -1], [3, -1, -1], [2, 1, -1], [2, -1, -1]]
    assert w.tolist() == [[5.0, 0, 0], [7.0, 0, 0], [9.0, 5.0, 0], [9.0, 0, 0]]
    assert f.tolist() == [True, False, True, False]
    v, _, f = _preferred_views(views[3:], weights[3:], full[3:], keep[3:], np.ones((1, 3), bool))
    assert v.tolist() == [[2, 1, -1]] and f.tolist() == [False]
