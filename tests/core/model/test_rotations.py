"""The cross products of the hot paths give the same bits as ``np.cross``."""

from __future__ import annotations

import numpy as np

from core.model.rotations import cross3, cross_rows


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
