"""The loop's side of the NMPC, for both clocks: 60 Hz instants, hand-over to a runner, pick-up
of finished plans, their recording, and NMPC health for the safety supervisor.

``step`` runs in the loop, once per WBC tick while ARMED / RUNNING. A finished result is taken
first; then, at an NMPC instant with the runner idle, the decision is built from the tick's
measurements and MoCap frame and submitted, and taken at once if the runner already has it
(lockstep without a modelled delay). With ``decide_after_send`` (a runner that answers on a
later tick: thread or process) the decision is built in ``after_send`` instead, once the tick's
commands are out: the same tick's measurements and time, but the decision's build (~0.5-1 ms)
no longer delays that tick's commands. The runner is ``deploy.nmpc_runtime.nmpc_thread.NmpcThread``
(paced clock: a background thread, the WBC never waits) or
``deploy.nmpc_runtime.nmpc_lockstep.LockstepNmpc`` (simulated time).

One timing grid: the instants are ``start + k / nmpc_hz``; after a submit, and again when a plan
takes effect, the next instant is the first grid instant after now, so an update that overruns
skips the instants it covered (no back-to-back burst). The decision is planned for the instant
its plan will take effect: the state predicted over the recent median delay from decision to
taking effect (``TeamController.compensation_s``, ``core.nmpc.delay_compensation``); a taken
plan becomes the active one with stage 0 at that instant. ``step`` returns (solver failed,
deadline missed) on ticks where a plan was taken, for ``SafetyInputs``; a plan flagged only for
starting inside a safety margin, or for relaxing its soft barriers, is no solver failure (the
braking rule, ``TeamController.plan_taken``, counts those), and the deadline (one NMPC period from
decision to taking effect) is None when the runner has none (lockstep, no modelled delay).

On the tick after a plan took effect, the coupling F/T readings are logged against the plan's
first-stage wrench (``LoopRecording.plan_applied``) and passed to ``hooks``.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import numpy as np

from core.model.obstacles import Obstacle
from core.nmpc.mpc_plan import MpcPlan
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.recording.loop_recording import LoopRecording
from deploy.runtime.clock import PeriodStats
from deploy.runtime.controller import NmpcDecision, TeamController
from drivers.interfaces import MocapFrame, RobotMeasurement, WrenchSensors

__all__ = ["Flags", "NmpcHooks", "NmpcRunner", "NmpcSchedule"]

Flags = tuple[bool | None, bool | None]


class NmpcRunner(Protocol):
    @property
    def busy(self) -> bool: ...
    def submit(self, decision: NmpcDecision, update: int) -> None: ...
    def take(self) -> NmpcResult | None: ...
    def close(self) -> None: ...


class NmpcHooks(Protocol):
    """What a simulation measures around the NMPC (``deploy.runtime.sim_run``)."""

    def decided(self, decision: NmpcDecision) -> None: ...
    def planned(self, plan: MpcPlan) -> None: ...
    def wrench_compared(self, planned_force_n: np.ndarray, measured_force_n: np.ndarray
                        ) -> None: ...


class NmpcSchedule:
    """Owns the NMPC runner; ``plan`` / ``plan_start_s`` is what the WBC tracks."""

    def __init__(self, control: TeamController, runner: NmpcRunner, nmpc_hz: float,
                 clock: Callable[[], float], recording: LoopRecording | None,
                 force_torque: WrenchSensors | None, has_deadline: bool = True,
                 hooks: NmpcHooks | None = None,
                 truth: Callable[[], tuple[np.ndarray, np.ndarray]] | None = None,
                 decide_after_send: bool = False) -> None:
        self.control, self.runner, self.clock = control, runner, clock
        self.decide_after_send = decide_after_send
        self.recording, self.force_torque = recording, force_torque
        self.has_deadline, self.hooks, self.truth = has_deadline, hooks, truth
        self.names = control.robot_names
        self.period_s = 1.0 / nmpc_hz
        self.stats = PeriodStats(self.period_s)  # busy_s: each update's compute time
        self.delays_s: list[float] = []  # from each taken plan's decision to its taking effect
        self.plan: MpcPlan | None = None
        self.plan_start_s = 0.0
        self.start_s = 0.0
        self.next_instant = 0
        self.updates = 0
        self.plans_applied = 0
        self.deadline_misses = 0
        self.solver_failures = 0
        self.margin_flags = 0  # converged plans that start inside a safety margin
        self.relaxed_plans = 0  # plans whose soft barriers used slack
        self._submitted: dict[int, tuple[float, tuple[np.ndarray, np.ndarray] | None]] = {}
        self._compare_wrenches = False

    def start(self, t: float) -> None:
        """The first instant is now."""
        self.start_s, self.next_instant = t, 0

    def close(self) -> None:
        self.runner.close()

    def flush(self, t: float) -> None:
        """At the run's end: the wrench comparison of a plan that took effect last tick."""
        if self._compare_wrenches:
            self._compare_wrenches = False
            self._log_wrenches(t)

    def _grid_after(self, t: float) -> int:
        return int(np.floor((t - self.start_s) / self.period_s + 1e-6)) + 1

    def step(self, t: float, measurements: dict[str, RobotMeasurement],
             frame: MocapFrame | None) -> Flags:
        if self._compare_wrenches:
            self._compare_wrenches = False
            self._log_wrenches(t)
        flags: Flags = (None, None)
        result = self.runner.take()
        if result is not None:
            flags = self._apply(t, result)
        if not self.decide_after_send and self._decide(t, measurements, frame):
            result = self.runner.take()
            if result is not None:
                flags = self._apply(t, result)
        return flags

    def after_send(self, t: float, measurements: dict[str, RobotMeasurement],
                   frame: MocapFrame | None) -> None:
        """With ``decide_after_send``: the tick's decision, after its commands went out (the
        loop calls this on every ARMED / RUNNING tick; it does nothing otherwise)."""
        if self.decide_after_send:
            self._decide(t, measurements, frame)

    def _decide(self, t: float, measurements: dict[str, RobotMeasurement],
                frame: MocapFrame | None) -> bool:
        """Build and submit a decision if an instant is due and the runner idle; True if so."""
        due = t >= self.start_s + self.next_instant * self.period_s - 1e-9
        if (due and not self.runner.busy and frame is not None
                and all(name in measurements and name in frame.poses for name in self.names)):
            self._submit(t, measurements, frame)
            return True
        return False

    def _submit(self, t: float, measurements: dict[str, RobotMeasurement],
                frame: MocapFrame) -> None:
        active = None if self.plan is None else (self.plan, self.plan_start_s)
        delay_s = self.control.compensation_s(self.delays_s) if self.has_deadline else 0.0
        decision = self.control.nmpc_inputs(t, [measurements[n] for n in self.names], frame,
                                            self.obstacles(t, frame), delay_s=delay_s,
                                            active=active)
        if self.hooks is not None:
            self.hooks.decided(decision)
        if self.recording is not None:
            self.recording.nmpc_inputs(t, self.updates, decision.inputs)
        self._submitted[self.updates] = (t, self.truth() if self.truth is not None else None)
        self.stats.tick(self.clock())
        self.runner.submit(decision, self.updates)
        self.updates += 1
        self.next_instant = self._grid_after(t)

    def obstacles(self, t: float, frame: MocapFrame) -> list[Obstacle]:
        """The scenario's obstacles, at their MoCap position where the config names a body
        (``obstacle_<i>`` in the tracker's frame), moving at the scenario's velocity."""
        obstacles = list(self.control.obstacles)
        for i, obstacle in enumerate(obstacles):
            pose = frame.poses.get(f"obstacle_{i}")
            if pose is not None:
                elapsed = t - self.control.start_s
                x, y = np.asarray(pose[0][0:2]) - elapsed * np.asarray(obstacle.velocity_m_s)
                obstacles[i] = Obstacle(position_m=(float(x), float(y)),
                                        velocity_m_s=obstacle.velocity_m_s,
                                        radius_m=obstacle.radius_m)
        return obstacles

    def _apply(self, t: float, result: NmpcResult) -> Flags:
        decided_s, truth = self._submitted.pop(result.update, (t, None))
        delay_s = t - decided_s
        self.delays_s.append(delay_s)
        self.next_instant = max(self.next_instant, self._grid_after(t))
        self.stats.busy_s.append(result.wall_s)
        missed = delay_s > self.period_s if self.has_deadline else None
        self.deadline_misses += int(bool(missed))
        if self.recording is not None and result.memory is not None:
            self.recording.warm_start(decided_s, result.update, result.memory)
        if result.plan is None:
            self.solver_failures += 1
            if self.recording is not None:
                self.recording.error(t, f"NMPC update {result.update} raised: {result.error}")
            return True, missed
        plan, decision = result.plan, result.decision
        self.plan, self.plan_start_s = plan, decision.time_s
        self.plans_applied += 1
        self._compare_wrenches = True
        if self.hooks is not None:
            self.hooks.planned(plan)
        # Only a failed solve counts toward the supervisor's rule; a converged plan that starts
        # a few millimetres inside a margin (MoCap noise, the ADMM consensus gap) is a recovery
        # plan, counted and logged (its warnings become /events) but not a failure.
        self.solver_failures += int(not plan.success)
        self.margin_flags += int(plan.start_inside_margin)
        self.relaxed_plans += int(plan.relaxed)
        braking = self.control.plan_taken(t, plan)
        if braking is not None and self.recording is not None:
            self.recording.warning(t, braking)
        if self.recording is not None:
            self.recording.nmpc_update(decision.time_s, result.update, decision.inputs, plan,
                                       decision.frame, decision.payload_estimate, truth)
        return not plan.success, missed

    def _log_wrenches(self, t: float) -> None:
        """The active plan's first-stage wrench against the F/T readings now."""
        plan = self.plan
        readings = self.force_torque.latest() if self.force_torque is not None else {}
        if plan is None:
            return
        for i, name in enumerate(self.names):
            reading = readings.get(name)
            if reading is None:
                continue
            if self.hooks is not None:
                self.hooks.wrench_compared(plan.wrench[i, 0:3], reading.force_n)
            if self.recording is not None:
                self.recording.plan_applied(t, name, plan.wrench[i],
                                            (reading.force_n, reading.torque_nm))
