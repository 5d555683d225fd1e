"""CAN readers: the e-stop heartbeat monitor and the coupling force/torque sensors.

Both are ``can.Listener``s fed by a ``can.Notifier`` (its own thread), frames laid out as in
``drivers.can.protocol``. Each takes either a ``can.BusABC`` or an interface/channel to open
one (default ``interface="virtual"``). python-can allows one notifier per bus: a reader given
a bus that already has a notifier joins it, so ``EstopMonitor(bus)`` and
``ForceTorqueSensors(names, bus)`` can share one bus; the last reader to close stops the
notifier and shuts down the bus if a reader opened them. Times are on the injected monotonic
``clock`` [s]. Frames of other ids are ignored; frames with this reader's id that do not fit
the layout are rejected and counted by reason.
"""

from __future__ import annotations

import math
import threading
import time
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Self

import can

from drivers.can.protocol import (
    ESTOP_HEARTBEAT_ID,
    MAX_SENSORS,
    CanFrameError,
    EstopHeartbeat,
    EstopState,
    WrenchHalf,
    decode_estop_heartbeat,
    decode_wrench_half,
    is_force_torque_id,
)
from drivers.interfaces import EstopStatus, WrenchReading

DEFAULT_CHANNEL = "porter"
_NOTIFIER_POLL_S = 0.01
_OPENED_BUSES: weakref.WeakSet[can.BusABC] = weakref.WeakSet()
_OPENED_NOTIFIERS: weakref.WeakSet[can.Notifier] = weakref.WeakSet()


@dataclass
class CanCounters:
    frames_received: int = 0  # valid frames for this reader
    frames_rejected: int = 0  # this reader's ids, not fitting the layout
    rejection_reasons: dict[str, int] = field(default_factory=dict)


class _CanReader(can.Listener):
    """Bus and notifier bookkeeping shared by the readers; subclasses implement ``_handle``
    (return False for frames that are not theirs, raise ``CanFrameError`` to reject)."""

    def __init__(self, bus: can.BusABC | None, interface: str, channel: str,
                 clock: Callable[[], float]) -> None:
        self._clock = clock
        self._lock = threading.Lock()
        self.counters = CanCounters()
        self._closed = False
        if bus is None:
            bus = can.Bus(interface=interface, channel=channel)
            _OPENED_BUSES.add(bus)
        self.bus = bus
        notifiers = can.Notifier.find_instances(bus)
        if notifiers:
            self.notifier = notifiers[0]
            self.notifier.add_listener(self)
        else:
            self.notifier = can.Notifier(bus, [self], timeout=_NOTIFIER_POLL_S)
            _OPENED_NOTIFIERS.add(self.notifier)

    def on_message_received(self, msg: can.Message) -> None:
        try:
            with self._lock:
                if self._handle(msg, self._clock()):
                    self.counters.frames_received += 1
        except CanFrameError as error:
            with self._lock:
                self.counters.frames_rejected += 1
                reasons = self.counters.rejection_reasons
                reasons[error.reason] = reasons.get(error.reason, 0) + 1

    def _handle(self, message: can.Message, now_s: float) -> bool:
        raise NotImplementedError

    def close(self) -> None:
        """Leave the notifier; the last reader out stops what readers opened."""
        if self._closed:
            return
        self._closed = True
        if self in self.notifier.listeners:
            self.notifier.remove_listener(self)
        if self.notifier in _OPENED_NOTIFIERS and not self.notifier.listeners:
            self.notifier.stop(timeout=1.0)
            if self.bus in _OPENED_BUSES:
                self.bus.shutdown()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()


