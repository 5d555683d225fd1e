"""ADMM distributed NMPC (paper Sec. III): n_A local NLPs coordinated by consensus over the
payload-state and wrench trajectories.

Per MPC update, warm-started from the shifted previous step, for r = 0 .. iterations-1:

1. local step: every agent i solves min J^i(z^i) + 1/2 ||s^i - s_bar_r + w_r^i||_P^2 over Z^i;
2. consensus: s_bar_{r+1} = mean_i (s^i_{r+1} + w^i_r);
3. scaled dual update: w^i_{r+1} = w^i_r + s^i_{r+1} - s_bar_{r+1}.

Residuals per iteration: primal r^i = s^i - s_bar (payload-state and wrench parts separately)
and dual ||P (s_bar_{r+1} - s_bar_r)||. The wrench-only ablation is the same algorithm with
``coupling.enabled = False`` and a small or zero ``admm.rho_state``.

Two topologies, one controller protocol (``core.nmpc.team_mpc.TeamMpc``): ``DistributedMpc``
coordinates the iterations here (its executor solves each round's local NLPs), and
``core.admm.admm_peer_mpc.PeerDistributedMpc`` hands the whole update to agents that run the
iterations among themselves. ``AdmmMpc`` holds what both share: the update's preparation, the
warm start and the plan.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from core.admm.admm_executor import (
    AgentAdmm,
    LocalSolveExecutor,
    LocalSolveRequest,
    LocalSolverSpec,
    SerialExecutor,
    consensus_step,
    fallback_solution,
)
from core.communication.lossy_channel import LossyChannel
from core.model.srb_model import STATE_SIZE, WRENCH_SIZE
from core.model.team import TeamModel
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import AdmmIteration, MpcPlan, decode_plan
from core.nmpc.nlp_solver import NlpCompiler, NlpSolution, SolveStats
from core.nmpc.settings import MpcSettings
from core.nmpc.transport_problem import build_transport_problem
from core.nmpc.warm_start import ControllerMemory, initial_guess, shifted_multipliers

__all__ = ["AdmmMpc", "AdmmStart", "DistributedMpc", "PeerExecutor"]


class PeerExecutor(Protocol):
    """Agents that run an update's ADMM iterations among themselves (``run_admm``)."""

    def run_admm(self, requests: list[LocalSolveRequest], consensus: np.ndarray,
                 duals: np.ndarray, iterations: int) -> list[AgentAdmm]: ...

    def close(self) -> None: ...


@dataclass
class AdmmStart:
    """What one update's iterations start from: each agent's initial guess, bounds, obstacle
    selection, parameters (consensus target zero) and warm multipliers, and s-bar and the
    duals shifted from the previous update."""

    guesses: list[np.ndarray]
    bounds: list[tuple[np.ndarray, np.ndarray]]
    selections: list
    parameters: list[np.ndarray]
    multipliers: list[tuple[np.ndarray, np.ndarray] | None]
    consensus: np.ndarray
    duals: np.ndarray


