"""ADMM local solves on ``porter agent`` processes over Zenoh. Two topologies
(``AgentNetwork.topology``): ``coordinator`` (the paper's: this process, the NMPC loop,
computes the consensus and the duals; agents solve, one request per agent and iteration) and
``peer`` (coordinator-free: one request per agent and update, the agents exchange their s^i
and each computes s-bar and every dual itself; ``run_admm``).

Each round publishes one ``SolveRequest`` per agent and waits up to ``reply_timeout_s`` for
the replies of that round; a silent agent yields a failed solve for its robot (the ADMM's and
the supervisor's failure rules apply: fallback to the last plan, braking, safe stop), late
replies of earlier rounds are dropped and counted, malformed or foreign messages too.
"""

from __future__ import annotations

import contextlib
import os
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter
from pathlib import Path

import numpy as np
import yaml

from core.admm.admm_executor import AgentAdmm, LocalSolveRequest, LocalSolverSpec
from core.nmpc.nlp_solver import NlpSolution
from core.nmpc.transport_problem import build_transport_problem
from deploy.agents import wire
from deploy.agents.zenoh_session import (
    AgentNetwork,
    Credentials,
    any_port_of,
    concrete_endpoint,
    hello_key,
    key_agent,
    load_credentials,
    open_session,
    reply_key,
    request_key,
    write_credentials,
)
from deploy.nmpc_runtime.process_executor import failed_solution

_STDERR_TAIL = 1500


