"""``porter agent``: one robot's ADMM local solver as a process of its own, served over Zenoh.

The agent builds its local NLP once, announces itself (``Hello``: team, agent, problem digest,
host, pid) every heartbeat, and answers each ``SolveRequest`` on its key with a ``SolveReply``.
Coordinator-free topology (a request with ``admm_iterations``): the agent runs the update's
ADMM iterations with its peers itself (``core.admm.admm_executor.run_agent_admm``), sending
its s^i to every agent (``SharedTrajectory``) and computing s-bar and every dual from theirs;
a peer silent for ``peer_timeout_s`` ends its run as a failed solve, said in the reply.
Malformed, foreign and other-problem requests are dropped and counted, never solved. When
requests queue up (a slow solve), only the newest is solved: the coordinator waits for that
round only. It exits on the coordinator's stop message, when its parent process (the one that
spawned it, if any) is gone, or on SIGTERM/Ctrl-C.
"""

from __future__ import annotations

import contextlib
import os
import queue
import socket
import threading
from collections import Counter
from dataclasses import dataclass

import numpy as np

from core.admm.admm_executor import LocalSolverSpec, run_agent_admm, solve_request
from core.nmpc.layout import shared_indices
from deploy.agents import wire
from deploy.agents.zenoh_session import (
    Credentials,
    concrete_endpoint,
    hello_key,
    key_agent,
    open_session,
    reply_key,
    request_key,
    shared_key,
)

HEARTBEAT_S = 0.5
# Peers' shared trajectories kept for rounds not reached yet: at most this many (sequence,
# iteration) rounds, and none more than MAX_SEQUENCES_AHEAD requests ahead of the newest
# this agent finished (a slow agent whose requests were superseded may lag some). A flood of
# future rounds is counted and dropped, not stored: memory stays bounded.
MAX_PENDING_ROUNDS = 2 * wire.MAX_ADMM_ITERATIONS
MAX_SEQUENCES_AHEAD = 64


@dataclass(frozen=True)
class AgentAddress:
    """Who the agent is and where it meets the coordinator."""

    team: str
    agent: int
    key_prefix: str
    connect: list[str]
    listen: list[str]
    credentials: Credentials | None = None  # the team's (None: no authentication, tests)


