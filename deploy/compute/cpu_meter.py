"""CPU time of porter's processes by role, and per simulated second while RUNNING.

``cpu_seconds`` reads user + system time of this process (the loop, recorder, MoCap and CAN
threads, and the NMPC thread with ``nmpc.runner: thread``) and of every live descendant: a
child by the name multiprocessing gave it (``porter-sim-world``, ``porter-nmpc``,
``porter-admm-agent<i>``), a grandchild by its system name (``porter-admm<i>``, the ADMM
workers of the NMPC process, ``deploy.compute.process_names``). ``RunningCpu`` is a loop hook taking a
reading on the first tick of RUNNING and on the first tick after it, so the figures exclude
start-up (imports, scene building, stand-up) and sit-down.
"""

from __future__ import annotations

import contextlib
import multiprocessing
from collections.abc import Callable

import psutil

from deploy.runtime.controller import WbcStep
from deploy.safety.supervisor import SafetyState

__all__ = ["RunningCpu", "cpu_seconds"]


def cpu_seconds() -> dict[str, float]:
    """CPU seconds (user + system) by process role."""
    this = psutil.Process()
    roles = {process.pid: process.name for process in multiprocessing.active_children()}
    result = {"porter": sum(this.cpu_times()[0:2])}
    for child in this.children(recursive=True):
        with contextlib.suppress(psutil.Error):
            name = child.name()
            role = roles.get(child.pid) or (name if name.startswith("porter")
                                            else f"{name} {child.pid}")
            result[role] = sum(child.cpu_times()[0:2])
    return result


class RunningCpu:
    """Loop hook: CPU seconds per second of the loop's clock (simulated seconds under
    ``--backend sim``) over RUNNING, by process role."""

    def __init__(self, state: Callable[[], SafetyState]) -> None:
        self.state = state
        self.start: tuple[float, dict[str, float]] | None = None
        self.end: tuple[float, dict[str, float]] | None = None

    def before_tick(self, t: float) -> None:
        running = self.state() == SafetyState.RUNNING
        if running and self.start is None:
            self.start = (t, cpu_seconds())
        elif not running and self.start is not None and self.end is None:
            self.end = (t, cpu_seconds())

    def wbc_stepped(self, steps: list[WbcStep]) -> None:
        """Nothing to measure per WBC step."""

    def per_second(self) -> dict[str, float]:
        """CPU-s per loop-clock second over RUNNING for every role seen at both readings."""
        if self.start is None or self.end is None or self.end[0] <= self.start[0]:
            return {}
        (t0, first), (t1, last) = self.start, self.end
        return {role: (last[role] - first[role]) / (t1 - t0) for role in last if role in first}
