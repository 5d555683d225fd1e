"""The deploy loop's side of the NMPC: 60 Hz instants, hand-over to ``deploy.runtime.nmpc_thread``,
pick-up of finished plans, their recording, and NMPC health for the safety supervisor.

``step`` runs in the loop, once per WBC tick while ARMED / RUNNING. At an NMPC instant with the
thread idle it builds the decision from the tick's measurements and MoCap frame and submits it;
the instants stay on the ``1 / nmpc_hz`` grid: an update that overruns skips the instants it
covered (the next one starts at the first grid instant after it finished, no back-to-back
burst). The decision is planned for the instant its plan will take effect (the state predicted
over the recent median update time, ``core.nmpc.delay_compensation``), and a finished update's plan
becomes the active one with stage 0 at that instant. ``step`` returns (solver failed, deadline
missed) on ticks where an update finished, for ``SafetyInputs`` (a plan flagged only for
starting inside a safety margin is no solver failure); the deadline is one NMPC
period of the loop's clock. On each new plan the coupling F/T readings are logged against the
plan's first-stage wrench (``LoopRecording.plan_applied``).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from core.model.obstacles import Obstacle
from core.nmpc.mpc_plan import MpcPlan
from deploy.recording.loop_recording import LoopRecording
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.runtime.controller import TeamController
from deploy.runtime.nmpc_thread import NmpcResult, NmpcThread
from deploy.runtime.timing import PeriodStats
from drivers.can.bus import ForceTorqueSensors
from drivers.interfaces import MocapFrame, RobotMeasurement

Flags = tuple[bool | None, bool | None]


class NmpcSchedule:
    """Owns the NMPC thread; ``plan`` / ``plan_start_s`` is what the WBC tracks."""

    def __init__(self, control: TeamController, nmpc_hz: float, clock: Callable[[], float],
                 recording: LoopRecording | None,
                 force_torque: ForceTorqueSensors | None) -> None:
        self.control, self.clock = control, clock
        self.recording, self.force_torque = recording, force_torque
        self.names = control.robot_names
        self.period_s = 1.0 / nmpc_hz
        self.thread = NmpcThread(control, clock)
        self.stats = PeriodStats(self.period_s)  # busy_s: each update's time, submit to done
        self.plan: MpcPlan | None = None
        self.plan_start_s = 0.0
        self.next_s = 0.0
        self.updates = 0
        self.deadline_misses = 0
        self.solver_failures = 0
        self.margin_flags = 0  # converged plans that start inside a safety margin

    def start(self, t: float) -> None:
        """The first instant is now."""
        self.next_s = t

    def close(self) -> None:
        self.thread.close()

    def step(self, t: float, measurements: dict[str, RobotMeasurement],
             frame: MocapFrame | None) -> Flags:
        flags: Flags = (None, None)
        result = self.thread.take()
        if result is not None:
            flags = self._apply(t, result)
        if (t >= self.next_s and not self.thread.busy and frame is not None
                and all(name in measurements and name in frame.poses for name in self.names)):
            active = None if self.plan is None else (self.plan, self.plan_start_s)
            decision = self.control.nmpc_inputs(t, [measurements[n] for n in self.names], frame,
                                                self.obstacles(t, frame),
                                                delay_s=self.control.compensation_s(self.stats.busy_s),
                                                active=active)
            if self.recording is not None:
                self.recording.nmpc_inputs(t, self.updates, decision.inputs,
                                           self.control.controller.memory())
            self.thread.submit(decision, self.updates)
            self.updates += 1
            self.stats.tick(self.clock())
            while self.next_s <= t:
                self.next_s += self.period_s
        return flags

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
        missed = result.wall_s > self.period_s
        self.deadline_misses += int(missed)
        self.stats.busy_s.append(result.wall_s)
        if result.plan is None:
            self.solver_failures += 1
            if self.recording is not None:
                self.recording.event(t, f"NMPC update {result.update} raised: {result.error}",
                                     pb.Event.ERROR)
            return True, missed
        plan, decision = result.plan, result.decision
        self.plan, self.plan_start_s = plan, decision.time_s
        # Only a failed solve counts toward the supervisor's rule; a converged plan that starts
        # a few millimetres inside a margin (MoCap noise, the ADMM consensus gap) is a recovery
        # plan, counted and logged (its warnings become /events) but not a failure.
        self.solver_failures += int(not plan.success)
        self.margin_flags += int(plan.start_inside_margin)
        if self.recording is not None:
            self.recording.nmpc_update(decision.time_s, result.update, decision.inputs, plan,
                                       decision.frame, decision.payload_estimate, None)
            readings = self.force_torque.latest() if self.force_torque is not None else {}
            for i, name in enumerate(self.names):
                if name in readings:
                    self.recording.plan_applied(t, name, plan.wrench[i],
                                                (readings[name].force_n, readings[name].torque_nm))
        return not plan.success, missed
