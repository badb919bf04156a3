"""Write small multi-level COPC files for tests and benchmarks with copc-lib (a test
dependency: laspy reads COPC but does not write it).

Levels are made as an octree level-of-detail builder does: at level ``l`` every voxel of side
``2 * halfsize / 2**l / GRID`` that still holds unassigned points gives one of them (the first)
to that level, and the last level takes all that remain. So every node holding points has a
parent holding points, as COPC readers expect, and the root spacing is ``2 * halfsize / GRID``.
"""

from __future__ import annotations

import numpy as np

GRID = 8  # voxels per node side


def _records(xyz, offsets, scale, classification, intensity, gps_time):
    """laspy PDRF 6 records of the points (one return each)."""
    import laspy

    las = laspy.LasData(laspy.LasHeader(point_format=6, version="1.4"))
    las.header.offsets, las.header.scales = offsets, [scale] * 3
    las.x, las.y, las.z = xyz.T
    las.classification = classification
    las.intensity = intensity
    las.gps_time = gps_time
    las.return_number = np.ones(len(xyz), np.uint8)
    las.number_of_returns = np.ones(len(xyz), np.uint8)
    return las.points.array


def assign_levels(xyz, lo_corner, halfsize, max_levels: int = 8) -> np.ndarray:
    """The octree level of each point (see the module docstring)."""
    level = np.full(len(xyz), -1, np.int32)
    for lev in range(max_levels):
        todo = np.flatnonzero(level < 0)
        if lev == max_levels - 1 or len(todo) == 0:
            level[todo] = lev
            break
        cell = 2 * halfsize / 2**lev / GRID
        v = np.floor((xyz[todo] - lo_corner) / cell).astype(np.int64)
        key = (v[:, 0] * (1 << 21) + v[:, 1]) * (1 << 21) + v[:, 2]
        _, first = np.unique(key, return_index=True)
        level[todo[first]] = lev
    return level


def write_copc(path, xyz, *, classification=None, intensity=None, gps_time=None, wkt="", scale=0.01,
               max_levels: int = 6) -> None:
    """Write points ``xyz`` (n, 3) as a COPC file of up to ``max_levels`` octree levels."""
    import copclib as copc

    xyz = np.asarray(xyz, dtype=np.float64)
    n = len(xyz)
    classification = np.full(n, 1, np.uint8) if classification is None else classification
    intensity = np.zeros(n, np.uint16) if intensity is None else intensity
    gps_time = np.arange(n, dtype=np.float64) if gps_time is None else gps_time
    lo, hi = xyz.min(0), xyz.max(0)
    offsets = np.floor(lo)
    rec = _records(xyz, offsets, scale, classification, intensity, gps_time)
    centre, half = (lo + hi) / 2, float((hi - lo).max() / 2) + 1.0
    cfg = copc.CopcConfigWriter(6, copc.Vector3(scale, scale, scale), copc.Vector3(*offsets), wkt)
    cfg.las_header.min, cfg.las_header.max = copc.Vector3(*lo), copc.Vector3(*hi)
    info = cfg.copc_info
    info.center_x, info.center_y, info.center_z = centre
    info.halfsize, info.spacing = half, 2 * half / GRID
    w = copc.FileWriter(str(path), cfg)
    level = assign_levels(xyz, centre - half, half, max_levels)
    for lev in range(int(level.max()) + 1):
        idx = np.flatnonzero(level == lev)
        cell = np.clip(np.floor((xyz[idx] - (centre - half)) / (2 * half / 2**lev)).astype(np.int64), 0, 2**lev - 1)
        key = (cell[:, 0] * (1 << 21) + cell[:, 1]) * (1 << 21) + cell[:, 2]
        order = np.argsort(key, kind="stable")
        starts = np.flatnonzero(np.r_[True, np.diff(key[order]) != 0])
        for part in np.split(idx[order], starts[1:]):
            i, j, k = cell[np.searchsorted(idx, part[0])]
            w.AddNode(copc.VoxelKey(lev, int(i), int(j), int(k)),
                      copc.VectorChar(np.frombuffer(rec[part].tobytes(), np.int8)))
    w.Close()
