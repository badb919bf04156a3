"""Failure gallery of the ground filters on small simulated scenes (tests/ground/gallery_scenes.py).

Two failure modes measured on held-back real files, each as a scene every method's defaults
must survive:

* isolated low points (multipath, ghost echoes) 1-100 m under the terrain: none may be ground,
  all become class 7 (the low-noise step every method runs first);
* a closed canopy where 5 % of the pulses reach the ground: the DTM from each method's ground
  within 1 m RMS of the true terrain (SMRF's grid low-outlier step threw that ground out).
"""

from __future__ import annotations

import numpy as np
import pytest

from gallery_scenes import ORIGIN, dense_canopy, low_outliers, ridges
from workstation.core.classes import ASPRSClass
from workstation.ground.common import tin_interpolate
from workstation.ground.methods import METHOD_NAMES, ground_filter
from workstation.ground.noise import LowNoiseParams, low_noise


@pytest.fixture(scope="module")
def canopy():
    return dense_canopy(seed=0)


@pytest.fixture(scope="module")
def outliers():
    return low_outliers(seed=0)


def dtm_rms(cloud, ground, terrain) -> float:
    """RMS (m) of the TIN of ``ground`` against ``terrain`` on a 1 m grid 2 m inside the scene."""
    lo, hi = cloud.xyz[:, :2].min(axis=0), cloud.xyz[:, :2].max(axis=0)
    gx, gy = np.meshgrid(np.arange(lo[0] + 2, hi[0] - 2), np.arange(lo[1] + 2, hi[1] - 2))
    q = np.column_stack([gx.ravel(), gy.ravel()])
    d = tin_interpolate(cloud.xyz[ground, :2], cloud.xyz[ground, 2], q) - terrain(q)
    return float(np.sqrt(np.mean(d * d)))


def test_scenes_are_what_they_say(canopy, outliers):
    cloud, _, is_ground = canopy
    last = np.asarray(cloud.attrs["return_number"]) == np.asarray(cloud.attrs["number_of_returns"])
    pulses = last.sum()
    assert 0.04 < is_ground.sum() / pulses < 0.06  # 5 % penetration
    assert 0.15 < is_ground.sum() / 80.0**2 < 0.25  # ground points per m²
    cloud, terrain, out = outliers
    depth = terrain(cloud.xyz[out, :2]) - cloud.xyz[out, 2]
    assert out.sum() == pytest.approx(0.001 * (~out).sum(), abs=1)
    assert depth.min() >= 1.0 and depth.max() <= 100.0


@pytest.mark.parametrize("method", METHOD_NAMES)
def test_no_low_outlier_is_ground_and_all_are_class_7(outliers, method):
    cloud, terrain, out = outliers
    cls = np.asarray(ground_filter(cloud, method).attrs["classification"])
    assert not (cls[out] == ASPRSClass.GROUND).any()
    assert (cls[out] == ASPRSClass.LOW_POINT).all()
    # and the step takes (almost) nothing else
    assert (cls[~out] == ASPRSClass.LOW_POINT).sum() <= 2


@pytest.mark.parametrize("method", METHOD_NAMES)
def test_dtm_under_a_closed_canopy_within_1_m(canopy, method):
    cloud, terrain, is_ground = canopy
    cls = np.asarray(ground_filter(cloud, method).attrs["classification"])
    assert dtm_rms(cloud, cls == ASPRSClass.GROUND, terrain) < 1.0
    # the sparse true ground is never taken for noise
    assert not (cls[is_ground] == ASPRSClass.LOW_POINT).any()


def test_the_two_failures_without_the_fixes(canopy, outliers):
    """What the gallery guards against: SMRF with Pingel's grid low-outlier step under the
    canopy, and SMRF without the noise step on the low outliers."""
    cloud, terrain, _ = canopy
    g = np.asarray(ground_filter(cloud, "smrf", low_outliers=True, noise=False).attrs["classification"]) == 2
    assert dtm_rms(cloud, g, terrain) > 1.0
    cloud, _, out = outliers
    cls = np.asarray(ground_filter(cloud, "smrf", noise=False).attrs["classification"])
    assert (cls[out] == ASPRSClass.GROUND).sum() >= 5
    assert not (cls == ASPRSClass.LOW_POINT).any()


def test_low_noise_is_slope_invariant_and_keeps_ground_in_a_ditch():
    rng = np.random.default_rng(3)
    xy = rng.uniform(0, 60, (60 * 60 * 4, 2))
    z = 0.5 * xy[:, 0] + rng.normal(0, 0.03, len(xy))
    # a ditch 1.5 m deep and 1 m wide along y at x = 30, sparsely hit
    ditch = np.abs(xy[:, 0] - 30.0) < 0.5
    z[ditch] -= 1.5
    xyz = np.column_stack([xy, z])
    # shallow and deep outliers on the 0.5 slope
    k = np.array([100, 200, 300])
    xyz[k, 2] -= [1.5, 4.0, 60.0]
    # the three are taken, the ditch's sparse bottom is not
    assert set(np.flatnonzero(low_noise(xyz))) == set(k.tolist())
    # sparse ground under crowns: 0.15 points/m² of ground among 2 points/m² of crowns 10-20 m up
    gxy = rng.uniform(0, 60, (540, 2))
    cxy = rng.uniform(0, 60, (7200, 2))
    pts = np.vstack([np.column_stack([gxy, 0.2 * gxy[:, 0]]),
                     np.column_stack([cxy, 0.2 * cxy[:, 0] + rng.uniform(10, 20, len(cxy))])])
    assert not low_noise(pts).any()
    # off with depth 0
    assert not low_noise(xyz, LowNoiseParams(depth=0.0)).any()


def test_noise_step_is_a_declared_default_and_can_be_switched_off(outliers):
    from workstation.ground.methods import make_params

    for m in METHOD_NAMES:
        p = make_params(m)
        assert p.noise is True and isinstance(p.noise_params, LowNoiseParams)
    cloud, _, out = outliers
    off = np.asarray(ground_filter(cloud, "pmf", noise=False).attrs["classification"])
    assert not (off == ASPRSClass.LOW_POINT).any()


def test_the_ridge_scene_is_what_it_says():
    """The steep ridge of sparse old ALS (samp61's failure mode, ``bench_ground.py ridges``):
    0.16 points/m², a top 9 m over the low side and 5 m over the high one, 1:1 faces."""
    cloud, terrain, top, decks = ridges(seed=0)
    assert 0.15 < cloud.n / (240.0 * 200.0) < 0.2 and not decks and top.sum() > 300
    y = np.linspace(70.0, 130.0, 601)
    z = terrain(np.column_stack([np.full(601, 120.0), y]) + ORIGIN[:2])
    low, crest, high = z[y < 85].mean(), z[np.abs(y - 100.3) < 3].mean(), z[y > 115].mean()
    assert crest - low == pytest.approx(9.0, abs=0.5) and high - low == pytest.approx(4.0, abs=0.5)
    assert np.max(np.abs(np.diff(z) / np.diff(y))) == pytest.approx(1.0, abs=0.05)  # the faces
