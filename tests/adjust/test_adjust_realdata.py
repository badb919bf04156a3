"""Strip-wise adjustment of a real delivery (bcts_1: three flight lines, no trajectory)."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.adjust import AdjustParams, apply_corrections, estimate_corrections
from workstation.adjust.report import pair_table, result_dict, swath_pass

pytestmark = pytest.mark.realdata


def test_bcts_1_strip_shifts_never_worsen_a_pair(shared_data):
    from workstation.io import read_cloud

    c = read_cloud(shared_data / "lidar" / "bcts_1.laz")
    attrs = dict(c.attrs)
    res = estimate_corrections(c.xyz, attrs, AdjustParams())
    out = result_dict(res)
    assert sorted(res.strips) == [66, 67, 68]
    # forest floor and gentle slopes: the heights are determined, the plan shifts are reported
    for s in out["strips"]:
        assert s["fixed"] or s["shift_m"][2] is not None
    assert 0.01 < res.noise_m <= 0.06
    fixed = apply_corrections(c.xyz, attrs, res)
    before = swath_pass(c.xyz, attrs)
    pairs = pair_table(before.result(), swath_pass(fixed, attrs, before.grid.cell).result())
    assert len(pairs) == 3
    for p in pairs:
        assert p["rmsdz_after_m"] <= p["rmsdz_before_m"]
    assert np.mean([p["rmsdz_after_m"] for p in pairs]) < 0.8 * np.mean([p["rmsdz_before_m"] for p in pairs])
