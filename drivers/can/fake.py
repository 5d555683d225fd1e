"""A fake CAN node: the e-stop box's heartbeat and the coupling F/T sensors, on a python-can bus.

``FakeCanNode`` sends frames laid out as in ``drivers.can.protocol``. The heartbeat goes out
every ``heartbeat_period_s`` through ``bus.send_periodic`` (python-can's cyclic task), its
counter advanced and its state set by the task's modifier callback before each frame;
``press_estop`` / ``release_estop`` change the state, ``stop_heartbeat`` silences it (a cut
cable, a dead e-stop box), ``resume`` restarts it released. ``send_heartbeat`` sends one frame
now, for deterministic tests.

F/T readings come from ``wrench_source(robot_name) -> (force [N] (3,), torque [N m] (3,))``,
e.g. ``TeamSimulation.coupling_wrench`` (world frame, torque about the coupling point);
``publish_wrenches`` sends one sample (two frames) per robot, robot ``robot_names[i]`` on
sensor index i, all with the same sample counter.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence

import can
import numpy as np

from drivers.can.protocol import (
    ESTOP_HEARTBEAT_ID,
    EstopState,
    encode_estop_heartbeat,
    encode_wrench,
)

WrenchSource = Callable[[str], tuple[np.ndarray, np.ndarray]]


class FakeCanNode:
    """E-stop heartbeat (started released, unless ``heartbeat=False``) and F/T sensors.

    Given no ``bus``, opens ``can.Bus(interface, channel)`` and shuts it down on ``close``;
    on the ``virtual`` interface a bus does not receive its own frames, so readers need their
    own bus on the same channel.
    """

    def __init__(self, bus: can.BusABC | None = None, *, interface: str = "virtual",
                 channel: str = "porter", robot_names: Sequence[str] = (),
                 wrench_source: WrenchSource | None = None, heartbeat_period_s: float = 0.02,
                 heartbeat: bool = True) -> None:
        self._owns_bus = bus is None
        self.bus = bus if bus is not None else can.Bus(interface=interface, channel=channel)
        self.robot_names = tuple(robot_names)
        self.wrench_source = wrench_source
        self.heartbeat_period_s = heartbeat_period_s
        self.state = EstopState.RUN
        self.heartbeats_sent = 0
        self._heartbeat_counter = 0
        self._sample_counter = 0
        self._lock = threading.Lock()
        self._task: can.broadcastmanager.CyclicSendTaskABC | None = None
        if heartbeat:
            self.resume()

    # --- e-stop ---------------------------------------------------------------------------
    def press_estop(self) -> None:
        """From the next heartbeat on, the state is "stopped"."""
        self.state = EstopState.STOPPED

    def release_estop(self) -> None:
        self.state = EstopState.RUN

    def stop_heartbeat(self) -> None:
        """Stop sending heartbeats (the monitor must time out)."""
        if self._task is not None:
            self._task.stop()
            self._task = None

    def resume(self) -> None:
        """Release the e-stop and (re)start the periodic heartbeat."""
        self.stop_heartbeat()
        self.release_estop()
        template = encode_estop_heartbeat(0, self.state)  # filled in by _advance
        self._task = self.bus.send_periodic(template, self.heartbeat_period_s,
                                            modifier_callback=self._advance)

    def send_heartbeat(self) -> None:
        """Send one heartbeat now with the next counter and the current state."""
        self.bus.send(self._next_heartbeat())

    def _next_heartbeat(self) -> can.Message:
        with self._lock:
            self._heartbeat_counter = (self._heartbeat_counter + 1) % 256
            self.heartbeats_sent += 1
            return encode_estop_heartbeat(self._heartbeat_counter, self.state)

    def _advance(self, message: can.Message) -> None:
        """Cyclic-task modifier: runs before each periodic frame, sets counter and state."""
        if message.arbitration_id == ESTOP_HEARTBEAT_ID:
            message.data[:] = self._next_heartbeat().data

    # --- F/T sensors ----------------------------------------------------------------------
    def publish_wrenches(self) -> int:
        """Send one F/T sample per robot from ``wrench_source``; returns the frames sent."""
        if self.wrench_source is None:
            raise ValueError("FakeCanNode has no wrench_source to publish")
        self._sample_counter = (self._sample_counter + 1) % 256
        frames = 0
        for index, name in enumerate(self.robot_names):
            force_n, torque_nm = self.wrench_source(name)
            for message in encode_wrench(index, force_n, torque_nm, self._sample_counter):
                self.bus.send(message)
                frames += 1
        return frames

    def close(self) -> None:
        self.stop_heartbeat()
        if self._owns_bus:
            self.bus.shutdown()

    def __enter__(self) -> FakeCanNode:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()
