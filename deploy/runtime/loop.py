"""The one control loop of ``porter sim`` and ``porter deploy``, under the safety supervisor.

One tick per ``rates.wbc_hz`` (500 Hz) on a ``LoopClock`` (``deploy.runtime.clock``): lockstep
(simulated time, ``porter sim`` and tests) or paced (the wall clock scaled by ``time_scale``,
``porter deploy``). Every tick, in every state: the estimator pipeline
(``deploy.runtime.state_pipeline``: every robot, the MoCap, the base states; a lost link is a
fault, not an exception); in ARMED / RUNNING the NMPC schedule
(``deploy.nmpc_runtime.nmpc_schedule``: one timing grid, one plan hand-off);
``SafetySupervisor.check``; the commands of the state's source
(``deploy.runtime.team_commands``); ``filter_commands``; send; the NMPC's decision where its
runner answers later (``after_send``); record (``deploy.recording.loop_recording``). Times: the
loop clock minus the start of the run; the log uses the same times.

The run's states and transitions are ``deploy.safety.run_sequence``'s (its table): the loop
fills one ``RunEvents`` record per tick, hands it to the sequence at the tick's start, before
the commands and at its end, and sends what the state's command source gives.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Literal, TextIO

from core.model.conventions import PAYLOAD_NAME
from deploy.compute.gc_pauses import GcPauses
from deploy.nmpc_runtime.nmpc_process import NmpcProcessError
from deploy.nmpc_runtime.nmpc_schedule import NmpcSchedule
from deploy.recording.loop_recording import LoopRecording
from deploy.runtime.clock import LoopClock, PeriodStats, TickStages
from deploy.runtime.controller import TeamController, WbcStep
from deploy.runtime.links import TeamLinks
from deploy.runtime.loop_interfaces import Heartbeat, LoopHooks, LoopSettings
from deploy.runtime.state_pipeline import StatePipeline
from deploy.runtime.team_commands import StaleStateHold, TeamCommands, link_notes
from deploy.safety.checks import robot_limits
from deploy.safety.posture import sitting_posture, standing_posture
from deploy.safety.run_sequence import (
    Confirm,
    Preflight,
    RunEvents,
    RunSequence,
    SequenceSettings,
)
from deploy.safety.supervisor import SafetyInputs, SafetyState, SafetySupervisor, Transition
from drivers.interfaces import JointCommand, RobotMeasurement

__all__ = ["ControlLoop", "Heartbeat", "LoopHooks", "LoopSettings"]
S = SafetyState


class ControlLoop:
    """One run; ``run()`` returns once the team is DONE."""

    def __init__(self, control: TeamController, links: TeamLinks, settings: LoopSettings,
                 clock: LoopClock, nmpc: NmpcSchedule, recording: LoopRecording | None,
                 stop: Callable[[], bool], duration_s: float,
                 sequence: Literal["deploy", "standing"] = "deploy",
                 confirm: Confirm | None = None, preflight: Preflight | None = None,
                 hooks: LoopHooks | None = None, out: TextIO | None = None,
                 verbose: bool = True, watchdog: Heartbeat | None = None) -> None:
        self.control, self.links, self.settings, self.clock = control, links, settings, clock
        self.nmpc, self.recording, self.duration_s = nmpc, recording, duration_s
        self.kind, self.hooks, self.out, self.verbose = sequence, hooks, out, verbose
        self.watchdog = watchdog
        self.watchdog_tripped = False  # the watchdog took over during the run
        self.names = control.robot_names
        types = {robot.name: robot.robot_type for robot in control.robots}
        self.limits = {name: robot_limits(types[name], name) for name in self.names}
        self.pipeline = StatePipeline(links.drivers, links.tracker, links.base_velocity)
        self.supervisor = SafetySupervisor(settings.safety, list(self.limits.values()),
                                           self._on_transition)
        recorder = recording.recorder.settings.on_failure if recording is not None else ""
        self.sequence = RunSequence(
            self.supervisor, SequenceSettings(
                sequence, duration_s, settings.posture, settings.preflight_timeout_s,
                settings.rates.max_armed_s, settings.rates.max_plan_age_s,
                control.settings.braking.controlled_stop_s, recorder == "safe_stop"),
            {name: standing_posture(types[name]) for name in self.names},
            {name: sitting_posture(types[name], settings.posture.sit_lowering_m)
             for name in self.names}, stop, confirm, preflight, self.say)
        self.wbc_stats = PeriodStats(1.0 / settings.rates.wbc_hz)
        self.stages = TickStages()  # wall time per stage of the RUNNING ticks
        self.gc_pauses = GcPauses()  # start-up frozen out of the collector while the loop runs
        self.required_bodies = [*self.names, PAYLOAD_NAME]
        self.t0 = clock.now()
        self.stale = StaleStateHold(self.names, settings.safety.stale_state_hold_ticks,
                                    self.wbc_stats.period_s)
        self.commands = TeamCommands(self.names, self.limits,
                                     settings.safety.torque_limit_fraction, self.stale)
        self.heights: dict[str, list[float]] = {name: [] for name in self.names}
        self._overruns_seen = 0  # the clock's overrun count at the last tick
        self.recorder_failure: str | None = None

    def now(self) -> float:
        return self.clock.now() - self.t0

    def outcome(self) -> dict:
        """How the run ended, in both sequences: result, final state, safe-stop cause, every
        transition, NMPC health and torque clipping (the shared part of both summaries)."""
        supervisor, nmpc, sequence = self.supervisor, self.nmpc, self.sequence
        return {
            "result": sequence.ended_by, "final_state": supervisor.state.name,
            "safe_stop": supervisor.fault or None,
            "transitions": [f"{t.time_s:.3f} s {t.text}" for t in supervisor.transitions],
            "nmpc_updates": nmpc.updates, "nmpc_deadline_misses": nmpc.deadline_misses,
            # the longest a decision waited for its plan [ms of the loop's clock]
            "nmpc_longest_delay_ms": round(1e3 * max(nmpc.delays_s, default=0.0), 3),
            "nmpc_failed_updates": nmpc.solver_failures,
            "nmpc_margin_flags": nmpc.margin_flags, "nmpc_relaxed_plans": nmpc.relaxed_plans,
            "braking_since_s": self.control.braking_since_s,
            "reference_held_s": round(self.control.reference_held_s, 3),
            "controlled_stop": sequence.controlled_stop,
            "recorder_failure": self.recorder_failure,
            "torque_saturations": dict(self.commands.saturations),
            "wbc_failed_ticks": supervisor.wbc_failures.failed_ticks,
            "stale_state_held_ticks": dict(self.stale.held_ticks),
            "longest_stale_state_ticks": dict(self.stale.longest_stale_ticks),
        }

    def say(self, text: str) -> None:
        if self.verbose:
            command = "deploy" if self.kind == "deploy" else "sim"
            print(f"porter {command}: {text}", file=self.out or sys.stderr, flush=True)

    def _on_transition(self, transition: Transition) -> None:
        self.sequence.entered(transition.target, transition.time_s)
        self.say(f"[{transition.time_s:7.3f} s] {transition.text}")
        if self.recording is not None:
            self.recording.transition(transition.time_s, transition.text,
                                      transition.target == S.SAFE_STOP)

    # --- the run -------------------------------------------------------------------------
    def run(self, start_text: str) -> None:
        if self.recording is not None:
            self.recording.start(self.now(), start_text)
        self.sequence.entered(S.PREFLIGHT, self.now())  # the pre-flight timeout counts from here
        self.gc_pauses.start()
        self.clock.start()
        try:
            while not self._tick():
                self.clock.wait()
        except BaseException as error:  # damp the robots, then let the error through
            self.sequence.abort(self.now(), f"exception: {error!r}")
            for _ in range(3):
                self.links.send(self.supervisor.damping_commands())
            raise
        finally:
            # The run is over (DONE, or damped after an exception): the watchdog must not take
            # the summary, the log's close or the NMPC's shutdown for a dead loop.
            if self.watchdog is not None:
                self.watchdog_tripped = self.watchdog.tripped
                self.watchdog.disarm()
            self.gc_pauses.stop()
            self.nmpc.close()

    def _tick(self) -> bool:
        """One loop period; True once the run is over. ``stages`` times each part of it."""
        stages, sequence = self.stages, self.sequence
        stages.start()
        start = self.clock.now()
        events = RunEvents(start - self.t0)
        t = events.time_s
        if self.watchdog is not None:
            self.watchdog.beat()
            events.watchdog_tripped = self.watchdog.tripped
        if self.hooks is not None:
            self.hooks.before_tick(t)
        reading = self.pipeline.update(t, stages.mark)
        measurements, frame = events.measurements, events.frame = reading.measurements, reading.frame
        events.link_errors = reading.link_errors
        start_plans, over = sequence.at_tick_start(events)
        self._start_plans(t, measurements, start_plans)
        if over:
            self.nmpc.flush(t)
            return True
        flags: tuple[bool | None, bool | None] = (None, None)
        if sequence.planning:
            try:
                flags = self.nmpc.step(t, measurements, frame)
            except NmpcProcessError as error:  # it died: no plan will come
                events.nmpc_lost = str(error)
        stages.mark("nmpc")
        estop = self.links.estop.status() if self.links.estop is not None else None
        age = self.links.tracker.age_s(self.required_bodies) if self.links.tracker else None
        overran, self._overruns_seen = self.clock.overruns > self._overruns_seen, self.clock.overruns
        stale = self.stale.stale_s()
        self.supervisor.check(SafetyInputs(
            t, estop.run_allowed if estop else False, estop.reason if estop else "no e-stop",
            age, measurements, events.link_errors, *flags, loop_overrun=overran,
            stale_state_s=stale,
            link_notes=link_notes(self.links.drivers, stale) if stale else {}))
        events.plan_start_s = self.nmpc.plan_start_s
        sequence.before_commands(events)
        events.nmpc_lost = None  # reported: a later loss is the tick end's
        stages.mark("check")
        commands, steps = self._commands(t, measurements)
        stages.mark("control")
        sent = self.supervisor.filter_commands(t, commands, measurements)
        stages.mark("filter")
        events.send_failed = self.links.send(sent)
        stages.mark("send")
        if sequence.planning and events.send_failed is None:
            try:  # the NMPC's next decision, when built after the commands (async runners)
                self.nmpc.after_send(t, measurements, frame)
            except NmpcProcessError as error:
                events.nmpc_lost = str(error)
            stages.mark("nmpc")
        if self.recording is not None:
            self.recording.team_tick(t, self.names, measurements, sent, steps)
            events.recorder_failed = self.recording.writer_failure(t)
            self.recorder_failure = events.recorder_failed or self.recorder_failure
        stages.mark("record")
        running = self.supervisor.state == S.RUNNING
        if running:
            self.wbc_stats.tick(start)
            self.wbc_stats.busy_s.append(self.clock.now() - start)
            for name, m in measurements.items():
                self.heights[name].append(float(m.position_in_world_m[2]))
        stages.recording = running
        stages.finish()
        events.plan_ready, events.braking = self.nmpc.plan is not None, self.control.braking
        start_plans, over = sequence.at_tick_end(events)
        self._start_plans(t, measurements, start_plans)
        return over

    def _start_plans(self, t: float, measurements: dict[str, RobotMeasurement],
                     start: bool) -> None:
        if start:
            self.control.reset([measurements[n] for n in self.names], start_s=t)
            self.nmpc.start(t)

    # --- commands by the state's source ------------------------------------------------------
    def _commands(self, t: float, measurements: dict[str, RobotMeasurement]
                  ) -> tuple[dict[str, JointCommand], list[WbcStep] | None]:
        source, plan = self.sequence.source, self.nmpc.plan
        if source == "posture":
            return self.commands.posture(t, self.sequence.moves, measurements), None
        if source == "plan" and plan is not None and len(measurements) == len(self.names):
            steps = self.control.wbc_steps(t, plan, self.nmpc.plan_start_s,
                                           [measurements[n] for n in self.names])
            for name, step in zip(self.names, steps, strict=True):
                self.supervisor.wbc_ticked(t, name, step.output.success, step.output.status)
            if self.hooks is not None:
                self.hooks.wbc_stepped(steps)
            return self.commands.planned(steps, measurements)
        return {}, None
