"""Real-time pacing and period statistics of the deploy loops.

``Pacer`` sleeps until the next tick of a fixed-period schedule on an injected monotonic clock
[s]; a tick that starts more than one period late re-anchors the schedule (no burst of
catch-up ticks) and counts as an overrun. ``PeriodStats`` keeps the start times of a loop's
ticks and reports the achieved rate, the period and the period jitter |period - nominal| as
p50 / p99 [ms].
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np


class Pacer:
    """Fixed-period schedule: ``wait()`` returns at the next tick."""

    def __init__(self, period_s: float, clock: Callable[[], float] = time.monotonic,
                 sleep: Callable[[float], None] = time.sleep) -> None:
        self.period_s = period_s
        self.clock = clock
        self.sleep = sleep
        self.next_s = clock() + period_s
        self.overruns = 0

    def wait(self) -> None:
        left_s = self.next_s - self.clock()
        if left_s > 0.0:
            self.sleep(left_s)
            self.next_s += self.period_s
        elif left_s < -self.period_s:  # more than a period late: start again from now
            self.overruns += 1
            self.next_s = self.clock() + self.period_s
        else:
            self.next_s += self.period_s


class PeriodStats:
    """Tick start times [s] of one loop with nominal period ``period_s``."""

    def __init__(self, period_s: float) -> None:
        self.period_s = period_s
        self.starts_s: list[float] = []
        self.busy_s: list[float] = []  # time spent working in each tick

    def tick(self, start_s: float) -> None:
        self.starts_s.append(start_s)

    def summary(self) -> dict[str, float | int | None]:
        """Rate [Hz], period and jitter p50 / p99 [ms], and the busy time per tick [ms]."""
        periods = np.diff(np.asarray(self.starts_s))
        busy = np.asarray(self.busy_s)
        if periods.size == 0:
            return {"ticks": len(self.starts_s), "rate_hz": None}
        jitter = np.abs(periods - self.period_s)
        return {
            "ticks": len(self.starts_s),
            "nominal_hz": round(1.0 / self.period_s, 3),
            "rate_hz": float(1.0 / periods.mean()),
            "period_p50_ms": float(1e3 * np.percentile(periods, 50)),
            "period_p99_ms": float(1e3 * np.percentile(periods, 99)),
            "jitter_p50_ms": float(1e3 * np.percentile(jitter, 50)),
            "jitter_p99_ms": float(1e3 * np.percentile(jitter, 99)),
            "late_ticks": int(np.sum(periods > 1.5 * self.period_s)),
            "busy_p50_ms": float(1e3 * np.percentile(busy, 50)) if busy.size else None,
            "busy_p99_ms": float(1e3 * np.percentile(busy, 99)) if busy.size else None,
        }
