"""The team's control logic, run by the one control loop (``deploy.runtime.loop``) in
simulation and on robots: NMPC inputs from measured data, the NMPC, and each robot's WBC tick.

No I/O and no waiting: callers read the drivers and the MoCap, pass the measurements in, and
send the returned joint commands. World frame, SI units; times in seconds on the caller's
clock. ``start_s`` is the time at which the team starts (the run's t = 0): the team stands
still (all feet down, reference held) for ``SETTLE_S`` after it, then the gait and the
reference start.

NMPC inputs (``nmpc_inputs``): robot SRB states from the MoCap pose and the robot's own twist
and joints, the payload state from ``PayloadEstimator`` (never ground truth), references,
trot contact schedule and Raibert footholds, obstacles at the current time.
WBC (``wbc_steps``): the plan interpolated at the tick's time, gait stance flags and swing-foot
targets, the QP's torques sent as the hybrid command ``tau + kp (q* - q) + kd (dq* - dq)``,
q* and dq* integrated one tick ahead from the QP's accelerations (``hybrid_command``).
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass, field

import numpy as np

from core.admm.admm_executor import LocalSolverSpec
from core.admm.admm_mpc import DistributedMpc
from core.admm.admm_peer_mpc import PeerDistributedMpc
from core.estimation.payload_estimator import PayloadEstimator
from core.locomotion.gait import TrotGait
from core.locomotion.plan_tracking import LegCoordinator, wbc_target
from core.locomotion.settings import WbcSettings
from core.locomotion.whole_body_control import WbcOutput, WholeBodyController
from core.model.obstacles import Obstacle
from core.model.team import TeamModel
from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.delay_compensation import predict_states
from core.nmpc.inputs_builder import build_mpc_inputs
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.reference import BrakingReference, WaypointReference
from core.nmpc.settings import MpcSettings
from core.nmpc.team_mpc import TeamMpc
from deploy.agents.zenoh_executor import ZenohExecutor
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import Scenario
from deploy.nmpc_runtime.process_executor import ProcessExecutor
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.loop_recording import LoopRecording
from deploy.runtime.state_pipeline import mocap_state, wbc_state
from deploy.safety.run_sequence import Braking
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement
from drivers.robot_descriptions import (
    FOOT_RADIUS_M,
    load_pinocchio_model,
    srb_parameters,
    standing_configuration,
)

SETTLE_S = 0.3  # standing (all feet down) before the gait starts and the reference moves
WBC_TICK_S = 0.002  # 500 Hz


@dataclass
class RobotControl:
    """One robot's controller parts: its WBC and its gait bookkeeping."""

    name: str
    robot_type: str
    wbc: WholeBodyController
    legs: LegCoordinator
    joint_damping: np.ndarray = field(init=False)  # (12,) kd [N m s/rad] sent with the torques
    joint_stiffness: np.ndarray = field(init=False)  # (12,) kp [N m/rad] sent with the torques

    def __post_init__(self) -> None:
        self.joint_damping = np.full(12, self.wbc.settings.joint_damping_nm_s)
        self.joint_stiffness = np.full(12, self.wbc.settings.joint_stiffness_nm_rad)


@dataclass(frozen=True)
class NmpcDecision:
    """What one NMPC update starts from: its inputs, the MoCap frame and payload estimate
    (12,) they were built from, at ``time_s``."""

    time_s: float
    inputs: MpcInputs
    frame: MocapFrame
    payload_estimate: np.ndarray


@dataclass(frozen=True)
class WbcStep:
    """One robot's WBC tick: the joint command to send, the QP output, the gait's stance
    flags (4,) and the foot position targets [m] (4, 3), world frame."""

    command: JointCommand
    output: WbcOutput
    stance: np.ndarray
    foot_targets_m: np.ndarray


def build_team_mpc(scenario: Scenario, settings: MpcSettings, cache: CompiledCodeCache,
                   solve_first_here: bool = True, executor_spin_s: float = 0.0
                   ) -> TeamMpc:
    """The scenario's NMPC (centralized, or ADMM with the scenario's executor) on ``settings``
    (``Scenario.mpc_settings``), its solvers built from ``cache``. ``solve_first_here``: with
    the process executor, the first agent's solve runs in this process (False where this
    interpreter also runs the 500 Hz loop); ``executor_spin_s``: its ``spin_s``."""
    team = TeamModel.from_settings(scenario.team_settings(), srb_parameters)
    if scenario.controller.mode == "centralized":
        return CentralizedMpc(team, settings, compiler=cache)
    spec = LocalSolverSpec(settings, team.agent_count, cache)
    network = scenario.controller.network
    if scenario.controller.executor == "zenoh":
        agents = ZenohExecutor(spec, network, scenario.name)
        if network.topology == "peer":  # the agents run the iterations among themselves
            return PeerDistributedMpc(team, settings, agents)
        return DistributedMpc(team, settings, executor=agents)
    executor = (ProcessExecutor(spec, solve_first_here=solve_first_here, spin_s=executor_spin_s)
                if scenario.controller.executor == "process" else None)
    return DistributedMpc(team, settings, executor=executor, compiler=cache)


