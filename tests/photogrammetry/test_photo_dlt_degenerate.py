"""DLT calibration refuses degenerate control points and unphysical cameras."""

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.products import Camera
from workstation.photogrammetry import calibration as cal
from workstation.photogrammetry.collinearity import pose_from_opk, project

CAM = Camera(1000, 800, 1500.0, 1500.0, 500.0, 400.0)
X = np.random.default_rng(0).uniform(-5, 5, (10, 3))
UV = project(X, CAM, pose_from_opk(0.1, 0.05, -0.2, [1.0, 2.0, 30.0]))


def test_exact_points_still_calibrate():
    r = cal.calibrate_dlt(X, UV, (1000, 800))
    assert abs(r.camera.fx - 1500.0) < 1e-6


@pytest.mark.parametrize("label, X_, uv, match", [
    ("repeated rows", np.vstack([X[:4]] * 3), np.vstack([UV[:4]] * 3), "6 distinct"),
    ("pixels on a line", X, np.column_stack([np.linspace(0, 100, 10), np.linspace(0, 50, 10)]), "on one line"),
    ("one pixel", X, np.full((10, 2), 5.0), "same pixel"),
    ("nan", X, np.where(np.arange(10)[:, None] == 3, np.nan, UV), "non-finite"),
    ("coplanar", X * [1, 1, 0], UV, "coplanar"),
])
def test_degenerate_control_points_are_refused(label, X_, uv, match):
    with pytest.raises(InvalidInputError, match=match):
        cal.calibrate_dlt(X_, uv, (1000, 800))


def test_pixels_that_do_not_belong_to_the_points_give_no_camera():
    uv = np.random.default_rng(1).uniform(0, 1000, (10, 2))
    with pytest.raises(StageError, match="not physical"):
        cal.calibrate_dlt(X, uv, (1000, 800))
