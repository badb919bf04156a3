"""Neighbourhood PCA and grouped plane fits against known answers and a per-group SVD loop."""

from __future__ import annotations

import doctest

import numpy as np
import pytest
from scipy.spatial import cKDTree

from workstation.core import pca
from workstation.core.errors import InvalidInputError
from workstation.core.pca import grouped_plane_fit, local_pca, sym3_eigen, sym3_eigenvector_z


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def svd_plane(pts):
    """Reference: centroid, unit normal (z >= 0), singular values of the centred points."""
    c = pts.mean(axis=0)
    _, s, vt = np.linalg.svd(pts - c, full_matrices=False)
    n = vt[-1] if vt[-1, 2] >= 0 else -vt[-1]
    return c, n, s


def noisy_plane(rng, n, normal, offset, sigma, extent=20.0):
    """Points on ``normal . x = offset`` (|n_z| well above 0) with Gaussian noise along z."""
    xy = rng.uniform(-extent, extent, (n, 2))
    z = (offset - xy @ normal[:2]) / normal[2] + rng.normal(0, sigma, n)
    return np.column_stack([xy, z])


def test_local_pca_recovers_a_tilted_plane_with_noise():
    rng = np.random.default_rng(0)
    normal = unit([0.3, -0.2, 1.0])
    sigma = 0.01
    xyz = noisy_plane(rng, 4000, normal, 5.0, sigma) + [6.0e5, 5.2e6, 300.0]  # UTM-sized coordinates
    r = local_pca(xyz, k=40)
    assert r.normals.shape == (4000, 3) and r.indices.shape == (4000, 40) and r.distances.shape == (4000, 40)
    assert np.all(r.normals[:, 2] > 0)  # orient="up"
    ang = np.degrees(np.arccos(np.clip(r.normals @ normal, -1, 1)))
    assert np.median(ang) < 1.0
    # smallest eigenvalue: variance along the normal (noise along z projected on the normal,
    # less the share a 40-point fit absorbs); the others: the in-plane spread
    s = np.sqrt(np.median(r.eigenvalues[:, 0])) / (sigma * normal[2])
    assert 0.75 < s < 1.05
    assert np.all(np.diff(r.eigenvalues, axis=1) >= 0)
    np.testing.assert_allclose(np.linalg.norm(r.normals, axis=1), 1.0, atol=1e-12)


def test_local_pca_matches_a_loop_of_svd():
    rng = np.random.default_rng(1)
    xyz = rng.normal(0, 1, (500, 3)) * [3.0, 2.0, 0.5]
    k = 12
    r = local_pca(xyz, k=k, orient=None)
    _, idx = cKDTree(xyz).query(xyz, k=k)
    np.testing.assert_array_equal(r.indices, idx)
    for i in range(0, 500, 7):
        c, n, s = svd_plane(xyz[idx[i]])
        np.testing.assert_allclose(r.centroids[i], c, atol=1e-12)
        np.testing.assert_allclose(r.eigenvalues[i], np.sort(s ** 2 / k), rtol=1e-9, atol=1e-12)
        assert abs(abs(r.normals[i] @ n) - 1.0) < 1e-9
    up = local_pca(xyz, k=k)
    np.testing.assert_array_equal(up.normals, r.normals * np.where(r.normals[:, 2:3] < 0, -1.0, 1.0))


