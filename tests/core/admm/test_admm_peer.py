"""The coordinator-free ADMM: agents that exchange their s^i and compute s-bar and every dual
themselves (``run_agent_admm``) reach the coordinator's s-bar, duals and plan on identical
inputs, agree among themselves, and one silent peer fails the update for every robot."""

from __future__ import annotations

import threading

import numpy as np
import pytest

from core.admm.admm_executor import (
    AgentAdmm,
    LocalSolveRequest,
    LocalSolverSpec,
    consensus_step,
    run_agent_admm,
)
from core.admm.admm_mpc import DistributedMpc
from core.admm.admm_peer_mpc import PeerDistributedMpc
from core.nmpc.layout import shared_indices
from core.nmpc.settings import ChannelSettings
from tests.core.controller_fixtures import inputs_at_start, settings, team


class _ThreadPeers:
    """Each agent's ADMM in a thread of its own with its own solver; the exchange is a barrier
    (every agent's s^i of an iteration, or None for the agents told to go silent)."""

    def __init__(self, spec: LocalSolverSpec, silent: int | None = None) -> None:
        self.solvers = [spec.build() for _ in range(spec.agent_count)]
        self.spec, self.silent = spec, silent
        problem = self.solvers[0].problem
        self.target = problem.parameters.slice("consensus_target")
        self.indices = shared_indices(problem.decision, spec.settings.horizon_steps,
                                      spec.agent_count)

    def run_admm(self, requests: list[LocalSolveRequest], consensus: np.ndarray,
                 duals: np.ndarray, iterations: int) -> list[AgentAdmm]:
        n = len(requests)
        board: dict[tuple[int, int], np.ndarray] = {}
        barrier = threading.Barrier(n)
        runs: list[AgentAdmm | None] = [None] * n

        def exchange(agent: int, iteration: int, shared: np.ndarray) -> np.ndarray | None:
            if agent != self.silent:
                board[(iteration, agent)] = shared
            barrier.wait()
            if any((iteration, j) not in board for j in range(n)):
                return None
            return np.array([board[(iteration, j)] for j in range(n)])

        def agent(i: int) -> None:
            runs[i] = run_agent_admm(self.solvers[i], requests[i], consensus.copy(),
                                     duals.copy(), iterations, self.target, self.indices,
                                     lambda r, s: exchange(i, r, s))

        threads = [threading.Thread(target=agent, args=(i,)) for i in range(n)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        return [run for run in runs if run is not None]

    def solve_all(self, requests: list) -> list:
        raise AssertionError("a coordinator-free update hands over whole updates")

    def close(self) -> None:
        pass


def test_consensus_step_is_the_papers_update() -> None:
    received = np.array([[1.0, 2.0], [3.0, 6.0]])
    duals = np.array([[0.5, 0.0], [-0.5, 0.0]])
    consensus, new_duals = consensus_step(received, duals, np.zeros(2))
    np.testing.assert_allclose(consensus, [2.0, 4.0])  # mean of s^j + w^j
    np.testing.assert_allclose(new_duals, [[-0.5, -2.0], [0.5, 2.0]])  # w + s - s_bar
    held, kept = consensus_step(received, duals, np.ones(2), np.zeros(2, dtype=bool))
    np.testing.assert_array_equal(held, np.ones(2))  # nobody fresh: nothing moves
    assert kept is duals


def test_a_gated_round_keeps_the_duals_summing_to_zero() -> None:
    rng = np.random.default_rng(3)
    received = rng.normal(size=(3, 4))
    duals = rng.normal(size=(3, 4))
    duals -= duals.mean(axis=0)  # the invariant the paper's update keeps
    for fresh in ([True, False, False], [True, True, False], [False, True, True]):
        mask = np.array(fresh)
        consensus, new_duals = consensus_step(received, duals, np.zeros(4), mask)
        np.testing.assert_allclose(new_duals.sum(axis=0), 0.0, atol=1e-12)
        np.testing.assert_allclose(consensus, received[mask].mean(axis=0))
        np.testing.assert_array_equal(new_duals[~mask], duals[~mask])  # held agents wait
    # a lone fresh agent keeps its dual (not reset to zero)
    _, lone = consensus_step(received, duals, np.zeros(4), np.array([True, False, False]))
    np.testing.assert_allclose(lone[0], duals[0])
    # with every agent fresh, both forms agree on s-bar under the invariant
    everyone, _ = consensus_step(received, duals, np.zeros(4), np.ones(3, dtype=bool))
    np.testing.assert_allclose(everyone, received.mean(axis=0), atol=1e-12)


def test_peers_reach_the_coordinators_consensus_on_identical_inputs() -> None:
    mpc, model = settings(), team()
    inputs = inputs_at_start(model, mpc)
    spec = LocalSolverSpec(mpc, model.agent_count)
    coordinator, peers = DistributedMpc(model, mpc), PeerDistributedMpc(model, mpc,
                                                                        _ThreadPeers(spec))
    for _ in range(2):  # the second update starts from the shifted consensus and duals
        central, shared = coordinator.update(inputs), peers.update(inputs)
        assert shared.success and not shared.warnings
        np.testing.assert_allclose(shared.consensus_trajectory, central.consensus_trajectory,
                                   rtol=0, atol=1e-9)
        np.testing.assert_allclose(shared.grf, central.grf, atol=1e-6)
        assert len(shared.admm_iterations) == len(central.admm_iterations) == 2
        for ours, theirs in zip(shared.admm_iterations, central.admm_iterations, strict=True):
            np.testing.assert_allclose(ours.primal_wrench_rms, theirs.primal_wrench_rms,
                                       atol=1e-9)
            assert abs(ours.dual_norm - theirs.dual_norm) <= 1e-9 * max(1.0, theirs.dual_norm)
    np.testing.assert_allclose(peers.memory().duals, coordinator.memory().duals, atol=1e-9)


def test_a_silent_peer_fails_the_update_of_every_robot() -> None:
    mpc, model = settings(), team()
    spec = LocalSolverSpec(mpc, model.agent_count)
    plan = PeerDistributedMpc(model, mpc, _ThreadPeers(spec, silent=1)).update(
        inputs_at_start(model, mpc))
    assert not plan.success
    assert all(not stats.success for stats in plan.solves)
    assert any("silent" in stats.status for stats in plan.solves)
    assert np.all(np.isfinite(plan.grf))  # the warm start stands in: the plan stays usable


def test_an_agent_that_finished_fails_too_when_a_peer_stopped() -> None:
    """One agent completed its iterations, the other stopped: the update fails for both."""
    mpc, model = settings(), team()
    spec = LocalSolverSpec(mpc, model.agent_count)
    controller = PeerDistributedMpc(model, mpc, _ThreadPeers(spec))
    inputs = inputs_at_start(model, mpc)
    runs = controller.peers.run_admm(*_first_requests(controller, inputs), 2)
    assert all(not run.failure for run in runs)
    runs[1].failure = "a peer was silent at ADMM iteration 1"
    consensus = runs[0].consensus[0]
    solutions, records, kept, _, _ = controller._from_agents(runs, consensus, runs[0].duals, 2)
    assert [s.stats.success for s in solutions] == [False, False]
    assert solutions[0].stats.status == "a peer stopped the update"
    assert len(records) == 1 and kept is consensus


def _first_requests(controller: PeerDistributedMpc, inputs) -> tuple:  # noqa: ANN001
    """Cold requests of a first update (zero guesses), with zero consensus and duals."""
    na, problem = controller.team.agent_count, controller.problem
    size = controller.weights.size
    requests = []
    for i in range(na):
        lower, upper = problem.decision_bounds(inputs.contacts, agent=i)
        requests.append(LocalSolveRequest(
            agent=i, initial_guess=np.zeros(problem.nlp.decision.size),
            parameters=problem.parameter_vector(controller.team, inputs, agent=i,
                                                consensus_target=np.zeros(size)),
            lower_bounds=lower, upper_bounds=upper, warm_start=False))
    return requests, np.zeros(size), np.zeros((na, size))


def test_the_emulated_channel_is_refused_without_a_coordinator() -> None:
    mpc, model = settings(), team()
    lossy = mpc.model_copy(update={"admm": mpc.admm.model_copy(
        update={"channel": ChannelSettings(max_delay_rounds=2)})})
    with pytest.raises(ValueError, match="applies at the coordinator"):
        PeerDistributedMpc(model, lossy, _ThreadPeers(LocalSolverSpec(mpc, model.agent_count)))
