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

import time
from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .bridges import BridgeParams
from .noise import LowNoiseParams

STAGE_LOWEST = "ground.lowest"
STAGE_LOCALMIN = "ground.local_min"


@dataclass(frozen=True)
class LowestParams:
    """Lowest point per cell. Lengths in metres.

    Attributes
    ----------
    cell : float
        Cell size, metres (5.0).
    threshold : float
        Height above the cell's lowest point still counted as ground, metres (0.3).
    reclassify, last_returns_only, noise, noise_params, bridges, bridge_params
        See :class:`workstation.ground.smrf.SMRFParams`.
    """

    cell: float = 5.0
    threshold: float = 0.3
    reclassify: bool = False
    last_returns_only: bool = True
    noise: bool = True
    noise_params: LowNoiseParams = field(default_factory=LowNoiseParams)
    bridges: bool = True
    bridge_params: BridgeParams = field(default_factory=BridgeParams)


@dataclass(frozen=True)
class LocalMinParams:
    """Local minimum with a slope threshold (Vosselman 2000). Lengths in metres.

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
    reclassify, last_returns_only, noise, noise_params, bridges, bridge_params
        See :class:`workstation.ground.smrf.SMRFParams`.
    """

    cell: float = 1.0
    radius: float = 15.0
    slope: float = 0.3
    threshold: float = 0.5
    reclassify: bool = False
    last_returns_only: bool = True
    noise: bool = True
    noise_params: LowNoiseParams = field(default_factory=LowNoiseParams)
    bridges: bool = True
    bridge_params: BridgeParams = field(default_factory=BridgeParams)


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
    t0 = time.perf_counter()
    prep = common.prepare(cloud, STAGE_LOWEST, p.reclassify, p.last_returns_only,
                          noise=p.noise_params if p.noise else None)
    return common.write_classes(cloud, prep, lowest_ground(prep.xyz, p), STAGE_LOWEST, p, t0, p.reclassify)


def local_min(cloud: Cloud, params: LocalMinParams | None = None, **overrides) -> Cloud:
    """Classify ground by the local minimum with a slope threshold (Vosselman 2000)."""
    p = replace(params or LocalMinParams(), **overrides)
    t0 = time.perf_counter()
    prep = common.prepare(cloud, STAGE_LOCALMIN, p.reclassify, p.last_returns_only,
                          noise=p.noise_params if p.noise else None)
    return common.write_classes(cloud, prep, local_min_ground(prep.xyz, p), STAGE_LOCALMIN, p, t0, p.reclassify)
