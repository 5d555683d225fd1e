"""Payload estimator: exact inverse of an independent forward map of the yaw-free coupling,
invariance to robot yaw, noise figures against their analytic values, yaw unwrapping, bad input."""

from __future__ import annotations

import numpy as np
import pytest

from core.estimation.payload_estimator import PayloadEstimator
from core.model.team import TeamModel
from core.model.team_settings import AgentSettings, PayloadSettings, TeamSettings
from core.nmpc.reference import robot_state_from_payload
from core.plant.standard_scenarios import ring_team_settings
from drivers.robot_descriptions import srb_parameters
from tests.core.rigid_body_math import euler_from_rotation, rot_z, rotation

TEAMS = [("go2", "go2"), ("go2", "go2", "a1"), ("go2", "a1", "go2", "a1")]


def _team(types) -> TeamModel:
    return TeamModel.from_settings(ring_team_settings(list(types), srb_parameters),
                                   srb_parameters)


def _offset_team() -> TeamModel:
    """Two Go2 whose coupling points are off-centre in both bodies (not a ring)."""
    agents = [
        AgentSettings(name="a", robot_type="go2", coupling_point_in_payload_m=(0.6, 0.1, 0.05),
                      coupling_point_in_robot_m=(0.1, -0.05, 0.15)),
        AgentSettings(name="b", robot_type="go2", coupling_point_in_payload_m=(-0.5, -0.2, 0.0),
                      coupling_point_in_robot_m=(-0.08, 0.04, 0.12)),
    ]
    settings = TeamSettings(agents=agents, payload=PayloadSettings(mass_kg=5.0))
    return TeamModel.from_settings(settings, srb_parameters)


def _robot_states(team: TeamModel, payload: np.ndarray, robot_yaws: np.ndarray,
                  spins: np.ndarray) -> np.ndarray:
    """Consistent robot states: R_i = R_L Rz(yaw_i) (z-axes parallel, relative yaw free),
    omega_i = omega_L + spin_i n, coupling points and their velocities coincide."""
    r_l = rotation(payload[6:9])
    n = r_l[:, 2]
    omega_l = payload[9:12]
    states = []
    for i in range(team.agent_count):
        r_i = r_l @ rot_z(robot_yaws[i])
        d_l = r_l @ team.coupling_points_in_payload_m[i]
        d_r = r_i @ team.coupling_points_in_robot_m[i]
        omega_i = omega_l + spins[i] * n
        p_i = payload[0:3] + d_l - d_r
        v_i = payload[3:6] + np.cross(omega_l, d_l) - np.cross(omega_i, d_r)
        states.append(np.concatenate([p_i, v_i, euler_from_rotation(r_i), omega_i]))
    return np.array(states)


def _random_payload(rng: np.random.Generator, tilt: float = 0.3) -> np.ndarray:
    return np.concatenate([
        rng.uniform(-5, 5, 3), rng.normal(0, 0.5, 3),
        [rng.uniform(-tilt, tilt), rng.uniform(-tilt, tilt), rng.uniform(-np.pi, np.pi)],
        rng.normal(0, 0.8, 3),
    ])


def _assert_state_close(estimate: np.ndarray, expected: np.ndarray) -> None:
    np.testing.assert_allclose(estimate[0:3], expected[0:3], atol=1e-9)
    np.testing.assert_allclose(estimate[6:9], expected[6:9], atol=1e-9)
    np.testing.assert_allclose(estimate[3:6], expected[3:6], atol=1e-9)
    np.testing.assert_allclose(estimate[9:12], expected[9:12], atol=1e-9)


@pytest.mark.parametrize("types", TEAMS)
def test_inverts_the_coupling_for_tilted_spinning_payloads(types):
    team = _team(types)
    estimator = PayloadEstimator(team)
    rng = np.random.default_rng(len(types))
    for _ in range(50):
        payload = _random_payload(rng)
        states = _robot_states(team, payload, rng.uniform(-np.pi, np.pi, team.agent_count),
                               rng.normal(0, 2.0, team.agent_count))
        _assert_state_close(estimator.estimate(states), payload)


def test_inverts_off_centre_coupling_points():
    team = _offset_team()
    estimator = PayloadEstimator(team)
    rng = np.random.default_rng(7)
    for _ in range(50):
        payload = _random_payload(rng, tilt=0.5)
        states = _robot_states(team, payload, rng.uniform(-np.pi, np.pi, 2), rng.normal(0, 2, 2))
        _assert_state_close(estimator.estimate(states), payload)


def test_robot_yaw_and_yaw_rate_do_not_change_the_estimate():
    team = _team(("go2", "go2", "a1"))
    estimator = PayloadEstimator(team)
    rng = np.random.default_rng(3)
    payload = _random_payload(rng)
    reference = estimator.estimate(_robot_states(team, payload, np.zeros(3), np.zeros(3)))
    for _ in range(20):
        states = _robot_states(team, payload, rng.uniform(-np.pi, np.pi, 3), rng.normal(0, 3, 3))
        np.testing.assert_allclose(estimator.estimate(states), reference, atol=1e-9)


