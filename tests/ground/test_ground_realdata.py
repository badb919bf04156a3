"""Every method on the six ISPRS reference samples (Sithole & Vosselman 2004).

Goals of issue 4 that are met are asserted as such (SMRF ≤ 4.1 % mean total error); for the
methods that miss their goal the bound is the level measured (docs/benchmarks.md), so a
regression still fails.
"""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.ground.evaluate import ground_errors
from workstation.ground.methods import ground_filter

SAMPLES = ["samp11", "samp21", "samp31", "samp42", "samp51", "samp61"]


@pytest.fixture(scope="module")
def isprs(shared_data):
    out = {}
    for s in SAMPLES:
        d = np.loadtxt(shared_data / "isprs" / f"{s}.txt")
        out[s] = (Cloud(d[:, :3]), d[:, 3] == 0)
    return out


def _mean_total(isprs, method, samples=SAMPLES):
    errs = {}
    for s in samples:
        cloud, ref = isprs[s]
        cls = np.asarray(ground_filter(cloud, method).attrs["classification"])
        errs[s] = ground_errors(ref, cls == 2).total_error
    return float(np.mean(list(errs.values()))), errs


# method -> largest mean total error over the six samples (fraction)
BOUNDS = {"smrf": 0.041, "pmf": 0.080, "lowest": 0.25, "local_min": 0.15}


@pytest.mark.realdata
@pytest.mark.parametrize("method", sorted(BOUNDS))
def test_isprs_mean_total_error(isprs, method):
    mean, errs = _mean_total(isprs, method)
    assert mean <= BOUNDS[method], errs


@pytest.mark.realdata
@pytest.mark.slow
def test_isprs_auto_beats_smrf(isprs):
    mean_auto, errs = _mean_total(isprs, "auto")
    mean_smrf, _ = _mean_total(isprs, "smrf")
    assert mean_auto < mean_smrf
    # 3.03 % on grids aligned to the cell lattice (2.94 % on grids from each sample's minimum
    # corner; 2.93-3.06 % over half-cell shifts of the grid, docs/benchmarks.md)
    assert mean_auto <= 0.031, errs


@pytest.mark.realdata
@pytest.mark.slow
def test_isprs_ptd(isprs):
    mean, errs = _mean_total(isprs, "ptd", ["samp21", "samp31", "samp42", "samp51"])
    assert mean <= 0.032, errs


@pytest.mark.realdata
@pytest.mark.slow
def test_isprs_csf_fixes(isprs):
    # samp31 holds a point 80 m under the terrain: the package alone gives 13.3 % there;
    # samp21: 4.1 % with the package's own heights for empty particles, 1.6 % with ours
    _, errs = _mean_total(isprs, "csf", ["samp21", "samp31"])
    assert errs["samp31"] < 0.035, errs
    assert errs["samp21"] < 0.025, errs


@pytest.mark.parametrize("name", ["Topography.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las", "MixedConifer.laz"])
def test_auto_dtm_on_the_classified_tiles(shared_data, name):
    """Issue 4's terrain goal: 1 m TIN DTM of ``auto``'s ground within 0.25 m RMSE of the file's
    own ground class (measured 0.230, 0.205, 0.224, 0.181, 0.091 m; docs/benchmarks.md)."""
    from workstation.ground.common import crs_unit_factors
    from workstation.io import read_cloud
    from workstation.ml.realdata import dtm_rmse

    cloud = read_cloud(shared_data / "lidar" / name)
    hf, vf = crs_unit_factors(cloud.crs)
    ref = np.asarray(cloud.attrs["classification"]) == 2
    out = ground_filter(cloud, "auto", reclassify=True)
    rmse = dtm_rmse(np.asarray(cloud.xyz), ref, np.asarray(out.attrs["classification"]) == 2, vf, hf)
    assert rmse <= 0.25, rmse
