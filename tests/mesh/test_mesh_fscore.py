"""F-score against a true surface (workstation.mesh.quality) on analytic shapes with known answers."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.core.products import Camera, Image, Mesh, Reconstruction
from workstation.mesh.quality import (FScoreParams, closest_on_mesh, fscore, fscore_against_truth, sample_surface,
                                      views_seeing)
from workstation.photogrammetry.rigs import look_at

from scanline_synth import scan_line_xy  # tests/mesh/ is on the path

ORIGIN = np.array([500_000.0, 4_000_000.0, 100.0])  # map coordinates: the float32 queries must keep mm


def grid_plane(size=10.0, n=20, z=0.0) -> Mesh:
    """A square (size × size, metres) in the plane z, centred on ORIGIN, split into 2 n² triangles."""
    x = np.linspace(-size / 2, size / 2, n + 1)
    X, Y = np.meshgrid(x, x, indexing="ij")
    V = np.column_stack([X.ravel(), Y.ravel(), np.full(X.size, z)]) + ORIGIN
    i = np.arange(n)[:, None] * (n + 1) + np.arange(n)[None, :]
    a, b, c, d = i.ravel(), i.ravel() + 1, i.ravel() + n + 1, i.ravel() + n + 2
    return Mesh(V, np.vstack([np.column_stack([a, c, b]), np.column_stack([b, c, d])]))


def uv_sphere(radius=1.0, n=120) -> Mesh:
    """A latitude-longitude sphere centred on ORIGIN (n bands, 2n sectors)."""
    th = np.linspace(0, np.pi, n + 1)[1:-1]
    ph = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)
    T, P = np.meshgrid(th, ph, indexing="ij")
    T, P = T.ravel(), P.ravel()
    V = np.column_stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)])
    V = np.vstack([[0, 0, 1], V, [0, 0, -1]]) * radius + ORIGIN
    ring = lambda k: 1 + k * 2 * n + np.arange(2 * n)  # noqa: E731
    F = [np.column_stack([np.zeros(2 * n, int), ring(0), np.roll(ring(0), -1)])]
    for k in range(n - 2):
        a, b = ring(k), ring(k + 1)
        F += [np.column_stack([a, b, np.roll(b, -1)]), np.column_stack([a, np.roll(b, -1), np.roll(a, -1)])]
    last = len(V) - 1
    F.append(np.column_stack([ring(n - 2), np.full(2 * n, last), np.roll(ring(n - 2), -1)]))
    return Mesh(V, np.vstack(F).astype(np.int64))


def cameras(centres, target, size=(400, 300), f=150.0) -> Reconstruction:
    """Cameras at ``centres`` (metres from ORIGIN) looking at ``target``: one point, or one per camera."""
    cam = Camera(size[0], size[1], f, f, (size[0] - 1) / 2, (size[1] - 1) / 2)
    aim = np.broadcast_to(np.asarray(target, float), np.shape(centres)) + ORIGIN
    return Reconstruction({1: cam}, {k: Image(f"c{k}.png", 1, look_at(np.asarray(c, float) + ORIGIN, aim[k - 1]))
                                     for k, c in enumerate(centres, start=1)})


def test_sample_surface_is_uniform_by_area():
    m = Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 5], [3, 0, 5], [0, 3, 5]], float),
             np.array([[0, 1, 2], [3, 4, 5]]))
    p, f = sample_surface(m, 100_000)
    assert abs((f == 1).mean() - 0.9) < 0.005  # areas 0.5 and 4.5
    assert np.allclose(p[f == 0, 2], 0) and (p[f == 0, :2].sum(1) <= 1 + 1e-12).all()
    assert abs(p[f == 1, 0].mean() - 1.0) < 0.01  # the centroid of the larger triangle


def test_plane_against_shifted_plane():
    truth = grid_plane()
    rec = cameras([[-2, 0, 3], [2, 0, 3]], [[-2, 0, 0], [2, 0, 0]])  # both looking straight down
    shifted = Mesh(truth.vertices + [0, 0, 0.015], truth.faces)
    out = fscore_against_truth(shifted, truth, rec, params=FScoreParams(taus=(0.01, 0.02), truth_samples=20_000,
                                                                        recon_samples=20_000))
    s = out["scores"]
    assert s[0.01] == {"precision": 0.0, "recall": 0.0, "f": 0.0}
    assert s[0.02]["precision"] == 1.0 and s[0.02]["recall"] == 1.0 and s[0.02]["f"] == 1.0
    assert out["precision_dist"]["p50"] == pytest.approx(0.015, abs=1e-4)
    assert out["recall_dist"]["p50"] == pytest.approx(0.015, abs=1e-4)
    # each camera sees 8 x 6 m (3 m x 400 / 150 by 3 m x 300 / 150) around x = -2 or 2: both see
    # x in [-2, 2], y in [-3, 3], 24 % of the 10 x 10 m square
    assert out["truth_seen_share"] == pytest.approx(0.24, abs=0.01)


def test_plane_half_covered_halves_recall_not_precision():
    truth = grid_plane()
    rec = cameras([[-2, 0, 30], [2, 0, 30]], [0, 0, 0])  # sees the whole square
    half = grid_plane()
    keep = (half.vertices[half.faces][:, :, 0] - ORIGIN[0] <= 1e-9).all(axis=1)  # x <= 0 half
    part = Mesh(half.vertices, half.faces[keep])
    out = fscore_against_truth(part, truth, rec, params=FScoreParams(taus=(0.02,), truth_samples=40_000))
    s = out["scores"][0.02]
    assert out["truth_seen_share"] == 1.0
    assert s["precision"] == 1.0
    assert s["recall"] == pytest.approx(0.5, abs=0.01)
    assert s["f"] == pytest.approx(2 * 0.5 / 1.5, abs=0.01)


def test_sphere_visibility_and_radial_error():
    truth = uv_sphere(1.0)
    # cameras 10 m away on the +x side: each sees the cap facing it, (1 - R/D)/2 = 45 % of the sphere
    rec = cameras([[10, 0, 0], [10, 0.3, 0]], [0, 0, 0], f=100.0)
    big = Mesh((truth.vertices - ORIGIN) * 1.03 + ORIGIN, truth.faces)
    out = fscore_against_truth(big, truth, rec, params=FScoreParams(taus=(0.02, 0.05), truth_samples=40_000))
    assert 0.42 < out["truth_seen_share"] < 0.46
    assert out["scores"][0.02]["f"] == 0.0 and out["scores"][0.05]["f"] == 1.0
    assert out["precision_dist"]["p50"] == pytest.approx(0.03, abs=0.002)
    # a cloud of the true sphere's vertices: its recall is limited by its spacing (KD-tree)
    pts = truth.vertices
    cloud = fscore_against_truth(pts, truth, rec, params=FScoreParams(taus=(0.001, 0.05), truth_samples=20_000))
    assert cloud["scores"][0.001]["precision"] > 0.99 and cloud["scores"][0.001]["recall"] < 0.05
    assert cloud["scores"][0.05]["f"] > 0.99


def test_precision_counts_floaters_and_crops_to_the_target():
    truth_sphere = uv_sphere(1.0, n=60)
    ground = grid_plane(size=40.0, n=4, z=-1.5)
    truth = Mesh(np.vstack([truth_sphere.vertices, ground.vertices]),
                 np.vstack([truth_sphere.faces, ground.faces + len(truth_sphere.vertices)]))
    target = np.r_[np.ones(len(truth_sphere.faces), bool), np.zeros(len(ground.faces), bool)]
    rec = cameras([[8, 0, 3], [8, 1, 3]], [0, 0, 0], f=100.0)
    rng = np.random.default_rng(0)
    on = rng.normal(size=(9000, 3))
    on = on / np.linalg.norm(on, axis=1, keepdims=True) + ORIGIN
    floaters = ORIGIN + rng.uniform(-1.3, 1.3, (1000, 3)) * [1, 1, 0.1] + [0, 0, 1.2]  # above the top
    ground_pts = ORIGIN + np.column_stack([rng.uniform(5, 15, (3000, 2)), np.full(3000, -1.5)])
    out = fscore_against_truth(np.vstack([on, floaters, ground_pts]), truth, rec, target,
                               FScoreParams(taus=(0.01,), truth_samples=10_000))
    assert out["recon_samples"] == 10_000  # the ground points are cropped away
    d_f, _ = closest_on_mesh(floaters, truth_sphere.vertices, truth_sphere.faces)
    expected = (9000 + (d_f <= 0.01).sum()) / 10_000
    assert out["scores"][0.01]["precision"] == pytest.approx(expected, abs=0.002)


def test_views_seeing_counts_occlusion():
    truth = grid_plane(size=4.0, n=2)
    wall = grid_plane(size=1.0, n=1, z=2.0)  # a small roof between the cameras and the centre
    occ = Mesh(np.vstack([truth.vertices, wall.vertices]), np.vstack([truth.faces, wall.faces + len(truth.vertices)]))
    rec = cameras([[0, 0, 6], [0.01, 0, 6]], [0, 0, 0])
    pts = ORIGIN + np.array([[0.0, 0.0, 0.0], [1.8, 0.0, 0.0], [0.0, 0.0, -0.5]])
    n = views_seeing(pts, rec, occ.vertices, occ.faces)
    assert n.tolist() == [0, 2, 0]  # hidden by the roof; seen; under the plane


def test_fscore_and_params_reject_bad_input():
    assert fscore([0.0, 1.0], [0.0], (0.5,))[0.5] == {"precision": 0.5, "recall": 1.0, "f": 2 * 0.5 / 1.5}
    with pytest.raises(InvalidInputError):
        fscore([], [0.1], (0.5,))
    with pytest.raises(InvalidInputError):
        FScoreParams(taus=(0.0,))
    with pytest.raises(InvalidInputError):
        fscore_against_truth(np.zeros((3, 2)), grid_plane(), cameras([[0, 0, 5]], [0, 0, 0]))


def test_poisson_support_trim_removes_invented_surface_only():
    from workstation.core.cloud import Cloud
    from workstation.mesh import PoissonParams, point_spacing, poisson

    n = 6000
    i = np.arange(n) + 0.5
    phi, th = np.arccos(1 - 2 * i / n), np.pi * (1 + 5 ** 0.5) * i
    u = np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    u = u[u[:, 2] < 0.5]  # a sphere without its top cap (a third of its height): Poisson closes it
    cloud = Cloud(ORIGIN + 2.0 * u, {"normal": u})
    closed, _ = poisson(cloud, PoissonParams(depth=6, trim_quantile=0.0, support_trim=0.0, threads=1))
    trimmed, rec = poisson(cloud, PoissonParams(depth=6, trim_quantile=0.0, support_trim=3.0, threads=1))
    sp = point_spacing(cloud.xyz)
    assert rec.summary["point_spacing"] == pytest.approx(sp)
    top = lambda m: (m.vertices[:, 2] - ORIGIN[2] > 1.4).sum()  # noqa: E731  (the cap starts at z = 1 m)
    assert top(closed) > 50 and top(trimmed) == 0
    assert rec.summary["vertices_without_support"] > 0
    # the surface over the data stays: every input point is still within a spacing of the mesh
    d, _ = closest_on_mesh(cloud.xyz, trimmed.vertices, trimmed.faces)
    assert np.percentile(d, 99) < sp
    with pytest.raises(InvalidInputError):
        PoissonParams(support_trim=-1.0)


def _scan_lines(gap: float, step: float, size: float = 10.0, hole: float = 3.0):
    """Scan lines across a smooth 10 m square (points ``step`` apart along lines ``gap`` apart,
    at 30° to x), with a ``hole`` m square without data in the middle; its true height."""
    h = lambda x, y: 0.5 * np.sin(x / 3.0) * np.cos(y / 4.0)  # noqa: E731
    x, y = scan_line_xy(gap, step, 30.0, size, hole)
    gx = np.cos(x / 3.0) * np.cos(y / 4.0) / 6.0
    gy = -np.sin(x / 3.0) * np.sin(y / 4.0) / 8.0
    nrm = np.column_stack([-gx, -gy, np.ones_like(x)])
    return np.column_stack([x, y, h(x, y)]), nrm / np.linalg.norm(nrm, axis=1, keepdims=True), h


def test_poisson_support_trim_keeps_the_surface_between_scan_lines():
    """Lines 0.5 m apart, points 5 cm apart on them: the nearest-neighbour spacing (5 cm) is a
    tenth of the gap, and 3 of them would cut the true surface between the lines (the middle
    lies 25 cm from every point). The trim measures the spacing across the lines: the surface
    between lines stays, the surface Poisson invents over the 3 m hole goes."""
    from workstation.core.cloud import Cloud
    from workstation.mesh import PoissonParams, poisson
    from workstation.mesh.reconstruct import across_spacing

    xyz, nrm, h = _scan_lines(0.5, 0.05)
    assert across_spacing(xyz) == pytest.approx(0.5, rel=0.02)
    cloud = Cloud(ORIGIN + xyz, {"normal": nrm})
    closed, _ = poisson(cloud, PoissonParams(depth=8, trim_quantile=0.0, support_trim=0.0, threads=1))
    trimmed, rec = poisson(cloud, PoissonParams(depth=8, trim_quantile=0.0, support_trim=3.0, threads=1))
    assert rec.summary["point_spacing"] == pytest.approx(0.05, rel=0.02)
    assert rec.summary["support_reach"] == pytest.approx(3 * 0.5 * rec.summary["across_spacing"])
    # the true surface over the data, away from the edges and the hole, is all still meshed
    rng = np.random.default_rng(1)
    x, y = rng.uniform(0.5, 9.5, (2, 20000))
    data = (np.abs(x - 5) > 2.0) | (np.abs(y - 5) > 2.0)
    t = ORIGIN + np.column_stack([x, y, h(x, y)])[data]
    d, _ = closest_on_mesh(t, trimmed.vertices, trimmed.faces)
    assert np.mean(d > 0.05) < 0.001
    # Poisson spans the hole; the trim takes its middle (farther than the 0.75 m reach from data)
    hole = (np.abs(x - 5) < 0.6) & (np.abs(y - 5) < 0.6)
    t = ORIGIN + np.column_stack([x, y, h(x, y)])[hole]
    assert np.median(closest_on_mesh(t, closed.vertices, closed.faces)[0]) < 0.05
    assert closest_on_mesh(t, trimmed.vertices, trimmed.faces)[0].min() > 0.3


def test_refine_to_cloud_averages_the_noise_of_the_points():
    from workstation.core.cloud import Cloud
    from workstation.mesh import PoissonParams, poisson
    from workstation.mesh.reconstruct import RefineParams, refine_to_cloud

    n = 15_000
    i = np.arange(n) + 0.5
    phi, th = np.arccos(1 - 2 * i / n), np.pi * (1 + 5 ** 0.5) * i
    u = np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    r = 2.0 + np.random.default_rng(0).normal(0, 0.02, n)  # 2 cm noise on a 2 m sphere
    cloud = Cloud(ORIGIN + r[:, None] * u, {"normal": u})
    mesh, _ = poisson(cloud, PoissonParams(depth=6, trim_quantile=0.0, support_trim=0.0, point_weight=4.0, threads=1))
    refined, rec = refine_to_cloud(mesh, cloud, RefineParams(k=48))
    err = lambda m: np.abs(np.linalg.norm(m.vertices - ORIGIN, axis=1) - 2.0)  # noqa: E731
    assert np.sqrt(np.mean(err(refined) ** 2)) < 0.6 * np.sqrt(np.mean(err(mesh) ** 2))
    assert np.sqrt(np.mean(err(refined) ** 2)) < 0.01
    assert np.array_equal(refined.faces, mesh.faces) and rec.name == "refine_mls" and rec.summary["move_p50"] > 0
    with pytest.raises(InvalidInputError):
        RefineParams(k=2)
