"""What the control loop records, at which rate: the bridge from loop data to log messages.

Per WBC tick (500 Hz) and robot: state, joint command, WBC tick. Per NMPC update (60 Hz): the
decision's inputs, a warm-start keyframe every ``warm_start_every`` updates (with the inputs of
every update this makes each decision replayable exactly, see ``deploy.recording.regression``), the
update's outcome and plan, every ADMM iteration, CBF values, MoCap frame, payload estimate,
obstacles, loop timing. When a plan takes effect: measured vs predicted interaction wrench per
robot. Ground truth (``/tf`` and ``/sim/ground_truth``) at ``ground_truth_hz``.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np

from core.locomotion.whole_body_control import WbcOutput
from core.model.conventions import PAYLOAD_NAME
from core.model.obstacles import Obstacle
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.warm_start import ControllerMemory
from deploy.recording import log_format as fmt
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.messages import porter_log_pb2 as pb
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement


class WbcStepRecord(Protocol):
    """What is logged of one robot's WBC tick (``deploy.runtime.controller.WbcStep``)."""

    @property
    def command(self) -> JointCommand: ...
    @property
    def output(self) -> WbcOutput: ...
    @property
    def stance(self) -> np.ndarray: ...
    @property
    def foot_targets_m(self) -> np.ndarray: ...


