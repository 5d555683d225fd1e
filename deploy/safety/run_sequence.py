"""The run's sequence: which state the team is in, what moves it on, and where its commands
come from. The control loop (``deploy.runtime.loop``) reads, estimates, asks and sends; this
object alone decides the planned transitions, and with the supervisor the safe stops.

Each tick the loop fills one ``RunEvents`` record and passes it at three points of the tick:
``at_tick_start`` (after reading and estimating), ``before_commands`` (after the NMPC step and
the supervisor's check) and ``at_tick_end`` (after sending and recording). The point decides
which commands a transition affects: the same tick's (start, before commands) or the next's
(end). ``source`` says where the commands of the current state come from.

Transitions, in the order they are tested each tick (``kind`` "deploy" or "standing", the
simulation whose team starts standing; "active": STANDING_UP, ARMED, RUNNING, SITTING_DOWN):

=====  ===================  ============  ========================================  ============
row    point                from          when                                      to
=====  ===================  ============  ========================================  ============
1      tick start           active        the watchdog took over                    SAFE_STOP
2      tick start           PREFLIGHT     kind standing                             RUNNING [a]
3      tick start           RUNNING       kind standing; stop, or duration_s run    DONE [b]
4      before commands      active        the NMPC process was lost                 SAFE_STOP
5      before commands      RUNNING       the plan is older than max_plan_age_s     SAFE_STOP
6      tick end             active        a command could not be sent               SAFE_STOP
7      tick end             active        the NMPC process was lost after sending   SAFE_STOP
8      tick end             active        the recorder failed, on_failure safe_stop SAFE_STOP
9      tick end             RUNNING       braking for controlled_stop_s             SITTING_DOWN
10     tick end             PREFLIGHT     stop requested                            DONE
11     tick end             PREFLIGHT     the pre-flight checks pass                STANDING_UP
12     tick end             PREFLIGHT     preflight_timeout_s passed                DONE
13     tick end             STANDING_UP   stop requested                            SITTING_DOWN
14     tick end             STANDING_UP   stood and settled; the operator arms      ARMED [a]
15     tick end             STANDING_UP   stood and settled; the operator declines  SITTING_DOWN
16     tick end             ARMED         stop requested                            SITTING_DOWN
17     tick end             ARMED         a plan is ready                           RUNNING
18     tick end             ARMED         no plan max_armed_s after arming          SAFE_STOP
19     tick end             RUNNING       kind deploy; stop, or duration_s run      SITTING_DOWN
20     tick end             SITTING_DOWN  sit_down_s passed                         DONE
21     tick end             SAFE_STOP     final_damping_s passed                    DONE
22     tick end             DONE          final_damping_s passed                    (over)
=====  ===================  ============  ========================================  ============

[a] the plans start (the loop resets the controller and starts the NMPC schedule).
[b] the pending plans are flushed and the run is over at once.
Any fault the supervisor finds (``SafetySupervisor.check``, ``filter_commands``, a WBC's
failures) moves an active state to SAFE_STOP as well. Commands by state: PREFLIGHT ``limp``,
STANDING_UP / ARMED / SITTING_DOWN ``posture`` (``moves``), RUNNING ``plan`` (the WBC), SAFE_STOP
and DONE ``damping``. Braking is the controller's state (``TeamController.braking``): this
object only turns its age into the controlled stop.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from deploy.config.deploy_config import PostureConfig
from deploy.safety.posture import PostureMove
from deploy.safety.preflight import PreflightReport
from deploy.safety.supervisor import SafetyState, SafetySupervisor
from drivers.interfaces import MocapFrame, RobotMeasurement

__all__ = ["Braking", "RunEvents", "RunSequence", "SequenceSettings", "Source"]

S = SafetyState
Source = Literal["limp", "posture", "plan", "damping"]
SOURCES: dict[SafetyState, Source] = {
    S.PREFLIGHT: "limp", S.STANDING_UP: "posture", S.ARMED: "posture", S.RUNNING: "plan",
    S.SITTING_DOWN: "posture", S.SAFE_STOP: "damping", S.DONE: "damping"}
Confirm = Callable[[], bool | None]  # None while the operator has not answered
Preflight = Callable[[dict[str, RobotMeasurement], dict[str, str]], PreflightReport]


@dataclass(frozen=True)
class Braking:
    """The braking backup took over at ``since_s`` [s, loop time] for ``cause``."""

    since_s: float
    cause: str


@dataclass(frozen=True)
class SequenceSettings:
    """How long each state may or must last [s, loop time]."""

    kind: Literal["deploy", "standing"]
    duration_s: float  # of RUNNING
    posture: PostureConfig
    preflight_timeout_s: float
    max_armed_s: float
    max_plan_age_s: float
    controlled_stop_s: float  # braking this long ends the run with a sit-down
    recorder_failure_stops: bool = True  # a failed recorder is a safe stop, else a warning


@dataclass
class RunEvents:
    """What the loop saw in one tick; filled as the tick goes."""

    time_s: float
    measurements: dict[str, RobotMeasurement] = field(default_factory=dict)
    link_errors: dict[str, str] = field(default_factory=dict)
    frame: MocapFrame | None = None
    watchdog_tripped: bool = False
    nmpc_lost: str | None = None
    plan_ready: bool = False
    plan_start_s: float = 0.0  # when the plan in force took effect
    braking: Braking | None = None
    send_failed: str | None = None
    recorder_failed: str | None = None


class RunSequence:
    """One run's states over ``supervisor``; ``stop``, ``confirm`` and ``preflight`` are asked
    only when a row needs them (the operator is asked once the team stood and settled);
    ``say`` prints what the operator should read (the braking cause, a failed recorder)."""

    def __init__(self, supervisor: SafetySupervisor, settings: SequenceSettings,
                 standing: dict[str, np.ndarray], sitting: dict[str, np.ndarray],
                 stop: Callable[[], bool], confirm: Confirm | None = None,
                 preflight: Preflight | None = None,
                 say: Callable[[str], None] = lambda text: None) -> None:
        self.supervisor, self.settings = supervisor, settings
        self.standing, self.sitting = standing, sitting
        self.stop, self.confirm, self.preflight, self.say = stop, confirm, preflight, say
        self.since: dict[SafetyState, float] = {S.PREFLIGHT: 0.0}
        self.moves: dict[str, PostureMove] = {}
        self.report: PreflightReport | None = None
        self.frames: dict[str, MocapFrame] = {}  # at the start and the end of RUNNING
        self.ended_by, self.stopped_early = "", False
        self.controlled_stop = False  # the braking backup ended the run with a sit-down
        self._braking_said = False

    @property
    def state(self) -> SafetyState:
        return self.supervisor.state

    @property
    def source(self) -> Source:
        return SOURCES[self.supervisor.state]

    @property
    def planning(self) -> bool:
        """Whether the NMPC schedule runs in this state (ARMED and RUNNING)."""
        return self.supervisor.state in (S.ARMED, S.RUNNING)

    def entered(self, state: SafetyState, time_s: float) -> None:
        """The supervisor moved to ``state`` at ``time_s`` (its transition callback)."""
        self.since[state] = time_s

    def abort(self, time_s: float, cause: str) -> None:
        """A safe stop for an error the loop cannot go on from (an exception)."""
        self.supervisor.trigger_safe_stop(time_s, cause)

    # --- the three points of a tick ----------------------------------------------------------
    def at_tick_start(self, events: RunEvents) -> tuple[bool, bool]:
        """Rows 1-3: (plans start now, the run is over now)."""
        t, supervisor = events.time_s, self.supervisor
        if events.watchdog_tripped:  # it saw this loop late: it is sending damping already
            supervisor.trigger_safe_stop(t, "watchdog took over: the loop's heartbeat was late")
        if self.settings.kind != "standing":
            return False, False
        if supervisor.state == S.PREFLIGHT:
            supervisor.start_standing(t)
            return True, False
        if supervisor.state == S.RUNNING:
            stop = self.stop()
            if stop or t - self.since[S.RUNNING] >= self.settings.duration_s - 1e-9:
                self.stopped_early = stop
                self.ended_by = "stop requested" if stop else f"ran {self.settings.duration_s:g} s"
                supervisor.end_standing(t)
                return False, True
        return False, False

    def before_commands(self, events: RunEvents) -> None:
        """Rows 4-5."""
        t, supervisor = events.time_s, self.supervisor
        if events.nmpc_lost is not None:  # it died: no plan will come; stop here
            supervisor.trigger_safe_stop(t, f"NMPC process lost: {events.nmpc_lost}")
        plan_age_s, max_age_s = t - events.plan_start_s, self.settings.max_plan_age_s
        if supervisor.state == S.RUNNING and plan_age_s > max_age_s:
            supervisor.trigger_safe_stop(t, f"NMPC stalled: the plan is {plan_age_s:.3f} s "
                                            f"old (max {max_age_s} s)")

    def at_tick_end(self, events: RunEvents) -> tuple[bool, bool]:
        """Rows 6-22: (plans start now, the run is over)."""
        t, supervisor = events.time_s, self.supervisor
        if events.send_failed is not None:
            supervisor.trigger_safe_stop(t, f"send failed: {events.send_failed}")
        if events.nmpc_lost is not None:
            supervisor.trigger_safe_stop(t, f"NMPC process lost: {events.nmpc_lost}")
        if events.recorder_failed is not None:
            self.say(f"[{t:7.3f} s] ERROR: flight recorder failed: {events.recorder_failed}")
            if self.settings.recorder_failure_stops:
                supervisor.trigger_safe_stop(
                    t, f"flight recorder failed: {events.recorder_failed}")
        return self._planned(events)

    # --- the planned transitions (rows 9-22) ------------------------------------------------
    def _planned(self, events: RunEvents) -> tuple[bool, bool]:
        t, supervisor, posture = events.time_s, self.supervisor, self.settings.posture
        state = supervisor.state
        elapsed = t - self.since.get(state, t)
        braking = events.braking
        if braking is not None and not self._braking_said:
            self._braking_said = True
            self.say(f"[{t:7.3f} s] {braking.cause}")
        if (state == S.RUNNING and braking is not None
                and t - braking.since_s >= self.settings.controlled_stop_s):
            self.controlled_stop = True
            self._sit_down(events, f"controlled stop: braking since {braking.since_s:.3f} s "
                                   f"({braking.cause})")
        elif state == S.PREFLIGHT:
            self.report = (self.preflight(events.measurements, events.link_errors)
                           if self.preflight else None)
            if self.stop():
                self.ended_by = "stop requested during pre-flight"
                supervisor.finish(t)
            elif self.report is not None and self.report.ok:
                supervisor.begin_stand_up(t)
                self._moves_to(events, self.standing, posture.stand_up_s)
            elif elapsed > self.settings.preflight_timeout_s:
                self.ended_by = "pre-flight failed"
                supervisor.finish(t)
        elif state == S.STANDING_UP:
            if self.stop():
                self._sit_down(events, "stop requested while standing up")
            elif elapsed >= posture.stand_up_s + posture.settle_s:
                answer = self.confirm() if self.confirm is not None else True
                if answer:
                    supervisor.arm(t)
                    return True, False
                if answer is not None:
                    self._sit_down(events, "the operator declined to arm")
        elif state == S.ARMED:
            if self.stop():
                self._sit_down(events, "stop requested while armed")
            elif events.plan_ready:
                supervisor.begin_run(t)
                if events.frame is not None:
                    self.frames["start"] = events.frame
            elif elapsed > self.settings.max_armed_s:
                supervisor.trigger_safe_stop(t, f"no NMPC plan {elapsed:.3f} s after arming "
                                                f"(max {self.settings.max_armed_s} s)")
        elif state == S.RUNNING and self.settings.kind == "deploy":
            if self.stop() or elapsed >= self.settings.duration_s:
                if events.frame is not None:
                    self.frames["end"] = events.frame
                self._sit_down(events, "stop requested" if self.stop()
                               else f"ran {self.settings.duration_s:g} s")
        elif state == S.SITTING_DOWN:
            if elapsed >= posture.sit_down_s:
                supervisor.finish(t)
        elif state == S.SAFE_STOP:
            self.ended_by = self.ended_by or f"safe stop: {supervisor.fault}"
            if elapsed >= posture.final_damping_s:
                supervisor.finish(t)
        elif state == S.DONE:
            return False, elapsed >= posture.final_damping_s
        return False, False

    def _moves_to(self, events: RunEvents, goal: dict[str, np.ndarray], duration_s: float
                  ) -> None:
        posture, measurements = self.settings.posture, events.measurements
        self.moves = {name: PostureMove(
            measurements[name].position_rad if name in measurements else goal[name],
            goal[name], events.time_s, duration_s, posture.kp, posture.kd) for name in goal}

    def _sit_down(self, events: RunEvents, why: str) -> None:
        self.ended_by = why
        self.supervisor.begin_sit_down(events.time_s, why if self.controlled_stop else None)
        self._moves_to(events, self.sitting, self.settings.posture.sit_down_s)

