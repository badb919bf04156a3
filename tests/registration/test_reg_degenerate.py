"""Registration refuses clouds and voxel sizes Open3D cannot use, before calling it."""

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.registration.register import RegisterParams, register


@pytest.fixture(scope="module")
def pair():
    rng = np.random.default_rng(0)
    x = rng.uniform(0, 10, (2000, 3))
    x[:, 2] = np.sin(x[:, 0]) + 0.3 * x[:, 1]
    return Cloud(x + [0.2, 0.1, 0.0]), Cloud(x)


def test_a_voxel_too_small_for_open3d_is_refused(pair):
    with pytest.raises(InvalidInputError, match="too small") as e:
        register(*pair, RegisterParams(voxel_size=1e-9))
    assert e.value.field == "voxel_size" and "--voxel-size" in e.value.hint


def test_a_voxel_leaving_under_three_points_is_refused(pair):
    with pytest.raises(InvalidInputError, match="leaves 1 point"):
        register(*pair, RegisterParams(voxel_size=100.0, method="fpfh_ransac"))


def test_one_repeated_point_is_refused(pair):
    same = Cloud(np.tile([1.0, 2.0, 3.0], (50, 1)), meta={"source": "same.ply"})
    with pytest.raises(InvalidInputError, match="same point") as e:
        register(same, pair[1])
    assert "same.ply" in str(e.value)
