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
#: Faces whose sample points are projected at once (16 points each), and faces whose view
#: colours are compared at once (k² pairs each): bound the memory of :func:`view_samples` and
#: :func:`consistent_views` whatever the mesh's size.
SAMPLE_CHUNK, CONSISTENCY_CHUNK = 1 << 16, 1 << 14


def _sample_bary(n: int = 4) -> np.ndarray:
    """(n², 3) barycentric centroids of the n² triangles of a face split n times along each
    edge: points spread evenly over the face, whose mean colour stands for the face's."""
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    up = np.stack([i, j, n - 1 - i - j], -1)[i + j <= n - 1] + 1 / 3
    down = np.stack([i, j, n - 2 - i - j], -1)[i + j <= n - 2] + 2 / 3
    return np.concatenate([up, down]) / n


_SAMPLE_BARY = _sample_bary()


def view_samples(mesh: Mesh, rec: Reconstruction, views: np.ndarray, iid: int, chunk: int = SAMPLE_CHUNK):
    """Where the sample points (:func:`_sample_bary`, 16 per face) of the faces one of whose
    ``views`` (m, k) is image ``iid`` fall in that photo, ``chunk`` faces at a time: yields
    (faces (n,), slots (n,), u (n, 16), v (n, 16)), image coordinates clipped to the image.
    One photo and one chunk at a time, so that the memory does not grow with the mesh."""
    from workstation.registration.colorize import project

    im = rec.images[int(iid)]
    cam = rec.cameras[im.camera_id]
    faces, slots = np.nonzero(views == iid)
    for a in range(0, len(faces), chunk):
        f, s = faces[a:a + chunk], slots[a:a + chunk]
        pts = np.einsum("pk,nkd->npd", _SAMPLE_BARY, mesh.vertices[mesh.faces[f]])
        u, v, _ = project(pts.reshape(-1, 3), cam, im.pose)
        shape = (len(f), len(_SAMPLE_BARY))
        yield f, s, np.clip(u, 0, cam.width - 1).reshape(shape), np.clip(v, 0, cam.height - 1).reshape(shape)


def face_colours(mesh: Mesh, rec: Reconstruction, views: np.ndarray, photos) -> np.ndarray:
    """(m, k, 3) mean colour of every face in each of its ``views`` (m, k): the photo sampled
    bilinearly at 16 points spread evenly over the face (:func:`view_samples`) and averaged; NaN
    where the slot holds no view; ``photos`` maps an image id to its (h, w, 3) pixels. Shared by
    the exposure balance and the photo-consistency check."""
    from workstation.registration.colorize import bilinear

    colour = np.full(views.shape + (3,), np.nan)
    for iid in np.unique(views[views >= 0]):
        for f, s, u, v in view_samples(mesh, rec, views, int(iid)):
            c = bilinear(photos(int(iid)), u.ravel(), v.ravel())[:, :3]
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
    8-bit step and their resampling). The differences fill one array, pair by pair, whose
    median over the views present is taken in place."""
    d = np.empty((math.comb(colour.shape[1], 2),) + colour.shape[:1] + colour.shape[2:])
    for i, (a, b) in enumerate(zip(*np.triu_indices(colour.shape[1], 1))):
        np.subtract(colour[:, a], colour[:, b], out=d[i])
    d = np.abs(d, out=d).reshape(-1)
    if np.isnan(d).all():
        return 1.0
    return max(1.0, 1.4826 * float(np.nanmedian(d, overwrite_input=True)) / math.sqrt(2.0))


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
    (m, k) bool, optional: the views that take part (the others are kept as they are). Faces
    are processed ``CONSISTENCY_CHUNK`` at a time (the view-pair distances take k² values per face)."""
    ok = views >= 0 if eligible is None else (views >= 0) & eligible
    r = math.sqrt(-2.0 * math.log(CONSISTENCY_KERNEL)) * sigma
    keep = np.zeros(views.shape, bool)
    for a in range(0, len(views), CONSISTENCY_CHUNK):
        b = slice(a, a + CONSISTENCY_CHUNK)
        keep[b] = _mean_shift_keep(colour[b], ok[b], r, iterations)
    return keep | ((views >= 0) & ~ok)


