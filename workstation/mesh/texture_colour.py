"""Colour agreement between the views of a face, for :mod:`workstation.mesh.texture`: mean
face colours in each view, per-photo exposure gains (Brown & Lowe 2007, section 6), the
photo-consistency vote (Waechter, Moehrle & Goesele 2014, section 4.1) and the per-photo
occlusion masks pooled from its outcome; steps 4 and 5 of that module's description."""

from __future__ import annotations

import math

import numpy as np

from workstation.core.products import Mesh, Reconstruction


#: Views per face compared when balancing exposure; Brown & Lowe's sigmas (grey levels, gain).
BALANCE_VIEWS, SIGMA_N, SIGMA_G = 4, 10.0, 0.1
#: Candidate views per face for the photo-consistency check; the Gaussian kernel value below
#: which Waechter et al. drop a view (6e-3, a Mahalanobis distance of sqrt(-2 ln 6e-3) = 3.2).
CONSISTENCY_VIEWS, CONSISTENCY_KERNEL = 8, 6e-3
#: Side, in pixels, of the box over which the photo-consistency votes of neighbouring faces are
#: pooled into a photo's occlusion mask (:func:`occluded_views`).
OCCLUSION_WINDOW = 9


def _sample_bary(n: int = 4) -> np.ndarray:
    """(n², 3) barycentric centroids of the n² triangles of a face split n times along each
    edge: points spread evenly over the face, whose mean colour stands for the face's."""
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    up = np.stack([i, j, n - 1 - i - j], -1)[i + j <= n - 1] + 1 / 3
    down = np.stack([i, j, n - 2 - i - j], -1)[i + j <= n - 2] + 2 / 3
    return np.concatenate([up, down]) / n


_SAMPLE_BARY = _sample_bary()


def view_samples(mesh: Mesh, rec: Reconstruction, views: np.ndarray) -> dict:
    """Where the faces' sample points (:func:`_sample_bary`, 16 per face) fall in each of their
    ``views`` (m, k): image id -> (faces (n,), slots (n,), u (n, 16), v (n, 16)), image
    coordinates clipped to the image, float32. Computed once and shared by
    :func:`face_colours` and :func:`occluded_views`."""
    from workstation.registration.colorize import project

    out = {}
    for iid in np.unique(views[views >= 0]):
        f, s = np.nonzero(views == iid)
        pts = np.einsum("pk,nkd->npd", _SAMPLE_BARY, mesh.vertices[mesh.faces[f]])
        im = rec.images[int(iid)]
        cam = rec.cameras[im.camera_id]
        u, v, _ = project(pts.reshape(-1, 3), cam, im.pose)
        shape = (len(f), len(_SAMPLE_BARY))
        out[int(iid)] = (f, s, np.clip(u, 0, cam.width - 1).reshape(shape).astype(np.float32),
                         np.clip(v, 0, cam.height - 1).reshape(shape).astype(np.float32))
    return out


def face_colours(mesh: Mesh, rec: Reconstruction, views: np.ndarray, photos, samples: dict | None = None) -> np.ndarray:
    """(m, k, 3) mean colour of every face in each of its ``views`` (m, k): the photo sampled
    bilinearly at 16 points spread evenly over the face (:func:`_sample_bary`) and averaged; NaN
    where the slot holds no view; ``photos`` maps an image id to its (h, w, 3) pixels;
    ``samples``: :func:`view_samples` of ``views`` when already computed. Shared by the
    exposure balance and the photo-consistency check."""
    from workstation.registration.colorize import bilinear

    colour = np.full(views.shape + (3,), np.nan)
    for iid, (f, s, u, v) in (view_samples(mesh, rec, views) if samples is None else samples).items():
        c = bilinear(photos(int(iid)), u.ravel().astype(np.float64), v.ravel().astype(np.float64))[:, :3]
        colour[f, s] = c.reshape(len(f), -1, 3).mean(axis=1)
    return colour


def exposure_gains(views: np.ndarray, colour: np.ndarray) -> dict:
    """Per-photo, per-channel gains (image id -> (3,) float) that make the photos agree where
    they see the same faces (Brown & Lowe 2007, section 6; module description, step 4).

    ``views`` (m, k): the faces' candidate views; ``colour`` (m, k, 3): their mean colours
    (:func:`face_colours`). For each pair of photos i, j, N_ij counts the faces both see and
    I_ij is photo i's mean colour over those faces; the gains g minimise
    sum N_ij ((g_i I_ij - g_j I_ji)^2 / SIGMA_N^2 + (1 - g_i)^2 / SIGMA_G^2), one linear system
    per channel. Photos sharing no face keep gain 1."""
    ids = np.unique(views[views >= 0])
    if ids.size < 2 or views.shape[1] < 2:
        return {}
    slot = np.searchsorted(ids, np.maximum(views, ids[0]))
    n = ids.size
    N = np.zeros((n, n))
    S = np.zeros((n, n, 3))  # S[i, j]: sum of photo i's colours over the faces i and j share
    for a in range(views.shape[1]):
        for b in range(views.shape[1]):
            both = (views[:, a] >= 0) & (views[:, b] >= 0) & (a != b)
            np.add.at(N, (slot[both, a], slot[both, b]), 1.0)
            np.add.at(S, (slot[both, a], slot[both, b]), colour[both, a])
    I = S / np.maximum(N, 1.0)[..., None]
    gains = np.ones((n, 3))
    alone = N.sum(axis=1) == 0
    for c in range(3):
        A = np.diag((N * (2 * I[..., c] ** 2 / SIGMA_N**2 + 1 / SIGMA_G**2)).sum(axis=1))
        A -= 2 * N * I[..., c] * I[..., c].T / SIGMA_N**2 * (1 - np.eye(n))
        b = N.sum(axis=1) / SIGMA_G**2
        A[alone, alone], b[alone] = 1.0, 1.0
        gains[:, c] = np.linalg.solve(A, b)
    return {int(i): gains[k] for k, i in enumerate(ids)}


