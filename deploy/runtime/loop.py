"""The one control loop of ``porter sim`` and ``porter deploy``, under the safety supervisor.

One tick per ``rates.wbc_hz`` (500 Hz) on a ``LoopClock`` (``deploy.runtime.clock``): lockstep
(simulated time, ``porter sim`` and tests) or paced (the wall clock scaled by ``time_scale``,
``porter deploy``). Every tick, in every state: read every robot (a lost link is a fault, not
an exception) and the MoCap; estimate (base velocity from leg odometry and MoCap for robots
whose driver measures none, ``core.estimation.base_velocity``); in ARMED / RUNNING the NMPC
schedule (``deploy.nmpc_runtime.nmpc_schedule``: one timing grid, one plan hand-off);
``SafetySupervisor.check``; the state's commands (posture moves, or each robot's WBC on the
active plan, its last fresh command where its state is stale, ``deploy.runtime.stale_state``),
clipped when just past a torque limit; ``filter_commands``; send; the NMPC's decision where its
runner answers later (``after_send``); record (``deploy.recording.loop_recording``). Times: the
loop clock minus the start of the run; the log uses the same times.

States (``deploy.safety.supervisor``), by ``sequence``:
- ``deploy``: PREFLIGHT (limp commands solicit the A1's states; the ``preflight`` checks are
  evaluated each tick until all pass or ``preflight_timeout_s``) -> STANDING_UP (joint PD to
  standing, ``deploy.safety.posture``, then ``posture.settle_s`` holding it; then the operator
  is asked) -> ARMED (holding; the first plan is computed) -> RUNNING (WBC on the plan, for
  ``duration_s`` or until a stop request) -> SITTING_DOWN -> DONE (joint damping for
  ``posture.final_damping_s``).
- ``standing`` (simulation: the team starts standing): PREFLIGHT -> RUNNING on the first tick;
  at ``duration_s`` or a stop request RUNNING -> DONE and the loop ends.
In both, any fault -> SAFE_STOP (damping only, latched) -> DONE after ``final_damping_s``; a
plan older than ``rates.max_plan_age_s`` while RUNNING trips the safe stop (NMPC stalled).
Infeasible plans are no fault: after ``MpcSettings.braking.after_flagged_updates`` of them in a
row the controller brakes and holds (``TeamController.plan_taken``), and
``braking.controlled_stop_s`` later RUNNING -> SITTING_DOWN -> DONE (a controlled stop), in both
sequences. Every transition goes to the flight recorder as an event (source ``safety``).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import replace
from typing import Literal, TextIO

import numpy as np

from core.estimation.base_velocity import BaseVelocityEstimator
from core.model.conventions import PAYLOAD_NAME
from deploy.nmpc_runtime.nmpc_process import NmpcProcessError
from deploy.nmpc_runtime.nmpc_schedule import NmpcSchedule
from deploy.recording.loop_recording import LoopRecording
from deploy.runtime.clock import LoopClock
from deploy.runtime.controller import TeamController, WbcStep
from deploy.runtime.gc_pauses import GcPauses
from deploy.runtime.links import TeamLinks
from deploy.runtime.loop_interfaces import Heartbeat, LoopHooks, LoopSettings
from deploy.runtime.stale_state import StaleStateHold, link_notes
from deploy.runtime.timing import PeriodStats, TickStages
from deploy.safety.checks import clip_torque, robot_limits
from deploy.safety.posture import PostureMove, sitting_posture, standing_posture
from deploy.safety.preflight import PreflightReport
from deploy.safety.supervisor import SafetyInputs, SafetyState, SafetySupervisor, Transition
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement
from drivers.link_errors import DriverError, LinkLostError

__all__ = ["ControlLoop", "Heartbeat", "LoopHooks", "LoopSettings", "SATURATION_MARGIN"]

SATURATION_MARGIN = 0.25  # commands up to 25 % past a torque limit are clipped to it
Confirm = Callable[[], bool | None]  # None while the operator has not answered
Preflight = Callable[[dict[str, RobotMeasurement], dict[str, str]], PreflightReport]
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
        self.nmpc, self.recording, self.stop, self.duration_s = nmpc, recording, stop, duration_s
        self.sequence, self.confirm, self.preflight = sequence, confirm, preflight
        self.hooks, self.out, self.verbose, self.watchdog = hooks, out, verbose, watchdog
        self.watchdog_tripped = False  # the watchdog took over during the run
        self.names = control.robot_names
        types = {robot.name: robot.robot_type for robot in control.robots}
        self.limits = {name: robot_limits(types[name], name) for name in self.names}
        self.standing = {name: standing_posture(types[name]) for name in self.names}
        self.sitting = {name: sitting_posture(types[name], settings.posture.sit_lowering_m)
                        for name in self.names}
        self.velocity: dict[str, BaseVelocityEstimator] = links.base_velocity
        self.supervisor = SafetySupervisor(settings.safety, list(self.limits.values()),
                                           self._on_transition)
        self.wbc_stats = PeriodStats(1.0 / settings.rates.wbc_hz)
        self.stages = TickStages()  # wall time per stage of the RUNNING ticks
        self.gc_pauses = GcPauses()  # start-up frozen out of the collector while the loop runs
        self.required_bodies = [*self.names, PAYLOAD_NAME]
        self.t0 = clock.now()
        self.since: dict[SafetyState, float] = {S.PREFLIGHT: 0.0}
        self.moves: dict[str, PostureMove] = {}
        self.saturations = dict.fromkeys(self.names, 0)  # ticks with a clipped torque
        self.stale = StaleStateHold(self.names, settings.safety.stale_state_hold_ticks,
                                    self.wbc_stats.period_s)
        self.report: PreflightReport | None = None
        self.frames: dict[str, MocapFrame] = {}  # at the start and the end of RUNNING
        self.heights: dict[str, list[float]] = {name: [] for name in self.names}
        self.ended_by, self.stopped_early = "", False
        self._overruns_seen = 0  # the clock's overrun count at the last tick
        self.controlled_stop = False  # the braking backup ended the run with a sit-down
        self.recorder_failure: str | None = None
        self._braking_said = False

    def now(self) -> float:
        return self.clock.now() - self.t0

    def outcome(self) -> dict:
        """How the run ended, in both sequences: result, final state, safe-stop cause, every
        transition, NMPC health and torque clipping (the shared part of both summaries)."""
        supervisor, nmpc = self.supervisor, self.nmpc
        return {
            "result": self.ended_by, "final_state": supervisor.state.name,
            "safe_stop": supervisor.fault or None,
            "transitions": [f"{t.time_s:.3f} s {t.text}" for t in supervisor.transitions],
            "nmpc_updates": nmpc.updates, "nmpc_deadline_misses": nmpc.deadline_misses,
            "nmpc_failed_updates": nmpc.solver_failures,
            "nmpc_margin_flags": nmpc.margin_flags, "nmpc_relaxed_plans": nmpc.relaxed_plans,
            "braking_since_s": self.control.braking_since_s,
            "reference_held_s": round(self.control.reference_held_s, 3),
            "controlled_stop": self.controlled_stop, "recorder_failure": self.recorder_failure,
            "torque_saturations": dict(self.saturations),
            "wbc_failed_ticks": supervisor.wbc_failures.failed_ticks,
            "stale_state_held_ticks": dict(self.stale.held_ticks),
            "longest_stale_state_ticks": dict(self.stale.longest_stale_ticks),
        }

    def say(self, text: str) -> None:
        if self.verbose:
            command = "deploy" if self.sequence == "deploy" else "sim"
            print(f"porter {command}: {text}", file=self.out or sys.stderr, flush=True)

    def _on_transition(self, transition: Transition) -> None:
        self.since[transition.target] = transition.time_s
        self.say(f"[{transition.time_s:7.3f} s] {transition.text}")
        if self.recording is not None:
            self.recording.transition(transition.time_s, transition.text,
                                      transition.target == S.SAFE_STOP)

    # --- the run -------------------------------------------------------------------------
    def run(self, start_text: str) -> None:
        if self.recording is not None:
            self.recording.start(self.now(), start_text)
        self.since[S.PREFLIGHT] = self.now()  # the pre-flight timeout counts from here
        self.gc_pauses.start()
        self.clock.start()
        try:
            while not self._tick():
                self.clock.wait()
        except BaseException as error:  # damp the robots, then let the error through
            self.supervisor.trigger_safe_stop(self.now(), f"exception: {error!r}")
            for _ in range(3):
                self._send(self.supervisor.damping_commands())
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
        stages = self.stages
        stages.start()
        start = self.clock.now()
        t = start - self.t0
        if self.watchdog is not None:
            self.watchdog.beat()
            if self.watchdog.tripped:  # it saw this loop late: it is sending damping already
                self.supervisor.trigger_safe_stop(
                    t, "watchdog took over: the loop's heartbeat was late")
        if self.hooks is not None:
            self.hooks.before_tick(t)
        measurements, link_errors = self._read()
        frame = self.links.tracker.poll() if self.links.tracker is not None else None
        stages.mark("read")
        measurements = self._estimate(t, measurements)
        stages.mark("estimate")
        if self.sequence == "standing" and self._standing_transitions(t, measurements):
            return True
        flags: tuple[bool | None, bool | None] = (None, None)
        if self.supervisor.state in (S.ARMED, S.RUNNING):
            try:
                flags = self.nmpc.step(t, measurements, frame)
            except NmpcProcessError as error:  # it died: no plan will come; stop here
                self.supervisor.trigger_safe_stop(t, f"NMPC process lost: {error}")
        stages.mark("nmpc")
        estop = self.links.estop.status() if self.links.estop is not None else None
        age = self.links.tracker.age_s(self.required_bodies) if self.links.tracker else None
        overran, self._overruns_seen = self.clock.overruns > self._overruns_seen, self.clock.overruns
        stale = self.stale.stale_s()
        self.supervisor.check(SafetyInputs(
            t, estop.run_allowed if estop else False, estop.reason if estop else "no e-stop",
            age, measurements, link_errors, *flags, loop_overrun=overran, stale_state_s=stale,
            link_notes=link_notes(self.links.drivers, stale) if stale else {}))
        plan_age_s, max_age_s = t - self.nmpc.plan_start_s, self.settings.rates.max_plan_age_s
        if self.supervisor.state == S.RUNNING and plan_age_s > max_age_s:
            self.supervisor.trigger_safe_stop(t, f"NMPC stalled: the plan is {plan_age_s:.3f} s "
                                              f"old (max {max_age_s} s)")
        stages.mark("check")
        commands, steps = self._commands(t, measurements)
        stages.mark("control")
        sent = self.supervisor.filter_commands(t, commands, measurements)
        stages.mark("filter")
        self._send(sent)
        stages.mark("send")
        if self.supervisor.state in (S.ARMED, S.RUNNING):
            try:  # the NMPC's next decision, when built after the commands (async runners)
                self.nmpc.after_send(t, measurements, frame)
            except NmpcProcessError as error:
                self.supervisor.trigger_safe_stop(t, f"NMPC process lost: {error}")
            stages.mark("nmpc")
        if self.recording is not None:
            self.recording.team_tick(t, self.names, measurements, sent, steps)
            failure = self.recording.writer_failure(t)
            if failure is not None:
                self._recorder_failed(t, failure)
        stages.mark("record")
        running = self.supervisor.state == S.RUNNING
        if running:
            self.wbc_stats.tick(start)
            self.wbc_stats.busy_s.append(self.clock.now() - start)
            for name, m in measurements.items():
                self.heights[name].append(float(m.position_in_world_m[2]))
        stages.recording = running
        stages.finish()
        return self._advance(t, measurements, link_errors, frame)

    def _read(self) -> tuple[dict[str, RobotMeasurement], dict[str, str]]:
        """Every robot's measurement; a lost link is reported, not raised."""
        measurements, errors = {}, {}
        for name, driver in self.links.drivers.items():
            try:
                measurements[name] = driver.read()
            except LinkLostError as error:
                errors[name] = str(error)
        return measurements, errors

    def _estimate(self, t: float, measurements: dict[str, RobotMeasurement]
                  ) -> dict[str, RobotMeasurement]:
        """The base velocity fused from legs and MoCap where the driver measures none."""
        for name, estimator in self.velocity.items():
            if name in measurements:
                measurement = measurements[name]
                measurements[name] = replace(measurement, linear_velocity_in_world_m_s=(
                    estimator.update(t, measurement)))
        return measurements

    def _send(self, commands: dict[str, JointCommand]) -> None:
        for name, command in commands.items():
            driver = self.links.drivers.get(name)
            if driver is not None:
                try:
                    driver.send(command)
                except DriverError as error:
                    self.supervisor.trigger_safe_stop(self.now(), f"send failed: {error}")

    # --- commands per state ----------------------------------------------------------------
    def _commands(self, t: float, measurements: dict[str, RobotMeasurement]
                  ) -> tuple[dict[str, JointCommand], list[WbcStep] | None]:
        state = self.supervisor.state
        if state in (S.STANDING_UP, S.ARMED, S.SITTING_DOWN):
            return {name: self._saturate(name, move.command(t), measurements.get(name))
                    for name, move in self.moves.items()}, None
        plan = self.nmpc.plan
        if state == S.RUNNING and plan is not None and len(measurements) == len(self.names):
            steps = self.control.wbc_steps(t, plan, self.nmpc.plan_start_s,
                                           [measurements[n] for n in self.names])
            for name, step in zip(self.names, steps, strict=True):
                self.supervisor.wbc_ticked(t, name, step.output.success, step.output.status)
            if self.hooks is not None:
                self.hooks.wbc_stepped(steps)
            # a new step only where held or clipped: dataclasses.replace costs ~10 us a robot
            held = [self.stale.command(n, measurements[n], s.command)
                    for n, s in zip(self.names, steps, strict=True)]
            steps = [step if (command := self._saturate(name, c, measurements[name])) is step.command
                     else replace(step, command=command)
                     for name, step, c in zip(self.names, steps, held, strict=True)]
            return {n: step.command for n, step in zip(self.names, steps, strict=True)}, steps
        return {}, None

    def _saturate(self, name: str, command: JointCommand, measurement: RobotMeasurement | None
                  ) -> JointCommand:
        """``clip_torque`` at robot ``name``'s limit, counting the clipped ticks."""
        if measurement is None:
            return command
        limit = self.limits[name].torque_nm * self.settings.safety.torque_limit_fraction
        clipped = clip_torque(command, measurement, limit, SATURATION_MARGIN)
        self.saturations[name] += int(clipped is not command)
        return clipped

    def _moves_to(self, t: float, goal: dict[str, np.ndarray], duration_s: float,
                  measurements: dict[str, RobotMeasurement]) -> None:
        posture = self.settings.posture
        self.moves = {name: PostureMove(
            measurements[name].position_rad if name in measurements else goal[name],
            goal[name], t, duration_s, posture.kp, posture.kd) for name in self.names}

    # --- transitions ---------------------------------------------------------------------
    def _standing_transitions(self, t: float, measurements: dict[str, RobotMeasurement]) -> bool:
        """The simulation's start (standing, straight to RUNNING) and end (at ``duration_s``
        or a stop request, before the tick's work); True once the run is over."""
        supervisor = self.supervisor
        if supervisor.state == S.PREFLIGHT:
            supervisor.start_standing(t)
            self.control.reset([measurements[n] for n in self.names], start_s=t)
            self.nmpc.start(t)
        elif supervisor.state == S.RUNNING:
            stop = self.stop()
            if stop or t - self.since[S.RUNNING] >= self.duration_s - 1e-9:
                self.stopped_early = stop
                self.ended_by = "stop requested" if stop else f"ran {self.duration_s:g} s"
                self.nmpc.flush(t)
                supervisor.end_standing(t)
                return True
        return False

    def _advance(self, t: float, measurements: dict[str, RobotMeasurement],
                 link_errors: dict[str, str], frame: MocapFrame | None) -> bool:
        supervisor, state, posture = self.supervisor, self.supervisor.state, self.settings.posture
        elapsed = t - self.since.get(state, t)
        braking_since = self.control.braking_since_s
        if self.nmpc.braking and not self._braking_said:
            self._braking_said = True
            self.say(f"[{t:7.3f} s] {self.nmpc.braking}")
        if (state == S.RUNNING and braking_since is not None
                and t - braking_since >= self.control.settings.braking.controlled_stop_s):
            self.controlled_stop = True
            self._sit_down(t, measurements, f"controlled stop: braking since "
                           f"{braking_since:.3f} s ({self.nmpc.braking})")
        elif state == S.PREFLIGHT:
            self.report = self.preflight(measurements, link_errors) if self.preflight else None
            if self.stop():
                self.ended_by = "stop requested during pre-flight"
                supervisor.finish(t)
            elif self.report is not None and self.report.ok:
                supervisor.begin_stand_up(t)
                self._moves_to(t, self.standing, posture.stand_up_s, measurements)
            elif elapsed > self.settings.preflight_timeout_s:
                self.ended_by = "pre-flight failed"
                supervisor.finish(t)
        elif state == S.STANDING_UP:
            if self.stop():
                self._sit_down(t, measurements, "stop requested while standing up")
            elif elapsed >= posture.stand_up_s + posture.settle_s:
                answer = self.confirm() if self.confirm is not None else True
                if answer:
                    supervisor.arm(t)
                    self.control.reset([measurements[n] for n in self.names], start_s=t)
                    self.nmpc.start(t)
                elif answer is not None:
                    self._sit_down(t, measurements, "the operator declined to arm")
        elif state == S.ARMED:
            if self.stop():
                self._sit_down(t, measurements, "stop requested while armed")
            elif self.nmpc.plan is not None:
                supervisor.begin_run(t)
                if frame is not None:
                    self.frames["start"] = frame
            elif elapsed > self.settings.rates.max_armed_s:
                supervisor.trigger_safe_stop(t, f"no NMPC plan {elapsed:.3f} s after arming "
                                                f"(max {self.settings.rates.max_armed_s} s)")
        elif state == S.RUNNING and self.sequence == "deploy":
            if self.stop() or elapsed >= self.duration_s:
                if frame is not None:
                    self.frames["end"] = frame
                self._sit_down(t, measurements, "stop requested" if self.stop()
                               else f"ran {self.duration_s:g} s")
        elif state == S.SITTING_DOWN:
            if elapsed >= posture.sit_down_s:
                supervisor.finish(t)
        elif state == S.SAFE_STOP:
            self.ended_by = self.ended_by or f"safe stop: {supervisor.fault}"
            if elapsed >= posture.final_damping_s:
                supervisor.finish(t)
        elif state == S.DONE:
            return elapsed >= posture.final_damping_s
        return False

    def _recorder_failed(self, t: float, failure: str) -> None:
        """The flight recorder stopped writing: a safe stop, or a warning, by its settings."""
        self.recorder_failure = failure
        self.say(f"[{t:7.3f} s] ERROR: flight recorder failed: {failure}")
        if self.recording is not None and self.recording.recorder.settings.on_failure == "safe_stop":
            self.supervisor.trigger_safe_stop(t, f"flight recorder failed: {failure}")

    def _sit_down(self, t: float, measurements: dict[str, RobotMeasurement], why: str) -> None:
        self.ended_by = why
        self.supervisor.begin_sit_down(t, why if self.controlled_stop else None)
        self._moves_to(t, self.sitting, self.settings.posture.sit_down_s, measurements)
