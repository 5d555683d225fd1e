"""``porter sim``: one scenario in the in-process MuJoCo world, on the one control loop in
lockstep (``deploy.runtime.loop``, ``deploy.runtime.clock.LockstepClock``).

Deterministic: simulated time advances only when the loop steps it, so the same scenario and
seed give the same trajectory whatever the machine's speed (timing metrics aside). Physics at
1 kHz, the loop at 500 Hz, the NMPC at 60 Hz. The loop talks to the world only through
``drivers.interfaces`` (the simulation's robot drivers, its MoCap at the NMPC rate, its coupling
F/T sensors, a simulated e-stop); the safety supervisor runs as on robots, except that the team
starts standing (PREFLIGHT -> RUNNING at once) and the run ends standing at ``duration_s``. A
fault (a fall, a NaN, a torque beyond its limit, repeated solver failures) ends in SAFE_STOP
and joint damping, as on robots. With ``controller.model_computation_delay`` a plan takes
effect only after its measured (or ``computation_delay_s``) update time has passed in
simulated time (``deploy.nmpc_runtime.nmpc_lockstep``); with a fixed delay and
``controller.overlap_computation`` the NMPC computes in its own process meanwhile (same results).

Ground truth is read from the simulation for the metrics (``deploy.runtime.run_metrics``) and
the log's ``/sim/ground_truth`` only, after every physics tick.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable

import numpy as np

from core.locomotion.settings import WbcSettings
from core.locomotion.whole_body_control import FloatingBaseState
from core.model.conventions import PAYLOAD_NAME
from core.model.rotations import (
    euler_from_rotation,
    rotation_from_quaternion_wxyz,
    yaw_from_quaternion_wxyz,
)
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.settings import MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.deploy_config import PostureConfig, RatesConfig
from deploy.config.scenario import Scenario
from deploy.nmpc_runtime.nmpc_lockstep import LockstepNmpc
from deploy.nmpc_runtime.nmpc_process import NmpcProcess
from deploy.nmpc_runtime.nmpc_schedule import NmpcSchedule
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.loop_recording import LoopRecording
from deploy.runtime.clock import LockstepClock
from deploy.runtime.controller import NmpcDecision, TeamController, WbcStep
from deploy.runtime.links import MocapTracker, TeamLinks
from deploy.runtime.loop import ControlLoop, LoopSettings
from deploy.runtime.run_metrics import (
    FALL_HEIGHT_FRACTION,
    MAX_TILT_RAD,
    RunMetrics,
    run_outcome,
)
from deploy.safety.settings import SupervisorSettings
from drivers.interfaces import RobotDriver
from drivers.mujoco.scene import PHYSICS_TIMESTEP_S, build_team_scene
from drivers.mujoco.sim_links import SimulatedEstop
from drivers.mujoco.simulation import TeamSimulation

__all__ = ["WBC_DECIMATION", "SimRun"]

WBC_DECIMATION = 2  # physics steps per loop tick: 500 Hz
MOCAP_VELOCITY_WINDOW_S = 0.08
# the process executor's spin (``ProcessExecutor``): an update's rounds come ~0.3 ms apart
LOCKSTEP_EXECUTOR_SPIN_S = 0.002


def lockstep_spin_s() -> float:
    """The executor's spin for a lockstep run: ``LOCKSTEP_EXECUTOR_SPIN_S`` where this process
    may use two CPUs or more; 0 where it has one (a spinning caller or worker would take the
    core the other one waits for)."""
    return LOCKSTEP_EXECUTOR_SPIN_S if len(os.sched_getaffinity(0)) > 1 else 0.0

Progress = Callable[[float, float, float], None]  # (sim time, duration, wall time) [s]


class SimRun:
    """One scenario in MuJoCo: build once with ``SimRun(scenario)``, then ``run()``."""

    def __init__(self, scenario: Scenario, cache: CompiledCodeCache | None = None,
                 base_settings: MpcSettings | None = None,
                 wbc_settings: WbcSettings | None = None,
                 supervisor_settings: SupervisorSettings | None = None) -> None:
        self.scenario = scenario
        tick_s = WBC_DECIMATION * PHYSICS_TIMESTEP_S
        # overlapping: the NMPC is built in its own process instead (``run``). In lockstep the
        # ADMM workers' core and this one are the run's own: the executor spins for answers
        self.control = TeamController(scenario, cache, base_settings, wbc_settings, tick_s=tick_s,
                                      build_mpc=not scenario.controller.overlap_computation,
                                      executor_spin_s=lockstep_spin_s())
        self.wbc_settings = self.control.wbc_settings
        self.settings = self.control.settings
        self.obstacles = self.control.obstacles
        # the obstacles as arrays: every body's clearance to every obstacle in one expression
        # per tick (this runs at the WBC rate)
        self._obstacle_start_m = np.array([o.position_m for o in self.obstacles],
                                          dtype=float).reshape(-1, 2)
        self._obstacle_velocity_m_s = np.array([o.velocity_m_s for o in self.obstacles],
                                               dtype=float).reshape(-1, 2)
        self._obstacle_radius_m = np.array([o.radius_m for o in self.obstacles], dtype=float)
        scene = build_team_scene(
            scenario.team_settings(), payload_true_mass_kg=scenario.true_payload_mass_kg,
            obstacles=[(*o.position_m, o.radius_m, o.height_m, *o.velocity_m_s)
                       for o in scenario.obstacles],
            timestep_s=PHYSICS_TIMESTEP_S, payload_height_m=scenario.reference.payload_height_m)
        noise = scenario.disturbances
        self.simulation = TeamSimulation(scene, seed=scenario.seed,
                                         mocap_position_noise_m=noise.mocap_position_noise_m,
                                         mocap_angle_noise_rad=noise.mocap_angle_noise_rad)
        sim = self.simulation
        names = self.control.robot_names
        self.estop = SimulatedEstop()
        now = lambda: sim.time_s  # noqa: E731
        # The MoCap delivers frames at the NMPC rate: each frame draws its noise once, on the
        # NMPC's own grid instants.
        mocap = sim.mocap(rate_hz=1.0 / self.settings.sample_period_s)
        tracker = MocapTracker(mocap, {name: name for name in [*names, PAYLOAD_NAME]},
                               MOCAP_VELOCITY_WINDOW_S, now)
        drivers: dict[str, RobotDriver] = {name: sim.robot_driver(name) for name in names}
        self.links = TeamLinks(drivers, None, tracker, self.estop, sim.wrench_sensors())
        self.metrics = RunMetrics(scenario.name, self.control.reference.goal_m(),
                                  scenario.goal_tolerance_m, self._pair_names())
        self.loop_settings = LoopSettings(
            RatesConfig(wbc_hz=1.0 / tick_s, nmpc_hz=1.0 / self.settings.sample_period_s),
            supervisor_settings or SupervisorSettings(), PostureConfig())
        self.recording: LoopRecording | None = None
        self._pushes = sorted(scenario.disturbances.pushes, key=lambda p: p.time_s)
        self._tick_wall_s: float | None = None
        self.loop: ControlLoop | None = None
        # zero velocities of the ground truth's base states (read-only: shared by every tick)
        self._still = (np.zeros(3), np.zeros(12))
        for zeros in self._still:
            zeros.flags.writeable = False

    def attach_recorder(self, recorder: FlightRecorder) -> None:
        """Record the run to ``recorder`` (what and when: ``deploy.recording.loop_recording``)."""
        self.recording = self.control.loop_recording(recorder)

    def _pair_names(self) -> list[str]:
        bodies = [PAYLOAD_NAME, *self.control.robot_names]
        return [f"{body}|obstacle_{j}" for body in bodies for j in range(len(self.obstacles))]

    def close(self) -> None:
        self.control.close()

    # --- the run -------------------------------------------------------------------------
    def run(self, progress: Progress | None = None, stop: Callable[[], bool] | None = None,
            verbose: bool = True) -> dict:
        """Simulate the scenario to its end, a safe stop, or until ``stop()`` is true (checked
        every tick); returns the summary dict."""
        sim, controller = self.simulation, self.scenario.controller
        process = (NmpcProcess(self.scenario, self.settings, self.control.cache)
                   if controller.overlap_computation else None)
        if process is not None:  # warm starts back only for the log's keyframes
            process.memory_every = (None if self.recording is None
                                    else self.recording.recorder.settings.warm_start_every)
        runner = LockstepNmpc(self.control, lambda: sim.time_s, controller.model_computation_delay,
                              controller.computation_delay_s, process)
        nmpc = NmpcSchedule(self.control, runner, 1.0 / self.settings.sample_period_s,
                            lambda: sim.time_s, self.recording, self.links.force_torque,
                            has_deadline=controller.model_computation_delay, hooks=self,
                            truth=sim.payload_pose)
        start = time.perf_counter()

        def after_step(t: float) -> None:
            self._record_ground_truth(t)
            ticks = int(round(t / (WBC_DECIMATION * PHYSICS_TIMESTEP_S)))
            if progress is not None and ticks % 50 == 0:
                progress(t, self.scenario.duration_s, time.perf_counter() - start)

        clock = LockstepClock(sim, WBC_DECIMATION, after_step)
        loop = self.loop = ControlLoop(
            self.control, self.links, self.loop_settings, clock, nmpc, self.recording,
            stop or (lambda: False), self.scenario.duration_s, sequence="standing", hooks=self,
            verbose=verbose)
        loop.run(f"start: scenario {self.scenario.name}, {controller.mode} NMPC, "
                 f"seed {self.scenario.seed}")
        self.metrics.wall_s = time.perf_counter() - start
        self.metrics.plans_applied = nmpc.plans_applied
        self.metrics.stopped_early = loop.sequence.stopped_early
        summary = self.metrics.summary()
        summary["safety"] = loop.outcome()
        summary["outcome"] = run_outcome(summary)
        summary["expected_outcome"] = self.scenario.expected_outcome
        if self.recording is not None:
            if loop.sequence.stopped_early:
                self.recording.event(sim.time_s, "stop requested: run ended early", level=1)
            self.recording.event(sim.time_s, f"end: reached goal {summary['reached_goal']}, "
                                 f"falls {summary['falls']}")
        return summary

    # --- hooks of the loop and the NMPC schedule ------------------------------------------
    def before_tick(self, t: float) -> None:
        now = time.perf_counter()
        if self._tick_wall_s is not None:
            self.metrics.loop_tick_ms.append(1e3 * (now - self._tick_wall_s))
        self._tick_wall_s = now
        while self._pushes and self._pushes[0].time_s <= t + 1e-9:
            push = self._pushes.pop(0)
            self.simulation.apply_push(push.target, np.asarray(push.force_n), push.duration_s)
            if self.recording is not None:
                self.recording.event(t, f"push on {push.target}: {list(push.force_n)} N for "
                                     f"{push.duration_s} s")

    def wbc_stepped(self, steps: list[WbcStep]) -> None:
        for step in steps:
            self.metrics.record_wbc(step.output.solve_time_s, step.output.success)

    def decided(self, decision: NmpcDecision) -> None:
        true_position, true_quaternion = self.simulation.payload_pose()
        self.metrics.record_estimate(decision.payload_estimate, true_position, euler_from_rotation(
            rotation_from_quaternion_wxyz(true_quaternion)))

    def planned(self, plan: MpcPlan) -> None:
        self.metrics.record_plan(plan)

    def wrench_compared(self, planned_force_n: np.ndarray, measured_force_n: np.ndarray) -> None:
        self.metrics.record_wrench(planned_force_n, measured_force_n)

    def _record_ground_truth(self, t: float) -> None:
        """Metrics (and the log's ground truth) from the simulator's state at ``t``."""
        sim = self.simulation
        position, quaternion = sim.payload_pose()
        yaw = yaw_from_quaternion_wxyz(quaternion)
        desired = self.control.reference.payload_state(self.control.reference_time(t))
        bodies = [position[0:2]]
        sitting = self.loop is not None and self.loop.sequence.controlled_stop
        still3, still12 = self._still
        for robot in self.control.robots:
            base_position, base_quaternion = sim.base_pose(robot.name)
            state = robot.wbc.srb_state(FloatingBaseState(
                base_position, base_quaternion, still3, still3, still12, still12))
            bodies.append(state[0:2])
            nominal = robot.legs.robot.nominal_height_m
            # A controlled stop sits the team down on purpose: then only a tilt is a fall.
            low = state[2] < FALL_HEIGHT_FRACTION * nominal and not sitting
            if low or max(abs(state[6]), abs(state[7])) > MAX_TILT_RAD:
                self.metrics.record_fall(robot.name)
        centers = self._obstacle_start_m + t * self._obstacle_velocity_m_s  # Obstacle.row's
        body_xy_m = np.array(bodies)
        offsets = body_xy_m[:, None, :] - centers[None, :, :]
        h = (np.sqrt(np.einsum("bok,bok->bo", offsets, offsets))
             - self.settings.safety.safety_distance_m - self._obstacle_radius_m)
        coupling = np.array([sim.coupling_error_m(r.name) for r in self.control.robots])
        self.metrics.body_xy_m.append(body_xy_m)
        self.metrics.record_ground_truth(t, position[0:2], yaw, desired[0:2], desired[8], h,
                                         coupling)
        if self.recording is not None and self.recording.ground_truth_due(t):
            poses = {PAYLOAD_NAME: (position, quaternion)}
            poses.update({r.name: sim.base_pose(r.name) for r in self.control.robots})
            self.recording.ground_truth(t, poses, yaw, desired, h, coupling)


