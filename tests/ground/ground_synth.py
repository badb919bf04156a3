"""Tiny deterministic synthetic terrain with box buildings for the ground-filter tests."""

from __future__ import annotations

import numpy as np


def terrain_with_boxes(seed: int = 0, size: float = 80.0, density: float = 2.0, slope: float = 0.08):
    """Points (n, 3) and truth (n,) bool ground of a gently sloping, undulating terrain with two
    box buildings (10 x 12 m and 14 x 8 m, 6 and 9 m tall) and a low outlier.

    Returns
    -------
    xyz : (n, 3) float64, metres, around x=500000, y=4e6
    ground : (n,) bool
    """
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    zt = slope * xy[:, 0] + 0.8 * np.sin(xy[:, 1] / 9.0) + rng.normal(0, 0.03, n)
    boxes = [((15, 25), (20, 32), 6.0), ((45, 59), (50, 58), 9.0)]
    z = zt.copy()
    ground = np.ones(n, dtype=bool)
    for (x0, x1), (y0, y1), h in boxes:
        inside = (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)
        z[inside] = slope * (x0 + x1) / 2 + 0.8 * np.sin((y0 + y1) / 2 / 9.0) + h + rng.normal(0, 0.03, inside.sum())
        ground[inside] = False
    # a low outlier 30 m under the terrain
    xy = np.vstack([xy, [[40.0, 40.0]]])
    z = np.append(z, slope * 40 + 0.8 * np.sin(40 / 9.0) - 30.0)
    ground = np.append(ground, False)
    xyz = np.column_stack([xy[:, 0] + 500000.0, xy[:, 1] + 4_000_000.0, z + 100.0])
    return xyz, ground
