"""How far the real-time iteration lands from a converged solve, in closed loop: every warm
local solve of an ``rti`` run is solved again, from the same request, by converged fatrop;
the first-stage GRF differences [N] are summarized (median, p95, max)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.admm.admm_executor import (
    LocalSolveRequest,
    LocalSolverSpec,
    SerialExecutor,
    solve_request,
)
from core.admm.admm_mpc import DistributedMpc
from core.nmpc.nlp_solver import NlpSolution
from core.nmpc.settings import MpcSettings
from core.plant.closed_loop import run_closed_loop
from core.plant.standard_scenarios import standard_scenario
from drivers.robot_descriptions import srb_parameters

__all__ = ["RtiFidelity", "rti_fidelity"]


@dataclass(frozen=True)
class RtiFidelity:
    """First-stage GRF difference [N] of each warm RTI local solve from converged fatrop."""

    agents: int
    solves: int
    converged_failures: int  # fatrop did not converge on these: left out of the figures
    median_n: float
    p95_n: float
    max_n: float


class _ComparingExecutor(SerialExecutor):
    def __init__(self, spec: LocalSolverSpec, converged: LocalSolverSpec) -> None:
        super().__init__(spec)
        self._converged = converged.build()
        self._layout = self._converged.problem.decision
        self.differences_n: list[float] = []
        self.failures = 0

    def solve_all(self, requests: list[LocalSolveRequest]) -> list[NlpSolution]:
        results = super().solve_all(requests)
        for request, result in zip(requests, results, strict=True):
            if not request.warm_start:
                continue  # a cold RTI start iterates to convergence already
            reference = solve_request(self._converged, request)
            if not reference.stats.success:
                self.failures += 1
                continue
            difference = (self._layout.get(result.decision, "grf_self@0")
                          - self._layout.get(reference.decision, "grf_self@0"))
            self.differences_n.append(float(np.max(np.abs(difference))))
        return results


def rti_fidelity(agents: int, settings: MpcSettings, compiler, duration_s: float
                 ) -> RtiFidelity:
    """Closed loop of the standard scenario (SRB plant, serial local solves) with ``settings``
    (an ``rti`` solver), each warm local solve compared with converged fatrop."""
    scenario = standard_scenario(agents, srb_parameters)
    fatrop = settings.model_copy(update={"solver": settings.solver.model_copy(
        update={"name": "fatrop"})})
    executor = _ComparingExecutor(LocalSolverSpec(settings, agents, compiler),
                                  LocalSolverSpec(fatrop, agents, compiler))
    controller = DistributedMpc(scenario.team, settings, executor=executor)
    try:
        run_closed_loop(controller, scenario.team, scenario.team, settings,
                        scenario.reference, scenario.obstacles, duration_s)
    finally:
        controller.close()
    values = np.asarray(executor.differences_n) if executor.differences_n else np.full(1, np.nan)
    return RtiFidelity(agents, len(executor.differences_n), executor.failures,
                       float(np.median(values)), float(np.percentile(values, 95)),
                       float(np.max(values)))
