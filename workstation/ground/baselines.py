"""Textbook baselines for comparison: lowest point per cell, local minimum with a slope limit.

Low noise is set aside first by the low-noise step of every filter (``noise=True``).

* ``lowest``: the lowest point of every ``cell`` and every point within ``threshold`` above
  it is ground (no object removal: roofs wider than a cell stay ground);
* ``local_min``: the slope-based filter of Vosselman (2000, "Slope based filtering of laser
  altimetry data", Int. Arch. Photogramm. Remote Sens. 33(B3):935-942) on the lowest-point
  grid: a point is ground when no grid minimum within ``radius`` lies lower than
  ``z - (threshold + slope · distance)``, computed as the grey erosion of the min-grid by a
  cone (a disk erosion per distance ring).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .options import FilterOptions

STAGE_LOWEST = "ground.lowest"
STAGE_LOCALMIN = "ground.local_min"


@dataclass(frozen=True)
class LowestParams(FilterOptions):
    """Lowest point per cell, and the options of every filter
    (:class:`~workstation.ground.options.FilterOptions`). Lengths in metres.

    Attributes
    ----------
    cell : float
        Cell size, metres (5.0).
    threshold : float
        Height above the cell's lowest point still counted as ground, metres (0.3).
    """

    cell: float = 5.0
    threshold: float = 0.3


@dataclass(frozen=True)
class LocalMinParams(FilterOptions):
    """Local minimum with a slope threshold (Vosselman 2000), and the options of every filter
    (:class:`~workstation.ground.options.FilterOptions`). Lengths in metres.

    Attributes
    ----------
    cell : float
        Grid cell, metres (1.0).
    radius : float
        Neighbourhood radius, metres (15.0).
    slope : float
        Largest terrain slope, rise over run (0.3).
    threshold : float
        Height tolerance added to the slope term, metres (0.5).
    """

    cell: float = 1.0
    radius: float = 15.0
    slope: float = 0.3
    threshold: float = 0.5


LOWEST_PRESETS: dict[str, LowestParams] = common.presets(LowestParams)
LOCAL_MIN_PRESETS: dict[str, LocalMinParams] = common.presets(
    LocalMinParams, flat={"slope": 0.15}, steep={"slope": 1.0, "threshold": 1.0})


def lowest_ground(xyz: np.ndarray, p: LowestParams) -> np.ndarray:
    """Ground flags (m,) bool: within ``threshold`` of the lowest point of the cell."""
    r, c, shape, _ = common.grid_index(xyz[:, :2], p.cell, common.aligned_origin(xyz[:, :2], p.cell))
    zmin, _ = common.grid_min(xyz[:, 2], r, c, shape)
    return xyz[:, 2] - zmin[r, c] <= p.threshold


def local_min_ground(xyz: np.ndarray, p: LocalMinParams) -> np.ndarray:
    """Ground flags (m,) bool by the slope-based local minimum test on the min-grid."""
    r, c, shape, _ = common.grid_index(xyz[:, :2], p.cell, common.aligned_origin(xyz[:, :2], p.cell))
    zmin, _ = common.grid_min(xyz[:, 2], r, c, shape)
    filled = np.where(np.isnan(zmin), np.inf, zmin)
    # lowest allowed surface: min over rings k of (erosion by disk k) + slope·k·cell
    bound = filled.copy()
    rad = max(1, int(np.ceil(p.radius / p.cell)))
    for k in range(1, rad + 1):
        er = common._disk_filter(filled, k, True)
        np.minimum(bound, er + p.slope * k * p.cell, out=bound)
    return xyz[:, 2] <= bound[r, c] + p.threshold


def lowest(cloud: Cloud, params: LowestParams | None = None, **overrides) -> Cloud:
    """Classify ground as the lowest point per cell (and points just above it)."""
    p = replace(params or LowestParams(), **overrides)
    return common.run_filter(cloud, p, STAGE_LOWEST, lambda prep: lowest_ground(prep.xyz, p))


def local_min(cloud: Cloud, params: LocalMinParams | None = None, **overrides) -> Cloud:
    """Classify ground by the local minimum with a slope threshold (Vosselman 2000)."""
    p = replace(params or LocalMinParams(), **overrides)
    return common.run_filter(cloud, p, STAGE_LOCALMIN, lambda prep: local_min_ground(prep.xyz, p))
