"""CAN e-stop heartbeat and F/T sensors over python-can's virtual bus: frame layout and
quantization, e-stop press / heartbeat loss / resume, bad frames rejected and counted, and
coupling wrenches of a MuJoCo TeamSimulation through the bus."""

from __future__ import annotations

import itertools
import time

import can
import numpy as np
import pytest

from core.plant.standard_scenarios import ring_team_settings
from drivers.can.bus import EstopMonitor, ForceTorqueSensors
from drivers.can.fake import FakeCanNode
from drivers.can.protocol import (
    FORCE_RESOLUTION_N,
    TORQUE_RESOLUTION_NM,
    CanFrameError,
    EstopState,
    decode_estop_heartbeat,
    decode_wrench_half,
    encode_estop_heartbeat,
    encode_wrench,
)
from drivers.interfaces import JointCommand
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters

WAIT_S = 2.0
_channels = itertools.count()


@pytest.fixture
def channel() -> str:
    """A virtual CAN channel of its own (virtual channels are shared process-wide)."""
    return f"porter-test-{next(_channels)}"


def _wait_until(condition, timeout_s: float = WAIT_S) -> bool:
    deadline_s = time.monotonic() + timeout_s
    while not condition():
        if time.monotonic() > deadline_s:
            return False
        time.sleep(0.002)
    return True


# --- layout ---------------------------------------------------------------------------------
def test_frames_round_trip_within_quantization_and_saturate():
    heartbeat = decode_estop_heartbeat(encode_estop_heartbeat(300, EstopState.STOPPED))
    assert (heartbeat.counter, heartbeat.state) == (300 % 256, EstopState.STOPPED)
    force_n, torque_nm = np.array([12.345, -0.004, 250.0]), np.array([0.1234, -3.0, 0.0])
    force, torque = (decode_wrench_half(m) for m in encode_wrench(3, force_n, torque_nm, 9))
    assert force.is_force and not torque.is_force
    assert force.sensor_index == torque.sensor_index == 3
    assert force.sample_counter == torque.sample_counter == 9
    assert np.abs(force.values - force_n).max() <= FORCE_RESOLUTION_N / 2 + 1e-12
    assert np.abs(torque.values - torque_nm).max() <= TORQUE_RESOLUTION_NM / 2 + 1e-12
    assert not force.saturated and not torque.saturated
    force, torque = (decode_wrench_half(m) for m in encode_wrench(
        0, np.array([400.0, -400.0, np.nan]), np.array([0.0, 40.0, 0.0]), 1))
    assert force.saturated and torque.saturated
    np.testing.assert_allclose(force.values, [327.67, -327.67, 0.0])
    np.testing.assert_allclose(torque.values, [0.0, 32.767, 0.0])


@pytest.mark.parametrize(("message", "reason"), [
    (can.Message(arbitration_id=0x010, is_extended_id=False, data=b"\x01"), "length"),
    (can.Message(arbitration_id=0x010, is_extended_id=True, data=b"\x01\x00"), "frame type"),
    (can.Message(arbitration_id=0x010, is_extended_id=False, is_remote_frame=True, dlc=2),
     "frame type"),
    (can.Message(arbitration_id=0x010, is_extended_id=False, data=b"\x01\x07"), "state"),
    (can.Message(arbitration_id=0x011, is_extended_id=False, data=b"\x01\x00"), "id"),
])
def test_bad_heartbeat_frames_are_rejected(message, reason):
    with pytest.raises(CanFrameError) as error:
        decode_estop_heartbeat(message)
    assert error.value.reason == reason


@pytest.mark.parametrize(("message", "reason"), [
    (can.Message(arbitration_id=0x200, is_extended_id=False, data=bytes(6)), "length"),
    (can.Message(arbitration_id=0x300, is_extended_id=False, data=bytes(8)), "id"),
    (can.Message(arbitration_id=0x201, is_extended_id=False,
                 data=b"\x00\x80" + bytes(6)), "value"),
])
def test_bad_force_torque_frames_are_rejected(message, reason):
    with pytest.raises(CanFrameError) as error:
        decode_wrench_half(message)
    assert error.value.reason == reason


# --- e-stop -------------------------------------------------------------------------------
def test_estop_press_heartbeat_loss_and_resume(channel):
    with EstopMonitor(channel=channel, timeout_s=0.1) as monitor:
        assert not monitor.is_run_allowed()
        assert "no e-stop heartbeat" in monitor.reason()
        with FakeCanNode(channel=channel, heartbeat_period_s=0.01) as node:
            assert _wait_until(monitor.is_run_allowed)
            node.press_estop()
            assert _wait_until(lambda: not monitor.is_run_allowed())
            assert "e-stop pressed" in monitor.reason()
            node.release_estop()
            assert _wait_until(monitor.is_run_allowed)
            node.stop_heartbeat()
            stopped_s = time.monotonic()
            assert _wait_until(lambda: not monitor.is_run_allowed())
            assert time.monotonic() - stopped_s >= 0.09
            assert "heartbeat lost" in monitor.reason()
            node.resume()
            assert _wait_until(monitor.is_run_allowed)
        assert monitor.counters.frames_received >= 3  # run, stopped, run, (silence), run
        assert monitor.counters.frames_rejected == 0
        assert monitor.heartbeats_missed == 0


