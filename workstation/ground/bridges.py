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
   level deck, not a hillside); anything else a *block*. The rays are not walked one by
   one: the answered cells are taken in order along each line of the grid, and each one's
   surface ends at the first cell from it on that does not continue (a running minimum);
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
6. the deck's ends over sloping (spill-through) abutments, where the cells see no drop, and
   the corners of a skewed deck: its plane and band are fitted about its own axis (the
   rays see four axes, a road runs at any angle); slice by slice along the axis, the depth
   of the ground beside each edge under the deck's plane, taken at the edge, is the gap's
   depth, then falls along the abutment's slope and levels off over the ground beyond. A
   line for the fall and a line for the ground beyond, fitted where the depth is under
   ``clearance``, meet where the deck's surface meets the ground: that edge's end, unless
   one line fits as well (the road beyond a wall, or a road on an embankment, whose crest
   meets its side faces without a step: nothing taken). Where an edge falls, its end is
   then refined on the ground points beside it, as two planes in (along, out from the
   edge): the abutment's slope and the ground beyond, the ground the lower of the two;
   they meet along the slope's top, where the deck rests, a line oblique to the edge on a
   skewed bridge (slices taken square to the axis straddle it). The deck ends on the line
   joining its two edges' ends.

The ground methods (:func:`workstation.ground.common.write_classes`) put those points in class
17 and out of the ground, so a DTM from the ground is interpolated across the gap; the point
classifier (:mod:`workstation.ml.classifier`) labels them 17.

Limits: a road on an embankment held by vertical retaining walls on both sides looks like a
deck and is called one; over spill-through abutments the deck's last decimetres stand within
the noise of the bank under them (a deck flush with its road, or whose plane dips under the
bank's curved top at a corner): no height test tells them from the ground, only the end line,
so an end placed a decimetre short leaves them ground and one placed long takes a strip of the
road beyond (``python scripts/bench_ground.py bridges``); a deck less than
``clearance`` over its gap (a footbridge over a ditch) is not found, nor one whose
surroundings gave no echo within ``span`` (a river that answered nothing), nor a low deck
over gentle banks whose cells never drop by ``clearance`` on both sides; the end cells hold
up to one cell of the road beyond a vertical abutment.

Cost: grid arithmetic, O(points + cells): 0.01-0.04 CPU s for 44-74 k points, 0.005-0.04 s for
the real tiles of ``../shared/data`` (0.03-0.6 M points), 0.4 CPU s for 5 M points (12 points/m²).

References
----------
ASPRS (2019). LAS Specification 1.4 - R15 (class 17, bridge deck).
USGS (2024). Lidar Base Specification, v2.x (bare-earth DEMs, bridges removed).
G. Sithole, G. Vosselman (2006). Bridge detection in airborne laser scanner data. ISPRS J.
Photogramm. Remote Sens. 61(1):33-46.
G. Schwarz (1978). Estimating the dimension of a model. Ann. Statist. 6(2):461-464 (the
information criterion that picks one line or two).
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
        Longest walk of a ray, so the widest deck measured across (40.0); a deck's end is
        looked for at most ``span`` / 2 beyond its found cells.
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
    grid's row/col of every point, its shape and origin (all points on the surface: taken
    as they are, not gathered)."""
    from .common import grid_index, grid_min

    r, c, shape, origin = grid_index(xyz[:, :2], cell, option="bridge_params.cell")
    if surface.all():
        z, low = grid_min(xyz[:, 2], r, c, shape)
    else:
        g = np.flatnonzero(surface)
        z, low = grid_min(xyz[g, 2], r[g], c[g], shape)
        low[low >= 0] = g[low[low >= 0]]
    x, y = _plan_at(xyz, low)
    return z, x, y, r, c, shape, origin


def _plan_at(xyz: np.ndarray, low: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """x and y (shaped as ``low``) of the points ``low`` indexes, NaN where it is -1 (none)."""
    x, y = np.full(low.shape, np.nan), np.full(low.shape, np.nan)
    ok = low >= 0
    x[ok], y[ok] = xyz[low[ok], 0], xyz[low[ok], 1]
    return x, y


def _cell(xyz: np.ndarray, surface: np.ndarray, count: int, cell: float) -> float:
    """The grid's cell: :func:`workstation.ground.common.auto_cell` of the ``count``
    ``surface`` points' plan positions. When the box of all the points keeps ``cell`` for
    that count, so does the surface's box inside it (a grid of no more cells), and the
    surface points are not copied out."""
    from workstation.core.budget import fit_cell

    from .common import auto_cell, column_max, column_min

    ext = column_max(xyz[:, :2]) - column_min(xyz[:, :2])
    if fit_cell(cell, float(ext[0]), float(ext[1]), count) == cell:
        return cell
    return auto_cell(xyz[surface, :2], cell)


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


def _lines(filled: np.ndarray, d):
    """The cells ``filled`` (bool grid) in order along the lines of the axis ``d`` (row, col):
    their flat indices, the line of each and its position along it (in steps of ``d``),
    sorted by line, then position. Rows and columns come in that order from ``nonzero``; the
    diagonals by a counting sort over their (line, place) keys, the place counted along the
    grid's shorter side (the row, or the column the way ``d`` goes), so the keys number at
    most twice the cells whatever the grid's shape."""
    rows, cols = filled.shape
    if d == (0, 1):
        r, c = np.nonzero(filled)
        return r * cols + c, r, c
    if d == (1, 0):
        c, r = np.nonzero(filled.T)
        return r * cols + c, c, r
    r, c = np.nonzero(filled)
    line = c - r + (rows - 1) if d == (1, 1) else r + c
    side = min(rows, cols)
    place = r if rows <= cols else (c if d == (1, 1) else cols - 1 - c)
    key = np.zeros((rows + cols - 1) * side, bool)
    key[line * side + place] = True
    line, place = np.divmod(np.flatnonzero(key), side)
    if rows <= cols:
        r = place
    else:
        c = place if d == (1, 1) else cols - 1 - place
        r = c - line + (rows - 1) if d == (1, 1) else line - c
    c = line - (rows - 1) + r if d == (1, 1) else line - r
    return r * cols + c, line, r


