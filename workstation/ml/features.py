"""Vectorised multi-scale local features for per-point classification.

Every feature is computed in **local metric coordinates** (the cloud's coordinates minus their
minimum corner, scaled to metres with the CRS's linear unit), so a model trained in metres
works on a US-survey-feet file too, and each one is chosen to be independent of the point
density, the scanner and the intensity calibration as far as possible, which is what lets a
model trained on simulated scans transfer to real ones:

* **heights above local minima** at radii 2.5, 5, 10, 20 and 40 m (grid minimum filters),
  and the local height range at 2.5 m;
* **height above a provisional ground surface**: a progressive morphological filter on a
  minimum-elevation grid (Zhang et al. 2003; the slope-dependent thresholds of SMRF,
  Pingel et al. 2013), with the flagged cells inpainted; plus the surface's slope;
* **eigenvalue features** of the k-nearest-neighbour covariance (Weinmann et al. 2015;
  Demantké et al. 2011) at two scales: linearity, planarity, scattering, verticality, the
  normal's |z| and the neighbourhood's z spread; the coarse scale is computed once per voxel
  of a grid-subsampled cloud and broadcast back to its points (Hackel et al. 2016);
* **echo features**: return number / number of returns, number of returns, first/last flags,
  and a flag saying whether returns are present at all;
* **intensity** normalised per cloud by robust statistics (median and 10-90 % range), with a
  flag when it is missing or constant, so a model survives missing or rescaled intensity;
* **local density**: log of the mean kNN distance relative to the cloud's median;
* **object areas**: the footprint area of the connected raised region (more than 1 m above
  the provisional ground) a point belongs to, and of the connected raised *planar* region
  (see :func:`_object_areas`), the object-level context that separates a car (a few m²)
  from a house (tens of m²) and a roof from canopy.

The kNN neighbourhoods are taken among one representative point per voxel (0.75 m fine,
1.5 m coarse) and broadcast back to the voxel's points, and the covariances are float32
moments, which keeps the whole feature pass at a few CPU-seconds per million points.
Neighbours at equal distances are taken in the representatives' order, so a neighbourhood
does not depend on the KD-tree, and the kNN scales, the pass's largest memory, can go tile by
tile (``tile_side`` of :func:`features_and_segments`) with every value the whole cloud's.

References
----------
K. Zhang et al. (2003). A progressive morphological filter for removing nonground
measurements from airborne LIDAR data. IEEE TGRS 41(4):872-882.
T. J. Pingel, K. C. Clarke, W. A. McBride (2013). An improved simple morphological filter for
the terrain classification of airborne LIDAR data. ISPRS J. 77:21-30.
M. Weinmann, B. Jutzi, S. Hinz, C. Mallet (2015). Semantic point cloud interpretation based on
optimal neighborhoods, relevant features and efficient classifiers. ISPRS J. 105:286-304.
T. Hackel, J. D. Wegner, K. Schindler (2016). Fast semantic segmentation of 3D point clouds
with strongly varying density. ISPRS Annals III-3:177-184.
"""

from __future__ import annotations

import weakref
from concurrent.futures import ThreadPoolExecutor
from dataclasses import asdict, dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.cpu import in_blocks
from workstation.core.errors import InvalidInputError
from workstation.core.pca import sym3_eigen, sym3_eigenvalues, sym3_eigenvector_z  # noqa: F401 (sym3_eigen re-exported)
from workstation.ground.common import fill_cut, fill_nearest

#: Names of the feature columns, in order.
FEATURE_NAMES: tuple[str, ...] = (
    "dz_min_2_5", "dz_min_5", "dz_min_10", "dz_min_20", "dz_min_40", "range_2_5",
    "dz_max_2_5", "hag_prov", "hag_prov_soft", "ground_slope",
    "lin_f", "plan_f", "scat_f", "vert_f", "nz_f", "zstd_f", "dzknn_min_f", "dzknn_max_f",
    "lin_c", "plan_c", "scat_c", "vert_c", "nz_c", "zstd_c",
    "ret_ratio", "n_returns", "is_first", "is_last", "has_returns",
    "intensity", "has_intensity", "log_density",
    "elev_area", "planar_area",
)


@dataclass(frozen=True)
class FeatureParams:
    """Feature extraction settings (lengths in metres).

    Attributes
    ----------
    cell : float
        Grid cell of the minimum-elevation grids (m).
    min_radii : tuple of float
        Radii (m) of the height-above-local-minimum features (five values).
    ground_window : float
        Largest opening window radius of the provisional ground filter (m): at least half the
        largest building. 70 m so that a 100 m block whose surroundings are partly empty (a
        crop, a data gap filled by its nearest cells) is still opened away.
    ground_slope : float
        Terrain slope tolerance of the provisional filter (rise/run).
    ground_trend_slope : float
        Slope-adaptive provisional filter (dimensionless factor; 0 = off): a second pass with a
        per-cell tolerance ``max(ground_slope, ground_trend_slope · mean terrain slope over
        trend_window)``, as SMRF's ``trend_slope`` (:mod:`workstation.ground.smrf`).
    trend_window : float
        Side (m) of the box over which the terrain slope is averaged.
    k_fine : int
        Neighbours of the fine eigenvalue scale (on the points, or on ``fine_voxel`` voxels).
    fine_voxel : float
        Voxel (m) to subsample the cloud before the fine kNN (0 = every point).
    k_coarse : int
        Neighbours of the coarse scale, computed on ``coarse_voxel`` voxels.
    coarse_voxel : float
        Voxel (m) of the coarse scale.
    object_height : float
        Height above the provisional ground (m) from which a point belongs to a raised object
        (the object-area features).
    workers : int
        Threads of the kNN scales: their KD-tree queries, eigen rows and tile writes (1: one
        thread; -1: all cores).
    """

    cell: float = 1.0
    min_radii: tuple = (2.5, 5.0, 10.0, 20.0, 40.0)
    ground_window: float = 70.0
    ground_slope: float = 0.15
    ground_trend_slope: float = 0.5
    trend_window: float = 30.0
    k_fine: int = 10
    fine_voxel: float = 0.75
    k_coarse: int = 16
    coarse_voxel: float = 1.5
    object_height: float = 1.0
    workers: int = -1

    def to_dict(self) -> dict:
        d = asdict(self)
        d["min_radii"] = list(self.min_radii)
        return d


