"""The NMPC schedule, with a controller that builds no NLP and runners on an injected clock:
one timing grid, one plan hand-off, the supervisor's flags, delay compensation."""

from __future__ import annotations

import threading
import time

import pytest

from deploy.nmpc_runtime.nmpc_lockstep import LockstepNmpc
from deploy.nmpc_runtime.nmpc_schedule import NmpcSchedule
from deploy.nmpc_runtime.nmpc_thread import NmpcThread
from tests.deploy.runtime.fakes import FakeClock, FakeControl, frame, measurements, plan

TICK_S = 0.002
HZ = 60.0


def _schedule(control: FakeControl, clock: FakeClock, model_delay: bool = False,
              fixed_delay_s: float | None = None) -> NmpcSchedule:
    runner = LockstepNmpc(control, clock, model_delay, fixed_delay_s)  # type: ignore[arg-type]
    schedule = NmpcSchedule(control, runner, HZ, clock, None, None,  # type: ignore[arg-type]
                            has_deadline=model_delay)
    schedule.start(clock())
    return schedule


def _ticks(schedule: NmpcSchedule, clock: FakeClock, count: int) -> list[tuple]:
    flags = []
    for _ in range(count):
        flags.append(schedule.step(clock(), measurements(), frame(clock())))
        clock.t = round(clock.t + TICK_S, 9)
    return flags


def test_lockstep_updates_on_the_60_hz_grid_and_plans_take_effect_at_once() -> None:
    control, clock = FakeControl(), FakeClock()
    schedule = _schedule(control, clock)
    flags = _ticks(schedule, clock, 500)  # 1 s
    times = [t for t, _ in control.decided]
    assert len(times) == 60
    # every update on the first tick at or after its grid instant k / 60
    for k, t in enumerate(times):
        assert k / HZ - 1e-9 <= t < k / HZ + TICK_S
    assert schedule.plans_applied == 60 and schedule.plan_start_s == times[-1]
    assert all(delay == 0.0 for _, delay in control.decided)
    assert flags.count((False, None)) == 60  # no deadline without a modelled delay


def test_a_modelled_delay_holds_the_plan_skips_covered_instants_and_is_compensated() -> None:
    control, clock = FakeControl(), FakeClock()
    schedule = _schedule(control, clock, model_delay=True, fixed_delay_s=0.025)
    flags = _ticks(schedule, clock, 500)
    decided = [t for t, _ in control.decided]
    # 25 ms per update > one 16.7 ms period: every other instant is skipped, never a burst
    gaps = [b - a for a, b in zip(decided, decided[1:], strict=False)]
    assert min(gaps) > 1.0 / HZ
    assert len(decided) < 40
    # each plan takes effect 26 ms (the next tick) after its decision: missed deadline
    assert schedule.delays_s[1:] == pytest.approx([0.026] * (len(schedule.delays_s) - 1))
    assert (False, True) in flags and schedule.deadline_misses == len(schedule.delays_s) - 1
    # ... and later decisions are planned for the instant their plan takes effect
    assert control.decided[-1][1] == pytest.approx(0.026)
    # (the last decision's plan is still computing at the end; the one before it is active)
    assert schedule.runner.busy
    assert schedule.plan_start_s == pytest.approx(control.decided[-2][0] + 0.026)


def test_failed_solves_and_margin_flags_are_told_apart() -> None:
    control = FakeControl(plans=[plan(success=False), plan(inside_margin=True), plan()])
    clock = FakeClock()
    schedule = _schedule(control, clock)
    flags = [f for f in _ticks(schedule, clock, 30) if f != (None, None)]  # 4 updates
    assert flags == [(True, None), (False, None), (False, None), (False, None)]
    assert schedule.solver_failures == 1 and schedule.margin_flags == 1


def test_relaxed_plans_are_no_solver_failures_but_reach_the_braking_rule() -> None:
    control = FakeControl(plans=[plan(), plan(relaxed=True), plan()])
    clock = FakeClock()
    schedule = _schedule(control, clock)
    flags = [f for f in _ticks(schedule, clock, 30) if f != (None, None)]  # 4 updates
    assert flags == [(False, None)] * 4
    assert schedule.solver_failures == 0 and schedule.relaxed_plans == 1
    assert [p.relaxed for _, p in control.taken] == [False, True, False, False]


def test_an_update_that_raises_is_a_solver_failure_and_keeps_the_old_plan() -> None:
    control, clock = FakeControl(), FakeClock()
    schedule = _schedule(control, clock)
    _ticks(schedule, clock, 1)
    first = schedule.plan
    control.raises = True
    flags = [f for f in _ticks(schedule, clock, 10) if f != (None, None)]
    assert flags == [(True, None)] and schedule.plan is first and schedule.solver_failures == 1


def test_the_thread_runner_hands_plans_over_without_blocking_the_loop() -> None:
    control, clock = FakeControl(), FakeClock()
    thread = NmpcThread(control, time.perf_counter)  # type: ignore[arg-type]
    schedule = NmpcSchedule(control, thread, HZ, clock, None, None)  # type: ignore[arg-type]
    schedule.start(0.0)
    try:
        assert schedule.step(0.0, measurements(), frame(0.0)) in ((None, None), (False, False))
        deadline = time.monotonic() + 5.0
        while schedule.plan is None and time.monotonic() < deadline:
            clock.t += TICK_S
            schedule.step(clock(), measurements(), frame(clock()))
            time.sleep(0.001)
        assert schedule.plan is not None and schedule.plans_applied == 1
        # the plan's stage 0 is its decision's time; the next update waits for the grid
        assert schedule.plan_start_s == 0.0 and len(control.decided) == 1
    finally:
        schedule.close()


def test_the_thread_reports_an_exception_as_a_result_not_a_crash() -> None:
    gate = threading.Event()  # the solve is held until the second submit was tried
    control = FakeControl(raises=True, gate=gate)
    thread = NmpcThread(control)  # type: ignore[arg-type]
    try:
        thread.submit(control.nmpc_inputs(0.0, [], frame(0.0)), 7)
        with pytest.raises(RuntimeError):
            thread.submit(control.nmpc_inputs(0.0, [], frame(0.0)), 8)  # one at a time
        gate.set()
        deadline = time.monotonic() + 5.0
        result = None
        while result is None and time.monotonic() < deadline:
            result = thread.take()
            time.sleep(0.001)
        assert result is not None and result.plan is None and result.update == 7
        assert "solver exploded" in result.error and not thread.busy
    finally:
        thread.close()


def test_deciding_after_send_keeps_the_grid() -> None:
    """``decide_after_send``: ``step`` only takes results, ``after_send`` decides, on the same
    ticks (the 60 Hz instants) as deciding in ``step``, with as many plans taking effect."""
    runs = []
    for after_send in (False, True):
        control, clock = FakeControl(), FakeClock()
        runner = LockstepNmpc(control, clock, True, 0.025)  # type: ignore[arg-type]
        schedule = NmpcSchedule(control, runner, HZ, clock, None, None,  # type: ignore[arg-type]
                                has_deadline=True, decide_after_send=after_send)
        schedule.start(clock())
        for _ in range(250):
            decided = len(control.decided)
            schedule.step(clock(), measurements(), frame(clock()))
            if after_send:
                assert len(control.decided) == decided  # step only took results
            schedule.after_send(clock(), measurements(), frame(clock()))
            clock.t = round(clock.t + TICK_S, 9)
        runs.append(([t for t, _ in control.decided], schedule.plans_applied))
    assert len(runs[0][0]) >= 10
    assert runs[0] == runs[1]
