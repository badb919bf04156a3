"""Shared fixtures: the real-data folder and small deterministic clouds."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import settings

# Property tests draw the same examples every run, so that a CI run repeats the last one; to
# look for new failing examples, run with --hypothesis-profile explore (tests that set
# derandomize in their own settings, as the I/O fuzz tests, keep theirs).
settings.register_profile("repeatable", derandomize=True, database=None)
settings.register_profile("explore", derandomize=False)
settings.load_profile("repeatable")

REPO = Path(__file__).resolve().parents[1]
SHARED_DATA = Path(os.environ.get("WS_SHARED_DATA", REPO.parent / "shared" / "data"))


def pytest_collection_modifyitems(config, items):
    if SHARED_DATA.is_dir():
        return
    skip = pytest.mark.skip(reason=f"real data folder {SHARED_DATA} is absent")
    for item in items:
        if "realdata" in item.keywords:
            item.add_marker(skip)


@pytest.fixture(scope="session")
def shared_data() -> Path:
    """Path of ../shared/data (or $WS_SHARED_DATA); tests using it are marked ``realdata``."""
    if not SHARED_DATA.is_dir():
        pytest.skip(f"real data folder {SHARED_DATA} is absent")
    return SHARED_DATA


@pytest.fixture
def rng() -> np.random.Generator:
    return np.random.default_rng(12345)


@pytest.fixture
def small_cloud(rng):
    """A 1000-point cloud with the common LAS attributes."""
    from workstation.core.cloud import Cloud

    n = 1000
    xyz = np.column_stack([rng.uniform(500000, 500100, n), rng.uniform(4e6, 4e6 + 100, n), rng.uniform(100, 130, n)])
    xyz = np.round(xyz, 3)
    rn = rng.integers(1, 4, n)
    return Cloud(
        xyz,
        {
            "intensity": rng.integers(0, 65535, n),
            "return_number": rn,
            "number_of_returns": np.maximum(rn, rng.integers(1, 4, n)),
            "classification": rng.choice([1, 2, 5, 6], n),
            "gps_time": np.round(rng.uniform(0, 1000, n), 6),
        },
        crs="EPSG:32632",
    )
