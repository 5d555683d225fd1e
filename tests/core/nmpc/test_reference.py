"""core.nmpc.reference: the robots' references from the payload's, a horizon at once."""

from __future__ import annotations

import numpy as np

from core.model.rotations import cross3, yaw_rotation
from core.model.srb_model import STATE_SIZE
from core.model.team import TeamModel
from core.nmpc.reference import (
    WaypointReference,
    horizon_references,
    robot_state_from_payload,
    robot_states_from_payload,
)
from tests.core.controller_fixtures import team


def stage_by_stage(team_model: TeamModel, agent: int, payload_state: np.ndarray) -> np.ndarray:
    """The per-stage formulation the vectorized one replaced (the reference here)."""
    rotation = yaw_rotation(payload_state[8])
    state = np.zeros(STATE_SIZE)
    point = payload_state[0:3] + rotation @ team_model.coupling_points_in_payload_m[agent]
    state[0:3] = point - rotation @ team_model.coupling_points_in_robot_m[agent]
    point_velocity = payload_state[3:6] + cross3(payload_state[9:12], point - payload_state[0:3])
    omega = np.array([0.0, 0.0, payload_state[11]])
    state[3:6] = point_velocity - cross3(
        omega, rotation @ team_model.coupling_points_in_robot_m[agent])
    state[8] = payload_state[8]
    state[11] = payload_state[11]
    return state


def test_vectorized_robot_states_equal_the_stage_by_stage_formulation() -> None:
    rng = np.random.default_rng(3)
    for types in (("go2", "go2"), ("go2", "go2", "a1")):
        team_model = team(types)
        payload = rng.normal(size=(20, STATE_SIZE))
        payload[:, 8] = rng.uniform(-4.0, 4.0, size=20)  # yaws beyond +-pi too
        for agent in range(team_model.agent_count):
            expected = np.array([stage_by_stage(team_model, agent, x) for x in payload])
            states = robot_states_from_payload(team_model, agent, payload)
            np.testing.assert_allclose(states, expected, rtol=0.0, atol=1e-12)
            single = robot_state_from_payload(team_model, agent, payload[5])
            np.testing.assert_allclose(single, expected[5], rtol=0.0, atol=1e-12)


def test_robot_state_keeps_the_coupling_points_together() -> None:
    """The robot's coupling point lands on the payload's, in world coordinates."""
    team_model = team()
    payload = np.zeros(STATE_SIZE)
    payload[0:3], payload[8] = (1.0, -2.0, 0.5), 0.7
    rotation = yaw_rotation(0.7)
    for agent in range(team_model.agent_count):
        state = robot_state_from_payload(team_model, agent, payload)
        on_robot = state[0:3] + rotation @ team_model.coupling_points_in_robot_m[agent]
        on_payload = payload[0:3] + rotation @ team_model.coupling_points_in_payload_m[agent]
        np.testing.assert_allclose(on_robot, on_payload, atol=1e-12)
        assert state[8] == 0.7


def test_horizon_references_follow_the_payload_reference() -> None:
    team_model = team()
    reference = WaypointReference(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]), 0.5, 0.45,
                                  yaw_rad=0.3)
    robots, payload = horizon_references(team_model, reference, 1.5, 16, 0.05)
    assert robots.shape == (2, 16, STATE_SIZE) and payload.shape == (16, STATE_SIZE)
    for k in range(16):
        np.testing.assert_array_equal(payload[k], reference.payload_state(1.5 + (k + 1) * 0.05))
        for agent in range(2):
            np.testing.assert_allclose(robots[agent, k],
                                       stage_by_stage(team_model, agent, payload[k]),
                                       rtol=0.0, atol=1e-12)
