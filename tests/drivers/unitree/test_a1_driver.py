"""A1 driver against its MuJoCo-backed fake over real UDP sockets on loopback: packed layout,
state and command round trips with the wire conventions checked on the raw datagrams,
rejection of malformed datagrams on both sides, link loss and recovery, default binding."""

from __future__ import annotations

import socket
import struct
import time

import numpy as np
import pytest

from core.model.conventions import LEG_JOINT_NAMES
from core.plant.standard_scenarios import ring_team_settings
from drivers.interfaces import JointCommand, RobotDriver
from drivers.link_errors import DriverError, LinkLostError
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters
from drivers.unitree.a1_driver import A1Driver
from drivers.unitree.a1_fake import FakeA1
from drivers.unitree.a1_udp_layout import (
    LOW_CMD_SIZE,
    LOW_STATE_SIZE,
    decode_low_cmd,
    decode_low_state,
    default_crc,
    encode_low_cmd,
    encode_low_state,
)
from drivers.unitree.conventions import (
    UNITREE_JOINT_NAMES,
    UNITREE_LEG_ORDER,
    WireState,
    wire_command_from_joint_command,
)

ROBOT = "a1_0"
FORCE_N_PER_COUNT = 0.1


class ManualClock:
    """Seconds that move only when told (deterministic link timeouts)."""

    def __init__(self) -> None:
        self.now_s = 100.0

    def __call__(self) -> float:
        return self.now_s


@pytest.fixture(scope="module")
def scene():
    return build_team_scene(ring_team_settings(["a1", "a1"], srb_parameters))