class ZenohExecutor:
    """``LocalSolveExecutor`` whose agents are processes reached over Zenoh."""

    def __init__(self, spec: LocalSolverSpec, network: AgentNetwork, team: str) -> None:
        self.spec = spec
        self.network = network
        self.team = team
        self.key_prefix = network.key_prefix or f"porter/{team}/{os.getpid()}"
        self.endpoints = [concrete_endpoint(e) for e in network.listen]
        self.sizes = wire.ProblemSizes.of(
            build_transport_problem(spec.settings, spec.agent_count, local=True).nlp)
        self.digest = wire.problem_digest(spec)
        self.rejected: Counter[str] = Counter()  # dropped messages by reason
        self.late_replies = 0  # replies of an earlier round, dropped
        self.hellos: dict[int, wire.pb.Hello] = {}  # each agent's latest
        self._sequence = 0
        self._replies: dict[int, NlpSolution] = {}
        self._runs: dict[int, AgentAdmm | None] = {}
        self._condition = threading.Condition()
        self._processes: list[subprocess.Popen[bytes]] = []
        self._stderr: list[tempfile._TemporaryFileWrapper[bytes]] = []
        self._settings_file: Path | None = None
        self._own_credentials: Path | None = None  # written for this run: removed at close
        self.credentials = self._team_credentials(network)
        self._session = open_session(self.endpoints, [], self.credentials)
        try:
            self._session.declare_subscriber(reply_key(self.key_prefix, "*"), self._on_reply)
            self._session.declare_subscriber(hello_key(self.key_prefix, "*"), self._on_hello)
            self._publishers = [self._session.declare_publisher(request_key(self.key_prefix, i))
                                for i in range(spec.agent_count)]
            if network.spawn_agents:
                self._spawn_agents()
            self._wait_for_agents(network.start_timeout_s)
        except BaseException:
            self.close()
            raise

    def _team_credentials(self, network: AgentNetwork) -> Credentials:
        if network.credentials_file is not None:
            return load_credentials(network.credentials_file)
        # (AgentNetwork requires the file for agents started by hand)
        folder = Path(tempfile.mkdtemp(prefix="porter-zenoh-"))
        credentials = write_credentials(folder / "credentials")
        self._own_credentials = credentials.file
        return credentials

    # --- agents -------------------------------------------------------------------------------
    def agent_command(self, agent: int, settings_file: Path) -> list[str]:
        """The command line that starts ``agent`` against this coordinator."""
        return [sys.executable, "-m", "deploy.cli", "agent", "--settings", str(settings_file),
                "--agents", str(self.spec.agent_count), "--index", str(agent),
                "--team", self.team, "--key-prefix", self.key_prefix,
                "--connect", self.endpoints[0], "--parent-pid", str(os.getpid()),
                "--peer-timeout", f"{self.network.reply_timeout_s:g}",
                "--credentials", str(self.credentials.file),
                # an endpoint of its own on the coordinator's host: peers find one another
                # through the coordinator's session (Zenoh gossip) and talk directly
                "--listen", any_port_of(self.endpoints[0])]

    def _spawn_agents(self) -> None:
        handle, name = tempfile.mkstemp(prefix="porter-agent-", suffix=".yaml")
        with os.fdopen(handle, "w") as file:
            yaml.safe_dump(self.spec.settings.model_dump(mode="json"), file)
        self._settings_file = Path(name)
        for agent in range(self.spec.agent_count):
            # stderr into a file, not a pipe: nobody reads a pipe while the run goes on
            self._stderr.append(tempfile.NamedTemporaryFile(  # noqa: SIM115 (closed in close)
                prefix=f"porter-agent{agent}-"))
            self._processes.append(subprocess.Popen(
                self.agent_command(agent, self._settings_file), stdout=subprocess.DEVNULL,
                stderr=self._stderr[-1], cwd=Path(__file__).resolve().parents[2]))

    def _wait_for_agents(self, timeout_s: float) -> None:
        deadline = time.monotonic() + timeout_s
        with self._condition:
            while len(self.hellos) < self.spec.agent_count:
                for agent, process in enumerate(self._processes):
                    if process.poll() is not None:
                        self._stderr[agent].seek(0)
                        error = self._stderr[agent].read().decode(errors="replace")
                        raise RuntimeError(f"ADMM agent {agent} exited with code "
                                           f"{process.returncode}:\n{error[-_STDERR_TAIL:]}")
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    missing = sorted(set(range(self.spec.agent_count)) - set(self.hellos))
                    raise RuntimeError(f"ADMM agents {missing} did not announce themselves on "
                                       f"{self.key_prefix} within {timeout_s:g} s")
                self._condition.wait(min(remaining, 0.5))
        for agent, hello in self.hellos.items():
            if hello.problem_digest != self.digest:
                raise RuntimeError(f"ADMM agent {agent} ({hello.host}, pid {hello.pid}) holds "
                                   f"problem {hello.problem_digest}, this team's is "
                                   f"{self.digest}: start it with the same settings")

    # --- receiving ----------------------------------------------------------------------------
    def _on_hello(self, sample: object) -> None:
        try:
            hello = wire.decode_hello(sample.payload.to_bytes(),  # type: ignore[attr-defined]
                                      self.team, self.spec.agent_count)
        except wire.WireError as error:
            self._reject(error)
            return
        if key_agent(sample.key_expr) != hello.agent:  # type: ignore[attr-defined]
            self._reject(wire.WireError("agent not its key's"))
            return
        with self._condition:
            self.hellos[hello.agent] = hello
            self._condition.notify_all()

    def _on_reply(self, sample: object) -> None:
        try:
            agent, sequence, solution, run = wire.decode_reply(
                sample.payload.to_bytes(), self.team,  # type: ignore[attr-defined]
                self.spec.agent_count, self.sizes)
        except wire.WireError as error:
            self._reject(error)
            return
        # a reply is bound to the key it came on: agent i's reply on agent j's key is forged
        if key_agent(sample.key_expr) != agent:  # type: ignore[attr-defined]
            self._reject(wire.WireError("agent not its key's"))
            return
        with self._condition:
            if sequence != self._sequence:
                self.late_replies += 1
                return
            self._replies[agent] = solution
            self._runs[agent] = run
            self._condition.notify_all()

    def _reject(self, error: wire.WireError) -> None:
        with self._condition:
            self.rejected[error.reason.split(":")[0]] += 1

    # --- LocalSolveExecutor -------------------------------------------------------------------
    def _round(self, messages: list[tuple[int, bytes]], timeout_s: float
               ) -> tuple[dict[int, NlpSolution], dict[int, AgentAdmm | None]]:
        """Send one message per agent (encoded with this round's sequence), wait for their
        replies up to ``timeout_s``: the replies that came, by agent."""
        for agent, message in messages:
            self._publishers[agent].put(message)
        wanted = {agent for agent, _ in messages}
        deadline = time.monotonic() + timeout_s
        with self._condition:
            while not wanted <= set(self._replies):
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    break
                self._condition.wait(remaining)
            return dict(self._replies), dict(self._runs)

    def _next_sequence(self) -> int:
        with self._condition:
            self._sequence += 1
            self._replies, self._runs = {}, {}
            return self._sequence

    def solve_all(self, requests: list[LocalSolveRequest]) -> list[NlpSolution]:
        sequence = self._next_sequence()
        replies, _ = self._round(
            [(r.agent, wire.encode_request(r, self.team, sequence, self.digest))
             for r in requests], self.network.reply_timeout_s)
        return [replies[r.agent] if r.agent in replies else failed_solution(
                    r, f"agent {r.agent} did not answer within "
                       f"{self.network.reply_timeout_s:g} s")
                for r in requests]

    def run_admm(self, requests: list[LocalSolveRequest], consensus: np.ndarray,
                 duals: np.ndarray, iterations: int) -> list[AgentAdmm]:
        """Coordinator-free: each agent runs the update's ``iterations`` ADMM iterations with
        its peers from ``consensus`` and ``duals``; each agent's run (a silent agent: a failed
        one, its warm start kept)."""
        sequence = self._next_sequence()
        messages = [(r.agent, wire.encode_peer_request(
            wire.PeerRequest(r, iterations, consensus, duals), self.team, sequence,
            self.digest)) for r in requests]
        replies, runs = self._round(messages, iterations * self.network.reply_timeout_s)
        out = []
        for request in requests:
            run = runs.get(request.agent)
            if request.agent in replies and run is not None:
                out.append(run)
                continue
            reason = (f"agent {request.agent} did not answer within "
                      f"{iterations * self.network.reply_timeout_s:g} s")
            out.append(AgentAdmm(failed_solution(request, reason), failure=reason))
        return out

    def close(self) -> None:
        for agent, publisher in enumerate(getattr(self, "_publishers", [])):
            with contextlib.suppress(Exception):
                publisher.put(wire.encode_stop(self.team, agent, self.digest))
        for process in self._processes:
            try:
                process.wait(timeout=2.0)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        for file in self._stderr:
            file.close()
        self._processes, self._stderr = [], []
        with contextlib.suppress(Exception):
            self._session.close()
        if self._settings_file is not None:
            self._settings_file.unlink(missing_ok=True)
            self._settings_file = None
        if self._own_credentials is not None:
            self._own_credentials.unlink(missing_ok=True)
            with contextlib.suppress(OSError):
                self._own_credentials.parent.rmdir()
            self._own_credentials = None

