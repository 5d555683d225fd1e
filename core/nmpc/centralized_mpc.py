"""Centralized NMPC baseline: one NLP over every robot, the payload and every wrench."""

from __future__ import annotations

import time

import numpy as np

from core.model.team import TeamModel
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan, decode_plan
from core.nmpc.nlp_solver import NlpCompiler, NlpSolution, NlpSolver
from core.nmpc.settings import MpcSettings
from core.nmpc.transport_problem import build_transport_problem
from core.nmpc.warm_start import ControllerMemory, initial_guess, shifted_multipliers


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

    def close(self) -> None:
        """Nothing to release: the solver runs in this process."""

    def memory(self) -> ControllerMemory:
        """The warm start the next ``update`` will use (a reference, not a copy)."""
        return ControllerMemory([self._previous])

    def restore(self, memory: ControllerMemory) -> None:
        """Continue from ``memory`` (e.g. a logged keyframe): the next update uses it."""
        self._previous = memory.previous[0]

    def update(self, inputs: MpcInputs) -> MpcPlan:
        start = time.perf_counter()
        self.problem.validate(inputs)  # once: the problem's own checks below are skipped
        guess = initial_guess(self.problem, self.team, inputs, self._previous, agent=None)
        selection = self.problem.select_obstacles(inputs, guess, validated=True)
        parameters = self.problem.parameter_vector(self.team, inputs, selection=selection,
                                                   validated=True)
        lower, upper = self.problem.decision_bounds(inputs.contacts, inputs=inputs)
        previous = self._previous
        lam_g, lam_x = (None, None) if previous is None else shifted_multipliers(
            self.problem, previous)
        solution = self.solver.solve(guess, parameters, lower, upper, lam_g, lam_x,
                                     warm_start=previous is not None)
        usable = bool(np.all(np.isfinite(solution.decision)))
        decision = solution.decision if usable else guess
        if usable:
            self._previous = solution
        plan = decode_plan(self.problem, self.team, decision)
        plan.solves = [solution.stats]
        plan.success = solution.stats.success
        plan.flag_unsafe_start(inputs.safety_values())
        plan.flag_relaxed_barriers(self.settings.safety.slack_tolerance_m)
        plan.flag_dropped_obstacles([selection])
        plan.update_time_s = time.perf_counter() - start
        return plan
