"""Where ADMM local solves run. The algorithm hands over plain arrays and gets solutions back,
so the same code runs serially, in worker processes
(``deploy.nmpc_runtime.process_executor``) or in agent processes over a network
(``deploy.agents.zenoh_executor``)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from core.nmpc.nlp_solver import NlpCompiler, NlpSolution, NlpSolver
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