class AdmmMpc:
    """Receding-horizon ADMM distributed NMPC; ``update`` is one MPC step, its iterations
    ``_iterate``'s (one topology per subclass)."""

    def __init__(self, team: TeamModel, settings: MpcSettings) -> None:
        self.team = team
        self.settings = settings
        self.problem = build_transport_problem(settings, team.agent_count, local=True)
        self.weights = self.problem.consensus_weights()
        self._updates = 0  # MPC updates so far (numbers the local-solve requests)
        self._payload_size = settings.horizon_steps * STATE_SIZE
        self.channel: LossyChannel | None = None  # uplink: s^i to the consensus
        self.downlink: LossyChannel | None = None  # s-bar - w^i to the agents
        self.executor: LocalSolveExecutor | PeerExecutor | None = None
        self.reset()

    def reset(self) -> None:
        self._previous: list[NlpSolution | None] = [None] * self.team.agent_count
        self._consensus: np.ndarray | None = None
        self._duals = np.zeros((self.team.agent_count, self.weights.size))
        for channel in (self.channel, self.downlink):
            if channel is not None:
                channel.reset()

    def close(self) -> None:
        """Stop the executor's workers or agents (if any)."""
        if self.executor is not None:
            self.executor.close()

    def memory(self) -> ControllerMemory:
        """The warm start the next ``update`` will use (references, not copies)."""
        return ControllerMemory(list(self._previous), self._consensus,
                                None if self._consensus is None else self._duals)

    def restore(self, memory: ControllerMemory) -> None:
        """Continue from ``memory`` (e.g. a logged keyframe): the next update uses it."""
        if len(memory.previous) != self.team.agent_count:
            raise ValueError(f"memory has {len(memory.previous)} agents, the controller "
                             f"{self.team.agent_count}")
        self._previous = list(memory.previous)
        self._consensus = memory.consensus
        self._duals = (np.zeros((self.team.agent_count, self.weights.size))
                       if memory.duals is None else np.array(memory.duals))

    def update(self, inputs: MpcInputs, iterations: int | None = None) -> MpcPlan:
        start = time.perf_counter()
        iterations = iterations or self.settings.admm.iterations
        begin = self._start(inputs)
        self._updates += 1
        solutions, records, consensus, duals, warnings = self._iterate(begin, iterations)
        self._previous = list(solutions)
        self._consensus, self._duals = consensus, duals
        plan = self._plan(inputs, solutions, consensus)
        plan.warnings.extend(warnings)
        plan.admm_iterations = records
        plan.solves = [stats for record in records for stats in record.solves]
        plan.success = all(stats.success for stats in plan.solves)
        plan.flag_unsafe_start(inputs.safety_values())
        plan.flag_relaxed_barriers(self.settings.safety.slack_tolerance_m)
        plan.flag_dropped_obstacles(begin.selections)
        plan.update_time_s = time.perf_counter() - start
        return plan

    def _iterate(self, begin: AdmmStart, iterations: int
                 ) -> tuple[list[NlpSolution], list[AdmmIteration], np.ndarray, np.ndarray,
                            list[str]]:
        """The update's ``iterations``: solutions, iteration records, s-bar, duals, warnings."""
        raise NotImplementedError

    def _start(self, inputs: MpcInputs) -> AdmmStart:
        na = self.team.agent_count
        self.problem.validate(inputs)  # once: the problem's own checks below are skipped
        guesses = [initial_guess(self.problem, self.team, inputs, self._previous[i], agent=i)
                   for i in range(na)]
        bounds = [self.problem.decision_bounds(inputs.contacts, agent=i, inputs=inputs)
                  for i in range(na)]
        # Everything but the consensus target is fixed during the update: build it once.
        zero_target = np.zeros(self.weights.size)
        selections = [self.problem.select_obstacles(inputs, guesses[i], agent=i, validated=True)
                      for i in range(na)]
        parameters = [self.problem.parameter_vector(self.team, inputs, agent=i,
                                                    consensus_target=zero_target,
                                                    selection=selections[i], validated=True)
                      for i in range(na)]
        if self._consensus is None:
            consensus = np.mean([self.problem.shared_trajectory(g) for g in guesses], axis=0)
            duals = np.zeros_like(self._duals)
        else:
            consensus = self._shift_shared(self._consensus)
            duals = np.array([self._shift_shared(w) for w in self._duals])
        # Iteration 0 starts from the previous update's multipliers, shifted like the primal;
        # iteration r + 1 from iteration r's (same instant: only the consensus target moved).
        multipliers = [None if previous is None else shifted_multipliers(self.problem, previous)
                       for previous in self._previous]
        return AdmmStart(guesses, bounds, selections, parameters, multipliers, consensus, duals)

    def _plan(self, inputs: MpcInputs, solutions: list[NlpSolution], consensus: np.ndarray
              ) -> MpcPlan:
        """One wrench source per robot, its own local solution: robot i's trajectory, GRFs and
        wrench trajectory all come from local problem i, where they satisfy robot i's dynamics
        together (the consensus wrench does not, by the consensus gap). The payload prediction
        is the consensus trajectory, which is also kept whole (``consensus_trajectory``)."""
        n = self.settings.horizon_steps
        plan = decode_plan(self.problem, self.team, solutions[0].decision, agent=0)
        for i in range(1, self.team.agent_count):
            own = decode_plan(self.problem, self.team, solutions[i].decision, agent=i)
            plan.robot_trajectories[i] = own.robot_trajectories[i]
            plan.grf_trajectories[i] = own.grf_trajectories[i]
            plan.grf[i] = own.grf[i]
            plan.wrench[i] = own.wrench[i]
            plan.wrench_trajectories[i] = own.wrench_trajectories[i]
            plan.barrier_slack_m = max(plan.barrier_slack_m, own.barrier_slack_m)
        plan.payload_trajectory = np.vstack([
            inputs.payload_state, consensus[: self._payload_size].reshape(n, STATE_SIZE)
        ])
        plan.consensus_trajectory = consensus
        return plan

    def _residuals(self, primal: np.ndarray, consensus_change: np.ndarray,
                   stats: list[SolveStats]) -> AdmmIteration:
        """Residuals of one iteration from r^i = s^i - s_bar (n_A rows) and s_bar_r - s_bar_{r-1}."""
        n, na = self.settings.horizon_steps, self.team.agent_count
        payload = primal[:, : self._payload_size].reshape(na, n, STATE_SIZE)
        wrench = primal[:, self._payload_size :].reshape(na, na * n, WRENCH_SIZE)
        return AdmmIteration(
            primal_payload_rms=_rms(primal[:, : self._payload_size]),
            primal_wrench_rms=_rms(primal[:, self._payload_size :]),
            dual_norm=float(np.linalg.norm(self.weights * consensus_change)),
            solves=tuple(stats),
            primal_position_rms_m=_rms(payload[:, :, 0:3].reshape(na, -1)),
            primal_force_rms_n=_rms(wrench[:, :, 0:3].reshape(na, -1)),
        )

    def _shift_shared(self, shared: np.ndarray) -> np.ndarray:
        """Shift a shared-trajectory vector one stage, repeating the last stage."""
        n = self.settings.horizon_steps
        payload = shared[: self._payload_size].reshape(n, STATE_SIZE)
        wrenches = shared[self._payload_size :].reshape(self.team.agent_count, n, WRENCH_SIZE)
        payload = np.vstack([payload[1:], payload[-1:]])
        wrenches = np.concatenate([wrenches[:, 1:], wrenches[:, -1:]], axis=1)
        return np.concatenate([payload.reshape(-1), wrenches.reshape(-1)])


