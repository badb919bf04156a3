"""Bridge decks: ground-like surfaces that span a gap, kept out of the ground as class 17.

A deck is smooth, level and often wider than a morphological filter's window; its ends meet
the road on the banks. Ground filters therefore accept it, or its ends, and a DTM through it
is a dam across the river or the road below. The ASPRS LAS 1.4 R15 specification gives decks
their own class (17, bridge deck), and the USGS Lidar Base Specification (2024) wants the
bare-earth DEM without them, interpolated across the gap. A deck shows itself in profile
(Sithole & Vosselman 2006): across it, the surface drops abruptly on *both* sides to the gap it
spans (water, a road, a valley); along it, the surface runs on into the terrain at both ends.
An embankment or a dam drops on both sides too, but down faces of at most 1:1 that carry
points; a roof drops on every side and joins nothing; a terrace or a cliff drops on one side
only. So:

1. a grid of ``cell`` metres holding each cell's lowest echo of any class (noise left out):
   a filter that rejected the middle of a deck and kept its ends leaves fragments no test
   could judge, while the lowest echoes show the deck whole; vegetation and roofs fail the
   tests below on their own;
2. from every cell, rays in eight directions (four axes) over at most ``span`` metres follow
   the surface while consecutive answered cells differ by less than ``step``
   (= ``clearance`` / 2), passing over empty cells and over one-cell bumps (a parapet, a
   post); the first larger difference ends the ray: a *drop* when the next cell is lower by
   ``step`` or more and steeper than ``gradient`` (rise over run between the two lowest
   points; across a void, over one cell's step, since an unanswered gap beside a deck — water,
   its shadow — is no face), and the edge lies within ``clearance`` of the start's height (a
   level deck, not a hillside); anything else a *block*. The rays are followed by pointer
   doubling over the grid, not walked one by one;
3. a cell that drops on both sides of an axis is *weak*; by ``clearance`` or more on both
   sides, a *seed* (hysteresis: a deck's ends stand lower over their banks than its middle);
4. 8-connected weak cells holding a seed, covering ``min_area`` and smooth (at most a fifth
   of their neighbour pairs differ by ``step`` / 2 or more) make a candidate; its
   *across* axis is the one on which most of its cells drop, and it is a deck when the surface
   runs on at least ``approach`` metres beyond both of its ends along the other axis (the road
   beyond the abutments; Sithole & Vosselman's "connected to the terrain in one direction
   only") and, where the filter's ground is given, reaches it within ``span`` (a roof's
   ridge runs on into more roof, cut off from the ground by the eaves). Holes in a deck are
   filled;
5. the points of the deck's cells, and of the cells beside it that reach down into the gap or
   up to a parapet, lying from ``step`` / 2 under the deck's surface to ``structure`` metres
   above it, are the deck;
6. beyond each end, slice by slice along the axis, the band of the deck's width is taken
   while it holds the deck's plane and both its edges still step down (the points just
   outside lie lower than a 1:1 face from the edge would, by ``step`` / 4): the end spans over
   sloping (spill-through) abutments, where the cells see no drop.

The ground methods (:func:`workstation.ground.common.write_classes`) put those points in class
17 and out of the ground, so a DTM from the ground is interpolated across the gap; the point
classifier (:mod:`workstation.ml.classifier`) labels them 17.

Limits: a road on an embankment held by vertical retaining walls on both sides looks like a
deck and is called one; over spill-through abutments the last metre or two of each end, less
than about ``step`` above the slope, stays ground (measured on the gallery's 1:1.5 abutments:
about 20 % of the deck points stay unfound, against none on vertical abutments); a deck less
than ``clearance`` over its gap (a footbridge over a ditch) is not found, nor one whose
surroundings gave no echo within ``span`` (a river that answered nothing); the end cells hold
up to one cell of the road beyond the abutment.

Cost: grid arithmetic, O(cells · log(span / cell)): 0.04 s for 44 k points, 0.2-0.4 s for the
real tiles of ``../shared/data`` (0.1-0.7 M points), 1.6 CPU s for 5 M points (12 points/m²).

References
----------
ASPRS (2019). LAS Specification 1.4 - R15 (class 17, bridge deck).
USGS (2024). Lidar Base Specification, v2.x (bare-earth DEMs, bridges removed).
G. Sithole, G. Vosselman (2006). Bridge detection in airborne laser scanner data. ISPRS J.
Photogramm. Remote Sens. 61(1):33-46.
J. C. Wyllie (1979). The complexity of parallel computations. PhD thesis, Cornell University
(pointer jumping).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class BridgeParams:
    """Parameters of the deck test. Lengths in metres (whatever the CRS unit), gradient a rise
    over run.

    Attributes
    ----------
    clearance : float
        Least height of a deck's seed above the gap it spans on both sides (2.0: above railway
        platforms and loading docks, below any navigable or road clearance). Its half, the
        ``step``, is the height difference that breaks a surface and the least drop of a
        deck's weak cells.
    gradient : float
        A drop steeper than this (rise over run) is a structure's edge (2.0, 63°): earthwork
        faces (dams, levees, road and railway embankments) are 1:1 (45°) or gentler.
    span : float
        Longest walk of a ray, so the widest deck measured across (40.0).
    approach : float
        How far the surface must continue beyond each end of a deck (5.0).
    min_area : float
        Least plan area of a deck, m² (20.0).
    structure : float
        Height above the deck's surface up to which points in its cells belong to it (1.5:
        parapets, railings, kerbs).
    cell : float
        Grid cell (1.0).
    """

    clearance: float = 2.0
    gradient: float = 2.0
    span: float = 40.0
    approach: float = 5.0
    min_area: float = 20.0
    structure: float = 1.5
    cell: float = 1.0

    @property
    def step(self) -> float:
        """Height difference (m) that breaks a surface: ``clearance`` / 2."""
        return 0.5 * self.clearance


#: The four axes as (row, col) steps; x is the column, y the row.
AXES = ((0, 1), (1, 1), (1, 0), (1, -1))


def _surface(xyz: np.ndarray, surface: np.ndarray, cell: float):
    """The lowest ``surface`` point of each cell: z, x, y grids (NaN where empty), and the
    grid's row/col of every point, its shape and origin."""
    from .common import grid_index, grid_min

    r, c, shape, origin = grid_index(xyz[:, :2], cell, option="bridge_params.cell")
    g = np.flatnonzero(surface)
    z, low = grid_min(xyz[g, 2], r[g], c[g], shape)
    x = np.full(shape, np.nan)
    y = np.full(shape, np.nan)
    ok = low >= 0
    x[ok] = xyz[g[low[ok]], 0]
    y[ok] = xyz[g[low[ok]], 1]
    return z, x, y, r, c, shape, origin


