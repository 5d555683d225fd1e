"""ADMM messages through a network that delays and drops them (``ChannelSettings``), with
hold-last at the receiver: one channel per direction, the agents' shared trajectories s^i on
their way to the consensus (uplink) or the coordinator's targets s-bar - w^i on their way to
the agents (downlink).

Round r (one ADMM iteration) sends one message per agent. A message is dropped with probability p,
else it arrives at round r + d, d drawn uniformly from 0..D. What the consensus uses for agent
i at round r is the newest message (by sending round) that has arrived by then, shifted one
stage per MPC update since it was sent (as a warm start is shifted): the paper's hold-last.
The first round's messages always arrive at once (a team starts connected), so there is
always a message to hold. The generator is seeded: the same run draws the same delays;
``stream`` gives each direction draws of its own.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from core.nmpc.settings import ChannelSettings


@dataclass(frozen=True)
class _Message:
    agent: int
    sent_round: int
    sent_update: int
    arrival_round: int
    shared: np.ndarray


class LossyChannel:
    """Delays, drops and holds agents' shared trajectories; ``exchange`` once per round."""

    def __init__(self, settings: ChannelSettings, agent_count: int,
                 shift: Callable[[np.ndarray], np.ndarray], stream: int = 0) -> None:
        """``shift``: one stage earlier for a shared-trajectory vector (last stage repeated);
        ``stream`` 0 (the uplink) draws from ``seed`` alone, another from (seed, stream)."""
        self.settings = settings
        self.stream = stream
        self.agent_count = agent_count
        self._shift = shift
        self.reset()

    def reset(self) -> None:
        seed = self.settings.seed
        self._rng = np.random.default_rng(seed if self.stream == 0 else [seed, self.stream])
        self._round = 0
        self._in_flight: list[_Message] = []
        self._held: list[_Message | None] = [None] * self.agent_count
        self.sent = 0
        self.dropped = 0

    def exchange(self, shared: np.ndarray, update: int) -> tuple[np.ndarray, np.ndarray]:
        """What the receivers hold this round (rows per agent) from what was sent
        (``shared``, rows per agent) during MPC update ``update``, and per agent whether it
        is fresh enough to use (``max_age_rounds``; always with hold-last only)."""
        s = self.settings
        first = self._round == 0
        for agent in range(self.agent_count):
            self.sent += 1
            if self._rng.random() < s.drop_probability and not first:
                self.dropped += 1
                continue
            delay = 0 if first else int(self._rng.integers(0, s.max_delay_rounds + 1))
            self._in_flight.append(_Message(agent, self._round, update, self._round + delay,
                                            np.array(shared[agent])))
        arrived = [m for m in self._in_flight if m.arrival_round <= self._round]
        self._in_flight = [m for m in self._in_flight if m.arrival_round > self._round]
        for message in arrived:
            held = self._held[message.agent]
            if held is None or message.sent_round > held.sent_round:
                self._held[message.agent] = message
        received = np.array(shared, dtype=float)
        fresh = np.ones(self.agent_count, dtype=bool)
        for agent, held in enumerate(self._held):
            assert held is not None  # the first round delivers every message
            limit = s.max_age_rounds
            fresh[agent] = limit is None or self._round - held.sent_round <= limit
            value = held.shared
            for _ in range(max(0, update - held.sent_update)):
                value = self._shift(value)
            received[agent] = value
        self._round += 1
        return received, fresh
