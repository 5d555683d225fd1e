"""Whole-body controller: QP consistency, and standing / body-height tracking in MuJoCo."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from core.locomotion.settings import WbcSettings
from core.locomotion.whole_body_control import FloatingBaseState, WbcTarget, WholeBodyController
from core.plant.standard_scenarios import ring_team_settings
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import (
    FOOT_RADIUS_M,
    load_pinocchio_model,
    srb_parameters,
    standing_configuration,
)


def _controller(robot_type: str, coupling_point: tuple[float, float, float]
                ) -> WholeBodyController:
    model = load_pinocchio_model(robot_type)
    return WholeBodyController(model, standing_configuration(robot_type, model),
                               np.asarray(coupling_point), FOOT_RADIUS_M[robot_type])


def _state(m: RobotMeasurement) -> FloatingBaseState:
    return FloatingBaseState(m.position_in_world_m, m.quaternion_wxyz,
                             m.linear_velocity_in_world_m_s, m.angular_velocity_in_body_rad_s,
                             m.position_rad, m.velocity_rad_s)


def _standing_target(srb: np.ndarray, feet: np.ndarray, stance: np.ndarray, grf: np.ndarray,
                     wrench_on_robot: np.ndarray) -> WbcTarget:
    zeros = np.zeros(3)
    return WbcTarget(srb[0:3], zeros, zeros, srb[6:9], zeros, zeros, stance, grf, feet,
                     np.zeros((4, 3)), np.zeros((4, 3)), wrench_on_robot)


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_static_qp_satisfies_dynamics_friction_and_limits(robot_type: str) -> None:
    wbc = _controller(robot_type, (0.0, 0.0, 0.1))
    model = wbc.model
    q = standing_configuration(robot_type, model)
    q[0:3] = (0.0, 0.0, 0.4)
    state = FloatingBaseState(q[0:3], np.array([1.0, 0, 0, 0]), np.zeros(3), np.zeros(3),
                              q[7:], np.zeros(12))
    stance = np.array([True, False, False, True])  # trot pair: FR, RL swing
    weight = srb_parameters(robot_type).mass_kg * 9.81
    grf = np.tile([0.0, 0.0, weight / 2], (4, 1))
    wrench = np.array([0.0, 0.0, -20.0, 0.0, 0.0, 0.0])  # payload presses down
    output = wbc.compute(state, _standing_target(wbc.srb_state(state), wbc.foot_positions(state),
                                                 stance, grf, wrench))
    assert output.success
    forces = output.contact_force_n
    np.testing.assert_allclose(forces[~stance], 0.0)
    mu = wbc.settings.friction_coefficient
    assert np.all(np.abs(forces[stance, 0:2]) <= mu * forces[stance, 2:3] + 1e-6)
    # vertical balance: stance forces carry the robot and the payload's push
    assert forces[:, 2].sum() == pytest.approx(weight + 20.0, rel=0.05)
    assert np.all(np.abs(output.torque_nm) <= model.effortLimit[6:] + 1e-9)
    # torques reproduce the QP's accelerations through the full rigid-body dynamics
    v = np.zeros(model.nv)
    data = model.createData()
    qp = np.concatenate([q[0:3], (0, 0, 0, 1), q[7:]])
    pin.computeAllTerms(model, data, qp, v)
    frames = [model.getFrameId(f"{leg}_foot") for leg in ("FL", "FR", "RL", "RR")]
    external = sum(pin.getFrameJacobian(model, data, f, pin.LOCAL_WORLD_ALIGNED)[0:3].T
                   @ forces[i] for i, f in enumerate(frames))
    generalized = np.concatenate([np.zeros(6), output.torque_nm]) + external
    acceleration = pin.aba(model, data, qp, v,
                           generalized - np.concatenate([np.zeros(6), np.zeros(12)])
                           + _coupling_force(wbc, wrench))
    np.testing.assert_allclose(acceleration[6:], output.joint_acceleration_rad_s2, atol=1e-5)


def _random_state(wbc: WholeBodyController, rng: np.random.Generator) -> FloatingBaseState:
    q = standing_configuration("go2", wbc.model)
    quaternion = np.array([3.0, 0.0, 0.0, 0.0]) + rng.normal(size=4) * [1, 0.05, 0.05, 0.2]
    return FloatingBaseState(np.array([0.1, -0.2, 0.3]) + rng.normal(size=3) * 0.02,
                             quaternion / np.linalg.norm(quaternion), rng.normal(size=3) * 0.3,
                             rng.normal(size=3) * 0.3, q[7:] + rng.normal(size=12) * 0.05,
                             rng.normal(size=12) * 0.5)


@pytest.mark.parametrize("stance", [(1, 1, 1, 1), (1, 0, 0, 1), (0, 1, 1, 0), (1, 1, 1, 0),
                                    (0, 0, 0, 0)])
def test_one_pinocchio_pass_per_tick_gives_the_same_torques(stance: tuple[int, ...]) -> None:
    """``observe`` (SRB state and feet in the pass ``compute`` reuses) changes no figure; a
    different state object, or a Pinocchio call in between, is computed afresh; a conversion
    of another state in between changes nothing."""
    rng = np.random.default_rng(sum(stance))
    shared, fresh = _controller("go2", (0.0, 0.0, 0.1)), _controller("go2", (0.0, 0.0, 0.1))
    weight = srb_parameters("go2").mass_kg * 9.81
    for _ in range(5):
        state, other = _random_state(shared, rng), _random_state(shared, rng)
        srb, feet = shared.observe(state)
        np.testing.assert_allclose(srb, fresh.srb_state(state), rtol=0, atol=1e-12)
        np.testing.assert_allclose(feet, fresh.foot_positions(state), rtol=0, atol=1e-12)
        target = _standing_target(srb + rng.normal(size=12) * 0.01, feet + 0.01,
                                  np.array(stance, dtype=bool),
                                  np.tile([0.0, 0.0, weight / 2], (4, 1)), rng.normal(size=6))
        reused, alone = shared.compute(state, target), fresh.compute(state, target)
        np.testing.assert_allclose(reused.torque_nm, alone.torque_nm, rtol=0, atol=1e-9)
        np.testing.assert_allclose(reused.contact_force_n, alone.contact_force_n, atol=1e-9)
        assert reused.success == alone.success
        shared.observe(state)
        shared.foot_positions(other)  # moves the Pinocchio data to another state
        np.testing.assert_allclose(shared.compute(state, target).torque_nm, alone.torque_nm,
                                   rtol=0, atol=1e-9)
        shared.observe(other)
        np.testing.assert_allclose(shared.compute(state, target).torque_nm, alone.torque_nm,
                                   rtol=0, atol=1e-9)
        # the NMPC's inputs or a reset between observe and compute (another state's SRB state,
        # (q, v)) leave the observed tick's arrays alone: the same torques as before
        shared.observe(state)
        shared.srb_state(other)
        shared.pinocchio_state(other)
        np.testing.assert_array_equal(shared.compute(state, target).torque_nm, reused.torque_nm)


def _coupling_force(wbc: WholeBodyController, wrench: np.ndarray) -> np.ndarray:
    generalized = np.zeros(18)
    lever = wbc.coupling_in_base_m
    generalized[0:3] = wrench[0:3]
    generalized[3:6] = wrench[3:6] + np.cross(lever, wrench[0:3])
    return generalized


def _stand(seconds: float, height_step_m: float, step_at_s: float) -> list[np.ndarray]:
    """Two Go2 coupled to a 5 kg payload standing under their WBCs; returns per-tick SRB state
    errors of robot 0 vs its set-point."""
    team = ring_team_settings(["go2", "go2"], srb_parameters)
    simulation = TeamSimulation(build_team_scene(team))
    robots = []
    for agent in team.agents:
        wbc = _controller(agent.robot_type, agent.coupling_point_in_robot_m)
        driver = simulation.robot_driver(agent.name)
        state = _state(driver.read())
        robots.append((wbc, driver, wbc.srb_state(state), wbc.foot_positions(state)))
    weight = (srb_parameters("go2").mass_kg + team.payload.mass_kg / 2) * 9.81
    grf = np.tile([0.0, 0.0, weight / 4], (4, 1))
    wrench = np.array([0.0, 0.0, -team.payload.mass_kg * 9.81 / 2, 0.0, 0.0, 0.0])
    errors = []
    for tick in range(int(seconds / 0.002)):
        for i, (wbc, driver, start, feet) in enumerate(robots):
            state = _state(driver.read())
            set_point = start.copy()
            if tick * 0.002 >= step_at_s:
                set_point[2] += height_step_m
            output = wbc.compute(state, _standing_target(set_point, feet, np.ones(4, bool), grf,
                                                         wrench))
            assert output.success
            driver.send(JointCommand(torque_nm=output.torque_nm))
            if i == 0:
                errors.append(wbc.srb_state(state) - set_point)
        simulation.step(2)
    return errors


def test_standing_holds_height_and_posture() -> None:
    errors = np.array(_stand(1.5, 0.0, 10.0))
    settled = errors[250:]
    assert np.max(np.abs(settled[:, 2])) < 0.005  # height [m]
    assert np.max(np.abs(settled[:, 0:2])) < 0.01  # horizontal drift [m]
    assert np.max(np.abs(settled[:, 6:8])) < 0.03  # roll, pitch [rad]


def test_body_height_step_is_tracked() -> None:
    errors = np.array(_stand(1.5, 0.04, 0.5))
    before_step = errors[200:250, 2]
    after_settling = errors[500:, 2]
    assert np.max(np.abs(before_step)) < 0.005
    assert np.max(np.abs(after_settling)) < 0.005  # the new height, 0.5 s after the step
    assert np.max(np.abs(errors[250:260, 2])) > 0.02  # the step really happened


def test_wbc_settings_reject_bad_values() -> None:
    from pydantic import ValidationError

    with pytest.raises(ValidationError, match="friction_coefficient"):
        WbcSettings(friction_coefficient=-1.0)