def _bumps(z: np.ndarray, d, step: float) -> np.ndarray:
    """Cells (bool grid) standing ``step`` or more above both their neighbours along the axis
    ``d`` (an empty neighbour counts as lower, but not both): a parapet, a kerb, a post, a
    crown without a ground echo, one cell wide. The rays pass over them as over a void."""
    rows, cols = z.shape
    lower = []
    for s in (1, -1):
        nb = np.full(z.shape, np.nan)
        dr, dc = s * d[0], s * d[1]
        nb[max(0, -dr): rows - max(0, dr), max(0, -dc): cols - max(0, dc)] = \
            z[max(0, dr): rows - max(0, -dr), max(0, dc): cols - max(0, -dc)]
        lower.append(nb)
    with np.errstate(invalid="ignore"):
        up = [np.isnan(nb) | (z - nb >= step) for nb in lower]
    return np.isfinite(z) & up[0] & up[1] & ~(np.isnan(lower[0]) & np.isnan(lower[1]))


def _rays(zp, xp, yp, d, reach: int, p: BridgeParams, cell: float) -> np.ndarray:
    """Drop depth (rows, cols) met by the ray from every cell of the grid ``zp`` (NaN where
    empty; ``xp``, ``yp`` the plan position of each cell's point) in direction ``d`` (row, col);
    NaN where the ray is blocked, runs out, or meets its edge more than ``clearance`` above
    or below its start (sloping ground, not a level deck).

    Each cell points to the next answered cell ahead (across any void); where the two differ
    by less than ``step`` the surface continues and the cell takes the fate of the next, else
    the transition is its own: a drop (lower by ``step`` and steeper than ``gradient``, the
    run across a void counted as one step) or a block. The chains are followed by pointer
    doubling (Wyllie 1979), O(cells · log reach), with no walk per ray."""
    rows, cols = zp.shape
    n = rows * cols
    z, x, y = zp.ravel(), xp.ravel(), yp.ravel()
    it = np.int32 if n < 2**31 - 1 else np.int64
    idx = np.arange(n, dtype=it)
    r, c = np.divmod(idx, it(cols))
    rr, cc = r + d[0], c + d[1]
    inside = (rr >= 0) & (rr < rows) & (cc >= 0) & (cc < cols)
    sink = n  # beyond the grid: an answered cell of no height that ends every chain as "open"
    nxt = np.where(inside, rr * cols + cc, sink).astype(it)
    empty = np.append(np.isnan(z) | _bumps(zp, d, p.step).ravel(), False)
    z = np.append(z, np.nan)
    # the first answered cell ahead, and how many steps away (pointer doubling over voids)
    ahead, gap = np.append(nxt, it(sink)), np.ones(n + 1, it)
    for _ in range(int(np.ceil(np.log2(reach + 1))) + 1):
        go = empty[ahead]
        if not go.any():
            break
        gap = np.where(go, gap + gap[ahead], gap)
        ahead = np.where(go, ahead[ahead], ahead)
    ahead, gap = ahead[:n], gap[:n]
    filled = ~empty[:n]
    t = ahead
    zt = z[t]
    dz = z[:n] - zt
    xt, yt = np.append(x, np.nan)[t], np.append(y, np.nan)[t]
    dist = np.hypot(xt - x, yt - y)
    dist = np.where(gap > 1, np.minimum(dist, cell * float(np.hypot(*d))), dist)  # across a void: one step
    with np.errstate(invalid="ignore"):
        cont = filled & (np.abs(dz) < p.step) & (gap <= reach)
        drop = filled & ~cont & (dz >= p.step) & (dz >= p.gradient * dist) & (gap <= reach)
    # follow the continuous surface to its end: the terminal cell and the steps to it
    end, steps = np.where(cont, t, idx), np.where(cont, gap, 0).astype(it)
    end, steps = np.append(end, it(sink)), np.append(steps, it(0))
    for _ in range(int(np.ceil(np.log2(reach + 1))) + 1):
        nxt_end = end[end]
        if (nxt_end == end).all():
            break
        steps = np.minimum(steps + steps[end], reach + 1)
        end = nxt_end
    end, steps = end[:n], steps[:n]
    depth = np.full(n, np.nan)
    hit = filled & (steps <= reach) & (end < n)
    e = end[hit]
    hit_idx = np.flatnonzero(hit)
    ok = drop[e] & (np.abs(z[hit_idx] - z[e]) <= p.clearance)
    depth[hit_idx[ok]] = np.minimum(z[hit_idx[ok]], z[e[ok]]) - zt[e[ok]]
    return depth.reshape(rows, cols)