def test_bad_can_frames_are_rejected_counted_and_do_not_refresh_the_heartbeat(channel):
    clock_s = [0.0]
    with EstopMonitor(channel=channel, timeout_s=0.1, clock=lambda: clock_s[0]) as monitor, \
            ForceTorqueSensors(["go2_0", "go2_1"], monitor.bus) as sensors, \
            can.Bus(interface="virtual", channel=channel) as raw, \
            FakeCanNode(raw, heartbeat=False) as node:
        node.send_heartbeat()
        assert _wait_until(lambda: monitor.counters.frames_received == 1)
        assert monitor.is_run_allowed()
        clock_s[0] = 0.2  # the heartbeat is now too old; only valid frames may refresh it
        repeated = encode_estop_heartbeat(node._heartbeat_counter, EstopState.RUN)
        bad = [repeated,
               can.Message(arbitration_id=0x010, is_extended_id=False, data=b"\x05"),
               can.Message(arbitration_id=0x010, is_extended_id=False, data=b"\x05\x03"),
               can.Message(arbitration_id=0x010, is_extended_id=True, data=b"\x05\x00"),
               *encode_wrench(5, np.zeros(3), np.zeros(3), 1),  # sensor 5: no such robot
               can.Message(arbitration_id=0x202, is_extended_id=False, data=bytes(7))]
        for message in bad:
            raw.send(message)
        raw.send(can.Message(arbitration_id=0x123, is_extended_id=False, data=b""))  # not ours
        assert _wait_until(lambda: monitor.counters.frames_rejected == 4
                           and sensors.counters.frames_rejected == 3)
        assert monitor.counters.rejection_reasons == {"counter": 1, "length": 1, "state": 1,
                                                      "frame type": 1}
        assert sensors.counters.rejection_reasons == {"sensor": 2, "length": 1}
        assert not monitor.is_run_allowed() and "heartbeat lost" in monitor.reason()
        assert sensors.latest() == {}
        node.send_heartbeat()
        assert _wait_until(monitor.is_run_allowed)


# --- force/torque -----------------------------------------------------------------------------
def test_samples_pair_by_counter(channel):
    with ForceTorqueSensors(["go2_0"], channel=channel) as sensors, \
            can.Bus(interface="virtual", channel=channel) as raw:
        force_a, _ = encode_wrench(0, np.ones(3), np.ones(3), 1)
        force_b, torque_b = encode_wrench(0, 2 * np.ones(3), 2 * np.ones(3), 2)
        for message in (force_a, torque_b, force_b):
            raw.send(message)
        assert _wait_until(lambda: sensors.reading("go2_0") is not None)
        reading = sensors.reading("go2_0")
        assert reading is not None and reading.sample_counter == 2
        np.testing.assert_allclose(reading.force_n, 2.0)
        assert sensors.samples_incomplete == 1  # force_a never met its torque
        assert sensors.age_s("go2_0") < WAIT_S
        with pytest.raises(KeyError, match="go2_0"):
            sensors.reading("nobody")


def test_team_simulation_coupling_wrenches_through_the_bus(channel):
    team = ring_team_settings(["go2", "go2"], srb_parameters)
    scene = build_team_scene(team)
    simulation = TeamSimulation(scene)
    names = [robot.name for robot in scene.robots]
    for robot in scene.robots:
        simulation.robot_driver(robot.name).send(
            JointCommand.hold(scene.initial_qpos[robot.leg_qpos_addresses], 100.0, 5.0))
    simulation.step(100)
    with ForceTorqueSensors(names, channel=channel) as sensors, \
            EstopMonitor(sensors.bus) as monitor, \
            FakeCanNode(channel=channel, robot_names=names,
                        wrench_source=simulation.coupling_wrench) as node:
        assert node.publish_wrenches() == 4
        assert _wait_until(lambda: len(sensors.latest()) == 2 and monitor.is_run_allowed())
        for name in names:
            force_n, torque_nm = simulation.coupling_wrench(name)
            assert np.linalg.norm(force_n) > 1.0  # carrying a share of the payload
            reading = sensors.reading(name)
            assert reading is not None and not reading.saturated
            assert np.abs(reading.force_n - force_n).max() <= FORCE_RESOLUTION_N / 2 + 1e-9
            assert np.abs(reading.torque_nm - torque_nm).max() <= TORQUE_RESOLUTION_NM / 2 + 1e-9
        assert sensors.counters.frames_rejected == 0
    assert sensors.notifier.stopped  # the last reader out stopped the shared notifier
