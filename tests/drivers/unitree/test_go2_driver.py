"""Go2 driver against its MuJoCo-backed fake over real CycloneDDS on loopback: state and
command round trips with the wire conventions checked on the raw messages, CRC and
plausibility rejection, link loss and recovery, damping, sport-mode release."""

from __future__ import annotations

import itertools
import os
import time

import numpy as np
import pytest
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

from core.model.conventions import LEG_JOINT_NAMES
from core.plant.standard_scenarios import ring_team_settings
from drivers.interfaces import JointCommand, RobotDriver
from drivers.link_errors import DriverError, LinkLostError
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters
from drivers.unitree.conventions import (
    POS_STOP_F,
    UNITREE_JOINT_NAMES,
    UNITREE_LEG_ORDER,
    wire_command_from_joint_command,
    wire_state_from_measurement,
)
from drivers.unitree.go2_dds_types import (
    LowCmd_,
    LowState_,
    low_cmd_crc,
    low_cmd_from_wire,
    low_state_crc,
    low_state_from_wire,
)
from drivers.unitree.go2_driver import Go2Driver, cyclonedds_config, open_participant, topic_name
from drivers.unitree.go2_fake import FakeGo2

DOMAIN_ID = 57
ROBOT = "go2_0"
FORCE_N_PER_COUNT = 0.1
_prefixes = itertools.count()


class ManualClock:
    """Seconds that move only when told (deterministic link timeouts)."""

    def __init__(self) -> None:
        self.now_s = 100.0

    def __call__(self) -> float:
        return self.now_s


@pytest.fixture(scope="module")
def scene():
    return build_team_scene(ring_team_settings(["go2", "go2"], srb_parameters))


@pytest.fixture
def link(scene):
    """(simulation, fake, driver, prefix) on a topic prefix of their own (no crosstalk with
    other tests or processes on the same domain)."""
    prefix = f"test_{os.getpid()}_{next(_prefixes)}"
    simulation = TeamSimulation(scene)
    clock = ManualClock()
    fake = FakeGo2(simulation.robot_driver(ROBOT), DOMAIN_ID, topic_prefix=prefix,
                   foot_force_n_per_count=FORCE_N_PER_COUNT)
    driver = Go2Driver(ROBOT, DOMAIN_ID, topic_prefix=prefix, link_timeout_s=0.05,
                       foot_force_n_per_count=FORCE_N_PER_COUNT, contact_threshold_n=1.0,
                       clock=clock)
    fake.publish_state()
    assert driver.wait_for_state(after_s=0.0, timeout_s=2.0)
    return simulation, fake, driver, prefix


def _distinctive_state(simulation: TeamSimulation) -> None:
    robot = simulation.scene.robot(ROBOT)
    data = simulation.data
    data.qpos[robot.leg_qpos_addresses] += 0.01 * np.arange(1, 13)
    data.qvel[robot.leg_qvel_addresses] = -0.1 * np.arange(1, 13)
    quaternion = np.array([0.9, 0.1, -0.2, 0.3])
    a = robot.base_qpos_address
    data.qpos[a + 3:a + 7] = quaternion / np.linalg.norm(quaternion)
    data.qvel[robot.base_qvel_address + 3:robot.base_qvel_address + 6] = (0.3, -0.2, 0.1)
    data.ctrl[robot.actuator_ids] = 0.5 * np.arange(1, 13)
    simulation.forward()


def test_driver_is_a_robot_driver(link):
    assert isinstance(link[2], RobotDriver)
    assert topic_name("", "lowcmd") == "rt/lowcmd"
    assert topic_name("go2_left", "lowstate") == "go2_left/rt/lowstate"
    assert '<NetworkInterface name="lo"/>' in cyclonedds_config("lo")
    # a name is data: quotes and angle brackets cannot end the attribute or add elements
    hostile = cyclonedds_config('eth0"/><Tracing verbosity="finest')
    assert "<Tracing" not in hostile and hostile.count("<NetworkInterface ") == 1


