"""Reference trajectories: the payload follows waypoints at a constant speed; each robot's
reference keeps its coupling point on the payload's coupling point with the payload's yaw."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from core.model.rotations import cross_rows
from core.model.srb_model import STATE_SIZE
from core.model.team import TeamModel


@dataclass(frozen=True)
class WaypointReference:
    """Piecewise-linear payload path through ``waypoints_m`` (n, 2) at ``speed_m_s``, at a
    constant height and yaw [rad]."""

    waypoints_m: np.ndarray
    speed_m_s: float
    height_m: float
    yaw_rad: float = 0.0

    @cached_property
    def _segments(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(points, segments, lengths) of the path, computed once (the NMPC asks for the
        reference at every stage of every decision)."""
        points = np.asarray(self.waypoints_m, dtype=float)
        segments = np.diff(points, axis=0)
        return points, segments, np.linalg.norm(segments, axis=1)

    def payload_state(self, time_s: float) -> np.ndarray:
        points, segments, lengths = self._segments
        distance = self.speed_m_s * max(time_s, 0.0)
        state = np.zeros(STATE_SIZE)
        state[2] = self.height_m
        state[8] = self.yaw_rad
        for start, segment, length in zip(points[:-1], segments, lengths, strict=True):
            if distance <= length and length > 0:
                direction = segment / length
                state[0:2] = start + direction * distance
                state[3:5] = direction * self.speed_m_s
                return state
            distance -= length
        state[0:2] = points[-1]
        return state

    def goal_m(self) -> np.ndarray:
        return np.asarray(self.waypoints_m, dtype=float)[-1]


@dataclass(frozen=True)
class BrakingReference:
    """The braking backup's payload reference: from ``position_m`` (2,) moving at
    ``velocity_m_s`` (2,) at ``start_time_s`` (reference time [s]), decelerate at
    ``deceleration_m_s2`` along that heading to rest, then hold the position reached; constant
    height [m] and yaw [rad] (the measured yaw: the team does not turn while it brakes)."""

    start_time_s: float
    position_m: np.ndarray
    velocity_m_s: np.ndarray
    height_m: float
    yaw_rad: float
    deceleration_m_s2: float

    def payload_state(self, time_s: float) -> np.ndarray:
        speed = float(np.linalg.norm(self.velocity_m_s))
        direction = np.asarray(self.velocity_m_s, float) / speed if speed > 0 else np.zeros(2)
        elapsed = min(max(time_s - self.start_time_s, 0.0), speed / self.deceleration_m_s2)
        state = np.zeros(STATE_SIZE)
        state[0:2] = np.asarray(self.position_m, float) + direction * (
            speed * elapsed - 0.5 * self.deceleration_m_s2 * elapsed ** 2)
        state[2] = self.height_m
        state[3:5] = direction * (speed - self.deceleration_m_s2 * elapsed)
        state[8] = self.yaw_rad
        return state

    def goal_m(self) -> np.ndarray:
        """Where the payload comes to rest [m]."""
        return self.payload_state(np.inf)[0:2]


def robot_state_from_payload(team: TeamModel, agent: int, payload_state: np.ndarray
                             ) -> np.ndarray:
    """Robot state whose coupling point coincides with the payload's, same yaw, level trunk.

    Valid for a level payload (roll = pitch = 0) turning about z only, as the references are.
    """
    return robot_states_from_payload(team, agent, np.asarray(payload_state)[None])[0]


def robot_states_from_payload(team: TeamModel, agent: int, payload_states: np.ndarray
                              ) -> np.ndarray:
    """``robot_state_from_payload`` of every row of ``payload_states`` (S, 12) at once: (S, 12)
    (the NMPC asks for a horizon of them per agent at each decision)."""
    payload = np.asarray(payload_states, dtype=float)
    yaw = payload[:, 8]
    cos, sin = np.cos(yaw), np.sin(yaw)

    def rotated(vector: np.ndarray) -> np.ndarray:  # Rz(yaw) @ vector for every row's yaw
        x, y, z = (float(v) for v in vector)
        return np.stack([cos * x - sin * y, sin * x + cos * y, np.full_like(yaw, z)], axis=1)

    in_robot = rotated(team.coupling_points_in_robot_m[agent])
    in_payload = rotated(team.coupling_points_in_payload_m[agent])  # from the payload origin
    states = np.zeros((len(payload), STATE_SIZE))
    states[:, 0:3] = payload[:, 0:3] + in_payload - in_robot
    point_velocity = payload[:, 3:6] + cross_rows(payload[:, 9:12], in_payload)
    omega = np.zeros((len(payload), 3))
    omega[:, 2] = payload[:, 11]  # level trunk turning with the payload
    states[:, 3:6] = point_velocity - cross_rows(omega, in_robot)
    states[:, 8] = yaw
    states[:, 11] = payload[:, 11]
    return states


def horizon_references(team: TeamModel, reference: WaypointReference | BrakingReference,
                       time_s: float,
                       steps: int, sample_period_s: float) -> tuple[np.ndarray, np.ndarray]:
    """Robot references (n_A, steps, 12) and payload reference (steps, 12) at stages 1..steps."""
    payload = np.array([reference.payload_state(time_s + k * sample_period_s)
                        for k in range(1, steps + 1)])
    robots = np.array([robot_states_from_payload(team, i, payload)
                       for i in range(team.agent_count)])
    return robots, payload
