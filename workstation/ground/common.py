"""What every ground filter shares: units, which points take part, and writing the classes.

Every filter works internally on **local metric coordinates**: the cloud's coordinates minus
their minimum corner, scaled to metres with the CRS's linear unit (pyproj), so parameters
given in metres mean metres in a US-survey-feet CRS too, and float precision is never lost to
large eastings/northings. Results (classes, heights) go back in the CRS's units.

Classes written: :attr:`ASPRSClass.GROUND` (2) for ground, :attr:`ASPRSClass.UNCLASSIFIED` (1)
for the rest, :attr:`ASPRSClass.LOW_POINT` (7) for the isolated low points of the low-noise
step every filter runs first (:func:`workstation.ground.noise.low_noise`, ``noise=True``),
:attr:`ASPRSClass.BRIDGE_DECK` (17) for the bridge decks every filter takes out of its ground
last (:func:`workstation.ground.bridges.bridge_decks`, ``bridges=True``). Points already in
another class (anything but 0, 1 and 2) keep it unless ``reclassify`` is set; noise (7, 18)
also stays out of the filter so one bad point cannot pull the ground down.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from functools import lru_cache
from typing import Callable

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger

log = get_logger(__name__)

#: Classes a ground filter may overwrite without ``reclassify``.
OVERWRITABLE = (int(ASPRSClass.CREATED_NEVER_CLASSIFIED), int(ASPRSClass.UNCLASSIFIED), int(ASPRSClass.GROUND))
#: Classes that never take part in filtering unless ``reclassify``.
NOISE_CLASSES = (int(ASPRSClass.LOW_POINT), int(ASPRSClass.HIGH_NOISE))


@lru_cache(maxsize=64)
def crs_unit_factors(crs: str | None) -> tuple[float, float]:
    """Metres per CRS unit, horizontally and vertically (1.0, 1.0 when the CRS is unknown).

    Examples
    --------
    >>> crs_unit_factors("EPSG:2994")[0]
    0.3048
    >>> crs_unit_factors(None)
    (1.0, 1.0)
    """
    from workstation.io.crs import crs_units

    u = crs_units(crs)  # the one unit model (GeoKey overrides are in the CRS string already)
    if u.geographic:
        raise InvalidInputError(
            f"the CRS is geographic ({u.h_name}); ground filters need a projected CRS",
            "reproject first, e.g. ws convert IN OUT --to-crs EPSG:<utm zone>", field="crs")
    return u.h, u.v


@dataclass(frozen=True)
class Prepared:
    """Points a filter works on.

    Attributes
    ----------
    xyz : (m, 3) float64
        Local metric coordinates (metres, origin at the minimum corner) of the used points.
    index : (m,) int64
        Their indices in the input cloud.
    hfac, vfac : float
        Metres per CRS unit (horizontal, vertical).
    noise : (k,) int64
        Indices in the input cloud of the low noise the noise step took out (class 7 when
        written; empty when the step is off).
    """

    xyz: np.ndarray
    index: np.ndarray
    hfac: float
    vfac: float
    origin: np.ndarray
    noise: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64))


LATTICE_M = 100.0  # metres; local planar origins are multiples of it (see prepare)


def prepare(cloud: Cloud, stage: str, reclassify: bool = False, last_returns_only: bool = False,
            min_points: int = 3, noise=None) -> Prepared:
    """Select the points a filter uses and convert them to local metres.

    Noise classes (7, 18) are left out unless ``reclassify``; with ``last_returns_only`` only
    last (and only) returns take part (where return numbers are present and valid). With
    ``noise`` (a :class:`workstation.ground.noise.LowNoiseParams`) the low-noise step runs on
    those points first and takes its low points out (``Prepared.noise``; class 7 when written).
    """
    n = cloud.n
    if n == 0:
        raise StageError(stage, "the cloud has no points", "check the input file")
    use = np.ones(n, dtype=bool)
    cls = cloud.attrs.get("classification")
    if cls is not None and not reclassify:
        use &= ~np.isin(cls, NOISE_CLASSES)
    if last_returns_only and "return_number" in cloud.attrs and "number_of_returns" in cloud.attrs:
        rn = np.asarray(cloud.attrs["return_number"])
        nr = np.asarray(cloud.attrs["number_of_returns"])
        valid = (nr > 0) & (rn > 0)
        if valid.mean() > 0.9:
            use &= ~valid | (rn >= nr)
    idx = np.flatnonzero(use)
    if idx.size < min_points:
        raise StageError(stage, f"only {idx.size} usable point(s) (of {n}); need at least {min_points}",
                         "noise-classified points are skipped; pass reclassify to use them")
    hf, vf = crs_unit_factors(cloud.crs)
    p = cloud.xyz[idx]
    origin = p.min(axis=0)
    # planar origin on a global 100 m lattice: grids whose cells divide 100 m and start at a
    # multiple of the cell (smrf_surface) then fall on the same lines whatever the extent, so a
    # tile or a chunk of a survey is filtered on the cells of the whole survey
    origin[:2] = np.floor(origin[:2] * hf / LATTICE_M) * LATTICE_M / hf
    local = (p - origin) * np.array([hf, hf, vf])
    if noise is None:
        return Prepared(local, idx, hf, vf, origin)
    from .noise import low_noise

    low = low_noise(local, noise)
    if idx.size - int(low.sum()) < min_points:
        raise StageError(stage, f"only {idx.size - int(low.sum())} usable point(s) (of {n}) after the low-noise step",
                         "turn the noise step off (--no-noise-step, noise=False)")
    if low.any():
        log.info("%s: low-noise step: %d isolated low point(s) -> class 7", stage, int(low.sum()))
    return Prepared(local[~low], idx[~low], hf, vf, origin, idx[low])


def write_classes(cloud: Cloud, prep: Prepared, ground_local: np.ndarray, stage: str, params, t0: float,
                  reclassify: bool = False, extra_attrs: dict | None = None) -> Cloud:
    """A new cloud with class 2 on ground points and 1 on the rest (existing classes kept);
    with ``params.bridges``, the bridge decks among them are class 17 and not ground.

    Parameters
    ----------
    ground_local : (m,) bool
        Ground flags of the prepared points (``prep.index``).
    """
    g = np.asarray(ground_local, dtype=bool)
    if g.shape != prep.index.shape:
        raise StageError(stage, "internal: ground mask does not match the prepared points")
    deck = np.zeros(0, np.int64)
    if getattr(params, "bridges", False) and g.any():  # every method's last step: decks out (class 17)
        from .bridges import bridge_decks

        on = bridge_decks(prep.xyz, params.bridge_params, ground=g)
        g = g & ~on
        deck = prep.index[on]
        if deck.size:
            log.info("%s: bridges: %d deck point(s) -> class 17", stage, deck.size)
    if not g.any():
        raise StageError(stage, "no ground point found",
                         "check the units and the parameters (a larger window, a larger threshold), or the noise classes")
    ground = np.zeros(cloud.n, dtype=bool)
    ground[prep.index[g]] = True
    new = np.where(ground, np.uint8(ASPRSClass.GROUND), np.uint8(ASPRSClass.UNCLASSIFIED)).astype(np.uint8)
    new[prep.noise] = np.uint8(ASPRSClass.LOW_POINT)
    new[deck] = np.uint8(ASPRSClass.BRIDGE_DECK)
    old = cloud.attrs.get("classification")
    if old is not None and not reclassify:
        keep = ~np.isin(old, OVERWRITABLE)
        new = np.where(keep, np.asarray(old, dtype=np.uint8), new)
    out = cloud.with_attrs(classification=new, **(extra_attrs or {}))
    pd = asdict(params) if hasattr(params, "__dataclass_fields__") else dict(params or {})
    log.info("%s: %d ground of %d points (%.1f %%) in %.2f s", stage, int(ground.sum()), cloud.n,
             100.0 * ground.mean(), time.perf_counter() - t0)
    return out.with_history(stage, pd, time.perf_counter() - t0)


def prepare_filter(cloud: Cloud, params, stage: str) -> Prepared:
    """The points a ground method with ``params`` (reclassify, last_returns_only, noise,
    noise_params) filters: :func:`prepare` as :func:`run_filter` calls it."""
    return prepare(cloud, stage, params.reclassify, params.last_returns_only,
                   noise=params.noise_params if params.noise else None)


def run_filter(cloud: Cloud, params, stage: str, core: Callable[[Prepared], np.ndarray]) -> Cloud:
    """The run of every ground filter: select and convert the points (:func:`prepare`, with the
    low-noise step when ``params.noise``), flag their ground with ``core``, write the classes
    (:func:`write_classes`, bridge decks out when ``params.bridges``).

    Parameters
    ----------
    params : FilterOptions
        The method's parameters (:class:`workstation.ground.options.FilterOptions` fields read
        here; the history record gets them all).
    core : callable
        ``core(prep)``: (m,) bool ground flags of the prepared points ``prep.xyz`` (local
        metres); ``prep.index`` places them in ``cloud``.
    """
    t0 = time.perf_counter()
    prep = prepare_filter(cloud, params, stage)
    return write_classes(cloud, prep, core(prep), stage, params, t0, params.reclassify)


#: The presets every method has (``ws ground --preset``).
PRESET_NAMES = ("default", "flat", "urban", "forest", "steep")


def presets(cls: type, **changes: dict) -> dict:
    """A method's presets: for each of :data:`PRESET_NAMES`, ``cls`` with the fields of
    ``changes[name]`` (its defaults for a name not given).

    Examples
    --------
    >>> from workstation.ground.smrf import SMRFParams
    >>> p = presets(SMRFParams, steep={"slope": 0.6})
    >>> list(p), p["steep"].slope, p["flat"] == SMRFParams()
    (['default', 'flat', 'urban', 'forest', 'steep'], 0.6, True)
    """
    unknown = sorted(set(changes) - set(PRESET_NAMES))
    if unknown:
        raise ValueError(f"{cls.__name__}: unknown preset(s) {', '.join(unknown)}; "
                         f"the presets are {', '.join(PRESET_NAMES)}")
    return {name: cls(**changes.get(name, {})) for name in PRESET_NAMES}


# -- grids -----------------------------------------------------------------------------------
def column_min(a: np.ndarray) -> np.ndarray:
    """``a.min(axis=0)`` of an (n, d) array, one column at a time: the same values (a minimum
    is exact), about ten times faster than numpy's axis-0 reduction of a few columns."""
    return np.array([a[:, i].min() for i in range(a.shape[1])], a.dtype)


