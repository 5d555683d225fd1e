"""The lockstep NMPC: plans handed over on the modelled delay, computed here or, overlapping
the world's steps, in the NMPC's own process (the hand-over rules stay the same)."""

from __future__ import annotations

from typing import cast

import pytest

from deploy.nmpc_runtime.nmpc_lockstep import LockstepNmpc
from deploy.nmpc_runtime.nmpc_process import NmpcProcess
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.runtime.controller import NmpcDecision, TeamController


class _Clock:
    def __init__(self) -> None:
        self.t = 0.0

    def __call__(self) -> float:
        return self.t


class _Process:
    """The NmpcProcess calls the lockstep runner makes; answers with the wall time it took."""

    def __init__(self) -> None:
        self.submitted: list[int] = []
        self.waits = 0
        self.closed = False

    def submit(self, decision: NmpcDecision, update: int) -> None:
        self.submitted.append(update)

    def wait(self, timeout_s: float) -> NmpcResult:
        self.waits += 1
        return NmpcResult(cast(NmpcDecision, None), self.submitted[-1], None, 0.0042)

    def close(self) -> None:
        self.closed = True


def _runner(process: _Process, clock: _Clock) -> LockstepNmpc:
    return LockstepNmpc(cast(TeamController, None), clock, model_delay=True, fixed_delay_s=0.012,
                        process=cast(NmpcProcess, process))


def test_overlapping_needs_a_fixed_modelled_delay() -> None:
    process = cast(NmpcProcess, _Process())
    control = cast(TeamController, None)
    with pytest.raises(ValueError, match="fixed modelled delay"):
        LockstepNmpc(control, _Clock(), model_delay=True, fixed_delay_s=None, process=process)
    with pytest.raises(ValueError, match="fixed modelled delay"):
        LockstepNmpc(control, _Clock(), model_delay=False, fixed_delay_s=0.01, process=process)


def test_the_process_answer_is_taken_at_the_modelled_instant_only() -> None:
    process, clock = _Process(), _Clock()
    runner = _runner(process, clock)
    decision = cast(NmpcDecision, None)
    runner.submit(decision, 0)  # the first plan is handed over at once
    assert runner.busy and process.submitted == [0]
    first = runner.take()
    assert first is not None and first.update == 0 and first.wall_s == 0.0
    clock.t = 0.018
    runner.submit(decision, 1)
    with pytest.raises(RuntimeError, match="while one is running"):
        runner.submit(decision, 2)
    for t in (0.018, 0.020, 0.0299):  # the world steps on; nobody waits for the process
        clock.t = t
        assert runner.take() is None
    assert process.waits == 1
    clock.t = 0.030
    second = runner.take()
    assert second is not None and second.update == 1 and process.waits == 2
    assert second.wall_s == pytest.approx(0.012)  # the modelled time, not the process's own
    assert not runner.busy and runner.take() is None
    runner.close()
    assert process.closed


def test_a_fixed_delay_hands_over_on_its_tick_despite_the_clocks_rounding() -> None:
    """Simulated time is a sum of 1 ms physics steps (as MuJoCo's): a 12 ms delay is handed
    over exactly 6 ticks after its decision, every time (without the tolerance: half of them
    a tick late, where the sum rounds below submit + delay)."""
    process, clock = _Process(), _Clock()
    runner = _runner(process, clock)
    decision = cast(NmpcDecision, None)
    gaps, submitted_tick = [], 0
    runner.submit(decision, 0)
    for tick in range(600):
        result = runner.take()
        if result is not None and result.update > 0:
            gaps.append(tick - submitted_tick)
        if not runner.busy and tick % 9 == 0:  # a decision every 9 ticks
            runner.submit(decision, tick)
            submitted_tick = tick
        for _ in range(2):  # one 500 Hz tick: two physics steps
            clock.t += 0.001
    assert len(gaps) > 50
    assert set(gaps) == {6}
