"""Georeferencing chain: homogeneous transforms, inverse round trip, rotation conventions."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.lidar.georef import (
    R_MAP_FROM_NED,
    GeorefChain,
    beam_direction,
    homogeneous,
    invert,
    matrix_to_rpy,
    rot_x,
    rot_y,
    rot_z,
    rotate_rpy,
    rpy_matrix,
)


def test_rpy_matrix_is_z_y_x_sequence_and_inverts(rng):
    rpy = rng.uniform([-0.5, -0.5, -3.0], [0.5, 0.5, 3.0], (50, 3))
    R = rpy_matrix(rpy[:, 0], rpy[:, 1], rpy[:, 2])
    ref = rot_z(rpy[:, 2]) @ rot_y(rpy[:, 1]) @ rot_x(rpy[:, 0])
    np.testing.assert_allclose(R, ref, atol=1e-12)
    np.testing.assert_allclose(matrix_to_rpy(R), rpy, atol=1e-12)
    v = rng.normal(size=(50, 3))
    np.testing.assert_allclose(rotate_rpy(rpy, v), np.einsum("nij,nj->ni", R, v), atol=1e-12)
    np.testing.assert_allclose(rotate_rpy(rpy, rotate_rpy(rpy, v), inverse=True), v, atol=1e-12)


def test_yaw_is_heading_clockwise_from_north():
    # body x (forward) of an aircraft heading 90 degrees points east in the map frame
    fwd = R_MAP_FROM_NED @ rpy_matrix(0.0, 0.0, np.pi / 2) @ np.array([1.0, 0.0, 0.0])
    np.testing.assert_allclose(fwd, [1.0, 0.0, 0.0], atol=1e-12)
    # positive roll lowers the right wing: body y (right) gets a downward (negative up) component
    right = R_MAP_FROM_NED @ rpy_matrix(0.1, 0.0, 0.0) @ np.array([0.0, 1.0, 0.0])
    assert right[2] < 0


def test_forward_equals_homogeneous_chain_and_inverse_round_trips(rng):
    chain = GeorefChain(lever_arm=(0.3, -0.1, 0.5), boresight=(0.002, -0.003, 0.01))
    n = 200
    pos = rng.uniform(-100, 100, (n, 3)) + [0, 0, 800]
    rpy = rng.uniform([-0.1, -0.1, -np.pi], [0.1, 0.1, np.pi], (n, 3))
    d = beam_direction(rng.uniform(-0.4, 0.4, n), rng.uniform(-0.1, 0.1, n))
    r = rng.uniform(300, 1200, n)
    x = chain.forward(r, d, pos, rpy)
    # the same through the 4x4 matrices laser -> scanner -> body -> level -> map
    T = chain.matrix(pos, rpy)
    xh = np.einsum("nij,nj->ni", T, np.column_stack([r[:, None] * d, np.ones(n)]))[:, :3]
    np.testing.assert_allclose(x, xh, atol=1e-9)
    r2, d2 = chain.inverse(x, pos, rpy)
    np.testing.assert_allclose(r2, r, rtol=0, atol=1e-9)
    np.testing.assert_allclose(d2, d, atol=1e-12)
    # invert() undoes a transform
    np.testing.assert_allclose(invert(T) @ T, np.broadcast_to(np.eye(4), T.shape), atol=1e-9)


def test_nadir_beam_of_level_aircraft_points_straight_down():
    chain = GeorefChain()
    x = chain.forward(np.array([500.0]), beam_direction(np.array([0.0])), np.array([[10.0, 20.0, 600.0]]),
                      np.array([[0.0, 0.0, 1.0]]))
    np.testing.assert_allclose(x, [[10.0, 20.0, 100.0]], atol=1e-9)


def test_beam_direction_right_is_east_when_flying_north():
    chain = GeorefChain()
    x = chain.forward(np.array([100.0]), beam_direction(np.array([np.radians(30)])), np.zeros((1, 3)), np.zeros((1, 3)))
    assert x[0, 0] == pytest.approx(50.0) and x[0, 2] == pytest.approx(-100 * np.cos(np.radians(30)))


def test_homogeneous_shape_and_bad_mount():
    T = homogeneous(np.eye(3), [1, 2, 3])
    assert T.shape == (4, 4) and T[3, 3] == 1 and T[0, 3] == 1
    with pytest.raises(InvalidInputError):
        GeorefChain(lever_arm=(0.0, 1.0))
