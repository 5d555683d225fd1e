"""Coordinator-free ADMM (paper Sec. III, the agents' side of the iterations): the whole update
goes to agents that solve, exchange s^i with each other and compute s-bar and every dual
themselves (``deploy.agents``: ``porter agent`` over Zenoh with ``network.topology: peer``).
This process prepares the update (``core.admm.admm_mpc.AdmmMpc``), hands it over and keeps
s-bar and the duals between updates."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from core.admm.admm_executor import AgentAdmm, LocalSolveRequest
from core.admm.admm_mpc import AdmmMpc, AdmmStart, PeerExecutor
from core.model.team import TeamModel
from core.nmpc.mpc_plan import AdmmIteration
from core.nmpc.nlp_solver import NlpSolution
from core.nmpc.settings import MpcSettings

__all__ = ["PeerDistributedMpc"]


class PeerDistributedMpc(AdmmMpc):
    """ADMM run by the agents behind ``executor``; the emulated lossy channel
    (``admm.channel``) is the coordinator's and has no place here."""

    def __init__(self, team: TeamModel, settings: MpcSettings, executor: PeerExecutor) -> None:
        if not settings.admm.channel.perfect:
            raise ValueError("admm.channel (the emulated lossy channel) applies at the "
                             "coordinator; the coordinator-free topology has none")
        super().__init__(team, settings)
        self.executor = self.peers = executor

    def _iterate(self, begin: AdmmStart, iterations: int
                 ) -> tuple[list[NlpSolution], list[AdmmIteration], np.ndarray, np.ndarray,
                            list[str]]:
        requests = []
        for i, warm in enumerate(begin.multipliers):
            requests.append(LocalSolveRequest(
                agent=i, initial_guess=begin.guesses[i], parameters=begin.parameters[i],
                lower_bounds=begin.bounds[i][0], upper_bounds=begin.bounds[i][1],
                constraint_multipliers=None if warm is None else warm[0],
                bound_multipliers=None if warm is None else warm[1],
                warm_start=warm is not None, update=self._updates))
        runs = self.peers.run_admm(requests, begin.consensus, begin.duals, iterations)
        return self._from_agents(runs, begin.consensus, begin.duals, iterations)

    def _from_agents(self, runs: list[AgentAdmm], consensus: np.ndarray, duals: np.ndarray,
                     iterations: int) -> tuple[list[NlpSolution], list[AdmmIteration],
                                               np.ndarray, np.ndarray, list[str]]:
        """Solutions, iteration records, s-bar and duals from agents that ran the ADMM
        without a coordinator. They must agree on s-bar (same inputs, same arithmetic): a
        disagreement is a warning. One agent that stopped early fails the whole update."""
        solutions = [run.solution for run in runs]
        if any(run.failure for run in runs):
            # an agent that finished still followed an s-bar its stopped peer never shared in:
            # its solve counts as failed too
            stats = [replace(run.solution.stats, success=False,
                             status=run.solution.stats.status if run.failure
                             else "a peer stopped the update") for run in runs]
            solutions = [replace(s, stats=st) for s, st in zip(solutions, stats, strict=True)]
            shared = np.array([self.problem.shared_trajectory(s.decision) for s in solutions])
            record = self._residuals(shared - consensus, np.zeros_like(consensus), stats)
            return solutions, [record], consensus, duals, []
        records, previous = [], consensus
        for r in range(iterations):
            shared = np.array([run.shared[r] for run in runs])
            records.append(self._residuals(shared - runs[0].consensus[r],
                                           runs[0].consensus[r] - previous,
                                           [run.stats[r] for run in runs]))
            previous = runs[0].consensus[r]
        gap = max(float(np.max(np.abs(run.consensus[-1] - previous))) for run in runs)
        warnings = ([f"ADMM agents disagree on the consensus by {gap:.3g}"] if gap > 0.0
                    else [])
        assert runs[0].duals is not None
        return solutions, records, previous, runs[0].duals, warnings