def _drops(z, x, y, p: BridgeParams, cell: float) -> np.ndarray:
    """Per cell and axis the smaller of its two drops (rows, cols, 4), NaN where an axis does
    not drop on both sides (:func:`_rays`)."""
    both = np.full(z.shape + (len(AXES),), np.nan)
    for i, d in enumerate(AXES):
        reach = int(np.ceil(p.span / (cell * float(np.hypot(*d)))))
        fwd = _rays(z, x, y, d, reach, p, cell)
        if np.isnan(fwd).all():
            continue
        both[..., i] = np.minimum(fwd, _rays(z, x, y, (-d[0], -d[1]), reach, p, cell))
    return both


def _flood(z: np.ndarray, grown: np.ndarray, steps: int, step: float) -> np.ndarray:
    """``grown`` (bool grid) spread ``steps`` times to the 8 neighbours whose height differs
    from the grown cell's by less than ``step`` (the continuous surface around it)."""
    filled = np.isfinite(z)
    zpad = np.pad(z, 1, constant_values=np.nan)
    shape = z.shape
    grown = grown.copy()
    for _ in range(steps):
        gpad = np.pad(grown, 1)
        new = np.zeros(shape, bool)
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                if dr or dc:
                    nb = gpad[1 + dr: 1 + dr + shape[0], 1 + dc: 1 + dc + shape[1]]
                    nz = zpad[1 + dr: 1 + dr + shape[0], 1 + dc: 1 + dc + shape[1]]
                    with np.errstate(invalid="ignore"):
                        new |= nb & filled & (np.abs(z - nz) < step)
        new &= ~grown
        if not new.any():
            break
        grown |= new
    return grown


