"""CSF, the cloth simulation filter (Zhang et al. 2016), vectorised in numpy.

Zhang W., Qi J., Wan P., Wang H., Xie D., Wang X., Yan G. (2016) "An easy-to-use airborne LiDAR
data filtering method based on cloth simulation", Remote Sensing 8(6):501.

The cloud is turned upside down and a cloth of particles on a ``cloth_resolution`` grid falls
onto it; particles reaching the inverted surface (their *intersection height value*, IHV, the
height of the horizontally nearest point) stop; ``rigidness`` sets how strongly neighbours
pull each other; optional slope post-processing. Points within ``class_threshold`` of the
cloth are ground.

Our simulation (no longer the ``cloth-simulation-filter`` package, whose two flaws below it
avoids by construction): the particles form a ``(rows, cols)`` array; each step moves every
movable particle by Verlet integration under gravity (0.2 · time_step², damping 0.01, as the
package), then applies the internal forces as ``passes`` Jacobi relaxations towards the mean
of the 4 neighbours (each halving the difference; ``passes`` = 1, 3, 6 for rigidness 1, 2, 3),
then stops every particle that reached its IHV (made immovable there); it ends when no
particle moves more than 5 mm in a step (40-200 steps here) or after ``iterations``. The IHV
of a particle is the (inverted) *lowest* point whose nearest particle it is, so the cloth rests
on a lower envelope; particles without a point take SMRF's provisional ground surface (see
below), isolated low points are set aside first. Slope post-processing: movable particles
next to an immovable one and within 0.3 m of their IHV are snapped onto it, repeatedly.

Why the package misses the paper's figures here (measured on the six ISPRS samples)
--------------------------------------------------------------------------------------
With the paper's per-group settings (0.5 m cloth, time step 0.65, threshold 0.5 m, rigidness
3/2/1 by terrain group) the package (1.1.7) gives 13.3 % mean total error (samp11 30.4 %,
21 4.1 %, 31 13.3 %, 42 3.1 %, 51 13.1 %, 61 15.8 %) against the paper's 3.9 %; Type I errors
(ground rejected) dominate: 50 % of samp11's ground.

* **Not float precision**: subtracting the coordinate origin gives identical results (the
  package stores double precision). We subtract it anyway.
* **Low outliers hold the cloth up** (verified): samp31 has a point 80 m under the terrain;
  upside down it is a spike the cloth hangs on, pulling a tent over the ground around it.
  Setting isolated low points aside (now the low-noise step every filter runs first,
  :func:`workstation.ground.noise.low_noise`; first :func:`workstation.ground.noise.isolated_low_points`
  on the particles' lowest points) takes samp31 from 13.3 % to 1.5 % (paper 1.6 %).
* **Empty particles get wrong heights** (verified): at 0.5 m on 0.2-1 pt/m² most particles
  have no point; the package (``Rasterization.cpp``) gives them the IHV of the first filled
  particle to the *right in the same row* (then left, up, down), often metres away, on a roof
  or lower down a slope, so the cloth is held off the ground (Type I) or rests on roofs.
  Giving each empty particle a virtual point at a TIN interpolation of the filled particles
  (``empty_fill="tin"``) cuts Type I (samp11 47 % -> 14 %, samp51 20 % -> 0.5 %, samp61
  17 % -> 0.5 %) but the interpolated roofs raise Type II (samp42 3 % -> 17 %). Placing the
  virtual points on a *lower envelope* instead, SMRF's provisional ground surface
  (``empty_fill="ground"``, the default), fixes both: 4.25 % mean total error with one
  parameter set (rigidness 2, slope smoothing) for all six samples.
* **A stiffer cloth than the paper's** (not verified): the package links every particle to
  its 8 neighbours and to the 8 at distance 2 (``Cloth.cpp``), applying the 16 rigidness
  corrections in turn (Gauss-Seidel); the paper describes neighbour links only.

With the package and both fixes: 4.25 % mean total error on the six samples; with our own
simulation and the same fixes: see docs/benchmarks.md ("Ground filtering"), where the
paper's 3.87 % (tuned per terrain group) is approached, not reached, with one default set.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .options import FilterOptions

STAGE = "ground.csf"

#: Jacobi relaxation passes per step for rigidness 1 (steep), 2 (mixed), 3 (flat).
PASSES = {1: 1, 2: 3, 3: 6}
#: Gravity of the package (metres per step² per time_step²) and its damping.
GRAVITY = 0.2
DAMPING = 0.01


@dataclass(frozen=True)
class CSFParams(FilterOptions):
    """CSF parameters and the options of every filter
    (:class:`~workstation.ground.options.FilterOptions`). Lengths in metres, whatever the CRS unit.

    Attributes
    ----------
    cloth_resolution : float
        Particle spacing, metres (0.5 as in the paper's ISPRS tests).
    rigidness : int
        1 (steep terrain), 2 (terraced/mixed, default) or 3 (flat): 1, 3 or 6 relaxation
        passes per step.
    time_step : float
        Simulation time step (dimensionless, 0.65).
    class_threshold : float
        Largest point-to-cloth distance of a ground point, metres (0.5).
    iterations : int
        Largest number of simulation steps (500).
    tolerance : float
        The simulation ends when no particle moved more than this in a step, metres (0.005).
    slope_smooth : bool
        Slope post-processing of movable particles (True).
    smooth_threshold : float
        Largest particle-to-IHV distance snapped by the slope post-processing, metres (0.3).
    empty_fill : str
        IHV of particles without a point: "ground" (default) SMRF's provisional ground
        surface (PDAL defaults) there, "tin" linear interpolation of the filled particles.
    remove_low_outliers : bool
        Set isolated low points among the particles' lowest points aside before simulating
        (False: the low-noise step, ``noise``, does it for every filter; this k-neighbour test
        also takes out sparse ground under a closed canopy).
    """

    cloth_resolution: float = 0.5
    rigidness: int = 2
    time_step: float = 0.65
    class_threshold: float = 0.5
    iterations: int = 500
    tolerance: float = 0.005
    slope_smooth: bool = True
    smooth_threshold: float = 0.3
    empty_fill: str = "ground"
    remove_low_outliers: bool = False


PRESETS: dict[str, CSFParams] = common.presets(
    CSFParams, flat={"rigidness": 3, "slope_smooth": False}, urban={"rigidness": 3, "slope_smooth": False},
    forest={"rigidness": 2, "cloth_resolution": 1.0}, steep={"rigidness": 1, "slope_smooth": True})


class _StdoutToStderr:
    """Send C-level stdout to stderr while a C++ library runs (the ``CSF`` package prints
    progress with ``std::cout``; used by scripts/bench_ground.py to time it side by side)."""

    def __enter__(self):
        import os
        import sys

        sys.stdout.flush()
        self._saved = os.dup(1)
        os.dup2(2, 1)
        return self

    def __exit__(self, *exc):
        import os
        import sys

        sys.stdout.flush()
        os.dup2(self._saved, 1)
        os.close(self._saved)
        return False


def _neighbour_sum(z: np.ndarray, out: np.ndarray | None = None, r0: int = 0, r1: int | None = None) -> np.ndarray:
    """Sum of the 4 neighbours of the particles of rows ``r0:r1`` (all rows by default) of a
    (rows, cols) grid, added as ``((up + down) + left) + right`` into the same rows of
    ``out``; a border particle is its own neighbour beyond the border of the grid.

    The rows are worked on as one flat run of values, in contiguous 1-D adds (faster than 2-D
    column slices); the two border columns, which the flat shifts give the neighbouring row's
    end, are recomputed from their saved ``up + down``. ``z`` is read as a C-contiguous copy when
    it is not one; ``out`` must be C-contiguous (ValueError otherwise).

    Examples
    --------
    >>> _neighbour_sum(np.array([[0.0, 4.0], [8.0, 12.0]]))
    array([[12., 20.],
           [28., 36.]])
    """
    z = np.ascontiguousarray(z)
    rows, cols = z.shape
    r1 = rows if r1 is None else r1
    if out is None:
        out = np.empty_like(z)
    elif not out.flags.c_contiguous or out.shape != z.shape:
        raise ValueError(f"out must be a C-contiguous array of shape {z.shape}")  # else reshape(-1) copies
    f, s = z.reshape(-1), out.reshape(-1)
    a, b = max(r0, 1), min(r1, rows - 1)  # the rows with a row above and below
    if a < b:
        np.add(f[(a - 1) * cols : (b - 1) * cols], f[(a + 1) * cols : (b + 1) * cols], out=s[a * cols : b * cols])
    if r0 == 0:
        np.add(z[0], z[min(1, rows - 1)], out=out[0])
    if r1 == rows:
        np.add(z[max(rows - 2, 0)], z[rows - 1], out=out[rows - 1])
    first, last = out[r0:r1, 0].copy(), out[r0:r1, -1].copy()
    lo, hi = r0 * cols, r1 * cols
    s[lo + 1 : hi] += f[lo : hi - 1]
    s[lo : hi - 1] += f[lo + 1 : hi]
    first += z[r0:r1, 0]
    first += z[r0:r1, min(1, cols - 1)]
    last += z[r0:r1, max(cols - 2, 0)]
    last += z[r0:r1, -1]
    out[r0:r1, 0] = first
    out[r0:r1, -1] = last
    return out


#: Particles per band of rows in which the neighbour sums are formed and read at once, so
#: that a large cloth's sums are read while they are still in the processor's cache (the
#: results do not depend on it).
BAND_PARTICLES = 262144


def _neighbour_sums_at(z: np.ndarray, out: np.ndarray, idx: np.ndarray, edges: np.ndarray, cut: np.ndarray,
                       near: np.ndarray) -> np.ndarray:
    """Neighbour sums (:func:`_neighbour_sum`) at the flat indices ``idx`` (sorted) into
    ``near``, band by band: the rows ``edges[k]:edges[k + 1]`` hold ``idx[cut[k]:cut[k + 1]]``;
    bands without one of them are skipped."""
    s = out.reshape(-1)
    if idx.size and (idx[0] < 0 or idx[-1] >= s.size):  # idx is sorted: all in range
        raise IndexError(f"particle index out of range 0..{s.size - 1}")
    for k in np.flatnonzero(cut[1:] > cut[:-1]):
        _neighbour_sum(z, out, int(edges[k]), int(edges[k + 1]))
        # mode "clip" clips nothing (checked above); the default mode would buffer ``out``
        np.take(s, idx[cut[k] : cut[k + 1]], out=near[cut[k] : cut[k + 1]], mode="clip")
    return near


#: Stopped particles stay in the compact arrays of :func:`_fall` (held at their IHV) until
#: more than this fraction of the arrays has stopped since the last compaction; compacting
#: less often saves copies and changes nothing in the cloth.
COMPACT_FRACTION = 0.1


def _fall(z: np.ndarray, ihv: np.ndarray, p: CSFParams, passes: int) -> tuple[np.ndarray, int]:
    """The cloth's time steps on ``z`` (in place); returns the flat indices of the particles
    still movable at the end and the number of steps.

    Each step moves every movable particle by Verlet integration under gravity, then ``passes``
    Jacobi relaxations halve its difference to the mean of its 4 neighbours (all the new
    heights from the old ones), then stops the particles at or under their IHV. The movable
    particles' heights are kept in compact arrays (``cur``, ``old``: this step's and the last
    one's) and written back to the grid before every neighbour sum reads them (the next
    step's Verlet move writes them again, so the last pass's heights stay compact until the
    end). A stopped particle keeps its IHV on the grid; it stays in the compact arrays at a
    position listed in ``gone`` (its IHV in ``rest``, put back before every write to the grid;
    its ``low`` -inf, so that it does not stop again; its change left out) until more than
    :data:`COMPACT_FRACTION` of the arrays has stopped, when they are compacted. The neighbour
    sums are formed band by band of rows (:func:`_neighbour_sums_at`), only where a particle of
    the compact arrays is. The arithmetic per movable particle is that of a masked update of
    the whole grid, in the same order.
    """
    flat, target = z.reshape(-1), ihv.reshape(-1)
    idx = np.arange(flat.size)  # intp: int32 indices are cast at every scatter and take
    cur, old, low = flat.copy(), flat.copy(), target.copy()
    nsum, spare = np.empty_like(z), np.empty_like(cur)  # spare: the neighbour sums, the changes
    gone, rest = np.empty(0, dtype=np.intp), np.empty(0)
    edges = np.unique(np.append(np.arange(0, z.shape[0], max(1, BAND_PARTICLES // z.shape[1])), z.shape[0]))
    starts = edges * z.shape[1]
    cut = np.searchsorted(idx, starts)
    fall = GRAVITY * float(p.time_step) ** 2
    steps = 0
    for steps in range(1, int(p.iterations) + 1):
        np.subtract(cur, old, out=old)  # Verlet: z + (z - zold)(1 - damping) - g dt^2
        old *= 1.0 - DAMPING
        old += cur
        old -= fall
        old, cur = cur, old
        for _ in range(passes):  # internal springs: move towards the neighbours' mean
            cur[gone] = rest
            flat[idx] = cur
            near = _neighbour_sums_at(z, nsum, idx, edges, cut, spare)
            near *= 0.25
            cur += near
            cur *= 0.5
        now = np.flatnonzero(cur <= low)
        cur[now] = low[now]
        flat[idx[now]] = low[now]
        moved = 0.0
        if steps > 10 and cur.size:
            change = np.subtract(cur, old, out=spare)
            np.abs(change, out=change)
            change[gone] = 0.0
            moved = float(change.max())
        gone, rest = np.concatenate([gone, now]), np.concatenate([rest, low[now]])
        low[now] = -np.inf
        if gone.size > COMPACT_FRACTION * cur.size:
            keep = np.ones(cur.size, dtype=bool)
            keep[gone] = False
            now = change = near = spare = None  # freed before the copies
            gone, rest = gone[:0], rest[:0]
            idx = idx[keep]  # one array at a time, each freed as its copy is made
            cur = cur[keep]
            old = old[keep]
            low = low[keep]
            spare = np.empty_like(cur)
            cut = np.searchsorted(idx, starts)
        if steps > 10 and moved < p.tolerance:
            break
    cur[gone] = rest
    flat[idx] = cur
    return np.delete(idx, gone), steps


def simulate(ihv: np.ndarray, p: CSFParams) -> tuple[np.ndarray, int]:
    """Drop the cloth onto the inverted surface (:func:`_fall`), then the slope post-processing.

    Parameters
    ----------
    ihv : (rows, cols) float64
        Intersection height of every particle (inverted heights, metres, no NaN).
    p : CSFParams

    Returns
    -------
    cloth : (rows, cols) float64
        Final particle heights (inverted, metres).
    steps : int
        Simulation steps run.
    """
    passes = PASSES.get(int(p.rigidness))
    if passes is None:
        from workstation.core.errors import InvalidInputError

        raise InvalidInputError(f"rigidness must be 1, 2 or 3, not {p.rigidness}", field="rigidness")
    ihv = np.ascontiguousarray(ihv, dtype=np.float64)
    z = np.full(ihv.shape, float(np.max(ihv)) + 0.05)
    idx, steps = _fall(z, ihv, p, passes)
    if p.slope_smooth:
        movable = np.zeros(ihv.shape, dtype=bool)
        movable.reshape(-1)[idx] = True
        snap_to_slopes(z, ihv, movable, p.smooth_threshold)
    return z, steps


def snap_to_slopes(z: np.ndarray, ihv: np.ndarray, movable: np.ndarray, threshold: float) -> None:
    """CSF's slope post-processing, in place: a movable particle next to a fixed one and within
    ``threshold`` of its point's height is moved onto it and fixed, repeated until none is."""
    for _ in range(max(ihv.shape)):
        fixed = np.pad(~movable, 1, mode="constant", constant_values=False)
        touch = fixed[:-2, 1:-1] | fixed[2:, 1:-1] | fixed[1:-1, :-2] | fixed[1:-1, 2:]
        snap = movable & touch & (np.abs(z - ihv) < threshold)
        if not snap.any():
            break
        z[snap] = ihv[snap]
        movable &= ~snap


