"""Normals and meshes of scan-line clouds (airborne / terrestrial strips: points close along
each line, lines far apart), whose k nearest neighbours all lie on one line."""

from __future__ import annotations

import json

import numpy as np

from workstation.core.cloud import Cloud
from workstation.mesh import NormalParams, estimate_normals
from workstation.mesh.normals import orient_from_anchors, widen_collinear

from scanline_synth import scan_line_xy  # tests/mesh/ is on the path

ORIGIN = np.array([500_000.0, 4_000_000.0, 100.0])


def surface(x, y):
    """A smooth terrain-like surface (m)."""
    return np.sin(x / 4.0) * np.cos(y / 5.0)


def surface_normal(x, y):
    zx, zy = 0.25 * np.cos(x / 4.0) * np.cos(y / 5.0), -0.2 * np.sin(x / 4.0) * np.sin(y / 5.0)
    n = np.column_stack([-zx, -zy, np.ones_like(x)])
    return n / np.linalg.norm(n, axis=1, keepdims=True)


def scan_lines(gap=0.5, along=0.05, angle_deg=30.0, size=20.0, noise=0.003, seed=0):
    """Lines ``gap`` apart, points ``along`` apart on each, at ``angle_deg`` from x, over a
    size x size square of :func:`surface`, with Gaussian height noise (m)."""
    x, y = scan_line_xy(gap, along, angle_deg, size)
    return x, y, surface(x, y) + np.random.default_rng(seed).normal(0, noise, x.size)


