"""Test doubles for the runtime's components: a team controller without NLPs, a clock."""

from __future__ import annotations

import threading
from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from core.model.obstacles import Obstacle
from deploy.runtime.controller import NmpcDecision
from drivers.interfaces import MocapFrame, RobotMeasurement

NAMES = ["r0", "r1"]


def plan(success: bool = True, inside_margin: bool = False, relaxed: bool = False
         ) -> SimpleNamespace:
    """What the schedule reads of an ``MpcPlan``."""
    return SimpleNamespace(success=success, start_inside_margin=inside_margin, relaxed=relaxed,
                           barrier_slack_m=0.05 if relaxed else 0.0,
                           wrench=np.zeros((len(NAMES), 6)), update_time_s=0.01)


def frame(t: float) -> MocapFrame:
    return MocapFrame(t, {name: (np.zeros(3), np.array([1.0, 0, 0, 0])) for name in NAMES})


def measurements() -> dict[str, RobotMeasurement]:
    return dict.fromkeys(NAMES, None)  # type: ignore[arg-type]  # the fake reads none


@dataclass
class FakeControl:
    """``TeamController``'s NMPC side: decisions stamped with their time, plans on demand."""

    robot_names: list[str] = field(default_factory=lambda: list(NAMES))
    obstacles: list[Obstacle] = field(default_factory=list)
    start_s: float = 0.0
    plans: list[object] = field(default_factory=list)  # what update returns, in turn
    decided: list[tuple[float, float]] = field(default_factory=list)  # (t, delay_s)
    raises: bool = False
    taken: list[tuple[float, object]] = field(default_factory=list)  # plan_taken calls
    gate: threading.Event | None = None  # set: update may go on (a solve held on purpose)

    @property
    def controller(self) -> SimpleNamespace:
        return SimpleNamespace(memory=lambda: None)

    def nmpc_inputs(self, t: float, measurements: list, frame: MocapFrame,
                    obstacles: list | None = None, delay_s: float = 0.0,
                    active: object = None) -> NmpcDecision:
        self.decided.append((t, delay_s))
        return NmpcDecision(t + delay_s, None, frame, np.zeros(12))  # type: ignore[arg-type]

    def compensation_s(self, recent_delays_s: list[float]) -> float:
        recent = recent_delays_s[-10:]
        return float(np.median(recent)) if recent else 0.0

    def plan_taken(self, t: float, plan: object) -> str | None:
        """Starts braking on a relaxed plan (the real rule counts them: ``TeamController``)."""
        self.taken.append((t, plan))
        return "braking: test" if getattr(plan, "relaxed", False) else None

    def update(self, decision: NmpcDecision) -> object:
        if self.gate is not None:
            self.gate.wait(10.0)
        if self.raises:
            raise RuntimeError("solver exploded")
        return self.plans.pop(0) if self.plans else plan()


class FakeClock:
    """A clock that moves only when told to [s]."""

    def __init__(self, t: float = 0.0) -> None:
        self.t = t

    def __call__(self) -> float:
        return self.t

    def sleep(self, seconds: float) -> None:
        self.t += seconds