def column_max(a: np.ndarray) -> np.ndarray:
    """``a.max(axis=0)``, one column at a time (see :func:`column_min`)."""
    return np.array([a[:, i].max() for i in range(a.shape[1])], a.dtype)


def aligned_origin(xy: np.ndarray, cell: float) -> np.ndarray:
    """The lower-left corner of the cell that holds the lowest x and y, on multiples of ``cell``:
    grids from it start with an occupied row and column, and on :func:`prepare`'s lattice
    coordinates every chunk of a survey puts its cells on the same lines."""
    return np.floor(column_min(xy) / cell) * cell


#: Bytes a filter allocates per grid cell over all its grids (a few float64 surfaces, indices).
GRID_BYTES_PER_CELL = 64


def grid_index(xy: np.ndarray, cell: float, origin=None, option: str = "--cell") -> tuple[np.ndarray, np.ndarray, tuple[int, int], np.ndarray]:
    """Cell row/column of each point on a grid of ``cell`` metres.

    The grid's size is checked first (:func:`workstation.core.budget.check_grid`, at most 100
    cells a point and half the free memory): a cell far too small for the extent is an
    :class:`InvalidInputError` naming ``option``, not a huge allocation.

    Returns
    -------
    row, col : (m,) int64
    shape : (rows, cols)
    origin : (2,) float64 (x, y of the grid's lower-left corner)
    """
    from workstation.core.budget import cells_for, check_grid

    o = column_min(xy) if origin is None else np.asarray(origin, dtype=np.float64)
    if len(xy):
        ext = column_max(xy) - o
        check_grid(cells_for(ext[1], cell), cells_for(ext[0], cell), what="the ground filter's grid", option=option,
                   cell=cell, bytes_per_cell=GRID_BYTES_PER_CELL, n_points=len(xy))
    c = np.floor((xy[:, 0] - o[0]) / cell).astype(np.int64)
    r = np.floor((xy[:, 1] - o[1]) / cell).astype(np.int64)
    shape = (int(r.max()) + 1, int(c.max()) + 1)
    return r, c, shape, o


