"""ADMM messages on the wire: ``LocalSolveRequest`` / ``NlpSolution`` <-> protobuf bytes.

The schema is ``messages/admm_wire.proto`` (versioned by ``WIRE_VERSION``). Decoding checks
everything a receiver relies on before it uses a message: it parses, it has this version,
this team, an agent of the team, arrays of the problem's sizes and finite values where a
solver needs them. A message that fails raises ``WireError`` with a short reason the
receiver counts; it never reaches a solver or the ADMM.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass

import numpy as np
from google.protobuf.message import DecodeError

from core.admm.admm_executor import AgentAdmm, LocalSolveRequest, LocalSolverSpec
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from core.nmpc.stagewise_nlp import NlpProblem
from deploy.agents.messages import admm_wire_pb2 as pb

WIRE_VERSION = 1
_FLOAT = np.dtype("<f8")


# The most ADMM iterations a coordinator-free request may ask for (an update has 60 Hz to run
# them; the paper runs 2): a larger count is refused, not run.
MAX_ADMM_ITERATIONS = 100


class WireError(ValueError):
    """A received message that is malformed, foreign or inconsistent (``reason`` is short)."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


@dataclass(frozen=True)
class ProblemSizes:
    """Lengths of the local NLP's vectors: decision, parameters, constraints, and the shared
    trajectory s (``parameters.consensus_target``)."""

    decision: int
    parameters: int
    constraints: int
    shared: int = 0

    @classmethod
    def of(cls, problem: NlpProblem) -> ProblemSizes:
        target = problem.parameters.slice("consensus_target")
        return cls(problem.decision.size, problem.parameters.size,
                   problem.lower_constraints.size, target.stop - target.start)


@dataclass(frozen=True)
class PeerRequest:
    """Coordinator-free topology: the update's first local problem, and the ADMM state the
    agents start from (s-bar, every agent's dual) for ``iterations`` iterations."""

    request: LocalSolveRequest
    iterations: int
    consensus: np.ndarray
    duals: np.ndarray


def problem_digest(spec: LocalSolverSpec) -> str:
    """Identity of a local problem: the effective NMPC settings and the team size. A
    coordinator and an agent with different digests would solve different problems."""
    text = f"{spec.agent_count}|{spec.settings.model_dump_json()}"
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _pack(array: np.ndarray | None) -> bytes:
    return b"" if array is None else np.ascontiguousarray(array, dtype=_FLOAT).tobytes()


def _unpack(data: bytes, size: int, name: str, finite: bool = True) -> np.ndarray:
    if len(data) != size * _FLOAT.itemsize:
        raise WireError(f"{name} has {len(data) // _FLOAT.itemsize} values, "
                              f"expected {size}")
    array = np.frombuffer(data, dtype=_FLOAT).copy()
    if finite and not np.all(np.isfinite(array)):
        raise WireError(f"{name} is not finite")
    return array


def _parse(message_type: type, data: bytes) -> object:
    message = message_type()
    try:
        message.ParseFromString(data)
    except (DecodeError, RuntimeWarning, ValueError) as error:
        raise WireError(f"not a {message_type.__name__}: {error}") from None
    return message


def _check_header(message: object, team: str, agent_count: int) -> None:
    if message.wire_version != WIRE_VERSION:  # type: ignore[attr-defined]
        raise WireError(f"wire version {message.wire_version}, "  # type: ignore[attr-defined]
                              f"expected {WIRE_VERSION}")
    if message.team != team:  # type: ignore[attr-defined]
        raise WireError(f"foreign team {message.team!r}")  # type: ignore[attr-defined]
    if message.agent >= agent_count:  # type: ignore[attr-defined]
        raise WireError(f"agent {message.agent} not in a team of "  # type: ignore[attr-defined]
                              f"{agent_count}")