def _ray(z, x, y, pos, pairs, s: int, reach: int, p: BridgeParams, diag: float, cells=slice(None)) -> np.ndarray:
    """Drop depth met by the ray from each of the answered ``cells`` (indices, all by default;
    NaN where the ray is blocked, runs out, or meets its edge more than ``clearance`` above or
    below its start: sloping ground, not a level deck), forward along the lines (``s`` = 1)
    or back (-1). The cells come in order along their lines (1-D ``z``, plan position ``x``,
    ``y`` of each cell's point, ``pos`` along the line, :func:`_lines`), so each one's next
    answered cell ahead, across any void, is its neighbour ``s`` in the order when ``pairs``
    (:func:`_pairs`) says the two lie on one line within ``reach`` steps; ``diag`` is one
    step's run.

    Where the two differ by less than ``step`` the surface continues and the cell takes the
    fate of the next, else the transition is its own: a drop (lower by ``step`` and steeper
    than ``gradient``, the run across a void counted as one step) or a block. The surface's
    end is the first cell from each on that does not continue (a running minimum or maximum
    of the cells' order), and the ray meets it if it lies within ``reach`` steps."""
    near, cont, gap = pairs
    m = len(z)
    no = np.zeros(1, bool)
    if s > 0:  # cell j and its next, j + 1, are pair j
        near, cont, gap = np.append(near, no), np.append(cont, no), np.append(gap, 0)
        dz = np.append(z[:-1] - z[1:], 0.0)
        end = np.minimum.accumulate(np.where(cont, m, np.arange(m))[::-1])[::-1]
    else:  # cell j and its next, j - 1, are pair j - 1
        near, cont, gap = np.append(no, near), np.append(no, cont), np.append(0, gap)
        dz = np.append(0.0, z[1:] - z[:-1])
        end = np.maximum.accumulate(np.where(cont, -1, np.arange(m)))
    k = np.flatnonzero(near & (dz >= p.step))  # lower by step (so no continuation), and steeper than gradient:
    dist = np.hypot(x[k + s] - x[k], y[k + s] - y[k])
    dist = np.where(gap[k] > 1, np.minimum(dist, diag), dist)  # across a void: one step
    drop = np.zeros(m, bool)
    drop[k[dz[k] >= p.gradient * dist]] = True
    e, zc = end[cells], z[cells]
    hit = np.flatnonzero(drop[e] & (np.abs(pos[e] - pos[cells]) <= reach) & (np.abs(zc - z[e]) <= p.clearance))
    depth = np.full(len(e), np.nan)
    depth[hit] = np.minimum(zc[hit], z[e[hit]]) - z[e[hit] + s]
    return depth


