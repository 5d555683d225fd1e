"""Obstacle slots: the K nearest obstacles over the horizon, never silently dropping one that
gets within its margin."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from core.model.obstacles import Obstacle
from core.nmpc.cbf import PARKED_OBSTACLE
from core.nmpc.obstacle_selection import predicted_min_safety_values, select_obstacles
from core.nmpc.transport_problem import build_transport_problem
from tests.core.controller_fixtures import inputs_at_start, settings, team

TS = 1.0 / 60.0
N = 8


def straight_path(speed_m_s: float = 0.3) -> np.ndarray:
    """One body moving along +x from the origin, stages 0..N: (1, N + 1, 2)."""
    x = speed_m_s * TS * np.arange(N + 1)
    return np.stack([x, np.zeros(N + 1)], axis=1)[None]


def test_min_safety_value_matches_a_brute_force_sweep() -> None:
    rng = np.random.default_rng(1)
    positions = rng.normal(size=(3, N + 1, 2))
    obstacles = np.column_stack([rng.normal(size=(5, 2)), rng.normal(size=(5, 2)),
                                 rng.uniform(0.3, 0.8, 5)])
    expected = [min(np.linalg.norm(positions[b, k] - (o[0:2] + k * TS * o[2:4])) - o[4]
                    for b in range(3) for k in range(N + 1)) for o in obstacles]
    np.testing.assert_allclose(predicted_min_safety_values(positions, obstacles, TS), expected)


def test_an_obstacle_closing_in_within_the_horizon_beats_a_nearer_receding_one() -> None:
    d = 0.6
    obstacles = np.array([
        [0.0, 0.75, 0.0, 1.0, d],    # h = 0.15 m now, moving away at 1 m/s
        [0.0, -0.9, 0.0, 3.0, d],    # h = 0.30 m now, crossing the path at 3 m/s
        [2.0, 0.0, 0.0, 0.0, d],     # far ahead
    ])
    selection = select_obstacles(straight_path(), obstacles, 1, TS)
    assert selection.min_h_m[1] < 0.0 < selection.min_h_m[0]
    assert list(selection.indices) == [1]
    assert selection.dropped_near == ()


def test_every_obstacle_inside_its_margin_is_kept_while_slots_suffice() -> None:
    rng = np.random.default_rng(7)
    for _ in range(200):
        count = rng.integers(1, 9)
        obstacles = np.column_stack([rng.uniform(-2, 2, (count, 2)), rng.uniform(-1, 1, (count, 2)),
                                     rng.uniform(0.3, 0.9, count)])
        positions = straight_path() + rng.normal(scale=0.2, size=(1, 1, 2))
        slots = int(rng.integers(0, 5))
        selection = select_obstacles(positions, obstacles, slots, TS)
        inside = set(np.flatnonzero(selection.min_h_m <= 0.0).tolist())
        assert len(selection.indices) == min(slots, count)
        if len(inside) <= slots:
            assert inside <= set(selection.indices.tolist())
            assert selection.dropped_near == ()
        else:  # more than the slots can hold: the left-out ones are reported
            assert set(selection.dropped_near) == inside - set(selection.indices.tolist())
            assert len(selection.dropped_near) == len(inside) - slots


def test_slots_are_filled_with_the_selection_then_parked() -> None:
    model = team()
    mpc = settings(safety=settings().safety.model_copy(update={"obstacle_slots": 2}))
    problem = build_transport_problem(mpc, 2, local=True)
    inputs = inputs_at_start(model, mpc, [Obstacle((4.0, 0.0)), Obstacle((1.0, 0.9)),
                                          Obstacle((1.2, -0.9)), Obstacle((0.3, 1.2))])
    target = np.zeros(problem.consensus_weights().size)
    selection = problem.select_obstacles(inputs, agent=0)
    assert len(selection.indices) == 2 and 0 not in selection.indices  # the far one is out
    values = problem.parameter_vector(model, inputs, agent=0, consensus_target=target,
                                      selection=selection)
    rows = problem.nlp.parameters.get(values, "obstacles").reshape(-1, 5)
    np.testing.assert_array_equal(rows, inputs.obstacles[selection.indices])
    # fewer obstacles than slots: the free slot is parked
    single = dataclasses.replace(inputs, obstacles=inputs.obstacles[:1])
    values = problem.parameter_vector(model, single, agent=0, consensus_target=target)
    rows = problem.nlp.parameters.get(values, "obstacles").reshape(-1, 5)
    np.testing.assert_array_equal(rows, [single.obstacles[0], PARKED_OBSTACLE])


def test_more_slots_than_the_scene_allows_is_rejected() -> None:
    with pytest.raises(ValueError, match="obstacle_slots"):
        settings().safety.model_validate({"obstacle_slots": 9, "max_obstacles": 8})
