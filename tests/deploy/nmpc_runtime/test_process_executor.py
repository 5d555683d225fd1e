"""The process executor gives the same ADMM result as the serial one, and survives a dead worker."""

from __future__ import annotations

import numpy as np

from core.nmpc.admm_executor import LocalSolverSpec
from core.nmpc.admm_mpc import DistributedMpc
from deploy.nmpc_runtime.process_executor import ProcessExecutor
from tests.core.controller_fixtures import inputs_at_start, settings, team


def test_process_and_serial_executors_agree() -> None:
    mpc = settings()
    model = team()
    inputs = inputs_at_start(model, mpc)
    serial = DistributedMpc(model, mpc).update(inputs)
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count))
    try:
        parallel = DistributedMpc(model, mpc, executor=executor).update(inputs)
    finally:
        executor.close()
    assert parallel.success
    np.testing.assert_allclose(parallel.grf, serial.grf, atol=1e-6)
    np.testing.assert_allclose(parallel.consensus_trajectory, serial.consensus_trajectory,
                               atol=1e-6)


def test_dead_worker_gives_a_failed_plan_not_a_crash() -> None:
    mpc = settings()
    model = team()
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), timeout_s=5.0)
    try:
        executor._processes[1].kill()
        executor._processes[1].join()
        plan = DistributedMpc(model, mpc, executor=executor).update(inputs_at_start(model, mpc))
    finally:
        executor.close()
    assert not plan.success
    assert any("executor" in s.status for s in plan.solves)
    assert np.all(np.isfinite(plan.grf))


def test_first_agent_solved_here_agrees_and_a_dead_worker_still_fails_cleanly() -> None:
    """``solve_first_here``: agent 0's solve runs in this process, the others in workers (one
    fewer); same ADMM result as serial; a dead worker of another agent fails the plan."""
    mpc = settings()
    model = team()
    inputs = inputs_at_start(model, mpc)
    serial = DistributedMpc(model, mpc).update(inputs)
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), timeout_s=5.0,
                               solve_first_here=True)
    try:
        assert sorted(executor._processes) == list(range(1, model.agent_count))
        assert executor.solves_here == (0,)
        controller = DistributedMpc(model, mpc, executor=executor)
        here = controller.update(inputs)
        assert here.success
        np.testing.assert_allclose(here.grf, serial.grf, atol=1e-6)
        executor._processes[1].kill()
        executor._processes[1].join()
        controller.reset()
        plan = controller.update(inputs)
    finally:
        executor.close()
    assert not plan.success
    assert [s.success for s in plan.solves[: model.agent_count]][0]  # agent 0's own solve
    assert any("executor" in s.status for s in plan.solves)