def _continues(z, comp, along, p: BridgeParams, cell: float, terrain=None) -> bool:
    """Whether the surface runs on at least ``approach`` beyond both ends of ``comp`` (bool
    grid) along the unit plan vector ``along`` (x, y), measured inside its band across; with
    ``terrain`` (bool grid, the cells holding ground points), whether it also reaches terrain
    within ``span`` (a roof's ridge runs on into more roof, cut off from the ground by the
    eaves; a filter may have rejected an embankment's crest, not its foot)."""
    from scipy import ndimage

    n = int(np.ceil(p.approach / cell)) + 1
    far = int(np.ceil(p.span / cell)) if terrain is not None else n
    rows, cols = np.nonzero(comp)
    r0, r1 = max(rows.min() - far, 0), min(rows.max() + far + 1, z.shape[0])
    c0, c1 = max(cols.min() - far, 0), min(cols.max() + far + 1, z.shape[1])
    zw, cw = z[r0:r1, c0:c1], comp[r0:r1, c0:c1]
    grown = _flood(zw, cw, n, p.step)
    gr, gc = np.nonzero(grown)
    kr, kc = np.nonzero(ndimage.binary_dilation(cw, np.ones((3, 3), bool)))
    proj = lambda rr, cc: (cc * along[0] + rr * along[1]) * cell  # noqa: E731
    perp = lambda rr, cc: (-cc * along[1] + rr * along[0]) * cell  # noqa: E731
    cp = perp(kr, kc)
    band = (perp(gr, gc) >= cp.min()) & (perp(gr, gc) <= cp.max())
    g = proj(gr[band], gc[band])
    k = proj(kr, kc)
    need = p.approach - cell
    if not (g.size and g.max() >= k.max() + need and g.min() <= k.min() - need):
        return False
    return terrain is None or bool((_flood(zw, grown, far - n, p.step) & terrain[r0:r1, c0:c1] & ~cw).any())


def _components(z: np.ndarray, x: np.ndarray, y: np.ndarray, p: BridgeParams, cell: float, terrain=None) -> list:
    """The decks: (weak cells, bool grid with holes; unit plan vector (x, y) along the deck)
    pairs, steps 2-4 of the module notes."""
    from scipy import ndimage

    decks = []
    both = _drops(z, x, y, p, cell)
    axis_of = np.isfinite(both)
    weak = axis_of.any(axis=2)
    if not weak.any():
        return decks
    with np.errstate(invalid="ignore"):
        seed = (both >= p.clearance).any(axis=2)
    labels, count = ndimage.label(weak, np.ones((3, 3), bool))
    size = np.bincount(labels.ravel(), minlength=count + 1)
    seeded = np.bincount(labels.ravel(), weights=seed.ravel(), minlength=count + 1) > 0
    # smooth, as a deck is: at most a fifth of its neighbour pairs differ by step / 2 or more
    # (a clump of crowns without a ground echo is rough)
    pairs = np.zeros(count + 1)
    rough = np.zeros(count + 1)
    for a, b, za, zb in ((labels[:, :-1], labels[:, 1:], z[:, :-1], z[:, 1:]),
                         (labels[:-1], labels[1:], z[:-1], z[1:])):
        same = (a > 0) & (a == b)
        pairs += np.bincount(a[same], minlength=count + 1)
        rough += np.bincount(a[same], weights=np.abs(za[same] - zb[same]) >= 0.5 * p.step, minlength=count + 1)
    keep = (size >= p.min_area / (cell * cell)) & seeded & (rough <= 0.2 * np.maximum(pairs, 1))
    keep[0] = False
    for lab, sl in enumerate(ndimage.find_objects(labels), start=1):
        if not keep[lab]:
            continue
        comp = labels[sl] == lab
        across = AXES[int(axis_of[sl][comp].sum(axis=0).argmax())]
        along = np.array([-across[0], across[1]], float)  # (x, y), perpendicular to (col, row) = across
        along /= np.hypot(*along)
        full = np.zeros(z.shape, bool)
        full[sl] = comp
        if _continues(z, full, along, p, cell, terrain):
            decks.append((full, along))
    return decks


