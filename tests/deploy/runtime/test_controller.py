"""The team controller on its own, from the in-process simulation's measurements: the NMPC
decision while settling and walking, delay compensation's rule, and the WBC ticks."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.reference import BrakingReference
from core.nmpc.settings import BrakingSettings, MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.runtime.controller import SETTLE_S, TeamController
from deploy.runtime.sim_run import SimRun


@pytest.fixture(scope="module")
def run() -> SimRun:
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, CompiledCodeCache())
    yield run
    run.close()


def _read(run: SimRun) -> tuple[list, object]:
    names = run.control.robot_names
    measurements = [run.links.drivers[name].read() for name in names]
    frame = run.simulation.mocap().latest()
    return measurements, frame


def test_decision_holds_the_start_pose_while_settling_then_moves(run: SimRun) -> None:
    control = run.control
    measurements, frame = _read(run)
    control.reset(measurements, start_s=0.0)
    settling = control.nmpc_inputs(0.0, measurements, frame)
    inputs = settling.inputs
    n, agents = control.settings.horizon_steps, len(control.robot_names)
    assert inputs.robot_states.shape == (agents, 12)
    assert inputs.feet_positions.shape == (agents, n, 4, 3)
    assert np.all(inputs.contacts == 1.0)  # every foot down
    assert not inputs.payload_reference[:, 3:6].any()  # the reference stands still
    assert inputs.obstacles.shape == (len(control.obstacles), 5)
    walking = control.nmpc_inputs(SETTLE_S + 0.5, measurements, frame).inputs
    assert walking.payload_reference[:, 3:6].any()
    assert (walking.contacts == 0.0).any()  # the trot lifts feet over the horizon
    # without an active plan there is nothing to predict from: no compensation
    delayed = control.nmpc_inputs(SETTLE_S + 0.5, measurements, frame, delay_s=0.03)
    assert delayed.time_s == SETTLE_S + 0.5
    np.testing.assert_array_equal(delayed.inputs.robot_states, walking.robot_states)


def test_compensation_is_the_median_of_the_last_ten_delays(run: SimRun) -> None:
    control = run.control
    assert control.compensation_s([]) == 0.0
    assert control.compensation_s([1.0] * 5 + [0.02, 0.03, 0.04] * 4) == pytest.approx(0.03)


def test_the_measured_delay_imports_nothing_on_the_loops_first_use() -> None:
    """The first measured delay came with np.median's import of numpy.ma (~20 ms in one
    tick: past the watchdog's timeout). In a fresh interpreter no module loads on first use."""
    script = (
        "import sys, types\n"
        "from deploy.runtime.controller import TeamController\n"
        "before = set(sys.modules)\n"
        "setting = types.SimpleNamespace(delay_compensation_s='measured')\n"
        "me = types.SimpleNamespace(scenario=types.SimpleNamespace(controller=setting))\n"
        "assert TeamController.compensation_s(me, [0.01, 0.03, 0.02, 0.05]) == 0.025\n"
        "print(sorted(set(sys.modules) - before))\n")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=120, check=True)
    assert result.stdout.strip() == "[]", result.stdout


def test_one_update_and_wbc_ticks_give_commands_within_the_limits(run: SimRun) -> None:
    control = run.control
    measurements, frame = _read(run)
    control.reset(measurements, start_s=0.0)
    decision = control.nmpc_inputs(0.0, measurements, frame)
    plan = control.update(decision)
    assert plan.success
    steps = control.wbc_steps(0.004, plan, decision.time_s, measurements)
    assert len(steps) == len(control.robot_names)
    for step in steps:
        assert step.output.success and np.all(np.isfinite(step.command.torque_nm))
        assert np.all(step.stance == 1.0)  # settling: all feet in stance
        # the hybrid command: the QP's torque, the firmware PD at the WBC's gains toward the
        # joint targets one tick ahead of the measured joints
        settings = control.robots[0].wbc.settings
        assert np.all(step.command.kp == settings.joint_stiffness_nm_rad) and step.command.kp.any()
        assert np.all(step.command.kd == settings.joint_damping_nm_s)
    for step, m in zip(steps, measurements, strict=True):
        drift = step.command.position_rad - m.position_rad
        assert np.all(np.abs(drift) < 0.05), drift  # one 2 ms tick of motion, not a posture


def _plan(relaxed: bool = False, success: bool = True, slack_m: float = 0.0) -> MpcPlan:
    zeros = np.zeros
    return MpcPlan(grf=zeros((2, 12)), wrench=zeros((2, 6)),
                   robot_trajectories=zeros((2, 9, 12)), payload_trajectory=zeros((9, 12)),
                   grf_trajectories=zeros((2, 8, 12)), wrench_trajectories=zeros((2, 8, 6)),
                   solves=[], success=success, update_time_s=0.0, barrier_slack_m=slack_m,
                   relaxed=relaxed)


@pytest.fixture
def control(run: SimRun) -> TeamController:
    """A fresh controller (no NMPC of its own) reset on the simulation's standing team."""
    control = TeamController(run.scenario, build_mpc=False)
    control.reset(_read(run)[0], start_s=0.0)
    return control


