"""The supervisor's budgets: consecutive NMPC solver and WBC failures, a robot's stale state,
control-loop and NMPC deadline overruns within their window; each trips into the latched
damping stop exactly past its budget."""

from __future__ import annotations

import pytest

from deploy.safety.settings import SupervisorSettings
from tests.deploy.safety.test_supervisor import (
    SETTINGS,
    TICK_S,
    S,
    _assert_latched_damping,
    _inputs,
    _supervisor_in,
)


def test_consecutive_solver_failures_trip_and_a_success_resets(limits, standing):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    failures = [True, True, True, False, True, True, True, False] * 3 + [True] * 4
    for update, failed in enumerate(failures):
        for tick in range(10):  # an NMPC update finishes every 10th tick
            time_s += TICK_S
            inputs = _inputs(time_s, standing, solver_failed=failed if tick == 9 else None)
            state = supervisor.check(inputs)
        assert state == (S.SAFE_STOP if update == len(failures) - 1 else S.RUNNING)
    assert "NMPC solver failed 4 consecutive updates (max 3)" in supervisor.fault
    _assert_latched_damping(supervisor, time_s, standing)


def test_consecutive_wbc_failures_of_one_robot_trip_at_once(limits, standing):
    """A failed QP repeats the robot's last torques: allowed for ``max`` ticks in a row, the
    next one stops the team in the same tick (before its commands are filtered)."""
    settings = SupervisorSettings(max_consecutive_wbc_failures=2)
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing, settings)
    first, second = (robot.name for robot in limits)
    # failures alternate between robots, or are broken by a solved tick: never a streak of 3
    for success_first, success_second in [(False, True), (False, False), (True, False),
                                          (False, True), (True, True), (False, True),
                                          (False, True)]:
        time_s += TICK_S
        supervisor.check(_inputs(time_s, standing))
        supervisor.wbc_ticked(time_s, first, success_first, 1 if success_first else -3)
        supervisor.wbc_ticked(time_s, second, success_second, 1 if success_second else -3)
        assert supervisor.state == S.RUNNING
    time_s += TICK_S
    supervisor.wbc_ticked(time_s, first, False, -3)  # first's third failure in a row
    assert supervisor.state == S.SAFE_STOP
    assert f"WBC failed: {first}'s QP failed 3 consecutive ticks (status -3; max 2)" \
        in supervisor.fault
    assert supervisor.wbc_failures.failed_ticks == 8
    _assert_latched_damping(supervisor, time_s, standing)


@pytest.mark.parametrize(("stale_s", "trips"), [(0.05, False), (0.052, True)])
def test_a_state_stale_past_its_budget_trips_naming_the_robot(limits, standing, stale_s, trips):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    name = limits[0].name
    assert SETTINGS.stale_state_budget_s == 0.05
    state = supervisor.check(_inputs(time_s + TICK_S, standing, stale_state_s={name: stale_s}))
    assert (state == S.SAFE_STOP) == trips
    if trips:
        assert supervisor.fault == (f"robot state stale: {name}: no new state for 52 ms "
                                    "(budget 50 ms)")
        _assert_latched_damping(supervisor, time_s + TICK_S, standing)


@pytest.mark.parametrize(("late_ticks", "trips"), [(4, False), (5, True)])
def test_loop_overruns_count_within_the_window(limits, standing, late_ticks, trips):
    settings = SupervisorSettings(loop_overrun_budget=4, deadline_window_s=1.0)
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing, settings)
    for tick in range(400):  # 0.8 s
        time_s += TICK_S
        state = supervisor.check(_inputs(time_s, standing,
                                         loop_overrun=tick % 80 == 0 and tick // 80 < late_ticks))
    assert (state == S.SAFE_STOP) == trips
    if trips:
        assert "control-loop overruns: 5 within 1.0 s (budget 4)" in supervisor.fault


@pytest.mark.parametrize(("overruns", "spacing_ticks", "trips"), [
    (6, 50, True),  # 6 within 0.5 s
    (5, 5, False),  # exactly the budget
    (40, 101, False),  # every 0.202 s: at most 5 in any 1 s window, for 8 s
    (40, 95, True),  # every 0.19 s: 6 within 0.95 s
])
def test_deadline_overruns_count_within_the_window(limits, standing, overruns, spacing_ticks,
                                                    trips):
    settings = SupervisorSettings(deadline_overrun_budget=5, deadline_window_s=1.0)
    supervisor, start_s = _supervisor_in(S.RUNNING, limits, standing, settings)
    for tick in range(1, overruns * spacing_ticks + 1):
        time_s = start_s + tick * TICK_S
        missed = tick % spacing_ticks == 0  # every tick is an update; some overrun
        if supervisor.check(_inputs(time_s, standing, deadline_missed=missed)) == S.SAFE_STOP:
            break
    assert (supervisor.state == S.SAFE_STOP) == trips
    if trips:
        assert "NMPC deadline overruns: 6 within 1.0 s (budget 5)" in supervisor.fault
        _assert_latched_damping(supervisor, time_s, standing)
