"""Roof faces of a building part: the lower envelope of its planes, or, where the roof is not
convex (cross-gabled L and T roofs, valleys), their arrangement.

The lower envelope of a part's planes (:func:`lower_envelope`; :func:`envelope_faces` drops the
planes the points contradict) is the roof of every convex roof (flat, shed, gabled, hipped, pyramid); where two gabled wings cross,
the valleys make the roof the *upper* envelope of some planes and the lower of others, and the
envelope stretches one plane over the whole part. This module builds such roofs as geoflow / 3DBAG
(Peters et al. 2022) and PolyFit (Nan & Wonka 2017) do, in a reduced form:

1. the part polygon is cut by the lines where every pair of its planes meet (the arrangement):
   every roof edge between two planes (ridge, hip, valley) is one of these lines;
2. every arrangement cell takes the plane that owns most of the ownership-raster cells whose
   centres fall in it (a cell without raster cells takes the label of the nearest raster cell);
3. where two neighbouring cells of different planes do not meet on those planes' intersection
   line (a vertical jump, which no wall closes), cells on the jumps are relabelled one at a time,
   each time the move that shortens the jumps at the smallest loss of raster votes; cells
   still on jumps are then relabelled jointly (every labelling of them, while few); if jumps
   remain, the plane owning the fewest raster cells is left out and the arrangement rebuilt;
4. the cells of one plane are merged into faces.

The result replaces the envelope only when it is continuous everywhere (watertight once walled)
and more raster cells agree with it than with the envelope; a part whose envelope keeps all its
planes (the envelope agrees with the points) keeps the envelope unchanged, so convex roofs come
out exactly as from :func:`envelope_faces`.
"""

from __future__ import annotations

import numpy as np


#: Height gap (m) above which two faces along a shared edge count as not meeting; far below the
#: vertex welding tolerance of :func:`~workstation.buildings.models.weld` (1e-4 m).
JUMP_TOL = 1e-6

#: Fewest raster cells a plane must own in the part to take part in the arrangement (as in
#: :func:`~workstation.buildings.models.envelope_faces`).
MIN_CELLS = 4


def halfplane_clip(poly: np.ndarray, a: float, b: float, c: float) -> np.ndarray:
    """Sutherland-Hodgman clip of a convex polygon (k, 2) to a x + b y + c <= 0."""
    if len(poly) == 0:
        return poly
    s = poly @ np.array([a, b]) + c
    nxt = np.roll(np.arange(len(poly)), -1)
    out = []
    for i in range(len(poly)):
        j = nxt[i]
        if s[i] <= 0:
            out.append(poly[i])
        if (s[i] < 0 < s[j]) or (s[j] < 0 < s[i]):
            t = s[i] / (s[i] - s[j])
            out.append(poly[i] + t * (poly[j] - poly[i]))
    return np.array(out).reshape(-1, 2)


def lower_envelope(part, normals: np.ndarray, points: np.ndarray) -> list:
    """Faces of the lower envelope of planes (normals (p, 3) up, points (p, 3)) over a shapely
    polygon ``part``: [(plane index, shapely polygon)], each the part clipped to where that
    plane is the lowest."""
    import shapely

    g, h = _plane_coefficients(normals, points)  # z_i(x, y) = g_i . (x, y) + h_i
    x0, y0, x1, y1 = part.bounds
    box = np.array([[x0 - 1, y0 - 1], [x1 + 1, y0 - 1], [x1 + 1, y1 + 1], [x0 - 1, y1 + 1]])
    out = []
    for i in range(len(normals)):
        cell = box
        for j in range(len(normals)):
            if j != i:
                cell = halfplane_clip(cell, *(g[i] - g[j]), h[i] - h[j])
        if len(cell) < 3:
            continue
        piece = part.intersection(shapely.Polygon(cell))
        for geom in getattr(piece, "geoms", [piece]):
            if geom.geom_type == "Polygon" and geom.area > SLIVER_AREA:
                out.append((i, shapely.orient_polygons(geom)))
    return out


def envelope_faces(poly, normals, points, grid, centres):
    """Lower-envelope faces of a part; planes whose face covers under four raster cells, or
    holds under half cells of their own label (an envelope the points contradict), are dropped
    one at a time (smallest first) and the envelope recomputed."""
    import shapely

    use = np.arange(len(normals))
    for _ in range(len(normals)):
        faces = lower_envelope(poly, normals[use], points[use])
        if len(use) == 1:
            break
        bad = []
        area = np.bincount([k for k, _ in faces], [f.area for _, f in faces], minlength=len(use))
        for k, face in faces:
            inside = shapely.contains_xy(face, centres[..., 0], centres[..., 1]) & (grid != -1)
            if inside.sum() < 4 or np.mean(grid[inside] == use[k]) < 0.5:  # under 4 cells, or contradicted
                bad.append(k)
        if not bad:
            break
        worst = min(bad, key=lambda k: area[k])
        use = np.delete(use, worst)
    return [(use[k], f) for k, f in faces]


