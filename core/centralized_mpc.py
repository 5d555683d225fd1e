"""Centralized NMPC baseline: one NLP over every robot, the payload and every wrench."""

from __future__ import annotations

import time

import numpy as np

from core.mpc_inputs import MpcInputs
from core.mpc_plan import MpcPlan
from core.nlp_solver import NlpCompiler, NlpSolution, NlpSolver
from core.settings import MpcSettings
from core.team_model import TeamModel
from core.transport_problem import TransportProblem, build_transport_problem
from core.warm_start import conform_forces, shift_solution


class CentralizedMpc:
    """Receding-horizon centralized NMPC; ``update`` is one MPC step."""

    def __init__(
        self,
        team: TeamModel,
        settings: MpcSettings,
        compiler: NlpCompiler | None = None,
        shared_cost_copies: float = 1.0,
    ) -> None:
        self.team = team
        self.settings = settings
        self.problem = build_transport_problem(
            settings, team.agent_count, local=False, shared_cost_copies=shared_cost_copies
        )
        self.solver = NlpSolver(self.problem.nlp, settings.solver, compiler)
        self._previous: NlpSolution | None = None

    def reset(self) -> None:
        self._previous = None

    def update(self, inputs: MpcInputs) -> MpcPlan:
        start = time.perf_counter()
        parameters = self.problem.parameter_vector(self.team, inputs)
        guess = initial_guess(self.problem, self.team, inputs, self._previous, agent=None)
        lower, upper = self.problem.decision_bounds(inputs.contacts)
        previous = self._previous
        solution = self.solver.solve(
            guess, parameters, lower, upper,
            None if previous is None else previous.constraint_multipliers,
            None if previous is None else previous.bound_multipliers,
            warm_start=previous is not None,
        )
        usable = bool(np.all(np.isfinite(solution.decision)))
        decision = solution.decision if usable else guess
        if usable:
            self._previous = solution
        plan = decode_plan(self.problem, self.team, decision)
        plan.solves = [solution.stats]
        plan.success = solution.stats.success
        plan.flag_unsafe_start(inputs.safety_values())
        plan.update_time_s = time.perf_counter() - start
        return plan


def initial_guess(
    problem: TransportProblem,
    team: TeamModel,
    inputs: MpcInputs,
    previous: NlpSolution | None,
    agent: int | None,
) -> np.ndarray:
    """Shifted previous solution, or a cold guess holding the measured states with nominal
    forces; GRFs are conformed to the contact schedule either way."""
    layout = problem.nlp.decision
    n = problem.horizon_steps
    g = problem.settings.gravity_m_s2
    payload_share_kg = team.payload.mass_kg / team.agent_count
    if previous is not None:
        guess = shift_solution(layout, n, previous.decision)
    else:
        guess = np.zeros(layout.size)
        for k in range(n + 1):
            for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
                layout.put(guess, f"robot_{key}@{k}", inputs.robot_states[r])
            layout.put(guess, f"payload@{k}", inputs.payload_state)
            if k < n:
                for j in range(team.agent_count):
                    layout.put(guess, f"wrench_{j}@{k}",
                               np.array([0, 0, payload_share_kg * g, 0, 0, 0]))
    for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
        conform_forces(guess, layout, f"grf_{key}", inputs.contacts[r],
                       team.robots[r].mass_kg + payload_share_kg, g)
    return guess


def decode_plan(problem: TransportProblem, team: TeamModel, decision: np.ndarray,
                agent: int | None = None) -> MpcPlan:
    """Trajectories of the robots in ``problem`` (others left zero), payload and wrenches."""
    layout = problem.nlp.decision
    n = problem.horizon_steps
    na = team.agent_count
    robots = np.zeros((na, n + 1, 12))
    grfs = np.zeros((na, n, 12))
    for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
        robots[r] = [layout.get(decision, f"robot_{key}@{k}") for k in range(n + 1)]
        grfs[r] = [layout.get(decision, f"grf_{key}@{k}") for k in range(n)]
    payload = np.array([layout.get(decision, f"payload@{k}") for k in range(n + 1)])
    wrenches = np.array([[layout.get(decision, f"wrench_{j}@{k}") for k in range(n)]
                         for j in range(na)])
    return MpcPlan(
        grf=grfs[:, 0].copy(), wrench=wrenches[:, 0].copy(), robot_trajectories=robots,
        payload_trajectory=payload, grf_trajectories=grfs, wrench_trajectories=wrenches,
        solves=[], success=True, update_time_s=0.0,
    )
