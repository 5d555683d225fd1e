"""Everything one NMPC decision reads, validated: the record that makes a decision replayable."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.model.srb_model import STATE_SIZE
from core.nmpc.cbf import OBSTACLE_PARAMETER_SIZE


class InvalidMpcInputError(ValueError):
    """An NMPC input has the wrong shape, is not finite, or is physically impossible."""


@dataclass(frozen=True)
class MpcInputs:
    """Inputs of one NMPC update, world frame, SI units.

    - ``robot_states``: (n_A, 12) measured robot SRB states (p, v, Theta, omega).
    - ``payload_state``: (12,) estimated payload SRB state.
    - ``robot_references`` (n_A, N, 12) and ``payload_reference`` (N, 12): desired states at
      stages 1..N.
    - ``feet_positions``: (n_A, N, 4, 3) foot positions [m] per stage (legs FL, FR, RL, RR).
    - ``contacts``: (n_A, N, 4) stance flags (1 stance, 0 swing) per stage.
    - ``obstacles``: (n_O, 5) rows (o_x, o_y, vo_x, vo_y, safety distance) at the current time.
    """

    robot_states: np.ndarray
    payload_state: np.ndarray
    robot_references: np.ndarray
    payload_reference: np.ndarray
    feet_positions: np.ndarray
    contacts: np.ndarray
    obstacles: np.ndarray

    def validate(self, agent_count: int, horizon_steps: int, max_obstacles: int) -> None:
        """Raise ``InvalidMpcInputError`` naming the first bad field."""
        n, na = horizon_steps, agent_count
        expected = {
            "robot_states": (na, STATE_SIZE),
            "payload_state": (STATE_SIZE,),
            "robot_references": (na, n, STATE_SIZE),
            "payload_reference": (n, STATE_SIZE),
            "feet_positions": (na, n, 4, 3),
            "contacts": (na, n, 4),
        }
        for field, shape in expected.items():
            value = np.asarray(getattr(self, field))
            if value.shape != shape:
                raise InvalidMpcInputError(f"{field}: expected shape {shape}, got {value.shape}")
            if not np.all(np.isfinite(value)):
                raise InvalidMpcInputError(f"{field}: contains NaN or infinite values")
        obstacles = np.asarray(self.obstacles)
        if obstacles.ndim != 2 or obstacles.shape[1] != OBSTACLE_PARAMETER_SIZE:
            raise InvalidMpcInputError(
                f"obstacles: expected shape (n, {OBSTACLE_PARAMETER_SIZE}), got {obstacles.shape}"
            )
        if obstacles.shape[0] > max_obstacles:
            raise InvalidMpcInputError(
                f"obstacles: {obstacles.shape[0]} given, the problem was built for at most "
                f"{max_obstacles} (safety.max_obstacles)"
            )
        if not np.all(np.isfinite(obstacles)):
            raise InvalidMpcInputError("obstacles: contains NaN or infinite values")
        contacts = np.asarray(self.contacts)
        if not np.all((contacts == 0.0) | (contacts == 1.0)):
            raise InvalidMpcInputError("contacts: flags must be 0 or 1")

    def safety_values(self) -> np.ndarray:
        """h = ||p_xy - o|| - d [m] of every body (payload first, then robots) vs every obstacle,
        at the current time: shape (1 + n_A, n_O)."""
        positions = np.vstack([self.payload_state[None, 0:2], self.robot_states[:, 0:2]])
        obstacles = np.asarray(self.obstacles, dtype=float).reshape(-1, OBSTACLE_PARAMETER_SIZE)
        gaps = positions[:, None, :] - obstacles[None, :, 0:2]
        return np.linalg.norm(gaps, axis=2) - obstacles[None, :, 4]