@pytest.fixture
def raw():
    """A plain UDP socket on loopback, standing in for a robot or a controller."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        sock.bind(("127.0.0.1", 0))
        sock.settimeout(2.0)
        yield sock


@pytest.fixture
def link(scene):
    simulation = TeamSimulation(scene)
    fake = FakeA1(simulation.robot_driver(ROBOT), foot_force_n_per_count=FORCE_N_PER_COUNT)
    driver = A1Driver(ROBOT, robot_address=fake.local_endpoint, local_port=0,
                      link_timeout_s=0.05, contact_threshold_n=1.0,
                      foot_force_n_per_count=FORCE_N_PER_COUNT, clock=ManualClock())
    fake.peer_address = driver.local_endpoint
    fake.publish_state()
    assert driver.wait_for_state(after_s=0.0, timeout_s=2.0)
    yield simulation, fake, driver
    fake.close()
    driver.close()


def test_layout_sizes_and_round_trip():
    assert (LOW_CMD_SIZE, LOW_STATE_SIZE) == (730, 891)
    wire = wire_command_from_joint_command(JointCommand(torque_nm=np.arange(12.0)), 0x0A)
    packet = encode_low_cmd(wire)
    assert len(packet) == 730 and packet[0] == 0xFF
    assert packet[10] == 0x0A  # motorCmd[0].mode right after the 10-byte header
    assert struct.unpack_from("<f", packet, 11 + 8)[0] == wire.tau_nm[0]  # tau after q, dq
    assert struct.unpack_from("<I", packet, 726)[0] == default_crc(packet)
    level, back = decode_low_cmd(packet)
    assert level == 0xFF
    np.testing.assert_array_equal(back.tau_nm, wire.tau_nm)
    state = WireState(tick_ms=1234, foot_force=np.array([1, -2, 3, 4], dtype=np.int16))
    state.q_rad[:] = np.arange(20) * 0.25
    level, state_back = decode_low_state(encode_low_state(state))
    np.testing.assert_array_equal(state_back.q_rad, state.q_rad)
    assert state_back.tick_ms == 1234 and list(state_back.foot_force) == [1, -2, 3, 4]


def test_driver_is_a_robot_driver(link):
    assert isinstance(link[2], RobotDriver)


def test_state_round_trip(link, raw):
    simulation, fake, driver = link
    robot = simulation.scene.robot(ROBOT)
    data = simulation.data
    data.qpos[robot.leg_qpos_addresses] += 0.01 * np.arange(1, 13)
    data.qvel[robot.leg_qvel_addresses] = -0.1 * np.arange(1, 13)
    quaternion = np.array([0.9, 0.1, -0.2, 0.3])
    data.qpos[robot.base_qpos_address + 3:robot.base_qpos_address + 7] = \
        quaternion / np.linalg.norm(quaternion)
    data.ctrl[robot.actuator_ids] = 0.5 * np.arange(1, 13)
    simulation.forward()
    truth = simulation.robot_driver(ROBOT).read()
    fake.peer_address = raw.getsockname()  # first the raw datagram: Unitree conventions
    fake.publish_state()
    _, state = decode_low_state(raw.recv(2048))
    fr_calf = LEG_JOINT_NAMES.index("FR_calf_joint")
    assert UNITREE_JOINT_NAMES[2] == "FR_calf_joint"
    assert state.q_rad[2] == pytest.approx(truth.position_rad[fr_calf], rel=1e-6)
    assert state.quaternion_wxyz[0] == pytest.approx(truth.quaternion_wxyz[0], rel=1e-6)
    rl = UNITREE_LEG_ORDER.index("RL")
    assert state.foot_force[rl] == round(truth.foot_normal_force_n[2] / FORCE_N_PER_COUNT)
    fake.peer_address = driver.local_endpoint
    fake.publish_state()
    driver.clock.now_s += 0.01
    assert driver.wait_for_state(after_s=driver.clock.now_s - 1e-3, timeout_s=2.0)
    measurement = driver.read()
    for name in ("position_rad", "velocity_rad_s", "torque_nm", "quaternion_wxyz",
                 "angular_velocity_in_body_rad_s"):
        np.testing.assert_allclose(getattr(measurement, name), getattr(truth, name),
                                   rtol=1e-6, atol=1e-6, err_msg=name)
    np.testing.assert_allclose(measurement.foot_normal_force_n, truth.foot_normal_force_n,
                               atol=FORCE_N_PER_COUNT / 2)
    assert measurement.time_s == driver.clock.now_s
    assert driver.link.rejected_total == 0


def test_command_round_trip(link, raw):
    simulation, fake, driver = link
    joints = np.arange(12)
    command = JointCommand(torque_nm=0.1 * joints + 0.05, position_rad=0.02 * joints - 0.1,
                           velocity_rad_s=0.3 - 0.05 * joints, kp=20.0 + joints,
                           kd=0.5 + 0.1 * joints)
    with A1Driver("probe", robot_address=raw.getsockname(), local_port=0) as probe:
        probe.send(command)
        packet = raw.recv(2048)
    level, wire = decode_low_cmd(packet)
    assert len(packet) == 730 and level == 0xFF
    assert list(wire.mode) == [0x0A] * 12 + [0] * 8
    fl_thigh = LEG_JOINT_NAMES.index("FL_thigh_joint")
    assert wire.kp[UNITREE_JOINT_NAMES.index("FL_thigh_joint")] == 20.0 + fl_thigh
    driver.send(command)
    assert _poll_until(fake)
    for name in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd"):
        np.testing.assert_allclose(getattr(fake.last_command, name), getattr(command, name),
                                   rtol=1e-6, err_msg=name)
    robot = simulation.scene.robot(ROBOT)
    before = simulation.robot_driver(ROBOT).read()
    low, high = simulation.model.actuator_ctrlrange[robot.actuator_ids].T
    expected = np.clip(fake.last_command.torque_for(before.position_rad, before.velocity_rad_s),
                       low, high)
    simulation.step()
    np.testing.assert_allclose(simulation.data.actuator_force[robot.actuator_ids], expected)


def _poll_until(fake: FakeA1, attempts: int = 200) -> bool:
    """Poll until a command is applied (loopback delivery is immediate; this is a margin)."""
    for _ in range(attempts):
        if fake.poll_commands():
            return True
        time.sleep(0.001)
    return False


def _with_crc(packet: bytes) -> bytes:
    return packet[:-4] + struct.pack("<I", default_crc(packet))


def test_malformed_commands_are_rejected_and_the_previous_one_kept(link, raw):
    _, fake, driver = link
    good = JointCommand(torque_nm=np.linspace(-1.0, 1.0, 12))
    driver.send(good)
    assert _poll_until(fake)
    valid = encode_low_cmd(wire_command_from_joint_command(JointCommand(torque_nm=5.0), 0x0A))
    flipped = bytearray(valid)
    flipped[20] ^= 0x40
    wrong_level = _with_crc(b"\0" + valid[1:])
    nan_wire = wire_command_from_joint_command(JointCommand(), 0x0A)
    nan_wire.q_rad[0] = np.nan
    for packet in (valid[:100], valid + b"\0", bytes(flipped), wrong_level,
                   encode_low_cmd(nan_wire)):
        raw.sendto(packet, fake.local_endpoint)
    for _ in range(100):
        fake.poll_commands()
        if fake.commands_rejected_total == 5:
            break
        time.sleep(0.001)
    assert dict(fake.commands_rejected) == {"truncated": 1, "oversize": 1, "crc": 1,
                                            "level": 1, "non-finite": 1}
    np.testing.assert_allclose(fake.last_command.torque_nm, good.torque_nm, rtol=1e-6)
    with pytest.raises(DriverError, match="non-finite torque_nm"):
        driver.send(JointCommand(torque_nm=np.full(12, np.nan)))


def test_malformed_states_are_rejected(raw):
    """The raw socket plays the robot; the driver only accepts it as the source."""
    driver = A1Driver(robot_address=raw.getsockname(), local_port=0, clock=ManualClock())
    valid_state = WireState()
    valid = encode_low_state(valid_state)
    nan_state = WireState()
    nan_state.dq_rad_s[1] = np.inf
    implausible = WireState(quaternion_wxyz=np.array([2.0, 0.0, 0.0, 0.0]))
    flipped = bytearray(valid)
    flipped[100] ^= 0x01
    packets = [valid[:-1], valid + b"\0\0", bytes(flipped), encode_low_state(nan_state),
               encode_low_state(implausible), valid]
    for packet in packets:
        raw.sendto(packet, driver.local_endpoint)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as stranger:
        stranger.sendto(valid, driver.local_endpoint)
    for _ in range(100):
        driver.poll()
        if driver.link.received + driver.link.rejected_total == 7:
            break
        time.sleep(0.001)
    assert driver.link.received == 1
    assert dict(driver.link.rejected) == {"truncated": 1, "oversize": 1, "crc": 1,
                                          "non-finite": 1, "implausible": 1, "source": 1}
    driver.read()
    driver.close()


def test_link_lost_then_recovered(link):
    _, fake, driver = link
    driver.read()
    driver.clock.now_s += 0.2
    with pytest.raises(LinkLostError, match=r"A1 LowState from 127.0.0.1.*timeout 0.05 s"):
        driver.read()
    fake.publish_state()
    assert driver.wait_for_state(after_s=driver.clock.now_s - 1.0, timeout_s=2.0)
    driver.read()
    assert driver.link.reconnections == 1


def test_a_frozen_state_is_a_lost_link_and_a_fresh_one_recovers(link):
    """As the Go2's: the fake's tick advances with every message, even with the simulation
    standing still; an A1 repeating its last datagram (same tick) is not heard from, so the
    link times out, and its next fresh state recovers it."""
    _, fake, driver = link

    def deliver(count: int) -> int:
        seen = driver.link.received + driver.link.rejected_total + count
        valid, deadline = 0, time.monotonic() + 2.0
        while driver.link.received + driver.link.rejected_total < seen:
            assert time.monotonic() < deadline, "states did not arrive"
            valid += driver.poll()
            time.sleep(0.001)
        return valid

    ticks = []
    for _ in range(3):
        fake.publish_state()  # simulated time does not move between these
        assert deliver(1) == 1
        assert driver.last_state is not None
        ticks.append(driver.last_state.tick_ms)
    assert ticks[0] < ticks[1] < ticks[2]
    fake.frozen = True
    for _ in range(3):
        fake.publish_state()
    assert deliver(3) == 0 and driver.link.rejected["frozen tick"] == 3
    driver.clock.now_s += 0.2
    with pytest.raises(LinkLostError, match=r"rejected \{'frozen tick': 3\}"):
        driver.read()
    fake.frozen = False
    fake.publish_state()
    assert deliver(1) == 1
    assert driver.read().position_rad.shape == (12,) and driver.link.reconnections == 1


def test_default_binding_is_loopback_and_cannot_reach_the_robot():
    driver = A1Driver(local_port=0)
    assert driver.local_endpoint[0] == "127.0.0.1"
    assert driver.robot_address == ("192.168.123.10", 8007)
    with pytest.raises(LinkLostError, match="no valid state received yet"):
        driver.read()
    with pytest.raises(DriverError, match="is local_address on the robot's network"):
        driver.send(JointCommand())
    driver.close()


def test_crc_is_replaceable(link, raw):
    _, fake, _ = link
    other_crc = A1Driver("other_crc", robot_address=fake.local_endpoint, local_port=0,
                         crc=lambda packet: 0x12345678)
    other_crc.send(JointCommand())
    before = fake.commands_rejected["crc"]
    for _ in range(100):
        fake.poll_commands()
        if fake.commands_rejected["crc"] > before:
            break
        time.sleep(0.001)
    assert fake.commands_rejected["crc"] == before + 1
    other_crc.close()


def test_real_time_round_trip(link):
    simulation, fake, _ = link
    driver = A1Driver("rt", robot_address=fake.local_endpoint, local_port=0)
    fake.peer_address = None  # answer whoever commands, like the robot
    fake.start(rate_hz=1000.0)
    try:
        start_s = driver.clock()
        driver.send(JointCommand())
        assert driver.wait_for_state(after_s=start_s, timeout_s=2.0)
        assert driver.read().position_rad.shape == (12,)
    finally:
        fake.stop()
        driver.close()
    assert simulation.time_s == 0.0  # no step callable given: the fake only relays
