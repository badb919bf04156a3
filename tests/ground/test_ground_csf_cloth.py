"""CSF's cloth simulation against a plain whole-grid statement of the same rules.

:func:`workstation.ground.csf.simulate` keeps only the movable particles in compact arrays and
sums the neighbours on the flattened grid; the reference below moves every particle of the grid
with masks and takes the neighbours from an edge-padded copy. Both must give the same cloth,
bit for bit, and the same number of steps.
"""

from __future__ import annotations

import numpy as np
import pytest

from workstation.ground import csf
from workstation.ground.csf import DAMPING, GRAVITY, PASSES, CSFParams, _neighbour_sum, simulate


def _padded_sum(z):
    q = np.pad(z, 1, mode="edge")
    return ((q[:-2, 1:-1] + q[2:, 1:-1]) + q[1:-1, :-2]) + q[1:-1, 2:]


def _reference(ihv, p):
    """The cloth of :func:`simulate` by masked updates of the whole grid."""
    z = np.full(ihv.shape, float(ihv.max()) + 0.05)
    zold = z.copy()
    movable = np.ones(ihv.shape, dtype=bool)
    fall = GRAVITY * p.time_step**2
    steps = 0
    for steps in range(1, p.iterations + 1):
        start = z.copy()
        z = np.where(movable, ((z - zold) * (1.0 - DAMPING) + z) - fall, z)
        for _ in range(PASSES[p.rigidness]):
            z = np.where(movable, (z + _padded_sum(z) * 0.25) * 0.5, z)
        hit = movable & (z <= ihv)
        z[hit] = ihv[hit]
        movable &= ~hit
        if steps > 10 and np.abs(z - start).max() < p.tolerance:
            break
        zold = start
    if p.slope_smooth:  # unchanged by the compact simulation: the module's own step
        csf.snap_to_slopes(z, ihv, movable, p.smooth_threshold)
    return z, steps


