"""ADMM local solves in persistent worker processes, each holding its own built solver
(IPOPT/fatrop in threads scaled only 1.1-1.2x on 2 cores; processes ~1.8x).

The agents are shared out over ``processes`` processes (default: one per CPU core, at most
one per agent), agent i to process i mod ``processes``; a process solves its agents one after
the other. More processes than cores only add pipe round trips, wake-ups and contention.

With ``solve_first_here`` process 0 is the calling process: its agents' solves run there while
the workers solve theirs: the caller would only wait anyway, and it saves a round trip and a
wake-up per ADMM iteration (2 agents, 2 cores, SRB closed loop: a worker woken on the caller's
core preempted it before its second request was out; update median 9.3 -> 8.1 ms, p95 14.7 ->
10.9 ms, measured). Only for a caller that owns its interpreter (the NMPC process, lockstep
runs): a solve holds the interpreter lock for 1-2 ms.

Requests and solutions lie in shared memory (``deploy.nmpc_runtime.solve_slots``, one block
per worker); the pipe carries the round's number and flags one way and the solves' stats the
other. A worker that dies or does not answer in time yields a failed ``NlpSolution`` for each
of its agents (status says why), never an exception in the control loop.

``spin_s`` > 0 (the lockstep simulation: wall time is its figure, and the caller's core and the
worker's are its own): after answering, a worker polls its pipe without sleeping for up to
``spin_s`` before it blocks, and the caller polls for the answers so before it blocks. A pipe
write that wakes a sleeping reader costs the writer ~50 us on this VM and the reader as much
again to get going; the update's second round arrives within ~0.3 ms of the first's answer,
so it finds the worker awake. Measured (``porter bench sim two_go2``, 3 alternating runs): the
update's median 4.1-4.2 -> 3.7-3.8 ms with both (shared memory alone: 4.0-4.2). It costs up to
``spin_s`` of CPU per update on each side: 0 (blocking only) wherever the cores are shared, as
the deploy NMPC's are.
"""

from __future__ import annotations

import contextlib
import multiprocessing as mp
import os
import time
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess

import numpy as np

from core.admm.admm_executor import LocalSolveRequest, LocalSolverSpec, solve_request
from core.nmpc.nlp_solver import NlpSolution, NlpSolver, SolveStats
from deploy.compute.gc_pauses import freeze_startup_objects
from deploy.compute.process_names import name_this_process
from deploy.nmpc_runtime.solve_slots import SolveSlots

MAX_SPIN_S = 0.01


def _spin(connection: Connection, seconds: float) -> bool:
    """Poll ``connection`` without sleeping for up to ``seconds``; True once readable."""
    deadline = time.perf_counter() + seconds
    while time.perf_counter() < deadline:
        if connection.poll(0):
            return True
    return False


def _worker(spec: LocalSolverSpec, index: int, connection: Connection, spin_s: float) -> None:
    name_this_process(f"porter-admm{index}")
    solver = spec.build()
    freeze_startup_objects()  # no full collection of the solver's objects between solves
    connection.send(("ready", solver.sizes))
    layout = connection.recv()
    if layout is None:
        return
    slots = SolveSlots.attach(layout)
    try:
        while True:
            _spin(connection, spin_s)  # the update's next round comes within ~0.3 ms
            message = connection.recv()
            if message is None:
                return
            sequence, headers = message
            connection.send((sequence, [
                slots.put_solution(slot, solve_request(solver, slots.take_request(slot, header)))
                for slot, header in headers]))
    finally:
        slots.close()


