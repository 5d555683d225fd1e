"""The MuJoCo team scene: masses, sizes, limits, placement and the yaw-free coupling."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import mujoco
import numpy as np
import pytest

from core.model.conventions import LEG_JOINT_NAMES, LEG_NAMES
from core.model.team import TeamModel
from core.nmpc.reference import robot_state_from_payload
from core.plant.standard_scenarios import ring_team_settings
from drivers.mujoco.scene import TeamScene, build_team_scene, robot_spec, robot_urdf_text
from drivers.robot_descriptions import FOOT_RADIUS_M, robot_description, srb_parameters

ROBOT_MASS_KG = {"go2": 16.085, "a1": 13.741}
PAYLOAD_HEIGHT_M = 0.45


@pytest.fixture(scope="module")
def mixed_team():
    return ring_team_settings(["go2", "go2", "a1"], srb_parameters)


@pytest.fixture(scope="module")
def mixed_scene(mixed_team) -> TeamScene:
    return build_team_scene(mixed_team, obstacles=[(1.2, 0.6, 0.1, 1.0), (2.2, -0.6, 0.15, 0.8)])


def _standing_data(scene: TeamScene) -> mujoco.MjData:
    data = mujoco.MjData(scene.model)
    data.qpos[:] = scene.initial_qpos
    mujoco.mj_forward(scene.model, data)
    return data


def _coupling_gap_m(scene: TeamScene, data: mujoco.MjData) -> np.ndarray:
    return np.array([np.linalg.norm(data.site_xpos[r.coupling_site_id]
                                    - data.site_xpos[r.coupler_site_id]) for r in scene.robots])


def _yaw_rad(rotation: np.ndarray) -> float:
    return float(np.arctan2(rotation[1, 0], rotation[0, 0]))


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_single_robot_spec_mass_and_size(robot_type):
    assert "package://" not in robot_urdf_text(robot_type)
    assert "<visual" not in robot_urdf_text(robot_type)
    model = robot_spec(robot_type).compile()
    assert model.nq == 19 and model.nv == 18 and model.nu == 12
    assert model.body_subtreemass[1] == pytest.approx(ROBOT_MASS_KG[robot_type], abs=1e-3)


def test_robot_masses_and_sizes_in_team(mixed_team, mixed_scene):
    model = mixed_scene.model
    count = len(mixed_team.agents)
    hinge_dofs = count  # one yaw hinge per coupling
    assert model.nq == 7 * (count + 1) + 12 * count + hinge_dofs
    assert model.nv == 6 * (count + 1) + 12 * count + hinge_dofs
    assert model.nu == 12 * count
    assert model.neq == count
    for robot in mixed_scene.robots:
        assert model.body_subtreemass[robot.base_body_id] == pytest.approx(
            ROBOT_MASS_KG[robot.robot_type], abs=1e-3)
    assert model.body_subtreemass[mixed_scene.payload_body_id] == pytest.approx(5.0, abs=1e-9)


def test_two_go2_scene_compiles():
    scene = build_team_scene(ring_team_settings(["go2", "go2"], srb_parameters))
    assert scene.model.nq == 7 * 3 + 24 + 2
    assert [r.name for r in scene.robots] == ["go2_0", "go2_1"]
    assert scene.robot("go2_1").base_body_id != scene.robot("go2_0").base_body_id
    with pytest.raises(KeyError):
        scene.robot("nobody")


def test_payload_true_mass_override(mixed_team):
    scene = build_team_scene(mixed_team, payload_true_mass_kg=7.5)
    model = scene.model
    assert model.body_subtreemass[scene.payload_body_id] == pytest.approx(7.5, abs=1e-9)
    box_mass_kg = model.body_mass[scene.payload_body_id]
    a, b, c = mixed_team.payload.size_m
    assert model.body_inertia[scene.payload_body_id] == pytest.approx(
        [box_mass_kg * (b * b + c * c) / 12, box_mass_kg * (a * a + c * c) / 12,
         box_mass_kg * (a * a + b * b) / 12], rel=1e-9)


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_actuators_are_leg_motors_with_urdf_effort_limits(robot_type, mixed_scene):
    root = ET.parse(robot_description(robot_type).urdf_path).getroot()
    efforts = {j.attrib["name"]: float(j.find("limit").attrib["effort"])
               for j in root.iter("joint") if j.attrib.get("type") == "revolute"}
    expected = {"go2": [23.7, 23.7, 45.43], "a1": [33.5, 33.5, 33.5]}[robot_type]
    assert [efforts[j] for j in LEG_JOINT_NAMES[:3]] == expected
    model = mixed_scene.model
    for robot in (r for r in mixed_scene.robots if r.robot_type == robot_type):
        limits = np.array([efforts[j] for j in LEG_JOINT_NAMES])
        np.testing.assert_array_equal(model.actuator_ctrlrange[robot.actuator_ids],
                                      np.column_stack([-limits, limits]))
        assert all(model.actuator_ctrllimited[robot.actuator_ids])
        assert all(model.actuator_gainprm[robot.actuator_ids, 0] == 1.0)  # torque = ctrl
        targets = [model.joint(model.actuator_trnid[a, 0]).name for a in robot.actuator_ids]
        assert targets == [f"{robot.name}/{j}" for j in LEG_JOINT_NAMES]
        assert list(model.jnt_qposadr[model.actuator_trnid[robot.actuator_ids, 0]]) == list(
            robot.leg_qpos_addresses)


def test_foot_friction_and_obstacles(mixed_scene):
    model = mixed_scene.model
    ground = model.geom("ground").id
    for robot in mixed_scene.robots:
        feet = robot.foot_geom_ids
        assert [model.body(model.geom_bodyid[g]).name for g in feet] == [
            f"{robot.name}/{leg}_foot" for leg in LEG_NAMES]
        np.testing.assert_allclose(model.geom_friction[feet, 0], 0.8)
        assert all(model.geom_priority[feet] > model.geom_priority[ground])
    scene = build_team_scene(ring_team_settings(["a1"], srb_parameters), foot_friction=0.5)
    np.testing.assert_allclose(scene.model.geom_friction[scene.robots[0].foot_geom_ids, 0], 0.5)
    obstacles = mixed_scene.obstacle_geom_ids
    assert len(obstacles) == 2
    np.testing.assert_allclose(model.geom_size[obstacles[1]][:2], [0.15, 0.4])
    body = model.geom_bodyid[obstacles[1]]
    np.testing.assert_allclose(model.body_pos[body], [2.2, -0.6, 0.4])
    assert model.body_mocapid[body] == mixed_scene.obstacle_mocap_ids[1] >= 0  # kinematic
    assert not mixed_scene.obstacles_move
    # they collide with the robots and the payload
    robot_geom = mixed_scene.robots[0].foot_geom_ids[0]
    payload_geom = model.body_geomadr[mixed_scene.payload_body_id]
    for other in (robot_geom, payload_geom):
        assert (model.geom_contype[obstacles[1]] & model.geom_conaffinity[other]) or (
            model.geom_contype[other] & model.geom_conaffinity[obstacles[1]])


def test_initial_configuration_is_standing_at_the_reference(mixed_team, mixed_scene):
    data = _standing_data(mixed_scene)
    team_model = TeamModel.from_settings(mixed_team, srb_parameters)
    payload_state = np.zeros(12)
    payload_state[2] = PAYLOAD_HEIGHT_M
    np.testing.assert_allclose(data.xpos[mixed_scene.payload_body_id], [0, 0, PAYLOAD_HEIGHT_M])
    assert _coupling_gap_m(mixed_scene, data).max() < 1e-9
    for i, robot in enumerate(mixed_scene.robots):
        reference = robot_state_from_payload(team_model, i, payload_state)
        np.testing.assert_allclose(data.subtree_com[robot.base_body_id], reference[0:3], atol=1e-6)
        # MuJoCo quaternion w, x, y, z: level trunk, yaw 0
        q = mixed_scene.initial_qpos
        np.testing.assert_allclose(q[robot.base_qpos_address + 3:robot.base_qpos_address + 7],
                                   [1, 0, 0, 0])
        foot_heights_m = data.site_xpos[robot.foot_site_ids, 2] - FOOT_RADIUS_M[robot.robot_type]
        assert foot_heights_m.min() == pytest.approx(0.0, abs=1e-6)
        assert np.ptp(foot_heights_m) < 1e-3  # all four feet on the ground


def test_coupling_is_yaw_free_and_rigid_otherwise(mixed_team):
    """Torque (roll, pitch, yaw) on one robot, no gravity or contacts: only relative yaw moves."""
    scene = build_team_scene(mixed_team)
    model = scene.model
    model.opt.gravity[:] = 0.0
    model.opt.disableflags |= mujoco.mjtDisableBit.mjDSBL_CONTACT
    data = _standing_data(scene)
    robot = scene.robots[0]
    data.xfrc_applied[robot.base_body_id, 3:6] = [2.0, 2.0, 1.0]  # N m, world frame
    max_gap_m = 0.0
    for _ in range(300):
        mujoco.mj_step(model, data)
        max_gap_m = max(max_gap_m, _coupling_gap_m(scene, data).max())
    payload_rotation = data.xmat[scene.payload_body_id].reshape(3, 3)
    robot_rotation = data.xmat[robot.base_body_id].reshape(3, 3)
    relative = payload_rotation.T @ robot_rotation
    assert abs(_yaw_rad(relative)) > 0.05
    assert data.qpos[robot.coupler_hinge_qpos_address] == pytest.approx(_yaw_rad(relative),
                                                                        abs=2e-3)
    relative_tilt_rad = np.arccos(np.clip(relative[2, 2], -1.0, 1.0))
    assert relative_tilt_rad < np.radians(0.2)
    assert np.arccos(payload_rotation[2, 2]) > np.radians(0.3)  # the roll/pitch torque went through
    assert max_gap_m < 2e-3
    assert not np.isnan(data.qpos).any()


def test_zero_control_half_second_stays_finite(mixed_scene):
    data = _standing_data(mixed_scene)
    steps = int(round(0.5 / mixed_scene.model.opt.timestep))
    mujoco.mj_step(mixed_scene.model, data, nstep=steps)
    assert data.time == pytest.approx(0.5)
    assert np.isfinite(data.qpos).all() and np.isfinite(data.qvel).all()
    assert data.xpos[mixed_scene.payload_body_id, 2] > 0.0
    assert _coupling_gap_m(mixed_scene, data).max() < 2e-3


def test_coupling_time_constant_must_cover_two_steps(mixed_team):
    with pytest.raises(ValueError, match="two timesteps"):
        build_team_scene(mixed_team, timestep_s=0.005, coupling_time_constant_s=0.005)