def test_ws_mesh_defaults_cover_a_surface_sampled_by_scan_lines(tmp_path, capsys):
    """Lines 0.5 m apart, points 0.05 m apart on them: with 10 neighbours on one line the plane
    is undetermined about the line; the widened normals let Poisson find the whole surface."""
    from workstation.cli.main import main
    from workstation.io import write_cloud
    from workstation.io.mesh import read_mesh
    from workstation.mesh.quality import closest_on_mesh

    x, y, z = scan_lines()
    src = tmp_path / "lines.laz"
    write_cloud(Cloud(np.column_stack([x, y, z]) + ORIGIN), src)
    out = tmp_path / "lines.ply"
    assert main(["mesh", str(src), "-o", str(out), "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    mesh = read_mesh(out)
    rng = np.random.default_rng(1)
    qx, qy = rng.uniform(1.0, 19.0, (2, 20000))
    d, _ = closest_on_mesh(np.column_stack([qx, qy, surface(qx, qy)]) + ORIGIN, mesh.vertices, mesh.faces)
    assert np.mean(d > 0.05) < 0.01  # under 1 % of the true surface farther than 5 cm from the mesh
    normals = next(s for s in res["steps"] if s["name"] == "normals")
    assert normals["summary"]["points_widened"] == x.size  # every neighbourhood of 10 is one line


def test_scan_line_normals_follow_the_surface_with_one_sign():
    x, y, z = scan_lines(gap=1.0, angle_deg=10.0, size=12.0)
    out, rec = estimate_normals(Cloud(np.column_stack([x, y, z]) + ORIGIN), NormalParams(k=10))
    n = np.asarray(out.attrs["normal"], dtype=float)
    dot = np.einsum("ij,ij->i", n, surface_normal(x, y))
    assert np.all(dot > 0) or np.all(dot < 0)  # propagated consistently across the lines
    assert np.quantile(np.degrees(np.arccos(np.abs(dot))), 0.95) < 2.0
    assert rec.summary["points_widened"] == x.size


def test_isotropic_neighbourhoods_are_not_widened():
    """A jittered grid and a Fibonacci sphere: no neighbourhood is a line, normals untouched."""
    rng = np.random.default_rng(0)
    g = np.stack(np.meshgrid(np.arange(60.0), np.arange(60.0)), -1).reshape(-1, 2) * 0.1
    g = g + rng.uniform(-0.03, 0.03, g.shape)
    idx, fit, rows, cols, unresolved = widen_collinear(np.column_stack([g, surface(g[:, 0], g[:, 1])]), 10)
    assert idx.size == fit.shape[0] == rows.size == cols.size == unresolved.size == 0
    i = np.arange(3000) + 0.5
    phi, th = np.arccos(1 - 2 * i / 3000), np.pi * (1 + 5 ** 0.5) * i
    u = np.column_stack([np.cos(th) * np.sin(phi), np.sin(th) * np.sin(phi), np.cos(phi)])
    _, rec = estimate_normals(Cloud(ORIGIN + 2.0 * u), NormalParams(k=10))
    assert rec.summary["points_widened"] == 0


def test_lines_farther_apart_than_k_max_reaches_are_unresolved():
    """Lines 1 m apart, points 5 cm apart: 20 neighbours reach 0.5 m along their own line and
    never the next one, so with k_max = 20 all points but a few at the short lines' ends
    (whose 20 nearest reach a second line) are unresolved; 80 neighbours resolve them all."""
    x, y, z = scan_lines(gap=1.0, along=0.05, angle_deg=10.0, size=6.0)
    idx, fit, rows, cols, unresolved = widen_collinear(np.column_stack([x, y, z]), 10, k_max=20)
    assert unresolved.size > 0.99 * x.size and fit.shape[0] == idx.size
    assert np.array_equal(np.sort(np.concatenate([idx, unresolved])), np.arange(x.size))
    assert np.array_equal(np.unique(rows), np.arange(x.size))  # their edges still reach along the line
    _, fit80, _, _, unresolved80 = widen_collinear(np.column_stack([x, y, z]), 10, k_max=80)
    assert unresolved80.size == 0 and fit80.shape[0] == x.size


def test_the_sampled_pretest_finds_lines_and_skips_surfaces():
    """With a sample of 200 points the line test still flags every scan-line point; on a
    jittered grid (no line-shaped neighbourhood) it finds none and the full pass is skipped."""
    x, y, z = scan_lines(gap=0.5, along=0.05, angle_deg=30.0, size=8.0)
    idx, _, _, _, unresolved = widen_collinear(np.column_stack([x, y, z]), 10, sample=200)
    assert idx.size + unresolved.size == x.size > 200
    g = np.stack(np.meshgrid(np.arange(60.0), np.arange(60.0)), -1).reshape(-1, 2) * 0.1
    g = g + np.random.default_rng(0).uniform(-0.03, 0.03, g.shape)
    idx, _, rows, _, unresolved = widen_collinear(np.column_stack([g, surface(g[:, 0], g[:, 1])]), 10, sample=200)
    assert idx.size == rows.size == unresolved.size == 0


def test_widened_normals_take_the_sign_of_the_dense_part_of_the_cloud():
    """Dense patch (x < 5) next to scan lines (x >= 5), one surface: the lines' normals are
    oriented from the dense patch, whose normals are kept."""
    rng = np.random.default_rng(2)
    g = np.stack(np.meshgrid(np.arange(0, 5, 0.1), np.arange(0, 10, 0.1)), -1).reshape(-1, 2)
    g = g + rng.uniform(-0.02, 0.02, g.shape)
    x, y, _ = scan_lines(gap=0.5, along=0.05, angle_deg=0.0, size=10.0)
    line = x >= 5.0
    px, py = np.concatenate([g[:, 0], x[line]]), np.concatenate([g[:, 1], y[line]])
    xyz = np.column_stack([px, py, surface(px, py)]) + ORIGIN
    out, rec = estimate_normals(Cloud(xyz), NormalParams(k=10, orient="propagate"))
    n = np.asarray(out.attrs["normal"], dtype=float)
    dot = np.einsum("ij,ij->i", n, surface_normal(px, py))
    assert np.all(dot > 0) or np.all(dot < 0)
    assert rec.summary["points_widened"] >= 0.9 * line.sum()  # all but the lines' ends next to the patch


def test_orient_from_anchors_keeps_anchors_and_flips_the_rest():
    up, down = np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0])
    n = np.array([down, up, down, up, up, down, up])  # 0-3 a chain from anchor 0; 4-6 a free chain
    anchored = np.array([True, False, False, False, False, False, False])
    rows, cols = np.array([0, 1, 2, 4, 5]), np.array([1, 2, 3, 5, 6])
    out = orient_from_anchors(n, anchored, rows, cols)
    assert out[:4, 2].tolist() == [-1.0, -1.0, -1.0, -1.0]  # the anchor's sign, carried along the chain
    assert out[4:, 2].tolist() == [1.0, 1.0, 1.0]  # no anchor: the first point's sign