def deck_cells(z: np.ndarray, x: np.ndarray, y: np.ndarray, p: BridgeParams = BridgeParams(),
               cell: float = 1.0) -> np.ndarray:
    """Deck cells (bool grid, holes filled) of a lowest-ground grid ``z`` of ``cell``-metre
    cells whose points lie at plan positions ``x``, ``y`` (metres; NaN where empty)."""
    from scipy import ndimage

    deck = np.zeros(z.shape, bool)
    for comp, _ in _components(z, x, y, p, cell):
        deck |= comp
    return ndimage.binary_fill_holes(deck)


def _ends(xyz: np.ndarray, surface: np.ndarray, mine: np.ndarray, along, p: BridgeParams) -> np.ndarray:
    """The deck's points beyond its found ends (m,) bool: slice by slice (``step`` metres long)
    along its axis, for at most ``3 · clearance`` metres, while its band across holds the
    deck's plane (fitted to its points ``mine``) and both edges still step down.

    An edge steps down when the points just outside it (within ``step`` across, not above the
    plane) lie, in the median, lower than the plane by more than an earthwork face rising at
    1:1 from the edge would, plus ``step`` / 4: the discontinuity of a deck's side (its
    clearance over the abutment's slope) that a crest's rounded edge does not have. A void
    beside the deck counts as a drop, as in the rays."""
    u = np.asarray(along, float)
    v = np.array([-u[1], u[0]])
    idx = np.flatnonzero(mine)
    if len(idx) < 10:
        return np.zeros(len(xyz), bool)
    tol = 0.25 * p.step
    xy = xyz[:, :2]
    s_all, t_all = xy @ u, xy @ v
    a = np.column_stack([np.ones(len(idx)), s_all[idx], t_all[idx]])
    coef = np.linalg.lstsq(a, xyz[idx, 2], rcond=None)[0]
    res = xyz[idx, 2] - a @ coef
    flat = idx[np.abs(res) < tol]  # the deck's surface (no parapets)
    if len(flat) < 10:
        return np.zeros(len(xyz), bool)
    a = np.column_stack([np.ones(len(flat)), s_all[flat], t_all[flat]])
    coef = np.linalg.lstsq(a, xyz[flat, 2], rcond=None)[0]
    t_lo, t_hi = np.percentile(t_all[flat], [0.5, 99.5])
    s_lo, s_hi = s_all[flat].min(), s_all[flat].max()
    reach = 3.0 * p.clearance
    # the candidates: near the band, beyond the ends, within reach
    w = p.step
    near = surface & (t_all >= t_lo - w) & (t_all <= t_hi + w) & (s_all >= s_lo - reach) & (s_all <= s_hi + reach) \
        & ~((s_all >= s_lo) & (s_all <= s_hi))
    k = np.flatnonzero(near)
    s, t, zk = s_all[k], t_all[k], xyz[k, 2]
    dz = zk - (coef[0] + coef[1] * s + coef[2] * t)  # height above the deck's plane
    out = np.zeros(len(xyz), bool)
    for sign, start in ((1.0, s_hi), (-1.0, s_lo)):
        off = sign * (s - start)  # metres beyond this end
        for j in range(int(np.ceil(reach / p.step))):
            sl = (off > j * p.step) & (off <= (j + 1) * p.step)
            band = sl & (t >= t_lo) & (t <= t_hi) & (dz < tol)
            if band.sum() < 3 or np.mean(np.abs(dz[band]) < tol) < 0.8:
                break  # the band no longer holds the deck's plane
            steps = True
            for dt in (t - t_hi, t_lo - t):  # distance outside each edge
                side = sl & (dt > 0) & (dt <= w) & (dz < tol)
                if side.any() and np.median(-dz[side] - dt[side]) < 0.25 * p.step:
                    steps = False  # a continuous face (an embankment's crest), not a deck's side
            if not steps:
                break
            out[k[sl & (t >= t_lo - w) & (t <= t_hi + w) & (np.abs(dz) < tol)]] = True
            out[k[sl & (t >= t_lo) & (t <= t_hi) & (dz >= -tol) & (dz <= p.structure)]] = True
    return out


