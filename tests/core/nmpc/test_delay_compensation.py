"""Delay compensation predicts the state the plant reaches while a plan is computed."""

from __future__ import annotations

import numpy as np

from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.delay_compensation import interpolate_trajectory, predict_states
from core.plant.srb_plant import SrbPlant
from tests.core.controller_fixtures import inputs_at_start, settings, team


def test_interpolation_is_linear_between_stages_and_held_at_the_ends() -> None:
    trajectory = np.arange(3 * 12, dtype=float).reshape(3, 12)
    np.testing.assert_allclose(interpolate_trajectory(trajectory, 0.015, 0.01),
                               0.5 * (trajectory[1] + trajectory[2]))
    np.testing.assert_allclose(interpolate_trajectory(trajectory, -1.0, 0.01), trajectory[0])
    np.testing.assert_allclose(interpolate_trajectory(trajectory, 1.0, 0.01), trajectory[2])


def test_predicted_state_is_the_one_the_plant_reaches() -> None:
    """A team moving at 0.3 m/s: the plan is applied to the SRB plant for the delay; the
    prediction must land much closer to the plant than the stale measurement does."""
    model = team()
    mpc = settings()
    inputs = inputs_at_start(model, mpc)
    inputs.robot_states[:, 3] = 0.3  # all moving along x, as in the trot
    inputs.payload_state[3] = 0.3
    plan = CentralizedMpc(model, mpc).update(inputs)
    assert plan.success
    delay_s = 0.012
    plant = SrbPlant(model, 1e-3, mpc.gravity_m_s2)
    robots, payload, _ = plant.step(inputs.robot_states, inputs.payload_state, plan.grf,
                                    inputs.feet_positions[:, 0], round(delay_s / 1e-3))
    predicted_robots, predicted_payload = predict_states(
        plan, 0.0, delay_s, inputs.robot_states, inputs.payload_state, mpc.sample_period_s)
    for truth, predicted, stale in ((robots, predicted_robots, inputs.robot_states),
                                    (payload, predicted_payload, inputs.payload_state)):
        position_error = np.abs(predicted[..., 0:3] - truth[..., 0:3]).max()
        stale_error = np.abs(stale[..., 0:3] - truth[..., 0:3]).max()
        assert stale_error > 3e-3  # 3.6 mm travelled in 12 ms
        assert position_error < 0.1 * stale_error
        velocity_error = np.abs(predicted[..., 3:6] - truth[..., 3:6]).max()
        assert velocity_error < 0.02  # [m/s]
