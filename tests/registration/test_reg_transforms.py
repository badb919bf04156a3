import sys
from pathlib import Path

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.registration.transforms import (
    apply_transform, invert, make_transform, random_rotation, register_point_pairs, transform_error, umeyama)


def test_point_pairs_recover_rigid_transform_and_report_residuals(rng):
    R = random_rotation(rng)
    t = np.array([512.3, -41.0, 7.5])
    src = rng.uniform(-10, 10, (6, 3))
    noise = rng.normal(0, 0.002, (6, 3))
    dst = src @ R.T + t + noise
    fit = register_point_pairs(src, dst)
    rot_err, tr_err = transform_error(fit.result.transform, make_transform(R, t))
    assert rot_err < 0.05 and tr_err < 0.01
    # residuals are target - T(source), consistent with the reported RMSE
    assert np.allclose(fit.residuals, dst - apply_transform(fit.result.transform, src))
    assert fit.result.inlier_rmse == pytest.approx(np.sqrt(np.mean(fit.residual_norms**2)))
    assert 0.0005 < fit.result.inlier_rmse < 0.005
    assert fit.result.meta["dof_left"] == 3 * 6 - 6
    assert fit.result.scale == 1.0


def test_point_pairs_exact_with_three_points():
    src = np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0]])
    T = make_transform(random_rotation(np.random.default_rng(3)), [1.0, 2.0, 3.0])
    fit = register_point_pairs(src, apply_transform(T, src))
    assert np.allclose(fit.result.transform, T, atol=1e-10)
    assert fit.result.inlier_rmse < 1e-10


def test_seven_dof_pairs_recover_scale(rng):
    R = random_rotation(rng)
    s = 3.7
    src = rng.normal(size=(10, 3))
    dst = s * src @ R.T + [10.0, 20.0, 30.0]
    fit = register_point_pairs(src, dst, with_scale=True)
    assert fit.result.scale == pytest.approx(s, rel=1e-9)
    rigid = register_point_pairs(src, dst)
    assert rigid.result.inlier_rmse > 1.0  # a rigid fit cannot explain a scale change


def test_point_pairs_refuse_collinear_and_too_few():
    line = np.column_stack([np.arange(4.0), np.zeros(4), np.zeros(4)])
    with pytest.raises(InvalidInputError, match="collinear"):
        register_point_pairs(line, line + 1)
    with pytest.raises(InvalidInputError):
        umeyama(line[:2], line[:2])


def test_umeyama_never_returns_a_reflection(rng):
    src = rng.normal(size=(20, 3))
    dst = src * [1, 1, -1]  # a mirror image: the best proper rotation is not the reflection
    R, _, _ = umeyama(src, dst)
    assert np.linalg.det(R) == pytest.approx(1.0)


def test_invert_similarity(rng):
    T = make_transform(random_rotation(rng), rng.normal(size=3), 2.5)
    assert np.allclose(invert(T) @ T, np.eye(4), atol=1e-12)
