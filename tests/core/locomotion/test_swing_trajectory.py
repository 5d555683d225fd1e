"""Swing-foot trajectory: boundary conditions, apex height, derivatives."""

from __future__ import annotations

import numpy as np
import pytest

from core.locomotion.swing_trajectory import swing_point

START = np.array([0.1, -0.2, 0.0])
END = np.array([0.3, -0.15, 0.01])


def test_starts_and_ends_at_rest_on_the_footholds() -> None:
    first = swing_point(START, END, 0.0, 0.15, 0.08)
    last = swing_point(START, END, 1.0, 0.15, 0.08)
    np.testing.assert_allclose(first.position_m, START)
    np.testing.assert_allclose(last.position_m, END)
    for point in (first, last):
        np.testing.assert_allclose(point.velocity_m_s, 0.0, atol=1e-12)
        np.testing.assert_allclose(point.acceleration_m_s2, 0.0, atol=1e-9)


def test_apex_clears_the_line_by_the_swing_height() -> None:
    middle = swing_point(START, END, 0.5, 0.15, 0.08)
    assert middle.position_m[2] == pytest.approx((START[2] + END[2]) / 2 + 0.08)
    np.testing.assert_allclose(middle.position_m[0:2], (START[0:2] + END[0:2]) / 2)


def test_velocity_and_acceleration_are_time_derivatives() -> None:
    duration, eps = 0.15, 1e-6
    for progress in (0.2, 0.5, 0.8):
        point = swing_point(START, END, progress, duration, 0.08)
        ahead = swing_point(START, END, progress + eps / duration, duration, 0.08)
        behind = swing_point(START, END, progress - eps / duration, duration, 0.08)
        np.testing.assert_allclose(point.velocity_m_s,
                                   (ahead.position_m - behind.position_m) / (2 * eps), atol=1e-6)
        np.testing.assert_allclose(point.acceleration_m_s2,
                                   (ahead.velocity_m_s - behind.velocity_m_s) / (2 * eps),
                                   atol=1e-4)


def test_rejects_non_positive_duration() -> None:
    with pytest.raises(ValueError, match="duration"):
        swing_point(START, END, 0.5, 0.0, 0.08)


def test_legs_at_once_equal_one_leg_at_a_time() -> None:
    rng = np.random.default_rng(1)
    starts, ends = rng.normal(size=(3, 3)), rng.normal(size=(3, 3))
    progress = np.array([-0.1, 0.37, 1.2])  # clipped to [0, 1] like a single leg's
    together = swing_point(starts, ends, progress, 0.15, 0.08)
    for leg in range(3):
        alone = swing_point(starts[leg], ends[leg], float(progress[leg]), 0.15, 0.08)
        for field in ("position_m", "velocity_m_s", "acceleration_m_s2"):
            # to round-off: NumPy's vector kernels (SIMD width by CPU) may order a sum
            # differently from the scalar path
            np.testing.assert_allclose(getattr(together, field)[leg], getattr(alone, field),
                                       rtol=1e-14, atol=1e-14)