@pytest.mark.parametrize("types", TEAMS)
def test_inverts_the_reference_forward_map_for_level_payloads(types):
    """core.nmpc.reference.robot_state_from_payload models a level payload turning about z only."""
    team = _team(types)
    estimator = PayloadEstimator(team)
    rng = np.random.default_rng(11)
    for _ in range(20):
        payload = np.zeros(12)
        payload[0:6] = rng.normal(0, 1, 6)
        payload[8] = rng.uniform(-np.pi, np.pi)
        payload[11] = rng.normal(0, 1)
        states = np.array([robot_state_from_payload(team, i, payload)
                           for i in range(team.agent_count)])
        _assert_state_close(estimator.estimate(states), payload)


def test_position_noise_figures_match_their_analytic_values():
    """Two agents at +-0.55 m: p_L is the mean of the two coupling points, so each axis has the
    noise sigma / sqrt(2); the yaw error is the across-track noise of c_1 - c_2, sigma sqrt(2),
    over the 1.1 m baseline (first order)."""
    team = _team(("go2", "go2"))
    baseline = np.linalg.norm(np.diff(team.coupling_points_in_payload_m[:, 0:2], axis=0))
    assert baseline == pytest.approx(1.1)
    estimator = PayloadEstimator(team)
    rng = np.random.default_rng(5)
    sigma, trials = 0.005, 3000
    position_errors, yaw_errors = [], []
    for _ in range(trials):
        payload = _random_payload(rng, tilt=0.2)
        states = _robot_states(team, payload, rng.uniform(-np.pi, np.pi, 2), np.zeros(2))
        states[:, 0:3] += rng.normal(0, sigma, (2, 3))
        estimate = estimator.estimate(states)
        position_errors.append(estimate[0:3] - payload[0:3])
        yaw_errors.append(np.angle(np.exp(1j * (estimate[8] - payload[8]))))
    position_rms = np.sqrt(np.mean(np.square(position_errors)))
    yaw_rms = np.sqrt(np.mean(np.square(yaw_errors)))
    assert position_rms == pytest.approx(sigma / np.sqrt(2), rel=0.05)  # 3.54 mm per axis
    assert yaw_rms == pytest.approx(sigma * np.sqrt(2) / baseline, rel=0.08)  # 6.4 mrad
    assert np.max(np.abs(position_errors)) < 5 * sigma / np.sqrt(2)


def test_yaw_is_continuous_across_pi_with_a_previous_state():
    team = _team(("go2", "go2"))
    estimator = PayloadEstimator(team)
    payload = np.zeros(12)
    payload[2] = 0.45
    previous = None
    yaws = np.linspace(np.pi - 0.3, np.pi + 0.3, 61)  # unwrapped truth crossing +pi
    for yaw in yaws:
        payload[8] = yaw
        states = _robot_states(team, payload, np.zeros(2), np.zeros(2))
        principal = estimator.estimate(states)[8]  # no previous: principal value
        assert abs(principal) <= np.pi
        assert abs(np.angle(np.exp(1j * (principal - yaw)))) < 1e-9
        estimate = estimator.estimate(states, previous)
        assert estimate[8] == pytest.approx(yaw, abs=1e-9)  # first yaw is < pi: no wrap
        previous = estimate
    assert previous[8] == pytest.approx(np.pi + 0.3, abs=1e-9)


def test_bad_input_raises_value_error_naming_the_argument():
    team = _team(("go2", "go2"))
    estimator = PayloadEstimator(team)
    good = _robot_states(team, np.r_[0, 0, 0.45, np.zeros(9)], np.zeros(2), np.zeros(2))
    with pytest.raises(ValueError, match="robot_states"):
        estimator.estimate(good[0])
    with pytest.raises(ValueError, match="robot_states"):
        estimator.estimate(np.vstack([good, good]))
    nan = good.copy()
    nan[1, 4] = np.nan
    with pytest.raises(ValueError, match="robot_states"):
        estimator.estimate(nan)
    with pytest.raises(ValueError, match="previous"):
        estimator.estimate(good, np.zeros(11))
    with pytest.raises(ValueError, match="previous"):
        estimator.estimate(good, np.full(12, np.nan))


def test_unobservable_yaw_is_rejected():
    team = _team(("go2", "go2"))
    stacked = TeamModel(team.names, team.robot_types, team.robots, team.payload,
                        team.coupling_points_in_robot_m, np.zeros((2, 3)))
    with pytest.raises(ValueError, match="team"):
        PayloadEstimator(stacked)
