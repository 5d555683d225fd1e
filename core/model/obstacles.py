"""Planar obstacles as the controller sees them: a moving disc in the world frame."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Obstacle"]


@dataclass(frozen=True)
class Obstacle:
    """Planar obstacle: position [m] at t = 0, constant velocity [m/s], radius [m]."""

    position_m: tuple[float, float]
    velocity_m_s: tuple[float, float] = (0.0, 0.0)
    radius_m: float = 0.0

    def row(self, time_s: float, safety_distance_m: float) -> np.ndarray:
        """The NLP's obstacle parameters (o_x, o_y, vo_x, vo_y, d) at ``time_s`` [s]."""
        p = np.asarray(self.position_m) + time_s * np.asarray(self.velocity_m_s)
        return np.array([p[0], p[1], *self.velocity_m_s, safety_distance_m + self.radius_m])
