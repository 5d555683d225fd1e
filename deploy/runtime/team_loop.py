"""The team in physics: NMPC at 60 Hz, WBC at 500 Hz, MuJoCo at 1 kHz, in lockstep.

Deterministic: simulated time advances only when the loop steps it, so the same scenario and
seed give the same trajectory whatever the machine's speed (timing metrics aside). The loop
talks to the robots and the MoCap only through ``drivers.interfaces`` (``RobotDriver``,
``MocapSource``); ground truth is read from the simulation for the metrics only.

Per WBC tick (2 ms): at every NMPC instant (t >= next multiple of Ts) the NMPC inputs are built
from *measured* data -- robot poses from MoCap, velocities from the robots' own state
estimates, the payload state from ``PayloadEstimator`` -- and the controller plans; then each
robot's WBC tracks the active plan. With ``controller.model_computation_delay`` a new plan
becomes active only after its measured update time has passed in simulated time (the old one
is used meanwhile), and no update starts while one is computing (the instants it covered are
skipped), as on robots; the NMPC then plans from the state predicted to the instant its plan
takes effect (``controller.delay_compensation_s``, ``core.nmpc.delay_compensation``). The control
logic itself (NMPC inputs, WBC ticks) is ``deploy.runtime.controller``'s, shared with
``porter deploy``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from core.locomotion.settings import WbcSettings
from core.locomotion.whole_body_control import FloatingBaseState
from core.model.conventions import PAYLOAD_NAME
from core.model.rotations import euler_from_rotation, rotation_from_quaternion_wxyz
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.settings import MpcSettings
from deploy.config.scenario import Scenario
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.loop_recording import LoopRecording
from deploy.recording.messages.porter_log_pb2 import GroundTruth
from deploy.runtime.codegen_cache import CompiledCodeCache
from deploy.runtime.controller import (
    SETTLE_S,
    RobotControl,
    TeamController,
    measurement_state,
    mocap_state,
)
from deploy.runtime.run_metrics import FALL_HEIGHT_FRACTION, MAX_TILT_RAD, RunMetrics
from drivers.interfaces import RobotDriver, RobotMeasurement
from drivers.mujoco.scene import PHYSICS_TIMESTEP_S, build_team_scene
from drivers.mujoco.simulation import TeamSimulation

__all__ = ["SETTLE_S", "TeamLoop", "measurement_state", "mocap_state", "summary_line"]

WBC_DECIMATION = 2  # physics steps per WBC tick: 500 Hz

Progress = Callable[[float, float, float], None]  # (sim time, duration, wall time) [s]


@dataclass
class _Robot:
    control: RobotControl
    driver: RobotDriver

    @property
    def name(self) -> str:
        return self.control.name


class TeamLoop:
    """One scenario in MuJoCo: build once with ``TeamLoop(scenario)``, then ``run()``."""

    def __init__(self, scenario: Scenario, cache: CompiledCodeCache | None = None,
                 base_settings: MpcSettings | None = None,
                 wbc_settings: WbcSettings | None = None) -> None:
        self.scenario = scenario
        self.control = TeamController(scenario, cache, base_settings, wbc_settings,
                                      tick_s=WBC_DECIMATION * PHYSICS_TIMESTEP_S)
        self.wbc_settings = self.control.wbc_settings
        self.settings = self.control.settings
        self.team = self.control.team
        self.reference = self.control.reference
        self.obstacles = self.control.obstacles
        self.controller = self.control.controller
        scene = build_team_scene(
            scenario.team_settings(), payload_true_mass_kg=scenario.true_payload_mass_kg,
            obstacles=[(*o.position_m, o.radius_m, o.height_m) for o in scenario.obstacles],
            timestep_s=PHYSICS_TIMESTEP_S, payload_height_m=scenario.reference.payload_height_m)
        noise = scenario.disturbances
        self.simulation = TeamSimulation(scene, seed=scenario.seed,
                                         mocap_position_noise_m=noise.mocap_position_noise_m,
                                         mocap_angle_noise_rad=noise.mocap_angle_noise_rad)
        self.mocap = self.simulation.mocap()
        self.robots = [_Robot(control, self.simulation.robot_driver(control.name))
                       for control in self.control.robots]
        self.metrics = RunMetrics(scenario.name, self.reference.goal_m(),
                                  scenario.goal_tolerance_m, self._pair_names())
        self._updates = 0
        self.recording: LoopRecording | None = None

    def attach_recorder(self, recorder: FlightRecorder) -> None:
        """Record the run to ``recorder`` (what and when: ``deploy.recording.loop_recording``)."""
        self.recording = LoopRecording(
            recorder, [r.name for r in self.robots], self.obstacles,
            [o.height_m for o in self.scenario.obstacles],
            self.settings.safety.safety_distance_m, self.settings.sample_period_s,
            np.asarray(self.scenario.payload.size_m))

    def _pair_names(self) -> list[str]:
        bodies = [PAYLOAD_NAME] + [r.name for r in self.robots]
        return [f"{body}|obstacle_{j}" for body in bodies for j in range(len(self.obstacles))]

    def close(self) -> None:
        self.control.close()

    # --- the loop ------------------------------------------------------------------------
    def run(self, progress: Progress | None = None,
            stop: Callable[[], bool] | None = None) -> dict:
        """Simulate the scenario to its end, a fall, or until ``stop()`` is true (checked every
        tick); returns the summary dict."""
        sim = self.simulation
        ts = self.settings.sample_period_s
        tick_s = WBC_DECIMATION * PHYSICS_TIMESTEP_S
        total_ticks = int(round(self.scenario.duration_s / tick_s))
        pushes = sorted(self.scenario.disturbances.pushes, key=lambda p: p.time_s)
        delay = self.scenario.controller.model_computation_delay
        self.control.reset([r.driver.read() for r in self.robots])
        plan: MpcPlan | None = None
        # (takes effect at, plan, its stage-0 time, decision time)
        pending: tuple[float, MpcPlan, float, float] | None = None
        plan_start_s = 0.0
        next_update = 0
        delays_s: list[float] = []  # from each applied plan's decision to its taking effect
        recording = self.recording
        if recording is not None:
            recording.start(sim.time_s, f"start: scenario {self.scenario.name}, "
                            f"{self.scenario.controller.mode} NMPC, seed {self.scenario.seed}")
        start = time.perf_counter()
        tick_start = time.perf_counter()
        for tick in range(total_ticks):
            if tick:
                now = time.perf_counter()
                self.metrics.loop_tick_ms.append(1e3 * (now - tick_start))
                tick_start = now
            t = sim.time_s
            if stop is not None and stop():
                self.metrics.stopped_early = True
                if recording is not None:
                    recording.event(t, "stop requested: run ended early", level=1)
                break
            while pushes and pushes[0].time_s <= t + 1e-9:
                push = pushes.pop(0)
                sim.apply_push(push.target, np.asarray(push.force_n), push.duration_s)
                if recording is not None:
                    recording.event(t, f"push on {push.target}: {list(push.force_n)} N for "
                                    f"{push.duration_s} s")
            measurements = [r.driver.read() for r in self.robots]
            applied = False  # a new plan takes effect this tick
            # One NMPC at a time, as on the robots: with the computation delay modelled, no
            # update starts while the previous one is still computing; the instants it covered
            # are skipped (the next one is the first grid instant after it took effect).
            if t >= next_update * ts - 1e-9 and pending is None:
                compensation = self.control.compensation_s(delays_s) if delay else 0.0
                active = None if plan is None else (plan, plan_start_s)
                new_plan, stage0_s = self._nmpc_update(t, measurements, compensation, active)
                next_update = int(np.floor(t / ts + 1e-6)) + 1
                if delay and plan is not None:
                    fixed = self.scenario.controller.computation_delay_s
                    took_s = new_plan.update_time_s if fixed is None else fixed
                    pending = (t + took_s, new_plan, stage0_s, t)
                else:
                    plan, plan_start_s, applied = new_plan, stage0_s, True
            if pending is not None and t >= pending[0]:
                delays_s.append(t - pending[3])
                next_update = max(next_update, int(np.floor(t / ts + 1e-6)) + 1)
                plan, plan_start_s = pending[1], pending[2]
                pending, applied = None, True
            if applied:
                self.metrics.plans_applied += 1
            assert plan is not None
            self._wbc_tick(t, plan, plan_start_s, measurements)
            sim.step(WBC_DECIMATION)
            if applied:  # the new plan's first step: its planned wrench vs the coupling's
                for i, robot in enumerate(self.robots):
                    measured = sim.coupling_wrench(robot.name)
                    self.metrics.record_wrench(plan.wrench[i, 0:3], measured[0])
                    if recording is not None:
                        recording.plan_applied(sim.time_s, robot.name, plan.wrench[i], measured)
            if self._record_ground_truth(sim.time_s):
                if recording is not None:
                    recording.event(sim.time_s, "fall: " + ", ".join(sorted(self.metrics.fallen))
                                    + "; run stopped", level=2)
                break
            if progress is not None and (tick + 1) % 50 == 0:
                progress(sim.time_s, self.scenario.duration_s, time.perf_counter() - start)
        self.metrics.wall_s = time.perf_counter() - start
        summary = self.metrics.summary()
        if recording is not None:
            recording.event(sim.time_s, f"end: reached goal {summary['reached_goal']}, "
                            f"falls {summary['falls']}")
        return summary

    def _nmpc_update(self, t: float, measurements: list[RobotMeasurement], delay_s: float,
                     active: tuple[MpcPlan, float] | None) -> tuple[MpcPlan, float]:
        """One NMPC update from the measurements at ``t`` for a plan taking effect at
        ``t + delay_s``; returns the plan and its stage-0 time."""
        frame = self.mocap.latest()
        assert frame is not None
        decision = self.control.nmpc_inputs(t, measurements, frame, delay_s=delay_s,
                                            active=active)
        true_position, true_quaternion = self.simulation.payload_pose()
        self.metrics.record_estimate(decision.payload_estimate, true_position,
                                     euler_from_rotation(rotation_from_quaternion_wxyz(true_quaternion)))
        update = self._updates
        self._updates += 1
        if self.recording is not None:
            self.recording.nmpc_inputs(t, update, decision.inputs, self.controller.memory())
        plan = self.control.update(decision)
        self.metrics.record_plan(plan)
        if self.recording is not None:
            self.recording.nmpc_update(t, update, decision.inputs, plan, frame,
                                       decision.payload_estimate,
                                       (true_position, true_quaternion))
        return plan, decision.time_s

    def _wbc_tick(self, t: float, plan: MpcPlan, plan_start_s: float,
                  measurements: list[RobotMeasurement]) -> None:
        steps = self.control.wbc_steps(t, plan, plan_start_s, measurements)
        for robot, measurement, step in zip(self.robots, measurements, steps, strict=True):
            self.metrics.record_wbc(step.output.solve_time_s, step.output.success)
            robot.driver.send(step.command)
            if self.recording is not None:
                self.recording.wbc_tick(t, robot.name, measurement, step.command, step.output,
                                        step.stance, step.foot_targets_m)

    def _record_ground_truth(self, t: float) -> bool:
        """Metrics from ground truth; True when a robot has fallen (the run stops)."""
        sim = self.simulation
        position, quaternion = sim.payload_pose()
        rotation = rotation_from_quaternion_wxyz(quaternion)
        yaw = float(euler_from_rotation(rotation)[2])
        desired = self.reference.payload_state(self.control.reference_time(t))
        bodies = [position[0:2]]
        fallen = False
        for robot in self.robots:
            base_position, base_quaternion = sim.base_pose(robot.name)
            state = robot.control.wbc.srb_state(FloatingBaseState(
                base_position, base_quaternion, np.zeros(3), np.zeros(3), np.zeros(12),
                np.zeros(12)))
            bodies.append(state[0:2])
            nominal = robot.control.legs.robot.nominal_height_m
            if state[2] < FALL_HEIGHT_FRACTION * nominal or max(abs(state[6]), abs(state[7])) \
                    > MAX_TILT_RAD:
                self.metrics.record_fall(robot.name)
                fallen = True
        h = np.array([[np.linalg.norm(body - o.row(t, 0.0)[0:2]) - self.settings.safety
                       .safety_distance_m - o.radius_m for o in self.obstacles]
                      for body in bodies])
        coupling = np.array([sim.coupling_error_m(robot.name) for robot in self.robots])
        self.metrics.record_ground_truth(t, position[0:2], yaw, desired[0:2], desired[8], h,
                                         coupling)
        if self.recording is not None and self.recording.ground_truth_due(t):
            poses = {PAYLOAD_NAME: (position, quaternion)}
            poses.update({robot.name: sim.base_pose(robot.name) for robot in self.robots})
            self.recording.ground_truth(t, poses, GroundTruth(
                time_s=t, payload_position_in_world_m=position, payload_yaw_rad=yaw,
                desired_payload_position_in_world_m=desired[0:3],
                desired_payload_yaw_rad=desired[8], pair_names=self.recording.pair_names,
                h_m=h.reshape(-1), robot_names=[r.name for r in self.robots],
                coupling_error_m=coupling))
        return fallen


def summary_line(time_s: float, duration_s: float, wall_s: float) -> str:
    """A one-line progress bar: simulated time and real-time factor."""
    width = 30
    done = int(width * min(time_s / duration_s, 1.0)) if duration_s > 0 else width
    factor = time_s / wall_s if wall_s > 0 else math.inf
    return f"[{'#' * done}{'.' * (width - done)}] {time_s:5.1f}/{duration_s:.1f} s  RTF {factor:.2f}"