class EstopMonitor(_CanReader):
    """Run is allowed only while valid heartbeats say "run" and the last one is at most
    ``timeout_s`` old. A heartbeat whose counter repeats the previous one (a stuck sender)
    is rejected; skipped counters are counted in ``heartbeats_missed``."""

    def __init__(self, bus: can.BusABC | None = None, *, interface: str = "virtual",
                 channel: str = DEFAULT_CHANNEL, timeout_s: float = 0.1,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if timeout_s <= 0.0:
            raise ValueError(f"heartbeat timeout must be positive, got {timeout_s} s")
        self.timeout_s = timeout_s
        self.heartbeats_missed = 0
        self._last: EstopHeartbeat | None = None
        self._last_receive_s: float | None = None
        super().__init__(bus, interface, channel, clock)

    def _handle(self, message: can.Message, now_s: float) -> bool:
        if message.arbitration_id != ESTOP_HEARTBEAT_ID:
            return False
        heartbeat = decode_estop_heartbeat(message)
        if self._last is not None:
            step = (heartbeat.counter - self._last.counter) % 256
            if step == 0:
                raise CanFrameError(f"e-stop heartbeat: repeated counter {heartbeat.counter}",
                                    "counter")
            self.heartbeats_missed += step - 1
        self._last, self._last_receive_s = heartbeat, now_s
        return True

    @property
    def last_receive_time_s(self) -> float | None:
        """When (on ``clock``) the last valid heartbeat arrived; None before the first."""
        with self._lock:
            return self._last_receive_s

    def status(self) -> EstopStatus:
        """Whether running is allowed now, and why (not)."""
        now_s = self._clock()
        with self._lock:
            last, last_s = self._last, self._last_receive_s
        if last is None or last_s is None:
            return EstopStatus(False, "no e-stop heartbeat received yet")
        age_s = now_s - last_s
        if age_s > self.timeout_s:
            return EstopStatus(False, f"e-stop heartbeat lost: last valid one {age_s:.3f} s ago "
                                      f"(timeout {self.timeout_s} s)")
        if last.state == EstopState.STOPPED:
            return EstopStatus(False, f"e-stop pressed (heartbeat {last.counter})")
        return EstopStatus(True, "run allowed: e-stop released, heartbeat fresh")

    def is_run_allowed(self) -> bool:
        return self.status().run_allowed

    def reason(self) -> str:
        return self.status().reason


class ForceTorqueSensors(_CanReader):
    """Latest complete F/T sample per robot; robot ``robot_names[i]`` owns sensor index i."""

    def __init__(self, robot_names: Sequence[str], bus: can.BusABC | None = None, *,
                 interface: str = "virtual", channel: str = DEFAULT_CHANNEL,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if len(set(robot_names)) != len(robot_names) or len(robot_names) > MAX_SENSORS:
            raise ValueError(f"need at most {MAX_SENSORS} distinct robot names, got "
                             f"{list(robot_names)}")
        self.robot_names = tuple(robot_names)
        self.samples_incomplete = 0  # a half replaced before its partner arrived
        self._pending: dict[tuple[int, bool], WrenchHalf] = {}
        self._readings: dict[str, WrenchReading] = {}
        super().__init__(bus, interface, channel, clock)

    def _handle(self, message: can.Message, now_s: float) -> bool:
        if not is_force_torque_id(message.arbitration_id):
            return False
        half = decode_wrench_half(message)
        if half.sensor_index >= len(self.robot_names):
            raise CanFrameError(f"F/T frame: sensor {half.sensor_index} has no robot, "
                                f"robots are {list(self.robot_names)}", "sensor")
        key, other_key = (half.sensor_index, half.is_force), (half.sensor_index, not half.is_force)
        other = self._pending.get(other_key)
        if other is None or other.sample_counter != half.sample_counter:
            if key in self._pending:
                self.samples_incomplete += 1
            self._pending[key] = half
            return True
        del self._pending[other_key]
        if self._pending.pop(key, None) is not None:  # an older half that never met its partner
            self.samples_incomplete += 1
        force, torque = (half, other) if half.is_force else (other, half)
        self._readings[self.robot_names[half.sensor_index]] = WrenchReading(
            force.values, torque.values, half.sample_counter,
            force.saturated or torque.saturated, now_s)
        return True

    def reading(self, name: str) -> WrenchReading | None:
        """Robot ``name``'s latest complete sample, or None before the first."""
        if name not in self.robot_names:
            raise KeyError(f"no F/T sensor for {name!r}; robots are {list(self.robot_names)}")
        with self._lock:
            return self._readings.get(name)

    def latest(self) -> dict[str, WrenchReading]:
        with self._lock:
            return dict(self._readings)

    def age_s(self, name: str) -> float:
        """Seconds since robot ``name``'s latest sample completed; infinite before the first."""
        reading = self.reading(name)
        return math.inf if reading is None else self._clock() - reading.receive_time_s