def test_state_round_trip(link):
    simulation, fake, driver, prefix = link
    _distinctive_state(simulation)
    raw = DataReader(driver.participant, Topic(driver.participant,
                                               topic_name(prefix, "lowstate"), LowState_))
    truth = simulation.robot_driver(ROBOT).read()
    fake.publish_state()
    driver.clock.now_s += 0.01
    measurement = driver.read()
    for name in ("position_rad", "velocity_rad_s", "torque_nm", "quaternion_wxyz",
                 "angular_velocity_in_body_rad_s"):
        np.testing.assert_allclose(getattr(measurement, name), getattr(truth, name),
                                   rtol=1e-6, atol=1e-6, err_msg=name)
    np.testing.assert_allclose(measurement.foot_normal_force_n, truth.foot_normal_force_n,
                               atol=FORCE_N_PER_COUNT / 2)
    np.testing.assert_array_equal(measurement.foot_contact, truth.foot_normal_force_n > 1.0)
    np.testing.assert_array_equal(measurement.position_in_world_m, np.zeros(3))  # unmeasured
    np.testing.assert_array_equal(measurement.linear_velocity_in_world_m_s, np.zeros(3))
    # on the wire: FR first, IMU quaternion w first, foot forces FR, FL, RR, RL
    (message,) = raw.take(N=4)
    fr_calf = LEG_JOINT_NAMES.index("FR_calf_joint")
    assert UNITREE_JOINT_NAMES.index("FR_calf_joint") == 2
    assert message.motor_state[2].q == pytest.approx(truth.position_rad[fr_calf], rel=1e-6)
    assert message.motor_state[2].tau_est == pytest.approx(0.5 * (fr_calf + 1), rel=1e-6)
    assert message.imu_state.quaternion[0] == pytest.approx(truth.quaternion_wxyz[0], rel=1e-6)
    rl = UNITREE_LEG_ORDER.index("RL")
    assert message.foot_force[rl] == round(truth.foot_normal_force_n[2] / FORCE_N_PER_COUNT)
    assert driver.link.received == 2 and driver.link.rejected_total == 0


def test_command_round_trip(link):
    simulation, fake, driver, prefix = link
    raw = DataReader(driver.participant, Topic(driver.participant,
                                               topic_name(prefix, "lowcmd"), LowCmd_))
    joints = np.arange(12)
    command = JointCommand(torque_nm=0.1 * joints + 0.05, position_rad=0.02 * joints - 0.1,
                           velocity_rad_s=0.3 - 0.05 * joints, kp=20.0 + joints,
                           kd=0.5 + 0.1 * joints)
    driver.send(command)
    assert fake.poll_commands()
    for name in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd"):
        np.testing.assert_allclose(getattr(fake.last_command, name), getattr(command, name),
                                   rtol=1e-6, err_msg=name)
    (message,) = raw.take(N=4)
    assert list(message.head) == [0xFE, 0xEF] and message.level_flag == 0xFF
    assert [m.mode for m in message.motor_cmd] == [0x01] * 12 + [0] * 8
    assert message.crc == low_cmd_crc(message)
    fl_thigh = LEG_JOINT_NAMES.index("FL_thigh_joint")
    assert message.motor_cmd[UNITREE_JOINT_NAMES.index("FL_thigh_joint")].kp == 20.0 + fl_thigh
    # the sim applies the firmware law of exactly this command
    robot = simulation.scene.robot(ROBOT)
    before = simulation.robot_driver(ROBOT).read()
    low, high = simulation.model.actuator_ctrlrange[robot.actuator_ids].T
    expected = np.clip(fake.last_command.torque_for(before.position_rad, before.velocity_rad_s),
                       low, high)
    simulation.step()
    np.testing.assert_allclose(simulation.data.actuator_force[robot.actuator_ids], expected)


def test_corrupted_commands_are_rejected_and_the_previous_one_kept(link):
    _, fake, driver, prefix = link
    good = JointCommand(torque_nm=np.linspace(-1.0, 1.0, 12))
    driver.send(good)
    assert fake.poll_commands()
    intruder = DataWriter(driver.participant, Topic(driver.participant,
                                                    topic_name(prefix, "lowcmd"), LowCmd_))
    bad_crc = low_cmd_from_wire(wire_command_from_joint_command(JointCommand(torque_nm=5.0), 1))
    bad_crc.crc ^= 0x1
    intruder.write(bad_crc)
    bad_flag = low_cmd_from_wire(wire_command_from_joint_command(JointCommand(), 1))
    bad_flag.level_flag = 0xEE
    bad_flag.crc = low_cmd_crc(bad_flag)
    intruder.write(bad_flag)
    nan = low_cmd_from_wire(wire_command_from_joint_command(JointCommand(), 1))
    nan.motor_cmd[0].q = float("nan")
    nan.crc = low_cmd_crc(nan)
    intruder.write(nan)
    assert not fake.poll_commands()
    assert dict(fake.commands_rejected) == {"crc": 1, "header": 1, "non-finite": 1}
    assert fake.commands_received == 4
    np.testing.assert_allclose(fake.last_command.torque_nm, good.torque_nm, rtol=1e-6)
    with pytest.raises(DriverError, match="non-finite kp"):
        driver.send(JointCommand(kp=np.full(12, np.inf)))


