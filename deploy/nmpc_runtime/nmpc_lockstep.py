"""The NMPC in simulated time: the same interface as ``deploy.nmpc_runtime.nmpc_thread.NmpcThread``
(``busy``, ``submit``, ``take``, ``close``) for the lockstep clock.

``submit`` runs ``TeamController.update`` at once (simulated time stands still meanwhile); the
result is handed over by ``take`` once the loop's clock has reached the submit time plus the
modelled computation time: none by default (the plan takes effect on the tick it was decided),
the update's measured wall time with ``model_delay``, or ``fixed_delay_s`` when set
(deterministic). The first plan of a run is handed over at once (there is no plan to keep
tracking meanwhile). While a result waits, ``busy`` is True: one NMPC at a time, as on robots.

With a fixed delay the update may instead run in the NMPC's own process (``process``,
``controller.overlap_computation``): ``submit`` only sends the inputs and the world steps on
while the process computes; ``take`` at the hand-over instant waits for the answer. The plan,
its hand-over tick and the warm start are those of the synchronous run, so the trajectory is
the same; only the wall time shrinks (the loop and the NMPC each use a core).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from deploy.nmpc_runtime.nmpc_process import NmpcProcess
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.runtime.controller import NmpcDecision, TeamController

__all__ = ["LockstepNmpc"]

PROCESS_ANSWER_TIMEOUT_S = 120.0  # wall time; an update takes milliseconds
# Simulated time is a sum of physics steps: 0.018 + 0.012 can exceed the clock's 0.030 by
# rounding, which handed half the plans of a 12 ms delay over a tick late (measured). Far
# below a physics step, far above the rounding.
HANDOVER_TOLERANCE_S = 1e-9


class LockstepNmpc:
    """Synchronous NMPC updates whose results wait out a modelled computation time."""

    def __init__(self, control: TeamController, clock: Callable[[], float],
                 model_delay: bool = False, fixed_delay_s: float | None = None,
                 process: NmpcProcess | None = None) -> None:
        if process is not None and (not model_delay or fixed_delay_s is None):
            raise ValueError("an overlapping NMPC process needs a fixed modelled delay "
                             "(model_delay and fixed_delay_s)")
        self.control, self.clock = control, clock
        self.model_delay, self.fixed_delay_s = model_delay, fixed_delay_s
        self.process = process
        # (ready at [s], modelled time [s], result: None while the process computes it)
        self._waiting: tuple[float, float, NmpcResult | None] | None = None
        self._first = True

    @property
    def busy(self) -> bool:
        return self._waiting is not None

    def submit(self, decision: NmpcDecision, update: int) -> None:
        if self._waiting is not None:
            raise RuntimeError("NMPC update submitted while one is running")
        if self.process is not None:
            took_s = 0.0 if self._first else float(self.fixed_delay_s or 0.0)
            self._first = False
            self.process.submit(decision, update)
            self._waiting = (self.clock() + took_s, took_s, None)
            return
        plan, error = None, ""
        memory = self.control.controller.memory()  # replaced, never mutated, by update
        try:
            plan = self.control.update(decision)
        except Exception as exception:  # the loop's safety decides what a failure means
            error = f"{type(exception).__name__}: {exception}"
        took_s = 0.0
        if self.model_delay and not self._first:
            took_s = (self.fixed_delay_s if self.fixed_delay_s is not None
                      else plan.update_time_s if plan is not None else 0.0)
        self._first = False
        result = NmpcResult(decision, update, plan, took_s, error, memory)
        self._waiting = (self.clock() + took_s, took_s, result)

    def take(self) -> NmpcResult | None:
        """The waiting result once its computation time has passed on the clock."""
        if self._waiting is None or self.clock() < self._waiting[0] - HANDOVER_TOLERANCE_S:
            return None
        _, took_s, result = self._waiting
        if result is None:  # the process's answer, on the modelled (not the wall) time
            assert self.process is not None
            result = dataclasses.replace(self.process.wait(PROCESS_ANSWER_TIMEOUT_S),
                                         wall_s=took_s)
        self._waiting = None
        return result

    def close(self) -> None:
        self._waiting = None
        if self.process is not None:
            self.process.close()