def _pairs(z, line, pos, reach: int, step: float):
    """Per two consecutive cells of :func:`_lines`' order: whether they lie on one line
    within ``reach`` steps, whether the surface continues between them there (heights less
    than ``step`` apart), and the steps between them."""
    gap = pos[1:] - pos[:-1]
    near = (line[1:] == line[:-1]) & (gap <= reach)
    return near, near & (np.abs(z[:-1] - z[1:]) < step), gap


def _drops(z, x, y, p: BridgeParams, cell: float) -> np.ndarray:
    """Per cell and axis the smaller of its two drops (rows, cols, 4), NaN where an axis does
    not drop on both sides (:func:`_ray`, forward along each axis's lines, then back from the
    cells that dropped forward; a cell of a one-cell bump on an axis counts as a void on it,
    :func:`_bumps`)."""
    both = np.full(z.shape + (len(AXES),), np.nan)
    finite = ~np.isnan(z)  # an answered cell (+-inf: all its points NaN/inf) blocks, as it did
    zf, xf, yf = z.ravel(), x.ravel(), y.ravel()
    for i, d in enumerate(AXES):
        diag = cell * float(np.hypot(*d))
        reach = int(np.ceil(p.span / diag))
        idx, line, pos = _lines(finite & ~_bumps(z, d, p.step), d)
        zs, xs, ys = zf[idx], xf[idx], yf[idx]
        pairs = _pairs(zs, line, pos, reach, p.step)
        fwd = _ray(zs, xs, ys, pos, pairs, 1, reach, p, diag)
        cells = np.flatnonzero(np.isfinite(fwd))
        if not cells.size:
            continue
        bwd = _ray(zs, xs, ys, pos, pairs, -1, reach, p, diag, cells)
        layer = np.full(z.size, np.nan)
        layer[idx[cells]] = np.minimum(fwd[cells], bwd)
        both[..., i] = layer.reshape(z.shape)
    return both


def _links(z: np.ndarray, step: float) -> list:
    """Per neighbour offset (dr, dc) of the 8, the cells (bool grid) answered and differing
    from that neighbour's height by less than ``step``: the steps a flood may take."""
    filled = np.isfinite(z)
    zpad = np.pad(z, 1, constant_values=np.nan)
    rows, cols = z.shape
    links = []
    for dr in (-1, 0, 1):
        for dc in (-1, 0, 1):
            if dr or dc:
                nz = zpad[1 + dr: 1 + dr + rows, 1 + dc: 1 + dc + cols]
                with np.errstate(invalid="ignore"):
                    links.append(((dr, dc), filled & (np.abs(z - nz) < step)))
    return links


def _flood(links: list, grown: np.ndarray, steps: int, until: np.ndarray | None = None) -> np.ndarray:
    """``grown`` (bool grid) spread ``steps`` times to the 8 neighbours whose height differs
    from the grown cell's by less than ``step`` (``links``, :func:`_links`: the continuous
    surface around it); with ``until`` (bool grid), stopped as soon as it reaches a cell of
    it (it would only grow on: whether it reaches ``until`` is then known)."""
    rows, cols = grown.shape
    grown = grown.copy()
    if until is not None and (grown & until).any():
        return grown
    for _ in range(steps):
        gpad = np.pad(grown, 1)
        new = np.zeros(grown.shape, bool)
        for (dr, dc), ok in links:
            new |= gpad[1 + dr: 1 + dr + rows, 1 + dc: 1 + dc + cols] & ok
        new &= ~grown
        if not new.any():
            break
        grown |= new
        if until is not None and (new & until).any():
            break
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
    links = _links(zw, p.step)
    grown = _flood(links, cw, n)
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
    if terrain is None:
        return True
    reached = terrain[r0:r1, c0:c1] & ~cw
    return bool((_flood(links, grown, far - n, reached) & reached).any())


def _candidates(z: np.ndarray, x: np.ndarray, y: np.ndarray, p: BridgeParams, cell: float) -> list:
    """The candidate decks, (weak cells, bool grid with holes; unit plan vector (x, y) along
    the deck) pairs: 8-connected weak cells holding a seed, covering ``min_area`` and smooth
    (steps 2-4 of the module notes); those whose surface runs on beyond both ends
    (:func:`_continues`) are the decks."""
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
        decks.append((full, along))
    return decks