def surface_params(xyz: np.ndarray, p: CSFParams):
    """The :class:`~workstation.ground.smrf.SMRFParams` of the SMRF surface that fills the
    empty particles of a run on ``xyz`` (PDAL's defaults on a cell sized by the points), None
    when ``empty_fill`` is not "ground"."""
    from .smrf import SMRFParams

    if p.empty_fill != "ground":
        return None
    return SMRFParams(cell=common.auto_cell(xyz[:, :2], SMRFParams.cell))


def csf_ground(xyz: np.ndarray, p: CSFParams, shared=None) -> np.ndarray:
    """Ground flags (m,) bool of local metric points (metres) by CSF; ``shared`` (a
    :class:`workstation.ground.smrf.SharedSurfaces` of ``xyz``) serves the SMRF surface of the
    empty particles when it holds it."""
    from .noise import isolated_low_points

    if p.empty_fill not in ("ground", "tin"):
        from workstation.core.errors import InvalidInputError

        raise InvalidInputError(f"empty_fill must be ground or tin, not {p.empty_fill!r}", field="empty_fill")
    m = xyz.shape[0]
    res = float(p.cloth_resolution)
    origin = xyz[:, :2].min(axis=0)
    # particle (r, c) sits at origin + (c, r) * res; each point goes to its nearest particle
    r, c, shape, _ = common.grid_index(xyz[:, :2] + res / 2, res, origin=origin, option="--cloth-resolution")
    zmin, imin = common.grid_min(xyz[:, 2], r, c, shape)
    use = np.ones(m, dtype=bool)
    surface_job = None
    if p.empty_fill == "ground":
        # SMRF's provisional surface (it sets low outliers aside itself) is computed on a second
        # core while the isolated low points are found
        from concurrent.futures import ThreadPoolExecutor

        from .smrf import smrf_surface

        sp = surface_params(xyz, p)
        pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="csf-smrf")
        surface_job = pool.submit(smrf_surface, xyz, sp, shared)
        pool.shutdown(wait=False)
    if p.remove_low_outliers:
        lowest = imin[imin >= 0]  # a low outlier is the lowest point of its particle
        low = isolated_low_points(xyz[lowest])
        if low.any():
            use[lowest[low]] = False
            zmin, _ = common.grid_min(np.where(use, xyz[:, 2], np.inf), r, c, shape)
            zmin[np.isinf(zmin)] = np.nan
    if surface_job is not None:
        zpro, zo, _ = surface_job.result()
        gy, gx = np.mgrid[0:shape[0], 0:shape[1]]
        q = np.column_stack([origin[0] + gx.ravel() * res, origin[1] + gy.ravel() * res])
        surface = np.where(np.isnan(zmin), common.bilinear(zpro, q, sp.cell, zo).reshape(shape), zmin)
    else:
        surface = common.inpaint(zmin)
    cloth, _ = simulate(-surface, p)
    # the particle grid is cell-centred on a grid shifted by half a particle
    zc = -common.bilinear(cloth, xyz[:, :2] + res / 2, res, origin)
    return use & (np.abs(xyz[:, 2] - zc) < p.class_threshold)


def csf(cloud: Cloud, params: CSFParams | None = None, **overrides) -> Cloud:
    """Classify ground with the cloth simulation filter (Zhang et al. 2016).

    Parameters
    ----------
    cloud : Cloud
    params : CSFParams, optional
    **overrides
        Fields of :class:`CSFParams` to replace.

    Returns
    -------
    Cloud
        ``classification`` 2 on ground, 1 elsewhere (other classes kept unless ``reclassify``).
    """
    p = replace(params or CSFParams(), **overrides)
    return common.run_filter(cloud, p, STAGE, lambda prep: csf_ground(prep.xyz, p))
