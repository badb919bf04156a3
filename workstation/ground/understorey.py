"""Under-canopy refinement: where a canopy hides the terrain, ground is its lower envelope.

Under trees, the last returns that a ground filter accepts include understorey, litter and
low shrubs 0.1-0.5 m above the soil: a 0.5 m elevation test (SMRF's, CSF's) cannot tell them
from the terrain, and a DTM through them lies 0.2-0.3 m high (measured on the forest tiles in
``../shared/data/lidar``). Where the canopy is
open, the same test is right: the ground returns of rough terrain spread as much.

The canopy is read from the echoes: the share of the pulses in a ``canopy_cell`` (their last
returns) that had more than one echo. Where that share exceeds ``canopy_share``, the ground
points are tested twice against the ground around them:

1. *spike test* (``spike_passes`` times): a point more than ``threshold + spike_scalar ·
   slope`` above the least-squares plane through the other ground points of the 3 × 3 cells
   around it (cells of ``spike_cell`` times the mean ground spacing: about ten neighbours)
   is dropped (a leave-one-out residual, in the spirit of Axelsson 2000's iteration
   distance). The plane comes from per-cell moment sums (``bincount`` and a 3 × 3 box sum),
   O(m) with no neighbour search;
2. *envelope test*: the lowest ground point per cell of ``envelope_spacing`` times the mean
   ground spacing (at least 1 m), inpainted into a surface; a point more than ``threshold +
   envelope_scalar · slope · cell`` above it is dropped (the slope term covers a cell's lowest
   point lying downhill of the cell's centre).

Without return numbers (the ISPRS samples) the share is 0 and nothing changes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import common


@dataclass(frozen=True)
class UnderstoreyParams:
    """Parameters of the under-canopy refinement. Lengths in metres.

    Attributes
    ----------
    canopy_cell : float
        Cell (m) over which the share of multi-echo pulses is counted (5.0).
    canopy_share : float
        Cells where more than this fraction of the pulses had several echoes are under
        canopy (0.1).
    threshold : float
        Height (m) above the local ground surface beyond which a point under canopy is not
        ground (0.2).
    spike_scalar : float
        Added tolerance per unit slope of the neighbours' plane, metres (0.5).
    spike_passes : int
        Passes of the spike test (2; 0 = off).
    spike_cell : float
        Cell of the spike test's 3 × 3 neighbourhood in mean ground spacings (1.5).
    envelope_spacing : float
        Envelope cell in mean ground spacings (3.0; 0 = off).
    envelope_scalar : float
        Envelope tolerance per unit slope and metre of cell (0.7).
    """

    canopy_cell: float = 5.0
    canopy_share: float = 0.1
    threshold: float = 0.2
    spike_scalar: float = 0.5
    spike_passes: int = 2
    spike_cell: float = 1.5
    envelope_spacing: float = 3.0
    envelope_scalar: float = 0.7


def canopy_share(xy: np.ndarray, return_number: np.ndarray, number_of_returns: np.ndarray, cell: float) -> np.ndarray:
    """Share (m,) float64 of multi-echo pulses in each point's ``cell`` (pulses counted by
    their last returns; 0 where the return numbers are missing or invalid)."""
    rn = np.asarray(return_number)
    nr = np.asarray(number_of_returns)
    last = (nr > 0) & (rn >= nr)
    if not last.any():
        return np.zeros(len(xy))
    r, c, shape, _ = common.grid_index(xy, common.auto_cell(xy, cell))
    flat = r * shape[1] + c
    size = shape[0] * shape[1]
    pulses = np.bincount(flat[last], minlength=size)
    multi = np.bincount(flat[last & (nr > 1)], minlength=size)
    return (multi / np.maximum(pulses, 1))[flat]


def plane_residual(xyz: np.ndarray, cell: float, query=None) -> tuple[np.ndarray, np.ndarray]:
    """Height of each ``query`` point (indices into ``xyz``; all by default) above the
    least-squares plane through the other points of the 3 × 3 cells of ``cell`` metres
    around it, and that plane's slope magnitude; both float64, 0 where fewer than 3 other
    points or collinear ones."""
    from scipy import ndimage

    qi = np.arange(len(xyz)) if query is None else np.asarray(query)
    if len(qi) == 0:
        return np.zeros(0), np.zeros(0)
    lo = common.column_min(xyz)
    r, c, shape, _ = common.grid_index(xyz[:, :2], common.auto_cell(xyz[:, :2], cell), lo[:2])
    flat = r * shape[1] + c
    size = shape[0] * shape[1]
    x, y, z = (xyz[:, a] - lo[a] for a in range(3))
    box = np.ones((3, 3))

    def moment(w):  # sum of w over the 3 x 3 cells around each query point
        grid = np.bincount(flat, w, minlength=size).reshape(shape)
        return ndimage.convolve(grid, box, mode="constant").ravel()[flat[qi]]

    xq, yq, zq = x[qi], y[qi], z[qi]
    n = moment(None) - 1.0  # the point itself left out of every sum
    nn = np.maximum(n, 1.0)
    mx, my, mz = ((moment(v) - vq) / nn for v, vq in ((x, xq), (y, yq), (z, zq)))
    sxx = moment(x * x) - xq * xq - n * mx * mx
    syy = moment(y * y) - yq * yq - n * my * my
    sxy = moment(x * y) - xq * yq - n * mx * my
    sxz = moment(x * z) - xq * zq - n * mx * mz
    syz = moment(y * z) - yq * zq - n * my * mz
    det = sxx * syy - sxy * sxy
    ok = (n >= 3) & (det > 1e-9 * np.maximum(sxx * syy, 1e-30))
    det = np.where(ok, det, 1.0)
    gx = np.where(ok, (syy * sxz - sxy * syz) / det, 0.0)
    gy = np.where(ok, (sxx * syz - sxy * sxz) / det, 0.0)
    res = np.where(ok, zq - (mz + gx * (xq - mx) + gy * (yq - my)), 0.0)
    return res, np.hypot(gx, gy)


def envelope_height(xyz: np.ndarray, cell: float) -> tuple[np.ndarray, np.ndarray]:
    """Height of each point above the inpainted per-``cell`` minimum surface, and that
    surface's slope magnitude at the point; both (m,) float64."""
    lo = common.column_min(xyz[:, :2])
    cell = common.auto_cell(xyz[:, :2], cell)
    r, c, shape, _ = common.grid_index(xyz[:, :2], cell, lo)
    zmin, _ = common.grid_min(xyz[:, 2], r, c, shape)
    surf = common.inpaint(zmin.reshape(shape))
    gy, gx = common.gradient(surf, cell)
    return (xyz[:, 2] - common.bilinear(surf, xyz[:, :2], cell, lo),
            common.bilinear(np.hypot(gx, gy), xyz[:, :2], cell, lo))


