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
