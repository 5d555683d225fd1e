"""Garbage-collector pauses of a real-time process: what start-up built is frozen out of the
collector, and every collection after it is counted and timed.

CPython's cyclic collector stops the process while it scans. Its oldest generation holds
everything start-up built (models, solvers, drivers: ~10^5 objects in the loop's process), so
one full collection there took 17 ms of wall time in a `porter deploy --backend sim` run at
time scale 1.0: eight 500 Hz periods, and with the tick around it past the watchdog's 25 ms.
``gc.freeze()`` after start-up moves those objects to a permanent generation that collections
never scan; the young objects a tick allocates are still collected (no leak), at the cost of
scanning only themselves. Used by the control loop, the NMPC process and its ADMM workers.
"""

from __future__ import annotations

import gc
import time
from collections.abc import Callable

__all__ = ["GcPauses", "freeze_startup_objects"]


def freeze_startup_objects() -> None:
    """Collect once, then exempt every object alive now from later collections
    (``gc.freeze``): a process calls this when its start-up is over."""
    gc.collect()
    gc.freeze()


class GcPauses:
    """Counts and times this process's collections between ``start`` and ``stop``, per
    generation; ``start`` freezes the start-up objects first (``freeze_startup_objects``),
    ``stop`` returns them to the collector (a later run in the same process, e.g. a test,
    starts from the same state)."""

    def __init__(self, clock: Callable[[], float] = time.perf_counter) -> None:
        self.clock = clock
        self.pauses_s: dict[int, list[float]] = {0: [], 1: [], 2: []}
        self._started_at: float | None = None
        self._running = False

    def start(self, freeze: bool = True) -> None:
        if self._running:
            return
        if freeze:
            freeze_startup_objects()
        gc.callbacks.append(self._callback)
        self._running = True

    def stop(self) -> None:
        if not self._running:
            return
        self._running = False
        if self._callback in gc.callbacks:
            gc.callbacks.remove(self._callback)
        gc.unfreeze()

    def _callback(self, phase: str, info: dict) -> None:
        if phase == "start":
            self._started_at = self.clock()
        elif self._started_at is not None:
            generation = int(info.get("generation", 2))
            self.pauses_s.setdefault(generation, []).append(self.clock() - self._started_at)
            self._started_at = None

    def summary(self) -> dict[str, dict[str, float | int]]:
        """Per generation ("gen0", "gen1", "gen2"): collections and the longest pause [ms]
        (wall time, so a collection preempted by another process counts its wait too)."""
        return {f"gen{generation}": {
            "collections": len(pauses),
            "max_ms": round(max(pauses, default=0.0) * 1e3, 3),
        } for generation, pauses in sorted(self.pauses_s.items())}