def deck_cells(z: np.ndarray, x: np.ndarray, y: np.ndarray, p: BridgeParams = BridgeParams(),
               cell: float = 1.0) -> np.ndarray:
    """Deck cells (bool grid, holes filled) of a lowest-ground grid ``z`` of ``cell``-metre
    cells whose points lie at plan positions ``x``, ``y`` (metres; NaN where empty)."""
    from scipy import ndimage

    deck = np.zeros(z.shape, bool)
    for comp, along in _candidates(z, x, y, p, cell):
        if _continues(z, comp, along, p, cell):
            deck |= comp
    return ndimage.binary_fill_holes(deck)


def _edges(xy: np.ndarray, u: np.ndarray, cell: float):
    """The long edges of a deck's surface points ``xy`` (k, 2) seen along the unit vector
    ``u``: the outermost points of each ``cell``-long slice lie on two lines t = k s + a
    (t across); one slope ``k`` is fitted to both, refitted without the slices more than 2.5
    robust deviations off (a cell that missed the edge). Slices narrower or wider than the
    deck by a cell (its skewed ends, a strip of the road beyond them) are left out. Returns
    k and the edges: the outermost t on each side in nine slices of ten, or None under three
    slices."""
    v = np.array([-u[1], u[0]])
    s, t = xy @ u, xy @ v
    j = np.floor((s - s.min()) / cell).astype(np.int64)
    n = int(j.max()) + 1
    lo, hi = np.full(n, np.inf), np.full(n, -np.inf)
    np.minimum.at(lo, j, t)
    np.maximum.at(hi, j, t)
    ok = np.bincount(j, minlength=n) >= 3
    if ok.sum() < 3:
        return None
    ok &= np.abs(hi - lo - np.median((hi - lo)[ok])) <= cell
    if ok.sum() < 3:
        return None
    centre = (np.flatnonzero(ok) + 0.5) * cell
    a = np.column_stack([np.concatenate([centre, centre]), np.repeat([[1.0, 0.0], [0.0, 1.0]], len(centre), axis=0)])
    b = np.concatenate([lo[ok], hi[ok]])
    res = np.abs(b - a @ np.linalg.lstsq(a, b, rcond=None)[0])
    good = _robust_keep(res)
    k = float(np.linalg.lstsq(a[good], b[good], rcond=None)[0][0])
    return k, float(np.percentile(lo[ok], 10.0)), float(np.percentile(hi[ok], 90.0))


def _axis(xy: np.ndarray, along, cell: float = 1.0):
    """The deck's axis (unit plan vector) and its edges across it (t_lo, t_hi; t along the
    axis turned left), refined from ``along`` (the grid axis across which its cells dropped,
    within 22.5° of the road's) on its surface points ``xy`` (k, 2): a deck's long edges run
    parallel to its axis, so the slope of its edges (:func:`_edges`) seen along an axis is the
    angle between the two (three passes). None when the edges cannot be followed."""
    u = np.asarray(along, float) / np.hypot(*along)
    for _ in range(3):
        e = _edges(xy, u, cell)
        if e is None:
            return None
        k = e[0]
        v = np.array([-u[1], u[0]])
        u = (u + k * v) / np.hypot(1.0, k)
        if abs(k) < 1e-4:
            break
    e = _edges(xy, u, cell)
    return None if e is None else (u, e[1], e[2])


def _deck_plane(xyz: np.ndarray, idx: np.ndarray, u: np.ndarray, tol: float):
    """The plane z = c0 + c1 s + c2 t of a deck's surface (s along ``u``, t across) fitted to
    its points ``idx``, refitted without those more than ``tol`` off it (parapets, kerbs):
    the coefficients and the surface points, or None when fewer than 10 remain."""
    v = np.array([-u[1], u[0]])
    st = np.column_stack([xyz[idx, :2] @ u, xyz[idx, :2] @ v])
    a = np.column_stack([np.ones(len(idx)), st])
    coef = np.linalg.lstsq(a, xyz[idx, 2], rcond=None)[0]
    keep = np.abs(xyz[idx, 2] - a @ coef) < tol
    if keep.sum() < 10:
        return None
    coef = np.linalg.lstsq(a[keep], xyz[idx[keep], 2], rcond=None)[0]
    return coef, idx[keep]


