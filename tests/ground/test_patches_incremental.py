"""The raised-patch test's passes after the first: TIN edges made from the last full TIN
(workstation.ground.retile._incremental_edges) give the verdicts of a full triangulation."""

from __future__ import annotations

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.ground import patches, retile
from workstation.ground.patches import PatchParams, raised_patches


def _roof_scene():
    """terrain_with_boxes in local coordinates, all accepted as ground but the low outlier."""
    xyz, _ = terrain_with_boxes()
    local = xyz - xyz.min(axis=0)
    return local, local[:, 2] > 10


def _tower_scene():
    """The roofs with a 3 m tower on the 9 m one: three passes."""
    local, ground = _roof_scene()
    tower = (local[:, 0] > 49) & (local[:, 0] < 55) & (local[:, 1] > 52) & (local[:, 1] < 56)
    local[tower, 2] += 3.0
    return local, ground


def _lattice_scene(jitter_roofs: bool):
    """Flat-topped boxes on terrain sampled on a regular 0.5 m grid, coordinates on a 1 cm
    lattice: every grid square is four cocircular points (Qhull picks its diagonals freely).
    With ``jitter_roofs`` the roofs' points are moved off the grid (by 5-20 cm)."""
    g = np.arange(0.0, 60.0, 0.5)
    x, y = (a.ravel() for a in np.meshgrid(g, g))
    z = np.round(0.05 * x + 0.5 * np.sin(y / 7.0), 2)
    roof = np.zeros(len(x), bool)
    for (x0, x1), (y0, y1), h in [((10, 18), (12, 20), 5.0), ((30, 40), (30, 36), 7.0), ((33, 37), (32, 34), 10.0)]:
        box = (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
        z[box], roof = h, roof | box
    if jitter_roofs:
        rng = np.random.default_rng(1)
        x, y = x + roof * rng.uniform(0.05, 0.2, len(x)), y + roof * rng.uniform(0.05, 0.2, len(x))
    return np.column_stack([x, y, z]), np.ones(len(x), bool)


def _full_only(monkeypatch):
    monkeypatch.setattr(retile, "_incremental_edges", lambda *a, **k: None)


def _watch(monkeypatch, compare_edges: bool) -> list:
    """A list with, per incremental pass, whether its edges are (as a set) Qhull's."""
    made, real = [], retile._incremental_edges

    def watched(xyz, gid, pts, base, step):
        out = real(xyz, gid, pts, base, step)
        if out is not None:
            same = None
            if compare_edges:
                src, dst, _ = retile.full_edges(pts[:, :2])
                n = len(pts)
                same = np.array_equal(np.sort(out[0] * n + out[1]), np.sort(src * n + dst))
            made.append(same)
        return out

    monkeypatch.setattr(retile, "_incremental_edges", watched)
    return made


@pytest.mark.parametrize("scene", [_roof_scene, _tower_scene])
def test_incremental_passes_give_qhulls_edges_and_verdicts(monkeypatch, scene):
    xyz, ground = scene()
    with monkeypatch.context() as m:
        _full_only(m)
        full = raised_patches(xyz, ground)
    made = _watch(monkeypatch, compare_edges=True)
    assert np.array_equal(raised_patches(xyz, ground), full)
    assert made and all(made)  # incremental passes ran, each with Qhull's edges
    assert not full[~ground].any() and full.sum() < ground.sum()


@pytest.mark.parametrize("jitter_roofs", [False, True])
def test_cocircular_lattice_gives_the_same_verdicts(monkeypatch, jitter_roofs):
    """On a lattice the incremental pass may keep other diagonals than Qhull's full run: it is
    taken only where every choice of them gives the same verdicts (cocircular quads of the
    terrain: yes; across a roof's wall, where a diagonal may join or break: no)."""
    xyz, ground = _lattice_scene(jitter_roofs)
    with monkeypatch.context() as m:
        _full_only(m)
        full = raised_patches(xyz, ground)
    made = _watch(monkeypatch, compare_edges=False)
    assert np.array_equal(raised_patches(xyz, ground), full)
    assert full.sum() < ground.sum()
    if jitter_roofs:
        assert len(made) == 2  # both passes after the first made incrementally
    # the near-cocircular quads of the old TIN are found
    from workstation.ground.common import delaunay

    base = retile._Base(np.arange(len(xyz)), delaunay(xyz[:, :2]), {})
    assert len(retile._base_geometry(base).tie_quad) > 0.5 * len(xyz)


def test_ties_with_a_step_are_not_harmless():
    z = np.array([0.0, 0.2, 0.4, 1.5, 0.1])
    assert retile._ties_harmless(np.array([[0, 1, 2, 4]]), z, 1.0)
    assert not retile._ties_harmless(np.array([[0, 1, 2, 3]]), z, 1.0)
    # quads sharing a triangle (1, 2, 3) are one facet: 0.0 .. 1.05 spans the step
    z2 = np.array([0.0, 0.5, 0.5, 0.5, 1.05, 0.6, 0.6])
    assert not retile._ties_harmless(np.array([[1, 2, 0, 3], [2, 3, 1, 4]]), z2, 1.0)
    # quads sharing a point only are two facets
    assert retile._ties_harmless(np.array([[1, 2, 0, 3], [3, 5, 6, 4]]), z2, 1.0)


def test_sums_too_close_to_call_fall_back_to_qhulls_order():
    bound = np.array([0.7 * 10, 0.7 * 4, 0.7 * 4])
    drops = np.array([10, 4, 4])
    raised = np.array([True, True, True])
    assert patches._order_safe(np.array([1.0, 2.0, 3.0]), bound, drops, raised, largest=0)
    assert not patches._order_safe(np.array([1.0, 2.8 + 1e-15, 3.0]), bound, drops, raised, largest=0)
    assert patches._order_safe(np.array([1.0, 2.8 + 1e-15, 3.0]), bound, drops, raised & [1, 0, 1], largest=0)


def test_the_last_incremental_pass_leaves_a_tin_made_on_demand():
    from workstation.ground import common, risers

    xyz, ground = _roof_scene()
    tins = common.TinHandoff()
    g = raised_patches(xyz, ground, tins=tins)
    left = tins._slot[1]
    assert isinstance(left, retile._LazyTin) and left._tri is None
    pts = tins._slot[0]
    assert np.array_equal(left.simplices, common.delaunay(pts).simplices)
    votes = np.where(g, 5, 1)
    tins.put(pts, left)
    assert np.array_equal(risers.riser_fill(xyz, g, votes, tins=tins), risers.riser_fill(xyz, g, votes))


def test_a_removed_hull_vertex_falls_back(monkeypatch):
    """A raised patch on the data's edge changes the hull: a full triangulation."""
    xyz, ground = _roof_scene()
    xyz = xyz[xyz[:, 0] > 17]  # the first roof now reaches the left edge
    ground = xyz[:, 2] > 10
    made = _watch(monkeypatch, compare_edges=True)
    with monkeypatch.context() as m:
        _full_only(m)
        full = raised_patches(xyz, ground, PatchParams(max_resultant=1.0))
    assert np.array_equal(raised_patches(xyz, ground, PatchParams(max_resultant=1.0)), full)
    assert made == []


def test_an_added_point_falls_back_to_qhull():
    """Points join the representatives only where the grid moved: such a pass is made by Qhull,
    and a pass that only loses points is made from the last TIN."""
    rng = np.random.default_rng(3)
    m = 4000
    xyz = np.column_stack([rng.uniform(0, 60, (m, 2)), rng.normal(0, 0.3, m)])
    xyz[:4, :2] = [[-1, -1], [61, -1], [61, 61], [-1, 61]]  # the hull, kept
    old = np.flatnonzero(rng.random(m) < 0.8)
    old = np.concatenate([[0, 1, 2, 3], old[old >= 4]])
    _, _, base, full = retile.pass_edges(xyz, old, xyz[old], None, None, 1.0)
    assert full
    kept = np.union1d(old[rng.random(len(old)) < 0.95], [0, 1, 2, 3])
    out = retile._incremental_edges(xyz, kept, xyz[kept], base, 1.0)
    src, dst, _ = retile.full_edges(xyz[kept, :2])
    n = len(kept)
    assert out is not None and np.array_equal(np.sort(out[0] * n + out[1]), np.sort(src * n + dst))
    new = np.union1d(kept, np.setdiff1d(np.arange(m), old)[:1])
    assert retile._incremental_edges(xyz, new, xyz[new], base, 1.0) is None
    src, dst, again, full = retile.pass_edges(xyz, new, xyz[new], base, None, 1.0)
    ref_src, ref_dst, _ = retile.full_edges(xyz[new, :2])
    assert full and again is not base and np.array_equal(src, ref_src) and np.array_equal(dst, ref_dst)


@pytest.mark.parametrize("error", [IndexError, ValueError, "qhull"])
def test_an_error_in_the_incremental_path_falls_back_to_qhull(monkeypatch, error):
    """Whatever goes wrong in the re-tiling, the pass is triangulated in full and the passes go
    on: the result is the full path's."""
    from scipy.spatial import QhullError

    xyz, ground = _tower_scene()
    with monkeypatch.context() as m:
        _full_only(m)
        full = raised_patches(xyz, ground)
    calls = []

    def broken(*args):
        calls.append(1)
        raise QhullError("injected") if error == "qhull" else error("injected")

    monkeypatch.setattr(retile, "_retile", broken)
    assert np.array_equal(raised_patches(xyz, ground), full)
    assert len(calls) == 2  # both passes after the first tried, and went on
