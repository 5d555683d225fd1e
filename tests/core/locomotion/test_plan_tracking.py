"""The swing set-points as one CasADi function: the same as the NumPy gait and swing functions
over whole gait cycles (every phase, stance and swing legs), interpreted and compiled."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from core.locomotion.gait import TrotGait
from core.locomotion.plan_tracking import LegCoordinator
from core.locomotion.swing_trajectory import swing_point
from deploy.compute.codegen_cache import CompiledCodeCache
from drivers.robot_descriptions import srb_parameters
from tests.core.locomotion.gait_reference import swing_progress


def _numpy_set_points(legs: LegCoordinator, time_s: float, robot_state: np.ndarray,
                      velocity_reference_m_s: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The reference: ``FootholdPlanner.swing_targets`` and ``swing_point`` in NumPy, as the
    coordinator computed its set-points before ``SwingTargets``."""
    targets = legs.planner.swing_targets(time_s, robot_state, velocity_reference_m_s)
    progress = swing_progress(legs.gait, time_s)
    position = legs.planner.feet_in_world_m.copy()
    velocity = np.zeros((4, 3))
    acceleration = np.zeros((4, 3))
    swing = legs.stance == 0.0
    if swing.any():
        point = swing_point(legs.liftoff_m[swing], targets[swing], progress[swing],
                            legs.gait.swing_duration_s, legs.swing_height_m)
        position[swing] = point.position_m
        velocity[swing] = point.velocity_m_s
        acceleration[swing] = point.acceleration_m_s2
    return position, velocity, acceleration


def _walk(legs: LegCoordinator, rng: np.random.Generator, ticks: int
          ) -> list[tuple[tuple[np.ndarray, ...], tuple[np.ndarray, ...]]]:
    """(function, NumPy) set-points per tick of a trot with a drifting, yawing trunk."""
    state = np.zeros(12)
    state[0:3] = (0.2, -0.1, 0.3)
    neutral = legs.robot.nominal_feet_in_body_m
    assert neutral is not None
    feet = neutral + state[0:3]
    feet[:, 2] = 0.0
    legs.reset(state, feet)
    pairs: list[tuple[tuple[np.ndarray, ...], tuple[np.ndarray, ...]]] = []
    for tick in range(ticks):
        t = 0.002 * tick
        state[3:6] = (0.3, 0.05, 0.0) + rng.normal(size=3) * 0.05
        state[0:3] += 0.002 * state[3:6]
        state[8] = 0.4 * np.sin(t)  # yaw
        reference = np.zeros(12)
        reference[3:6] = (0.3, 0.0, 0.0)
        measured = feet + rng.normal(size=(4, 3)) * 0.01
        legs.advance(t, state, reference, measured)
        pairs.append((legs.swing_targets(t, state, reference[3:6]),
                      _numpy_set_points(legs, t, state, reference[3:6])))
    return pairs


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_function_equals_the_numpy_gait_and_swing(robot_type: str) -> None:
    legs = LegCoordinator(srb_parameters(robot_type), TrotGait(0.3, 0.5), 0.08)
    pairs = _walk(legs, np.random.default_rng(2), 400)  # 0.8 s: 2.7 gait cycles
    swinging = 0
    for function, numpy in pairs:
        for got, expected in zip(function, numpy, strict=True):
            assert got.shape == (4, 3)
            np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12)
        swinging += int(np.any(numpy[1] != 0.0))
    assert swinging > 300  # the trot had swing legs in most ticks


def test_compiled_function_is_the_interpreted_one(tmp_path: Path) -> None:
    interpreted = LegCoordinator(srb_parameters("go2"), TrotGait(0.3, 0.5), 0.08)
    compiled = LegCoordinator(srb_parameters("go2"), TrotGait(0.3, 0.5), 0.08,
                              compiler=CompiledCodeCache(tmp_path))
    for (a, _), (b, _) in zip(_walk(interpreted, np.random.default_rng(4), 100),
                              _walk(compiled, np.random.default_rng(4), 100), strict=True):
        for got, expected in zip(b, a, strict=True):
            np.testing.assert_array_equal(got, expected)
    assert compiled._set_points.compiled
    assert len(list(tmp_path.glob("swing_targets_*.so"))) == 1


def test_the_function_is_built_with_the_coordinator_not_in_a_tick(tmp_path: Path) -> None:
    """Its library is compiled and loaded when the coordinator is built: the first swing of a
    run happens inside a real-time tick, where ~10-20 ms of loading tripped the watchdog."""
    legs = LegCoordinator(srb_parameters("go2"), TrotGait(0.3, 0.5), 0.08,
                          compiler=CompiledCodeCache(tmp_path))
    assert len(list(tmp_path.glob("swing_targets_*.so"))) == 1
    assert legs._set_points.compiled
