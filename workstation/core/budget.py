"""Size checks run before a grid or array is allocated from a data extent and a user's cell.

A cell size that is valid on its own (``--cell 0.001``) can still ask for an impossible grid
over a large extent (1e12 m coordinates at 1 m cells: petabytes). :func:`check_grid` compares
the cells a grid would need with a bound and raises :class:`InvalidInputError` naming the
option, the size it would need and a value that would fit, before anything is allocated.

Two bounds, both from the machine or the data rather than tuned constants:

* memory: the grid's bytes may use at most :data:`MEMORY_FRACTION` of the memory available
  now (``psutil``; ``os.sysconf`` as a fallback);
* points (optional): a grid filled from ``n`` points needs at most :data:`CELLS_PER_POINT`
  cells per point (at least :data:`MIN_CELLS`) - finer cells are empty and only cost time.
"""

from __future__ import annotations

import math
import os

from .errors import InvalidInputError

#: Share of the available memory one grid may take.
MEMORY_FRACTION = 0.5
#: Point-driven grids: at most this many cells per point ...
CELLS_PER_POINT = 100
#: ... but a grid of this many cells is always allowed (a few MB).
MIN_CELLS = 1 << 22


def available_memory() -> int:
    """Bytes of memory available now (psutil), else physical pages (sysconf), else 4 GiB."""
    try:
        import psutil

        return int(psutil.virtual_memory().available)
    except Exception:  # psutil missing or unsupported platform
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return 4 << 30


def _bytes(n: float) -> str:
    """``n`` bytes in words (binary units)."""
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"):
        if n < 1024 or unit == "EiB":
            return f"{n:.3g} {unit}"
        n /= 1024.0
    return f"{n:.3g} EiB"  # pragma: no cover


def cells_for(extent: float, cell: float) -> float:
    """Cells along one axis to cover ``extent`` with ``cell`` (a float: never overflows)."""
    if not (cell > 0 and math.isfinite(cell)):
        return math.inf
    return math.floor(max(float(extent), 0.0) / cell) + 1.0


def max_cells(bytes_per_cell: float = 8.0, n_points: int | None = None) -> float:
    """The largest grid allowed by the memory bound and (with ``n_points``) the point bound."""
    limit = MEMORY_FRACTION * available_memory() / max(float(bytes_per_cell), 1.0)
    if n_points is not None:
        limit = min(limit, max(CELLS_PER_POINT * float(n_points), float(MIN_CELLS)))
    return limit


def check_grid(rows: float, cols: float, *, what: str, option: str, cell: float | None = None,
               bytes_per_cell: float = 8.0, n_points: int | None = None, unit: str = "m", path=None) -> None:
    """Refuse a grid of ``rows`` × ``cols`` cells larger than :func:`max_cells`.

    Parameters
    ----------
    rows, cols : float
        Grid size in cells (floats, so a huge extent cannot overflow).
    what : str
        The grid, in words ("SMRF ground grid").
    option : str
        The option the user can change (``--cell``): named in the message and as ``field``.
    cell : float, optional
        The cell size used; gives the hint a cell size that would fit.
    bytes_per_cell : float
        Bytes allocated per cell by the step (all its grids together).
    n_points : int, optional
        Points that fill the grid: bounds it to :data:`CELLS_PER_POINT` cells a point.
    path : str, optional
        The input file(s), named in the message.

    Raises
    ------
    InvalidInputError
        The grid is too large; nothing was allocated.

    Examples
    --------
    >>> check_grid(100, 100, what="test grid", option="--cell")
    >>> check_grid(1e12, 1e12, what="test grid", option="--cell", cell=1.0)
    Traceback (most recent call last):
    ...
    workstation.core.errors.InvalidInputError: field '--cell': test grid would need 1e+12 x 1e+12 cells (...
    """
    cells = float(rows) * float(cols)
    limit = max_cells(bytes_per_cell, n_points)
    if math.isfinite(cells) and cells <= limit:
        return
    by = "memory" if n_points is None or limit < CELLS_PER_POINT * n_points else f"{n_points} points"
    msg = (f"{what} would need {float(rows):.3g} x {float(cols):.3g} cells ({_bytes(cells * bytes_per_cell)}); "
           f"at most {limit:.3g} cells fit ({by})")
    hint = f"use a larger {option}"
    if cell is not None and math.isfinite(cells):
        hint += f", e.g. {option} {_round_up(cell * math.sqrt(cells / limit) * 1.01)} {unit}"
    hint += ", or split the input"
    raise InvalidInputError(msg, hint, path=path, field=option)


