"""Where ADMM local solves run. The algorithm hands over plain arrays and gets solutions back,
so the same code runs serially, in worker processes
(``deploy.nmpc_runtime.process_executor``) or in agent processes over a network
(``deploy.agents.zenoh_executor``).

The consensus and dual step (``consensus_step``) is here too, so that the coordinator
(``core.admm.admm_mpc``) and agents that run the ADMM among themselves without one
(``run_agent_admm``: every agent receives every s^j and computes s-bar and all duals) do
the same arithmetic: from the same inputs they reach the same s-bar, bit for bit."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Protocol

import numpy as np

from core.nmpc.nlp_solver import NlpCompiler, NlpSolution, NlpSolver, SolveStats
from core.nmpc.settings import MpcSettings
from core.nmpc.transport_problem import build_transport_problem


@dataclass(frozen=True)
class LocalSolveRequest:
    """One agent's local NLP at one ADMM iteration (all arrays, picklable)."""

    agent: int
    initial_guess: np.ndarray
    parameters: np.ndarray
    lower_bounds: np.ndarray
    upper_bounds: np.ndarray
    constraint_multipliers: np.ndarray | None = None
    bound_multipliers: np.ndarray | None = None
    warm_start: bool = True  # False when the guess is not a previous solution
    update: int = 0  # MPC update number (for messages on a network, and their logs)
    iteration: int = 0  # ADMM iteration within the update


@dataclass(frozen=True)
class LocalSolverSpec:
    """How to build the (agent-independent) local solver; picklable, so workers build their own."""

    settings: MpcSettings
    agent_count: int
    compiler: NlpCompiler | None = None

    def build(self) -> NlpSolver:
        problem = build_transport_problem(self.settings, self.agent_count, local=True)
        return NlpSolver(problem.nlp, self.settings.solver, self.compiler)


def solve_request(solver: NlpSolver, request: LocalSolveRequest) -> NlpSolution:
    return solver.solve(
        request.initial_guess, request.parameters, request.lower_bounds, request.upper_bounds,
        request.constraint_multipliers, request.bound_multipliers, request.warm_start,
    )


class LocalSolveExecutor(Protocol):
    def solve_all(self, requests: list[LocalSolveRequest]) -> list[NlpSolution]:
        """Solve every request (one per agent); results in request order."""
        ...

    def close(self) -> None: ...


class SerialExecutor:
    """All local solves one after another in this process, with one built solver."""

    def __init__(self, spec: LocalSolverSpec) -> None:
        self._solver = spec.build()

    def solve_all(self, requests: list[LocalSolveRequest]) -> list[NlpSolution]:
        return [solve_request(self._solver, request) for request in requests]

    def close(self) -> None:
        pass


def consensus_step(received: np.ndarray, duals: np.ndarray, consensus: np.ndarray,
                   fresh: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(s-bar, duals) after one ADMM iteration; ``received`` and ``duals`` have one row per
    agent.

    Every agent fresh (the paper's update): s-bar = mean_j (s^j + w^j), then w^j += s^j -
    s-bar, which leaves the duals summing to zero over the agents. Some agents fresh (a
    gated channel, ``ChannelSettings.max_age_rounds``): s-bar = the mean of the fresh agents'
    s^j, and only their duals move, w^j += s^j - s-bar; the moves sum to zero, so the duals'
    sum stays what it was (zero), and a lone fresh agent keeps its dual instead of losing it.
    (With the duals summing to zero, both forms give the same s-bar.) With no fresh agent both
    stay as they were."""
    if fresh is None or fresh.all():
        new_consensus = np.mean(received + duals, axis=0)
        return new_consensus, duals + received - new_consensus
    if not fresh.any():
        return consensus, duals
    new_consensus = np.mean(received[fresh], axis=0)
    new_duals = duals.copy()
    new_duals[fresh] = duals[fresh] + received[fresh] - new_consensus
    return new_consensus, new_duals


def fallback_solution(result: NlpSolution, guess: np.ndarray) -> NlpSolution:
    """A non-finite local result is replaced by its warm start (its stats still say it failed)."""
    if np.all(np.isfinite(result.decision)):
        return result
    return NlpSolution(guess, np.zeros_like(result.constraint_multipliers),
                       np.zeros_like(result.bound_multipliers), result.stats)


@dataclass
class AgentAdmm:
    """One agent's run of an update's ADMM iterations without a coordinator: its final local
    solution, and per iteration its solve's stats, its s^i and the s-bar after it; the duals
    of every agent at the end. ``failure`` says why it stopped early (a silent peer)."""

    solution: NlpSolution
    stats: list[SolveStats] = field(default_factory=list)
    shared: list[np.ndarray] = field(default_factory=list)
    consensus: list[np.ndarray] = field(default_factory=list)
    duals: np.ndarray | None = None
    failure: str = ""


# (iteration, this agent's s^i) -> every agent's s^j (one row each), or None if one is silent
Exchange = Callable[[int, np.ndarray], "np.ndarray | None"]


def run_agent_admm(solver: NlpSolver, request: LocalSolveRequest, consensus: np.ndarray,
                   duals: np.ndarray, iterations: int, target: slice,
                   shared_indices: np.ndarray, exchange: Exchange) -> AgentAdmm:
    """Agent ``request.agent``'s side of ``iterations`` ADMM iterations: solve with the
    consensus target s-bar - w^i (in ``target`` of the parameters), hand s^i to ``exchange``,
    and from every agent's s^j compute s-bar and every dual (``consensus_step``), as the
    coordinator would. Warm starts as in ``DistributedMpc.update``."""
    run = AgentAdmm(solution=NlpSolution(request.initial_guess, np.zeros(0), np.zeros(0),
                                         SolveStats("not run", False, 0, 0.0,
                                                    float("nan"), float("nan"))))
    current = request
    for iteration in range(iterations):
        parameters = request.parameters.copy()
        parameters[target] = consensus - duals[request.agent]
        current = replace(current, parameters=parameters, iteration=iteration)
        solution = fallback_solution(solve_request(solver, current), current.initial_guess)
        shared = solution.decision[shared_indices]
        run.solution = solution
        run.stats.append(solution.stats)
        run.shared.append(shared)
        received = exchange(iteration, shared)
        if received is None:
            run.failure = f"a peer was silent at ADMM iteration {iteration}"
            run.solution = replace(solution, stats=replace(
                solution.stats, status=run.failure, success=False))
            return run
        consensus, duals = consensus_step(received, duals, consensus)
        run.consensus.append(consensus)
        current = replace(current, initial_guess=solution.decision,
                          constraint_multipliers=solution.constraint_multipliers,
                          bound_multipliers=solution.bound_multipliers, warm_start=True)
    run.duals = duals
    return run