def _inverted_terrain(shape, seed):
    """Inverted heights: a rough slope with roofs (pits once inverted) and single spikes."""
    rng = np.random.default_rng(seed)
    r, c = np.mgrid[0 : shape[0], 0 : shape[1]]
    ihv = -(0.05 * r + 0.03 * c + 0.3 * np.sin(c / 4.0)) + rng.normal(0.0, 0.05, shape)
    for _ in range(max(1, ihv.size // 300)):
        r0, c0 = rng.integers(0, shape[0]), rng.integers(0, shape[1])
        ihv[r0 : r0 + 6, c0 : c0 + 8] -= rng.uniform(2.0, 9.0)
    spikes = rng.random(shape) < 0.01
    ihv[spikes] += rng.uniform(0.5, 3.0, spikes.sum())
    return ihv


@pytest.mark.parametrize("shape", [(1, 1), (1, 30), (30, 1), (2, 2), (3, 7), (45, 62)])
def test_neighbour_sum_is_the_edge_padded_sum(shape):
    z = np.random.default_rng(1).normal(0.0, 10.0, shape)
    assert np.array_equal(_neighbour_sum(z), _padded_sum(z))


@pytest.mark.parametrize("shape", [(1, 1), (3, 3), (5, 17), (30, 20)])
def test_neighbour_sum_of_a_band_of_rows(shape):
    z = np.random.default_rng(2).normal(0.0, 10.0, shape)
    want = _padded_sum(z)
    for r0 in range(shape[0]):
        for r1 in range(r0 + 1, shape[0] + 1):
            out = np.full(shape, np.nan)
            _neighbour_sum(z, out, r0, r1)
            assert np.array_equal(out[r0:r1], want[r0:r1])
            assert np.isnan(out[:r0]).all() and np.isnan(out[r1:]).all()  # the other rows untouched


def test_neighbour_sum_of_non_contiguous_arrays():
    z = np.random.default_rng(3).normal(0.0, 10.0, (20, 14))
    for view in (z.T, z[:, ::2], np.asfortranarray(z)):
        assert np.array_equal(_neighbour_sum(view), _padded_sum(view))
        assert np.array_equal(_neighbour_sum(view, np.empty(view.shape)), _padded_sum(view))
    with pytest.raises(ValueError, match="C-contiguous"):
        _neighbour_sum(z.T, np.empty((20, 14)).T)
    with pytest.raises(ValueError, match="C-contiguous"):
        _neighbour_sum(z, np.empty((20, 28))[:, ::2])


@pytest.mark.parametrize("setting, value", [
    ("COMPACT_FRACTION", 0.0), ("COMPACT_FRACTION", 0.1), ("COMPACT_FRACTION", 0.5), ("COMPACT_FRACTION", 1.0),
    ("BAND_PARTICLES", 1), ("BAND_PARTICLES", 45), ("BAND_PARTICLES", 100), ("BAND_PARTICLES", 1000)])
def test_compaction_and_bands_give_the_same_cloth(monkeypatch, setting, value):
    # compacting after every step (0), when 10 % or half of the arrays has stopped, or never (1);
    # bands of 1, 1, 2 and 22 rows of 45 particles (60 rows, 3 to 60 bands)
    ihv = _inverted_terrain((60, 45), seed=11)
    p = CSFParams(rigidness=2, slope_smooth=True)
    monkeypatch.setattr(csf, setting, value)
    cloth, steps = simulate(ihv, p)
    want, want_steps = _reference(ihv, p)
    assert steps == want_steps
    assert np.array_equal(cloth, want)


@pytest.mark.parametrize("shape", [(1, 40), (40, 1), (2, 3), (37, 52), (60, 45)])
@pytest.mark.parametrize("rigidness", [1, 2, 3])
@pytest.mark.parametrize("slope_smooth", [False, True])
def test_simulation_equals_the_whole_grid_reference(shape, rigidness, slope_smooth):
    ihv = _inverted_terrain(shape, seed=shape[0] * 100 + shape[1] + rigidness)
    p = CSFParams(rigidness=rigidness, slope_smooth=slope_smooth)
    cloth, steps = simulate(ihv, p)
    want, want_steps = _reference(ihv, p)
    assert steps == want_steps
    assert np.array_equal(cloth, want)
    assert (cloth == ihv).any() and steps >= 11  # the cloth fell onto the surface


@pytest.mark.parametrize("overrides", [{"tolerance": 0.3}, {"iterations": 14}, {"iterations": 5}])
def test_early_ends_equal_the_reference(overrides):
    # a loose tolerance ends the fall while particles are still stopping, in the last step too:
    # those must count as stopped for the slope post-processing
    ihv = _inverted_terrain((50, 40), seed=7)
    p = CSFParams(rigidness=2, slope_smooth=True, **overrides)
    cloth, steps = simulate(ihv, p)
    want, want_steps = _reference(ihv, p)
    assert steps == want_steps
    assert np.array_equal(cloth, want)


def test_a_particle_stopping_in_the_last_step_holds_the_slope_post_processing():
    # a loose tolerance ends the fall at step 11; particle P reaches its IHV in that very step,
    # so it is fixed and its neighbour Q, 0.2 m above its own IHV, is snapped onto it
    ihv = np.full((30, 30), -100.0)
    ihv[0, 0] = 0.0  # the highest point (the cloth starts above it), far from P
    p = CSFParams(rigidness=2, slope_smooth=True, tolerance=5.0)
    z10, _ = simulate(ihv, CSFParams(rigidness=2, slope_smooth=False, iterations=10))
    z11, steps = simulate(ihv, CSFParams(rigidness=2, slope_smooth=False, iterations=11))
    assert steps == 11
    P, Q = (20, 20), (20, 21)
    ihv[P] = 0.5 * (z10[P] + z11[P])
    ihv[Q] = z11[Q] - 0.2
    cloth, steps = simulate(ihv, p)
    want, want_steps = _reference(ihv, p)
    assert steps == want_steps == 11
    assert cloth[P] == ihv[P] and cloth[Q] == ihv[Q]
    assert np.array_equal(cloth, want)