def auto_cell(xy: np.ndarray, cell: float) -> float:
    """An internal grid's fixed ``cell`` (metres; not a user option) coarsened so its grid over
    ``xy`` (local metres) is sized by the points, not by their bounding box
    (:func:`workstation.core.budget.fit_cell`); unchanged on data of ordinary density."""
    from workstation.core.budget import fit_cell

    if len(xy) == 0:
        return cell
    lo = column_min(xy)
    ext = column_max(xy) - lo
    if fit_cell(cell, float(ext[0]), float(ext[1]), len(xy)) == cell:
        return cell
    return fit_cell(cell, float(ext[0]), float(ext[1]), len(xy), xy - lo)  # only evenly sparse points


def grid_min(z: np.ndarray, r: np.ndarray, c: np.ndarray, shape) -> tuple[np.ndarray, np.ndarray]:
    """Per-cell minimum z (NaN where empty) and the index of the lowest point (-1 where empty).

    O(m) with unbuffered ``ufunc.at`` scatters (12x faster than a lexsort on a million points);
    among equally low points of a cell the lowest index is kept.
    """
    flat = r * shape[1] + c
    size = shape[0] * shape[1]
    zmin = np.full(size, np.inf)
    np.fmin.at(zmin, flat, z)
    low = np.flatnonzero(z == zmin[flat])
    imin = np.full(size, np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(imin, flat[low], low)
    empty = np.bincount(flat, minlength=size) == 0
    zmin[empty] = np.nan
    imin[empty | (imin == np.iinfo(np.int64).max)] = -1
    return zmin.reshape(shape), imin.reshape(shape)


def lowest_per_cell(xyz: np.ndarray, cell: float, origin=None, option: str = "--cell") -> np.ndarray:
    """Indices (k,) of the lowest point of each occupied ``cell`` (grid from ``origin``, by
    default the points' minimum corner), in raster order: PTD's seeds, the riser test's TIN.
    ``option`` names ``cell`` in the error of a grid too large (:func:`grid_index`)."""
    r, c, shape, _ = grid_index(xyz[:, :2], cell, origin, option)
    _, imin = grid_min(xyz[:, 2], r, c, shape)
    return imin[imin >= 0]


def fill_nearest(grid: np.ndarray, empty: np.ndarray | None = None) -> np.ndarray:
    """Fill the ``empty`` cells (by default the NaN ones) with the value of the nearest other
    cell (Euclidean distance transform); ``grid`` itself when none is empty.

    Raises
    ------
    ValueError
        When every cell is empty (no value to fill with).
    """
    from scipy import ndimage

    mask = np.isnan(grid) if empty is None else empty
    if not mask.any():
        return grid
    if mask.all():
        raise ValueError("empty grid")
    idx = ndimage.distance_transform_edt(mask, return_distances=False, return_indices=True)
    return grid[tuple(idx)]


def fill_cut(surface: np.ndarray, cut: np.ndarray) -> np.ndarray:
    """``surface`` with its ``cut`` cells filled from the nearest kept cell and smoothed over
    3 cells, the kept cells as measured: the surface a morphological filter leaves (the point
    classifier's provisional ground, the crest step's steep surface)."""
    from scipy import ndimage

    kept = fill_nearest(surface, cut)
    return np.where(cut, ndimage.uniform_filter(kept, size=3, mode="nearest"), kept)


@lru_cache(maxsize=1)
def _blas_controller():
    """threadpoolctl's view of the loaded BLAS libraries, made once (finding them reads every
    loaded library's path, milliseconds a call); None without threadpoolctl."""
    try:
        from threadpoolctl import ThreadpoolController
    except ImportError:  # pragma: no cover - threadpoolctl comes with scikit-learn
        return None
    import scipy.linalg  # noqa: F401 - loads scipy's LAPACK before the libraries are listed

    return ThreadpoolController()


def _one_blas_thread():
    """Context limiting BLAS to one thread: find_simplex builds per-triangle transforms with
    tiny LAPACK calls, which OpenBLAS worker threads make ~100x slower on a busy machine."""
    controller = _blas_controller()
    if controller is None:  # pragma: no cover
        import contextlib

        return contextlib.nullcontext()
    return controller.limit(limits=1, user_api="blas")


def barycentric_transforms(points: np.ndarray, simplices: np.ndarray) -> np.ndarray:
    """The barycentric transforms (k, 3, 2) of the triangles ``simplices`` (k, 3) of 2-D
    ``points``, as scipy's ``Delaunay.transform`` holds them: rows 0-1 the inverse of
    ``T = [r0 - r2, r1 - r2]`` (the corners ``r`` as columns), row 2 the corner ``r2``; NaN for
    a triangle whose reciprocal condition number (1-norm) is under ``1000 · eps``, as scipy
    marks a degenerate one. The 2 x 2 inverses by the adjugate, vectorised: scipy builds them
    with three LAPACK calls per triangle, which costs more than the point location they serve.
    """
    p = points[simplices]
    r = p[:, 2]
    t00, t01 = p[:, 0, 0] - r[:, 0], p[:, 1, 0] - r[:, 0]
    t10, t11 = p[:, 0, 1] - r[:, 1], p[:, 1, 1] - r[:, 1]
    det = t00 * t11 - t01 * t10
    d = np.where(det == 0, 1.0, det)
    inv = np.stack([np.stack([t11 / d, -t01 / d], axis=1), np.stack([-t10 / d, t00 / d], axis=1)], axis=1)
    anorm = np.maximum(np.abs(t00) + np.abs(t01), np.abs(t10) + np.abs(t11))
    inorm = np.abs(inv).sum(axis=2).max(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        bad = (det == 0) | ~(1.0 / (anorm * inorm) >= 1000 * np.finfo(np.float64).eps)
    out = np.concatenate([inv, r[:, None, :]], axis=1)
    out[bad] = np.nan
    return out


def with_bulk_transforms(tri):
    """``tri`` (a scipy ``Delaunay``, returned) with the barycentric transforms its
    ``find_simplex`` walks on computed in bulk (:func:`barycentric_transforms`) instead of
    triangle by triangle as scipy builds them on first use. ``_transform`` is scipy's private
    cache of them (checked with scipy 1.17: the bulk-location test of the PTD TIN and the
    inpainting test on a curved surface fail if it is ignored or misread); it is filled only
    while empty, and a ``Delaunay`` without it is left alone."""
    if getattr(tri, "_transform", False) is None:
        tri._transform = barycentric_transforms(tri.points, tri.simplices)
    return tri


def orient2d(a: np.ndarray, b: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Twice the signed area of (a, b, q), rows of (n, 2): positive when q is left of a -> b
    (the triangle counter-clockwise)."""
    return (b[:, 0] - a[:, 0]) * (q[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (q[:, 0] - a[:, 0])


def walk_tin(xy: np.ndarray, simp: np.ndarray, nbr: np.ndarray, q: np.ndarray, start: np.ndarray,
             max_steps: int = 10000) -> np.ndarray:
    """Triangle (n,) of a TIN (vertices ``xy``, triangles ``simp``, ``nbr[t, j]`` the neighbour
    across from corner j, -1 on the hull) holding each point ``q`` (n, 2), by visibility walks
    (Devillers, Pion & Teillaud, *Walking in a triangulation*, 2002) from the triangles
    ``start``; -1 outside the hull, -2 where the walk did not end within ``max_steps``
    (degenerate input). The triangles may turn either way."""
    t = np.asarray(start, dtype=np.int64).copy()
    act = np.flatnonzero(t >= 0)
    for _ in range(max_steps):
        if act.size == 0:
            return t
        v = xy[simp[t[act]]]
        sgn = np.sign(orient2d(v[:, 0], v[:, 1], v[:, 2]))[:, None]
        qa = q[act]
        o = np.column_stack([orient2d(v[:, 1], v[:, 2], qa), orient2d(v[:, 2], v[:, 0], qa),
                             orient2d(v[:, 0], v[:, 1], qa)]) * sgn
        j = np.argmin(o, axis=1)
        out = o[np.arange(act.size), j] < 0
        t[act[out]] = nbr[t[act[out]], j[out]]
        act = act[out & (t[act] >= 0)]
    t[act] = -2
    return t


def locate(tri, q: np.ndarray) -> np.ndarray:
    """Triangle index (k,) of each point ``q`` (k, 2) in a scipy ``Delaunay``, -1 outside,
    with BLAS on one thread (see :func:`_one_blas_thread`); queries in raster order keep the
    walk from the previous query's triangle short."""
    with _one_blas_thread():
        return tri.find_simplex(q)


def tin_eval(tri, values: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Linear interpolation of vertex ``values`` over a scipy ``Delaunay`` at points ``q`` (k, 2).

    NaN outside the triangulation.
    """
    s = locate(tri, q)
    out = np.full(q.shape[0], np.nan)
    ok = s >= 0
    if ok.any():
        v = tri.simplices[s[ok]]
        a = tri.points[v[:, 0]]
        b = tri.points[v[:, 1]]
        c = tri.points[v[:, 2]]
        p = q[ok]
        # barycentric weights from signed areas (scipy's tri.transform is slow to build)
        det = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
        det = np.where(det == 0, np.finfo(np.float64).tiny, det)
        wb = ((p[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (p[:, 1] - a[:, 1])) / det
        wc = ((b[:, 0] - a[:, 0]) * (p[:, 1] - a[:, 1]) - (p[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])) / det
        out[ok] = (1.0 - wb - wc) * values[v[:, 0]] + wb * values[v[:, 1]] + wc * values[v[:, 2]]
    return out


_JITTER_PERIOD = 10  # cells; divides the offset between grids on the 100 m lattice (cells dividing 10 m)
_JITTER = np.random.default_rng(0).uniform(-1.0, 1.0, (_JITTER_PERIOD, _JITTER_PERIOD, 2))


def delaunay(pts: np.ndarray, jitter: float = 0.0, cells: np.ndarray | None = None):
    """scipy Delaunay of (k, 2) points; ``jitter`` (same unit) breaks grid degeneracy, which
    otherwise makes Qhull crawl on cell centres.

    With ``cells`` (k, 2) int (the points' cell indices on the 100 m lattice of
    :func:`prepare`) a point's jitter is a function of its cell modulo 10, not of its place in
    the array: a cell keeps its jitter whatever the grid's extent, so a chunk of a survey is
    triangulated as the whole survey is around it.

    Qhull runs with scipy's options plus ``Q5``, which skips its final check of the facets'
    outer planes (``qh_check_maxout``): a bound on the facets' thickness that nothing here
    reads, and about a tenth of a triangulation's time; the simplices, neighbours, equations,
    coplanar points and paraboloid shift and scale are those of scipy's options, bit for bit
    (all 265 triangulations of ``auto`` on the six ISPRS samples and five real tiles).
    """
    from scipy.spatial import Delaunay

    if jitter:
        if cells is None:
            u = np.random.default_rng(0).uniform(-1.0, 1.0, pts.shape)
        else:
            m = np.mod(cells, _JITTER_PERIOD)
            u = _JITTER[m[:, 0], m[:, 1]]
        pts = pts + jitter * u
    return Delaunay(pts, qhull_options=QHULL_OPTIONS)


#: scipy's Qhull options for a 2-D Delaunay triangulation ("Qbb Qc Qz Q12"; "Qt" is always
#: added) and ``Q5`` (see :func:`delaunay`)
QHULL_OPTIONS = "Qbb Qc Qz Q12 Q5"


class TinHandoff:
    """One Delaunay TIN handed from a step to a later one that may triangulate the same points.

    A step leaves its TIN with the exact array it triangulated (:meth:`put`); a later step
    asks for the TIN of its own array (:meth:`take`) and gets it only when the two arrays hold
    the same coordinates bit for bit, in the same order, and triangulates them itself
    otherwise. Qhull's output is a function of its input alone, so the TIN taken is the one
    the step would have made. The raised-patch test leaves the TIN of its last pass; when that
    pass took nothing out and its lowest ground point per cell and its local origin are the
    riser fill's (the ground reaches the cloud's lowest x and y: ISPRS samp51 and samp61,
    Topography), the riser fill takes it instead of making it again.
    """

    def __init__(self):
        self._slot: tuple[np.ndarray, object] | None = None  # (points, TIN), set and taken whole

    def put(self, pts: np.ndarray, tri) -> None:
        """Leave ``tri``, the TIN of ``pts`` (kept as given: not to be changed afterwards)."""
        self._slot = (pts, tri)

    def clear(self) -> None:
        """Drop the TIN left (before a new one is made: one at a time in memory)."""
        self._slot = None

    def take(self, pts: np.ndarray):
        """The TIN left for an array equal to ``pts`` bit for bit, else None; the slot is
        emptied either way (a TIN is large)."""
        slot, self._slot = self._slot, None
        if slot is None:
            return None
        left, tri = slot
        return tri if _same_bits(left, pts) else None


def _same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    """``a`` and ``b`` hold the same values bit for bit (shape and dtype included; -0.0 and
    0.0 differ, a NaN equals the same NaN), compared in place: float64 arrays as uint64 views,
    others as byte views of contiguous copies."""
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype == np.float64:
        return bool(np.array_equal(a.view(np.uint64), b.view(np.uint64)))
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return bool(np.array_equal(a.reshape(-1).view(np.uint8), b.reshape(-1).view(np.uint8)))


def inpaint(grid: np.ndarray, offset=(0, 0)) -> np.ndarray:
    """Fill NaN cells smoothly: linear interpolation over a Delaunay TIN of the filled cells
    that border an empty one, nearest value outside their hull (the role of SMRF's image
    inpainting). ``offset``: the (row, col) of cell (0, 0) on the lattice grid of
    :func:`prepare`, which fixes each cell's tie-breaking jitter (see :func:`delaunay`)."""
    mask = np.isnan(grid)
    if not mask.any():
        return grid
    from scipy import ndimage

    border = ~mask & ndimage.binary_dilation(mask, structure=np.ones((3, 3), bool))
    br, bc = np.nonzero(border)
    if br.size < 3:
        return fill_nearest(grid)
    # a frame one cell outside the grid, valued by the nearest filled cell, puts every query
    # inside the TIN (scipy's find_simplex falls back to brute force for points outside)
    near = fill_nearest(grid)
    rows, cols = grid.shape
    fr = np.concatenate([np.full(cols + 2, -1), np.full(cols + 2, rows), np.arange(rows), np.arange(rows)])
    fc = np.concatenate([np.arange(-1, cols + 1), np.arange(-1, cols + 1), np.full(rows, -1), np.full(rows, cols)])
    fv = near[np.clip(fr, 0, rows - 1), np.clip(fc, 0, cols - 1)]
    sr = np.concatenate([br, fr])
    sc = np.concatenate([bc, fc])
    sv = np.concatenate([grid[br, bc], fv])
    out = grid.copy()
    er, ec = np.nonzero(mask)
    try:
        tri = delaunay(np.column_stack([sr, sc]).astype(np.float64), 1e-4, np.column_stack([sr, sc]) + np.asarray(offset))
    except Exception:  # degenerate support: nearest
        return near
    # the walk's transforms, vectorised: a query (a cell centre) lies far beyond rounding
    # distance of every edge between the jittered corners, so the walk ends in the triangle
    # scipy's own transforms lead to (tin_eval weighs the corners itself)
    with_bulk_transforms(tri)
    out[er, ec] = tin_eval(tri, sv, np.column_stack([er, ec]).astype(np.float64))
    nan = np.isnan(out)
    out[nan] = near[nan]
    return out


def bilinear(grid: np.ndarray, xy: np.ndarray, cell: float, origin) -> np.ndarray:
    """Bilinear interpolation of a cell-centred grid at points (edge cells extend outward).

    Flat indices and ``take`` on the raveled grid, in-place arithmetic: 3x faster than 2-D
    fancy indexing on a million points (it runs four times per classified cloud)."""
    rows, cols = grid.shape
    fx = (xy[:, 0] - origin[0]) * (1.0 / cell) - 0.5
    fy = (xy[:, 1] - origin[1]) * (1.0 / cell) - 0.5
    np.clip(fx, 0, cols - 1, out=fx)
    np.clip(fy, 0, rows - 1, out=fy)
    c0 = np.minimum(fx.astype(np.int64), max(cols - 2, 0))  # fx >= 0: truncation is floor
    r0 = np.minimum(fy.astype(np.int64), max(rows - 2, 0))
    fx -= c0
    fy -= r0
    g = grid.ravel()
    i = r0 * cols + c0
    dc = 1 if cols > 1 else 0
    dr = cols if rows > 1 else 0
    a = np.asarray(g.take(i), dtype=np.float64)  # (no copy for a float64 grid)
    a += fx * (g.take(i + dc) - a)
    c = np.asarray(g.take(i + dr), dtype=np.float64)
    c += fx * (g.take(i + dr + dc) - c)
    a += fy * (c - a)
    return a


def gradient(z: np.ndarray, cell: float) -> tuple[np.ndarray, np.ndarray]:
    """``np.gradient`` (dz/drow, dz/dcol) of a grid, 0 along an axis of a single cell (a cloud
    on one line of cells has no slope across it), where numpy would raise."""
    gy = np.gradient(z, cell, axis=0) if z.shape[0] > 1 else np.zeros(z.shape)
    gx = np.gradient(z, cell, axis=1) if z.shape[1] > 1 else np.zeros(z.shape)
    return gy, gx


def trend_tolerance(z: np.ndarray, cell: float, slope: float, factor: float, window: float) -> np.ndarray:
    """Per-cell slope tolerance of a slope-adaptive morphological object test:
    ``max(slope, factor · s)``, ``s`` the box mean over ``window`` (m) of the slope magnitude
    |∇z| of a filled (no NaN) ground surface ``z`` (rows, cols) on ``cell``-metre cells. The
    magnitude is averaged, not the surface, so the two flanks of a ridge do not cancel."""
    from scipy.ndimage import uniform_filter

    gy, gx = gradient(z, cell)
    width = max(3, int(round(window / cell)) | 1)
    return np.maximum(slope, factor * uniform_filter(np.hypot(gx, gy), width, mode="nearest"))


def tin_interpolate(xy_known: np.ndarray, z_known: np.ndarray, xy_query: np.ndarray) -> np.ndarray:
    """Linear interpolation on a Delaunay TIN of (k, 2) points; nearest known value outside the hull."""
    from scipy.spatial import cKDTree

    out = np.full(xy_query.shape[0], np.nan)
    if xy_known.shape[0] >= 3:
        # four far corners (value NaN) keep every query inside the TIN, so find_simplex never
        # falls back to brute force; queries in triangles touching them become nearest below
        lo = np.minimum(xy_known.min(axis=0), xy_query.min(axis=0))
        hi = np.maximum(xy_known.max(axis=0), xy_query.max(axis=0))
        span = float(np.max(hi - lo)) + 1.0
        corners = np.array([[lo[0] - span, lo[1] - span], [hi[0] + span, lo[1] - span],
                            [hi[0] + span, hi[1] + span], [lo[0] - span, hi[1] + span]])
        try:
            tri = delaunay(np.vstack([xy_known, corners]))
            out = tin_eval(tri, np.concatenate([z_known, np.full(4, np.nan)]), xy_query)
        except Exception:  # collinear support
            pass
    bad = np.isnan(out)
    if bad.any():
        _, j = cKDTree(xy_known).query(xy_query[bad])
        out[bad] = z_known[j]
    return out


# -- grey morphology with diamond (L1) structuring elements -----------------------------------
def _cross_step(a: np.ndarray, op, fill: float) -> np.ndarray:
    """One erosion/dilation with the 3x3 cross (a diamond of radius 1 cell)."""
    p = np.pad(a, 1, mode="constant", constant_values=fill)
    out = op(p[1:-1, 1:-1], p[:-2, 1:-1])
    op(out, p[2:, 1:-1], out=out)
    op(out, p[1:-1, :-2], out=out)
    op(out, p[1:-1, 2:], out=out)
    return out


def erode_diamond(a: np.ndarray, radius: int) -> np.ndarray:
    """Grey erosion by a diamond of ``radius`` cells (``radius`` cross erosions)."""
    for _ in range(int(radius)):
        a = _cross_step(a, np.minimum, np.inf)
    return a


def dilate_diamond(a: np.ndarray, radius: int) -> np.ndarray:
    """Grey dilation by a diamond of ``radius`` cells (``radius`` cross dilations)."""
    for _ in range(int(radius)):
        a = _cross_step(a, np.maximum, -np.inf)
    return a


def disk(radius: int) -> np.ndarray:
    """Boolean disk footprint of ``radius`` cells (x² + y² ≤ r²); the 3x3 square for radius 1."""
    r = int(radius)
    if r <= 1:
        return np.ones((3, 3), dtype=bool)
    y, x = np.mgrid[-r : r + 1, -r : r + 1]
    return x * x + y * y <= r * r


def _grow_chord(chord: np.ndarray, spare: np.ndarray, a: np.ndarray, w: int, target: int, op) -> tuple:
    """The running minimum (maximum: ``op``) of each row of ``a`` over a chord of half-width
    ``w`` (``chord``; edges extend outward), grown to half-width ``target``: returns the chord
    array (``chord`` or ``spare``, the other being free), the other array and ``target``.

    One cell at a time, the chord takes in ``a`` ``w`` cells away on either side; a jump of
    ``s = target - w ≥ 2`` cells with ``2 w ≥ target`` takes the chord ``s`` cells away on either
    side instead, whose windows with the chord's own cover the wider one (at a row's ends too).
    Both cost two minima (maxima) per row, and minima and maxima are exact, so any covering of
    the window gives the same values."""
    m = a.shape[1]
    while w < target:
        s = target - w
        if s >= 2 and 2 * w >= target:
            if s < m:
                op(chord[:, : m - s], chord[:, s:], out=spare[:, : m - s])
                spare[:, m - s :] = chord[:, m - s :]
                op(spare[:, s:], chord[:, : m - s], out=spare[:, s:])
                chord, spare = spare, chord
            w = target
        else:
            w += 1
            if w < m:
                op(chord[:, : m - w], a[:, w:], out=chord[:, : m - w])
                op(chord[:, w:], a[:, : m - w], out=chord[:, w:])
    return chord, spare, w


def _disk_filter(a: np.ndarray, radius: int, erode: bool) -> np.ndarray:
    """Grey erosion/dilation by :func:`disk` as a union of its rows (edges extend outward).

    The running minimum (maximum) of each row over a chord of the row offset's half-width is
    grown from the narrowest to the widest (:func:`_grow_chord`), and each is taken into the
    result, shifted by its row offset, as soon as it has its width: one in-place minimum
    (maximum) per row of the disk and two minima (maxima) per growth step (one cell, or a jump
once the chord is at least half the target), O(cells · radius).
    Minima and maxima are exact, so the result does not depend on the order they are taken in.
    ``a`` holds no NaN (a NaN spreads over its whole footprint): mark empty cells with ±inf.
    """
    fp = disk(radius)
    r = fp.shape[0] // 2
    op = np.minimum if erode else np.maximum
    halfw = fp.sum(axis=1) // 2  # chord half-width per row offset
    n = a.shape[0]
    out = np.full(a.shape, np.inf if erode else -np.inf)
    chord, spare = a.copy(), np.empty_like(a)
    w = 0
    for k in np.argsort(halfw, kind="stable"):  # row offsets, narrowest chord first
        chord, spare, w = _grow_chord(chord, spare, a, w, int(halfw[k]), op)
        dy = int(k) - r
        # out[i] = op(out[i], chord[i + dy]) where i + dy is inside the grid
        lo, hi = max(0, -dy), min(n, n - dy)
        if lo < hi:
            op(out[lo:hi], chord[lo + dy : hi + dy], out=out[lo:hi])
    return out


def open_square(a: np.ndarray, radius: int) -> np.ndarray:
    """Grey opening by a square of side ``2 * radius + 1`` cells (edges extend outward)."""
    from scipy import ndimage

    size = 2 * radius + 1
    return ndimage.grey_opening(a, size=(size, size), mode="nearest")


def opening_steps(surface: np.ndarray, cell: float, windows, opening=None) -> list[np.ndarray]:
    """The steepest step of a progressive opening (Zhang et al. 2003; SMRF), per cell.

    Openings of ``surface`` with radii 1, 2, ... cells, each opening the previous one; for
    each window (m) the grid of ``max over radii r ≤ ceil(window / cell)`` of
    ``(opening_{r-1} - opening_r) / (cell · r)``. One step lowers a cell by more than
    ``slope · cell · r`` exactly where this exceeds ``slope``: the openings do not depend on the
    slope, so one sequence serves every tolerance (scalar or per cell) and every window up to
    the largest.

    Parameters
    ----------
    surface : (rows, cols) float64, no NaN
    cell : float
        Cell size, metres.
    windows : sequence of float
        Largest radius of each result, metres.
    opening : callable, optional
        ``opening(grid, radius)``: :func:`open_disk` (default, SMRF) or :func:`open_square`.

    Returns
    -------
    list of (rows, cols) float64, one per window
    """
    opening = opening or open_disk
    # a disk reaching every cell opens the grid to its minimum, and later steps are 0: radii
    # beyond the grid's diagonal change nothing, so they are clamped to it (a window of 1e9 m
    # costs as much as one the size of the data)
    reach = int(np.ceil(np.hypot(*surface.shape))) + 1
    if max(windows) / cell > reach:
        log.info("window of %g m reaches beyond the %d x %d-cell grid: clamped to %g m",
                 max(windows), *surface.shape, reach * cell)
    radii = [max(1, int(np.ceil(min(w / cell, reach)))) for w in windows]
    steepest = np.zeros(surface.shape)
    step = np.empty(surface.shape)
    out: dict[int, np.ndarray] = {}
    last = surface
    for r in range(1, max(radii) + 1):
        opened = opening(last, r)
        np.subtract(last, opened, out=step)
        step /= cell * r
        np.maximum(steepest, step, out=steepest)
        last = opened
        if r in radii:
            out[r] = steepest.copy()
    return [out[r] for r in radii]


def open_disk(a: np.ndarray, radius: int) -> np.ndarray:
    """Grey opening (erosion then dilation) by a disk of ``radius`` cells."""
    return _disk_filter(_disk_filter(a, radius, True), radius, False)
