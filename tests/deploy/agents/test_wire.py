"""ADMM messages on the wire: round trips keep every value, and whatever is malformed,
foreign or for another problem is rejected with a reason before anything uses it."""

from __future__ import annotations

import math

import numpy as np
import pytest

from core.admm.admm_executor import AgentAdmm, LocalSolveRequest, LocalSolverSpec
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from core.nmpc.settings import MpcSettings
from deploy.agents import wire
from deploy.agents.messages import admm_wire_pb2 as pb

SIZES = wire.ProblemSizes(decision=7, parameters=5, constraints=3, shared=4)
TEAM, AGENTS, DIGEST = "team_a", 2, "abc123"


def _request(**changes: object) -> LocalSolveRequest:
    rng = np.random.default_rng(1)
    fields: dict = dict(agent=1, initial_guess=rng.normal(size=7), parameters=rng.normal(size=5),
                        lower_bounds=np.full(7, -np.inf), upper_bounds=rng.normal(size=7),
                        constraint_multipliers=rng.normal(size=3),
                        bound_multipliers=rng.normal(size=7), warm_start=True, update=12,
                        iteration=1)
    fields.update(changes)
    return LocalSolveRequest(**fields)


def _decode(data: bytes) -> LocalSolveRequest | None:
    return wire.decode_request(data, TEAM, AGENTS, DIGEST, SIZES)[1]


def test_a_request_round_trips_exactly() -> None:
    request = _request()
    sequence, decoded = wire.decode_request(wire.encode_request(request, TEAM, 41, DIGEST),
                                            TEAM, AGENTS, DIGEST, SIZES)
    assert sequence == 41 and decoded is not None
    for name in ("initial_guess", "parameters", "lower_bounds", "upper_bounds",
                 "constraint_multipliers", "bound_multipliers"):
        np.testing.assert_array_equal(getattr(decoded, name), getattr(request, name))
    assert (decoded.agent, decoded.update, decoded.iteration, decoded.warm_start) == (1, 12, 1, True)


def test_a_cold_request_has_no_multipliers_and_a_stop_has_no_request() -> None:
    cold = _decode(wire.encode_request(_request(constraint_multipliers=None,
                                                bound_multipliers=None, warm_start=False),
                                       TEAM, 1, DIGEST))
    assert cold is not None and cold.constraint_multipliers is None and not cold.warm_start
    assert _decode(wire.encode_stop(TEAM, 0, DIGEST)) is None


def test_a_stop_for_another_problem_and_an_unbounded_iteration_count_are_refused() -> None:
    with pytest.raises(wire.WireError, match="problem other"):
        _decode(wire.encode_stop(TEAM, 0, "other"))  # a stop carries the digest too
    rng = np.random.default_rng(3)
    for iterations, allowed in ((wire.MAX_ADMM_ITERATIONS, True),
                                (wire.MAX_ADMM_ITERATIONS + 1, False), (10**9, False)):
        peer = wire.PeerRequest(_request(), iterations, rng.normal(size=4),
                                rng.normal(size=(AGENTS, 4)))
        data = wire.encode_peer_request(peer, TEAM, 5, DIGEST)
        if allowed:
            assert isinstance(_decode_any(data), wire.PeerRequest)
        else:
            with pytest.raises(wire.WireError, match="admm_iterations .* above 100"):
                _decode_any(data)


def _decode_any(data: bytes) -> object:
    return wire.decode_request(data, TEAM, AGENTS, DIGEST, SIZES)[1]


def test_a_reply_round_trips_and_a_failed_one_may_carry_nan() -> None:
    stats = SolveStats("Solve_Succeeded", True, 3, 0.004, 1.5, 1e-9, 0.003)
    solution = NlpSolution(np.arange(7.0), np.arange(3.0), np.arange(7.0) * 2, stats)
    agent, sequence, decoded, run = wire.decode_reply(
        wire.encode_reply(solution, TEAM, 1, 9, _request()), TEAM, AGENTS, SIZES)
    assert (agent, sequence) == (1, 9) and decoded.stats == stats and run is None
    np.testing.assert_array_equal(decoded.decision, solution.decision)
    failed = NlpSolution(np.full(7, np.nan), np.zeros(3), np.zeros(7),
                         SolveStats("Infeasible", False, 50, 0.1, math.nan, math.inf))
    _, _, decoded, _ = wire.decode_reply(
        wire.encode_reply(failed, TEAM, 0, 9, _request(agent=0)), TEAM, AGENTS, SIZES)
    assert not decoded.stats.success and np.isnan(decoded.decision).all()
    # a successful reply with a NaN is a corrupt message
    corrupt = NlpSolution(np.full(7, np.nan), np.zeros(3), np.zeros(7), stats)
    with pytest.raises(wire.WireError, match="decision is not finite"):
        wire.decode_reply(wire.encode_reply(corrupt, TEAM, 0, 9, _request(agent=0)), TEAM,
                          AGENTS, SIZES)