class LoopRecording:
    """Turns the loop's data into messages for ``recorder`` (which never blocks the loop)."""

    def __init__(self, recorder: FlightRecorder, robot_names: list[str],
                 obstacles: list[Obstacle], obstacle_heights_m: list[float],
                 safety_distance_m: float, sample_period_s: float,
                 payload_size_m: np.ndarray, ground_truth_hz: float = 100.0) -> None:
        self.recorder = recorder
        self.robot_names = robot_names
        self.obstacles = obstacles
        self.obstacle_heights_m = obstacle_heights_m
        self.safety_distance_m = safety_distance_m
        self.sample_period_s = sample_period_s
        self.payload_size_m = payload_size_m
        self.ground_truth_period_s = 1.0 / ground_truth_hz
        self._next_ground_truth_s = 0.0
        self.pair_names = [f"{body}|obstacle_{j}" for body in [PAYLOAD_NAME, *robot_names]
                           for j in range(len(obstacles))]
        self.deadline_misses = 0
        self._writer_failed = False
        self._wbc_times: list[float] = []
        self._topics = {name: {kind: fmt.robot_topic(name, kind)
                               for kind in ("state", "command", "wbc", "wrench")}
                        for name in robot_names}

    def start(self, time_s: float, text: str) -> None:
        self.recorder.log(fmt.OBSTACLES, self._obstacle_scene(time_s), time_s)
        self.recorder.log("/payload/box", fmt.payload_box(time_s, self.payload_size_m), time_s)
        self.recorder.event(time_s, text)

    def event(self, time_s: float, text: str, level: int = pb.Event.INFO) -> None:
        self.recorder.event(time_s, text, level=level)

    def error(self, time_s: float, text: str) -> None:
        self.event(time_s, text, pb.Event.ERROR)

    def writer_failure(self, time_s: float) -> str | None:
        """Once, when the recorder's writer has failed: the cause (also as an ERROR event,
        which reaches the file only if the writer can still write); else None."""
        if self._writer_failed:
            return None
        failure = self.recorder.failure
        if failure is not None:
            self._writer_failed = True
            self.error(time_s, f"flight recorder failed: {failure}")
        return failure

    def warning(self, time_s: float, text: str) -> None:
        self.event(time_s, text, pb.Event.WARNING)

    def transition(self, time_s: float, text: str, fault: bool) -> None:
        """A safety state transition (source ``safety``; a safe stop is an error)."""
        self.recorder.event(time_s, text, source="safety",
                            level=pb.Event.ERROR if fault else pb.Event.INFO)

    def robot_tick(self, time_s: float, robot: str, measurement: RobotMeasurement,
                   command: JointCommand) -> None:
        """A tick without a WBC step (posture moves, damping): state and command only."""
        topics = self._topics[robot]
        self.recorder.log(topics["state"], fmt.robot_state(robot, measurement), time_s)
        self.recorder.log(topics["command"], fmt.joint_command(time_s, robot, command), time_s)

    def team_tick(self, time_s: float, names: list[str],
                  measurements: dict[str, RobotMeasurement], sent: dict[str, JointCommand],
                  steps: Sequence[WbcStepRecord] | None) -> None:
        """One loop tick of every robot that was measured and commanded: its WBC tick where the
        command sent is the WBC's own (``steps`` in ``names`` order), else state and command."""
        for i, name in enumerate(names):
            measurement, command = measurements.get(name), sent.get(name)
            if measurement is None or command is None:
                continue
            if steps is not None and command is steps[i].command:
                step = steps[i]
                self.wbc_tick(time_s, name, measurement, command, step.output, step.stance,
                              step.foot_targets_m)
            else:
                self.robot_tick(time_s, name, measurement, command)

    def wbc_tick(self, time_s: float, robot: str, measurement: RobotMeasurement,
                 command: JointCommand, output: WbcOutput, stance: np.ndarray,
                 foot_targets_m: np.ndarray) -> None:
        topics = self._topics[robot]
        log = self.recorder.log
        log(topics["state"], fmt.robot_state(robot, measurement), time_s)
        log(topics["command"], fmt.joint_command(time_s, robot, command), time_s)
        log(topics["wbc"], pb.WbcTick(
            time_s=time_s, robot=robot, success=output.success, status=str(output.status),
            solve_time_s=output.solve_time_s, stance=fmt.as_list(stance),
            contact_force_in_world_n=fmt.as_list(output.contact_force_n),
            foot_target_in_world_m=fmt.as_list(foot_targets_m)), time_s)
        self._wbc_times.append(output.solve_time_s)

    def nmpc_inputs(self, time_s: float, update: int, inputs: MpcInputs) -> None:
        """Before the update: its inputs."""
        a = fmt.array
        self.recorder.log(fmt.NMPC_INPUTS, pb.NmpcInputs(
            update=update, time_s=time_s, robot_states=a(inputs.robot_states),
            payload_state=a(inputs.payload_state), robot_references=a(inputs.robot_references),
            payload_reference=a(inputs.payload_reference),
            feet_positions=a(inputs.feet_positions), contacts=a(inputs.contacts),
            obstacles=a(inputs.obstacles)), time_s)

    def warm_start(self, time_s: float, update: int, memory: ControllerMemory) -> None:
        """The warm start ``update`` (decided at ``time_s``) started from, when a keyframe is
        due (every ``warm_start_every`` updates). Logged once the update is back, as the NMPC
        may run in another process."""
        if update % self.recorder.settings.warm_start_every == 0:
            self.recorder.log(fmt.NMPC_WARM_START, warm_start_message(time_s, update, memory),
                              time_s)

    def nmpc_update(self, time_s: float, update: int, inputs: MpcInputs, plan: MpcPlan,
                    frame: MocapFrame, payload_estimate: np.ndarray,
                    true_payload_pose: tuple[np.ndarray, np.ndarray] | None) -> None:
        log = self.recorder.log
        missed = plan.update_time_s > self.sample_period_s
        self.deadline_misses += int(missed)
        log(fmt.NMPC_UPDATE, update_message(time_s, update, plan, missed), time_s)
        for r, record in enumerate(plan.admm_iterations):
            log(fmt.ADMM, pb.AdmmIteration(
                update=update, time_s=time_s, iteration=r,
                primal_payload_rms=record.primal_payload_rms,
                primal_wrench_rms=record.primal_wrench_rms, dual_norm=record.dual_norm,
                max_primal_payload_rms=float(np.max(record.primal_payload_rms)),
                max_primal_wrench_rms=float(np.max(record.primal_wrench_rms)),
                primal_position_rms_m=record.primal_position_rms_m,
                primal_force_rms_n=record.primal_force_rms_n), time_s)
        h_now = inputs.safety_values().reshape(-1)
        predicted = self._predicted_min_h(time_s, plan)
        log(fmt.CBF, pb.CbfValues(update=update, time_s=time_s, pair_names=self.pair_names,
                                  h_m=h_now, predicted_min_h_m=predicted,
                                  min_h_m=float(h_now.min()) if h_now.size else 0.0), time_s)
        for topic, message in fmt.mocap_messages(frame).items():
            log(topic, message, time_s)
        estimate = pb.PayloadEstimate(time_s=time_s, estimate=payload_estimate,
                                      has_ground_truth=true_payload_pose is not None)
        if true_payload_pose is not None:
            estimate.true_position_in_world_m.extend(true_payload_pose[0])
            estimate.true_quaternion_wxyz.extend(true_payload_pose[1])
        log(fmt.PAYLOAD_ESTIMATE, estimate, time_s)
        if any(np.any(o.velocity_m_s) for o in self.obstacles):
            log(fmt.OBSTACLES, self._obstacle_scene(time_s), time_s)
        ticks = np.asarray(self._wbc_times or [0.0])
        self._wbc_times.clear()
        log(fmt.LOOP_TIMING, pb.LoopTiming(
            time_s=time_s, nmpc_update_s=plan.update_time_s, nmpc_period_s=self.sample_period_s,
            deadline_missed=missed, deadline_misses=self.deadline_misses,
            wbc_tick_max_s=float(ticks.max()), wbc_tick_mean_s=float(ticks.mean()),
            recorder_dropped=self.recorder.dropped), time_s)
        for warning in plan.warnings:
            self.event(time_s, f"NMPC update {update}: {warning}", pb.Event.WARNING)
        failed = [s for s in plan.solves if not s.success]
        if failed:
            self.event(time_s, f"NMPC update {update}: {len(failed)} solve(s) failed "
                       f"({', '.join(sorted({s.status for s in failed}))})", pb.Event.WARNING)

    def plan_applied(self, time_s: float, robot: str, predicted: np.ndarray,
                     measured: tuple[np.ndarray, np.ndarray]) -> None:
        """``predicted``: the plan's first-stage wrench (6,); ``measured``: (force, torque)."""
        force, torque = measured
        self.recorder.log(self._topics[robot]["wrench"], pb.InteractionWrench(
            time_s=time_s, robot=robot, measured_force_n=force, predicted_force_n=predicted[0:3],
            measured_torque_nm=torque, predicted_torque_nm=predicted[3:6],
            force_error_n=float(np.linalg.norm(predicted[0:3] - force))), time_s)

    def ground_truth_due(self, time_s: float) -> bool:
        if time_s + 1e-9 < self._next_ground_truth_s:
            return False
        self._next_ground_truth_s += self.ground_truth_period_s
        return True

    def ground_truth(self, time_s: float, poses: dict[str, tuple[np.ndarray, np.ndarray]],
                     payload_yaw_rad: float, desired_payload_state: np.ndarray,
                     h_m: np.ndarray, coupling_error_m: np.ndarray) -> None:
        """The simulator's truth: every body's pose (``/tf``), the payload's pose against the
        reference state (12,), h of every (body, obstacle) pair and each coupling's error."""
        self.recorder.log(fmt.TF, fmt.frame_transforms(time_s, poses), time_s)
        self.recorder.log(fmt.GROUND_TRUTH, pb.GroundTruth(
            time_s=time_s, payload_position_in_world_m=poses[PAYLOAD_NAME][0],
            payload_yaw_rad=payload_yaw_rad,
            desired_payload_position_in_world_m=desired_payload_state[0:3],
            desired_payload_yaw_rad=desired_payload_state[8], pair_names=self.pair_names,
            h_m=np.asarray(h_m).reshape(-1), robot_names=self.robot_names,
            coupling_error_m=coupling_error_m), time_s)

    def _obstacle_scene(self, time_s: float) -> object:
        return fmt.obstacle_scene(time_s, self.obstacles, self.safety_distance_m,
                                  self.obstacle_heights_m)

    def _predicted_min_h(self, time_s: float, plan: MpcPlan) -> np.ndarray:
        """Minimum over the predicted stages 1..N of h per (body, obstacle) pair."""
        if not self.obstacles:
            return np.zeros(0)
        n = plan.payload_trajectory.shape[0] - 1
        times = time_s + self.sample_period_s * np.arange(1, n + 1)
        bodies = np.concatenate([plan.payload_trajectory[None, 1:, 0:2],
                                 plan.robot_trajectories[:, 1:, 0:2]])  # (1 + n_A, N, 2)
        rows = np.array([[o.row(t, self.safety_distance_m) for t in times]
                         for o in self.obstacles])  # (n_O, N, 5)
        gaps = bodies[:, None, :, :] - rows[None, :, :, 0:2]
        h = np.linalg.norm(gaps, axis=3) - rows[None, :, :, 4]
        return h.min(axis=2).reshape(-1)