def _edge_clearance(off, dt, depth, h: float, j0: int, j1: int) -> np.ndarray:
    """Per slice ``j0`` ≤ j < ``j1`` (``h`` long, by ``off`` along the axis) the depth of the
    ground beside one edge of the deck under its surface, taken at the edge: the median of
    ``depth - b · dt`` over the slice's points (``dt`` metres out from the edge), with ``b``
    the across slope of the ground fitted within the slice and its two neighbours (a bank or
    an embankment's side falls away from the edge). +inf where a slice holds no point (a
    void beside the deck, as in the rays, counts as a drop)."""
    j = np.floor(off / h).astype(np.int64) - j0
    n = j1 - j0
    ok = (j >= 0) & (j < n)
    j, dt, depth = j[ok], dt[ok], depth[ok]
    cnt = np.bincount(j, minlength=n).astype(float)
    mdt = np.bincount(j, dt, n) / np.maximum(cnt, 1)
    mdz = np.bincount(j, depth, n) / np.maximum(cnt, 1)
    ddt, ddz = dt - mdt[j], depth - mdz[j]
    sxy, sxx = np.bincount(j, ddt * ddz, n), np.bincount(j, ddt * ddt, n)
    win = lambda q: q + np.append(q[1:], 0.0) + np.append(0.0, q[:-1])  # noqa: E731
    b = np.clip(win(sxy) / np.maximum(win(sxx), 1e-9), -1.0, 1.0)
    at_edge = depth - b[j] * dt
    order = np.lexsort((at_edge, j))
    js, vs = j[order], at_edge[order]
    first = np.searchsorted(js, np.arange(n))
    c = np.full(n, np.inf)
    has = cnt > 0
    lo = first[has] + (cnt[has].astype(np.int64) - 1) // 2
    hi = first[has] + cnt[has].astype(np.int64) // 2
    c[has] = 0.5 * (vs[lo] + vs[hi])
    return c


def _line(x: np.ndarray, y: np.ndarray):
    """Least-squares line through (x, y): slope, intercept and the sum of squared residuals."""
    slope, icpt = np.polyfit(x, y, 1)
    return float(slope), float(icpt), float(np.sum((y - icpt - slope * x) ** 2))


def _end_offset(c: np.ndarray, j0: int, h: float, ramp: float, step: float, kappa: float, window: int) -> float:
    """Where one edge of the deck ends (metres beyond the found end), from its clearance
    ``c`` per slice from the deck's middle (slice ``j0``, ``h`` long; :func:`_edge_clearance`).

    Going out, the clearance is the gap's depth, then falls under ``ramp`` (the rays see no
    drop there) at slice ``a``. Over the next ``window`` slices, either it runs on along one
    line (the ground beyond a wall, near the deck's plane: the deck ends at ``a``, and not
    beyond its found cells), or it
    falls along the abutment's slope, from ``step`` or more and staying above ``kappa`` but
    for its last slice (a slice astride a wall is no slope), and then runs on along a gentler line over the
    ground beyond (the road and its verges, a little under the deck's
    plane and trending with the terrain): two lines, meeting where the deck's surface meets
    the ground. Both models are fitted (the second with its knee at every slice, least
    squares) and the one with the smaller Bayesian information criterion is kept; the deck
    ends at the knee."""
    o = (np.arange(len(c)) + j0 + 0.5) * h
    fin = np.isfinite(c)
    low = np.flatnonzero(fin & (c <= ramp))
    if not low.size:  # no fall from the gap within reach: nothing to follow
        return 0.0
    a = int(low[0])
    wall = min(o[a] - 0.5 * h, 0.0)  # over a wall the deck ends with its cells
    keep = fin[a: a + window]
    x, y = o[a: a + window][keep], c[a: a + window][keep]
    n = len(y)
    if n < 5:
        return wall
    best = n * np.log(max(_line(x, y)[2] / n, 1e-6)) + 2.0 * np.log(n)
    end = wall
    for k in range(3, n - 2):  # the slope on x[:k] (a slice or two astride a wall are no slope)
        s1, i1, e1 = _line(x[:k], y[:k])
        s2, i2, e2 = _line(x[k:], y[k:])
        bic = n * np.log(max((e1 + e2) / n, 1e-6)) + 4.0 * np.log(n)
        if s1 < min(s2, 0.0) and i1 + s1 * wall >= step and y[: k - 1].min() > kappa and bic < best:
            best = bic
            end = float(np.clip((i2 - i1) / (s1 - s2), wall, x[k] + 0.5 * h))
    return end