def test_implausible_states_are_rejected(link):
    simulation, _, driver, prefix = link
    before = driver.read()
    intruder = DataWriter(driver.participant, Topic(driver.participant,
                                                    topic_name(prefix, "lowstate"), LowState_))
    valid = wire_state_from_measurement(simulation.robot_driver(ROBOT).read(), 1.0)
    message = low_state_from_wire(valid)
    message.motor_state[0].q = float("nan")
    message.crc = low_state_crc(message)  # well-formed, CRC right, contents impossible
    intruder.write(message)
    message = low_state_from_wire(valid)
    message.imu_state.quaternion = [0.0, 0.0, 0.0, 0.0]
    message.crc = low_state_crc(message)
    intruder.write(message)
    message = low_state_from_wire(valid)
    message.motor_state[4].dq = 1e5
    message.crc = low_state_crc(message)
    intruder.write(message)
    assert driver.poll() == 0
    assert dict(driver.link.rejected) == {"non-finite": 1, "implausible": 2}
    np.testing.assert_allclose(driver.read().position_rad, before.position_rad, rtol=1e-6)


def test_a_state_with_a_wrong_crc_is_rejected_unless_the_check_is_off(link):
    """A LowState_ whose contents changed after its CRC was computed (a bit flipped on the way)
    counts for nothing; a driver with ``check_state_crc`` off takes it (for a firmware that
    leaves the field unfilled), and one that never heard a valid state says which setting."""
    simulation, fake, driver, prefix = link
    driver.read()
    fake.corrupt = "bad_crc"
    for _ in range(3):
        fake.publish_state()
    assert _deliver(driver, 3) == 0 and driver.link.rejected == {"crc": 3}
    unchecked = Go2Driver("unchecked", DOMAIN_ID, topic_prefix=prefix, check_state_crc=False)
    fake.publish_state()
    assert unchecked.wait_for_state(after_s=0.0, timeout_s=2.0)
    assert unchecked.link.rejected_total == 0
    fresh = Go2Driver("fresh", DOMAIN_ID, topic_prefix=prefix)
    deadline = time.monotonic() + 2.0
    while fresh.link.rejected["crc"] == 0:
        assert time.monotonic() < deadline, "no state arrived"
        fake.publish_state()
        fresh.poll()
        time.sleep(0.002)
    with pytest.raises(LinkLostError, match="failed Unitree's CRC.*check_state_crc"):
        fresh.read()
    fake.corrupt = None
    fake.publish_state()
    assert _deliver(driver, 1) == 1


def test_link_lost_then_recovered(link):
    _, fake, driver, _ = link
    driver.read()
    driver.clock.now_s += 0.2
    with pytest.raises(LinkLostError, match=r"rt/lowstate on DDS domain 57.*timeout 0.05 s"):
        driver.read()
    fake.publish_state()
    driver.read()
    assert driver.link.reconnections == 1


def _deliver(driver: Go2Driver, count: int) -> int:
    """Poll until ``count`` messages (valid or rejected) more have arrived; valid ones."""
    seen = driver.link.received + driver.link.rejected_total + count
    valid = 0
    deadline = time.monotonic() + 2.0
    while driver.link.received + driver.link.rejected_total < seen:
        assert time.monotonic() < deadline, "states did not arrive"
        valid += driver.poll()
        time.sleep(0.001)
    return valid