def _mean_shift_keep(colour: np.ndarray, ok: np.ndarray, r: float, iterations: int) -> np.ndarray:
    """(m, k) bool: the views ``ok`` (m, k) whose ``colour`` (m, k, 3) lies within ``r`` of the
    face's dominant colour, found by the flat-kernel mean shift of :func:`consistent_views`."""
    col = np.where(ok[..., None], colour, 0.0)
    d = np.linalg.norm(col[:, :, None] - col[:, None, :], axis=3)  # (m, k, k)
    near = (d <= r) & ok[:, :, None] & ok[:, None, :]
    start = np.argmax(near.sum(axis=2), axis=1)
    rows = np.arange(len(ok))
    centre = col[rows, start]
    for _ in range(iterations):
        inside = ok & (np.linalg.norm(col - centre[:, None], axis=2) <= r)
        inside[rows, start] = True
        centre = (col * inside[..., None]).sum(axis=1) / inside.sum(axis=1)[:, None]
    keep = ok & (np.linalg.norm(col - centre[:, None], axis=2) <= r)
    keep[rows, start] = ok[rows, start]
    few = ok.sum(axis=1) < 3
    keep[few] = ok[few]
    return keep


def occluded_views(mesh: Mesh, rec: Reconstruction, views: np.ndarray, voted: np.ndarray, dropped: np.ndarray,
                   window: int = OCCLUSION_WINDOW) -> np.ndarray:
    """(m, k) bool: the views (``views`` (m, k)) whose image of a face overlaps a region of
    the photo where an occluder missing from the mesh stands.

    An occluder (a tree, a passer-by) is one connected blob in each photo, and the faces
    behind it that have enough views to vote (``voted`` (m, k): the views that took part in
    :func:`consistent_views`) lose that photo's view there (``dropped`` (m, k)). In each photo
    the votes are counted per pixel at the faces' 16 sample points (+1 dropped, -1 kept) and
    summed exactly, in integers, over a ``window`` x ``window`` pixel box (:func:`_vote_table`,
    :func:`_box_sum`): a pixel is occluded where the dropped votes outnumber the kept ones (a
    tie is not). A view of any face (voted or not: the faces with one or two views have no
    majority of their own) is occluded when one of the face's sample points falls on an
    occluded pixel, as a view is a full candidate only when all the face's probes are visible
    (:func:`workstation.mesh.texture.ranked_views`). One photo at a time; the table covers only
    the bounding box of the photo's voting sample points."""
    out = np.zeros(views.shape, bool)
    for iid in np.unique(views[dropped]):
        parts = [(f, s, np.rint(u).astype(np.int32), np.rint(v).astype(np.int32))
                 for f, s, u, v in view_samples(mesh, rec, views, int(iid))]
        f, s, x, y = (np.concatenate(a) for a in zip(*parts))
        vote = dropped[f, s].astype(np.int32) - (voted[f, s] & ~dropped[f, s])
        table, x0, y0 = _vote_table(x, y, vote)
        for a in range(0, len(f), SAMPLE_CHUNK):
            b = slice(a, a + SAMPLE_CHUNK)
            out[f[b], s[b]] = (_box_sum(table, x[b] - x0, y[b] - y0, window) > 0).any(axis=1)
    return out


def _vote_table(x: np.ndarray, y: np.ndarray, vote: np.ndarray):
    """The votes (``vote`` (n,) int32, one per row, cast at each of the row's pixels ``x``,
    ``y`` (n, p) int32: columns and rows) as an exact int32 summed-area table over the bounding
    box of the pixels that vote: (table (h + 1, w + 1), table[i, j] the sum over the box's rows
    < i and columns < j; the box's first column x0 and row y0)."""
    cast = vote != 0
    if not cast.any():
        return np.zeros((1, 1), np.int32), 0, 0
    xs, ys = x[cast], y[cast]
    x0, y0 = int(xs.min()), int(ys.min())
    table = np.zeros((int(ys.max()) - y0 + 2, int(xs.max()) - x0 + 2), np.int32)
    np.add.at(table, (ys.ravel() - y0 + 1, xs.ravel() - x0 + 1), np.repeat(vote[cast], x.shape[1]))
    np.cumsum(table, axis=0, dtype=np.int32, out=table)
    np.cumsum(table, axis=1, dtype=np.int32, out=table)
    return table, x0, y0


def _box_sum(table: np.ndarray, x: np.ndarray, y: np.ndarray, window: int) -> np.ndarray:
    """The sums of a summed-area ``table`` (:func:`_vote_table`) over the ``window`` x
    ``window`` boxes centred at the pixels ``x``, ``y`` (any shape, int, relative to the table's
    box; each box placed as :func:`scipy.ndimage.uniform_filter` places it and clipped to the
    table's box, outside which no vote lies)."""
    h, w = table.shape[0] - 1, table.shape[1] - 1
    lo, hi = window // 2, window - 1 - window // 2
    c0, c1 = np.clip(x - lo, 0, w), np.clip(x + hi + 1, 0, w)
    r0, r1 = np.clip(y - lo, 0, h), np.clip(y + hi + 1, 0, h)
    return table[r1, c1] - table[r0, c1] - table[r1, c0] + table[r0, c0]
