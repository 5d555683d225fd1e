"""Which obstacles a problem constrains: the K nearest to its bodies over the horizon.

A problem is built with ``safety.obstacle_slots`` (K) obstacle slots instead of one per
obstacle of the scene: each update, per problem, the obstacles are ranked by their smallest
predicted safety value h = ||p_xy - o|| - d over the horizon, taken over the problem's bodies
(payload and its robots) along both the warm-start trajectory and the reference, and the K
lowest fill the slots (free slots are parked far away). So every obstacle whose h gets within
its margin (h <= 0) over the horizon is kept as long as at most K do; when more do, the ones
left out are reported (``ObstacleSelection.dropped_near``), never silently lost.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.nmpc.cbf import OBSTACLE_PARAMETER_SIZE, PARKED_OBSTACLE


@dataclass(frozen=True)
class ObstacleSelection:
    """``indices``: obstacles in the slots, in scene order (a slot keeps its obstacle while
    the selection does not change); ``min_h_m``: each obstacle's
    smallest predicted h [m] (scene order); ``dropped_near``: obstacles left out although
    their predicted h fell below ``near_m``."""

    indices: np.ndarray
    min_h_m: np.ndarray
    dropped_near: tuple[int, ...]

    def parameters(self, obstacles: np.ndarray, slots: int) -> np.ndarray:
        """The slot parameter vector: selected rows, then parked slots, flattened."""
        rows = np.asarray(obstacles, dtype=float).reshape(-1, OBSTACLE_PARAMETER_SIZE)
        chosen = rows[self.indices]
        padding = np.tile(PARKED_OBSTACLE, (slots - chosen.shape[0], 1))
        return np.concatenate([chosen, padding]).reshape(-1)


def predicted_min_safety_values(positions_xy_m: np.ndarray, obstacles: np.ndarray,
                                sample_period_s: float) -> np.ndarray:
    """Smallest h [m] per obstacle over bodies and stages.

    ``positions_xy_m``: (bodies, N + 1, 2) planar positions at stages 0..N; ``obstacles``:
    (n_O, 5) rows (o_x, o_y, vo_x, vo_y, d) at stage 0, moving at constant velocity.
    """
    rows = np.asarray(obstacles, dtype=float).reshape(-1, OBSTACLE_PARAMETER_SIZE)
    stages = np.arange(positions_xy_m.shape[1]) * sample_period_s
    centres = rows[:, None, 0:2] + stages[None, :, None] * rows[:, None, 2:4]  # (n_O, N+1, 2)
    gaps = positions_xy_m[:, None, :, :] - centres[None, :, :, :]  # (bodies, n_O, N+1, 2)
    h = np.linalg.norm(gaps, axis=3) - rows[None, :, None, 4]
    return h.min(axis=(0, 2)) if rows.size else np.zeros(0)


def select_obstacles(positions_xy_m: np.ndarray, obstacles: np.ndarray, slots: int,
                     sample_period_s: float, near_m: float = 0.0) -> ObstacleSelection:
    """The ``slots`` obstacles with the smallest predicted h (see module docstring)."""
    min_h = predicted_min_safety_values(positions_xy_m, obstacles, sample_period_s)
    order = np.argsort(min_h, kind="stable")
    kept, left = order[:slots], order[slots:]
    dropped = tuple(int(i) for i in left if min_h[i] <= near_m)
    return ObstacleSelection(np.sort(kept), min_h, dropped)