def metric_xyz(cloud: Cloud) -> tuple[np.ndarray, float, float]:
    """Local metric coordinates (m) of a cloud: minus the minimum corner, scaled by the CRS unit.

    Returns
    -------
    xyz : (n, 3) float64
        Metres, origin at the minimum corner.
    h_factor, v_factor : float
        Metres per CRS unit, horizontally and vertically (1.0 when the CRS is unknown).
    """
    from workstation.ground.common import crs_unit_factors

    src = cloud.xyz
    hit = _METRIC_CACHE[0]
    if hit is not None and hit[0]() is src and hit[1] == cloud.crs:  # the features, the segments,
        return hit[2], hit[3], hit[4]  # the roof test and the understorey step of one cloud
    try:
        hf, vf = crs_unit_factors(cloud.crs)
    except Exception:  # unparsable CRS: assume metres
        hf, vf = 1.0, 1.0
    from workstation.ground.common import column_min

    xyz = np.asarray(src, np.float64)
    lo = column_min(xyz)
    out = np.empty_like(xyz)
    out[:, :2] = (xyz[:, :2] - lo[:2]) * hf
    out[:, 2] = (xyz[:, 2] - lo[2]) * vf
    out.flags.writeable = False  # shared by the callers of one cloud
    try:  # kept while the cloud's coordinates live, dropped with them
        key = weakref.ref(src)
        weakref.finalize(src, _METRIC_CACHE.__setitem__, 0, None)
        _METRIC_CACHE[0] = (key, cloud.crs, out, hf, vf)
    except TypeError:  # not weak-referenceable: no cache
        pass
    return out, hf, vf


#: The last cloud's metric coordinates: (weak reference to its xyz array, CRS, result, factors).
_METRIC_CACHE: list = [None]


# -- grids --------------------------------------------------------------------------------
def _grid(xy: np.ndarray, cell: float):
    c = np.floor(xy[:, 0] / cell).astype(np.int64)
    r = np.floor(xy[:, 1] / cell).astype(np.int64)
    shape = (int(r.max()) + 1, int(c.max()) + 1)
    return r, c, shape


def grid_reduce(z, r, c, shape, fn, fill):
    g = np.full(shape[0] * shape[1], fill, np.float64)
    fn.at(g, r * shape[1] + c, z)
    return g.reshape(shape)


def opening_steps(z0: np.ndarray, cell: float, windows) -> list[np.ndarray]:
    """SMRF's steepest step per cell for each of ``windows`` (m), with square openings
    (:func:`workstation.ground.common.opening_steps`): one opening sequence serves both
    provisional grounds and every tolerance."""
    from workstation.ground.common import open_square
    from workstation.ground.common import opening_steps as steps

    return steps(z0, cell, windows, open_square)


def provisional_ground(xyz: np.ndarray, cell: float, window: float, slope: float,
                       zmin: np.ndarray | None = None, rc=None, trend_slope: float = 0.0,
                       trend_window: float = 30.0, steps: np.ndarray | None = None) -> np.ndarray:
    """A provisional bare-earth grid by a progressive morphological filter.

    Square openings of the minimum-elevation grid with radii 1, 2, ... cells up to ``window``,
    each opening the previous one; a cell is flagged non-ground when one step lowers it by more
    than ``slope * cell * radius`` (Zhang et al. 2003; the progressive scheme of SMRF, Pingel et
    al. 2013); flagged and empty cells take the nearest ground cell's value, smoothed.

    Parameters
    ----------
    xyz : (n, 3) float64
        Local metric coordinates (m).
    cell : float
        Grid cell (m).
    window : float
        Largest window (m).
    slope : float
        Slope tolerance (rise/run).
    trend_slope, trend_window : float
        When ``trend_slope > 0``, a second pass with the per-cell tolerance
        ``max(slope, trend_slope · s)``, ``s`` the first pass's terrain slope averaged over a
        ``trend_window``-metre box (see :class:`FeatureParams`).
    steps : (rows, cols) float64, optional
        :func:`opening_steps` of this grid for ``window``, when computed beforehand (the
        feature pass shares one opening sequence between its two provisional grounds).

    Returns
    -------
    (rows, cols) float64
        Ground elevation per cell (m, local), cell-centred, origin (0, 0).
    """
    if rc is None:
        r, c, shape = _grid(xyz[:, :2], cell)
    else:
        r, c, shape = rc
    if zmin is None:
        zmin = grid_reduce(xyz[:, 2], r, c, shape, np.minimum, np.inf)
    empty = ~np.isfinite(zmin)
    z0 = fill_nearest(zmin, empty)
    if steps is None:
        (steps,) = opening_steps(z0, cell, (window,))
    bad = (steps > slope) | empty
    if bad.all():
        return z0
    if trend_slope > 0:
        from workstation.ground.common import trend_tolerance

        bad = (steps > trend_tolerance(fill_nearest(z0, bad), cell, slope, trend_slope, trend_window)) | empty
    return fill_cut(z0, bad)


def _despike_low(zmin: np.ndarray, threshold: float = 1.5) -> np.ndarray:
    """Empty the cells of isolated low outliers: a cell lower by more than ``threshold`` (m)
    than every other filled cell of its 5x5 neighbourhood (multipath, low noise), twice.
    Empty cells are +inf on input and output."""
    from scipy import ndimage

    ring = np.ones((5, 5), bool)
    ring[2, 2] = False
    for _ in range(2):
        nb = ndimage.minimum_filter(zmin, footprint=ring, mode="constant", cval=np.inf)
        spike = np.isfinite(zmin) & np.isfinite(nb) & (zmin < nb - threshold)
        if not spike.any():
            break
        zmin = np.where(spike, np.inf, zmin)
    return zmin


def grid_bilinear(grid: np.ndarray, xy: np.ndarray, cell: float) -> np.ndarray:
    from workstation.ground.common import bilinear

    return bilinear(grid, xy, cell, (0.0, 0.0))


