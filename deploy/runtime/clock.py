"""The loop's time: its two clocks, the pacing of real time, and what each tick took.

``LoopClock``: ``now()`` [s] on the loop's time base and ``wait()`` until the next tick. The
paced clock (``PacedClock``: the wall clock, or the simulated world's scaled clock) sleeps on a
``Pacer``; the lockstep clock (``LockstepClock``) steps the in-process MuJoCo simulation by one
tick's physics steps, then calls ``after_step`` (ground truth), so a run is deterministic
whatever the machine's speed.

``Pacer`` sleeps until the next tick of a fixed-period schedule on an injected monotonic clock
[s]; a tick that starts more than one period late re-anchors the schedule (no burst of
catch-up ticks) and counts as an overrun. ``PeriodStats`` keeps the start times of a loop's
ticks and reports the achieved rate, the period and the period jitter |period - nominal| as
p50 / p99 [ms]. ``TickStages`` splits each tick's work into named stages on the wall clock
(``time.perf_counter``, whatever the loop's clock) and reports median and p99 per stage.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

import numpy as np

if TYPE_CHECKING:  # the robot path never imports MuJoCo
    from drivers.mujoco.simulation import TeamSimulation

__all__ = ["LockstepClock", "LoopClock", "PacedClock", "Pacer", "PeriodStats", "TickStages"]


class LoopClock(Protocol):
    @property
    def overruns(self) -> int: ...
    @property
    def paced(self) -> bool: ...
    def start(self) -> None: ...
    def now(self) -> float: ...
    def wait(self) -> None: ...


class PacedClock:
    """Real time on ``clock`` (monotonic, or the sim backend's scaled clock), ``period_s``
    ticks; a tick more than a period late re-anchors the schedule (an overrun)."""

    paced = True

    def __init__(self, period_s: float, clock: Callable[[], float] = time.monotonic,
                 sleep: Callable[[float], None] = time.sleep) -> None:
        self.clock, self.sleep, self.period_s = clock, sleep, period_s
        self.pacer = Pacer(period_s, clock, sleep)

    def start(self) -> None:
        """The first tick's period starts now."""
        self.pacer = Pacer(self.period_s, self.clock, self.sleep)

    @property
    def overruns(self) -> int:
        return self.pacer.overruns

    def now(self) -> float:
        return self.clock()

    def wait(self) -> None:
        self.pacer.wait()


class LockstepClock:
    """Simulated time: ``wait`` steps ``simulation`` by ``steps_per_tick`` physics steps."""

    paced = False
    overruns = 0

    def __init__(self, simulation: TeamSimulation, steps_per_tick: int,
                 after_step: Callable[[float], None] | None = None) -> None:
        self.simulation = simulation
        self.steps_per_tick = steps_per_tick
        self.after_step = after_step

    def start(self) -> None:
        """Simulated time needs no anchor."""

    def now(self) -> float:
        return self.simulation.time_s

    def wait(self) -> None:
        self.simulation.step(self.steps_per_tick)
        if self.after_step is not None:
            self.after_step(self.simulation.time_s)


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


class TickStages:
    """Wall time of each stage of the loop's ticks: ``start()`` at the top of a tick,
    ``mark(stage)`` at the end of each stage (the time since the previous mark counts for it),
    ``finish()`` at the end of a tick (kept only while ``recording``)."""

    def __init__(self, clock: Callable[[], float] = time.perf_counter) -> None:
        self.clock = clock
        self.recording = False
        self.samples_s: dict[str, list[float]] = {}
        self.totals_s: list[float] = []
        self._tick: dict[str, float] = {}
        self._start_s = self._last_s = 0.0

    def start(self) -> None:
        self._tick = {}
        self._start_s = self._last_s = self.clock()

    def mark(self, stage: str) -> None:
        now = self.clock()
        self._tick[stage] = self._tick.get(stage, 0.0) + now - self._last_s
        self._last_s = now

    def finish(self) -> None:
        if not self.recording:
            return
        for stage, seconds in self._tick.items():
            self.samples_s.setdefault(stage, []).append(seconds)
        self.totals_s.append(self._last_s - self._start_s)

    def summary(self) -> dict[str, dict[str, float] | int]:
        """Per stage and for the whole tick: p50 / p99 / mean [ms] over the recorded ticks."""
        def stats(values: list[float]) -> dict[str, float]:
            v = 1e3 * np.asarray(values)
            return {"p50_ms": float(np.percentile(v, 50)), "p99_ms": float(np.percentile(v, 99)),
                    "mean_ms": float(v.mean())}
        result: dict[str, dict[str, float] | int] = {"ticks": len(self.totals_s)}
        if self.totals_s:
            result.update({stage: stats(values) for stage, values in self.samples_s.items()})
            result["total"] = stats(self.totals_s)
        return result
