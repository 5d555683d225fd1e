"""The loop's two clocks: paced (the wall clock, or the simulated world's scaled clock) and
lockstep (simulated time that advances only when the loop steps the world).

Both give ``now()`` [s] on the loop's time base and ``wait()`` until the next tick. The paced
clock sleeps on a ``Pacer`` (``deploy.runtime.timing``); the lockstep clock steps the in-process
MuJoCo simulation by one tick's physics steps, then calls ``after_step`` (ground truth), so a
run is deterministic whatever the machine's speed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

from deploy.runtime.timing import Pacer

if TYPE_CHECKING:  # the robot path never imports MuJoCo
    from drivers.mujoco.simulation import TeamSimulation

__all__ = ["LockstepClock", "LoopClock", "PacedClock"]


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
