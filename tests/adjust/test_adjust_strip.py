"""Strip-wise model (no trajectory): shifts recovered, horizontal shifts from flat ground
reported as not determined, the datum strip, and the least-squares and patch building blocks."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.adjust import AdjustParams, PatchParams, apply_corrections, estimate_corrections, find_patches
from workstation.adjust.lsq import robust_inliers, solve
from workstation.adjust.report import result_dict, swath_pass
from workstation.core.errors import InvalidInputError

from .synth import calibration_lines, fly, plates

SHIFT2, SHIFT4 = (0.10, -0.05, 0.08), (0.0, 0.0, -0.06)


@pytest.fixture(scope="module")
def shifted():
    return fly(calibration_lines(), plates(np.random.default_rng(1), n=40), line_shift={2: SHIFT2, 4: SHIFT4})


def test_strip_shifts_recovered_relative_to_the_datum(shifted):
    xyz, attrs, _ = shifted
    keep = (xyz.copy(), {k: v.copy() for k, v in attrs.items()})
    res = estimate_corrections(xyz, attrs, AdjustParams(fixed_strip=1))
    out = result_dict(res)
    assert out["model"] == "strip" and out["fixed_strip"] == 1 and out["boresight_deg"] is None
    by_id = {s["id"]: s for s in out["strips"]}
    assert by_id[1]["fixed"] and by_id[1]["shift_m"] == [0.0, 0.0, 0.0]
    # the correction is the opposite of the navigation offset of each line
    tol = np.array([0.01, 0.01, 0.003])
    assert np.all(np.abs(np.add(by_id[2]["shift_m"], SHIFT2)) <= tol)
    assert np.all(np.abs(np.add(by_id[4]["shift_m"], SHIFT4)) <= tol)
    assert np.all(np.abs(by_id[3]["shift_m"]) <= tol)
    assert all(s > 0 for s in by_id[2]["shift_sigma_m"])
    fixed = apply_corrections(xyz, attrs, res)
    np.testing.assert_array_equal(xyz, keep[0])
    assert all(np.array_equal(attrs[k], v) for k, v in keep[1].items())
    before, after = swath_pass(xyz, attrs).result(), swath_pass(fixed, attrs).result()
    assert before["rmsdz_all"] > 0.04 > 0.02 > after["rmsdz_all"]


def test_default_datum_is_the_most_connected_strip(shifted):
    xyz, attrs, _ = shifted
    res = estimate_corrections(xyz, attrs, AdjustParams())
    # lines 2 and 3 lie in the middle of the block: each overlaps all three others
    assert res.fixed_strip in (2, 3)
    with pytest.raises(InvalidInputError, match="datum strip"):
        estimate_corrections(xyz, attrs, AdjustParams(fixed_strip=9))


def test_flat_ground_determines_heights_only():
    xyz, attrs, _ = fly(calibration_lines(), None, line_shift={2: SHIFT2})
    res = estimate_corrections(xyz, attrs, AdjustParams(fixed_strip=1))
    out = result_dict(res)
    s2 = {s["id"]: s for s in out["strips"]}[2]
    assert s2["shift_m"][0] is None and s2["shift_m"][1] is None  # reported, not estimated
    assert s2["shift_m"][2] == pytest.approx(-SHIFT2[2], abs=0.003)
    assert out["not_determined"]
    fixed = apply_corrections(xyz, attrs, res)
    moved = fixed - xyz
    assert np.abs(moved[:, :2]).max() < 0.01  # no horizontal move made up from noise


def test_patches_reject_rough_cells_and_estimate_the_noise():
    rng = np.random.default_rng(5)
    n = 40_000
    xy = rng.uniform(0, 60, (n, 2))
    sid = np.where(rng.random(n) < 0.5, 1, 2)
    z = 0.1 * xy[:, 0] + rng.normal(0, 0.02, n)
    rough = xy[:, 0] > 40  # "vegetation": a metre of scatter
    z[rough] += rng.uniform(0, 1.0, rough.sum())
    P = find_patches(np.column_stack([xy, z]), sid, PatchParams(cell_m=3.0))
    assert P.noise_m == pytest.approx(0.02, rel=0.15)
    centres = np.column_stack([np.bincount(P.slot, np.column_stack([xy, z])[P.index][:, 0]) / np.bincount(P.slot)])
    assert centres.max() < 40.5  # no patch in the rough part
    assert P.pair_a.size > 0.8 * (40 / 3) * (60 / 3)
    assert np.all(P.strip[P.pair_a] < P.strip[P.pair_b])


def test_solve_leaves_out_undetermined_directions_and_mad_rejects_outliers():
    rng = np.random.default_rng(0)
    m = 200
    A = np.column_stack([np.ones(m), rng.normal(0, 1e-6, m)])  # the second unknown barely observed
    l = 0.3 + rng.normal(0, 0.01, m)
    l[:5] += 5.0  # gross errors
    sig = np.full(m, 0.01)
    step = solve(A, l, sig, np.ones(2), tol_m=0.05)
    assert step.determined.tolist() == [True, False]
    assert abs(step.delta[1]) < 1e-6 and len(step.null_directions) == 1
    inl = robust_inliers(step.residuals, sig)
    assert not inl[:5].any() and inl[5:].mean() > 0.97
    step = solve(A, l, sig, np.ones(2), tol_m=0.05, inliers=inl)
    assert step.delta[0] == pytest.approx(0.3, abs=0.003)
    assert np.sqrt(step.cov[0, 0]) == pytest.approx(0.01 / np.sqrt(inl.sum()), rel=0.2)