def _request_message(request: LocalSolveRequest, team: str, sequence: int, digest: str
                     ) -> pb.SolveRequest:
    warm = request.constraint_multipliers is not None and request.bound_multipliers is not None
    return pb.SolveRequest(
        wire_version=WIRE_VERSION, team=team, agent=request.agent, sequence=sequence,
        update=request.update, iteration=request.iteration, problem_digest=digest,
        initial_guess=_pack(request.initial_guess), parameters=_pack(request.parameters),
        lower_bounds=_pack(request.lower_bounds), upper_bounds=_pack(request.upper_bounds),
        has_multipliers=warm, constraint_multipliers=_pack(request.constraint_multipliers),
        bound_multipliers=_pack(request.bound_multipliers), warm_start=request.warm_start)


def encode_request(request: LocalSolveRequest, team: str, sequence: int, digest: str) -> bytes:
    return _request_message(request, team, sequence, digest).SerializeToString()


def encode_peer_request(peer: PeerRequest, team: str, sequence: int, digest: str) -> bytes:
    """A request asking the agent to run ``peer.iterations`` ADMM iterations with its peers."""
    message = _request_message(peer.request, team, sequence, digest)
    message.admm_iterations = peer.iterations
    message.consensus = _pack(peer.consensus)
    message.duals = _pack(peer.duals)
    return message.SerializeToString()


def encode_stop(team: str, agent: int, digest: str) -> bytes:
    """Stop the agent; it carries the problem's digest, as a request does (a stop from
    someone holding another problem is refused like its requests)."""
    return pb.SolveRequest(wire_version=WIRE_VERSION, team=team, agent=agent,
                           problem_digest=digest, stop=True).SerializeToString()


def decode_request(data: bytes, team: str, agent_count: int, digest: str,
                   sizes: ProblemSizes) -> tuple[int, LocalSolveRequest | PeerRequest | None]:
    """(sequence, request) of a request for this team's problem; request None for a stop, a
    ``PeerRequest`` when the agents are to run the ADMM themselves."""
    message = _parse(pb.SolveRequest, data)
    _check_header(message, team, agent_count)
    assert isinstance(message, pb.SolveRequest)
    if message.problem_digest != digest:
        raise WireError(f"problem {message.problem_digest}, this agent holds {digest}")
    if message.stop:
        return message.sequence, None
    if message.admm_iterations > MAX_ADMM_ITERATIONS:
        raise WireError(f"admm_iterations {message.admm_iterations} above "
                        f"{MAX_ADMM_ITERATIONS}")
    n, m = sizes.decision, sizes.constraints
    multipliers = ((_unpack(message.constraint_multipliers, m, "constraint multipliers"),
                    _unpack(message.bound_multipliers, n, "bound multipliers"))
                   if message.has_multipliers else (None, None))
    # Bounds may be infinite (free variables); guesses and parameters may not.
    request = LocalSolveRequest(
        agent=message.agent, initial_guess=_unpack(message.initial_guess, n, "initial guess"),
        parameters=_unpack(message.parameters, sizes.parameters, "parameters"),
        lower_bounds=_unpack(message.lower_bounds, n, "lower bounds", finite=False),
        upper_bounds=_unpack(message.upper_bounds, n, "upper bounds", finite=False),
        constraint_multipliers=multipliers[0], bound_multipliers=multipliers[1],
        warm_start=message.warm_start, update=message.update, iteration=message.iteration)
    if message.admm_iterations == 0:
        return message.sequence, request
    duals = _unpack(message.duals, agent_count * sizes.shared, "duals")
    return message.sequence, PeerRequest(
        request, message.admm_iterations, _unpack(message.consensus, sizes.shared, "consensus"),
        duals.reshape(agent_count, sizes.shared))


def encode_shared(team: str, agent: int, sequence: int, update: int, iteration: int,
                  shared: np.ndarray) -> bytes:
    return pb.SharedTrajectory(wire_version=WIRE_VERSION, team=team, agent=agent,
                               sequence=sequence, update=update, iteration=iteration,
                               shared=_pack(shared)).SerializeToString()


