"""TIN rasterisation speedups are exact: pruned/regrouped == a plain per-triangle computation.

``rasterize_triangles`` drops triangles whose bounding box holds no target cell, evaluates the
rest over stencils sized per direction and resolves cells written by several triangles with a
per-cell rank; ``lattice_tin`` shares the query-independent barycentric terms. None of that may
change a single bit of the output, so the references below are straightforward per-triangle
(per-quad) loops written with the same floating-point expressions, compared byte for byte.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import Delaunay

from workstation.raster import grid
from workstation.raster.grid import _EPS, fill_voids_tin, lattice_tin, rasterize_triangles, tin_surface


def reference_rasterize(tri_u, tri_v, tri_z, out, target=None) -> int:
    """Every triangle on its own, over its whole bounding box, no pruning.

    Order of writes (a later write wins a cell on a shared edge): triangles by the size class
    ``ceil(log2(max(w, h)))`` of their clipped box, then by index; this is the order of the
    original bucketed implementation.
    """
    R, C = out.shape
    umin = np.maximum(np.ceil(tri_u.min(1) - _EPS).astype(np.int64), 0)
    umax = np.minimum(np.floor(tri_u.max(1) + _EPS).astype(np.int64), C - 1)
    vmin = np.maximum(np.ceil(tri_v.min(1) - _EPS).astype(np.int64), 0)
    vmax = np.minimum(np.floor(tri_v.max(1) + _EPS).astype(np.int64), R - 1)
    w, h = umax - umin + 1, vmax - vmin + 1
    keep = (w > 0) & (h > 0)
    size_class = np.ceil(np.log2(np.maximum(np.maximum(w, h), 1))).astype(np.int64)
    written = 0
    for t in np.flatnonzero(keep)[np.argsort(size_class[keep], kind="stable")]:
        qv, qu = np.mgrid[vmin[t] : vmax[t] + 1, umin[t] : umax[t] + 1]
        (p0u, p1u, p2u), (p0v, p1v, p2v) = tri_u[t], tri_v[t]
        with np.errstate(divide="ignore", invalid="ignore"):
            den = (p1v - p2v) * (p0u - p2u) + (p2u - p1u) * (p0v - p2v)
            l0 = ((p1v - p2v) * (qu - p2u) + (p2u - p1u) * (qv - p2v)) / den
            l1 = ((p2v - p0v) * (qu - p2u) + (p0u - p2u) * (qv - p2v)) / den
            l2 = 1.0 - l0 - l1
            m = (l0 >= -_EPS) & (l1 >= -_EPS) & (l2 >= -_EPS)
            if target is not None:
                m &= target[qv, qu]
            out[qv[m], qu[m]] = (l0 * tri_z[t, 0] + l1 * tri_z[t, 1] + l2 * tri_z[t, 2])[m]
        written += int(m.sum())
    return written


def reference_lattice(du, dv, z, valid, max_edge=None):
    """``lattice_tin`` as first written: the full barycentric formula for every corner and triangle."""
    R, C = z.shape
    out = np.full((R, C), np.nan)
    sl = {"A": (slice(0, R - 1), slice(0, C - 1)), "B": (slice(0, R - 1), slice(1, C)),
          "C": (slice(1, R), slice(0, C - 1)), "D": (slice(1, R), slice(1, C))}
    base = {"A": (0.0, 0.0), "B": (1.0, 0.0), "C": (0.0, 1.0), "D": (1.0, 1.0)}
    U = {k: base[k][0] + du[s] for k, s in sl.items()}
    V = {k: base[k][1] + dv[s] for k, s in sl.items()}
    Z = {k: z[s] for k, s in sl.items()}
    qvalid = valid[sl["A"]] & valid[sl["B"]] & valid[sl["C"]] & valid[sl["D"]]
    ad = (U["D"] - U["A"]) ** 2 + (V["D"] - V["A"]) ** 2 <= (U["C"] - U["B"]) ** 2 + (V["C"] - V["B"]) ** 2
    tris = []
    for corners in ((("A", "A"), ("B", "B"), ("D", "C")), (("A", "B"), ("D", "D"), ("C", "C"))):
        tu = [np.where(ad, U[a], U[b]) for a, b in corners]
        tv = [np.where(ad, V[a], V[b]) for a, b in corners]
        tz = [np.where(ad, Z[a], Z[b]) for a, b in corners]
        tris.append((tu, tv, tz, qvalid & grid._edges_ok(tu, tv, max_edge)))
    for k in ("A", "B", "C", "D"):
        qu, qv = base[k]
        view = out[sl[k]]
        for tu, tv, tz, ok in tris:
            l0, l1, l2 = grid._bary(tu[0], tv[0], tu[1], tv[1], tu[2], tv[2], qu, qv)
            inside = ok & (l0 >= -_EPS) & (l1 >= -_EPS) & (l2 >= -_EPS) & np.isnan(view)
            with np.errstate(invalid="ignore"):
                view[inside] = (l0 * tz[0] + l1 * tz[1] + l2 * tz[2])[inside]
    return out


def random_voids(rng, shape=(70, 90), n_voids=12, scatter=0.03, jitter=True):
    """Representatives on a jittered (or exact cell-centre) lattice with rectangular voids."""
    R, C = shape
    du = rng.uniform(-0.5, 0.5, shape) if jitter else np.zeros(shape)
    dv = rng.uniform(-0.5, 0.5, shape) if jitter else np.zeros(shape)
    z = rng.normal(0.0, 1.0, shape).cumsum(0).cumsum(1) / 10.0
    valid = rng.uniform(0, 1, shape) > scatter
    for _ in range(n_voids):
        h, w = rng.integers(2, 15, 2)
        r, c = rng.integers(0, R - h), rng.integers(0, C - w)
        valid[r : r + h, c : c + w] = False
    return du, dv, z, valid


def rim_triangles(du, dv, z, valid, out):
    """The rim Delaunay triangles ``fill_voids_tin`` rasterises, with their void mask."""
    voids = np.isnan(out)
    ii, jj = np.nonzero(valid & grid._dilate(voids, 1))
    pu, pv = jj + du[ii, jj], ii + dv[ii, jj]
    s = Delaunay(np.column_stack([pu, pv])).simplices
    return pu[s], pv[s], z[ii, jj][s], voids


def same_bits(a, b):
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("jitter", [True, False])  # False: cell centres on shared edges everywhere
def test_pruned_rasterize_equals_per_triangle_reference(rng, jitter):
    du, dv, z, valid = random_voids(rng, jitter=jitter)
    out0 = lattice_tin(du, dv, z, valid)
    tu, tv, tz, voids = rim_triangles(du, dv, z, valid, out0)
    # many triangles cover no void cell at all: the pruning has something to drop
    assert voids.any() and len(tu) > 500
    for target in (voids, None):
        ref = out0.copy()
        n_ref = reference_rasterize(tu, tv, tz, ref, target)
        for chunk in (2_000_000, 50):  # one array operation per group, or many small ones
            ours = out0.copy()
            n = rasterize_triangles(tu, tv, tz, ours, target=target, chunk=chunk)
            assert n == n_ref
            assert same_bits(ours, ref)


def test_rasterize_edge_cases_match_reference(rng):
    out0 = np.full((12, 15), np.nan)
    out0[::3, ::2] = 1.0
    target = np.isnan(out0)
    tu = np.array([[1.0, 6.0, 1.0],      # shares the edge (1,1)-(6,6) with the next one
                   [1.0, 6.0, 6.0],
                   [2.0, 4.0, 8.0],      # collinear: zero area
                   [-20.0, -5.0, -10.0],  # off the grid
                   [3.0, 3.0, 3.0],      # a point on a cell centre
                   [-3.0, 40.0, 5.0]])   # clipped by the grid
    tv = np.array([[1.0, 6.0, 6.0], [1.0, 6.0, 1.0], [2.0, 4.0, 8.0], [3.0, 4.0, 9.0], [7.0, 7.0, 7.0], [-4.0, 5.0, 30.0]])
    tz = rng.normal(0, 1, (len(tu), 3))
    for tgt in (target, None, np.zeros_like(target)):
        ref = out0.copy()
        ours = out0.copy()
        assert rasterize_triangles(tu, tv, tz, ours, target=tgt) == reference_rasterize(tu, tv, tz, ref, tgt)
        assert same_bits(ours, ref)
    assert rasterize_triangles(tu[:0], tv[:0], tz[:0], out0.copy()) == 0


def test_a_cell_centre_on_a_shared_edge_takes_the_last_triangle(rng):
    """Two triangles through one cell centre give values a few ulps apart; which one wins is
    the write order of the reference (size class, then index), whatever the grouping."""
    n = 300
    c = rng.integers(4, 36, (n, 2)).astype(float)  # the cell centre (u, v) on the shared edge
    d = rng.uniform(0.2, 3.0, (n, 2)) * rng.choice([-1.0, 1.0], (n, 2))
    nrm = np.column_stack([-d[:, 1], d[:, 0]])
    p, q = c - d, c + d
    r1 = c + nrm * rng.uniform(0.2, 2.0, (n, 1)) + d * rng.uniform(-1.0, 1.0, (n, 1))
    r2 = c - nrm * rng.uniform(0.2, 2.0, (n, 1)) + d * rng.uniform(-1.0, 1.0, (n, 1))
    zp, zq, z1, z2 = rng.normal(0, 10, (4, n))
    tri = np.concatenate([np.stack([p, q, r1], 1), np.stack([q, p, r2], 1)])  # (2n, 3, 2)
    tz = np.concatenate([np.stack([zp, zq, z1], 1), np.stack([zq, zp, z2], 1)])
    perm = rng.permutation(2 * n)
    tu, tv, tz = tri[perm, :, 0], tri[perm, :, 1], tz[perm]
    # the test has teeth: for many pairs the two triangles disagree in the last bits at c
    first, second = np.full((40, 40), np.nan), np.full((40, 40), np.nan)
    inv = np.argsort(perm)
    reference_rasterize(tu[inv[:n]], tv[inv[:n]], tz[inv[:n]], first)
    reference_rasterize(tu[inv[n:]], tv[inv[n:]], tz[inv[n:]], second)
    ci, cj = c[:, 1].astype(int), c[:, 0].astype(int)
    assert (first[ci, cj] != second[ci, cj]).sum() > n // 10
    target = np.ones((40, 40), bool)
    target[::7] = False
    for tgt in (None, target):
        ref = np.full((40, 40), np.nan)
        n_ref = reference_rasterize(tu, tv, tz, ref, tgt)
        for chunk in (2_000_000, 3):
            ours = np.full((40, 40), np.nan)
            assert rasterize_triangles(tu, tv, tz, ours, target=tgt, chunk=chunk) == n_ref
            assert same_bits(ours, ref)


def test_fill_voids_and_tin_surface_unchanged_by_the_fast_rasterizer(rng, monkeypatch):
    du, dv, z, valid = random_voids(rng, shape=(60, 75))
    out0 = lattice_tin(du, dv, z, valid)
    fast = [fill_voids_tin(out0, du, dv, z, valid, me) for me in (None, 4.0)]
    fast.append(tin_surface(du, dv, z, valid, tile=16))
    monkeypatch.setattr(grid, "rasterize_triangles", lambda tu, tv, tz, out, target=None: reference_rasterize(tu, tv, tz, out, target))
    slow = [fill_voids_tin(out0, du, dv, z, valid, me) for me in (None, 4.0)]
    slow.append(tin_surface(du, dv, z, valid, tile=16))
    for a, b in zip(fast, slow):
        assert same_bits(a, b)


@pytest.mark.parametrize("max_edge", [None, 1.2])
def test_lattice_tin_equals_reference(rng, max_edge):
    for jitter in (True, False):
        du, dv, z, valid = random_voids(rng, shape=(41, 53), jitter=jitter)
        assert same_bits(lattice_tin(du, dv, z, valid, max_edge), reference_lattice(du, dv, z, valid, max_edge))