def colour_noise(colour: np.ndarray) -> float:
    """Robust standard deviation (grey levels, per channel) of one view's mean face colour:
    from the differences between every two views of the same face (each difference has
    variance 2 sigma^2), sigma = 1.4826 median |difference| / sqrt(2); views of an occluder
    are a minority of the pairs and do not move the median. At least 1 grey level (the photos'
    8-bit step and their resampling)."""
    k = colour.shape[1]
    a, b = np.triu_indices(k, 1)
    d = np.abs(colour[:, a] - colour[:, b])
    d = d[np.isfinite(d)]
    if d.size == 0:
        return 1.0
    return max(1.0, 1.4826 * float(np.median(d)) / math.sqrt(2.0))


def consistent_views(views: np.ndarray, colour: np.ndarray, sigma: float, iterations: int = 5,
                     eligible: np.ndarray | None = None) -> np.ndarray:
    """(m, k) bool: the views whose colour agrees with the face's dominant colour (Waechter,
    Moehrle & Goesele 2014, section 4.1, with a flat kernel of the paper's radius).

    The radius is r = sqrt(-2 ln CONSISTENCY_KERNEL) sigma (3.2 sigma; ``sigma``: the colour
    noise, :func:`colour_noise`). For faces with >= 3 views, the centre starts at the view
    colour with the most other views within r (ties: the best view) and moves to the mean of
    the view colours within r of it, a few times (mean shift); views farther than r from the
    final centre are occluded by something the mesh lacks (a tree, a passer-by) and dropped.
    Faces with fewer views, and each face's starting view, keep their views. ``eligible``
    (m, k) bool, optional: the views that take part (the others are kept as they are)."""
    ok = views >= 0 if eligible is None else (views >= 0) & eligible
    col = np.where(ok[..., None], colour, 0.0)
    r = math.sqrt(-2.0 * math.log(CONSISTENCY_KERNEL)) * sigma
    d = np.linalg.norm(col[:, :, None] - col[:, None, :], axis=3)  # (m, k, k)
    near = (d <= r) & ok[:, :, None] & ok[:, None, :]
    start = np.argmax(near.sum(axis=2), axis=1)
    rows = np.arange(len(views))
    centre = col[rows, start]
    for _ in range(iterations):
        inside = ok & (np.linalg.norm(col - centre[:, None], axis=2) <= r)
        inside[rows, start] = True
        centre = (col * inside[..., None]).sum(axis=1) / inside.sum(axis=1)[:, None]
    keep = ok & (np.linalg.norm(col - centre[:, None], axis=2) <= r)
    keep[rows, start] = ok[rows, start]
    few = ok.sum(axis=1) < 3
    keep[few] = ok[few]
    return keep | ((views >= 0) & ~ok)


def occluded_views(mesh: Mesh, rec: Reconstruction, views: np.ndarray, voted: np.ndarray, dropped: np.ndarray,
                   window: int = OCCLUSION_WINDOW, samples: dict | None = None) -> np.ndarray:
    """(m, k) bool: the views (``views`` (m, k)) whose image of a face overlaps a region of
    the photo where an occluder missing from the mesh stands.

    An occluder (a tree, a passer-by) is one connected blob in each photo, and the faces
    behind it that have enough views to vote (``voted`` (m, k): the views that took part in
    :func:`consistent_views`) lose that photo's view there (``dropped`` (m, k)). In each photo
    the votes are counted per pixel at the faces' 16 sample points, dropped and kept
    separately, and summed over a ``window`` x ``window`` pixel box: a pixel is occluded where
    the dropped votes outnumber the kept ones. A view of any face (voted or not: the faces with
    one or two views have no majority of their own) is occluded when one of the face's sample
    points falls on an occluded pixel, as a view is a full candidate only when all the face's
    probes are visible (:func:`workstation.mesh.texture.ranked_views`). ``samples``:
    :func:`view_samples` of ``views`` when already computed."""
    from scipy.ndimage import uniform_filter

    out = np.zeros(views.shape, bool)
    samples = view_samples(mesh, rec, views) if samples is None else samples
    for iid in np.unique(views[dropped]):
        f, s, u, v = samples[int(iid)]
        cam = rec.cameras[rec.images[int(iid)].camera_id]
        pix = np.round(v).astype(np.int64) * cam.width + np.round(u).astype(np.int64)
        n = cam.width * cam.height
        dr, kept = dropped[f, s], voted[f, s] & ~dropped[f, s]
        count = [uniform_filter(np.bincount(pix[sel].ravel(), minlength=n).reshape(cam.height, cam.width)
                                .astype(np.float64), window, mode="constant") for sel in (dr, kept)]
        occluded = (count[0] > np.maximum(count[1], 0.5 / window**2)).ravel()  # half a vote: not rounding
        out[f, s] = occluded[pix].any(axis=1)
    return out