def _plane_coefficients(normals: np.ndarray, points: np.ndarray):
    """Gradients g (p, 2) and offsets h (p,) of z = g . (x, y) + h for upward planes."""
    g = -normals[:, :2] / normals[:, 2:3]
    h = points[:, 2] - np.einsum("ij,ij->i", g, points[:, :2])
    return g, h


def arrangement_cells(poly, g: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Cells (array of shapely Polygons) into which the lines z_i = z_j of every pair of planes
    (gradients ``g`` (p, 2), offsets ``h`` (p,)) cut the shapely polygon ``poly``."""
    import shapely

    i, j = np.triu_indices(len(g), 1)
    a, c = g[i] - g[j], h[i] - h[j]  # line a . x + c = 0
    n2 = np.einsum("ij,ij->i", a, a)
    ok = n2 > 1e-12  # parallel planes never meet
    a, c, n2 = a[ok], c[ok], n2[ok]
    x0, y0, x1, y1 = poly.bounds
    ctr = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    r = np.hypot(x1 - x0, y1 - y0) + 1.0
    foot = ctr - ((a @ ctr + c) / n2)[:, None] * a  # the line's point nearest the centre
    near = np.hypot(*(foot - ctr).T) < r
    d = np.column_stack([-a[:, 1], a[:, 0]]) / np.sqrt(n2)[:, None]
    ends = np.stack([foot - r * d, foot + r * d], axis=1)[near]
    # whole lines, not clipped to the polygon: a clipped end is not exactly on the boundary and
    # would not be noded with it; the noding computes every crossing once
    noded = shapely.unary_union(np.r_[np.array([poly.boundary], object), shapely.linestrings(ends)])
    cells = shapely.get_parts(shapely.polygonize(shapely.get_parts(noded)))
    rep = shapely.get_coordinates(shapely.point_on_surface(cells))
    return cells[shapely.contains_xy(poly, rep[:, 0], rep[:, 1]) & (shapely.area(cells) > 0)]


def _polygon_of(polys, xy: np.ndarray) -> np.ndarray:
    """Index of the polygon (of non-overlapping ``polys``) containing each point (n, 2), -1 for
    none: one prepared point-in-polygon test per polygon over the points in its bounds."""
    import shapely

    out = np.full(len(xy), -1, np.int64)
    bounds = shapely.bounds(np.asarray(polys, object))
    for i, (poly, (x0, y0, x1, y1)) in enumerate(zip(polys, bounds)):
        near = np.flatnonzero((xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1))
        out[near[shapely.contains_xy(poly, xy[near, 0], xy[near, 1])]] = i
    return out


def _cell_votes(cells: np.ndarray, grid: np.ndarray, centres: np.ndarray, n_planes: int):
    """Raster votes (cells, planes) of the labelled raster cells whose centres lie in each cell,
    and the label of the raster cell nearest each cell's interior point (for empty cells)."""
    import shapely

    m = grid >= 0
    xy, lab = centres[m], grid[m]
    votes = np.zeros((len(cells), n_planes), np.int64)
    if not len(lab):
        return votes, np.zeros(len(cells), np.int64)
    ci = _polygon_of(cells, xy)
    np.add.at(votes, (ci[ci >= 0], lab[ci >= 0]), 1)
    nearest = shapely.STRtree(shapely.points(xy)).nearest(shapely.point_on_surface(cells))
    return votes, lab[nearest]


def _shared_segments(cells: np.ndarray):
    """Segments shared by two cells: (first cell (s,), second cell (s,), start (s, 2), end (s, 2)).
    Polygonized cells share their edges vertex for vertex, so a shared segment appears twice."""
    import shapely

    rings, ring_cell = shapely.get_rings(cells, return_index=True)
    xy, pt_ring = shapely.get_coordinates(rings, return_index=True)
    same = pt_ring[1:] == pt_ring[:-1]
    a, b, cell = xy[:-1][same], xy[1:][same], ring_cell[pt_ring[:-1][same]]
    swap = (a[:, 0] > b[:, 0]) | ((a[:, 0] == b[:, 0]) & (a[:, 1] > b[:, 1]))
    a, b = np.where(swap[:, None], b, a), np.where(swap[:, None], a, b)
    key = np.column_stack([a, b])
    order = np.lexsort(key.T[::-1])
    k = key[order]
    twin = np.flatnonzero((k[1:] == k[:-1]).all(axis=1))
    c0, c1 = cell[order[twin]], cell[order[twin + 1]]
    keep = c0 != c1
    return c0[keep], c1[keep], k[twin[keep], :2], k[twin[keep], 2:]


def _meets(seg, g: np.ndarray, h: np.ndarray) -> np.ndarray:
    """(segments, planes, planes) bool: whether planes p and q meet along each shared segment
    (their heights agree within :data:`JUMP_TOL` at both ends; always for p = q)."""
    _, _, a, b = seg
    dz = lambda xy: np.abs((xy @ g.T + h)[:, :, None] - (xy @ g.T + h)[:, None, :])
    return np.maximum(dz(a), dz(b)) <= JUMP_TOL


def _jumps(labels: np.ndarray, seg, meet: np.ndarray) -> np.ndarray:
    """Length (m) of each shared segment along which its two cells' planes do not meet."""
    c0, c1, a, b = seg
    bad = ~meet[np.arange(len(c0)), labels[c0], labels[c1]]
    return np.where(bad, np.hypot(*(b - a).T), 0.0)


def _repair(labels: np.ndarray, votes: np.ndarray, seg, meet: np.ndarray) -> np.ndarray:
    """Relabel cells until neighbouring planes meet continuously: repeatedly, of all moves that
    give one cell on a jump another plane and shorten the total jump length, the one that loses
    the fewest raster votes is made (the largest shortening breaks ties); stops when no jump is
    left or no move shortens the jumps."""
    labels = labels.copy()
    c0, c1, a, b = seg
    length = np.hypot(*(b - a).T)
    s = np.r_[np.arange(len(c0)), np.arange(len(c0))]
    cell, other = np.r_[c0, c1], np.r_[c1, c0]  # each segment seen from both its cells
    for _ in range(2 * len(labels)):
        jump = _jumps(labels, seg, meet)
        if not jump.any():
            break
        # cost[c, q]: jump length along c's segments were c given plane q, its neighbours unchanged
        cost = np.zeros(votes.shape)
        np.add.at(cost, cell, length[s, None] * ~meet[s, :, labels[other]])
        on = np.zeros(len(labels), bool)
        on[c0[jump > 0]] = on[c1[jump > 0]] = True
        gain = np.where(on[:, None], cost[np.arange(len(labels)), labels][:, None] - cost, 0.0)
        lost = votes[np.arange(len(labels)), labels][:, None] - votes
        c, q = np.nonzero(gain > 1e-9)
        if not len(c):
            break
        best = np.lexsort((-gain[c, q], lost[c, q]))[0]
        labels[c[best]] = q[best]
    return labels


#: Most labellings :func:`_settle_jumps` tries (planes ** cells on jumps).
MAX_LABELLINGS = 4096


def _settle_jumps(labels: np.ndarray, votes: np.ndarray, seg, meet: np.ndarray) -> np.ndarray:
    """Labels with the cells on the remaining jumps relabelled jointly: of every labelling of
    those cells (when there are at most :data:`MAX_LABELLINGS`), the one without jumps that
    loses the fewest raster votes; ``labels`` unchanged when none is free of jumps. Where more
    than three planes meet (a cross wing's ridge ending near the main ridge), the noisy planes'
    lines cut tiny cells without raster cells of their own, which only a joint move of two or
    more of them makes continuous; :func:`_repair` moves one cell at a time."""
    c0, c1, a, b = seg
    jump = _jumps(labels, seg, meet)
    on = np.unique(np.r_[c0[jump > 0], c1[jump > 0]])
    p = votes.shape[1]
    if not len(on) or p ** len(on) > MAX_LABELLINGS:
        return labels
    combos = np.indices((p,) * len(on)).reshape(len(on), -1).T  # (p ** k, k)
    trial = np.repeat(labels[None, :], len(combos), axis=0)
    trial[:, on] = combos
    bad = ~meet[np.arange(len(c0))[None, :], trial[:, c0], trial[:, c1]]
    free = ~(bad & (np.hypot(*(b - a).T) > 0)[None, :]).any(axis=1)
    if not free.any():
        return labels
    lost = (votes[on, labels[on]][None, :] - votes[on[None, :], combos]).sum(axis=1)
    return trial[np.flatnonzero(free)[np.argmin(lost[free])]]


def agreement(faces: list, grid: np.ndarray, centres: np.ndarray) -> int:
    """Labelled raster cells whose centre lies in a face of their own plane; ``faces`` is
    [(plane index, shapely Polygon)], plane indices being the raster's labels."""
    m = grid >= 0
    if not faces or not m.any():
        return 0
    fi = _polygon_of([f for _, f in faces], centres[m])
    k = np.array([i for i, _ in faces])
    return int(np.count_nonzero((fi >= 0) & (grid[m] == k[np.maximum(fi, 0)])))


def _continuous_labels(poly, g: np.ndarray, h: np.ndarray, sub: np.ndarray, centres: np.ndarray):
    """Arrangement cells of the planes (g, h) over ``poly`` and a plane index per cell from the
    raster ``sub`` (indices into g, negative for none), repaired to meet continuously; None when
    jumps remain."""
    cells = arrangement_cells(poly, g, h)
    votes, nearest = _cell_votes(cells, sub, centres, len(g))
    labels = np.where(votes.sum(axis=1) > 0, np.argmax(votes, axis=1), nearest)
    seg = _shared_segments(cells)
    meet = _meets(seg, g, h)
    labels = _settle_jumps(_repair(labels, votes, seg, meet), votes, seg, meet)
    return None if _jumps(labels, seg, meet).any() else (cells, labels)


#: Area (m^2) under which a face is a sliver of the arrangement and dropped (:func:`arrangement_faces`).
SLIVER_AREA = 1e-9


def _fill_specks(poly):
    """``poly`` without its holes of under :data:`SLIVER_AREA`: where several planes' lines pass
    through nearly one point (a cross wing's ridge ending on the main ridge, once regularised),
    the noding cuts cells of about 1e-18 m^2 there; one inside another plane's face is a hole
    of it, and as a sliver it has no face of its own to fill that hole."""
    import shapely

    keep = [r for r in poly.interiors if shapely.Polygon(r).area > SLIVER_AREA]
    return poly if len(keep) == len(poly.interiors) else shapely.Polygon(poly.exterior, keep)


def arrangement_faces(poly, normals: np.ndarray, points: np.ndarray, grid: np.ndarray, centres: np.ndarray):
    """Faces [(plane index, shapely Polygon)] of the arrangement of the part's planes, labelled by
    the ownership raster ``grid`` (plane index per raster cell, negative for none) at ``centres``
    (rows, cols, 2). When the planes cannot be made to meet continuously, the plane owning the
    fewest raster cells is left out (a duplicate of a neighbour, a piece) and the arrangement
    rebuilt; None when no two planes are left."""
    import shapely

    inside = shapely.contains_xy(poly, centres[..., 0], centres[..., 1])
    own = np.bincount(grid[inside & (grid >= 0)], minlength=len(normals))
    use = np.flatnonzero(own >= MIN_CELLS)
    found = None
    while len(use) >= 2 and found is None:
        lut = np.full(len(normals), -1, np.int64)
        lut[use] = np.arange(len(use))
        sub = np.where(inside & (grid >= 0), lut[np.maximum(grid, 0)], -1)
        found = _continuous_labels(poly, *_plane_coefficients(normals[use], points[use]), sub, centres)
        if found is None:
            use = np.delete(use, np.argmin(own[use]))
    if found is None:
        return None
    cells, labels = found
    faces = []
    for q in np.unique(labels):
        merged = shapely.unary_union(cells[labels == q])
        faces += [(int(use[q]), shapely.orient_polygons(_fill_specks(p))) for p in shapely.get_parts(merged)
                  if p.geom_type == "Polygon" and p.area > SLIVER_AREA]
    # a face dropped as a sliver, or one enclosing a sliver of another plane, would leave a gap or
    # a degenerate hole in the solid
    area = sum(f.area for _, f in faces)
    if abs(area - poly.area) > 1e-9 * max(poly.area, 1.0) or any(
            shapely.Polygon(r).area < 1e-6 for _, f in faces for r in f.interiors):
        return None
    return faces


def roof_faces(poly, normals: np.ndarray, points: np.ndarray, grid: np.ndarray, centres: np.ndarray) -> list:
    """Roof faces [(plane index, shapely Polygon)] of one part polygon ``poly`` with planes
    (``normals`` (p, 3) upward, ``points`` (p, 3)), the ownership raster ``grid`` (rows, cols) of
    plane indices (negative: none or another part's plane) and its cell ``centres`` (rows, cols, 2):
    the lower envelope when it keeps every plane, else the arrangement faces when they are
    continuous and agree with more raster cells than the envelope does."""
    env = envelope_faces(poly, normals, points, grid, centres)
    if len(normals) < 2 or {k for k, _ in env} == set(range(len(normals))):
        return env
    arr = arrangement_faces(poly, normals, points, grid, centres)
    if arr is None:
        return env
    return arr if agreement(arr, grid, centres) > agreement(env, grid, centres) else env