def test_a_frozen_state_is_a_lost_link_and_a_fresh_one_recovers(link):
    """The fake's tick advances with every message, even with the simulation standing still;
    a robot repeating its last message (same tick) is not heard from, so the link times out."""
    _, fake, driver, _ = link
    ticks = []
    for _ in range(3):
        fake.publish_state()  # simulated time does not move between these
        assert _deliver(driver, 1) == 1
        ticks.append(driver.last_state.tick_ms)
    assert ticks[0] < ticks[1] < ticks[2]
    fake.frozen = True
    for _ in range(3):
        fake.publish_state()
    assert _deliver(driver, 3) == 0 and driver.link.rejected["frozen tick"] == 3
    driver.clock.now_s += 0.2
    with pytest.raises(LinkLostError, match=r"rejected \{'frozen tick': 3\}"):
        driver.read()
    fake.frozen = False
    fake.publish_state()
    assert _deliver(driver, 1) == 1
    assert driver.read().position_rad.shape == (12,) and driver.link.reconnections == 1


def test_no_state_yet_is_link_lost(scene):
    driver = Go2Driver(ROBOT, DOMAIN_ID, topic_prefix=f"silent_{os.getpid()}")
    with pytest.raises(LinkLostError, match="no valid state received yet"):
        driver.read()
    assert not driver.wait_for_state(after_s=0.0, timeout_s=0.02)


def test_damping_and_sport_mode_release(link):
    _, fake, driver, prefix = link
    driver.send_damping(kd=3.0)
    raw = DataReader(driver.participant, Topic(driver.participant,
                                               topic_name(prefix, "lowcmd"), LowCmd_))
    driver.send_damping(kd=3.0)
    assert raw.take(N=4)[0].motor_cmd[0].q == pytest.approx(POS_STOP_F)
    assert fake.poll_commands()
    assert (fake.last_command.kp == 0).all() and (fake.last_command.kd == 3.0).all()
    fake.unanswered_requests = 2  # two answers lost: the driver asks again until answered
    fake.start(rate_hz=500.0)
    try:
        assert driver.release_sport_mode(timeout_s=2.0) == 0
    finally:
        fake.stop()
    assert fake.sport_mode_released and fake.unanswered_requests == 0
    alone = Go2Driver("alone", DOMAIN_ID, topic_prefix=f"alone_{os.getpid()}")
    with pytest.raises(DriverError, match="no motion-switcher service"):
        alone.release_sport_mode(timeout_s=0.05)


def test_one_interface_per_domain_and_process(link):
    with pytest.raises(DriverError, match="already runs on interface 'lo'"):
        open_participant(DOMAIN_ID, "eth9")


def test_the_firmware_holds_the_last_command_unless_its_timeout_is_modelled(scene):
    """Default: commands stop, the last torque stays (the unsafe case, as on the robot). With
    ``command_timeout_s`` the fake damps once the last command is that old (simulated time),
    and a new command takes over again."""
    prefix = f"timeout_{os.getpid()}_{next(_prefixes)}"
    simulation = TeamSimulation(scene)
    held = FakeGo2(simulation.robot_driver(ROBOT), DOMAIN_ID, topic_prefix=prefix + "_held")
    timed = FakeGo2(simulation.robot_driver("go2_1"), DOMAIN_ID, topic_prefix=prefix,
                    command_timeout_s=0.05)
    drivers = [Go2Driver("held", DOMAIN_ID, topic_prefix=prefix + "_held"),
               Go2Driver("timed", DOMAIN_ID, topic_prefix=prefix)]
    torque = JointCommand(torque_nm=np.full(12, 2.0))
    try:
        for driver, fake in zip(drivers, (held, timed), strict=True):
            driver.send(torque)
            assert fake.wait_for_command(2.0) and fake.poll_commands()
        simulation.step(40)  # 40 ms without a command: within the timeout
        assert not timed.poll_commands() and timed.last_command.torque_nm[0] == 2.0
        simulation.step(20)  # 60 ms
        assert not timed.poll_commands()  # no new command, but the firmware reacts
        damping = timed.last_command
        assert not damping.torque_nm.any() and not damping.kp.any() and damping.kd.all()
        assert timed.command_timeout.timeouts == 1
        assert not timed.poll_commands() and timed.command_timeout.timeouts == 1  # once
        assert not held.poll_commands() and held.last_command.torque_nm[0] == 2.0  # held
        assert held.command_timeout.timeouts == 0
        drivers[1].send(torque)
        assert timed.wait_for_command(2.0) and timed.poll_commands()
        assert timed.last_command.torque_nm[0] == 2.0
    finally:
        for item in (*drivers, held, timed):
            item.close()
