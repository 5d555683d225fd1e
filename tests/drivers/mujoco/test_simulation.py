"""The MuJoCo backend behind the driver interface: standing PD, I/O round trip, conventions,
foot normal forces, coupling wrench, determinism, mocap noise, pushes."""

from __future__ import annotations

import copy
import dataclasses

import mujoco
import numpy as np
import pytest

from core.model.conventions import LEG_JOINT_NAMES
from core.model.team import TeamModel
from core.nmpc.reference import robot_state_from_payload
from core.plant.standard_scenarios import ring_team_settings
from drivers.interfaces import JointCommand, MocapSource, RobotDriver
from drivers.mujoco.scene import TeamScene, build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters

PAYLOAD_HEIGHT_M = 0.45
KP, KD = 100.0, 5.0  # measured sag at these gains: trunks 12 mm, payload 12 mm after 1 s


@pytest.fixture(scope="module")
def team():
    return ring_team_settings(["go2", "go2"], srb_parameters)


@pytest.fixture(scope="module")
def scene(team) -> TeamScene:
    return build_team_scene(team)


def _standing(scene: TeamScene, **options) -> TeamSimulation:
    simulation = TeamSimulation(scene, **options)
    for robot in scene.robots:
        simulation.robot_driver(robot.name).send(
            JointCommand.hold(scene.initial_qpos[robot.leg_qpos_addresses], KP, KD))
    return simulation


def test_drivers_satisfy_the_protocols(scene):
    simulation = TeamSimulation(scene)
    assert isinstance(simulation.robot_driver(scene.robots[0].name), RobotDriver)
    assert isinstance(simulation.mocap(), MocapSource)
    with pytest.raises(KeyError, match="go2_0"):
        simulation.robot_driver("nobody")


def test_joint_pd_holds_the_standing_pose(scene):
    simulation = _standing(scene)
    drivers = [simulation.robot_driver(r.name) for r in scene.robots]
    start_m = np.array([d.read().position_in_world_m[2] for d in drivers])
    worst_trunk_m, worst_payload_m = 0.0, 0.0
    for _ in range(100):
        simulation.step(10)
        heights_m = np.array([d.read().position_in_world_m[2] for d in drivers])
        worst_trunk_m = max(worst_trunk_m, float(np.abs(heights_m - start_m).max()))
        payload_z_m = simulation.payload_pose()[0][2]
        worst_payload_m = max(worst_payload_m, abs(payload_z_m - PAYLOAD_HEIGHT_M))
    assert simulation.time_s == pytest.approx(1.0)
    assert worst_trunk_m < 0.03
    assert worst_payload_m < 0.03
    for driver in drivers:  # standing on all four feet, carrying robot + share of payload
        measurement = driver.read()
        assert measurement.foot_contact.all()
        assert measurement.foot_normal_force_n.sum() == pytest.approx(
            (16.085 + 2.5) * 9.81, rel=0.2)
        assert np.abs(measurement.linear_velocity_in_world_m_s).max() < 0.01


def test_torque_command_round_trip_and_clipping(scene):
    simulation = TeamSimulation(scene)
    robot = scene.robots[1]
    driver = simulation.robot_driver(robot.name)
    torque_nm = np.linspace(-3.0, 3.0, 12)
    driver.send(JointCommand(torque_nm=torque_nm))
    simulation.step()
    np.testing.assert_allclose(simulation.data.actuator_force[robot.actuator_ids], torque_nm)
    np.testing.assert_allclose(driver.read().torque_nm, torque_nm)

    driver.send(JointCommand(torque_nm=np.full(12, 1e4)))
    simulation.step()
    limits_nm = scene.model.actuator_ctrlrange[robot.actuator_ids, 1]
    np.testing.assert_allclose(driver.read().torque_nm, limits_nm)
    # each entry drives the actuator of the same-named joint
    index = LEG_JOINT_NAMES.index("RL_thigh_joint")
    assert scene.model.actuator(int(robot.actuator_ids[index])).name == f"{robot.name}/RL_thigh"