def test_the_coordinator_free_messages_round_trip() -> None:
    """A peer request carries the ADMM state the agents start from; a shared trajectory goes
    to every agent; a reply carries the agent's whole run (or why it stopped)."""
    rng = np.random.default_rng(3)
    consensus, duals = rng.normal(size=4), rng.normal(size=(AGENTS, 4))
    peer = wire.PeerRequest(_request(), 2, consensus, duals)
    sequence, decoded = wire.decode_request(wire.encode_peer_request(peer, TEAM, 5, DIGEST),
                                            TEAM, AGENTS, DIGEST, SIZES)
    assert sequence == 5 and isinstance(decoded, wire.PeerRequest) and decoded.iterations == 2
    np.testing.assert_array_equal(decoded.consensus, consensus)
    np.testing.assert_array_equal(decoded.duals, duals)
    np.testing.assert_array_equal(decoded.request.parameters, _request().parameters)
    shared = rng.normal(size=4)
    assert wire.decode_shared(wire.encode_shared(TEAM, 1, 5, 12, 1, shared), TEAM, AGENTS,
                              SIZES)[:3] == (1, 5, 1)
    with pytest.raises(wire.WireError, match="shared trajectory has 3 values"):
        wire.decode_shared(wire.encode_shared(TEAM, 1, 5, 12, 1, shared[:3]), TEAM, AGENTS,
                           SIZES)
    with pytest.raises(wire.WireError, match="foreign team"):
        wire.decode_shared(wire.encode_shared("team_b", 1, 5, 12, 1, shared), TEAM, AGENTS,
                           SIZES)
    stats = SolveStats("Solve_Succeeded", True, 1, 0.002, 1.0, 0.0, 0.002)
    solution = NlpSolution(np.arange(7.0), np.arange(3.0), np.arange(7.0), stats)
    run = AgentAdmm(solution, [stats, stats], [shared, shared + 1], [consensus, consensus * 2],
                    duals)
    _, _, _, back = wire.decode_reply(wire.encode_reply(solution, TEAM, 1, 5, _request(), run),
                                      TEAM, AGENTS, SIZES)
    assert back is not None and back.failure == "" and back.stats == [stats, stats]
    np.testing.assert_array_equal(back.consensus[1], consensus * 2)
    np.testing.assert_array_equal(back.duals, duals)
    stopped = AgentAdmm(solution, [stats], [shared], [], None, "a peer was silent")
    _, _, _, back = wire.decode_reply(
        wire.encode_reply(solution, TEAM, 1, 5, _request(), stopped), TEAM, AGENTS, SIZES)
    assert back is not None and back.failure == "a peer was silent" and back.duals is None


@pytest.mark.parametrize(("data", "reason"), [
    (b"\xff\xfe garbage", "not a SolveRequest"),
    (wire.encode_request(_request(), "team_b", 1, DIGEST), "foreign team"),
    (wire.encode_request(_request(agent=5), TEAM, 1, DIGEST), "agent 5 not in a team of 2"),
    (wire.encode_request(_request(), TEAM, 1, "other"), "problem other"),
    (wire.encode_request(_request(parameters=np.zeros(4)), TEAM, 1, DIGEST),
     "parameters has 4 values, expected 5"),
    (wire.encode_request(_request(initial_guess=np.full(7, np.inf)), TEAM, 1, DIGEST),
     "initial guess is not finite"),
    (pb.SolveRequest(wire_version=99, team=TEAM).SerializeToString(), "wire version 99"),
])
def test_malformed_foreign_and_other_problem_requests_are_rejected(data: bytes,
                                                                   reason: str) -> None:
    with pytest.raises(wire.WireError, match=reason):
        _decode(data)


def test_the_digest_names_the_problem() -> None:
    base = MpcSettings()
    changed = base.model_copy(update={"horizon_steps": 9})
    assert wire.problem_digest(LocalSolverSpec(base, 2)) == wire.problem_digest(
        LocalSolverSpec(MpcSettings(), 2))
    assert wire.problem_digest(LocalSolverSpec(base, 2)) != wire.problem_digest(
        LocalSolverSpec(base, 3))
    assert wire.problem_digest(LocalSolverSpec(base, 2)) != wire.problem_digest(
        LocalSolverSpec(changed, 2))
