"""Swing-foot trajectory: from the lift-off point to the touchdown target with a swing height.

World frame, SI units. With normalized time s = (t - t_liftoff) / T_swing in [0, 1]:

    horizontal:  p_xy(s) = p0 + (p1 - p0) m(s),       m(s) = 10 s^3 - 15 s^4 + 6 s^5 (min-jerk)
    vertical:    p_z(s)  = z0 + (z1 - z0) m(s) + H b(s),   b(s) = 64 s^3 (1 - s)^3

m has zero velocity and acceleration at both ends and b peaks at b(1/2) = 1, so the foot leaves
and lands with zero velocity and acceleration and clears the straight line by the swing height H.
The touchdown target may move during the swing (Raibert's rule is re-evaluated each tick); the
trajectory is then re-evaluated from the same lift-off point, which is smooth while the target
moves smoothly.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def _min_jerk(s: float) -> tuple[float, float, float]:
    """m(s), dm/ds, d2m/ds2."""
    return (10 * s**3 - 15 * s**4 + 6 * s**5, 30 * s**2 - 60 * s**3 + 30 * s**4,
            60 * s - 180 * s**2 + 120 * s**3)


def _bump(s: float) -> tuple[float, float, float]:
    """b(s) = 64 s^3 (1 - s)^3 and its first two derivatives in s."""
    u = 1.0 - s
    return (64 * s**3 * u**3, 192 * s**2 * u**2 * (u - s),
            384 * s * u * (u * u - 3 * s * u + s * s))


@dataclass(frozen=True)
class SwingPoint:
    """Desired foot position [m], velocity [m/s] and acceleration [m/s^2], world frame."""

    position_m: np.ndarray
    velocity_m_s: np.ndarray
    acceleration_m_s2: np.ndarray


def swing_point(liftoff_m: np.ndarray, touchdown_m: np.ndarray, progress: float,
                duration_s: float, height_m: float) -> SwingPoint:
    """Foot set-point at ``progress`` in [0, 1] of a swing of ``duration_s`` [s]."""
    if duration_s <= 0:
        raise ValueError(f"swing duration must be positive, got {duration_s}")
    s = float(np.clip(progress, 0.0, 1.0))
    m, dm, ddm = _min_jerk(s)
    b, db, ddb = _bump(s)
    start = np.asarray(liftoff_m, dtype=float)
    delta = np.asarray(touchdown_m, dtype=float) - start
    up = np.array([0.0, 0.0, height_m])
    position = start + delta * m + up * b
    velocity = (delta * dm + up * db) / duration_s
    acceleration = (delta * ddm + up * ddb) / duration_s**2
    return SwingPoint(position, velocity, acceleration)