def _round_up(x: float) -> str:
    """``x`` rounded up to two significant digits, as text."""
    if not (x > 0 and math.isfinite(x)):
        return f"{x:g}"
    e = math.floor(math.log10(x)) - 1
    return f"{math.ceil(x / 10.0 ** e) * 10.0 ** e:.3g}"


#: Automatic (default) cell sizes are coarsened until their grid has at most this many cells
#: per point ...
AUTO_CELLS_PER_POINT = 16
#: ... or this many cells in all (a default never changes on data of ordinary density).
AUTO_MIN_CELLS = 1 << 18


def fit_cell(cell: float, extent_x: float, extent_y: float, n_points: int, xy=None) -> float:
    """A default ``cell`` coarsened so its grid over the extent is sized by the points.

    A default made for dense data (a 1 m cell) on a sparse cloud spread over kilometres would
    allocate a grid of the bounding box, not of the points; the cell then grows (by a round
    factor of 2, 2.5, 5 × 10^k) until the grid has at most ``max(AUTO_CELLS_PER_POINT × n,
    AUTO_MIN_CELLS)`` cells. A cell the user chose is never changed (:func:`check_grid` refuses
    it instead, naming the option).

    With the points ``xy`` ((n, 2), the units of the extent) the cell grows only when they
    are spread evenly over their box (:func:`evenly_spread`): a dense survey with one stray
    point 100 km away keeps its cell (and is refused by :func:`check_grid`) instead of being
    filtered on a coarse grid.

    Examples
    --------
    >>> fit_cell(1.0, 100.0, 100.0, 10_000)          # ordinary data: unchanged
    1.0
    >>> fit_cell(1.0, 5000.0, 5000.0, 6000)          # 6,000 points over 5 km x 5 km
    10.0
    """
    limit = max(AUTO_CELLS_PER_POINT * float(n_points), float(AUTO_MIN_CELLS))
    cells = cells_for(extent_x, cell) * cells_for(extent_y, cell)
    if not (cell > 0) or cells <= limit or (xy is not None and not evenly_spread(xy, extent_x, extent_y)):
        return cell
    for factor in _nice_factors(math.sqrt(cells / limit)):
        c = cell * factor
        if cells_for(extent_x, c) * cells_for(extent_y, c) <= limit:
            return c
    return cell * math.sqrt(cells / limit) * 2.0  # pragma: no cover - the loop always finds one


def _nice_factors(start: float):
    """1, 2, 2.5, 5 × 10^k factors from the one at or below ``start`` upwards."""
    e = math.floor(math.log10(max(start, 1.0)))
    while True:
        for m in (1.0, 2.0, 2.5, 5.0):
            if m * 10.0 ** e >= start * 0.999:
                yield m * 10.0 ** e
        e += 1


#: Share of the cells of the mean point spacing that must hold a point for a cloud to count as
#: evenly spread (1 - 1/e = 0.63 for uniform random points; a stray point makes it ~0).
EVEN_SHARE = 1.0 / 3.0


def evenly_spread(xy, extent_x: float, extent_y: float) -> bool:
    """True when points ``xy`` (n, 2) fill their box: at least :data:`EVEN_SHARE` of the
    cells of the mean spacing ``sqrt(area / n)`` hold a point.

    Examples
    --------
    >>> import numpy as np
    >>> xy = np.random.default_rng(0).uniform(0, 5000, (6000, 2))
    >>> evenly_spread(xy, 5000, 5000), evenly_spread(np.vstack([xy[:5999] / 100, [[5000, 5000]]]), 5000, 5000)
    (True, False)
    """
    import numpy as np

    xy = np.asarray(xy, dtype=np.float64)
    n = len(xy)
    area = float(extent_x) * float(extent_y)
    if n == 0 or not (area > 0 and math.isfinite(area)):
        return False
    s = math.sqrt(area / n)
    ij = np.floor((xy - xy.min(axis=0)) / s).astype(np.int64)
    occupied = len(np.unique(ij[:, 0] * (int(cells_for(extent_y, s)) + 1) + ij[:, 1]))
    return occupied >= EVEN_SHARE * cells_for(extent_x, s) * cells_for(extent_y, s)
