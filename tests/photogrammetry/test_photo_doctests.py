"""Run the docstring examples of the photogrammetry modules as tests."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "workstation.photogrammetry.collinearity",
    "workstation.photogrammetry.calibration",
    "workstation.photogrammetry.georef",
    "workstation.photogrammetry.bundle",
    "workstation.photogrammetry.sfm",
    "workstation.io.camera",
    "workstation.io.gcp",
    "workstation.io.reconstruction",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    mod = importlib.import_module(name)
    res = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert res.attempted > 0, f"{name} has no examples"
    assert res.failed == 0
