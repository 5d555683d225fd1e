"""Zenoh sessions for ADMM agents: settings, key expressions, credentials, peer-mode sessions.

Peer mode with multicast scouting off: a session talks only to the endpoints it is given
(loopback by default), so a run never reaches into the LAN unasked and two teams on one
machine meet only if they share a key prefix (each run gets its own by default). Every
session authenticates with the team's user and password (Zenoh's usrpwd): a session without
them, or with others, cannot open a link to the team, so nothing it says reaches an agent.
"""

from __future__ import annotations

import json
import os
import re
import secrets
import socket
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import zenoh
from pydantic import Field, field_validator, model_validator

from core.model.strict_model import StrictModel

_ENDPOINT = re.compile(r"^(tcp|udp|quic|tls|unixsock-stream)/\S+$")
_PREFIX = re.compile(r"^[A-Za-z0-9_\-]+(/[A-Za-z0-9_\-]+)*$")


class AgentNetwork(StrictModel):
    """Where the coordinator (the NMPC loop) and the agents meet.

    ``listen``: the coordinator's Zenoh endpoints (``tcp/127.0.0.1:0``: a free loopback
    port); agents started by porter connect to the first one, agents started by hand
    (``porter agent --connect``) to any. ``key_prefix``: the team's key expressions
    (None: ``porter/<scenario>/<process id>``, unique per run). ``spawn_agents``: porter
    starts one ``porter agent`` process per robot on this machine; False waits for agents
    started elsewhere. ``reply_timeout_s``: an agent silent this long in a round is a failed
    local solve (the ADMM's failure rules apply; with ``topology: peer`` per ADMM iteration,
    also between peers); ``start_timeout_s``: how long to wait for
    every agent's hello (a cold agent compiles its NLP, about a minute)."""

    listen: list[str] = Field(default_factory=lambda: ["tcp/127.0.0.1:0"], min_length=1)
    # coordinator: this process computes s-bar and the duals (the paper's); peer: the agents
    # exchange their s^i and compute them themselves, this process only hands out the updates
    topology: Literal["coordinator", "peer"] = "coordinator"
    key_prefix: str | None = None
    spawn_agents: bool = True
    reply_timeout_s: float = Field(1.0, gt=0.0, le=60.0)
    start_timeout_s: float = Field(600.0, gt=0.0, le=3600.0)
    # The team's Zenoh credentials (a ``user:password`` file, ``porter agent
    # --new-credentials FILE`` writes one): every session of the team authenticates with
    # them. None: porter writes a fresh one per run for the agents it spawns; agents started
    # by hand (spawn_agents false) need the file, copied to their machines.
    credentials_file: str | None = None

    @field_validator("listen")
    @classmethod
    def _endpoints(cls, endpoints: list[str]) -> list[str]:
        for endpoint in endpoints:
            if not _ENDPOINT.match(endpoint):
                raise ValueError(f"{endpoint!r} is not a Zenoh endpoint like tcp/127.0.0.1:7447")
        return endpoints

    @model_validator(mode="after")
    def _hand_started_agents_need_credentials(self) -> AgentNetwork:
        if not self.spawn_agents and self.credentials_file is None:
            raise ValueError("credentials_file: agents started by hand (spawn_agents false) "
                             "need the team's credentials; write them with porter agent "
                             "--new-credentials FILE and give every agent the same file")
        return self

    @field_validator("key_prefix")
    @classmethod
    def _prefix(cls, prefix: str | None) -> str | None:
        if prefix is not None and not _PREFIX.match(prefix):
            raise ValueError(f"{prefix!r} is not a key prefix like porter/team_a "
                             "(letters, digits, _ and -, separated by /)")
        return prefix


def concrete_endpoint(endpoint: str) -> str:
    """``endpoint`` with port 0 replaced by a free port of its address (tcp/udp only)."""
    protocol, _, address = endpoint.partition("/")
    host, _, port = address.rpartition(":")
    if protocol not in ("tcp", "udp") or port != "0":
        return endpoint
    kind = socket.SOCK_STREAM if protocol == "tcp" else socket.SOCK_DGRAM
    with socket.socket(socket.AF_INET, kind) as probe:
        probe.bind((host, 0))
        return f"{protocol}/{host}:{probe.getsockname()[1]}"


def any_port_of(endpoint: str) -> str:
    """``tcp/127.0.0.1:7447`` -> ``tcp/127.0.0.1:0``: the same host, a free port."""
    protocol, _, address = endpoint.partition("/")
    return f"{protocol}/{address.rpartition(':')[0]}:0"


@dataclass(frozen=True)
class Credentials:
    """A team's Zenoh user and password, and the file that holds them (the dictionary every
    session checks its peers against)."""

    user: str
    password: str
    file: Path


def write_credentials(path: Path | str) -> Credentials:
    """A new random user and password in ``path`` (created, readable by its owner only)."""
    path = Path(path)
    user, password = f"porter-{secrets.token_hex(4)}", secrets.token_urlsafe(24)
    handle = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(handle, "w") as file:
        file.write(f"{user}:{password}\n")
    return Credentials(user, password, path)


def load_credentials(path: Path | str) -> Credentials:
    """The credentials in ``path`` (its first ``user:password`` line); ValueError naming the
    file when it holds none."""
    path = Path(path)
    for line in path.read_text().splitlines():
        user, separator, password = line.strip().partition(":")
        if separator and user and password:
            return Credentials(user, password, path)
    raise ValueError(f"{path}: no user:password line (write one with porter agent "
                     "--new-credentials FILE)")


def open_session(listen: list[str], connect: list[str],
                 credentials: Credentials | None = None) -> zenoh.Session:
    """A peer-mode session listening on ``listen`` and connecting to ``connect``,
    authenticating with ``credentials`` (and accepting only peers that hold them)."""
    config = zenoh.Config()
    config.insert_json5("mode", json.dumps("peer"))
    config.insert_json5("listen/endpoints", json.dumps(listen))
    config.insert_json5("connect/endpoints", json.dumps(connect))
    config.insert_json5("scouting/multicast/enabled", "false")
    if credentials is not None:
        config.insert_json5("transport/auth/usrpwd", json.dumps({
            "user": credentials.user, "password": credentials.password,
            "dictionary_file": str(credentials.file)}))
    return zenoh.open(config)


def key_agent(key: object) -> int | None:
    """The agent index a key names (``.../agent/<i>/...``), or None when it names none."""
    parts = str(key).split("/")
    for name, value in zip(parts, parts[1:], strict=False):
        if name == "agent" and value.isdigit():
            return int(value)
    return None


def request_key(prefix: str, agent: int) -> str:
    return f"{prefix}/agent/{agent}/request"


def reply_key(prefix: str, agent: int | str) -> str:
    return f"{prefix}/agent/{agent}/reply"


def hello_key(prefix: str, agent: int | str) -> str:
    return f"{prefix}/agent/{agent}/hello"


def shared_key(prefix: str, agent: int | str) -> str:
    """Coordinator-free topology: agent's s^i, to every agent of the team."""
    return f"{prefix}/agent/{agent}/shared"