def _hinge_end(off, dt, dz, end: float, reach: float, rise: float) -> float:
    """Where one edge of a deck ends, refined on the ground beside it (points at ``off``
    metres beyond the deck's found end, ``dt`` out from the edge, ``dz`` above the deck's
    plane): within ``reach`` of the first estimate ``end`` the ground is the lower of two
    planes in (off, dt), the abutment's slope and the ground beyond, meeting along the
    slope's top (oblique to the edge on a skewed bridge); fitted by alternating assignment
    (each point to the lower plane), leaving out points more than 2.5 robust deviations off.
    Returns the top's offset at the edge (dt = 0), or ``end`` when the two planes do not
    make a slope rising to the ground beyond by ``rise`` or more over ``reach``, or meet
    more than ``reach`` from ``end``."""
    near = np.abs(off - end) <= reach
    if near.sum() < 12:
        return end
    a = np.column_stack([np.ones(int(near.sum())), off[near], dt[near]])
    zz = dz[near]
    beyond = a[:, 1] > end
    keep = np.ones(len(zz), bool)
    for _ in range(6):
        if min((~beyond & keep).sum(), (beyond & keep).sum()) < 4:
            return end
        p1 = np.linalg.lstsq(a[~beyond & keep], zz[~beyond & keep], rcond=None)[0]
        p2 = np.linalg.lstsq(a[beyond & keep], zz[beyond & keep], rcond=None)[0]
        f1, f2 = a @ p1, a @ p2
        beyond = f2 < f1
        res = zz - np.minimum(f1, f2)
        keep = _robust_keep(res)
    d = p1 - p2
    if d[1] * reach < rise:  # the slope must rise towards the ground beyond
        return end
    new = -float(d[0]) / float(d[1])
    return new if abs(new - end) <= reach else end


def _deck_band(xyz: np.ndarray, surface: np.ndarray, mine: np.ndarray, along, p: BridgeParams):
    """A found deck's plane and band: its axis ``u`` (:func:`_axis`), the plane's
    coefficients (z = c0 + c1 s + c2 t, s along ``u``, t across), its surface points, and the
    band's edges ``t_lo``, ``t_hi``; None when the deck's points ``mine`` hold no plane.

    The found cells miss the deck's edges (a cell whose lowest echo lies beside the deck is
    not a deck cell), so the edges are taken again (:func:`_edges`) on every ``surface``
    point along the found span that lies on the plane or up to ``structure`` above it (the
    outer faces of the parapets); slices holding the road beyond an end are too wide and
    left out."""
    tol = 0.25 * p.step
    idx = np.flatnonzero(mine)
    fit = _deck_plane(xyz, idx, np.asarray(along, float), tol) if len(idx) >= 10 else None
    axis = None if fit is None else _axis(xyz[fit[1], :2], along)
    if axis is None:
        return None
    u, t_lo, t_hi = axis
    fit = _deck_plane(xyz, fit[1], u, tol)  # the same plane, its coefficients about the axis
    if fit is None:
        return None
    coef, flat = fit
    v = np.array([-u[1], u[0]])
    s_all, t_all = xyz[:, :2] @ u, xyz[:, :2] @ v
    s_lo, s_hi = s_all[flat].min(), s_all[flat].max()
    on = np.flatnonzero(surface & (t_all >= t_lo - p.step) & (t_all <= t_hi + p.step)
                        & (s_all >= s_lo) & (s_all <= s_hi))
    above = xyz[on, 2] - (coef[0] + coef[1] * s_all[on] + coef[2] * t_all[on])
    on = on[(above > -tol) & (above <= p.structure)]
    edges = _edges(xyz[on, :2], u, 1.0) if len(on) >= 10 else None
    if edges is not None:
        t_lo, t_hi = min(t_lo, edges[1]), max(t_hi, edges[2])
    return u, coef, flat, t_lo, t_hi