def hybrid_command(output: WbcOutput, measurement: RobotMeasurement, tick_s: float,
                   kp: np.ndarray, kd: np.ndarray) -> JointCommand:
    """The hybrid joint command of a WBC tick: the QP's torque as feed-forward, and the joint
    position and velocity its accelerations integrate to one tick (``tick_s``) ahead of the
    measured joints as the motor PD's targets (``kp`` [N m/rad], ``kd`` [N m s/rad], (12,)).
    Applied on time, the PD terms are small; applied late, they hold the leg near where it was
    planned to be instead of integrating an old torque."""
    acceleration = output.joint_acceleration_rad_s2
    velocity = measurement.velocity_rad_s + acceleration * tick_s
    position = (measurement.position_rad
                + (measurement.velocity_rad_s + 0.5 * tick_s * acceleration) * tick_s)
    return JointCommand(torque_nm=output.torque_nm, position_rad=position,
                        velocity_rad_s=velocity, kp=kp, kd=kd)


class TeamController:
    """Build once per run from a scenario; ``reset`` at the standing start, then call
    ``nmpc_inputs`` + ``controller.update`` at NMPC instants and ``wbc_steps`` every tick.

    ``controller.update`` may run in another thread than the rest, provided the caller never
    builds inputs or reads ``controller.memory()`` while an update is in flight.
    """

    def __init__(self, scenario: Scenario, cache: CompiledCodeCache | None = None,
                 base_settings: MpcSettings | None = None,
                 wbc_settings: WbcSettings | None = None, tick_s: float = WBC_TICK_S,
                 build_mpc: bool = True, nmpc_shares_loop: bool = False,
                 executor_spin_s: float = 0.0) -> None:
        self.scenario = scenario
        self.tick_s = tick_s
        self.start_s = 0.0
        self.wbc_settings = wbc_settings or WbcSettings()
        self.settings = scenario.mpc_settings(base_settings or MpcSettings())
        team_settings = scenario.team_settings()
        self.team = TeamModel.from_settings(team_settings, srb_parameters)
        self.reference: WaypointReference | BrakingReference = scenario.reference.to_reference()
        self.braking: Braking | None = None  # the braking backup took over (latched)
        self.reference_held_s = 0.0  # reference-clock time the governor held back
        self.reference_holding = False  # the governor holds the reference at this decision
        self.held_since_s: float | None = None  # the governor has held without a break since
        self._last_decision_s: float | None = None
        self._flagged_in_row = 0
        self.obstacles = scenario.core_obstacles()
        gait = TrotGait(scenario.gait.period_s, scenario.gait.duty_factor)
        self.cache = cache or CompiledCodeCache()
        self.robots: list[RobotControl] = []
        for agent, parameters in zip(team_settings.agents, self.team.robots, strict=True):
            model = load_pinocchio_model(agent.robot_type)
            wbc = WholeBodyController(model, standing_configuration(agent.robot_type, model),
                                      np.asarray(agent.coupling_point_in_robot_m),
                                      FOOT_RADIUS_M[agent.robot_type], self.wbc_settings,
                                      self.cache)
            legs = LegCoordinator(parameters, gait, scenario.gait.swing_height_m,
                                  compiler=self.cache)
            self.robots.append(RobotControl(agent.name, agent.robot_type, wbc, legs))
        self.estimator = PayloadEstimator(self.team)
        # An NMPC thread beside the loop must leave every solve to worker processes.
        self._controller = (build_team_mpc(scenario, self.settings, self.cache,
                                           solve_first_here=not nmpc_shares_loop,
                                           executor_spin_s=executor_spin_s)
                            if build_mpc else None)
        self.payload_estimate: np.ndarray | None = None

    @property
    def controller(self) -> TeamMpc:
        """The NMPC of this process (``build_mpc`` True; else it runs elsewhere)."""
        if self._controller is None:
            raise RuntimeError("this TeamController was built without its NMPC "
                               "(build_mpc=False: the NMPC runs in another process)")
        return self._controller

    @property
    def robot_names(self) -> list[str]:
        return [robot.name for robot in self.robots]

    def loop_recording(self, recorder: FlightRecorder) -> LoopRecording:
        """What the control loop records of this team to ``recorder``."""
        scenario = self.scenario
        return LoopRecording(recorder, self.robot_names, self.obstacles,
                             [o.height_m for o in scenario.obstacles],
                             self.settings.safety.safety_distance_m,
                             self.settings.sample_period_s, np.asarray(scenario.payload.size_m))

    def close(self) -> None:
        """Stop the ADMM worker processes or agents (if any)."""
        if self._controller is not None:
            self._controller.close()

    def reset(self, measurements: list[RobotMeasurement], start_s: float = 0.0) -> None:
        """Standing start at ``start_s``: every leg in stance at its measured foot position."""
        self.start_s = start_s
        self.reference_held_s, self._last_decision_s = 0.0, None
        self.reference_holding, self.held_since_s = False, None
        for robot, measurement in zip(self.robots, measurements, strict=True):
            state = wbc_state(measurement)
            robot.legs.reset(robot.wbc.srb_state(state), robot.wbc.foot_positions(state))

    def gait_time(self, t: float) -> float | None:
        """Gait clock: None while settling (all feet down), then time since the gait started."""
        elapsed = t - self.start_s
        return None if elapsed < SETTLE_S else elapsed - SETTLE_S

    def reference_time(self, t: float) -> float:
        """The reference's clock at ``t``: time since the gait started, less what the reference
        governor held back (``scenario.reference.max_lag_m``)."""
        return max(t - self.start_s - SETTLE_S - self.reference_held_s, 0.0)

    def _govern_reference(self, t: float, payload: np.ndarray) -> None:
        """At a decision at ``t``: if the payload estimate lags the reference by more than
        ``max_lag_m`` along the reference's direction of travel, the time since the previous
        decision is held back (the reference waits for the team: an obstacle in the way, a
        push, a heavy payload) and the reference stands still until the next decision (zero
        reference velocities for the NMPC and the footholds). A sideways detour around an
        obstacle is no lag."""
        max_lag_m = self.scenario.reference.max_lag_m
        previous, self._last_decision_s = self._last_decision_s, t
        self.reference_holding = False
        if max_lag_m is None or previous is None or self.braking is not None:
            self.held_since_s = None
            return
        desired = self.reference.payload_state(self.reference_time(t))
        speed = float(np.linalg.norm(desired[3:5]))
        lag_m = (float(np.dot(desired[0:2] - payload[0:2], desired[3:5])) / speed
                 if speed > 0.0 else 0.0)
        if lag_m > max_lag_m:
            self.reference_held_s += max(t - previous, 0.0)
            self.reference_holding = True
            if self.held_since_s is None:
                self.held_since_s = previous
        else:
            self.held_since_s = None

    # --- NMPC ----------------------------------------------------------------------------
    def nmpc_inputs(self, t: float, measurements: list[RobotMeasurement], frame: MocapFrame,
                    obstacles: list[Obstacle] | None = None, delay_s: float = 0.0,
                    active: tuple[MpcPlan, float] | None = None) -> NmpcDecision:
        """The NMPC's inputs from ``frame`` (robot poses) and the robots' own measurements at
        ``t``, for a plan that takes effect at ``t + delay_s``: with ``delay_s`` > 0 and an
        ``active`` (plan, its stage-0 time), the measured states are predicted to that instant
        (``core.nmpc.delay_compensation``) and references, gait and obstacles (default: the
        scenario's) are taken there; the decision's ``time_s`` is ``t + delay_s``. Updates
        the payload estimate (from the measurement)."""
        settings = self.settings
        n, ts = settings.horizon_steps, settings.sample_period_s
        robot_states = np.array([
            robot.wbc.srb_state(mocap_state(m, frame, robot.name))
            for robot, m in zip(self.robots, measurements, strict=True)])
        payload = self.estimator.estimate(robot_states, self.payload_estimate)
        self.payload_estimate = payload
        self._govern_reference(t, payload)
        if delay_s > 0.0 and active is not None:
            plan, plan_start_s = active
            robot_states, payload = predict_states(plan, t - plan_start_s, delay_s,
                                                   robot_states, payload, ts)
        else:
            delay_s = 0.0
        t = t + delay_s
        gait_time = self.gait_time(t)

        def foot_horizon(i: int, state: np.ndarray, refs: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray]:
            planner = self.robots[i].legs.planner
            if gait_time is None:  # settling: every foot stays down where it is
                return np.repeat(planner.feet_in_world_m[None], n, axis=0), np.ones((n, 4))
            return planner.horizon(gait_time, n, ts, state, refs)

        inputs = build_mpc_inputs(
            self.team, self.reference, settings, robot_states, payload, self.reference_time(t),
            foot_horizon, self.obstacles if obstacles is None else obstacles, t - self.start_s,
            hold_pose=t - self.start_s < SETTLE_S, stand_still=self.reference_holding)
        return NmpcDecision(t, inputs, frame, self.payload_estimate)

    def plan_taken(self, t: float, plan: MpcPlan) -> str | None:
        """Count ``plan`` (taken at ``t``) toward the braking rules (``MpcSettings.braking``):
        the cause text when this plan starts the braking backup (infeasible plans in a row, or
        a team held back by the reference governor for ``blocked_stop_s``), else None."""
        settings = self.settings.braking
        infeasible = plan.relaxed or not plan.success
        self._flagged_in_row = self._flagged_in_row + 1 if infeasible else 0
        if not settings.enabled or self.braking is not None:
            return None
        held_since_s = self.held_since_s
        if (settings.blocked_stop_s is not None and held_since_s is not None
                and t - held_since_s >= settings.blocked_stop_s):
            return self.begin_braking(t, (
                f"braking: no progress for {t - held_since_s:.1f} s (the reference held "
                f"since {held_since_s:.3f} s: the team is blocked); it holds and sits down"))
        if self._flagged_in_row < settings.after_flagged_updates:
            return None
        what = f"barrier slack {plan.barrier_slack_m:.3f} m" if plan.relaxed else "failed solve"
        return self.begin_braking(t, (
            f"braking: {self._flagged_in_row} infeasible NMPC plans in a row (last: {what}); "
            f"the team decelerates at {settings.deceleration_m_s2} m/s^2 and holds"))

    @property
    def braking_since_s(self) -> float | None:
        """When the braking backup took over [s, loop time] (None: it has not)."""
        return None if self.braking is None else self.braking.since_s

    def begin_braking(self, t: float, cause: str = "braking: requested") -> str:
        """From now on the payload reference brakes from the latest payload estimate along its
        velocity, then holds (``BrakingReference``); latched. Returns ``cause``."""
        payload = self.payload_estimate
        if payload is None:
            payload = self.reference.payload_state(self.reference_time(t))
        self.reference = BrakingReference(
            start_time_s=self.reference_time(t), position_m=payload[0:2].copy(),
            velocity_m_s=payload[3:5].copy(),
            height_m=float(self.reference.payload_state(self.reference_time(t))[2]),
            yaw_rad=float(payload[8]), deceleration_m_s2=self.settings.braking.deceleration_m_s2)
        self.braking = Braking(t, cause)
        return cause

    def compensation_s(self, recent_delays_s: list[float]) -> float:
        """The delay the next plan is planned for (``controller.delay_compensation_s``): the
        setting, or the median of the last 10 measured delays (0 before the first)."""
        setting = self.scenario.controller.delay_compensation_s
        if setting != "measured":
            return float(setting)
        recent = recent_delays_s[-10:]
        # statistics, not NumPy: np.median's first call imports numpy.ma (~20 ms), which on
        # the loop's first measured delay stalled a tick past the watchdog's timeout
        return float(statistics.median(recent)) if recent else 0.0

    def update(self, decision: NmpcDecision) -> MpcPlan:
        """Run the NMPC on ``decision``'s inputs (the slow part: may run in another thread)."""
        return self.controller.update(decision.inputs)

    # --- WBC -----------------------------------------------------------------------------
    def wbc_steps(self, t: float, plan: MpcPlan, plan_start_s: float,
                  measurements: list[RobotMeasurement]) -> list[WbcStep]:
        """Each robot's WBC tick at ``t`` tracking ``plan`` (whose stage 0 is at
        ``plan_start_s``), from the robots' own measurements."""
        ts = self.settings.sample_period_s
        gait_time = self.gait_time(t)
        reference = self.reference.payload_state(self.reference_time(t))
        if self.reference_holding:  # the governor holds: footholds for standing still
            reference[3:6] = 0.0
        steps = []
        for i, (robot, measurement) in enumerate(zip(self.robots, measurements, strict=True)):
            state = wbc_state(measurement)
            srb, feet_now = robot.wbc.observe(state)
            if gait_time is None:
                stance = np.ones(4)
                feet = (robot.legs.planner.feet_in_world_m.copy(), np.zeros((4, 3)),
                        np.zeros((4, 3)))
            else:
                stance = robot.legs.advance(gait_time, srb, reference, feet_now)
                feet = robot.legs.swing_targets(gait_time, srb, reference[3:6])
            target = wbc_target(plan, i, t - plan_start_s, ts, stance, feet)
            output = robot.wbc.compute(state, target)
            command = hybrid_command(output, measurement, self.tick_s, robot.joint_stiffness,
                                     robot.joint_damping)
            steps.append(WbcStep(command, output, stance, feet[0]))
        return steps
