"""One ``porter agent``'s inbox for its peers' shared trajectories: bound to the key a message
came on, and bounded whatever arrives (a flood of future rounds is counted, not stored)."""

from __future__ import annotations

import numpy as np

from core.admm.admm_executor import LocalSolverSpec
from deploy.agents import wire
from deploy.agents.agent import MAX_PENDING_ROUNDS, AdmmAgent, AgentAddress
from deploy.agents.zenoh_session import shared_key
from tests.core.controller_fixtures import settings

PREFIX, TEAM = "porter/test/1", "two_go2"


class _Sample:
    """What Zenoh hands a subscriber: the key the sample came on and its payload."""

    class _Payload:
        def __init__(self, data: bytes) -> None:
            self.data = data

        def to_bytes(self) -> bytes:
            return self.data

    def __init__(self, key: str, data: bytes) -> None:
        self.key_expr = key
        self.payload = self._Payload(data)


def _agent() -> AdmmAgent:
    return AdmmAgent(LocalSolverSpec(settings(), 2),
                     AgentAddress(TEAM, 0, PREFIX, connect=[], listen=[]))


def test_a_flood_of_future_rounds_leaves_the_agent_bounded() -> None:
    agent = _agent()
    shared = np.zeros(agent.sizes.shared)
    for sequence in range(1, 10_001):  # 10k messages, each for a round of its own
        agent._on_shared(_Sample(shared_key(PREFIX, 1), wire.encode_shared(
            TEAM, 1, sequence, sequence, 0, shared)))
    assert len(agent._shared) <= MAX_PENDING_ROUNDS
    assert sum(agent.rejected.values()) >= 10_000 - MAX_PENDING_ROUNDS
    assert agent.rejected["round too far ahead"] > 0
    # iterations beyond what any request may ask for are refused as well
    agent._on_shared(_Sample(shared_key(PREFIX, 1), wire.encode_shared(
        TEAM, 1, 1, 1, wire.MAX_ADMM_ITERATIONS, shared)))
    assert (1, wire.MAX_ADMM_ITERATIONS) not in agent._shared


def test_a_peer_message_is_bound_to_its_key() -> None:
    agent = _agent()
    shared = np.ones(agent.sizes.shared)
    forged = wire.encode_shared(TEAM, 1, 1, 1, 0, shared)  # says agent 1...
    agent._on_shared(_Sample(shared_key(PREFIX, 0), forged))  # ...on agent 0's key
    assert agent.rejected["agent not its key's"] == 1 and not agent._shared
    agent._on_shared(_Sample(shared_key(PREFIX, 1), forged))
    assert list(agent._shared) == [(1, 0)] and 1 in agent._shared[(1, 0)]
