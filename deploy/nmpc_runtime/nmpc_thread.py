"""The NMPC off the 500 Hz loop: one background thread runs ``TeamController.update`` on the
decision the loop submits, so the WBC never waits for a plan; it tracks the newest finished one.

The loop builds the decision (inputs from its measurements, cheap) when the thread is idle and
an NMPC instant is due, ``submit``s it, and picks the result up with ``take`` on a later tick.
The controller's memory (warm start) is touched only by the thread while an update runs and by
the loop only while it is idle (``busy`` False), so no lock is needed around it. The ADMM
local solves themselves run in the ``ProcessExecutor``'s worker processes.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.warm_start import ControllerMemory
from deploy.runtime.controller import NmpcDecision, TeamController


@dataclass(frozen=True)
class NmpcResult:
    """A finished update: its decision, number, plan, time [s on the runner's clock] from
    submit to done, and the warm start it started from (for the log's keyframes)."""

    decision: NmpcDecision
    update: int
    plan: MpcPlan | None  # None: the update raised (``error`` says what)
    wall_s: float
    error: str = ""
    memory: ControllerMemory | None = None


class NmpcThread:
    """Runs ``control.update`` in a daemon thread, one decision at a time."""

    def __init__(self, control: TeamController,
                 clock: Callable[[], float] = time.perf_counter) -> None:
        self.control = control
        self.clock = clock
        self._condition = threading.Condition()
        self._pending: tuple[NmpcDecision, int, float] | None = None
        self._result: NmpcResult | None = None
        self._busy = False
        self._closed = False
        self._thread = threading.Thread(target=self._run, name="porter-nmpc", daemon=True)
        self._thread.start()

    @property
    def busy(self) -> bool:
        """An update is submitted or running (its result not yet taken counts as idle)."""
        return self._busy

    def submit(self, decision: NmpcDecision, update: int) -> None:
        with self._condition:
            if self._busy:
                raise RuntimeError("NMPC update submitted while one is running")
            self._busy = True
            self._pending = (decision, update, self.clock())
            self._condition.notify()

    def take(self) -> NmpcResult | None:
        """The result finished since the last ``take``, if any."""
        with self._condition:
            result, self._result = self._result, None
            return result

    def _run(self) -> None:
        while True:
            with self._condition:
                self._condition.wait_for(lambda: self._pending is not None or self._closed)
                if self._closed:
                    return
                assert self._pending is not None
                decision, update, start = self._pending
                self._pending = None
            plan, error = None, ""
            memory = self.control.controller.memory()  # replaced, never mutated, by update
            try:
                plan = self.control.update(decision)
            except Exception as exception:  # the loop's safety decides what a failure means
                error = f"{type(exception).__name__}: {exception}"
            with self._condition:
                self._result = NmpcResult(decision, update, plan, self.clock() - start,
                                          error, memory)
                self._busy = False

    def close(self, timeout_s: float = 10.0) -> None:
        """Stop the thread after the running update (if any) finishes."""
        with self._condition:
            self._closed = True
            self._condition.notify()
        self._thread.join(timeout_s)
