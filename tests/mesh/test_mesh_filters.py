"""Meshing stages on tiny synthetic shapes with known answers (sphere, plane, terrain)."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.products import Mesh
from workstation.mesh import (BallPivotingParams, CleanParams, ColorTransferParams, DecimateParams, Delaunay25dParams,
                              MeshChainParams, NormalParams, PoissonParams, QualityParams, SmoothParams,
                              ball_pivoting, clean, decimate, delaunay25d, estimate_normals, mesh_cloud, mesh_quality,
                              point_spacing, poisson, smooth, transfer_colors)
from workstation.mesh.quality import local_plane_distance, nearest_point_floor

R = 2.0
CENTRE = np.array([500_000.0, 4_000_000.0, 100.0])  # projected coordinates: origin handling matters


def sphere_points(n=4000, seed=0, noise=0.0):
    """Quasi-uniform points on a sphere (Fibonacci lattice) in UTM-like coordinates."""
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    th = np.pi * (1 + 5 ** 0.5) * i
    u = np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    r = R + (np.random.default_rng(seed).normal(0, noise, n) if noise else 0)
    return CENTRE + u * np.asarray(r).reshape(-1, 1), u


def icosphere(subdiv=3) -> Mesh:
    import pymeshlab

    ms = pymeshlab.MeshSet()
    ms.create_sphere(radius=R, subdiv=subdiv)
    m = ms.current_mesh()
    return Mesh(m.vertex_matrix() + CENTRE, m.face_matrix())


@pytest.fixture(scope="module")
def sphere_cloud():
    xyz, _ = sphere_points()
    return Cloud(xyz, crs="EPSG:32632")


@pytest.fixture(scope="module")
def sphere_poisson(sphere_cloud):
    oriented, _ = estimate_normals(sphere_cloud, NormalParams(k=10), viewpoints=None)
    return poisson(oriented, PoissonParams(depth=6, trim_quantile=0.0, threads=1))


def test_point_spacing_of_a_grid():
    g = np.stack(np.meshgrid(np.arange(50) * 0.25, np.arange(40) * 0.25), -1).reshape(-1, 2)
    xyz = np.column_stack([g, np.zeros(len(g))])
    assert point_spacing(xyz) == pytest.approx(0.25)


@pytest.mark.parametrize("offset", [(0.0, 0.0, 0.0), (3.7, -1.2, 0.4), tuple(CENTRE)])
def test_point_spacing_with_a_callers_centred_tree_is_the_same_number(offset):
    """A caller's tree of the centred points finds the neighbours; the distances stay those of
    the points themselves, to the last bit (duplicates and a rounded grid's ties included)."""
    from workstation.mesh.reconstruct import centred_tree

    rng = np.random.default_rng(7)
    for scale, n in ((0.05, 30_000), (7.0, 3_000), (60.0, 25_000)):
        xyz = rng.normal(size=(n, 3)) * scale + offset
        for pts in (xyz, np.vstack([xyz, xyz[: n // 3]]), np.round(xyz, 1)):
            assert point_spacing(pts, tree=centred_tree(pts)) == point_spacing(pts)


def test_normals_propagated_consistently_and_toward_viewpoint(sphere_cloud):
    c, rec = estimate_normals(sphere_cloud, NormalParams(k=10))
    n = np.asarray(c.attrs["normal"], dtype=float)
    radial = (sphere_cloud.xyz - CENTRE) / R
    dots = np.einsum("ij,ij->i", n, radial)
    assert np.all(np.abs(dots) > 0.95)  # PCA fit of a sphere
    # propagation: one sign everywhere
    assert max((dots > 0).mean(), (dots < 0).mean()) > 0.99
    assert "normal" not in sphere_cloud.attrs  # input unchanged
    # toward a viewpoint inside the sphere: every normal points inward
    inner, rec = estimate_normals(sphere_cloud, NormalParams(k=10, recompute=True), viewpoints=CENTRE)
    assert rec.params["orient"] == "viewpoint"
    assert np.all(np.einsum("ij,ij->i", np.asarray(inner.attrs["normal"], float), radial) < 0)


def test_normals_up_and_per_point_viewpoints():
    rng = np.random.default_rng(1)
    xyz = np.column_stack([rng.uniform(0, 10, 500), rng.uniform(0, 10, 500), 0.01 * rng.normal(size=500)])
    up, _ = estimate_normals(Cloud(xyz), NormalParams(k=12, orient="up"))
    assert np.all(np.asarray(up.attrs["normal"])[:, 2] > 0.9)
    vp = np.where((np.arange(500) % 2 == 0)[:, None], [5, 5, -10.0], [5, 5, 10.0])
    c, _ = estimate_normals(Cloud(xyz), NormalParams(k=12), viewpoints=vp)
    nz = np.asarray(c.attrs["normal"])[:, 2]
    assert np.all(nz[::2] < -0.9) and np.all(nz[1::2] > 0.9)
    with pytest.raises(InvalidInputError):
        estimate_normals(Cloud(xyz), NormalParams(orient="viewpoint"))


def test_poisson_sphere_is_closed_with_the_right_volume(sphere_poisson, sphere_cloud):
    mesh, rec = sphere_poisson
    assert rec.name == "poisson" and rec.params["depth"] == 6
    q = mesh_quality(mesh, sphere_cloud)
    assert q["watertight"] and q["genus"] == 0 and q["non_manifold_edges"] == 0
    assert q["volume"] == pytest.approx(4 / 3 * np.pi * R ** 3, rel=0.03)
    assert q["area"] == pytest.approx(4 * np.pi * R ** 2, rel=0.03)
    # surface passes through the samples: cloud -> mesh within 1 % of the radius
    assert q["cloud_to_mesh"]["p95"] < 0.01 * R
    assert np.abs(np.linalg.norm(mesh.vertices - CENTRE, axis=1) - R).max() < 0.03 * R


def test_poisson_pymeshlab_backend_agrees(sphere_cloud, sphere_poisson):
    assert sphere_poisson[1].params["backend"] == "open3d"  # the default (PyMeshLab #408)
    oriented, _ = estimate_normals(sphere_cloud, NormalParams(k=10))
    mesh, rec = poisson(oriented, PoissonParams(depth=6, trim_quantile=0.0, backend="pymeshlab", threads=1))
    assert rec.params["backend"] == "pymeshlab"
    q = mesh_quality(mesh, sphere_cloud)
    assert q["watertight"] and q["volume"] == pytest.approx(4 / 3 * np.pi * R ** 3, rel=0.03)
    assert q["cloud_to_mesh"]["p95"] < 0.01 * R
    assert "quality" in mesh.vertex_attrs
    with pytest.raises(InvalidInputError):
        PoissonParams(backend="cgal")


def test_poisson_trims_unsupported_surface():
    """A hemisphere of points: Poisson closes it; trimming by density removes the invented cap."""
    xyz, u = sphere_points(6000)
    keep = u[:, 2] > 0
    cloud = Cloud(xyz[keep])
    oriented, _ = estimate_normals(cloud, NormalParams(k=10), viewpoints=CENTRE + [0, 0, 50.0])
    closed, _ = poisson(oriented, PoissonParams(depth=6, trim_quantile=0.0, support_trim=0.0, threads=1))
    trimmed, rec = poisson(oriented, PoissonParams(depth=6, trim_quantile=0.3, support_trim=0.0, threads=1))
    from scipy.spatial import cKDTree

    tree = cKDTree(cloud.xyz)
    invented = lambda m: (tree.query(m.vertices)[0] > 0.1 * R).mean()  # noqa: E731
    assert invented(closed) > 0.05
    assert invented(trimmed) < 0.01
    assert rec.summary["faces"] < rec.summary["faces_untrimmed"]
    q = mesh_quality(trimmed, cloud)
    assert not q["watertight"] and q["volume"] is None
    assert q["mesh_to_cloud"]["max"] < mesh_quality(closed, cloud)["mesh_to_cloud"]["max"]


def test_poisson_needs_normals(sphere_cloud):
    with pytest.raises(InvalidInputError):
        poisson(sphere_cloud, PoissonParams(depth=5))


def test_ball_pivoting_keeps_input_points_as_vertices(sphere_cloud):
    oriented, _ = estimate_normals(sphere_cloud, NormalParams(k=10), viewpoints=CENTRE)
    oriented = oriented.with_attrs(normal=-np.asarray(oriented.attrs["normal"]))  # outward
    mesh, rec = ball_pivoting(oriented, BallPivotingParams(radius_factor=2.5))
    assert rec.params["radius"] == pytest.approx(2.5 * point_spacing(sphere_cloud.xyz))
    from scipy.spatial import cKDTree

    d, _ = cKDTree(sphere_cloud.xyz).query(mesh.vertices)
    assert d.max() < 1e-6
    assert mesh.n_faces > 1.8 * sphere_cloud.n  # a closed triangulation has ~2 faces per vertex
    assert mesh_quality(mesh)["area"] == pytest.approx(4 * np.pi * R ** 2, rel=0.05)


def test_delaunay25d_terrain_interpolates_and_skips_gaps():
    g = np.stack(np.meshgrid(np.arange(30.0), np.arange(20.0)), -1).reshape(-1, 2)
    g = g[~((g[:, 0] > 10) & (g[:, 0] < 20) & (g[:, 1] > 5) & (g[:, 1] < 15))]  # a 10 m gap
    z = 0.1 * g[:, 0] + 0.05 * g[:, 1] + 300
    cloud = Cloud(np.column_stack([g + [600_000, 5_000_000], z]),
                  {"rgb": np.tile(np.array([100, 150, 200], np.uint16), (len(g), 1))})
    mesh, rec = delaunay25d(cloud, Delaunay25dParams(max_edge_factor=2.0))
    assert rec.params["max_edge"] == pytest.approx(2.0)
    # a plane is reproduced exactly, every triangle faces up
    t = mesh.vertices[mesh.faces]
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    assert np.all(n[:, 2] > 0)
    assert np.abs(mesh.vertices[:, 2] - (0.1 * (mesh.vertices[:, 0] - 600_000)
                                                 + 0.05 * (mesh.vertices[:, 1] - 5_000_000) + 300)).max() < 1e-9
    # the gap is not bridged: no triangle centre inside it
    c = t.mean(axis=1) - [600_000, 5_000_000, 0]
    assert not np.any((c[:, 0] > 11) & (c[:, 0] < 19) & (c[:, 1] > 6) & (c[:, 1] < 14))
    # planimetric area = grid area minus the 10 x 10 gap, plus at most its four corner
    # triangles (half a cell each) whose short hypotenuse cuts a corner
    assert 29 * 19 - 100 <= np.abs(n[:, 2]).sum() / 2 <= 29 * 19 - 100 + 2 + 1e-9
    assert mesh.vertex_attrs["rgb"][0].tolist() == [100, 150, 200]


def test_clean_removes_duplicates_degenerates_non_manifold_and_small_pieces():
    base = icosphere(2)
    nv = base.n_vertices
    v = np.vstack([base.vertices, base.vertices[:3],  # duplicated vertices
                   CENTRE + [10, 0, 0], CENTRE + [10.01, 0, 0], CENTRE + [10, 0.01, 0],  # a tiny far piece
                   0.5 * (base.vertices[0] + base.vertices[1]),
                   CENTRE + 1.005 * (base.vertices[base.faces[0, 2]] - CENTRE)])
    f = np.vstack([base.faces, base.faces[:5],  # duplicate faces
                   [[0, 1, nv + 6]],  # zero area: three collinear vertices
                   [[nv + 3, nv + 4, nv + 5]],
                   [[base.faces[0, 0], base.faces[0, 1], nv + 7]]])  # a third face on one edge: non-manifold
    dirty = Mesh(v, f)
    out, rec = clean(dirty, CleanParams(min_piece_fraction=0.05))
    s = rec.summary
    assert s["removed"]["duplicate_faces"]["faces"] == 5
    assert s["removed"]["zero_area_faces"]["faces"] == 1
    assert s["removed"]["non_manifold_edges"]["faces"] >= 1
    assert s["removed"]["small_pieces_by_diameter"]["faces"] == 1
    assert s["non_manifold_edges"] == 0
    q = mesh_quality(out)
    assert q["non_manifold_edges"] == 0
    assert np.linalg.norm(out.vertices - CENTRE, axis=1).max() < R * 1.01  # far piece removed
    assert s["self_intersecting_faces"] == 0


def test_clean_fills_small_holes_only():
    base = icosphere(3)
    holed = Mesh(base.vertices, base.faces[1:])  # one missing triangle: a 3-edge hole
    assert not mesh_quality(holed)["watertight"]
    kept, _ = clean(holed, CleanParams(max_hole_edges=0))
    assert kept.n_faces == holed.n_faces
    filled, rec = clean(holed, CleanParams(max_hole_edges=10))
    assert rec.summary["holes_closed_faces"] == 1
    assert mesh_quality(filled)["watertight"]


def test_decimate_reaches_target_keeps_boundary_and_colours():
    g = np.stack(np.meshgrid(np.linspace(0, 10, 41), np.linspace(0, 10, 41)), -1).reshape(-1, 2)
    from scipy.spatial import Delaunay

    f = Delaunay(g).simplices
    z = 0.2 * np.sin(g[:, 0]) * np.cos(g[:, 1])
    rgb = np.where((g[:, 0] < 5)[:, None], [255, 0, 0], [0, 0, 255]).astype(np.uint8)
    mesh = Mesh(np.column_stack([g + 1000, z]), f, {"rgb": rgb})
    out, rec = decimate(mesh, DecimateParams(target_faces=600))
    assert out.n_faces <= 600 and out.n_faces > 500
    assert rec.summary["faces_in"] == mesh.n_faces
    # boundary preserved: the square outline stays at 0 and 10
    lo, hi = out.vertices[:, :2].min(0) - 1000, out.vertices[:, :2].max(0) - 1000
    assert np.allclose(lo, 0, atol=1e-9) and np.allclose(hi, 10, atol=1e-9)
    # colours kept: red on the left, blue on the right (away from the seam)
    x = out.vertices[:, 0] - 1000
    c = out.vertex_attrs["rgb"]
    assert np.all(c[x < 4.5, 0] == 255) and np.all(c[x > 5.5, 2] == 255)
    same, _ = decimate(out, DecimateParams(target_faces=10_000))
    assert same is out


def test_taubin_smooths_without_shrinking_laplacian_shrinks():
    base = icosphere(4)
    rng = np.random.default_rng(3)
    radial = (base.vertices - CENTRE) / R
    noisy = Mesh(base.vertices + radial * rng.normal(0, 0.02, (base.n_vertices, 1)), base.faces)
    dev = lambda m: np.std(np.linalg.norm(m.vertices - CENTRE, axis=1))  # noqa: E731
    mean_r = lambda m: np.mean(np.linalg.norm(m.vertices - CENTRE, axis=1))  # noqa: E731
    tau, rec = smooth(noisy, SmoothParams(method="taubin", iterations=20))
    lap, _ = smooth(noisy, SmoothParams(method="laplacian", iterations=20))
    assert dev(tau) < 0.5 * dev(noisy)
    assert mean_r(tau) == pytest.approx(R, rel=0.01)
    assert mean_r(lap) < mean_r(tau) - 0.005
    assert rec.params["lambda"] == 0.5 and tau.n_faces == noisy.n_faces


def test_colour_transfer_nearest_colours():
    base = icosphere(3)
    xyz, u = sphere_points(3000)
    rgb = np.where((u[:, 2] > 0)[:, None], [65535, 0, 0], [0, 65535, 0]).astype(np.uint16)
    out, rec = transfer_colors(base, Cloud(xyz, {"rgb": rgb}), ColorTransferParams(k=4))
    z = out.vertices[:, 2] - CENTRE[2]
    c = out.vertex_attrs["rgb"]
    assert c.dtype == np.uint8
    assert np.all(c[z > 0.2] == [255, 0, 0]) and np.all(c[z < -0.2] == [0, 255, 0])
    assert rec.summary["distance_median"] < 0.1
    with pytest.raises(InvalidInputError):
        transfer_colors(base, Cloud(xyz))


def test_local_plane_distance_has_no_sampling_floor():
    g = np.stack(np.meshgrid(np.arange(50.0), np.arange(50.0)), -1).reshape(-1, 2)
    xyz = np.column_stack([g, np.zeros(len(g))])
    rng = np.random.default_rng(0)
    s = np.column_stack([rng.uniform(5, 45, (1000, 2)), np.full(1000, 0.1)])
    d = local_plane_distance(s, xyz)
    assert np.allclose(d, 0.1, atol=1e-9)  # point-to-point would be up to 0.72
    far = local_plane_distance(np.array([[100.0, 25.0, 0.0]]), xyz)
    assert far[0] > 40  # invented surface far from the data still counts


def test_nearest_point_floor_of_a_unit_grid():
    """Samples 0.1 above a unit grid: their feet on the plane lie, in RMS, sqrt(1/6) = 0.408 of
    the spacing from the nearest grid point (uniform over a cell), whatever the height."""
    g = np.stack(np.meshgrid(np.arange(50.0), np.arange(50.0)), -1).reshape(-1, 2)
    xyz = np.column_stack([g, np.zeros(len(g))])
    rng = np.random.default_rng(0)
    s = np.column_stack([rng.uniform(5, 45, (20000, 2)), np.full(20000, 0.1)])
    f = nearest_point_floor(s, xyz)
    assert np.sqrt(np.mean(f ** 2)) == pytest.approx(np.sqrt(1 / 6), rel=0.02)
    assert np.sqrt(np.mean(nearest_point_floor(s, xyz * 2) ** 2)) == pytest.approx(2 * np.sqrt(1 / 6), rel=0.02)


def test_chain_records_every_step_and_colours(sphere_cloud):
    xyz = sphere_cloud.xyz
    rgb = np.where((xyz[:, 0] > CENTRE[0])[:, None], [60000, 0, 0], [0, 0, 60000]).astype(np.uint16)
    c = sphere_cloud.with_attrs(rgb=rgb)
    res = mesh_cloud(c, MeshChainParams(method="poisson", poisson=PoissonParams(depth=5, trim_quantile=0.0, threads=1),
                                        decimate=DecimateParams(target_faces=500), smooth=SmoothParams(iterations=2),
                                        quality=QualityParams()))
    names = [s.name for s in res.steps]
    assert names == ["normals", "poisson", "clean", "decimate", "smooth", "clean_after_decimation", "color_transfer",
                     "quality"]
    assert res.mesh.n_faces <= 500
    assert res.mesh.meta["steps"][1]["params"]["depth"] == 5
    assert res.quality["watertight"]
    x = res.mesh.vertices[:, 0] - CENTRE[0]
    assert np.all(res.mesh.vertex_attrs["rgb"][x > 0.3, 0] > 200)
    d = res.to_dict()
    assert d["faces"] == res.mesh.n_faces and len(d["steps"]) == 8
    with pytest.raises(InvalidInputError):
        MeshChainParams(method="marching")


def test_empty_results_raise_stage_error():
    xyz = np.column_stack([np.arange(10.0), np.zeros(10), np.zeros(10)])  # collinear
    with pytest.raises((StageError, InvalidInputError)):
        delaunay25d(Cloud(xyz))
