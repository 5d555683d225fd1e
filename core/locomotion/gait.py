"""Trot gait: contact schedule over the NMPC horizon and Raibert footholds.

Legs are ordered FL, FR, RL, RR. In a trot the diagonal pairs (FL, RR) and (FR, RL) alternate,
half a period apart. A leg is in stance while its phase is below the duty factor.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from core.model.rotations import yaw_rotation
from core.model.srb_model import SrbParameters

# Phase offsets of FL, FR, RL, RR in a trot.
TROT_OFFSETS = np.array([0.0, 0.5, 0.5, 0.0])
_OFFSETS = tuple(float(offset) for offset in TROT_OFFSETS)


@dataclass(frozen=True)
class TrotGait:
    """Periodic trot; ``period_s`` is one full gait cycle, ``duty_factor`` the stance fraction."""

    period_s: float = 0.3
    duty_factor: float = 0.5

    def contacts(self, time_s: float) -> np.ndarray:
        """(4,) stance flags at ``time_s``."""
        # four floats in Python: the same IEEE operations as np.mod over TROT_OFFSETS (a
        # float's % is floor-modulo as np.mod's), a few µs less per robot and 500 Hz tick
        cycles, duty = time_s / self.period_s, self.duty_factor
        return np.array([float((cycles + offset) % 1.0 < duty) for offset in _OFFSETS])

    def schedule(self, time_s: float, steps: int, sample_period_s: float) -> np.ndarray:
        """(steps, 4) stance flags at stages k = 0..steps-1 starting at ``time_s``."""
        return np.array([self.contacts(time_s + k * sample_period_s) for k in range(steps)])

    @property
    def stance_duration_s(self) -> float:
        return self.duty_factor * self.period_s

    @property
    def swing_duration_s(self) -> float:
        return (1.0 - self.duty_factor) * self.period_s

    def time_to_touchdown_s(self, time_s: float) -> np.ndarray:
        """(4,) time [s] until each leg's next touchdown (0 for legs in stance)."""
        phase = np.mod(time_s / self.period_s + TROT_OFFSETS, 1.0)
        return np.where(phase < self.duty_factor, 0.0, (1.0 - phase) * self.period_s)


@dataclass
class FootholdPlanner:
    """Keeps stance feet where they landed and places the next footholds with Raibert's rule:

    p_foot = p_hip(touchdown) + v_ref T_stance / 2 + k_v (v - v_ref), projected to the ground,
    with the hip position at touchdown predicted from the measured trunk state (footholds under
    the reference instead of the actual trunk let a lateral error run away).
    """

    robot: SrbParameters
    gait: TrotGait
    velocity_gain: float = 0.18  # ~sqrt(h / g): capture-point feedback on velocity error
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
        rotation = yaw_rotation(yaw)
        neutral = self.robot.nominal_feet_in_body_m
        if neutral is None:
            neutral = self.robot.hip_positions_in_body_m
        return state[0:3] + neutral @ rotation.T

    def _raibert(self, robot_state: np.ndarray, lead_time_s: float, velocity_ref: np.ndarray
                 ) -> np.ndarray:
        """Footholds for a touchdown ``lead_time_s`` from now: the measured hips carried forward
        at the measured velocity, plus Raibert's velocity terms, on the ground."""
        predicted = np.array(robot_state, dtype=float)
        predicted[0:3] = predicted[0:3] + lead_time_s * predicted[3:6]
        velocity = predicted[3:6]
        feet = self._hips(predicted) + velocity_ref * self.gait.stance_duration_s / 2 + (
            self.velocity_gain * (velocity - velocity_ref))
        feet[:, 2] = self.ground_height_m
        return feet

    def update(self, time_s: float, robot_state: np.ndarray, reference_state: np.ndarray,
               stance: np.ndarray | None = None) -> None:
        """Advance to ``time_s``: a leg that touches down now lands at its Raibert foothold.
        ``stance``: the gait's contacts at ``time_s`` when the caller has them."""
        if stance is None:
            stance = self.gait.contacts(time_s)
        landing = (stance == 1.0) & (self._stance == 0.0)
        if np.any(landing):
            target = self._raibert(robot_state, 0.0, reference_state[3:6])
            self.feet_in_world_m[landing] = target[landing]
        self._stance = stance

    def swing_targets(self, time_s: float, robot_state: np.ndarray,
                      velocity_reference: np.ndarray) -> np.ndarray:
        """(4, 3) touchdown targets [m] of each leg's next touchdown (Raibert, re-evaluated from
        the measured trunk ``robot_state`` with each leg's own time to touchdown)."""
        lead = np.asarray(self.gait.time_to_touchdown_s(time_s), dtype=float)
        # _raibert with each leg's own lead time, for all legs at once (the same arithmetic)
        state = np.asarray(robot_state, dtype=float)
        velocity = state[3:6]
        neutral = self.robot.nominal_feet_in_body_m
        if neutral is None:
            neutral = self.robot.hip_positions_in_body_m
        hips = (state[0:3] + lead[:, None] * velocity) + neutral @ yaw_rotation(state[8]).T
        feet = hips + velocity_reference * self.gait.stance_duration_s / 2 + (
            self.velocity_gain * (velocity - velocity_reference))
        feet[:, 2] = self.ground_height_m
        return feet

    def set_feet(self, feet_in_world_m: np.ndarray, mask: np.ndarray) -> None:
        """Overwrite the stored positions of the legs in ``mask`` (e.g. with measured
        touchdown points, so the NMPC's lever arms are the real ones)."""
        self.feet_in_world_m[mask] = np.asarray(feet_in_world_m)[mask]

    def horizon(self, time_s: float, steps: int, sample_period_s: float,
                robot_state: np.ndarray, reference_states: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray]:
        """Feet (steps, 4, 3) [m] and contacts (steps, 4) over the horizon.

        ``reference_states`` (steps, 12) are the robot's references at the stages; a leg that
        lands at stage k is placed by Raibert's rule for a touchdown k steps ahead.
        """
        contacts = self.gait.schedule(time_s, steps, sample_period_s)
        previous = np.vstack([self._stance[None], contacts[:-1]])
        landing = (contacts == 1.0) & (previous == 0.0)  # (steps, 4)
        feet = np.empty((steps, 4, 3))
        current = self.feet_in_world_m.copy()
        held_from = 0  # feet stay where they are between landings: fill those stages at once
        for k in np.flatnonzero(landing.any(axis=1)).tolist():
            feet[held_from:k] = current
            target = self._raibert(robot_state, k * sample_period_s, reference_states[k][3:6])
            current[landing[k]] = target[landing[k]]
            held_from = k
        feet[held_from:] = current
        return feet, contacts
