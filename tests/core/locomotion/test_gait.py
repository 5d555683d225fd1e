"""Trot schedule, swing timing and Raibert footholds."""

from __future__ import annotations

import numpy as np
import pytest

from core.locomotion.gait import TROT_OFFSETS, FootholdPlanner, TrotGait
from drivers.robot_descriptions import srb_parameters
from tests.core.locomotion.gait_reference import swing_progress


def test_trot_alternates_diagonal_pairs() -> None:
    gait = TrotGait(period_s=0.4, duty_factor=0.5)
    first, second = gait.contacts(0.05), gait.contacts(0.25)
    np.testing.assert_array_equal(first, [1, 0, 0, 1])  # FL + RR
    np.testing.assert_array_equal(second, [0, 1, 1, 0])  # FR + RL
    schedule = gait.schedule(0.0, 40, 0.01)
    assert np.all(schedule.sum(axis=1) == 2)
    assert schedule[:, 0].mean() == pytest.approx(0.5)


def test_contacts_are_the_numpy_phase_rule_exactly() -> None:
    """The four-float contacts equal np.mod's phase rule on every tick of 30 s, at negative
    times and on the exact phase edges (a tick landing on the duty factor is swing)."""
    rng = np.random.default_rng(11)
    for gait in (TrotGait(), TrotGait(period_s=0.4, duty_factor=0.6)):
        times = np.concatenate([np.arange(15000) * 0.002, rng.uniform(-5.0, 5.0, 2000),
                                gait.period_s * np.array([0.0, 0.5, gait.duty_factor, 1.0,
                                                          -0.5, 1.5 - gait.duty_factor])])
        for time_s in times:
            phase = np.mod(float(time_s) / gait.period_s + TROT_OFFSETS, 1.0)
            np.testing.assert_array_equal(gait.contacts(float(time_s)),
                                          (phase < gait.duty_factor).astype(float))


def test_swing_progress_and_touchdown_time() -> None:
    gait = TrotGait(period_s=0.3, duty_factor=0.6)
    # FR starts its swing at phase 0.6 (t = 0.03 s with its half-period offset)
    t = 0.03 + 0.25 * gait.swing_duration_s
    progress = swing_progress(gait, t)
    assert progress[1] == pytest.approx(0.25)
    assert progress[0] == 0.0 and gait.contacts(t)[0] == 1.0
    assert gait.time_to_touchdown_s(t)[1] == pytest.approx(0.75 * gait.swing_duration_s)
    assert gait.swing_duration_s == pytest.approx(0.12)


def test_raibert_footholds_lead_with_velocity_and_correct_errors() -> None:
    robot = srb_parameters("go2")
    gait = TrotGait()
    planner = FootholdPlanner(robot, gait)
    state = np.zeros(12)
    state[2] = robot.nominal_height_m
    planner.reset(state)
    neutral = planner.feet_in_world_m.copy()
    reference = np.zeros(12)
    reference[3] = 0.4
    # walking at the reference speed: feet land half a stance ahead of the (moved) hips
    moving = state.copy()
    moving[3] = 0.4
    targets = planner.swing_targets(0.2, moving, reference[3:6])
    lead = gait.time_to_touchdown_s(0.2)
    swing = gait.contacts(0.2) == 0
    expected_x = neutral[swing, 0] + 0.4 * lead[swing] + 0.4 * gait.stance_duration_s / 2
    np.testing.assert_allclose(targets[swing, 0], expected_x, atol=1e-12)
    assert np.all(targets[:, 2] == 0.0)
    # slower than the reference: feet land further back (capture-point correction)
    slow = moving.copy()
    slow[3] = 0.2
    slow_targets = planner.swing_targets(0.2, slow, reference[3:6])
    assert np.all(slow_targets[swing, 0] < targets[swing, 0])


def horizon_stage_by_stage(planner: FootholdPlanner, time_s: float, steps: int,
                           sample_period_s: float, robot_state: np.ndarray,
                           reference_states: np.ndarray) -> np.ndarray:
    """The per-stage loop the horizon's fill replaced (the reference here)."""
    contacts = planner.gait.schedule(time_s, steps, sample_period_s)
    feet = np.empty((steps, 4, 3))
    current = planner.feet_in_world_m.copy()
    previous = planner._stance.copy()
    for k in range(steps):
        landing = (contacts[k] == 1.0) & (previous == 0.0)
        if np.any(landing):
            target = planner._raibert(robot_state, k * sample_period_s, reference_states[k][3:6])
            current[landing] = target[landing]
        feet[k] = current
        previous = contacts[k]
    return feet


@pytest.mark.parametrize("time_s", [0.0, 0.07, 0.13, 0.31, 1.02])
def test_horizon_feet_are_the_stage_by_stage_footholds(time_s: float) -> None:
    """Feet stay put between landings and move to Raibert's foothold at each landing stage,
    from a stance that is not all-down (mid-trot, as in a run)."""
    rng = np.random.default_rng(int(time_s * 100))
    planner = FootholdPlanner(srb_parameters("go2"), TrotGait())
    state = np.zeros(12)
    state[2] = 0.3
    planner.reset(state)
    planner.update(time_s, state, np.zeros(12))  # the stance of a running trot
    planner.feet_in_world_m += rng.normal(scale=0.02, size=(4, 3))
    robot_state = state + rng.normal(scale=0.1, size=12)
    references = rng.normal(scale=0.3, size=(16, 12))
    feet, contacts = planner.horizon(time_s, 16, 0.05, robot_state, references)
    expected = horizon_stage_by_stage(planner, time_s, 16, 0.05, robot_state, references)
    np.testing.assert_array_equal(feet, expected)
    np.testing.assert_array_equal(contacts, planner.gait.schedule(time_s, 16, 0.05))
    moved = np.any(feet[1:] != feet[:-1], axis=(1, 2))
    assert moved.any() and not moved.all()  # some landings inside the horizon, not at each stage
