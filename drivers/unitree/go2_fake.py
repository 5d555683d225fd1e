"""``FakeGo2``: a MuJoCo-backed DDS peer that speaks the Go2's low-level protocol.

It wraps a simulated ``RobotDriver`` (``TeamSimulation.robot_driver(name)``):
``publish_state`` writes a ``LowState_`` of ``driver.read()`` on ``rt/lowstate`` (Unitree motor
and foot order, IMU quaternion wxyz, gyroscope in body, foot forces as counts);
``poll_commands`` takes the ``LowCmd_`` on ``rt/lowcmd``, rejects (and counts) those with a
wrong CRC, head, level flag or non-finite values, keeping the previous command, and sends
the newest valid one to the sim driver, whose firmware law applies it. It also answers the
motion switcher's ReleaseMode request (``sport_mode_released``).

Stepping is the caller's: step the simulation, then ``publish_state`` / ``poll_commands``
(deterministic). ``start(rate_hz, step)`` runs the same cycle in a background thread for
real-time use; the caller keeps the simulation safe from concurrent access.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace

from cyclonedds.core import ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from drivers.interfaces import JointCommand, RobotDriver
from drivers.unitree.conventions import (
    WireCommand,
    command_problem,
    joint_command_from_wire_command,
    wire_state_from_measurement,
)
from drivers.unitree.firmware_timeout import CommandTimeout
from drivers.unitree.go2_cdr import LowCmdCodec, LowStateCodec
from drivers.unitree.go2_dds_types import (
    LowCmd_,
    LowState_,
    Request_,
    Response_,
    api_response,
)
from drivers.unitree.go2_driver import (
    API_ID_RELEASE_MODE,
    MOTION_SWITCHER_SERVICE,
    REQUEST_QOS,
    open_participant,
    take_raw,
    topic_name,
    write_raw,
)
from drivers.unitree.peer import PeriodicThread, RealTimeFake

API_NOT_IMPLEMENTED_CODE = 3102  # unitree_sdk2 RPC_ERR_SERVER_API_NOT_IMPL
COMMAND_QUEUE = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(32))


class FakeGo2(RealTimeFake):
    """DDS peer of a ``Go2Driver``, backed by the simulated ``driver``. Same ``domain_id``,
    ``network_interface`` (loopback when None) and ``topic_prefix`` as the driver's."""

    def __init__(self, driver: RobotDriver, domain_id: int = 0,
                 network_interface: str | None = None, topic_prefix: str = "",
                 foot_force_n_per_count: float = 1.0,
                 command_timeout_s: float | None = None) -> None:
        self.driver = driver
        self.command_timeout = CommandTimeout(command_timeout_s)
        self.foot_force_n_per_count = foot_force_n_per_count
        self.participant = open_participant(domain_id, network_interface)
        p = self.participant
        self._state_writer = DataWriter(p, Topic(p, topic_name(topic_prefix, "lowstate"),
                                                 LowState_))
        self._command_reader = DataReader(
            p, Topic(p, topic_name(topic_prefix, "lowcmd"), LowCmd_), qos=COMMAND_QUEUE)
        service = f"api/{MOTION_SWITCHER_SERVICE}"
        self._request_reader = DataReader(
            p, Topic(p, topic_name(topic_prefix, f"{service}/request"), Request_),
            qos=REQUEST_QOS)
        self._response_writer = DataWriter(
            p, Topic(p, topic_name(topic_prefix, f"{service}/response"), Response_),
            qos=REQUEST_QOS)
        self.commands_received = 0
        self.commands_rejected: Counter[str] = Counter()
        self.states_published = 0
        self.frozen = False  # True: republish the last state unchanged (see publish_state)
        # fault injection: "garbage" publishes bytes that are no LowState_, "nan" a state with
        # a joint angle that is not a number, "bad_crc" states with one bit of the CRC flipped
        # (see publish_state)
        self.corrupt: str | None = None
        self._tick_ms = -1
        self._last_state_bytes: bytes | None = None
        self.last_command: JointCommand | None = None
        self.sport_mode_released = False
        # fault injection: this many motion-switcher requests go unanswered (an answer lost on
        # the way, as when the service's writer has not yet matched the client's reader)
        self.unanswered_requests = 0
        self._runner = PeriodicThread("FakeGo2")
        self._states, self._commands = LowStateCodec(), LowCmdCodec()
        self._command_waitset = WaitSet(p)
        self._command_waitset.attach(ReadCondition(self._command_reader,
                                                   SampleState.NotRead | ViewState.Any))

    def wait_for_command(self, timeout_s: float) -> bool:
        """Block until a ``LowCmd_`` is pending or ``timeout_s`` [s] passed (then False);
        an answering peer (``porter bench drivers``) then calls ``poll_commands``."""
        return bool(self._command_waitset.wait(duration(seconds=timeout_s)))

    def publish_state(self) -> None:
        """Write the simulated robot's current state as a ``LowState_``. Its ``tick`` [ms]
        advances with every message, as the robot's does (simulated time in ms, at least one
        more than the last); ``frozen`` repeats the last message byte for byte (a robot whose
        state stopped updating while it keeps publishing)."""
        if self.frozen and self._last_state_bytes is not None:
            write_raw(self._state_writer, self._last_state_bytes)
            self.states_published += 1
            return
        if self.corrupt == "garbage":
            # DDS itself refuses a sample of the wrong size, so: a LowState_'s size and CDR
            # header with every byte after it 0xFF (every float NaN, the tick 2^32 - 1)
            size = self._states.size
            write_raw(self._state_writer, self._states.encode_header() + b"\xff" * (size - 4))
            self.states_published += 1
            return
        measurement = self.driver.read()
        if self.corrupt == "nan":
            position = measurement.position_rad.copy()
            position[4] = float("nan")
            measurement = replace(measurement, position_rad=position)
        self._tick_ms = max(round(measurement.time_s * 1000.0), self._tick_ms + 1)
        wire = wire_state_from_measurement(measurement, self.foot_force_n_per_count,
                                           tick_ms=self._tick_ms)
        self._last_state_bytes = self._states.encode(wire)
        if self.corrupt == "bad_crc":
            data = bytearray(self._last_state_bytes)
            data[-1] ^= 0x01  # the crc field is the sample's last 4 bytes (no padding after)
            self._last_state_bytes = bytes(data)
        write_raw(self._state_writer, self._last_state_bytes)
        self.states_published += 1

    def poll_commands(self) -> bool:
        """Check every pending ``LowCmd_`` in arrival order; send the newest valid one to the
        sim driver. Returns whether a new command was applied. Also serves ReleaseMode."""
        self._serve_motion_switcher()
        newest: JointCommand | None = None
        for data in take_raw(self._command_reader, 32):
            self.commands_received += 1
            problem, wire = self._command_problem(data)
            if problem is not None or wire is None:
                self.commands_rejected[problem or "encoding"] += 1
                continue
            newest = joint_command_from_wire_command(wire)
        # the firmware's reaction to silence (simulated time from the robot's own clock)
        damping = self.command_timeout.update(newest, lambda: self.driver.read().time_s)
        if damping is not None:
            self.driver.send(damping)
            self.last_command = damping
        if newest is None:
            return False
        self.driver.send(newest)
        self.last_command = newest
        return True

    @property
    def commands_rejected_total(self) -> int:
        return sum(self.commands_rejected.values())

    def _command_problem(self, data: bytes) -> tuple[str | None, WireCommand | None]:
        """Why a received ``LowCmd_`` must be rejected (or None), and its values."""
        try:
            wire, header_ok, crc_ok = self._commands.decode(data)
        except ValueError:
            return "encoding", None
        if not crc_ok:
            return "crc", wire
        if not header_ok:
            return "header", wire
        return command_problem(wire), wire

    def _serve_motion_switcher(self) -> None:
        for request in self._request_reader.take(N=8):
            if not isinstance(request, Request_):
                continue
            identity = request.header.identity
            code = 0 if identity.api_id == API_ID_RELEASE_MODE else API_NOT_IMPLEMENTED_CODE
            self.sport_mode_released |= code == 0
            if self.unanswered_requests > 0:
                self.unanswered_requests -= 1
                continue
            if not request.header.policy.noreply:
                self._response_writer.write(api_response(request, code))

    def close(self) -> None:
        """Stop; the DDS entities go with the participant (one per domain and process)."""
        self.stop()
