"""A watchdog outside the control process: damping to every robot when the loop stops beating.

The control loop's own safe stop needs the loop: after ``kill -9``, a crash inside C code, an
OOM kill or a hung main thread, the last torque command would stay on the motors (a Go2 holds
its last command; the fakes model that by default). The watchdog is a small process of its own
(``porter-watchdog``) that opens its own links to every robot (a DDS writer per Go2, a UDP
socket per A1) before the run, then watches a heartbeat: a double in shared memory that the
loop sets to ``time.monotonic()`` every tick (no system call, no lock).

When the heartbeat is older than ``timeout_s`` (loop-clock seconds, converted with the sim
backend's time scale), or the loop's process is gone, it takes over: it marks itself tripped
(the loop, if it still runs, then safe-stops too) and sends joint damping (torque 0, kp 0,
kd ``damping_kd``) to every robot every ``period_s`` for ``damping_s``, then exits. Before
the first heartbeat it only watches the parent; ``disarm`` (the run ended cleanly) ends it
without a command.
"""

from __future__ import annotations

import contextlib
import multiprocessing as mp
import os
import signal
import time
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.sharedctypes import Synchronized
from typing import TYPE_CHECKING

from deploy.compute import realtime
from deploy.compute.process_names import name_this_process
from drivers.link_errors import DriverError
from drivers.unitree.a1_driver import A1Driver
from drivers.unitree.go2_driver import Go2Driver
from drivers.unitree.peer import UnitreeLowLevelDriver

if TYPE_CHECKING:  # deploy.config.deploy_config holds WatchdogSettings in its DeployConfig
    from deploy.config.deploy_config import DeployConfig

__all__ = ["Watchdog", "WatchdogSpec"]

_WATCHING, _DISARMED, _TRIPPED = 0, 1, 2


@dataclass(frozen=True)
class WatchdogSpec:
    """What the watchdog process needs: the links (already the sim's, under ``--backend
    sim``), the damping gain, and its times in wall-clock seconds."""

    config: DeployConfig
    damping_kd: float
    timeout_wall_s: float
    period_wall_s: float
    damping_wall_s: float
    priority: int | None = None  # SCHED_FIFO priority of its watch (None: normal scheduling)

    @classmethod
    def of(cls, config: DeployConfig, time_scale: float = 1.0,
           priority: int | None = None) -> WatchdogSpec:
        settings = config.watchdog
        return cls(config, config.safety.damping_kd, settings.timeout_s / time_scale,
                   settings.period_s / time_scale, settings.damping_s / time_scale, priority)


def _open_drivers(config: DeployConfig) -> list[UnitreeLowLevelDriver]:
    from deploy.config.deploy_config import Go2Link

    drivers: list[UnitreeLowLevelDriver] = []
    for name, link in config.robots.items():
        if isinstance(link, Go2Link):
            drivers.append(Go2Driver(f"watchdog {name}", link.domain_id,
                                     config.network_interface, link.topic_prefix))
        else:
            drivers.append(A1Driver(f"watchdog {name}", link.robot_address, link.local_address,
                                    0))
    return drivers


def _watch(spec: WatchdogSpec, heartbeat: Synchronized, state: Synchronized,
           parent_pid: int, ready: Connection) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the loop's to handle
    name_this_process("porter-watchdog")
    try:
        drivers = _open_drivers(spec.config)
    except DriverError as error:
        ready.send(f"error: {error}")
        return
    try:  # after the links: DDS's own threads stay at normal scheduling
        realtime.set_priority(spec.priority)
    except realtime.RealtimePriorityError as error:
        for driver in drivers:
            driver.close()
        ready.send(f"error: {error}")
        return
    ready.send("ready")
    try:
        while state.value == _WATCHING:
            time.sleep(spec.period_wall_s)
            beat = heartbeat.value
            parent_gone = os.getppid() != parent_pid
            if parent_gone or (beat > 0.0 and time.monotonic() - beat > spec.timeout_wall_s):
                state.value = _TRIPPED
        if state.value == _TRIPPED:
            end = time.monotonic() + spec.damping_wall_s
            while time.monotonic() < end and state.value == _TRIPPED:
                for driver in drivers:
                    with contextlib.suppress(DriverError, OSError):
                        driver.send_damping(spec.damping_kd)
                time.sleep(spec.period_wall_s)
    finally:
        for driver in drivers:
            with contextlib.suppress(Exception):
                driver.close()


class Watchdog:
    """The loop's side: ``beat`` every tick, ``tripped`` to learn it took over, ``disarm``
    at a clean end. Construction starts the process and waits until its links are open."""

    def __init__(self, spec: WatchdogSpec, start_timeout_s: float = 30.0) -> None:
        context = mp.get_context("spawn")
        self._heartbeat = context.Value("d", 0.0, lock=False)
        self._state = context.Value("i", _WATCHING, lock=False)
        receive, send = context.Pipe(duplex=False)
        self._process = context.Process(
            target=_watch, args=(spec, self._heartbeat, self._state, os.getpid(), send),
            name="porter-watchdog", daemon=True)
        self._process.start()
        send.close()
        answer = receive.recv() if receive.poll(start_timeout_s) else "no answer"
        receive.close()
        if answer != "ready":
            self._process.kill()
            raise DriverError(f"watchdog did not start: {answer}")

    def beat(self) -> None:
        """The loop is alive (call once per tick)."""
        self._heartbeat.value = time.monotonic()

    @property
    def tripped(self) -> bool:
        """The watchdog took over (the loop was late by more than its timeout)."""
        return bool(self._state.value == _TRIPPED)

    @property
    def alive(self) -> bool:
        return self._process.is_alive()

    @property
    def pid(self) -> int | None:
        """The watchdog process's id (its watch runs on its main thread)."""
        return self._process.pid

    def disarm(self, timeout_s: float = 5.0) -> None:
        """The run ended cleanly: stop watching (no command is sent). After a trip, the
        damping stops too. Calling it again does nothing."""
        if not self._process.is_alive() and self._state.value == _DISARMED:
            return
        self._state.value = _DISARMED
        self._process.join(timeout_s)
        if self._process.is_alive():
            self._process.kill()
