"""The options every ground filter shares (FilterOptions), read the same way by every method."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from ground_synth import terrain_with_boxes

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.ground.common import PRESET_NAMES, presets
from workstation.ground.methods import METHOD_NAMES, ground_filter, methods
from workstation.ground.options import FilterOptions
from workstation.ground.smrf import SMRFParams

OPTIONS = [f.name for f in dataclasses.fields(FilterOptions)]


@pytest.mark.parametrize("method", METHOD_NAMES)
def test_every_method_has_the_options_keyword_only_and_every_preset(method):
    m = methods()[method]
    assert issubclass(m.params, FilterOptions)
    fields = {f.name: f for f in dataclasses.fields(m.params)}
    assert all(fields[name].kw_only for name in OPTIONS)
    assert not any(f.kw_only for name, f in fields.items() if name not in OPTIONS)
    assert tuple(m.presets) == PRESET_NAMES
    assert all(type(p) is m.params for p in m.presets.values())


def test_options_do_not_take_positions():
    # the method's own fields keep their constructor positions; an option is named or absent
    assert SMRFParams(2.0, 0.2) == SMRFParams(cell=2.0, slope=0.2)
    with pytest.raises(TypeError):
        SMRFParams(1.0, 0.15, 18.0, 0.5, 1.25, False, 0.0, True)


def test_presets_refuse_an_unknown_name():
    with pytest.raises(ValueError, match="hilly"):
        presets(SMRFParams, hilly={"slope": 0.4})


@pytest.fixture(scope="module")
def cloud():
    xyz, _ = terrain_with_boxes(seed=5, size=50.0)
    cls = np.ones(len(xyz), np.uint8)
    cls[:10] = ASPRSClass.BUILDING  # a class no filter may overwrite without reclassify
    return Cloud(xyz, {"classification": cls}, crs="EPSG:32632")


@pytest.mark.parametrize("method", METHOD_NAMES)
def test_every_method_applies_the_options(cloud, method):
    kept = ground_filter(cloud, method)
    cls = np.asarray(kept.attrs["classification"])
    assert (cls[:10] == ASPRSClass.BUILDING).all()
    assert cls[-1] == ASPRSClass.LOW_POINT  # the low-noise step took the deep outlier out
    rec = kept.history[-1]
    assert rec.stage == f"ground.{method}" and set(OPTIONS) <= set(rec.params)
    off = np.asarray(ground_filter(cloud, method, noise=False, reclassify=True).attrs["classification"])
    assert not (off == ASPRSClass.LOW_POINT).any()
    assert not (off == ASPRSClass.BUILDING).any()
