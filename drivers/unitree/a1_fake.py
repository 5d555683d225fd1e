"""``FakeA1``: a MuJoCo-backed UDP peer that speaks the A1's low-level protocol.

It wraps a simulated ``RobotDriver`` (``TeamSimulation.robot_driver(name)``) behind a UDP
socket on ``local_address`` (loopback by default): ``poll_commands`` drains LowCmd datagrams,
rejects (and counts) those of the wrong size, CRC, level flag or with non-finite values,
keeping the previous command, and sends the newest valid one to the sim driver (whose
firmware law applies it); ``publish_state`` sends a LowState of ``driver.read()`` (Unitree
motor and foot order, IMU quaternion wxyz) to ``peer_address``, or, when that is None, to
the source of the last valid command (the real robot answers whoever commands it).

Stepping is the caller's: step the simulation, then ``poll_commands`` / ``publish_state``
(deterministic). ``start(rate_hz, step)`` runs that cycle in a background thread.
"""

from __future__ import annotations

import select
import socket
from collections import Counter

from drivers.interfaces import JointCommand, RobotDriver
from drivers.unitree.a1_udp_layout import (
    LEVEL_FLAG_LOW,
    LOW_CMD_SIZE,
    Crc,
    LayoutError,
    decode_low_cmd,
    default_crc,
    encode_low_state,
)
from drivers.unitree.conventions import (
    command_problem,
    joint_command_from_wire_command,
    wire_state_from_measurement,
)
from drivers.unitree.firmware_timeout import CommandTimeout
from drivers.unitree.peer import PeriodicThread, RealTimeFake


class FakeA1(RealTimeFake):
    """UDP peer of an ``A1Driver``, backed by the simulated ``driver``. ``local_port`` 0 picks
    a free port (``local_endpoint`` tells which; give it to the driver as robot address)."""

    def __init__(self, driver: RobotDriver, local_address: str = "127.0.0.1",
                 local_port: int = 0, peer_address: tuple[str, int] | None = None,
                 foot_force_n_per_count: float = 1.0, crc: Crc = default_crc,
                 command_timeout_s: float | None = None) -> None:
        self.driver = driver
        self.command_timeout = CommandTimeout(command_timeout_s)
        self.peer_address = peer_address
        self.foot_force_n_per_count = foot_force_n_per_count
        self.crc = crc
        self._socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._socket.bind((local_address, local_port))
        self._socket.setblocking(False)
        self.local_endpoint: tuple[str, int] = self._socket.getsockname()
        self.commands_received = 0
        self.commands_rejected: Counter[str] = Counter()
        self.states_published = 0
        self.last_command: JointCommand | None = None
        self.frozen = False  # True: resend the last state byte for byte (see publish_state)
        self._last_state_bytes: bytes | None = None
        self._tick_ms = -1
        self._last_source: tuple[str, int] | None = None
        self._runner = PeriodicThread("FakeA1")

    def close(self) -> None:
        self.stop()
        self._socket.close()

    @property
    def commands_rejected_total(self) -> int:
        return sum(self.commands_rejected.values())

    def wait_for_command(self, timeout_s: float) -> bool:
        """Block until a datagram is pending or ``timeout_s`` [s] passed (then False); an
        answering peer (the real A1 answers each LowCmd) then calls ``poll_commands``."""
        readable, _, _ = select.select([self._socket], [], [], timeout_s)
        return bool(readable)

    def poll_commands(self) -> bool:
        """Check every pending LowCmd in arrival order; send the newest valid one to the sim
        driver. Returns whether a new command was applied."""
        newest: JointCommand | None = None
        while True:
            try:
                data, source = self._socket.recvfrom(4096)
            except (BlockingIOError, InterruptedError):
                break
            except ConnectionRefusedError:  # ICMP port unreachable after a state send
                continue
            self.commands_received += 1
            if len(data) != LOW_CMD_SIZE:
                self.commands_rejected["truncated" if len(data) < LOW_CMD_SIZE
                                       else "oversize"] += 1
                continue
            try:
                level_flag, wire = decode_low_cmd(data, self.crc)
            except LayoutError:
                self.commands_rejected["crc"] += 1
                continue
            problem = "level" if level_flag != LEVEL_FLAG_LOW else command_problem(wire)
            if problem is not None:
                self.commands_rejected[problem] += 1
                continue
            newest = joint_command_from_wire_command(wire)
            self._last_source = source
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

    def publish_state(self) -> bool:
        """Send the simulated robot's state to the peer; False when no peer is known yet. Its
        ``tick`` [ms] advances with every message, as the robot's does (simulated time in ms,
        at least one more than the last). ``frozen`` resends the last datagram byte for byte,
        tick included (a robot whose sensors or firmware loop stopped while its network stack
        runs on)."""
        peer = self.peer_address or self._last_source
        if peer is None:
            return False
        if self.frozen and self._last_state_bytes is not None:
            self._socket.sendto(self._last_state_bytes, peer)
            self.states_published += 1
            return True
        measurement = self.driver.read()
        self._tick_ms = max(round(measurement.time_s * 1000.0), self._tick_ms + 1)
        wire = wire_state_from_measurement(measurement, self.foot_force_n_per_count,
                                           tick_ms=self._tick_ms)
        self._last_state_bytes = encode_low_state(wire, crc=self.crc)
        self._socket.sendto(self._last_state_bytes, peer)
        self.states_published += 1
        return True