def decode_shared(data: bytes, team: str, agent_count: int, sizes: ProblemSizes
                  ) -> tuple[int, int, int, np.ndarray]:
    """(agent, sequence, iteration, s^agent) of a peer's shared trajectory."""
    message = _parse(pb.SharedTrajectory, data)
    _check_header(message, team, agent_count)
    assert isinstance(message, pb.SharedTrajectory)
    return (message.agent, message.sequence, message.iteration,
            _unpack(message.shared, sizes.shared, "shared trajectory"))


def _stats(s: SolveStats) -> pb.SolveStats:
    return pb.SolveStats(status=s.status, success=s.success, iterations=s.iterations,
                         wall_time_s=s.wall_time_s, objective=s.objective,
                         constraint_violation=s.constraint_violation, cpu_time_s=s.cpu_time_s)


def _from_stats(s: pb.SolveStats) -> SolveStats:
    return SolveStats(s.status, s.success, s.iterations, s.wall_time_s,
                      s.objective if math.isfinite(s.objective) else math.nan,
                      s.constraint_violation, s.cpu_time_s)


def encode_reply(solution: NlpSolution, team: str, agent: int, sequence: int,
                 request: LocalSolveRequest, run: AgentAdmm | None = None) -> bytes:
    """A local solution (``run``: the agent's whole coordinator-free ADMM run with it)."""
    reply = pb.SolveReply(
        wire_version=WIRE_VERSION, team=team, agent=agent, sequence=sequence,
        update=request.update, iteration=request.iteration, decision=_pack(solution.decision),
        constraint_multipliers=_pack(solution.constraint_multipliers),
        bound_multipliers=_pack(solution.bound_multipliers), stats=_stats(solution.stats))
    if run is not None:
        for stats, shared, consensus in zip(run.stats, run.shared, run.consensus,
                                            strict=False):
            reply.admm.add(stats=_stats(stats), shared=_pack(shared),
                           consensus=_pack(consensus))
        reply.duals = _pack(run.duals)
        reply.admm_failure = run.failure
    return reply.SerializeToString()


def decode_reply(data: bytes, team: str, agent_count: int, sizes: ProblemSizes
                 ) -> tuple[int, int, NlpSolution, AgentAdmm | None]:
    """(agent, sequence, solution, the agent's coordinator-free run or None) of a reply. A
    failed solve may carry non-finite values (the ADMM replaces them); a successful one may
    not."""
    message = _parse(pb.SolveReply, data)
    _check_header(message, team, agent_count)
    assert isinstance(message, pb.SolveReply)
    success = message.stats.success
    n = sizes.decision
    solution = NlpSolution(
        _unpack(message.decision, n, "decision", finite=success),
        _unpack(message.constraint_multipliers, sizes.constraints, "constraint multipliers",
                finite=success),
        _unpack(message.bound_multipliers, n, "bound multipliers", finite=success),
        _from_stats(message.stats))
    run = None
    if message.admm or message.duals or message.admm_failure:
        m = sizes.shared
        run = AgentAdmm(
            solution, [_from_stats(i.stats) for i in message.admm],
            [_unpack(i.shared, m, "shared trajectory") for i in message.admm],
            [_unpack(i.consensus, m, "consensus") for i in message.admm],
            _unpack(message.duals, agent_count * m, "duals").reshape(agent_count, m)
            if message.duals else None,
            message.admm_failure)
    return message.agent, message.sequence, solution, run


def encode_hello(team: str, agent: int, digest: str, host: str, pid: int, solved: int) -> bytes:
    return pb.Hello(wire_version=WIRE_VERSION, team=team, agent=agent, problem_digest=digest,
                    host=host, pid=pid, solved=solved).SerializeToString()


def decode_hello(data: bytes, team: str, agent_count: int) -> pb.Hello:
    message = _parse(pb.Hello, data)
    _check_header(message, team, agent_count)
    assert isinstance(message, pb.Hello)
    return message
