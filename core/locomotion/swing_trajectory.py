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

# Coefficients of s^0 .. s^6 (rows) of m, dm/ds, d2m/ds2, b, db/ds, d2b/ds2 (columns), with
# b(s) = 64 (s^3 - 3 s^4 + 3 s^5 - s^6): all six for all legs in one product with the powers.
POLYNOMIALS = np.array([
    #  m      dm     ddm      b      db      ddb
    [0.0,    0.0,    0.0,    0.0,    0.0,     0.0],
    [0.0,    0.0,   60.0,    0.0,    0.0,   384.0],
    [0.0,   30.0, -180.0,    0.0,  192.0, -2304.0],
    [10.0, -60.0,  120.0,   64.0, -768.0,  3840.0],
    [-15.0, 30.0,    0.0, -192.0,  960.0, -1920.0],
    [6.0,    0.0,    0.0,  192.0, -384.0,     0.0],
    [0.0,    0.0,    0.0,  -64.0,    0.0,     0.0],
])
_POWERS = np.arange(7)


@dataclass(frozen=True)
class SwingPoint:
    """Desired foot position [m], velocity [m/s] and acceleration [m/s^2], world frame."""

    position_m: np.ndarray
    velocity_m_s: np.ndarray
    acceleration_m_s2: np.ndarray


def swing_point(liftoff_m: np.ndarray, touchdown_m: np.ndarray, progress: float | np.ndarray,
                duration_s: float, height_m: float) -> SwingPoint:
    """Foot set-point at ``progress`` in [0, 1] of a swing of ``duration_s`` [s]; ``progress``
    (n,) with lift-off and touchdown points (n, 3) gives n legs' set-points at once."""
    if duration_s <= 0:
        raise ValueError(f"swing duration must be positive, got {duration_s}")
    s = np.minimum(np.maximum(progress, 0.0), 1.0)
    # (..., 6): m, dm, ddm, b, db, ddb with the derivatives in time (1/T, 1/T^2 per order)
    scale = np.array([1.0, 1.0 / duration_s, duration_s**-2.0] * 2)
    values = (np.power.outer(s, _POWERS) @ POLYNOMIALS) * scale
    start = np.asarray(liftoff_m, dtype=float)
    delta = np.asarray(touchdown_m, dtype=float) - start
    # (..., 3 orders, 3 axes): delta times m's three, plus the lift (z only) times b's three
    motion = values[..., 0:3, None] * delta[..., None, :]
    motion[..., 2] += height_m * values[..., 3:6]
    motion[..., 0, :] += start
    return SwingPoint(motion[..., 0, :], motion[..., 1, :], motion[..., 2, :])