def test_joint_order_follows_leg_joint_names(scene):
    robot = scene.robots[0]
    qpos = scene.initial_qpos.copy()
    qpos[scene.model.joint(f"{robot.name}/FR_calf_joint").qposadr[0]] = -2.2
    simulation = TeamSimulation(dataclasses.replace(scene, initial_qpos=qpos))
    position_rad = simulation.robot_driver(robot.name).read().position_rad
    assert position_rad[LEG_JOINT_NAMES.index("FR_calf_joint")] == -2.2
    assert np.count_nonzero(position_rad == -2.2) == 1


def test_base_quaternion_is_wxyz_base_to_world(scene, team):
    team_model = TeamModel.from_settings(team, srb_parameters)
    payload_state = np.zeros(12)
    payload_state[2] = PAYLOAD_HEIGHT_M
    simulation = TeamSimulation(scene)
    for i, robot in enumerate(scene.robots):
        yaw = robot_state_from_payload(team_model, i, payload_state)[8]
        quaternion = simulation.robot_driver(robot.name).read().quaternion_wxyz
        np.testing.assert_allclose(quaternion, [np.cos(yaw / 2), 0, 0, np.sin(yaw / 2)],
                                   atol=1e-9)

    yaw = 0.7
    robot = scene.robots[0]
    qpos = scene.initial_qpos.copy()
    qpos[robot.base_qpos_address + 3:robot.base_qpos_address + 7] = (
        np.cos(yaw / 2), 0, 0, np.sin(yaw / 2))
    simulation = TeamSimulation(dataclasses.replace(scene, initial_qpos=qpos))
    quaternion = simulation.robot_driver(robot.name).read().quaternion_wxyz
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, quaternion)
    heading = matrix.reshape(3, 3) @ [1.0, 0.0, 0.0]  # the trunk's forward axis in world
    np.testing.assert_allclose(heading, [np.cos(yaw), np.sin(yaw), 0.0], atol=1e-9)
    np.testing.assert_allclose(simulation.data.xmat[robot.base_body_id], matrix, atol=1e-9)


def _reference_foot_normal_forces(simulation: TeamSimulation, robot) -> np.ndarray:
    """The plain definition: per foot, the sum over the contacts involving its geom of the
    normal component of ``mj_contactForce``."""
    data = simulation.data
    forces_n, wrench = np.zeros(4), np.zeros(6)
    for i in range(data.ncon):
        for foot, geom_id in enumerate(robot.foot_geom_ids):
            if geom_id in data.contact.geom[i]:
                mujoco.mj_contactForce(simulation.model, data, i, wrench)
                forces_n[foot] += wrench[0]
    return forces_n


@pytest.mark.parametrize("variant", ["standing", "elliptic cone", "mixed condim", "limp"])
def test_foot_normal_forces_match_mj_contact_force(scene, variant):
    model = copy.deepcopy(scene.model)
    if variant == "elliptic cone":
        model.opt.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    if variant == "mixed condim":  # frictionless, pyramids of 4, 6 and 10 edges
        model.geom_condim[scene.robots[0].foot_geom_ids] = [1, 3, 4, 6]
    variant_scene = dataclasses.replace(scene, model=model)
    # limp: the robots fold onto the ground, trunks and legs touching it besides the feet
    simulation = (TeamSimulation(variant_scene) if variant == "limp"
                  else _standing(variant_scene))
    drivers = [simulation.robot_driver(r.name) for r in scene.robots]
    touching = np.zeros((len(drivers), 4), dtype=bool)
    for _ in range(60):
        simulation.step(5)
        for robot, driver in zip(scene.robots, drivers, strict=True):
            measurement = driver.read()
            reference_n = _reference_foot_normal_forces(simulation, robot)
            np.testing.assert_allclose(measurement.foot_normal_force_n, reference_n,
                                       rtol=1e-9, atol=0.0)
            np.testing.assert_array_equal(measurement.foot_contact, reference_n > 0.0)
            touching |= measurement.foot_contact
    assert touching.all()
    if variant == "limp":  # other geoms reached the ground too
        assert not np.isin(simulation.data.contact.geom,
                           [0, *np.concatenate([r.foot_geom_ids for r in scene.robots])]).all()


