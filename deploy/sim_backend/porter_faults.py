"""Faults porter injects into its own process on the sim backend (drills and tests): the
``sim.faults`` kinds in ``deploy.config.deploy_config.PORTER_FAULTS``, due ``at_s`` after the
world's start (``SimBackend.start_s``), the instant the world's own faults count from: porter's
start-up after it (links, recorder) takes 0.1-0.3 simulated s, which would otherwise delay
porter's faults against the world's ground truth by as much.

``nmpc_failure``: from then on every NMPC plan is a failed solve (a solver that stops
converging); ``recorder_failure``: every flight-log write fails with ENOSPC (a full disk);
``loop_stall``: the loop's thread hangs ``STALL_S`` of wall time once (a blocking call, a
swapped-out page, a debugger), which the watchdog must catch; ``plan_late``: the first NMPC
plan ready from then on is handed to the loop ``duration_s`` later (on the loop's clock), once
(a solve that ran long, a descheduled NMPC process).
"""

from __future__ import annotations

import errno
import os
import time
from collections.abc import Callable
from typing import Any

from deploy.config.sim_faults import PORTER_FAULTS, SimFault
from deploy.nmpc_runtime.nmpc_schedule import NmpcRunner
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.recording.flight_recorder import FlightRecorder
from deploy.runtime.controller import NmpcDecision

__all__ = ["STALL_S", "PorterFaults"]

STALL_S = 0.3  # wall seconds of a loop stall


class PorterFaults:
    """The porter-side faults of ``faults`` on ``clock``, due ``at_s`` after ``start_s`` (on
    ``clock``; its first look if None); wraps what they act on."""

    def __init__(self, faults: list[SimFault], clock: Callable[[], float],
                 start_s: float | None = None) -> None:
        self.clock = clock
        self.start_s = clock() if start_s is None else start_s
        self.due_s: dict[str, float] = {fault.kind: fault.at_s for fault in faults
                                         if fault.kind in PORTER_FAULTS}
        self.late_by_s = next((fault.duration_s or 0.0 for fault in faults
                               if fault.kind == "plan_late"), 0.0)
        self._stalled = False

    def active(self, kind: str) -> bool:
        due = self.due_s.get(kind)
        return due is not None and self.clock() - self.start_s >= due

    def runner(self, runner: NmpcRunner) -> NmpcRunner:
        if "plan_late" in self.due_s:
            runner = _LateRunner(runner, self)
        return _FailingRunner(runner, self) if "nmpc_failure" in self.due_s else runner

    def recorder(self, recorder: FlightRecorder | None) -> None:
        """From ``recorder_failure`` on, the writer's every write raises ENOSPC."""
        if recorder is None or "recorder_failure" not in self.due_s:
            return
        write = recorder._write

        def failing_write(*args: Any) -> None:
            if self.active("recorder_failure"):
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
            write(*args)

        recorder._write = failing_write  # type: ignore[method-assign,assignment]

    def sleep(self, sleep: Callable[[float], None]) -> Callable[[float], None]:
        """The loop's sleep, which hangs ``STALL_S`` once from ``loop_stall`` on."""
        if "loop_stall" not in self.due_s:
            return sleep

        def stalling_sleep(seconds: float) -> None:
            if not self._stalled and self.active("loop_stall"):
                self._stalled = True
                time.sleep(STALL_S)
            sleep(seconds)

        return stalling_sleep


class _FailingRunner:
    """An NMPC runner whose plans, from ``nmpc_failure`` on, come back as failed solves."""

    def __init__(self, runner: NmpcRunner, faults: PorterFaults) -> None:
        self._runner, self._faults = runner, faults

    @property
    def busy(self) -> bool:
        return self._runner.busy

    def submit(self, decision: NmpcDecision, update: int) -> None:
        self._runner.submit(decision, update)

    def take(self) -> NmpcResult | None:
        result = self._runner.take()
        if result is not None and result.plan is not None and self._faults.active("nmpc_failure"):
            result.plan.success = False
        return result

    def close(self) -> None:
        self._runner.close()

    def __getattr__(self, name: str) -> Any:  # e.g. NmpcProcess.clock
        return getattr(self._runner, name)


class _LateRunner(_FailingRunner):
    """An NMPC runner that, from ``plan_late`` on, holds the first plan ready back
    ``late_by_s`` on the loop's clock before handing it over (busy meanwhile), once."""

    def __init__(self, runner: NmpcRunner, faults: PorterFaults) -> None:
        super().__init__(runner, faults)
        self._held: NmpcResult | None = None
        self._release_s: float | None = None
        self._done = False

    @property
    def busy(self) -> bool:
        return self._held is not None or self._runner.busy

    def take(self) -> NmpcResult | None:
        faults = self._faults
        if self._held is not None:
            assert self._release_s is not None
            if faults.clock() < self._release_s:
                return None
            held, self._held = self._held, None
            return held
        result = self._runner.take()
        if result is not None and not self._done and faults.active("plan_late"):
            self._done, self._held = True, result
            self._release_s = faults.clock() + faults.late_by_s
            return None
        return result