def voxel_ids(xyz: np.ndarray, voxel: float, index: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Voxel representative (first point) indices and each point's voxel index, the voxels
    numbered in (x, y, z) order; with ``index`` (each row's point number) the representative
    is the smallest ``index`` of the voxel's rows."""
    from workstation.ground.common import column_max, column_min

    f = np.divide(xyz, voxel)
    v = np.floor(f, out=f).astype(np.int64)
    del f
    v -= column_min(v)
    dims = column_max(v) + 1
    col = v[:, 0] * dims[1] + v[:, 1]  # each point's (x, y) column of voxels
    ncol = int(dims[0]) * int(dims[1])
    if ncol > 2 * len(col) + 1_000_000:  # sparse columns: sort
        key, size = col * dims[2] + v[:, 2], None
    else:
        key, size = _column_keys(col, v[:, 2], ncol)
    if size is None or size > 8 * len(key) + 1_000_000:  # a sparse voxel grid: sort
        _, first, inv = np.unique(key, return_index=True, return_inverse=True)
        inv = inv.ravel()
        if index is not None:
            first = np.full(len(first), np.iinfo(np.intp).max, np.intp)
            np.minimum.at(first, inv, index)
        return first, inv
    # a dense one (the usual case): the occupied voxels in key order from a mask of the keys,
    # each one's rank written at its key (the other entries are never read), and each voxel's
    # smallest point index, without a sort: the same arrays as
    # np.unique(key, return_index=True, return_inverse=True) gives
    occupied = np.zeros(size, bool)
    occupied[key] = True
    cells = np.flatnonzero(occupied)
    rank = np.empty(size, np.intp)
    rank[cells] = np.arange(len(cells))
    inv = rank.take(key)
    first = np.full(len(cells), np.iinfo(np.intp).max, np.intp)
    np.minimum.at(first, inv, np.arange(len(key)) if index is None else index)
    return first, inv


def _column_keys(col: np.ndarray, vz: np.ndarray, ncol: int) -> tuple[np.ndarray, int]:
    """Keys of the voxels (column ``col`` of ``ncol``, layer ``vz``) in (column, layer) order,
    packed: each column spans only its own lowest to highest layer, so the keys range over
    about the occupied voxels rather than the whole box (mostly air above the ground).
    Returns the keys and their range."""
    lo = np.full(ncol, np.iinfo(np.int64).max)
    np.minimum.at(lo, col, vz)
    hi = np.full(ncol, -1, np.int64)
    np.maximum.at(hi, col, vz)
    span = np.maximum(hi - lo + 1, 0)  # 0 for an empty column
    start = np.cumsum(span)
    size = int(start[-1])
    start -= span
    start -= lo  # a voxel's key: its column's start plus its layer above the column's lowest
    key = start.take(col)
    key += vz
    return key, size


def _representatives(xyz: np.ndarray, voxel: float) -> tuple[np.ndarray, np.ndarray]:
    """(first point of each voxel, each point's voxel) of :func:`voxel_ids`; every point its
    own representative when ``voxel`` is 0."""
    if voxel > 0:
        return voxel_ids(xyz, voxel)
    return np.arange(len(xyz)), np.arange(len(xyz))


def _coarser_representatives(xyz: np.ndarray, fine, fine_voxel: float, voxel: float):
    """:func:`_representatives` of ``xyz`` for ``voxel``, given ``fine``, those for
    ``fine_voxel``. When ``voxel`` is ``fine_voxel`` times a power of two, every fine voxel
    lies in one coarse voxel (``x / voxel`` is ``x / fine_voxel`` halved exactly, and
    floor(y / 2) = floor(floor(y) / 2)), so the coarse voxels are numbered among the fine
    representatives alone, each one's first point the smallest of its fine voxels' first
    points: the same arrays from about half the rows."""
    first, inv = fine
    s = round(float(np.log2(voxel / fine_voxel))) if fine_voxel > 0 and voxel > fine_voxel else 0
    if s < 1 or voxel != fine_voxel * 2.0 ** s:
        return _representatives(xyz, voxel)
    cfirst, cinv = voxel_ids(xyz[first], voxel, index=first)
    return cfirst, cinv.take(inv)


def _eigen(xyz_q: np.ndarray, xyz_ref: np.ndarray, k: int, workers: int, reach: bool = False, tree=None):
    """Eigenvalue features of the kNN covariance of each query point among reference points.

    Returns (m, 8) float32: linearity, planarity, scattering, verticality, |n_z|, z std,
    z - kNN min z, kNN max z - z; and the mean neighbour distance (m,); with ``reach`` also
    the distance of the farthest neighbour (m,). ``tree``: a cKDTree of ``xyz_ref`` (built
    here when None).

    The queries go in blocks of :data:`_QUERY_BLOCK` rows on ``workers`` threads
    (:func:`workstation.core.cpu.in_blocks`), each block's neighbours found and used at once:
    no neighbour list of the whole set is held, and the rows are independent, so the values
    are those of one query of all.
    """
    from scipy.spatial import cKDTree

    k = int(min(k, len(xyz_ref)))
    if tree is None:
        tree = cKDTree(xyz_ref, balanced_tree=False, compact_nodes=False)
    ref32 = np.ascontiguousarray(xyz_ref.T, dtype=np.float32)  # (3, r): x, y, z rows
    m = len(xyz_q)
    out = np.empty((m, 8), np.float32)
    mean, last = np.empty(m), np.empty(m)
    bound = _query_bound(tree, xyz_q, min(k + 1, tree.n), workers)

    def block(s):
        rows = slice(s, s + _QUERY_BLOCK)
        d, j = _knn(tree, xyz_q[rows], k, 1, bound)
        _eigen_rows(xyz_q[rows], ref32, j, k, out[rows])
        mean[rows] = d.mean(axis=1)
        last[rows] = d[:, -1]

    in_blocks(block, m, _QUERY_BLOCK, workers)
    if reach:
        return out, mean, last
    return out, mean


def _knn(tree, xyz_q: np.ndarray, k: int, workers: int, bound: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The ``k`` nearest reference points (distances, indices; (m, k)) of each query, ties
    of equal distance taken in reference order, so that neighbours and their order do not
    depend on the tree: any set of reference points holding a query's neighbours, in the same
    relative order, gives the same (the tiled feature pass). Queries ``k + 1`` to see a tie
    at the k-th distance; the rare rows whose tie runs beyond are queried again, wider. Ties
    at distance 0 are left as the tree gives them: those neighbours share the query's
    coordinates, so their order changes no feature (and a cloud of many duplicates would
    otherwise query every duplicate of every one). ``bound``: the search bound of
    :func:`_bounded_query` (None: :func:`_query_bound` of these queries)."""
    n = tree.n
    kq = min(k + 1, n)
    if bound is None:
        bound = _query_bound(tree, xyz_q, kq, workers)
    d, j = _bounded_query(tree, xyz_q, kq, workers, bound)
    if kq > 1:
        tie = np.flatnonzero(((d[:, 1:] == d[:, :-1]) & (d[:, 1:] > 0)).any(axis=1))
        if len(tie):
            d2, j2 = _ordered_ties(tree, xyz_q[tie], d[tie], j[tie], k, workers)
            d, j = d[:, :k].copy(), j[:, :k].copy()
            d[tie], j[tie] = d2, j2
    return d[:, :k], j[:, :k]


#: Queries per sampled query of :func:`_query_bound`, and the share of queries expected to
#: find their neighbours within its bound.
_BOUND_SAMPLE, _BOUND_SHARE = 64, 0.99


def _query_bound(tree, q: np.ndarray, kq: int, workers: int) -> float:
    """Search bound of :func:`_bounded_query` for the queries ``q``: the ``_BOUND_SHARE``
    quantile of the kq-th neighbour distance of one query in ``_BOUND_SAMPLE`` (infinity, no
    bound, for fewer than ``100 * _BOUND_SAMPLE`` queries, or where duplicates reach the kq-th
    neighbour)."""
    if len(q) < 100 * _BOUND_SAMPLE:
        return np.inf
    ds, _ = tree.query(q[::_BOUND_SAMPLE], k=kq, workers=workers)
    bound = float(np.quantile(ds.reshape(-1, kq)[:, -1], _BOUND_SHARE))
    return bound if np.isfinite(bound) and bound > 0 else np.inf


def _bounded_query(tree, q: np.ndarray, kq: int, workers: int, bound: float) -> tuple[np.ndarray, np.ndarray]:
    """``tree.query(q, k=kq)`` ((m, kq) distances, indices), searched within the distance
    ``bound`` (:func:`_query_bound`). The bound prunes the search (a tenth to a fifth less
    time on lidar representatives); the queries that find fewer than kq points within it are
    queried again without, so every row holds its kq nearest points either way."""
    m = len(q)
    d, j = tree.query(q, k=kq, workers=workers, distance_upper_bound=bound)
    d, j = d.reshape(m, kq), j.reshape(m, kq)
    if np.isfinite(bound):
        miss = np.flatnonzero(np.isinf(d[:, -1]))
        if len(miss):
            d2, j2 = tree.query(q[miss], k=kq, workers=workers)
            d[miss], j[miss] = d2.reshape(-1, kq), j2.reshape(-1, kq)
    return d, j


def _ordered_ties(tree, q: np.ndarray, d: np.ndarray, j: np.ndarray, k: int, workers: int):
    """:func:`_knn` of the queries ``q`` that have ties, given their first query (``d``, ``j``;
    ``kq`` > k columns): every reference point as near as the k-th (each row queried, wider,
    until the farthest returned is farther, or all are), sorted by distance and then index."""
    n, kq = tree.n, d.shape[1]
    out_d, out_j = np.empty((len(q), k)), np.empty((len(q), k), np.intp)
    rows = np.arange(len(q))
    while len(rows):
        wider = (kq < n) & (d[:, kq - 1] == d[:, k - 1])  # the tie may run past the last column
        done = ~wider
        order = np.lexsort((j[done], d[done]), axis=-1)[:, :k]
        out_d[rows[done]] = np.take_along_axis(d[done], order, axis=1)
        out_j[rows[done]] = np.take_along_axis(j[done], order, axis=1)
        rows, q = rows[wider], q[wider]
        if len(rows):
            kq = min(2 * kq, n)
            d, j = tree.query(q, k=kq, workers=workers)
    return out_d, out_j


def _transposed(a: np.ndarray, block: int = 32768) -> np.ndarray:
    """``np.ascontiguousarray(a.T)`` of an (m, k) array, copied a block of rows at a time: each
    block is read from memory once (the plain copy reads the whole array once per column)."""
    out = np.empty(a.shape[::-1], a.dtype)
    for s in range(0, len(a), block):
        out[:, s:s + block] = a[s:s + block].T
    return out


#: Query rows per block of :func:`_eigen_rows`: a block's (k, rows) neighbour coordinates and
#: the eigen solver's temporaries stay in the core's cache.
_ROW_BLOCK = 16384


#: Query rows per block of :func:`_eigen`: one row block of :func:`_eigen_rows` each.
_QUERY_BLOCK = _ROW_BLOCK


def _eigen_rows(xyz_q: np.ndarray, ref32: np.ndarray, j: np.ndarray, k: int, out: np.ndarray) -> None:
    """:func:`_eigen`'s features of the query rows ``xyz_q`` whose neighbours are ``j`` (column
    indices of ``ref32``, the reference points' float32 x, y, z rows (3, r)), written into
    ``out`` (len(xyz_q), 8), a block of :data:`_ROW_BLOCK` rows at a time
    (:func:`_eigen_block`; the rows are independent, so the values do not depend on the
    blocks)."""
    for s in range(0, len(xyz_q), _ROW_BLOCK):
        _eigen_block(xyz_q[s:s + _ROW_BLOCK], ref32, j[s:s + _ROW_BLOCK], k, out[s:s + _ROW_BLOCK])


def _eigen_block(xyz_q: np.ndarray, ref32: np.ndarray, j: np.ndarray, k: int, out: np.ndarray) -> None:
    """:func:`_eigen_rows` of one block of rows.

    The neighbourhoods are gathered neighbour-major, (k, m) per coordinate, so that every
    reduction over the neighbours is a sequence of whole-row operations: the sums add the
    neighbours one after the other, as ``nb.mean(axis=1)`` and ``einsum("mk,mk->m")`` of an
    (m, k, 3) array do, so the values are the same bit for bit, at about half the CPU time."""
    m = len(xyz_q)
    jt = np.ascontiguousarray(j.T)  # (k, m)
    # float32 second moments of the neighbours about their mean (local metric coordinates, so
    # float32 keeps 0.1 mm at a kilometre)
    mu = np.empty((3, m), np.float32)
    cols = []
    for a in range(3):
        c = np.take(ref32[a], jt)  # (k, m)
        # mean as numpy's: the neighbours added in order, then a true division by an intp count
        # (added row by row: numpy's own reduce turns pairwise for a single query, m == 1)
        total = c[0].copy()
        for i in range(1, k):
            total += c[i]
        np.true_divide(total, np.intp(k), out=mu[a], casting="unsafe")
        c -= mu[a]
        cols.append(c)
    x, y, zc = cols
    # the six distinct covariance entries, each a contiguous float64 row: xx, yy, zz, xy, xz, yz
    # (float32 products accumulated from zero in neighbour order, as einsum does, then / k):
    # each entry's k products in one call, then added row by row
    cov = np.empty((6, m), np.float64)
    acc = np.empty(m, np.float32)
    prod = np.empty((k, m), np.float32)
    for a, (u, v) in enumerate(((x, x), (y, y), (zc, zc), (x, y), (x, zc), (y, zc))):
        np.multiply(u, v, out=prod)
        acc.fill(0)
        for i in range(k):
            acc += prod[i]
        cov[a] = acc / k
    cov[:3] += 1e-8
    l1, l2, l3 = sym3_eigenvalues(*cov)
    l1 = np.maximum(l1, 1e-12)
    l2 = np.clip(l2, 0, l1)
    l3 = np.clip(l3, 0, l2)
    nrm_z = sym3_eigenvector_z(*cov, l3)  # the normal's and the main direction's z components
    main_z = sym3_eigenvector_z(*cov, l1)
    zq = xyz_q[:, 2] - mu[2]  # heights relative to the neighbourhood mean
    out[:, 0] = (l1 - l2) / l1
    out[:, 1] = (l2 - l3) / l1
    out[:, 2] = l3 / l1
    out[:, 3] = 1.0 - np.abs(main_z)  # verticality of the main direction
    out[:, 4] = np.abs(nrm_z)
    out[:, 5] = np.sqrt(np.maximum(cov[2], 0))
    out[:, 6] = np.minimum(zq - np.minimum.reduce(zc, axis=0), 30.0)
    out[:, 7] = np.minimum(np.maximum.reduce(zc, axis=0) - zq, 30.0)


def _object_areas(hag: np.ndarray, nz: np.ndarray, scat: np.ndarray, r: np.ndarray, c: np.ndarray,
                  shape: tuple, cell: float, height: float) -> tuple[np.ndarray, np.ndarray]:
    """Footprint areas (m², as log(1 + area)) of the raised object each point belongs to.

    A grid cell is *raised* when one of its points is more than ``height`` metres above the
    provisional ground, and *planar-raised* when at least 40 % of its raised points lie on a
    plane that is not a wall (fine-scale |n_z| > 0.5, scattering < 0.1). The connected
    components (8-neighbourhood, after closing one-cell gaps so sparse scans stay connected)
    of each mask give two areas per point: a car is a few m², a house tens, a hall thousands,
    while canopy forms raised but rarely planar-raised regions. Points at or below ``height``
    get 0. The object-level context a per-point network cannot see (in the spirit of the
    segment features of Vosselman et al. 2017, Contextual segment-based classification of
    airborne laser scanner data, ISPRS J. 128:354-371).

    Returns
    -------
    areas : (n, 2) float32
        log(1 + raised area), log(1 + planar-raised area).
    segments : (n,) int64
        Each point's planar-raised component (0: none): the classifier's context step.
    """
    out = np.zeros((len(hag), 2), np.float32)
    segments = np.zeros(len(hag), np.int64)
    up = hag > height
    if not up.any():
        return out, segments
    flat = r * shape[1] + c
    for j, (lab, k) in enumerate(_raised_components(hag, nz, scat, flat, shape, height)):
        point_lab = lab.ravel()[flat]
        if j == 1:
            segments = np.where(up, point_lab, 0)
        if k == 0:
            continue
        area = np.bincount(lab.ravel(), minlength=k + 1).astype(np.float32) * (cell * cell)
        area[0] = 0.0
        out[:, j] = np.where(up, np.log1p(area[point_lab]), 0.0)
    return out, segments


def _raised_components(hag, nz, scat, flat, shape, height):
    """Connected components (grid labels, count) of the raised and the planar-raised cells
    (definitions in :func:`_object_areas`)."""
    from scipy import ndimage

    up = hag > height
    size = shape[0] * shape[1]
    n_up = np.bincount(flat[up], minlength=size)
    n_pl = np.bincount(flat[up & (nz > 0.5) & (scat < 0.1)], minlength=size)
    st = np.ones((3, 3), bool)
    out = []
    masks = ((n_up > 0), (n_pl * 5 >= n_up * 2) & (n_up > 0))
    for mask in masks:
        m = mask.reshape(shape)
        m = ndimage.binary_closing(m, structure=st) | m
        out.append(ndimage.label(m, structure=st))
    return out


def _voxel_eigen(xyz: np.ndarray, voxel: float, k: int, workers: int):
    """Eigen features of one representative point per ``voxel`` (m; 0 = every point).

    Returns
    -------
    e : (v, 8) float32
        :func:`_eigen` features of the representatives.
    z : (v,) float64
        Their heights.
    dist : (v,) float64
        Their mean kNN distance.
    inv : (n,) int64
        Each point's representative.
    """
    first, inv = _representatives(xyz, voxel)
    ref = xyz[first]
    e, dist = _eigen(ref, ref, k, workers)
    return e, ref[:, 2], dist, inv


def _echo_features(cloud: Cloud) -> np.ndarray:
    n = cloud.n
    out = np.zeros((n, 5), np.float32)
    a = cloud.attrs
    if "return_number" in a and "number_of_returns" in a:
        rn = np.asarray(a["return_number"]).astype(np.float32)
        nr = np.asarray(a["number_of_returns"]).astype(np.float32)
        valid = (nr >= 1) & (rn >= 1)
        if valid.mean() > 0.5 and nr.max() > 1:
            nr = np.where(valid, nr, 1)
            rn = np.clip(np.where(valid, rn, 1), 1, nr)
            out[:, 0] = rn / nr
            out[:, 1] = np.minimum(nr, 5)
            out[:, 2] = rn == 1
            out[:, 3] = rn == nr
            out[:, 4] = 1
            return out
    out[:, 0] = 1
    out[:, 1] = 1
    out[:, 2] = 1
    out[:, 3] = 1
    return out


def _intensity_features(cloud: Cloud) -> np.ndarray:
    n = cloud.n
    out = np.zeros((n, 2), np.float32)
    if "intensity" not in cloud.attrs:
        return out
    i = np.asarray(cloud.attrs["intensity"], np.float64)
    p10, p50, p90 = np.percentile(i, [10, 50, 90])
    span = p90 - p10
    if not np.isfinite(span) or span <= 0:
        return out
    out[:, 0] = np.clip((i - p50) / span, -3, 3)
    out[:, 1] = 1
    return out


def compute_features(cloud: Cloud, params: FeatureParams = FeatureParams()) -> np.ndarray:
    """Per-point feature matrix (:func:`features_and_segments` without the segments)."""
    return features_and_segments(cloud, params)[0]


def features_and_segments(cloud: Cloud, params: FeatureParams = FeatureParams(),
                          with_hag=None, tile_side: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Per-point feature matrix, and the planar raised object of each point (the components
    behind the ``planar_area`` feature, found on the way; the classifier's context step).

    Parameters
    ----------
    cloud : Cloud
        Any cloud with at least 3 points; ``return_number``/``number_of_returns`` and
        ``intensity`` are used when present.
    params : FeatureParams
    with_hag : callable, optional
        Called with the height above the provisional ground (the ``hag_prov`` column) as
        soon as it is known, while the kNN threads are still running: work that needs only
        that height can use the idle core (the classifier builds its roof test's KD-tree).
    tile_side : float, optional
        Compute the kNN scales, the pass's memory, tile by tile in squares of this side (m;
        :func:`_tiled_eigen_columns`), with the same values: the grids, the statistics and the
        objects are the whole cloud's either way.

    Returns
    -------
    F : (n, len(FEATURE_NAMES)) float32
        Columns as :data:`FEATURE_NAMES`; heights in metres.
    segments : (n,) int64
        Planar raised component of each point, 0 for none.
    """
    if cloud.n < 3:
        raise InvalidInputError(f"needs at least 3 points, got {cloud.n}", field="xyz")
    xyz, _, _ = metric_xyz(cloud)
    n = len(xyz)
    p = params
    F = np.empty((n, len(FEATURE_NAMES)), np.float32, order="F")
    # the kNN scales run in worker threads (KD-tree queries and numpy release the GIL) while
    # this thread does the grid features: the two scales of the whole cloud side by side, or
    # the tiles one after the other, writing their own columns of F (10-23)
    pool = ThreadPoolExecutor(max_workers=1 if p.workers == 1 else 2)
    if tile_side is None:
        futures = [pool.submit(_voxel_eigen, xyz, v, k, p.workers)
                   for v, k in ((p.fine_voxel, p.k_fine), (p.coarse_voxel, p.k_coarse))]
    else:
        futures = [pool.submit(_tiled_eigen_columns, F, xyz, p, float(tile_side))]
    cell, (r, c, shape) = _grid_columns(F, cloud, xyz, p)
    if with_hag is not None:
        with_hag(F[:, 7])
    done = [f.result() for f in futures]
    pool.shutdown()
    dh = done[0] if tile_side is not None else _eigen_columns(F, xyz[:, 2], *done)
    _density_column(F, dh)
    F[:, 32:34], segments = _object_areas(F[:, 7], F[:, 14], F[:, 12], r, c, shape, cell, p.object_height)
    with np.errstate(invalid="ignore", over="ignore"):  # finite only if every value is; no temporaries
        finite = np.isfinite(F.sum())  # (an overflow would cost a pass that changes nothing)
    if not finite:
        np.nan_to_num(F, copy=False, nan=0.0, posinf=60.0, neginf=-20.0)
    return F, segments


def _grid_columns(F: np.ndarray, cloud: Cloud, xyz: np.ndarray, p: FeatureParams):
    """Columns 0-9 (the grid features) and 24-30 (echoes, intensity) of ``F``; returns the
    grid's cell (m) and each point's (row, column, grid shape)."""
    from workstation.ground.common import auto_cell

    cell = auto_cell(xyz[:, :2], p.cell)  # sparse data over a large extent: grids sized by the points
    r, c, shape = _grid(xyz[:, :2], cell)
    zmin = _despike_low(grid_reduce(xyz[:, 2], r, c, shape, np.minimum, np.inf))
    zmax = grid_reduce(xyz[:, 2], r, c, shape, np.maximum, -np.inf)
    zmin_f = fill_nearest(zmin, ~np.isfinite(zmin))  # despiked cells take their neighbours' value
    flat = r * shape[1] + c  # each point's cell in the raveled grids
    _relief_features(F, xyz[:, 2], zmin_f, zmax, flat, cell, p)
    _ground_features(F, xyz, zmin, zmin_f, (r, c, shape), cell, p)
    F[:, 24:29] = _echo_features(cloud)
    F[:, 29:31] = _intensity_features(cloud)
    return cell, (r, c, shape)


def knn_buffer(p: FeatureParams) -> float:
    """First buffer (m) of a kNN tile (:func:`_tiled_eigen_columns` widens it where needed)."""
    return 8.0 * max(p.fine_voxel, p.coarse_voxel, 1.0)


def square_tiles(xy: np.ndarray, side: float, buffer: float):
    """Square tiles of ``side`` (m) over local metric ``xy`` (origin 0): (core mask, indices
    of the points within ``buffer`` of the core, that rectangle (x0, x1, y0, y1)) of each
    occupied tile; every point lies in one core."""
    from workstation.ground.common import column_max

    ext = column_max(xy)
    nx, ny = int(np.ceil(ext[0] / side)) or 1, int(np.ceil(ext[1] / side)) or 1
    tile = np.minimum((xy[:, 0] / side).astype(np.int64), nx - 1)  # each point's tile, a * ny + b
    tile *= ny
    tile += np.minimum((xy[:, 1] / side).astype(np.int64), ny - 1)
    occupied = np.bincount(tile, minlength=nx * ny)
    for a in range(nx):
        if not occupied[a * ny:(a + 1) * ny].any():
            continue
        x0, x1 = a * side - buffer, (a + 1) * side + buffer
        strip = np.flatnonzero((xy[:, 0] >= x0) & (xy[:, 0] < x1))  # the column's buffered x range, once
        ys = xy[strip, 1]
        for b in range(ny):
            if not occupied[a * ny + b]:
                continue
            y0, y1 = b * side - buffer, (b + 1) * side + buffer
            yield tile == a * ny + b, strip[(ys >= y0) & (ys < y1)], (x0, x1, y0, y1)


def _tiled_eigen_columns(F: np.ndarray, xyz: np.ndarray, p: FeatureParams, side: float) -> np.ndarray:
    """:func:`_eigen_columns` of the whole cloud, the kNN scales computed tile by tile
    (:func:`square_tiles`, buffer :func:`knn_buffer`): each core point takes its voxel
    representative's features from :func:`_exact_scale`, the same neighbours as in the
    whole cloud. Returns each point's mean neighbour distance (the density column's input)."""
    from workstation.ground.common import column_max, column_min

    dh = np.empty(len(xyz))
    lo, hi = column_min(xyz[:, :2]), column_max(xyz[:, :2])
    whole: dict = {}  # voxel -> the whole cloud's representatives and their tree, made when first needed
    # a tile's columns are written (one core: the takes, and the first touch of F's pages) while
    # the next tile's neighbours are found; each tile writes its own rows of F and dh
    writer = ThreadPoolExecutor(max_workers=1) if p.workers != 1 else None
    pending = None  # the last tile's write: one tile's scales held at a time
    try:
        for core, sel, rect in square_tiles(xyz[:, :2], side, knn_buffer(p)):
            keep = core[sel]
            rows = sel[keep]
            part = xyz[sel]
            fine = _representatives(part, p.fine_voxel)
            reps = (fine, _coarser_representatives(part, fine, p.fine_voxel, p.coarse_voxel))
            scales = [_exact_scale(xyz, part, keep, r, rect, (lo, hi), v, k, p.workers, whole)
                      for r, (v, k) in zip(reps, ((p.fine_voxel, p.k_fine), (p.coarse_voxel, p.k_coarse)))]
            if writer is None:
                _tile_columns(F, dh, xyz, rows, scales)
                continue
            if pending is not None:
                pending.result()  # (its error, if any, raised here)
            pending = writer.submit(_tile_columns, F, dh, xyz, rows, scales)
        if pending is not None:
            pending.result()
    finally:
        if writer is not None:
            writer.shutdown(cancel_futures=True)
    return dh


def _tile_columns(F: np.ndarray, dh: np.ndarray, xyz: np.ndarray, rows: np.ndarray, scales) -> None:
    """Columns 10-23 of ``F`` and the mean fine neighbour distance ``dh`` at the core points
    ``rows`` of one tile, from its two :func:`_exact_scale` ``scales``."""
    Ft = np.empty((len(rows), 24), np.float32, order="F")  # _eigen_columns writes columns 10-23
    dh[rows] = _eigen_columns(Ft, xyz[rows, 2], *scales)
    F[rows, 10:24] = Ft[:, 10:24]


def _exact_scale(xyz, part, keep, reps, rect, extent, voxel: float, k: int, workers: int, whole: dict):
    """:func:`_voxel_eigen` of the points ``part`` of ``xyz`` (a tile and its buffer, the
    rectangle ``rect``, in the cloud's order; ``reps``: its :func:`_representatives`), exact
    for the representatives of the points ``keep`` of ``part`` (the core): the same
    neighbours as among the whole cloud's representatives. Returns the core's representatives' features, heights and mean kNN
    distances, and each core point's representative among them (the arrays of
    :func:`_voxel_eigen` without the representatives no core point reads).

    The representatives of the voxels inside ``rect`` are the whole cloud's (the first point
    of each, ``part`` being in the cloud's order); those of voxels cut by its edge may differ,
    but all lie within ``voxel`` of the edge. So a representative's k neighbours are the whole
    cloud's when the farthest of them is nearer than its distance to each edge inside the
    cloud's ``extent`` (lo, hi) less ``voxel``. The few others (a lone point far above the
    rest reaches across tiles) are queried among the whole cloud's representatives, made once
    per voxel size into ``whole`` when a tile first needs them."""
    first, inv = reps
    ref = part[first]
    own = inv[keep]  # each core point's representative
    used = np.zeros(len(ref), bool)
    used[own] = True
    u = np.flatnonzero(used)  # the core's representatives: the only rows queried
    rank = np.empty(len(ref), np.intp)
    rank[u] = np.arange(len(u))
    q = ref[u]
    e, dist, reach = _eigen(q, ref, k, workers, reach=True)
    far = np.flatnonzero(~_inside(q, reach, rect, extent, voxel, len(ref) >= k))
    if len(far):
        if voxel not in whole:
            from scipy.spatial import cKDTree

            wref = xyz[_representatives(xyz, voxel)[0]]
            whole[voxel] = (wref, cKDTree(wref, balanced_tree=False, compact_nodes=False))
        wref, tree = whole[voxel]
        e[far], dist[far], reach[far] = _eigen(q[far], wref, k, workers, reach=True, tree=tree)
    return e, q[:, 2], dist, rank.take(own)


def _inside(ref: np.ndarray, reach: np.ndarray, rect, extent, voxel: float, full: bool) -> np.ndarray:
    """Whether each representative's neighbourhood (radius ``reach``) stays clear of the
    rectangle's edges inside the cloud's extent by more than ``voxel`` (see
    :func:`_exact_scale`); none does when the rectangle held fewer than k representatives
    (``full`` false) unless it covers the extent."""
    (lo, hi), (x0, x1, y0, y1) = extent, rect
    clear = np.full(len(ref), np.inf)
    for edge, inner, axis, sign in ((x0, x0 > lo[0], 0, 1), (x1, x1 <= hi[0], 0, -1),
                                    (y0, y0 > lo[1], 1, 1), (y1, y1 <= hi[1], 1, -1)):
        if inner:
            np.minimum(clear, sign * (ref[:, axis] - edge) - voxel, out=clear)
    if not full:
        return np.isinf(clear)
    return reach < clear


def _eigen_columns(F: np.ndarray, z: np.ndarray, fine, coarse) -> np.ndarray:
    """Columns 10-23 of ``F`` from the two :func:`_voxel_eigen` scales (one query per voxel
    representative, broadcast to its points): six eigen features per scale (10-15 fine, 18-23
    coarse) and the fine neighbourhood's extremes relative to each point's own height (16-17,
    metres, capped at 30). Returns each point's mean fine neighbour distance."""
    (ef, zr, dh, finv), (ec, _, _, inv) = fine, coarse
    # broadcast: one ``take`` per column from a contiguous row of the transposed features
    # straight into F's (Fortran-order) columns, no (n, 8) temporaries
    eft, ect = _transposed(ef), _transposed(ec)
    for a in range(6):
        np.take(eft[a], finv, out=F[:, 10 + a])
        np.take(ect[a], inv, out=F[:, 18 + a])
    # extremes relative to each point's own height: the representatives' lowest and highest
    # neighbour heights (float64, as their per-point differences) broadcast, then subtracted
    buf = np.empty(len(z))
    np.take(zr - eft[6], finv, out=buf)
    np.subtract(z, buf, out=buf)
    F[:, 16] = np.clip(buf, 0, 30, out=buf)
    np.take(zr + eft[7], finv, out=buf)
    np.subtract(buf, z, out=buf)
    F[:, 17] = np.clip(buf, 0, 30, out=buf)
    return dh.take(finv)


def _density_column(F: np.ndarray, dh: np.ndarray) -> None:
    """Column 31 of ``F``: the log of each point's local spacing ``dh`` (its mean fine
    neighbour distance) relative to the cloud's median."""
    med = float(np.median(dh)) if len(dh) else 1.0
    F[:, 31] = np.clip(np.log((dh + 1e-3) / (med + 1e-3)), -3, 3)


def _relief_features(F: np.ndarray, z: np.ndarray, zmin_f: np.ndarray, zmax: np.ndarray, flat: np.ndarray,
                     cell: float, p: FeatureParams) -> None:
    """Columns 0-6 of ``F``: height above the lowest cell minimum within each of ``p.min_radii``,
    then the relief (highest minus lowest) within the smallest radius and the depth below its
    highest point; metres, capped at 60. The float64 per-point differences are made in one
    reused buffer."""
    from scipy import ndimage

    buf = np.empty(len(z))
    size = 2 * int(round(p.min_radii[0] / cell)) + 1
    m0 = None  # the smallest radius's minimum grid, used again for the relief
    for t, rad in enumerate(p.min_radii):
        m = ndimage.minimum_filter(zmin_f, size=2 * int(round(rad / cell)) + 1, mode="nearest")
        m0 = m if t == 0 else m0
        np.take(m.ravel(), flat, out=buf)
        np.subtract(z, buf, out=buf)
        F[:, t] = np.minimum(buf, 60.0, out=buf)
    mx = np.take(ndimage.maximum_filter(zmax, size=size, mode="nearest").ravel(), flat)
    np.take(m0.ravel(), flat, out=buf)
    np.subtract(mx, buf, out=buf)
    F[:, 5] = np.minimum(buf, 60.0, out=buf)
    np.subtract(mx, z, out=buf)
    F[:, 6] = np.minimum(buf, 60.0, out=buf)


def _ground_features(F: np.ndarray, xyz: np.ndarray, zmin: np.ndarray, zmin_f: np.ndarray, rc, cell: float,
                     p: FeatureParams) -> None:
    """Columns 7-9 of ``F``: heights above a provisional ground at two tolerances (the second
    with a smaller window and twice the slope; one opening sequence serves both, as the
    openings do not depend on the tolerance), and the slope of the first ground, capped at 3."""
    from workstation.ground.common import gradient

    r, c, shape = rc
    z = xyz[:, 2]
    windows = (p.ground_window, p.ground_window * 0.4)
    steps = opening_steps(zmin_f, cell, windows)
    g = provisional_ground(xyz, cell, windows[0], p.ground_slope, zmin=zmin, rc=(r, c, shape),
                           trend_slope=p.ground_trend_slope, trend_window=p.trend_window, steps=steps[0])
    F[:, 7] = _height_above(z, grid_bilinear(g, xyz[:, :2], cell))
    g2 = provisional_ground(xyz, cell, windows[1], p.ground_slope * 2, zmin=zmin, rc=(r, c, shape),
                            steps=steps[1])
    F[:, 8] = _height_above(z, grid_bilinear(g2, xyz[:, :2], cell))
    gy, gx = gradient(g, cell)  # 0 across a grid of one cell
    F[:, 9] = np.minimum(np.take(np.hypot(gx, gy).ravel(), r * shape[1] + c), 3.0)


def _height_above(z: np.ndarray, ground: np.ndarray) -> np.ndarray:
    """``clip(z - ground, -20, 60)`` (float64), made in ``ground``'s array."""
    np.subtract(z, ground, out=ground)
    return np.clip(ground, -20, 60, out=ground)