class AdmmAgent:
    """One agent's local solver behind Zenoh; ``serve`` runs until told to stop."""

    def __init__(self, spec: LocalSolverSpec, address: AgentAddress,
                 parent_pid: int | None = None, peer_timeout_s: float = 1.0) -> None:
        if not 0 <= address.agent < spec.agent_count:
            raise ValueError(f"agent {address.agent} is not in a team of {spec.agent_count}")
        self.spec = spec
        self.address = address
        self.parent_pid = parent_pid
        self.solver = spec.build()
        self.sizes = wire.ProblemSizes.of(self.solver.problem)
        self.digest = wire.problem_digest(spec)
        self.rejected: Counter[str] = Counter()
        self.solved = 0
        self.superseded = 0  # requests replaced by a newer one before they were solved
        self._inbox: queue.Queue[bytes] = queue.Queue()
        self._stop = threading.Event()
        self.peer_timeout_s = peer_timeout_s
        problem = self.solver.problem
        self._target = problem.parameters.slice("consensus_target")
        self._shared_indices = shared_indices(problem.decision, spec.settings.horizon_steps,
                                              spec.agent_count)
        # peers' shared trajectories: (sequence, iteration) -> agent -> s^j
        self._shared: dict[tuple[int, int], dict[int, np.ndarray]] = {}
        self._shared_arrived = threading.Condition()
        self._finished_sequence = 0  # the newest coordinator-free round this agent answered
        self._shared_out: object = None

    def serve(self) -> None:
        a = self.address
        session = open_session([concrete_endpoint(e) for e in a.listen], a.connect,
                               a.credentials)
        try:
            session.declare_subscriber(request_key(a.key_prefix, a.agent),
                                       lambda sample: self._inbox.put(sample.payload.to_bytes()))
            session.declare_subscriber(shared_key(a.key_prefix, "*"), self._on_shared)
            self._shared_out = session.declare_publisher(shared_key(a.key_prefix, a.agent))
            replies = session.declare_publisher(reply_key(a.key_prefix, a.agent))
            hellos = session.declare_publisher(hello_key(a.key_prefix, a.agent))
            heartbeat = threading.Thread(target=self._heartbeat, args=(hellos,), daemon=True,
                                         name="porter-agent-heartbeat")
            heartbeat.start()
            while not self._stop.is_set():
                data = self._newest(timeout_s=HEARTBEAT_S)
                if data is not None:
                    self._answer(data, replies)
        finally:
            self._stop.set()
            with contextlib.suppress(Exception):
                session.close()

    def _newest(self, timeout_s: float) -> bytes | None:
        try:
            data = self._inbox.get(timeout=timeout_s)
        except queue.Empty:
            return None
        while True:
            try:
                newer = self._inbox.get_nowait()
            except queue.Empty:
                return data
            self.superseded += 1
            data = newer

    def _answer(self, data: bytes, replies: object) -> None:
        a = self.address
        try:
            sequence, request = wire.decode_request(data, a.team, self.spec.agent_count,
                                                    self.digest, self.sizes)
        except wire.WireError as error:
            self.rejected[error.reason.split(":")[0]] += 1
            return
        if request is None:
            self._stop.set()
            return
        local = request.request if isinstance(request, wire.PeerRequest) else request
        if local.agent != a.agent:
            self.rejected["request for another agent"] += 1
            return
        if isinstance(request, wire.PeerRequest):
            run = run_agent_admm(self.solver, local, request.consensus, request.duals,
                                 request.iterations, self._target, self._shared_indices,
                                 lambda iteration, shared: self._exchange(
                                     sequence, local.update, iteration, shared))
            reply = wire.encode_reply(run.solution, a.team, a.agent, sequence, local, run)
            with self._shared_arrived:  # this round is over: forget it and older ones
                self._shared = {key: value for key, value in self._shared.items()
                                if key[0] > sequence}
                self._finished_sequence = max(self._finished_sequence, sequence)
        else:
            reply = wire.encode_reply(solve_request(self.solver, local), a.team, a.agent,
                                      sequence, local)
        replies.put(reply)  # type: ignore[attr-defined]
        self.solved += 1

    # --- coordinator-free topology ------------------------------------------------------------
    def _on_shared(self, sample: object) -> None:
        try:
            agent, sequence, iteration, shared = wire.decode_shared(
                sample.payload.to_bytes(), self.address.team,  # type: ignore[attr-defined]
                self.spec.agent_count, self.sizes)
        except wire.WireError as error:
            self.rejected[error.reason.split(":")[0]] += 1
            return
        if key_agent(sample.key_expr) != agent:  # type: ignore[attr-defined]
            self.rejected["agent not its key's"] += 1
            return
        with self._shared_arrived:
            round_key = (sequence, iteration)
            if sequence <= self._finished_sequence:
                self.rejected["round already over"] += 1
                return
            if (sequence > self._finished_sequence + MAX_SEQUENCES_AHEAD
                    or iteration >= wire.MAX_ADMM_ITERATIONS
                    or (round_key not in self._shared
                        and len(self._shared) >= MAX_PENDING_ROUNDS)):
                self.rejected["round too far ahead"] += 1
                return
            self._shared.setdefault(round_key, {})[agent] = shared
            self._shared_arrived.notify_all()

    def _exchange(self, sequence: int, update: int, iteration: int, shared: np.ndarray
                  ) -> np.ndarray | None:
        """Send s^i to every agent; every agent's s^j of this iteration (agent order), or None
        when one stays silent for ``peer_timeout_s``."""
        agent = self.address.agent
        with self._shared_arrived:  # our own, without waiting for Zenoh to echo it
            self._shared.setdefault((sequence, iteration), {})[agent] = shared
        self._shared_out.put(wire.encode_shared(  # type: ignore[attr-defined]
            self.address.team, agent, sequence, update, iteration, shared))
        with self._shared_arrived:
            arrived = self._shared_arrived.wait_for(
                lambda: len(self._shared.get((sequence, iteration), {}))
                == self.spec.agent_count, self.peer_timeout_s)
            if not arrived:
                return None
            received = self._shared[(sequence, iteration)]
            return np.array([received[j] for j in range(self.spec.agent_count)])

    def _heartbeat(self, hellos: object) -> None:
        host = socket.gethostname()
        while not self._stop.is_set():
            if self.parent_pid is not None and not _alive(self.parent_pid):
                self._stop.set()  # spawned by a coordinator that is gone
                break
            hello = wire.encode_hello(self.address.team, self.address.agent, self.digest, host,
                                      os.getpid(), self.solved)
            with contextlib.suppress(Exception):
                hellos.put(hello)  # type: ignore[attr-defined]
            self._stop.wait(HEARTBEAT_S)


def _alive(parent_pid: int) -> bool:
    """Whether the process that spawned this one still is its parent (an orphan is adopted
    by another process, so a dead or killed coordinator shows as a changed parent)."""
    return os.getppid() == parent_pid