class ProcessExecutor:
    """Agents' solves in parallel over ``processes`` processes; ``solve_all`` runs one round."""

    def __init__(self, spec: LocalSolverSpec, timeout_s: float = 10.0,
                 start_timeout_s: float = 600.0, solve_first_here: bool = False,
                 processes: int | None = None, spin_s: float = 0.0) -> None:
        if processes is not None and processes < 1:
            raise ValueError(f"processes: must be at least 1, got {processes}")
        if not 0.0 <= spin_s <= MAX_SPIN_S:
            raise ValueError(f"spin_s: must be in [0, {MAX_SPIN_S}] s, got {spin_s}")
        self.spin_s = spin_s
        count = max(1, min(processes or os.cpu_count() or 1, spec.agent_count))
        context = mp.get_context("spawn")
        self.timeout_s = timeout_s
        self._sequence = 0
        self._process_of = {agent: agent % count for agent in range(spec.agent_count)}
        self._connections: dict[int, Connection] = {}
        self._processes: dict[int, BaseProcess] = {}
        self._slots: dict[int, SolveSlots] = {}  # per worker: its agents' arrays
        # each agent's slot in its process's block: its place among that process's agents
        self._slot_of = {agent: sum(1 for other in range(agent)
                                    if self._process_of[other] == self._process_of[agent])
                         for agent in range(spec.agent_count)}
        # Not where this process's solvers would get other kernels than a fresh worker's
        # (CasADi's BLASFEO loaded first: ~2x slower, other rounding than the workers').
        kernels = getattr(spec.compiler, "blas_kernels", None)
        if solve_first_here and kernels is not None and kernels().preempted:
            solve_first_here = False
        self._here: NlpSolver | None = spec.build() if solve_first_here else None
        for index in range(1 if solve_first_here else 0, count):
            parent, child = context.Pipe()
            process = context.Process(target=_worker, args=(spec, index, child, spin_s),
                                      daemon=True, name=f"porter-admm-agent{index}")
            process.start()
            self._connections[index] = parent
            self._processes[index] = process
        for index, connection in self._connections.items():
            try:
                answer = connection.recv() if connection.poll(start_timeout_s) else None
            except (EOFError, OSError):  # it died while starting
                answer = None
            if not (isinstance(answer, tuple) and answer[0] == "ready"):
                self.close()
                raise RuntimeError(f"ADMM worker {index} did not start")
            agents = sum(1 for process in self._process_of.values() if process == index)
            self._slots[index] = SolveSlots.create(agents, *answer[1])
            connection.send(self._slots[index].layout)

    @property
    def solves_here(self) -> tuple[int, ...]:
        """Agents whose solves run in the calling process (their CPU time is the caller's)."""
        if self._here is None:
            return ()
        return tuple(agent for agent, index in self._process_of.items() if index == 0)

    def worker_of(self, agent: int) -> BaseProcess | None:
        """The worker process that solves ``agent`` (None: the calling process does)."""
        return self._processes.get(self._process_of[agent])

    def solve_all(self, requests: list[LocalSolveRequest]) -> list[NlpSolution]:
        self._sequence += 1
        batches: dict[int, list[LocalSolveRequest]] = {}
        for request in requests:
            batches.setdefault(self._process_of[request.agent], []).append(request)
        sent: dict[int, bool] = {}
        unfit: set[int] = set()  # batches of another problem's requests: never sent
        for index, batch in batches.items():
            if index in self._connections:
                slots = self._slots[index]
                if not all(slots.layout.fits(request) for request in batch):
                    unfit.add(index)
                    continue
                headers = [(self._slot_of[r.agent], slots.put_request(self._slot_of[r.agent], r))
                           for r in batch]
                try:
                    self._connections[index].send((self._sequence, headers))
                    sent[index] = True
                except (BrokenPipeError, OSError):
                    sent[index] = False
        results: dict[int, NlpSolution] = {}
        for index, batch in batches.items():
            if index not in self._connections:
                if index != 0 or self._here is None:  # its worker is gone (closed)
                    sent[index] = False
                    continue
                for request in batch:
                    results[request.agent] = solve_request(self._here, request)
        for index in unfit:
            for request in batches[index]:
                results[request.agent] = failed_solution(
                    request, f"the request does not fit its worker's problem "
                    f"({self._slots[index].layout})")
        for index, ok in sent.items():
            reason = "worker is gone"
            if ok:
                try:
                    answer = self._receive(self._connections[index])
                    if answer is not None:
                        slots = self._slots[index]
                        for request, stats in zip(batches[index], answer, strict=True):
                            results[request.agent] = slots.take_solution(
                                self._slot_of[request.agent], stats)
                        continue
                    reason = "worker did not answer in time"
                except (EOFError, OSError):
                    reason = "worker died"
            for request in batches[index]:
                results[request.agent] = failed_solution(request, reason)
        return [results[request.agent] for request in requests]

    def _receive(self, connection: Connection) -> list[SolveStats] | None:
        """This round's answers (the solves' stats; the arrays are in the worker's slots);
        late answers of earlier (timed-out) rounds are discarded."""
        while _spin(connection, self.spin_s) or connection.poll(self.timeout_s):
            sequence, stats = connection.recv()
            if sequence == self._sequence:
                return stats
        return None

    def close(self) -> None:
        for connection in self._connections.values():
            with contextlib.suppress(BrokenPipeError, OSError):
                connection.send(None)
        for process in self._processes.values():
            process.join(timeout=2.0)
            if process.is_alive():
                process.kill()
        for slots in self._slots.values():  # after the workers: they have unmapped them
            slots.close()
        self._connections, self._processes, self._slots = {}, {}, {}

    def __del__(self) -> None:
        if getattr(self, "_processes", None):  # (None: __init__ refused its arguments)
            self.close()


def failed_solution(request: LocalSolveRequest, reason: str) -> NlpSolution:
    n = request.initial_guess.size
    m = 0 if request.constraint_multipliers is None else request.constraint_multipliers.size
    stats = SolveStats(f"executor: {reason}", False, 0, 0.0, float("nan"), float("inf"))
    return NlpSolution(np.array(request.initial_guess), np.zeros(m), np.zeros(n), stats)
