"""The team controller on its own, from the in-process simulation's measurements: the NMPC
decision while settling and walking, delay compensation's rule, and the WBC ticks."""

from __future__ import annotations

import numpy as np
import pytest

from deploy.config.scenario import load_scenario
from deploy.runtime.codegen_cache import CompiledCodeCache
from deploy.runtime.controller import SETTLE_S
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
    walking = control.nmpc_inputs(SETTLE_S + 1.0, measurements, frame).inputs
    assert walking.payload_reference[:, 3:6].any()
    assert (walking.contacts == 0.0).any()  # the trot lifts feet over the horizon
    # without an active plan there is nothing to predict from: no compensation
    delayed = control.nmpc_inputs(SETTLE_S + 1.0, measurements, frame, delay_s=0.03)
    assert delayed.time_s == SETTLE_S + 1.0
    np.testing.assert_array_equal(delayed.inputs.robot_states, walking.robot_states)


def test_compensation_is_the_median_of_the_last_ten_delays(run: SimRun) -> None:
    control = run.control
    assert control.compensation_s([]) == 0.0
    assert control.compensation_s([1.0] * 5 + [0.02, 0.03, 0.04] * 4) == pytest.approx(0.03)


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
        assert not step.command.kp.any() and step.command.kd.any()  # torque + damping only