def test_no_contact_no_foot_force(scene):
    qpos = scene.initial_qpos.copy()
    for robot in scene.robots:
        qpos[robot.base_qpos_address + 2] += 1.0
    qpos[scene.payload_qpos_address + 2] += 1.0
    simulation = TeamSimulation(dataclasses.replace(scene, initial_qpos=qpos))
    assert simulation.data.ncon == 0
    measurement = simulation.robot_driver(scene.robots[0].name).read()
    np.testing.assert_array_equal(measurement.foot_normal_force_n, np.zeros(4))
    assert not measurement.foot_contact.any()


def test_foot_forces_follow_steps_and_direct_changes(scene):
    """The feet's forces, computed once per physics step for the whole team, are those of
    the current state: after a step, and after a direct change to ``data`` and ``forward``."""
    simulation = _standing(scene)
    simulation.step(50)
    drivers = [simulation.robot_driver(r.name) for r in scene.robots]
    loaded = [driver.read().foot_normal_force_n for driver in drivers]
    assert all((forces > 0.0).any() for forces in loaded)
    loaded[0][:] = -1.0  # a caller's change stays with the caller
    assert (drivers[0].read().foot_normal_force_n >= 0.0).all()
    for robot in scene.robots:  # every robot lifted 1 m: no contact anywhere
        simulation.data.qpos[robot.base_qpos_address + 2] += 1.0
    simulation.data.qpos[scene.payload_qpos_address + 2] += 1.0
    simulation.forward()
    for robot, driver in zip(scene.robots, drivers, strict=True):
        np.testing.assert_array_equal(driver.read().foot_normal_force_n, np.zeros(4))
        np.testing.assert_array_equal(_reference_foot_normal_forces(simulation, robot),
                                      np.zeros(4))


def test_measurement_arrays_are_snapshots(scene):
    simulation = _standing(scene)
    driver = simulation.robot_driver(scene.robots[0].name)
    before = driver.read()
    kept = {f.name: np.copy(getattr(before, f.name)) for f in dataclasses.fields(before)}
    simulation.step(20)
    after = driver.read()
    assert not np.array_equal(after.position_in_world_m, before.position_in_world_m)
    for name, value in kept.items():  # later steps leave an earlier measurement as it was
        np.testing.assert_array_equal(getattr(before, name), value)
    assert before.position_rad.shape == (12,) and before.quaternion_wxyz.shape == (4,)
    assert before.foot_contact.dtype == bool and before.foot_normal_force_n.shape == (4,)


def test_static_coupling_forces_carry_the_payload_weight(scene):
    simulation = _standing(scene)
    simulation.step(1000)
    forces_n, torques_nm = zip(*(simulation.coupling_wrench(r.name) for r in scene.robots), strict=True)
    weight_n = scene.model.body_subtreemass[scene.payload_body_id] * 9.81
    total_n = np.sum(forces_n, axis=0)
    assert total_n[2] == pytest.approx(weight_n, rel=0.02)
    assert np.abs(total_n[:2]).max() < 0.02 * weight_n
    for force_n in forces_n:  # symmetric pair: each carries a fair share
        assert force_n[2] == pytest.approx(weight_n / 2, rel=0.3)
    for torque_nm in torques_nm:  # the yaw hinge transmits no torque about the vertical
        assert abs(torque_nm[2]) < 0.01


def _run(scene: TeamScene, seed: int) -> tuple[np.ndarray, list]:
    simulation = _standing(scene, seed=seed, mocap_position_noise_m=0.002,
                           mocap_angle_noise_rad=0.01)
    simulation.apply_push("go2_0", [0.0, 30.0, 0.0], 0.05)
    mocap = simulation.mocap()
    frames = []
    for _ in range(20):
        simulation.step(10)
        frames.append(mocap.latest())
    return simulation.data.qpos.copy(), frames


def test_same_seed_same_trajectory(scene):
    qpos_a, frames_a = _run(scene, seed=3)
    qpos_b, frames_b = _run(scene, seed=3)
    _, frames_c = _run(scene, seed=4)
    np.testing.assert_array_equal(qpos_a, qpos_b)
    for a, b, c in zip(frames_a, frames_b, frames_c, strict=True):
        assert a.time_s == b.time_s
        for name in a.poses:
            np.testing.assert_array_equal(a.poses[name][0], b.poses[name][0])
            np.testing.assert_array_equal(a.poses[name][1], b.poses[name][1])
            assert not np.array_equal(a.poses[name][0], c.poses[name][0])


