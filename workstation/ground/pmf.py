"""PMF, the progressive morphological filter (Zhang et al. 2003).

Zhang K., Chen S.-C., Whitman D., Shyu M.-L., Yan J., Zhang C. (2003) "A progressive
morphological filter for removing nonground measurements from airborne LIDAR data",
IEEE Trans. Geosci. Remote Sens. 41(4):872-882.

Low noise is set aside first by the low-noise step of every filter
(:func:`workstation.ground.noise.low_noise`, ``noise=True``). On the
minimum-height grid (empty cells filled with the nearest value), openings with square
windows of growing size ``w_k = 2·b^k + 1`` cells (exponential growth, ``b = 2``) up to
``max_window`` are applied to the previous opened surface; at each step the height threshold
is ``dh_k = slope · (w_k - w_{k-1}) · cell + initial_distance`` capped at ``max_distance``
(PCL/PDAL's form), and a point whose height is more than ``dh_k`` above the opened surface at
its cell is non-ground. Square openings are separable running minima/maxima (scipy.ndimage).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .options import FilterOptions

STAGE = "ground.pmf"


@dataclass(frozen=True)
class PMFParams(FilterOptions):
    """PMF parameters (PDAL's ``filters.pmf`` defaults but a 1 m cell) and the options of every
    filter (:class:`~workstation.ground.options.FilterOptions`). Lengths in metres.

    Attributes
    ----------
    cell : float
        Grid cell, metres (1.0).
    max_window : float
        Largest window size, metres (33.0).
    slope : float
        Terrain slope, rise over run (1.0).
    initial_distance : float
        Height threshold of the first window, metres (0.15).
    max_distance : float
        Largest height threshold, metres (2.5).
    exponential : bool
        Window sizes 2·2^k + 1 cells (True) or 2k + 1 (False).
    """

    cell: float = 1.0
    max_window: float = 33.0
    slope: float = 1.0
    initial_distance: float = 0.15
    max_distance: float = 2.5
    exponential: bool = True


PRESETS: dict[str, PMFParams] = common.presets(
    PMFParams, flat={"slope": 0.3, "max_distance": 2.0}, urban={"slope": 0.3, "max_window": 49.0, "max_distance": 2.0},
    forest={"slope": 1.0, "max_window": 17.0}, steep={"slope": 2.0, "max_window": 17.0, "max_distance": 4.0})


def _windows(p: PMFParams, shape=None) -> list[int]:
    """Window sizes (cells) of the progressive opening up to ``max_window``.

    With the grid ``shape``, the list stops at the first window that spans the whole grid: it
    opens the surface to its minimum, so every later window finds the same surface with a
    height threshold at least as large and changes no class (a ``max_window`` of 1e9 m costs
    as much as one the size of the data).
    """
    maxw = max(3, int(np.ceil(min(p.max_window / p.cell, 1e15))))  # (an int even for max_window = inf)
    span = 2 * max(shape) + 1 if shape is not None else None
    out = []
    k = 0
    while True:
        w = 2 * (2 ** k) + 1 if p.exponential else 2 * (k + 1) + 1
        if w > maxw:
            break
        out.append(w)
        if span is not None and w >= span:
            break
        k += 1
    return out or [3]


def pmf_ground(xyz: np.ndarray, p: PMFParams) -> np.ndarray:
    """Ground flags (m,) bool of local metric points by PMF."""
    from scipy import ndimage

    r, c, shape, _ = common.grid_index(xyz[:, :2], p.cell, common.aligned_origin(xyz[:, :2], p.cell))
    zmin, _ = common.grid_min(xyz[:, 2], r, c, shape)
    surf = common.fill_nearest(zmin)
    ground = np.ones(xyz.shape[0], dtype=bool)
    z = xyz[:, 2]
    prev_w = 1
    for w in _windows(p, shape):
        opened = ndimage.grey_opening(surf, size=(w, w), mode="nearest")
        dh = p.initial_distance if prev_w == 1 else min(p.slope * (w - prev_w) * p.cell + p.initial_distance, p.max_distance)
        ground &= (z - opened[r, c]) <= dh
        surf = opened
        prev_w = w
    return ground


def pmf(cloud: Cloud, params: PMFParams | None = None, **overrides) -> Cloud:
    """Classify ground with the progressive morphological filter (Zhang et al. 2003).

    Returns
    -------
    Cloud
        ``classification`` 2 on ground, 1 elsewhere (other classes kept unless ``reclassify``).
    """
    p = replace(params or PMFParams(), **overrides)
    return common.run_filter(cloud, p, STAGE, lambda prep: pmf_ground(prep.xyz, p))
