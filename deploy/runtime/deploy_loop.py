"""``porter deploy``'s loop: pre-flight, stand up, arm, run, sit down, under the safety supervisor.

One paced loop at ``rates.wbc_hz`` (500 Hz) in the calling thread, for every state:
read every robot (a lost link is a fault, not an exception) and the MoCap; in ARMED / RUNNING
pick up a finished NMPC plan and, at the 60 Hz instants when the NMPC thread is idle, submit
the next decision (``deploy.runtime.nmpc_thread``: the WBC never waits for a plan, it tracks the newest
finished one); ``SafetySupervisor.check``; the state's commands; ``filter_commands``; send;
record. Times: the loop's clock (monotonic, seconds) minus the start of the run; the log uses
the same times.

States (``deploy.safety.supervisor``): PREFLIGHT (limp commands solicit the A1's states; the
checks of ``deploy.safety.preflight`` are evaluated each tick until all pass or ``preflight.timeout_s``)
-> STANDING_UP (joint PD to standing, ``deploy.safety.posture``, then ``posture.settle_s`` holding it;
then the operator is asked) -> ARMED (holding; the first plan is computed) -> RUNNING (WBC on
the plan, for ``duration_s`` or until a stop request) -> SITTING_DOWN (joint PD to sitting) ->
DONE (joint damping for ``posture.final_damping_s``). Any fault -> SAFE_STOP (damping only,
latched) -> DONE. Every transition goes to the flight recorder as an event (source
``safety``). Besides the supervisor's checks, a plan older than ``rates.max_plan_age_s`` while
RUNNING trips the safe stop (the NMPC has stalled).
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from dataclasses import replace
from typing import TextIO

import numpy as np

from core.estimation.base_velocity import BaseVelocityEstimator
from core.model.conventions import PAYLOAD_NAME
from deploy.config.deploy_config import DeployConfig
from deploy.recording import log_format as fmt
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.loop_recording import LoopRecording
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.runtime.controller import TeamController, WbcStep
from deploy.runtime.links import TeamLinks
from deploy.runtime.nmpc_schedule import NmpcSchedule
from deploy.runtime.timing import Pacer, PeriodStats
from deploy.safety.posture import PostureMove, sitting_posture, standing_posture
from deploy.safety.preflight import PreflightReport, evaluate
from deploy.safety.supervisor import (
    SafetyInputs,
    SafetyState,
    SafetySupervisor,
    Transition,
    robot_limits,
)
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement
from drivers.link_errors import DriverError, LinkLostError
from drivers.robot_descriptions import load_pinocchio_model
from drivers.unitree.go2_driver import Go2Driver

SATURATION_MARGIN = 0.25  # commands up to 25 % past a torque limit are clipped to it
Confirm = Callable[[], bool | None]  # None while the operator has not answered
S = SafetyState


class DeployLoop:
    """One deployment run; ``run()`` returns once the team is DONE."""

    def __init__(self, config: DeployConfig, control: TeamController, links: TeamLinks,
                 recorder: FlightRecorder | None, confirm: Confirm, stop: Callable[[], bool],
                 duration_s: float, clock: Callable[[], float] = time.monotonic,
                 sleep: Callable[[float], None] = time.sleep, out: TextIO | None = None) -> None:
        self.config, self.control, self.links = config, control, links
        self.confirm, self.stop, self.duration_s = confirm, stop, duration_s
        self.clock, self.sleep, self.out = clock, sleep, out
        self.names = control.robot_names
        types = {robot.name: robot.robot_type for robot in control.robots}
        self.limits = {name: robot_limits(types[name], name) for name in self.names}
        self.standing = {name: standing_posture(types[name]) for name in self.names}
        self.velocity = {name: BaseVelocityEstimator(load_pinocchio_model(types[name]))
                         for name in self.names}
        self.sitting = {name: sitting_posture(types[name], config.posture.sit_lowering_m)
                        for name in self.names}
        self.supervisor = SafetySupervisor(config.safety, list(self.limits.values()),
                                           self._on_transition)
        self.recording = None if recorder is None else LoopRecording(
            recorder, self.names, control.obstacles,
            [o.height_m for o in control.scenario.obstacles],
            control.settings.safety.safety_distance_m, control.settings.sample_period_s,
            np.asarray(control.scenario.payload.size_m))
        self.nmpc = NmpcSchedule(control, config.rates.nmpc_hz, clock, self.recording,
                                 links.force_torque)
        self.wbc_stats = PeriodStats(1.0 / config.rates.wbc_hz)
        self.required_bodies = [*self.names, PAYLOAD_NAME]
        self.t0 = clock()
        self.since: dict[SafetyState, float] = {S.PREFLIGHT: 0.0}
        self.moves: dict[str, PostureMove] = {}
        self.saturations = dict.fromkeys(self.names, 0)  # ticks with a clipped torque
        self.pacer: Pacer | None = None
        self.report: PreflightReport | None = None
        self.sport_mode: dict[str, str] = {}
        self.frames: dict[str, MocapFrame] = {}  # at the start and the end of RUNNING
        self.heights: dict[str, list[float]] = {name: [] for name in self.names}
        self.ended_by = ""

    def now(self) -> float:
        return self.clock() - self.t0

    def say(self, text: str) -> None:
        print(f"porter deploy: {text}", file=self.out or sys.stderr, flush=True)

    def _on_transition(self, transition: Transition) -> None:
        self.since[transition.target] = transition.time_s
        self.say(f"[{transition.time_s:7.3f} s] {transition.text}")
        if self.recording is not None:
            level = pb.Event.ERROR if transition.target == S.SAFE_STOP else pb.Event.INFO
            self.recording.recorder.event(transition.time_s, transition.text, source="safety",
                                          level=level)

    # --- the run -------------------------------------------------------------------------
    def run(self) -> None:
        if self.recording is not None:
            self.recording.start(0.0, f"start: porter deploy, scenario {self.control.scenario.name}")
        for name, driver in self.links.drivers.items():
            link = self.config.robots[name]
            if isinstance(driver, Go2Driver) and getattr(link, "release_sport_mode", False):
                try:
                    code = driver.release_sport_mode()
                    self.sport_mode[name] = "released" if code == 0 else f"refused, code {code}"
                except DriverError as error:
                    self.sport_mode[name] = str(error)
        self.since[S.PREFLIGHT] = self.now()  # the pre-flight timeout counts from here
        pacer = self.pacer = Pacer(1.0 / self.config.rates.wbc_hz, self.clock, self.sleep)
        try:
            while not self._tick():
                pacer.wait()
        except BaseException as error:  # damp the robots, then let the error through
            self.supervisor.trigger_safe_stop(self.now(), f"exception: {error!r}")
            for _ in range(3):
                self._send(self.supervisor.damping_commands())
            raise
        finally:
            self.nmpc.close()

    def _tick(self) -> bool:
        """One loop period; True once the run is over."""
        start = self.clock()
        t = start - self.t0
        measurements, link_errors = self._read(t)
        frame = self.links.tracker.poll() if self.links.tracker is not None else None
        state = self.supervisor.state
        flags: tuple[bool | None, bool | None] = (None, None)
        if state in (S.ARMED, S.RUNNING):
            flags = self.nmpc.step(t, measurements, frame)
        estop = self.links.estop.status() if self.links.estop is not None else None
        age = self.links.tracker.age_s(self.required_bodies) if self.links.tracker else None
        self.supervisor.check(SafetyInputs(
            t, estop.run_allowed if estop else False, estop.reason if estop else "no CAN bus",
            age, measurements, link_errors, *flags))
        plan_age_s = t - self.nmpc.plan_start_s
        if self.supervisor.state == S.RUNNING and plan_age_s > self.config.rates.max_plan_age_s:
            self.supervisor.trigger_safe_stop(t, f"NMPC stalled: the plan is {plan_age_s:.3f} s "
                                              f"old (max {self.config.rates.max_plan_age_s} s)")
        commands, steps = self._commands(t, measurements)
        sent = self.supervisor.filter_commands(t, commands, measurements)
        self._send(sent)
        self._record(t, measurements, sent, steps)
        if self.supervisor.state == S.RUNNING:
            self.wbc_stats.tick(start)
            self.wbc_stats.busy_s.append(self.clock() - start)
            for name, m in measurements.items():
                self.heights[name].append(float(m.position_in_world_m[2]))
        return self._advance(t, measurements, link_errors, frame)

    def _read(self, t: float) -> tuple[dict[str, RobotMeasurement], dict[str, str]]:
        """Every robot's measurement, its base velocity fused from legs and MoCap
        (``core.estimation.base_velocity``); a lost link is reported, not raised."""
        measurements, errors = {}, {}
        for name, driver in self.links.drivers.items():
            try:
                measurement = driver.read()
            except LinkLostError as error:
                errors[name] = str(error)
                continue
            measurements[name] = replace(measurement, linear_velocity_in_world_m_s=(
                self.velocity[name].update(t, measurement)))
        return measurements, errors

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
            steps = [replace(step, command=self._saturate(name, step.command, measurements[name]))
                     for name, step in zip(self.names, self.control.wbc_steps(
                         t, plan, self.nmpc.plan_start_s,
                         [measurements[n] for n in self.names]), strict=True)]
            return {n: step.command for n, step in zip(self.names, steps, strict=True)}, steps
        return {}, None

    def _saturate(self, name: str, command: JointCommand, measurement: RobotMeasurement | None
                  ) -> JointCommand:
        """Clip the firmware law's torque at the measured state to the limit (as the motor
        would) by trimming the feed-forward, and count it, when it is at most
        ``SATURATION_MARGIN`` past the limit: the WBC's own torques respect the limits but its
        damping term ``kd (qdd dt)`` can push the sum just past them; a posture move's PD
        starting on a leg in mid-swing (sit-down) brakes it with kd (0 - dq). A command further
        past a limit is left alone: the supervisor's torque fault stops the team."""
        if measurement is None:
            return command
        limit = self.limits[name].torque_nm * self.config.safety.torque_limit_fraction
        total = command.torque_for(measurement.position_rad, measurement.velocity_rad_s)
        clipped = np.clip(total, -limit, limit)
        if np.array_equal(clipped, total) or not np.all(
                np.abs(total) <= (1.0 + SATURATION_MARGIN) * limit):
            return command
        self.saturations[name] += 1
        return replace(command, torque_nm=command.torque_nm + clipped - total)

    def _record(self, t: float, measurements: dict[str, RobotMeasurement],
                sent: dict[str, JointCommand], steps: list[WbcStep] | None) -> None:
        if self.recording is None:
            return
        for i, name in enumerate(self.names):
            measurement, command = measurements.get(name), sent.get(name)
            if measurement is None or command is None:
                continue
            if steps is not None and command is steps[i].command:
                step = steps[i]
                self.recording.wbc_tick(t, name, measurement, command, step.output,
                                        step.stance, step.foot_targets_m)
            else:
                log = self.recording.recorder.log
                log(fmt.robot_topic(name, "state"), fmt.robot_state(name, measurement), t)
                log(fmt.robot_topic(name, "command"), fmt.joint_command(t, name, command), t)

    def _moves_to(self, t: float, goal: dict[str, np.ndarray], duration_s: float,
                  measurements: dict[str, RobotMeasurement]) -> None:
        posture = self.config.posture
        self.moves = {name: PostureMove(
            measurements[name].position_rad if name in measurements else goal[name],
            goal[name], t, duration_s, posture.kp, posture.kd) for name in self.names}

    # --- transitions ---------------------------------------------------------------------
    def _advance(self, t: float, measurements: dict[str, RobotMeasurement],
                 link_errors: dict[str, str], frame: MocapFrame | None) -> bool:
        supervisor, state, posture = self.supervisor, self.supervisor.state, self.config.posture
        elapsed = t - self.since.get(state, t)
        if state == S.PREFLIGHT:
            self.report = evaluate(self.config, self.links, self.limits, measurements,
                                   link_errors, self.sport_mode)
            if self.stop():
                self.ended_by = "stop requested during pre-flight"
                supervisor.finish(t)
            elif self.report.ok:
                supervisor.begin_stand_up(t)
                self._moves_to(t, self.standing, posture.stand_up_s, measurements)
            elif elapsed > self.config.preflight.timeout_s:
                self.ended_by = "pre-flight failed"
                supervisor.finish(t)
        elif state == S.STANDING_UP:
            if self.stop():
                self._sit_down(t, measurements, "stop requested while standing up")
            elif elapsed >= posture.stand_up_s + posture.settle_s:
                answer = self.confirm()
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
        elif state == S.RUNNING:
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

    def _sit_down(self, t: float, measurements: dict[str, RobotMeasurement], why: str) -> None:
        self.ended_by = why
        self.supervisor.begin_sit_down(t)
        self._moves_to(t, self.sitting, self.config.posture.sit_down_s, measurements)
