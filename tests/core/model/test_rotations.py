"""The hot paths' shortcuts give the same bits as the general functions: the cross products
as ``np.cross``, the yaw as the Euler angles of the rotation matrix."""

from __future__ import annotations

import numpy as np

from core.model.rotations import (
    cross3,
    cross_rows,
    euler_from_rotation,
    rotation_from_quaternion_wxyz,
    yaw_from_quaternion_wxyz,
)


def test_cross3_and_cross_rows_are_bit_identical_to_numpy() -> None:
    rng = np.random.default_rng(7)
    for _ in range(500):
        scale = 10.0 ** rng.uniform(-6, 4)
        a, b = rng.normal(size=(4, 3)) * scale, rng.normal(size=(4, 3))
        assert np.array_equal(cross_rows(a, b), np.cross(a, b))
        assert np.array_equal(cross_rows(a[0], b), np.cross(a[0], b))  # broadcast one row
        assert np.array_equal(cross_rows(a, b[1]), np.cross(a, b[1]))
        assert np.array_equal(cross3(a[2], b[3]), np.cross(a[2], b[3]))
    assert cross_rows(np.zeros((0, 3)), np.zeros((0, 3))).shape == (0, 3)


def test_yaw_from_quaternion_is_bit_identical_to_the_euler_angles() -> None:
    rng = np.random.default_rng(11)
    quaternions = rng.normal(size=(20000, 4)) * rng.uniform(0.5, 2.0, size=(20000, 1))
    quaternions[0] = (1.0, 0.0, 0.0, 0.0)
    quaternions[1] = (0.0, 0.0, 0.0, 1.0)  # yaw pi
    quaternions[2] = (0.0, 1.0, 0.0, 0.0)  # roll pi: R[0, 0] = 1, R[1, 0] = 0
    for quaternion in quaternions:
        expected = euler_from_rotation(rotation_from_quaternion_wxyz(quaternion))[2]
        assert yaw_from_quaternion_wxyz(quaternion) == expected
    assert yaw_from_quaternion_wxyz([0.0, 0.0, 0.0, 2.0]) == np.pi