class DistributedMpc(AdmmMpc):
    """ADMM coordinated here: each round, ``executor`` solves every agent's local NLP
    (serially here by default), and this process forms s-bar and the duals, through the
    emulated lossy channel where ``admm.channel`` sets one (both directions by default)."""

    def __init__(self, team: TeamModel, settings: MpcSettings,
                 executor: LocalSolveExecutor | None = None,
                 compiler: NlpCompiler | None = None) -> None:
        super().__init__(team, settings)
        channel = settings.admm.channel
        self.channel = (None if channel.perfect
                        else LossyChannel(channel, team.agent_count, self._shift_shared))
        self.downlink = (None if channel.perfect or not channel.downlink
                         else LossyChannel(channel, team.agent_count, self._shift_shared,
                                           stream=1))
        self.executor = self.local = executor or SerialExecutor(
            LocalSolverSpec(settings, team.agent_count, compiler))

    def _iterate(self, begin: AdmmStart, iterations: int
                 ) -> tuple[list[NlpSolution], list[AdmmIteration], np.ndarray, np.ndarray,
                            list[str]]:
        na = self.team.agent_count
        target_slice = self.problem.nlp.parameters.slice("consensus_target")
        consensus, duals = begin.consensus, begin.duals
        solutions: list[NlpSolution] = []
        records: list[AdmmIteration] = []
        for iteration in range(iterations):
            # The agents' targets s-bar - w^i, through the downlink where it is lossy: each
            # agent solves with the newest target it holds (hold-last, as the paper's channel).
            targets = consensus - duals
            if self.downlink is not None:
                targets, _ = self.downlink.exchange(targets, self._updates)
            requests = []
            for i in range(na):
                warm = ((solutions[i].constraint_multipliers, solutions[i].bound_multipliers)
                        if solutions else begin.multipliers[i])
                agent_parameters = begin.parameters[i].copy()
                agent_parameters[target_slice] = targets[i]
                requests.append(LocalSolveRequest(
                    agent=i,
                    initial_guess=solutions[i].decision if solutions else begin.guesses[i],
                    parameters=agent_parameters,
                    lower_bounds=begin.bounds[i][0],
                    upper_bounds=begin.bounds[i][1],
                    constraint_multipliers=None if warm is None else warm[0],
                    bound_multipliers=None if warm is None else warm[1],
                    warm_start=warm is not None,
                    update=self._updates,
                    iteration=iteration,
                ))
            results = self.local.solve_all(requests)
            solutions = [fallback_solution(result, request.initial_guess)
                         for result, request in zip(results, requests, strict=True)]
            shared = np.array([self.problem.shared_trajectory(s.decision) for s in solutions])
            # Through the network (ChannelSettings): the coordinator's consensus and duals see
            # what arrived (held last); the residuals recorded are the agents' true gaps.
            received, fresh = ((shared, np.ones(na, dtype=bool)) if self.channel is None
                               else self.channel.exchange(shared, self._updates))
            new_consensus, duals = consensus_step(received, duals, consensus, fresh)
            records.append(self._residuals(shared - new_consensus, new_consensus - consensus,
                                           [result.stats for result in results]))
            consensus = new_consensus
        return solutions, records, consensus, duals, []


def _rms(values: np.ndarray) -> np.ndarray:
    return np.sqrt(np.mean(np.square(values), axis=1))
