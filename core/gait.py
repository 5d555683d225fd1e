"""Trot gait: contact schedule over the NMPC horizon and Raibert footholds.

Legs are ordered FL, FR, RL, RR. In a trot the diagonal pairs (FL, RR) and (FR, RL) alternate,
half a period apart. A leg is in stance while its phase is below the duty factor.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from core.srb_model import SrbParameters

# Phase offsets of FL, FR, RL, RR in a trot.
TROT_OFFSETS = np.array([0.0, 0.5, 0.5, 0.0])


@dataclass(frozen=True)
class TrotGait:
    """Periodic trot; ``period_s`` is one full gait cycle, ``duty_factor`` the stance fraction."""

    period_s: float = 0.3
    duty_factor: float = 0.5

    def contacts(self, time_s: float) -> np.ndarray:
        """(4,) stance flags at ``time_s``."""
        phase = np.mod(time_s / self.period_s + TROT_OFFSETS, 1.0)
        return (phase < self.duty_factor).astype(float)

    def schedule(self, time_s: float, steps: int, sample_period_s: float) -> np.ndarray:
        """(steps, 4) stance flags at stages k = 0..steps-1 starting at ``time_s``."""
        return np.array([self.contacts(time_s + k * sample_period_s) for k in range(steps)])

    @property
    def stance_duration_s(self) -> float:
        return self.duty_factor * self.period_s


@dataclass
class FootholdPlanner:
    """Keeps stance feet where they landed and places the next footholds with Raibert's rule:

    p_foot = p_hip(touchdown) + v_ref T_stance / 2 + k_v (v - v_ref), projected to the ground.
    """

    robot: SrbParameters
    gait: TrotGait
    velocity_gain: float = 0.03
    ground_height_m: float = 0.0
    feet_in_world_m: np.ndarray = field(default_factory=lambda: np.zeros((4, 3)))
    _stance: np.ndarray = field(default_factory=lambda: np.ones(4))

    def reset(self, robot_state: np.ndarray) -> None:
        """Put all feet under the hips of ``robot_state`` (12,)."""
        self.feet_in_world_m = self._hips(robot_state)
        self.feet_in_world_m[:, 2] = self.ground_height_m
        self._stance = np.ones(4)

    def _hips(self, state: np.ndarray) -> np.ndarray:
        """Neutral footholds under the hips (standing foot positions) for a trunk at ``state``."""
        yaw = state[8]
        c, s = np.cos(yaw), np.sin(yaw)
        rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        neutral = self.robot.nominal_feet_in_body_m
        if neutral is None:
            neutral = self.robot.hip_positions_in_body_m
        return state[0:3] + neutral @ rotation.T

    def _raibert(self, reference_state: np.ndarray, measured_velocity: np.ndarray) -> np.ndarray:
        hips = self._hips(reference_state)
        v_ref = reference_state[3:6]
        offset = v_ref * self.gait.stance_duration_s / 2 + self.velocity_gain * (
            measured_velocity - v_ref)
        feet = hips + offset
        feet[:, 2] = self.ground_height_m
        return feet

    def update(self, time_s: float, robot_state: np.ndarray, reference_state: np.ndarray) -> None:
        """Advance to ``time_s``: a leg that touches down now lands at its Raibert foothold."""
        stance = self.gait.contacts(time_s)
        landing = (stance == 1.0) & (self._stance == 0.0)
        if np.any(landing):
            target = self._raibert(reference_state, robot_state[3:6])
            self.feet_in_world_m[landing] = target[landing]
        self._stance = stance

    def horizon(self, time_s: float, steps: int, sample_period_s: float,
                robot_state: np.ndarray, reference_states: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray]:
        """Feet (steps, 4, 3) [m] and contacts (steps, 4) over the horizon.

        ``reference_states`` (steps, 12) are the robot's references at the stages; a leg that
        lands at stage k uses the Raibert foothold computed from stage k's reference.
        """
        contacts = self.gait.schedule(time_s, steps, sample_period_s)
        feet = np.empty((steps, 4, 3))
        current = self.feet_in_world_m.copy()
        previous = self._stance.copy()
        for k in range(steps):
            landing = (contacts[k] == 1.0) & (previous == 0.0)
            if np.any(landing):
                target = self._raibert(reference_states[k], robot_state[3:6])
                current[landing] = target[landing]
            feet[k] = current
            previous = contacts[k]
        return feet, contacts