def bridge_decks(xyz: np.ndarray, p: BridgeParams = BridgeParams(), surface: np.ndarray | None = None,
                 ground: np.ndarray | None = None) -> np.ndarray:
    """Deck points (m,) bool among local metric points ``xyz`` (m, 3): the points of the
    decks' cells, and of the cells beside them that reach down into the gap, from ``step`` / 2
    under a deck's surface up to ``structure`` above it (see the module notes).

    The decks are found on the lowest of the ``surface`` points (m,) bool in each cell (None:
    all of them; noise should be left out), whatever their class: a filter that rejected the
    middle of a deck and kept its ends leaves fragments no test could judge, while the lowest
    echoes show the deck whole, and vegetation and roofs fail the test on their own (rough, or
    cut off from the terrain). With ``ground`` (m,) bool (a filter's ground), a deck's surface
    must also reach cells holding ground within ``span``.

    Examples
    --------
    A 10 m wide deck 4 m over a 30 m wide river, its ends on the banks:

    >>> g = np.mgrid[0:80:0.5, 0:60:0.5].reshape(2, -1).T
    >>> river = (g[:, 0] > 24.9) & (g[:, 0] < 55)
    >>> deck = river & (g[:, 1] > 25) & (g[:, 1] < 35)
    >>> z = np.where(river, -4.0, 0.0) + np.where(deck, 4.0, 0.0)
    >>> found = bridge_decks(np.column_stack([g, z]))
    >>> bool((found == deck).all())
    True
    """
    from scipy import ndimage

    from .common import auto_cell

    m = xyz.shape[0]
    surface = np.ones(m, bool) if surface is None else np.asarray(surface, bool)
    if int(surface.sum()) < 3:
        return np.zeros(m, bool)
    cell = auto_cell(xyz[surface, :2], p.cell)
    z, x, y, r, c, shape, _ = _surface(xyz, surface, cell)
    terrain = None
    if ground is not None:
        g = np.flatnonzero(np.asarray(ground, bool))
        terrain = np.zeros(shape, bool)
        terrain[r[g], c[g]] = True
    comps = _components(z, x, y, p, cell, terrain)
    if not comps:
        return np.zeros(m, bool)
    core = np.logical_or.reduce([comp for comp, _ in comps])
    deck = ndimage.binary_fill_holes(core)
    # the deck's level: its own in its cells, the nearest one in filled holes and beside it
    _, (ir, ic) = ndimage.distance_transform_edt(~core, return_indices=True)
    near = z[ir, ic]
    ring = ndimage.binary_dilation(deck, np.ones((3, 3), bool)) & ~deck
    with np.errstate(invalid="ignore"):
        # empty, down in the gap, or a parapet above: not the road beyond an end
        ring &= ~((z > near - p.step) & (z < near + 0.5 * p.step))
    where = deck | ring
    hz = near[r, c]
    zz = xyz[:, 2]
    on = where[r, c] & (zz >= hz - 0.5 * p.step) & (zz <= hz + p.structure)
    for comp, along in comps:  # the ends over sloping abutments, where the cells see no drop
        on |= _ends(xyz, surface, on & comp[r, c], along, p)
    return on