def _ends(xyz: np.ndarray, surface: np.ndarray, mine: np.ndarray, along, p: BridgeParams) -> np.ndarray:
    """The deck's points beyond its found cells (m,) bool: its ends over sloping
    (spill-through) abutments, where the cells see no drop, and the corners of a skewed
    deck.

    The deck is a plane over a band (:func:`_deck_band`); under it the ground is hidden, and
    beside it, from ``step`` / 2 (parapets) to ``2.5 · step`` out, lies the ground the DTM
    is interpolated across. Slice by slice (``step`` / 2 long) along the axis, from each
    edge's own found end (a skewed deck's ends are oblique), that edge's clearance
    (:func:`_edge_clearance`) is the gap's depth, then falls along the abutment's slope and
    levels off over the ground beyond; the edge ends where its surface meets the ground
    (:func:`_end_offset`), refined on the ground beside the edge up to ``step`` over the
    plane (:func:`_hinge_end`; on rolling ground the road beyond may rise over a level
    deck's plane), and at the latest where the band holds no point on the
    deck's plane, within ``span`` / 2 of the found cells. The deck's end is the line joining
    its two edges' ends: the top of a planar abutment slope, where the deck rests. A road on
    an embankment meets the embankment's sides without a step (clearance about nought all
    along) and is not taken. The points taken are those of the band and of its parapet
    margins, from ``step`` / 4 under the plane to ``structure`` over it, inside that line."""
    band_of = _deck_band(xyz, surface, mine, along, p)
    if band_of is None:
        return np.zeros(len(xyz), bool)
    u, coef, flat, t_lo, t_hi = band_of
    tol = 0.25 * p.step
    s_all, t_all = xyz[:, :2] @ u, xyz[:, :2] @ np.array([-u[1], u[0]])
    s_lo, s_hi = s_all[flat].min(), s_all[flat].max()
    h, m, wide, reach = 0.5 * p.step, 0.5 * p.step, 2.0 * p.step, 0.5 * p.span
    window = int(np.ceil(6.0 * p.clearance / h))
    inner = 0.5 * (s_hi - s_lo)
    k = np.flatnonzero(surface & (t_all >= t_lo - m - wide) & (t_all <= t_hi + m + wide)
                       & (s_all >= s_lo - reach) & (s_all <= s_hi + reach))
    s, t = s_all[k], t_all[k]
    dz = xyz[k, 2] - (coef[0] + coef[1] * s + coef[2] * t)  # height above the deck's plane
    frac = np.clip((t - t_lo) / max(t_hi - t_lo, 1e-9), 0.0, 1.0)
    band = (t >= t_lo - m) & (t <= t_hi + m) & (dz >= -tol) & (dz <= p.structure)
    flat_band = (t >= t_lo) & (t <= t_hi) & (np.abs(dz) < tol)
    out = np.zeros(len(xyz), bool)
    j0, j1 = -int(np.floor(inner / h)), int(np.ceil(reach / h))
    s_flat, t_flat = s_all[flat], t_all[flat]
    near_edge = (t_flat <= t_lo + p.clearance, t_flat >= t_hi - p.clearance)
    for sign, start in ((1.0, s_hi), (-1.0, s_lo)):
        off = sign * (s - start)  # metres beyond this end
        jj = np.floor(off[flat_band] / h).astype(np.int64)
        held = np.bincount(jj[(jj >= 0) & (jj < j1)], minlength=j1) > 0
        stop = int(np.argmin(held)) if not held.all() else j1  # the band leaves the plane
        ends = []
        for dt, near in zip((t_lo - t, t - t_hi), near_edge):  # distance out from each edge
            lead = float(np.max(sign * (s_flat[near] - start))) if near.any() else 0.0
            side = (dt > m) & (dt <= m + wide) & (dz < tol)
            c = _edge_clearance(off[side] - lead, dt[side], -dz[side], h, j0, j1)
            end = min(lead + _end_offset(c, j0, h, p.clearance, p.step, tol, window), stop * h)
            if end > lead:  # a fall onto the bank: the slope's top, fitted on the ground beside the edge
                bank = (dt > m) & (dt <= m + wide) & (dz < p.step)
                end = min(_hinge_end(off[bank], dt[bank], dz[bank], end, 2.0 * p.clearance, p.step),
                          stop * h)
            ends.append(end)
        limit = ends[0] + frac * (ends[1] - ends[0])  # the end line, edge to edge
        out[k[band & (off <= limit) & (off > -inner)]] = True
    return out & ~mine


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
    return deck_search(xyz, p, surface, ground).deck


