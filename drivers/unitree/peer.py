"""What the Go2 (DDS) and A1 (UDP) shims share: the driver side's read/send around the
transport-specific ``poll`` / ``send_wire``, and the fakes' real-time thread."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

import numpy as np

from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.link_errors import DriverError, LinkMonitor
from drivers.unitree.conventions import (
    WireCommand,
    WireState,
    damping_wire_command,
    measurement_from_wire_state,
    wire_command_from_joint_command,
)


class UnitreeLowLevelDriver:
    """``RobotDriver`` over a Unitree low-level link; subclasses provide ``poll`` (take what
    arrived, validating into ``last_state`` / ``link``) and ``send_wire``."""

    _name: str
    motor_mode: int
    link: LinkMonitor
    last_state: WireState | None
    foot_force_n_per_count: float
    contact_threshold_n: float

    @property
    def name(self) -> str:
        return self._name

    def poll(self) -> int:
        raise NotImplementedError

    def send_wire(self, wire: WireCommand) -> None:
        raise NotImplementedError

    def _wait_readable(self, timeout_s: float) -> None:
        """Block until something may have arrived or ``timeout_s`` [s] passed."""
        raise NotImplementedError

    def wait_for_state(self, after_s: float, timeout_s: float) -> bool:
        """Block until a valid state received later than ``after_s`` (on ``clock``) is in, or
        ``timeout_s`` [s] passed (then False)."""
        deadline_s = time.monotonic() + timeout_s
        while True:
            self.poll()
            last_s = self.link.last_receive_time_s
            if last_s is not None and last_s > after_s:
                return True
            left_s = deadline_s - time.monotonic()
            if left_s <= 0.0:
                return False
            self._wait_readable(min(left_s, 0.05))

    def read(self) -> RobotMeasurement:
        """The latest valid state in porter's conventions; raises ``LinkLostError`` if stale."""
        self.poll()
        self.link.check()
        assert self.last_state is not None and self.link.last_receive_time_s is not None
        return measurement_from_wire_state(self.last_state, self.link.last_receive_time_s,
                                           self.foot_force_n_per_count,
                                           self.contact_threshold_n)

    def send(self, command: JointCommand) -> None:
        """Send ``command`` in servo mode on the 12 leg motors; non-finite values are refused."""
        for field_name in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd"):
            if not np.isfinite(getattr(command, field_name)).all():
                raise DriverError(f"{self._name}: refusing a non-finite {field_name} command:"
                                  f" {getattr(command, field_name)}")
        self.send_wire(wire_command_from_joint_command(command, self.motor_mode))

    def send_damping(self, kd: float = 2.0) -> None:
        """Safe stop: position loops off (PosStopF), tau = kd [N m s/rad] x (0 - dq)."""
        self.send_wire(damping_wire_command(kd, self.motor_mode))

    def close(self) -> None:
        """Release the link; subclasses with sockets or DDS entities override it."""


class PeriodicThread:
    """Runs a list of calls every 1 / rate_hz s in a daemon thread (a fake's real-time mode)."""

    def __init__(self, name: str) -> None:
        self.name = name
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()

    def start(self, rate_hz: float, calls: list[Callable[[], object]]) -> None:
        if self._thread is not None:
            raise RuntimeError(f"{self.name} already started")
        period_s = 1.0 / rate_hz
        self._stop.clear()

        def loop() -> None:
            next_s = time.monotonic()
            while not self._stop.is_set():
                for call in calls:
                    call()
                next_s += period_s
                self._stop.wait(max(0.0, next_s - time.monotonic()))

        self._thread = threading.Thread(target=loop, name=self.name, daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the thread (no-op when not started)."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None


class RealTimeFake:
    """The real-time mode shared by the robot fakes: ``start`` runs a step (e.g. advancing the
    simulation), ``poll_commands`` and ``publish_state`` every 1 / ``rate_hz`` s in a daemon
    thread until ``stop``. Subclasses set ``_runner`` and define the two calls."""

    _runner: PeriodicThread

    def poll_commands(self) -> bool:
        raise NotImplementedError

    def publish_state(self) -> object:
        raise NotImplementedError

    def start(self, rate_hz: float, step: Callable[[], None] | None = None) -> None:
        calls: list[Callable[[], object]] = [] if step is None else [step]
        self._runner.start(rate_hz, [*calls, self.poll_commands, self.publish_state])

    def stop(self) -> None:
        """Stop the background thread (no-op when not started)."""
        self._runner.stop()
