"""The lossy channel: seeded drop and delay statistics, hold-last of the newest message,
shifting held messages by the MPC updates since they were sent, the freshness gate."""

from __future__ import annotations

import numpy as np

from core.communication.lossy_channel import LossyChannel
from core.nmpc.settings import ChannelSettings

AGENTS = 3


def _run(settings: ChannelSettings, rounds: int, rounds_per_update: int = 2
         ) -> tuple[LossyChannel, np.ndarray, np.ndarray]:
    """Each message carries its sending round; the shift adds 1000 per stage, so a received
    value v says: sent at round v % 1000, shifted v // 1000 times."""
    channel = LossyChannel(settings, AGENTS, shift=lambda shared: shared + 1000.0)
    received, fresh = [], []
    for r in range(rounds):
        values, mask = channel.exchange(np.full((AGENTS, 1), float(r)), r // rounds_per_update)
        received.append(values[:, 0])
        fresh.append(mask)
    return channel, np.array(received), np.array(fresh)


def test_drops_and_delays_follow_their_seeded_distributions() -> None:
    channel, received, _ = _run(ChannelSettings(max_delay_rounds=3, drop_probability=0.3,
                                                max_age_rounds=None), 4000, 10**6)
    assert abs(channel.dropped / channel.sent - 0.3) < 0.02  # ~ 5 sigma of a binomial
    ages = np.arange(4000)[:, None] - received
    assert ages.min() == 0 and (ages[0] == 0).all()  # the first round arrives at once
    # a delay is at most 3 rounds; only a run of drops makes the held message older
    assert np.mean(ages <= 3) > 0.75 and set(np.unique(ages[ages <= 3])) == {0, 1, 2, 3}


def test_without_drops_the_held_message_is_never_older_than_the_largest_delay() -> None:
    _, received, _ = _run(ChannelSettings(max_delay_rounds=4, max_age_rounds=None), 2000,
                          10**6)
    ages = np.arange(2000)[:, None] - received
    assert ages.max() <= 4 and np.mean(ages == 0) < 0.5  # delays happen


def test_hold_last_keeps_the_newest_sent_never_an_older_late_arrival() -> None:
    _, received, _ = _run(ChannelSettings(max_delay_rounds=20, drop_probability=0.5,
                                          max_age_rounds=None), 3000, 10**6)
    assert (np.diff(received, axis=0) >= 0).all()


def test_held_messages_are_shifted_by_the_updates_since_they_were_sent() -> None:
    _, received, _ = _run(ChannelSettings(max_delay_rounds=6, drop_probability=0.5,
                                          max_age_rounds=None), 600, rounds_per_update=2)
    shifts, sent = np.divmod(received, 1000.0)
    now = np.arange(600)[:, None]
    np.testing.assert_array_equal(shifts, now // 2 - sent // 2)
    assert shifts.max() > 0


def test_the_same_seed_draws_the_same_channel_and_reset_starts_it_over() -> None:
    settings = ChannelSettings(max_delay_rounds=5, drop_probability=0.4, seed=7)
    a, first, _ = _run(settings, 300)
    _, second, _ = _run(settings, 300)
    _, other, _ = _run(settings.model_copy(update={"seed": 8}), 300)
    np.testing.assert_array_equal(first, second)
    assert not np.array_equal(first, other)
    a.reset()
    assert a.sent == 0 and a.dropped == 0


def test_the_freshness_gate_marks_messages_older_than_max_age() -> None:
    _, received, fresh = _run(ChannelSettings(max_delay_rounds=8, drop_probability=0.5,
                                              max_age_rounds=2), 1000, 10**6)
    sent = received % 1000.0
    ages = np.arange(1000)[:, None] - sent
    np.testing.assert_array_equal(fresh, ages <= 2)
    assert (~fresh).any() and fresh.any()


def test_a_perfect_channel_is_the_default() -> None:
    assert ChannelSettings().perfect
    assert not ChannelSettings(drop_probability=0.1).perfect


def test_each_direction_draws_its_own_seeded_stream() -> None:
    settings = ChannelSettings(max_delay_rounds=5, drop_probability=0.4, seed=7)

    def drops(stream: int) -> list[int]:
        channel = LossyChannel(settings, AGENTS, shift=lambda shared: shared, stream=stream)
        counts = []
        for r in range(200):
            channel.exchange(np.full((AGENTS, 1), float(r)), 0)
            counts.append(channel.dropped)
        return counts

    assert drops(1) == drops(1)  # repeatable
    assert drops(1) != drops(0)  # the downlink does not mirror the uplink's draws
