"""Ties of the DEM interpolations are decided by a fixed rule, not by the rounding of the
coordinates: representatives moved by 1e-9 cell (what a change of unit or of origin does to
them) give the same surface. Lattices of points are where the ties are: co-circular quads,
cell centres equally far from several points, points on cell edges."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import Delaunay

from workstation.core.cloud import Cloud
from workstation.core.products import Raster
from workstation.raster.dem import DemParams, _discrete_sibson, _idw, build_dem, sample_bilinear
from workstation.raster.grid import GridSpec, canonical_ties, tin_surface

NOISE = 1e-9  # cells: float64 rounding of a 5e6 m northing on a 1 m cell


def lattice_reps(shape, du0, dv0, holes=True):
    """One representative per cell at the same offset (``du0``, ``dv0``) in every cell, on a
    twisted surface, with two rectangular voids for the Delaunay fill."""
    R, C = shape
    v, u = np.mgrid[0:R, 0:C].astype(float)
    du, dv = np.full(shape, du0), np.full(shape, dv0)
    z = np.sin((u + du) / 3.0) * np.cos((v + dv) / 4.0) + 0.05 * (u + du) * (v + dv)
    valid = np.ones(shape, bool)
    if holes:
        valid[5:12, 8:20] = False
        valid[20:23, 3:6] = False
    return du, dv, np.where(valid, z, np.nan), valid


def jiggle(du, dv, seed):
    rng = np.random.default_rng(seed)
    return du + rng.uniform(-NOISE, NOISE, du.shape), dv + rng.uniform(-NOISE, NOISE, dv.shape)


@pytest.mark.parametrize("offset", [(0.0, 0.0), (0.25, -0.1), (-0.5, 0.3)])
def test_tin_nn_idw_of_a_lattice_ignore_rounding(offset):
    du, dv, z, valid = lattice_reps((30, 36), *offset)
    tin = tin_surface(du, dv, z, valid)
    cells = np.isfinite(tin)
    assert cells.sum() > 0.9 * z.size
    ref = {"tin": tin, "idw": _idw(du, dv, z, valid, cells, 8, 2.0),
           "nn": _discrete_sibson(du, dv, z, valid, cells, tin, 24.0)}
    for seed in range(3):
        ju, jv = jiggle(du, dv, seed)
        jt = tin_surface(ju, jv, z, valid)
        got = {"tin": jt, "idw": _idw(ju, jv, z, valid, cells, 8, 2.0),
               "nn": _discrete_sibson(ju, jv, z, valid, cells, jt, 24.0)}
        for name in ref:
            np.testing.assert_array_equal(np.isnan(got[name]), np.isnan(ref[name]), err_msg=name)
            np.testing.assert_allclose(got[name], ref[name], rtol=0, atol=1e-6, err_msg=name)


def test_canonical_ties_split_a_lattice_one_way():
    v, u = np.mgrid[0:12, 0:15].astype(float)
    pu, pv = u.ravel() + 0.3, v.ravel() - 0.2
    rng = np.random.default_rng(4)

    def triangles(pu, pv):
        t = Delaunay(np.column_stack([pu, pv]))
        s = canonical_ties(pu, pv, t.simplices, t.neighbors)
        area = np.abs((pu[s[:, 1]] - pu[s[:, 0]]) * (pv[s[:, 2]] - pv[s[:, 0]])
                      - (pu[s[:, 2]] - pu[s[:, 0]]) * (pv[s[:, 1]] - pv[s[:, 0]]))
        return {tuple(sorted(x)) for x in s[area > 1e-6]}  # hull slivers of collinear points cover nothing

    ref = triangles(pu, pv)
    assert len(ref) == 2 * 11 * 14
    # every unit square split along the diagonal from its first point in row-major order (AD)
    assert all(max(t) - min(t) == 16 for t in ref)
    for _ in range(3):
        assert triangles(pu + rng.uniform(-NOISE, NOISE, pu.size), pv + rng.uniform(-NOISE, NOISE, pv.size)) == ref


def test_canonical_ties_leave_generic_points_alone(rng):
    pts = rng.uniform(0, 40, (400, 2))
    t = Delaunay(pts)
    s = canonical_ties(pts[:, 0], pts[:, 1], t.simplices, t.neighbors)
    assert {tuple(sorted(x)) for x in s} == {tuple(sorted(x)) for x in t.simplices}


def test_points_on_cell_edges_and_bilinear_on_centre_rows():
    # points exactly on the edges of 1 m cells, and the same points off by a float64 rounding
    g = np.arange(0.0, 30.0, 0.5)
    x, y = (a.ravel() for a in np.meshgrid(g, g))
    z = 10 + np.sin(x / 4) + 0.01 * x * y
    cls = {"classification": np.full(x.size, 2, np.uint8)}
    r0 = build_dem(Cloud(np.column_stack([x, y, z]), cls), DemParams(resolution=1.0, method="nn"))
    r1 = build_dem(Cloud(np.column_stack([x - 1e-12, y + 1e-12, z]), cls), DemParams(resolution=1.0, method="nn"))
    assert r0.shape == r1.shape and r0.transform == r1.transform
    np.testing.assert_array_equal(r0.array, r1.array)
    # a point on a row of cell centres next to a missing row takes that row's value
    a = np.array([[1.0, 2.0], [3.0, 4.0], [np.nan, np.nan]])
    ras = Raster(a, (1.0, 0.0, 0.0, 0.0, -1.0, 3.0))
    got = sample_bilinear(ras, np.array([0.5, 1.0, 1.0]), np.array([1.5, 1.5 - 1e-12, 1.0]))
    np.testing.assert_allclose(got[:2], [3.0, 3.5])
    assert np.isnan(got[2])  # between a row and the missing one: undefined