def test_mocap_noise_statistics(scene):
    position_std_m, angle_std_rad = 0.003, 0.02
    simulation = TeamSimulation(scene, seed=1, mocap_position_noise_m=position_std_m,
                                mocap_angle_noise_rad=angle_std_rad)
    true_position_m, true_quaternion = simulation.payload_pose()
    mocap = simulation.mocap()
    position_errors, angle_errors = [], []
    for _ in range(3000):
        frame = mocap.latest()
        assert frame is not None and set(frame.poses) == {"go2_0", "go2_1", "payload"}
        position_m, quaternion = frame.poses["payload"]
        position_errors.append(position_m - true_position_m)
        error = np.zeros(3)
        mujoco.mju_subQuat(error, quaternion, true_quaternion)
        angle_errors.append(error)
    np.testing.assert_allclose(np.std(position_errors, axis=0), position_std_m, rtol=0.2)
    np.testing.assert_allclose(np.std(angle_errors, axis=0), angle_std_rad, rtol=0.2)
    assert np.abs(np.mean(position_errors, axis=0)).max() < 0.2 * position_std_m


def test_push_moves_the_pushed_body(scene):
    reference, pushed = _standing(scene), _standing(scene)
    pushed.apply_push("payload", [60.0, 0.0, 0.0], 0.1)
    for simulation in (reference, pushed):
        simulation.step(200)
    shift_m = pushed.payload_pose()[0] - reference.payload_pose()[0]
    assert shift_m[0] > 0.005
    assert abs(shift_m[1]) < 0.2 * shift_m[0]
    assert not pushed.data.xfrc_applied.any()  # the push ended after 0.1 s


def test_a_moving_obstacle_follows_its_path_and_pushes_what_it_meets(team):
    """A kinematic cylinder crossing the payload at 0.5 m/s: on its path at every step (from
    ``obstacle_origin_s`` on), and the payload it runs into is pushed (a real contact)."""
    scene = build_team_scene(team, obstacles=[(0.0, 1.2, 0.1, 1.0, 0.0, -0.5),
                                              (3.0, 3.0, 0.2, 0.5)])
    assert scene.obstacles_move
    simulation = TeamSimulation(scene)
    simulation.obstacle_origin_s = 0.2
    mocap = scene.obstacle_mocap_ids
    payload_geom = scene.model.body_geomadr[scene.payload_body_id]
    touched_at_s = None
    while simulation.time_s < 2.0 and touched_at_s is None:
        simulation.step(10)
        moved_s = max(simulation.time_s - 0.2, 0.0)
        expected = np.array([0.0, 1.2 - 0.5 * moved_s, 0.5])
        position, quaternion = simulation.obstacle_pose(0)
        np.testing.assert_allclose(position, expected, atol=1e-9)
        np.testing.assert_allclose(quaternion, [1.0, 0.0, 0.0, 0.0])
        # mocap_pos was set at the last step's start: 1 ms behind the pose now
        last_step_s = max(simulation.time_s - simulation.timestep_s - 0.2, 0.0)
        np.testing.assert_allclose(simulation.data.mocap_pos[mocap[0]][1],
                                   1.2 - 0.5 * last_step_s, atol=1e-9)
        np.testing.assert_allclose(simulation.obstacle_pose(1)[0], [3.0, 3.0, 0.25])
        contacts = simulation.data.contact[:simulation.data.ncon]
        if any(payload_geom in (c.geom1, c.geom2) and scene.obstacle_geom_ids[0] in
               (c.geom1, c.geom2) for c in contacts):
            touched_at_s = simulation.time_s
    assert touched_at_s is not None  # the cylinder reached the payload's edge (y = 0.x)
    simulation.step(100)
    payload_velocity = simulation.data.qvel[scene.payload_qvel_address:
                                            scene.payload_qvel_address + 3]
    position, _ = simulation.payload_pose()
    assert position[1] < -0.01 or payload_velocity[1] < -0.05  # pushed along -y
