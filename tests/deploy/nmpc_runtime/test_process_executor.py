"""The process executor gives the same ADMM result as the serial one (blocking or spinning for
answers), survives a dead worker, and removes its shared memory when closed."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from core.admm.admm_executor import LocalSolveRequest, LocalSolverSpec
from core.admm.admm_mpc import DistributedMpc
from deploy.nmpc_runtime.process_executor import ProcessExecutor
from deploy.nmpc_runtime.solve_slots import SHM_DIRECTORY
from tests.core.controller_fixtures import inputs_at_start, settings, team

ROOT = Path(__file__).resolve().parents[3]


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
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), timeout_s=5.0,
                               processes=2)
    try:
        worker = executor.worker_of(1)
        assert worker is not None and worker is not executor.worker_of(0)
        worker.kill()
        worker.join()
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
                               solve_first_here=True, processes=model.agent_count)
    try:
        assert executor.worker_of(0) is None and executor.solves_here == (0,)
        assert all(executor.worker_of(a) is not None for a in range(1, model.agent_count))
        controller = DistributedMpc(model, mpc, executor=executor)
        here = controller.update(inputs)
        assert here.success
        np.testing.assert_allclose(here.grf, serial.grf, atol=1e-6)
        worker = executor.worker_of(1)
        assert worker is not None
        worker.kill()
        worker.join()
        controller.reset()
        plan = controller.update(inputs)
    finally:
        executor.close()
    assert not plan.success
    assert [s.success for s in plan.solves[: model.agent_count]][0]  # agent 0's own solve
    assert any("executor" in s.status for s in plan.solves)


def test_agents_shared_over_fewer_processes_than_agents_agree_with_serial() -> None:
    """Three agents over two processes (this one and a worker): agents 0 and 2 solved here,
    agent 1 in the worker; the ADMM result is the serial one."""
    mpc = settings()
    model = team(("go2", "go2", "go2"))
    inputs = inputs_at_start(model, mpc)
    serial = DistributedMpc(model, mpc).update(inputs)
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), solve_first_here=True,
                               processes=2)
    try:
        assert executor.solves_here == (0, 2) and len(executor._processes) == 1
        shared = DistributedMpc(model, mpc, executor=executor).update(inputs)
    finally:
        executor.close()
    assert shared.success
    np.testing.assert_allclose(shared.grf, serial.grf, atol=1e-6)
    with pytest.raises(ValueError, match="processes"):
        ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), processes=0)


def test_no_solve_here_in_a_process_that_loaded_casadis_blasfeo_first() -> None:
    """A process whose solvers got CasADi's generic BLASFEO (a fatrop plugin loaded before
    porter's build) does not take the first agent's solve: a fresh worker would solve it with
    other kernels (2x slower, other rounding)."""
    code = textwrap.dedent("""
        import platform
        import casadi as ca
        from core.admm.admm_executor import LocalSolveRequest, LocalSolverSpec
        from deploy.nmpc_runtime.process_executor import ProcessExecutor
        from deploy.compute.blas_kernels import cpu_target, host_cpu_flags
        from deploy.compute.codegen_cache import CompiledCodeCache
        from tests.core.controller_fixtures import settings
        x = ca.SX.sym("x")
        ca.nlpsol("s", "fatrop", {"x": x, "f": x * x})  # maps CasADi's libblasfeo
        cache = CompiledCodeCache()
        kernels = cache.blas_kernels()
        assert kernels.preempted == (cpu_target(platform.machine(), host_cpu_flags())
                                     is not None), kernels
        executor = ProcessExecutor(LocalSolverSpec(settings(), 2, cache),
                                   solve_first_here=True, processes=2)
        try:
            print(kernels.preempted, executor.solves_here, executor.worker_of(0) is not None)
        finally:
            executor.close()
    """)
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                            text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-2000:]
    preempted, here, worker = result.stdout.split(maxsplit=2)
    if preempted == "True":
        assert here == "()" and worker.strip() == "True"
    else:
        assert here == "(0,)" and worker.strip() == "False"


def test_spinning_for_answers_gives_the_serial_plans_and_a_dead_worker_still_fails() -> None:
    """``spin_s`` (lockstep runs): the caller and the workers poll without sleeping between
    rounds; the serial plans over several warm updates (as the blocking executor's: this
    process's kernels may be CasADi's, the workers' are porter's); a worker killed while it
    spins fails its agent's solves; the shared memory is gone after ``close``."""
    mpc = settings()
    model = team()
    inputs = inputs_at_start(model, mpc)
    serial = DistributedMpc(model, mpc)
    executor = ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), timeout_s=5.0,
                               processes=2, spin_s=0.002)
    blocks = [SHM_DIRECTORY / slots.layout.name for slots in executor._slots.values()]
    assert blocks and all(block.exists() for block in blocks)
    try:
        spinning = DistributedMpc(model, mpc, executor=executor)
        for _ in range(3):  # warm updates: the second round finds the worker spinning
            expected, plan = serial.update(inputs), spinning.update(inputs)
            assert plan.success
            np.testing.assert_allclose(plan.grf, expected.grf, atol=1e-6)
            np.testing.assert_allclose(plan.consensus_trajectory,
                                       expected.consensus_trajectory, atol=1e-6)
        worker = executor.worker_of(1)
        assert worker is not None
        worker.kill()
        worker.join()
        failed = spinning.update(inputs)
        assert not failed.success and any("executor" in s.status for s in failed.solves)
        # a request of another problem is refused per agent, not raised
        odd = LocalSolveRequest(1, np.zeros(3), np.zeros(2), np.zeros(3), np.zeros(3))
        results = executor.solve_all([odd])
        assert not results[0].stats.success and "does not fit" in results[0].stats.status
    finally:
        executor.close()
    assert not any(block.exists() for block in blocks)
    with pytest.raises(ValueError, match="spin_s"):
        ProcessExecutor(LocalSolverSpec(mpc, model.agent_count), spin_s=1.0)