def test_local_pca_radius_matches_brute_force_and_query_points():
    rng = np.random.default_rng(2)
    xyz = rng.uniform(0, 10, (800, 3)) * [1, 1, 0.2]
    q = rng.uniform(0, 10, (50, 3)) * [1, 1, 0.2]
    r = local_pca(xyz, radius=1.5, query=q)
    assert r.distances is None and r.indptr.shape == (51,)
    d = np.linalg.norm(q[:, None, :] - xyz[None, :, :], axis=2)
    for i in range(50):
        inside = np.flatnonzero(d[i] <= 1.5)
        got = r.indices[r.indptr[i]:r.indptr[i + 1]]
        np.testing.assert_array_equal(np.sort(got), inside)
        assert r.counts[i] == inside.size
        c, n, s = svd_plane(xyz[inside])
        np.testing.assert_allclose(r.centroids[i], c, atol=1e-12)
        np.testing.assert_allclose(r.eigenvalues[i], np.sort(s ** 2 / inside.size), rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(r.normals[i], n, atol=1e-9)


def test_local_pca_search_space_and_chunks():
    """Neighbours come from ``search_xyz``; covariances from ``xyz``; blocks change nothing."""
    rng = np.random.default_rng(3)
    xyz = rng.uniform(0, 5, (300, 3))
    stretched = xyz * [4.0, 1.0, 1.0]
    r = local_pca(xyz, k=10, search_xyz=stretched)
    _, idx = cKDTree(stretched).query(stretched, k=10)
    np.testing.assert_array_equal(r.indices, idx)
    np.testing.assert_allclose(r.centroids, xyz[idx].mean(axis=1), atol=1e-12)
    small = local_pca(xyz, k=10, search_xyz=stretched, chunk=37)
    np.testing.assert_array_equal(small.normals, r.normals)
    np.testing.assert_array_equal(small.eigenvalues, r.eigenvalues)
    assert local_pca(xyz[:4], k=10).indices.shape == (4, 4)  # k capped at n


def test_local_pca_bad_input():
    xyz = np.zeros((10, 3))
    with pytest.raises(InvalidInputError, match="exactly one"):
        local_pca(xyz)
    with pytest.raises(InvalidInputError, match="exactly one"):
        local_pca(xyz, k=3, radius=1.0)
    with pytest.raises(InvalidInputError, match=r"\(n, 3\)"):
        local_pca(np.zeros((10, 2)), k=3)
    with pytest.raises(InvalidInputError, match="radius"):
        local_pca(xyz, radius=0.0)
    with pytest.raises(InvalidInputError, match="search_xyz"):
        local_pca(xyz, k=3, query=xyz, search_xyz=xyz)
    with pytest.raises(InvalidInputError, match="orient"):
        local_pca(xyz + np.arange(30).reshape(10, 3) ** 2, k=3, orient="down")


def test_grouped_plane_fit_matches_a_loop_of_svd():
    """Random planes with noise, unlabelled points (-1) and an empty group."""
    rng = np.random.default_rng(4)
    m, pts, lab, truth = 30, [], [], []
    for g in range(m):
        if g == 7:
            truth.append(None)
            continue
        nrm = unit(rng.normal(0, 1, 3) * [1, 1, 3] + [0, 0, 0.5])
        nrm = nrm if nrm[2] > 0.2 else unit(nrm * [1, 1, 0] + [0, 0, 1])
        size = int(rng.integers(4, 400))
        p = noisy_plane(rng, size, nrm, rng.normal(0, 50), rng.uniform(0, 0.05), extent=rng.uniform(1, 30))
        pts.append(p + [4.5e5, 5.4e6, 0.0])
        lab.append(np.full(size, g))
        truth.append(nrm)
    pts.append(rng.normal(0, 100, (50, 3)))
    lab.append(np.full(50, -1))
    xyz, labels = np.vstack(pts), np.concatenate(lab)
    perm = rng.permutation(len(xyz))
    xyz, labels = xyz[perm], labels[perm]
    g = grouped_plane_fit(xyz, labels, m)
    assert g.normals.shape == (m, 3) and g.counts[7] == 0 and g.rms[7] == 0
    for q in range(m):
        if q == 7:
            continue
        sel = xyz[labels == q]
        c, n, s = svd_plane(sel)
        assert g.counts[q] == len(sel)
        np.testing.assert_allclose(g.centroids[q], c, rtol=0, atol=1e-8)
        np.testing.assert_allclose(g.normals[q], n, atol=1e-8)
        rms = np.sqrt(np.mean(((sel - c) @ n) ** 2))
        np.testing.assert_allclose(g.rms[q], rms, rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(g.eigenvalues[q], np.sort(s ** 2 / len(sel)), rtol=1e-6, atol=1e-9)
        np.testing.assert_allclose(g.offsets[q], -n @ c, rtol=1e-12)
    assert np.all(g.normals[:, 2] >= 0)
    fast = grouped_plane_fit(xyz, labels, m, residuals=False)  # rms from the smallest eigenvalue
    np.testing.assert_array_equal(fast.normals, g.normals)
    np.testing.assert_array_equal(fast.eigenvalues, g.eigenvalues)
    np.testing.assert_allclose(fast.rms, g.rms, rtol=1e-6, atol=1e-7)


def test_grouped_plane_fit_known_planes_and_errors():
    xy = np.array([[0, 0], [2, 0], [0, 2], [2, 2], [1, 1.0]])
    flat = np.column_stack([xy, np.full(5, 7.0)])
    roof = np.column_stack([xy, 1.0 + 0.5 * xy[:, 1]])
    g = grouped_plane_fit(np.vstack([roof, flat]), np.repeat([1, 0], 5))
    np.testing.assert_allclose(g.normals, [[0, 0, 1], unit([0, -0.5, 1])], atol=1e-12)
    np.testing.assert_allclose(g.centroids, [[1, 1, 7], [1, 1, 1.5]], atol=1e-12)
    np.testing.assert_allclose(g.rms, 0, atol=1e-12)
    np.testing.assert_allclose(g.offsets, [-7.0, -(unit([0, -0.5, 1]) @ [1, 1, 1.5])], atol=1e-12)
    with pytest.raises(InvalidInputError, match="labels"):
        grouped_plane_fit(flat, np.zeros(4, int))
    with pytest.raises(InvalidInputError, match="labels"):
        grouped_plane_fit(flat, np.zeros(5))
    with pytest.raises(InvalidInputError, match="number of groups"):
        grouped_plane_fit(flat, np.arange(5), 3)


def test_closed_form_eigen_matches_lapack():
    rng = np.random.default_rng(5)
    a = rng.normal(0, 1, (2000, 3, 3))
    cov = a @ a.transpose(0, 2, 1)
    w, v = np.linalg.eigh(cov)
    l1, l2, l3 = sym3_eigen(cov)
    np.testing.assert_allclose(np.column_stack([l3, l2, l1]), w, rtol=1e-6, atol=1e-9)
    entries = (cov[:, 0, 0], cov[:, 1, 1], cov[:, 2, 2], cov[:, 0, 1], cov[:, 0, 2], cov[:, 1, 2])
    gap = np.minimum(w[:, 1] - w[:, 0], w[:, 2] - w[:, 1]) / w[:, 2]
    ok = gap > 1e-3  # an eigenvector is defined only apart from the other eigenvalues
    np.testing.assert_allclose(np.abs(sym3_eigenvector_z(*entries, l3))[ok], np.abs(v[ok, 2, 0]), atol=1e-5)
    np.testing.assert_allclose(np.abs(sym3_eigenvector_z(*entries, l1))[ok], np.abs(v[ok, 2, 2]), atol=1e-5)


def test_docstring_examples():
    res = doctest.testmod(pca, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert res.attempted >= 3 and res.failed == 0