@dataclass(frozen=True, eq=False)
class DeckSearch:
    """One search of :func:`deck_search`: its deck points and the grids it searched, so that a
    search on fewer surface points need not build them again (:meth:`without`).

    Attributes
    ----------
    deck : (m,) bool
        The deck points (:func:`bridge_decks`).
    grids : tuple or None
        (z, x, y, row, col, shape, cell) of :func:`_surface` and the cell; None when there
        were too few surface points to search.
    """

    deck: np.ndarray
    grids: tuple | None = None

    def without(self, xyz: np.ndarray, p: BridgeParams, surface: np.ndarray, left: np.ndarray,
                ground: np.ndarray | None = None) -> "DeckSearch":
        """:func:`deck_search` of ``xyz`` on the ``surface`` points, the searched ones less the
        points ``left`` (indices; every searched point not in ``surface``, and no other): the
        grids are this search's but in the cells that lost their lowest point, whose lowest
        remaining point is found again (the lowest index among equally low ones, as
        :func:`workstation.ground.common.grid_min` keeps). The deck tests then run again on
        these grids with ``surface`` and ``ground``."""
        surface = np.asarray(surface, bool)
        count = int(surface.sum())
        if self.grids is None or count < 3:
            return deck_search(xyz, p, surface, ground)
        z, x, y, r, c, shape, cell = self.grids
        if _cell(xyz, surface, count, p.cell) != cell:
            return deck_search(xyz, p, surface, ground)
        with np.errstate(invalid="ignore"):  # (NaN heights: lost too, the cell made again)
            lost = left[~(xyz[left, 2] > z[r[left], c[left]])]  # each was, or tied, its cell's lowest
        if len(lost):
            from .common import grid_min

            cells = np.zeros(shape, bool)
            cells[r[lost], c[lost]] = True
            pts = np.flatnonzero(cells[r, c] & surface)
            z2, low = grid_min(xyz[pts, 2], r[pts], c[pts], shape)
            z, x, y = z.copy(), x.copy(), y.copy()
            z[cells] = z2[cells]
            low = low[cells]  # (-1: the cell lost every surface point)
            low[low >= 0] = pts[low[low >= 0]]
            x[cells], y[cells] = _plan_at(xyz, low)
        return _decks_on(xyz, p, surface, ground, (z, x, y, r, c, shape, cell))


def deck_search(xyz: np.ndarray, p: BridgeParams = BridgeParams(), surface: np.ndarray | None = None,
                ground: np.ndarray | None = None) -> DeckSearch:
    """:func:`bridge_decks`, with the grids it searched (:class:`DeckSearch`)."""
    m = xyz.shape[0]
    surface = np.ones(m, bool) if surface is None else np.asarray(surface, bool)
    count = int(surface.sum())
    if count < 3:
        return DeckSearch(np.zeros(m, bool))
    cell = _cell(xyz, surface, count, p.cell)
    z, x, y, r, c, shape, _ = _surface(xyz, surface, cell)
    return _decks_on(xyz, p, surface, ground, (z, x, y, r, c, shape, cell))


def _decks_on(xyz: np.ndarray, p: BridgeParams, surface: np.ndarray, ground: np.ndarray | None,
              grids: tuple) -> DeckSearch:
    """The decks of :func:`deck_search` found on its ``grids`` (:attr:`DeckSearch.grids`)."""
    from scipy import ndimage

    z, x, y, r, c, shape, cell = grids
    none = DeckSearch(np.zeros(xyz.shape[0], bool), grids)
    candidates = _candidates(z, x, y, p, cell)
    if not candidates:
        return none
    terrain = None
    if ground is not None:
        g = np.flatnonzero(np.asarray(ground, bool))
        terrain = np.zeros(shape, bool)
        terrain[r[g], c[g]] = True
    comps = [(full, along) for full, along in candidates if _continues(z, full, along, p, cell, terrain)]
    if not comps:
        return none
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
    return DeckSearch(on, grids)


def _robust_keep(res: np.ndarray) -> np.ndarray:
    """Residuals within 2.5 robust standard deviations (1.4826 x the median absolute residual,
    at least 1 mm) of zero."""
    a = np.abs(res)
    return a <= 2.5 * 1.4826 * max(float(np.median(a)), 1e-3)