def _extent(xy: np.ndarray) -> np.ndarray:
    """``np.ptp(xy, axis=0)``, one column at a time (:func:`common.column_min`)."""
    return common.column_max(xy) - common.column_min(xy)


def refine_understorey(xyz: np.ndarray, ground: np.ndarray, share: np.ndarray,
                       p: UnderstoreyParams = UnderstoreyParams()) -> np.ndarray:
    """Ground flags (m,) bool with the understorey taken out under canopy.

    Parameters
    ----------
    xyz : (m, 3) float64
        Local metric coordinates.
    ground : (m,) bool
        A ground filter's result.
    share : (m,) float
        :func:`canopy_share` of each point.
    """
    g = np.asarray(ground, dtype=bool).copy()
    under = np.asarray(share) > p.canopy_share
    if not (g & under).any():
        return g
    idx = np.flatnonzero(g)
    if p.spike_passes > 0 and len(idx) > 3:
        area = max(float(np.prod(_extent(xyz[idx, :2]))), 1.0)
        cell = p.spike_cell * np.sqrt(area / len(idx))
        for _ in range(p.spike_passes):
            test = np.flatnonzero(under[idx])
            res, slope = plane_residual(xyz[idx], cell, query=test)
            bad = res > p.threshold + p.spike_scalar * slope
            if not bad.any():
                break
            g[idx[test[bad]]] = False
            idx = np.flatnonzero(g)
    if p.envelope_spacing > 0 and len(idx) >= 4:
        area = max(float(np.prod(_extent(xyz[idx, :2]))), 1.0)
        cell = max(1.0, p.envelope_spacing * np.sqrt(area / len(idx)))
        h, slope = envelope_height(xyz[idx], cell)
        g[idx[under[idx] & (h > p.threshold + p.envelope_scalar * slope * cell)]] = False
    return g