def test_braking_starts_after_enough_infeasible_plans_in_a_row(control: TeamController,
                                                               run: SimRun) -> None:
    needed = control.settings.braking.after_flagged_updates
    measurements, frame = _read(run)
    control.nmpc_inputs(1.0, measurements, frame)  # a payload estimate to brake from
    # a feasible plan in between restarts the count
    for _ in range(needed - 1):
        assert control.plan_taken(1.0, _plan(relaxed=True, slack_m=0.05)) is None
    assert control.plan_taken(1.0, _plan()) is None
    for _ in range(needed - 1):
        assert control.plan_taken(1.1, _plan(success=False)) is None
    assert control.braking_since_s is None
    cause = control.plan_taken(1.2, _plan(relaxed=True, slack_m=0.05))
    assert cause is not None and "braking" in cause and "0.050 m" in cause
    assert control.braking_since_s == 1.2
    assert isinstance(control.reference, BrakingReference)
    # latched: later plans, feasible or not, change nothing
    assert control.plan_taken(1.3, _plan()) is None
    assert control.plan_taken(1.4, _plan(success=False)) is None
    assert control.braking_since_s == 1.2
    # the reference comes to rest within v^2 / 2a of the payload estimate, and holds
    estimate = control.payload_estimate
    assert estimate is not None
    rest = control.reference.goal_m()
    reach = np.linalg.norm(estimate[3:5]) ** 2 / (2 * control.settings.braking.deceleration_m_s2)
    assert np.linalg.norm(rest - estimate[0:2]) <= reach + 1e-9
    late = control.nmpc_inputs(20.0, measurements, frame).inputs
    assert not late.payload_reference[:, 3:6].any()


def test_braking_can_be_switched_off(run: SimRun) -> None:
    control = TeamController(run.scenario, build_mpc=False,
                             base_settings=MpcSettings(braking=BrakingSettings(enabled=False)))
    for _ in range(10):
        assert control.plan_taken(1.0, _plan(success=False)) is None
    assert control.braking_since_s is None


def test_reference_waits_for_a_team_that_lags_behind(control: TeamController,
                                                     run: SimRun) -> None:
    """The team stands still at the start: the reference runs ahead until it leads by
    ``max_lag_m`` along the path, then its clock stops."""
    max_lag_m = run.scenario.reference.max_lag_m
    assert max_lag_m is not None
    measurements, frame = _read(run)
    period = control.settings.sample_period_s
    times = np.arange(0.0, 6.0, period)
    leads = []
    for t in times:
        control.nmpc_inputs(float(t), measurements, frame)
        estimate = control.payload_estimate
        assert estimate is not None
        desired = control.reference.payload_state(control.reference_time(float(t)))
        leads.append(desired[0] - estimate[0])
    speed = run.scenario.reference.speed_m_s
    assert max(leads) <= max_lag_m + speed * period + 1e-9
    assert leads[-1] > max_lag_m - speed * period  # it held there, not further back
    assert control.reference_held_s > 4.0
    # a team that keeps up is never held: with the governor off the lead grows unbounded
    free = TeamController(run.scenario.model_copy(update={"reference": run.scenario.reference
                                                          .model_copy(update={"max_lag_m": None})}),
                          build_mpc=False)
    free.reset(measurements, start_s=0.0)
    for t in times:
        free.nmpc_inputs(float(t), measurements, frame)
    assert free.reference_held_s == 0.0


@pytest.mark.parametrize("blocked_stop_s", [2.0, None])
def test_a_team_held_back_too_long_brakes(run: SimRun, blocked_stop_s: float | None) -> None:
    """A team that stands still (blocked) is held by the reference governor; after
    ``braking.blocked_stop_s`` of holding without a break it brakes (and so sits down), not
    before; with the rule off (None) it waits for ever."""
    settings = MpcSettings(braking=BrakingSettings(blocked_stop_s=blocked_stop_s))
    control = TeamController(run.scenario, build_mpc=False, base_settings=settings)
    measurements, frame = _read(run)
    control.reset(measurements, start_s=0.0)
    period = control.settings.sample_period_s
    causes = []
    for t in np.arange(0.0, 12.0, period):
        control.nmpc_inputs(float(t), measurements, frame)
        cause = control.plan_taken(float(t), _plan())
        if cause is not None:
            causes.append((float(t), cause))
    if blocked_stop_s is None:
        assert causes == [] and control.braking_since_s is None
        assert control.held_since_s is not None and control.reference_held_s > 5.0
        return
    (t_brake, cause), = causes
    assert "no progress" in cause and "blocked" in cause
    assert control.braking_since_s == t_brake
    assert isinstance(control.reference, BrakingReference)
    # it held from when the reference led by max_lag_m; braking blocked_stop_s later
    max_lag_m = run.scenario.reference.max_lag_m
    assert max_lag_m is not None
    held_from = SETTLE_S + max_lag_m / run.scenario.reference.speed_m_s
    assert t_brake == pytest.approx(held_from + blocked_stop_s, abs=3 * period)
    assert control.held_since_s is None  # braking: the governor is off


def test_a_break_in_the_hold_restarts_the_blocked_clock(control: TeamController,
                                                        run: SimRun) -> None:
    measurements, frame = _read(run)
    period = control.settings.sample_period_s
    for t in np.arange(0.0, 6.0, period):
        control.nmpc_inputs(float(t), measurements, frame)
    held_since = control.held_since_s
    assert held_since is not None
    # the team catches up (the estimate jumps to the reference): the hold ends
    control.reference_held_s = 1e3  # the reference clock back at its start: no lag
    control.nmpc_inputs(6.0, measurements, frame)
    assert control.held_since_s is None and not control.reference_holding
