"""Requests and solutions through the executor's shared memory: what goes in comes out, the
block is mapped by name in another process, and it is removed when the executor closes."""

from __future__ import annotations

import multiprocessing as mp
from multiprocessing.connection import Connection

import numpy as np

from core.admm.admm_executor import LocalSolveRequest
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from deploy.nmpc_runtime.solve_slots import SHM_DIRECTORY, SlotLayout, SolveSlots

SIZES = (7, 5, 4)  # variables, parameters, constraints


def _request(rng: np.random.Generator, agent: int, multipliers: bool) -> LocalSolveRequest:
    n, p, m = SIZES
    return LocalSolveRequest(
        agent=agent, initial_guess=rng.normal(size=n), parameters=rng.normal(size=p),
        lower_bounds=rng.normal(size=n) - 5.0, upper_bounds=rng.normal(size=n) + 5.0,
        constraint_multipliers=rng.normal(size=m) if multipliers else None,
        bound_multipliers=rng.normal(size=n) if multipliers else None,
        warm_start=multipliers, update=12, iteration=agent)


def _echo_worker(layout: SlotLayout, connection: Connection) -> None:
    """A worker's side: each request's guess comes back as the decision, its slot doubled."""
    slots = SolveSlots.attach(layout)
    try:
        for slot, header in connection.recv():
            request = slots.take_request(slot, header)
            cm = (request.constraint_multipliers if request.constraint_multipliers is not None
                  else np.full(layout.constraints, -1.0))
            stats = SolveStats(f"agent {request.agent} {request.warm_start}", True,
                               request.iteration, 0.0, float(request.parameters.sum()), 0.0)
            slots.put_solution(slot, NlpSolution(2.0 * request.initial_guess, cm,
                                                 request.upper_bounds - request.lower_bounds,
                                                 stats))
            connection.send(stats)
    finally:
        slots.close()


def test_requests_and_solutions_cross_to_another_process_unchanged() -> None:
    rng = np.random.default_rng(4)
    slots = SolveSlots.create(2, *SIZES)
    path = SHM_DIRECTORY / slots.layout.name
    assert path.exists()
    parent, child = mp.get_context("spawn").Pipe()
    worker = mp.get_context("spawn").Process(target=_echo_worker, args=(slots.layout, child))
    worker.start()
    try:
        requests = [_request(rng, 0, True), _request(rng, 3, False)]
        parent.send([(slot, slots.put_request(slot, r)) for slot, r in enumerate(requests)])
        for slot, request in enumerate(requests):
            stats = parent.recv()
            assert stats.status == f"agent {request.agent} {request.warm_start}"
            assert stats.objective == float(request.parameters.sum())  # parameters arrived
            solution = slots.take_solution(slot, stats)
            np.testing.assert_array_equal(solution.decision, 2.0 * request.initial_guess)
            np.testing.assert_array_equal(solution.bound_multipliers,
                                          request.upper_bounds - request.lower_bounds)
            expected = (request.constraint_multipliers if request.constraint_multipliers
                        is not None else np.full(SIZES[2], -1.0))
            np.testing.assert_array_equal(solution.constraint_multipliers, expected)
            # the caller's copy: the next round's writes do not change it
            slots.arrays[slot]["decision"][:] = 0.0
            assert solution.decision.any()
        worker.join(10.0)
        assert worker.exitcode == 0
    finally:
        worker.kill()
        slots.close()
    assert not path.exists()  # the executor's close removed the block
    slots.close()  # twice is harmless


def test_the_worker_gets_copies_and_the_flags() -> None:
    rng = np.random.default_rng(5)
    slots = SolveSlots.create(1, *SIZES)
    try:
        request = _request(rng, 2, False)
        header = slots.put_request(0, request)
        taken = slots.take_request(0, header)
        assert taken.constraint_multipliers is None and taken.bound_multipliers is None
        assert (taken.agent, taken.warm_start, taken.update, taken.iteration) == (2, False, 12, 2)
        slots.arrays[0]["initial_guess"][:] = np.nan  # the executor's next round
        np.testing.assert_array_equal(taken.initial_guess, request.initial_guess)
        assert slots.layout.fits(request)
        assert not slots.layout.fits(LocalSolveRequest(  # another problem's sizes
            0, np.zeros(3), np.zeros(5), np.zeros(3), np.zeros(3)))
    finally:
        slots.close()
