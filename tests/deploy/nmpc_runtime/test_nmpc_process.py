"""The NMPC in its own process: the same plans as in the loop's process, non-blocking
hand-over, the warm start it started from (for the updates asked), and a dead process
reported, not hung on."""

from __future__ import annotations

import os
import time

import numpy as np
import pytest

from core.nmpc.mpc_plan import MpcPlan
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.nmpc_runtime.nmpc_process import NmpcProcess, NmpcProcessError
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.recording.regression import TOLERANCES
from deploy.runtime.sim_run import SimRun


@pytest.fixture(scope="module")
def run() -> SimRun:
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, CompiledCodeCache())
    yield run
    run.close()


def _decision(run: SimRun, t: float = 0.0):  # noqa: ANN202
    control = run.control
    names = control.robot_names
    measurements = [run.links.drivers[name].read() for name in names]
    control.reset(measurements, start_s=0.0)
    return control.nmpc_inputs(t, measurements, run.simulation.mocap().latest())


def _wait(runner: NmpcProcess, timeout_s: float = 60.0) -> NmpcResult:
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        result = runner.take()
        if result is not None:
            return result
        time.sleep(0.001)
    raise AssertionError("no result from the NMPC process")


def test_the_process_plans_what_the_loops_process_plans(run: SimRun) -> None:
    control = run.control
    runner = NmpcProcess(control.scenario, control.settings, control.cache)
    try:
        first, second = _decision(run), _decision(run, 0.05)
        runner.submit(first, 0)
        assert runner.busy
        with pytest.raises(RuntimeError):
            runner.submit(second, 1)  # one update at a time
        remote = _wait(runner)
        assert not runner.busy and remote.update == 0 and remote.decision is first
        assert remote.error == "" and remote.wall_s > 0.0
        assert remote.memory is not None and remote.memory.previous == [None, None]
        # the same decisions in this process, from the same (empty) warm start. Not bit for
        # bit: a fresh process loads porter's BLASFEO kernels, while in this one an earlier
        # test may have loaded CasADi's generic build first, and the cold start's SQP stops
        # within its tolerance at a slightly different iterate (measured: GRFs 6e-5 N apart,
        # the consensus's terminal wrenches up to 1.5e-3 with soft barriers)
        control.controller.restore(remote.memory)
        local = control.update(first)
        assert isinstance(remote.plan, MpcPlan) and remote.plan.success
        np.testing.assert_allclose(remote.plan.grf, local.grf, rtol=0, atol=1e-3)
        np.testing.assert_allclose(remote.plan.consensus_trajectory,
                                   local.consensus_trajectory, rtol=0, atol=1e-2)
        # the second update starts from the first one's solution, as in this process: one
        # warm RTI step on HPIPM's speed mode, which carries the two kernels' rounding further
        # (CI's clean run: 0.0088 N apart), so within the log replay's GRF tolerance
        runner.submit(second, 1)
        warm = _wait(runner)
        assert warm.memory is not None and all(p is not None for p in warm.memory.previous)
        np.testing.assert_allclose(warm.plan.grf, control.update(second).grf,  # type: ignore[union-attr]
                                   rtol=0, atol=TOLERANCES["grf_n"])
    finally:
        runner.close()
    assert not runner.alive


def test_a_dead_process_fails_the_running_update_then_refuses_the_next(run: SimRun) -> None:
    control = run.control
    cpu = max(os.sched_getaffinity(0))
    runner = NmpcProcess(control.scenario, control.settings, control.cache, cpus=[cpu])
    try:
        assert os.sched_getaffinity(runner.pid) == {cpu}  # nmpc.cpus, from its start
        runner.submit(_decision(run), 3)
        runner.kill()
        result = _wait(runner, timeout_s=5.0)
        assert result.plan is None and result.update == 3 and "died" in result.error
        assert not runner.busy and runner.take() is None
        with pytest.raises(NmpcProcessError, match="gone"):
            runner.submit(_decision(run), 4)
    finally:
        runner.close()


def test_wait_blocks_for_the_answer_and_reports_a_dead_process(run: SimRun) -> None:
    control = run.control
    runner = NmpcProcess(control.scenario, control.settings, control.cache)
    try:
        with pytest.raises(RuntimeError, match="no NMPC update submitted"):
            runner.wait(1.0)
        runner.memory_every = 2  # the warm start comes back for even updates only
        runner.submit(_decision(run), 7)
        answer = runner.wait(60.0)
        assert answer.update == 7 and answer.error == "" and answer.plan is not None
        assert answer.memory is None
        assert not runner.busy
        runner.submit(_decision(run, 0.05), 8)
        kept = runner.wait(60.0)
        assert kept.memory is not None and all(p is not None for p in kept.memory.previous)
        runner.memory_every = None  # no recording: never
        runner.submit(_decision(run, 0.1), 10)
        assert runner.wait(60.0).memory is None
        runner.submit(_decision(run, 0.15), 11)
        runner.kill()
        started = time.monotonic()
        dead = runner.wait(60.0)  # the broken pipe ends the wait, not the timeout
        assert time.monotonic() - started < 10.0
        assert dead.plan is None and dead.update == 11 and "died" in dead.error
    finally:
        runner.close()