def update_message(time_s: float, update: int, plan: MpcPlan, missed: bool) -> pb.NmpcUpdate:
    a = fmt.array
    solves_per_iteration = max(len(plan.solves) // max(len(plan.admm_iterations), 1), 1)
    message = pb.NmpcUpdate(
        update=update, time_s=time_s, success=plan.success, update_time_s=plan.update_time_s,
        deadline_missed=missed, warnings=plan.warnings, grf=a(plan.grf), wrench=a(plan.wrench),
        robot_trajectories=a(plan.robot_trajectories),
        payload_trajectory=a(plan.payload_trajectory),
        grf_trajectories=a(plan.grf_trajectories),
        wrench_trajectories=a(plan.wrench_trajectories),
        max_solve_time_s=max((s.wall_time_s for s in plan.solves), default=0.0),
        total_iterations=sum(s.iterations for s in plan.solves))
    for k, stats in enumerate(plan.solves):
        message.solves.append(pb.SolveStats(
            agent=k % solves_per_iteration, admm_iteration=k // solves_per_iteration,
            status=stats.status, success=stats.success, iterations=stats.iterations,
            wall_time_s=stats.wall_time_s, objective=stats.objective,
            constraint_violation=stats.constraint_violation))
    return message


def warm_start_message(time_s: float, update: int, memory: ControllerMemory) -> pb.WarmStart:
    a = fmt.array
    message = pb.WarmStart(update=update, time_s=time_s,
                           has_consensus=memory.consensus is not None,
                           consensus=a(memory.consensus), duals=a(memory.duals))
    for agent, solution in enumerate(memory.previous):
        if solution is None:
            message.agents.append(pb.AgentWarmStart(agent=agent, present=False))
        else:
            message.agents.append(pb.AgentWarmStart(
                agent=agent, present=True, decision=a(solution.decision),
                constraint_multipliers=a(solution.constraint_multipliers),
                bound_multipliers=a(solution.bound_multipliers)))
    return message
