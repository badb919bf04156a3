"""Small simulated ALS scenes for the ground-filter failure gallery (tests/ground/test_ground_gallery.py).

Pulse-level models in numpy, fast enough for a test (a second each), deterministic per seed:

* :func:`dense_canopy`: a closed conifer canopy 15-30 m tall over hilly terrain; each pulse gives
  one to four echoes and its last echo reaches the ground for only ``penetration`` of the
  pulses (5 %: about 0.2 ground points/m² at 4 pulses/m², the regime of a dense conifer plot);
  the other last echoes stop in the crowns, on stems or in the understorey.
* :func:`low_outliers`: open terrain with two buildings and a few trees, plus ``rate`` (0.1 %)
  of the points repeated 1-100 m under the terrain at their place (multipath, the ghost echoes
  of national tiles).

Both return a :class:`workstation.core.cloud.Cloud` (return numbers set) and the true terrain
height function ``terrain(xy) -> z``.
"""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud

ORIGIN = np.array([500000.0, 4_000_000.0, 300.0])


def hills(xy: np.ndarray, relief: float = 6.0, slope: float = 0.08) -> np.ndarray:
    """Terrain height (m, local) of a tilted, undulating surface: a mean slope plus two waves."""
    x, y = xy[:, 0], xy[:, 1]
    return slope * x + relief * 0.5 * (np.sin(x / 17.0) * np.cos(y / 23.0) + 0.5 * np.sin((x + y) / 11.0))


def _cloud(xyz: np.ndarray, rn: np.ndarray, nr: np.ndarray) -> Cloud:
    return Cloud(xyz + ORIGIN, {"return_number": rn.astype(np.uint8), "number_of_returns": nr.astype(np.uint8),
                                "classification": np.ones(len(xyz), np.uint8)})


def terrain_fn(relief: float = 6.0, slope: float = 0.08):
    """``terrain(xy)`` in the cloud's coordinates (absolute x, y -> absolute z)."""
    return lambda xy: hills(np.asarray(xy, float) - ORIGIN[:2], relief, slope) + ORIGIN[2]


def dense_canopy(seed: int = 0, size: float = 80.0, pulses: float = 4.0, penetration: float = 0.05,
                 understorey: float = 0.10):
    """A closed canopy over hills; ``penetration`` of the pulses end on the ground.

    Returns
    -------
    cloud : Cloud
    terrain : callable (k, 2) -> (k,), the true ground height
    is_ground : (n,) bool, the echoes from the terrain
    """
    rng = np.random.default_rng(seed)
    n = int(size * size * pulses)
    xy = rng.uniform(0, size, (n, 2))
    zg = hills(xy)
    # crowns: cones on a jittered 4 m lattice, tops 15-30 m; canopy top height at each pulse
    g = np.arange(2.0, size, 4.0)
    tx, ty = np.meshgrid(g, g)
    tops = np.column_stack([tx.ravel(), ty.ravel()]) + rng.uniform(-1.0, 1.0, (tx.size, 2))
    th = rng.uniform(15.0, 30.0, len(tops))
    from scipy.spatial import cKDTree

    d, j = cKDTree(tops).query(xy, k=3)
    canopy = np.max(th[j] - 2.5 * d, axis=1)  # conical crowns, 2.5 m down per metre out
    canopy = np.maximum(canopy, 8.0)  # crowns meet: no gap lower than 8 m
    base = 3.0  # crown base height
    n_ret = rng.integers(1, 5, n)  # echoes per pulse
    fate = rng.uniform(size=n)
    to_ground = fate < penetration
    to_under = (fate >= penetration) & (fate < penetration + understorey)
    pts, rns, nrs, gnd = [], [], [], []
    for k in range(1, 5):
        sel = n_ret >= k
        last = n_ret == k
        # echo k of the pulse: down the crown, from its top to its base
        frac = (k - 1) / 4.0 + rng.uniform(0, 0.25, n)
        h = canopy - frac * (canopy - base)
        h = np.where(last & to_ground, 0.0, h)
        h = np.where(last & to_under, rng.uniform(0.3, 2.0, n), h)
        h = np.where(last & ~to_ground & ~to_under, np.maximum(h, base + rng.uniform(0, 3.0, n)), h)
        z = zg + h + rng.normal(0, 0.03, n)
        pts.append(np.column_stack([xy[sel], z[sel]]))
        rns.append(np.full(sel.sum(), k))
        nrs.append(n_ret[sel])
        gnd.append((last & to_ground)[sel])
    xyz = np.concatenate(pts)
    return _cloud(xyz, np.concatenate(rns), np.concatenate(nrs)), terrain_fn(), np.concatenate(gnd)


def low_outliers(seed: int = 0, size: float = 80.0, pulses: float = 6.0, rate: float = 0.001,
                 depth=(1.0, 100.0)):
    """Open hills with two buildings and a row of trees, and ``rate`` of the points repeated
    ``depth`` metres (uniform) under the terrain at their place.

    Returns
    -------
    cloud : Cloud
    terrain : callable
    outlier : (n,) bool, the injected low points
    """
    rng = np.random.default_rng(seed)
    n = int(size * size * pulses)
    xy = rng.uniform(0, size, (n, 2))
    zg = hills(xy)
    z = zg + rng.normal(0, 0.03, n)
    for (x0, x1), (y0, y1), h in [((10, 24), (12, 26), 7.0), ((46, 62), (40, 50), 10.0)]:
        inside = (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)
        z[inside] = hills(np.array([[x0, y0]]))[0] + h + rng.normal(0, 0.03, inside.sum())
    trees = (np.abs(xy[:, 1] - 65.0) < 4.0) & (rng.uniform(size=n) < 0.7)
    z[trees] += rng.uniform(2.0, 12.0, trees.sum())
    k = max(1, int(round(rate * n)))
    src = rng.choice(n, k, replace=False)
    oxy = xy[src] + rng.normal(0, 0.2, (k, 2))
    oz = hills(oxy) - rng.uniform(*depth, k)
    xyz = np.vstack([np.column_stack([xy, z]), np.column_stack([oxy, oz])])
    ones = np.ones(len(xyz), np.uint8)
    out = np.zeros(len(xyz), bool)
    out[n:] = True
    return _cloud(xyz, ones, ones), terrain_fn(), out
