"""Capability limits: the robots' planned CoM speed per horizontal axis and CoM height are
bounded from ``from_stage`` on, widened to what the measured state reaches, and a plan that
would go beyond them is held to them."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.settings import CapabilitySettings, MpcSettings
from core.nmpc.transport_problem import build_transport_problem
from tests.core.controller_fixtures import inputs_at_start, settings, team


def _robot_state_bounds(mpc: MpcSettings, inputs: MpcInputs | None, agent: int = 0,
                        local: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """(N + 1, 12) lower and upper bounds of robot ``agent``'s planned states."""
    problem = build_transport_problem(mpc, agent_count=2, local=local)
    lower, upper = problem.decision_bounds(inputs.contacts if inputs is not None
                                           else np.ones((2, mpc.horizon_steps, 4)),
                                           agent=agent, inputs=inputs)
    key = "self" if local else str(agent)
    d = problem.nlp.decision
    return (np.array([d.get(lower, f"robot_{key}@{k}") for k in range(mpc.horizon_steps + 1)]),
            np.array([d.get(upper, f"robot_{key}@{k}") for k in range(mpc.horizon_steps + 1)]))


@pytest.mark.parametrize("local", [True, False])
def test_limits_bound_speed_and_height_from_their_stage(local: bool) -> None:
    mpc = settings()
    inputs = inputs_at_start(team(), mpc)
    limits = mpc.capability
    assert limits.max_planar_speed_m_s is not None and limits.max_height_deviation_m is not None
    lower, upper = _robot_state_bounds(mpc, inputs, agent=1, local=local)
    first = limits.from_stage
    assert np.all(np.isinf(lower[:first])) and np.all(np.isinf(upper[:first]))
    np.testing.assert_array_equal(upper[first:, 3:5], limits.max_planar_speed_m_s)
    np.testing.assert_array_equal(lower[first:, 3:5], -limits.max_planar_speed_m_s)
    heights = inputs.robot_references[1, first - 1:, 2]
    np.testing.assert_allclose(upper[first:, 2], heights + limits.max_height_deviation_m)
    np.testing.assert_allclose(lower[first:, 2], heights - limits.max_height_deviation_m)
    # nothing else of the state is bounded
    others = [0, 1, *range(5, 12)]
    assert np.all(np.isinf(lower[:, others])) and np.all(np.isinf(upper[:, others]))


def test_no_inputs_or_none_lift_the_limits() -> None:
    lower, upper = _robot_state_bounds(settings(), None)
    assert np.all(np.isinf(lower)) and np.all(np.isinf(upper))
    off = settings(capability=CapabilitySettings(max_planar_speed_m_s=None,
                                                 max_height_deviation_m=None))
    lower, upper = _robot_state_bounds(off, inputs_at_start(team(), off))
    assert np.all(np.isinf(lower)) and np.all(np.isinf(upper))


def test_limits_widen_to_what_the_measured_state_reaches() -> None:
    """A robot faster than the limit is planned to slow down to it at ``deceleration_m_s2``;
    one above its height band keeps its height plus the ballistic rise of its vertical speed
    (never further out); the other bounds keep the limits."""
    mpc = settings()
    inputs = inputs_at_start(team(), mpc)
    states = inputs.robot_states.copy()
    states[0, 3:6] = (0.8, -0.2, 0.3)  # fast forward, slow sideways, rising
    states[0, 2] += 0.05
    lower, upper = _robot_state_bounds(mpc, dataclasses.replace(inputs, robot_states=states))
    limits, ts = mpc.capability, mpc.sample_period_s
    first, band = limits.from_stage, 0.03
    stages = np.arange(first, mpc.horizon_steps + 1)
    np.testing.assert_allclose(upper[first:, 3],
                               np.maximum(0.5, 0.8 - limits.deceleration_m_s2 * stages * ts))
    assert upper[first, 3] > 0.5 and upper[-1, 3] < 0.8  # slowing down, not held at 0.8
    np.testing.assert_allclose(upper[first:, 4], 0.5)
    rise = 0.3 ** 2 / (2 * mpc.gravity_m_s2)
    np.testing.assert_allclose(upper[first:, 2], states[0, 2] + rise)
    np.testing.assert_allclose(lower[first:, 2], inputs.robot_references[0, first - 1:, 2] - band)


def _planned_speeds(mpc: MpcSettings, inputs: MpcInputs) -> np.ndarray:
    """|planned robot CoM velocity| per axis, (n_A, N + 1, 2), of one centralized update."""
    model = team()
    plan = CentralizedMpc(model, mpc).update(inputs)
    assert plan.success
    return np.abs(plan.robot_trajectories[:, :, 3:5])


def test_a_plan_that_would_run_faster_is_held_to_the_limit() -> None:
    """The references 0.4 m ahead: unbounded, the team plans to catch up at up to ~0.38 m/s;
    with a 0.2 m/s limit no stage from ``from_stage`` on exceeds it."""
    inputs = inputs_at_start(team(), settings())
    ahead = dataclasses.replace(
        inputs, robot_references=inputs.robot_references + np.r_[0.4, np.zeros(11)],
        payload_reference=inputs.payload_reference + np.r_[0.4, np.zeros(11)])
    free = settings(capability=CapabilitySettings(max_planar_speed_m_s=None))
    assert _planned_speeds(free, ahead).max() > 0.3
    limited = settings(capability=CapabilitySettings(max_planar_speed_m_s=0.2))
    speeds = _planned_speeds(limited, ahead)
    assert speeds[:, limited.capability.from_stage:].max() <= 0.2 + 1e-6
    assert speeds.max() > 0.15  # it still moves toward the reference
