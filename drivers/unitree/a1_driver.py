"""Unitree A1 low-level driver over UDP (unitree_legged_sdk 3.3.x protocol): ``RobotDriver``.

Frames and units as ``drivers.interfaces``; Unitree's motor and foot order are converted in
``drivers.unitree.conventions``, once. The A1 measures no world position or linear velocity: they
read zero (porter's estimator pipeline, ``deploy.runtime.state_pipeline``, fills them in).

Network: the socket binds to ``local_address`` (127.0.0.1 by default, so nothing beyond this
machine is reachable until an address on the robot's network, e.g. 192.168.123.162, is
configured) and port ``local_port``; commands go to ``robot_address`` (192.168.123.10:8007).
Datagrams from any other source are rejected. The robot answers each LowCmd with a LowState.

Receiving never blocks: ``poll`` drains the socket, rejecting and counting datagrams that
are truncated or oversize, fail the CRC (UNVERIFIED for the A1: see
``drivers.unitree.a1_udp_layout``), are not low level, or hold non-finite / implausible values.

Round trip (for ``porter bench drivers``): ``t = driver.clock(); driver.send(command);
driver.wait_for_state(after_s=t, timeout_s=...)``; then ``driver.clock() - t``.
"""

from __future__ import annotations

import select
import socket
import time
from collections.abc import Callable

from drivers.link_errors import DriverError, LinkMonitor
from drivers.unitree.a1_udp_layout import (
    LEVEL_FLAG_LOW,
    LOW_STATE_SIZE,
    MOTOR_MODE_SERVO,
    Crc,
    LayoutError,
    decode_low_state,
    default_crc,
    encode_low_cmd,
)
from drivers.unitree.conventions import (
    WireCommand,
    WireState,
    state_problem,
)
from drivers.unitree.peer import UnitreeLowLevelDriver

ROBOT_ADDRESS = ("192.168.123.10", 8007)
LOCAL_ADDRESS = "127.0.0.1"
LOCAL_PORT = 8080
_RECEIVE_BUFFER_BYTES = 4096  # larger than any valid datagram, so oversize ones are seen


class A1Driver(UnitreeLowLevelDriver):
    """One A1 over UDP. ``read`` raises ``LinkLostError`` without a valid state in the last
    ``link_timeout_s`` [s] (on ``clock``, seconds) and recovers when states resume.

    Foot forces [N] = raw counts x ``foot_force_n_per_count`` (UNVERIFIED scale); contact where
    the force exceeds ``contact_threshold_n``. Measurement ``time_s`` is the receive time on
    ``clock``. ``local_port`` 0 picks a free port (``local_endpoint`` tells which).
    """

    def __init__(self, name: str = "a1", robot_address: tuple[str, int] = ROBOT_ADDRESS,
                 local_address: str = LOCAL_ADDRESS, local_port: int = LOCAL_PORT,
                 link_timeout_s: float = 0.1, contact_threshold_n: float = 20.0,
                 foot_force_n_per_count: float = 1.0,
                 crc: Crc = default_crc,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self._name = name
        self.motor_mode = MOTOR_MODE_SERVO
        self.robot_address = (socket.gethostbyname(robot_address[0]), int(robot_address[1]))
        self.clock = clock
        self.crc = crc
        self.contact_threshold_n = contact_threshold_n
        self.foot_force_n_per_count = foot_force_n_per_count
        self._socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            self._socket.bind((local_address, local_port))
        except OSError as error:
            self._socket.close()
            raise DriverError(f"{name}: cannot bind UDP {local_address}:{local_port}: {error}"
                              ) from error
        self._socket.setblocking(False)
        self.local_endpoint: tuple[str, int] = self._socket.getsockname()
        self.link = LinkMonitor(
            f"{name}: A1 LowState from {self.robot_address[0]}:{self.robot_address[1]}",
            link_timeout_s, clock)
        self.commands_sent = 0
        self.last_state: WireState | None = None

    def close(self) -> None:
        """Close the socket."""
        self._socket.close()

    def __enter__(self) -> A1Driver:
        return self

    def __exit__(self, *exc_info: object) -> None:
        self.close()

    def poll(self) -> int:
        """Drain the socket; keep the newest valid state. Returns how many were valid."""
        valid = 0
        while True:
            try:
                data, source = self._socket.recvfrom(_RECEIVE_BUFFER_BYTES)
            except (BlockingIOError, InterruptedError):
                return valid
            except ConnectionRefusedError:  # ICMP port unreachable after a send
                continue
            problem, state = self._parse(data, source)
            if state is None:
                self.link.reject(problem)
                continue
            self.link.accept()
            self.last_state, valid = state, valid + 1

    def _parse(self, data: bytes, source: tuple[str, int]) -> tuple[str, WireState | None]:
        if source[:2] != self.robot_address:
            return "source", None
        if len(data) != LOW_STATE_SIZE:
            return ("truncated" if len(data) < LOW_STATE_SIZE else "oversize"), None
        try:
            level_flag, state = decode_low_state(data, self.crc)
        except LayoutError:
            return "crc", None
        if level_flag != LEVEL_FLAG_LOW:
            return "level", None
        problem = state_problem(state)
        if problem is None and self.last_state is not None \
                and state.tick_ms == self.last_state.tick_ms:
            # As on the Go2: the robot's tick advances with every message, so the same tick
            # again is a frozen state (sensors or firmware loop stopped), and a robot that
            # keeps repeating itself ends in a lost link after the timeout.
            problem = "frozen tick"
        return (problem, None) if problem is not None else ("", state)

    def _wait_readable(self, timeout_s: float) -> None:
        select.select([self._socket], [], [], timeout_s)

    def send_wire(self, wire: WireCommand) -> None:
        """Send a wire-convention command as a LowCmd datagram."""
        try:
            self._socket.sendto(encode_low_cmd(wire, self.crc), self.robot_address)
        except OSError as error:
            raise DriverError(
                f"{self._name}: cannot send to {self.robot_address[0]}:{self.robot_address[1]}"
                f" from {self.local_endpoint[0]}:{self.local_endpoint[1]} ({error}); is"
                " local_address on the robot's network?") from error
        self.commands_sent += 1
