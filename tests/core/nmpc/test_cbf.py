"""Discrete-time HOCBF: the stage-wise form equals the three-stage condition on states propagated
with the model's integrator, for static and moving obstacles."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from core.model.srb_model import BodyAcceleration, semi_implicit_euler_step
from core.nmpc.cbf import (
    OBSTACLE_PARAMETER_SIZE,
    PARKED_OBSTACLE,
    hocbf_condition,
    obstacle_position,
    safety_function,
    stagewise_hocbf,
)
from tests.core.rigid_body_math import as_array, random_state

TS = 1.0 / 60.0


def _h(position_xy: np.ndarray, obstacle: np.ndarray, stage: int) -> float:
    """Safety function computed directly: ||p - (o + stage Ts vo)|| - d."""
    o = obstacle[0:2] + stage * TS * obstacle[2:4]
    return float(np.linalg.norm(position_xy - o) - obstacle[4])


def _random_acceleration(rng: np.random.Generator) -> BodyAcceleration:
    return BodyAcceleration(ca.DM(rng.normal(size=3) * 5), ca.DM(rng.normal(size=3) * 5))


def _obstacle(rng: np.random.Generator, moving: bool) -> np.ndarray:
    velocity = rng.normal(size=2) * 1.5 if moving else np.zeros(2)
    return np.concatenate([rng.normal(size=2) * 1.5, velocity, [rng.uniform(0.3, 0.9)]])


@pytest.mark.parametrize("moving", [False, True])
@pytest.mark.parametrize("stage", [1, 2, 7])
@pytest.mark.parametrize("seed", range(4))
def test_stagewise_hocbf_equals_three_stage_condition(moving: bool, stage: int, seed: int) -> None:
    rng = np.random.default_rng(seed)
    alpha1, alpha2 = 0.4, 0.04
    obstacle = _obstacle(rng, moving)
    x_prev = random_state(rng, tilt=0.5)
    acc_prev, acc_k = _random_acceleration(rng), _random_acceleration(rng)
    x_k = as_array(semi_implicit_euler_step(ca.DM(x_prev), acc_prev, TS))
    x_next = as_array(semi_implicit_euler_step(ca.DM(x_k), acc_k, TS))
    h_prev = _h(x_prev[0:2], obstacle, stage - 1)
    h_k = _h(x_k[0:2], obstacle, stage)
    h_next = _h(x_next[0:2], obstacle, stage + 1)
    three_stage = h_next - (2 - alpha1 - alpha2) * h_k + (1 - alpha1) * (1 - alpha2) * h_prev
    stagewise = float(stagewise_hocbf(ca.DM(x_k), acc_k.linear, ca.DM(obstacle), stage, TS,
                                      alpha1, alpha2))
    assert stagewise == pytest.approx(three_stage, abs=1e-12)
    # The library's own three-stage building blocks give the same number.
    h = [float(safety_function(ca.DM(x[0:2]), obstacle_position(ca.DM(obstacle), s, TS),
                               obstacle[4]))
         for x, s in ((x_prev, stage - 1), (x_k, stage), (x_next, stage + 1))]
    np.testing.assert_allclose(h, [h_prev, h_k, h_next], atol=1e-12)
    assert float(hocbf_condition(*h, alpha1, alpha2)) == pytest.approx(three_stage, abs=1e-12)


def test_obstacle_motion_is_used_by_the_stagewise_form() -> None:
    """A moving obstacle must change the condition compared with a static one at the same spot."""
    rng = np.random.default_rng(1)
    x_k = random_state(rng, tilt=0.5)
    acc = rng.normal(size=3)
    static = np.array([0.5, -0.2, 0.0, 0.0, 0.4])
    moving = static.copy()
    moving[2:4] = (2.0, -1.0)
    args = (ca.DM(x_k), ca.DM(acc))
    value_static = float(stagewise_hocbf(*args, ca.DM(static), 3, TS, 0.4, 0.04))
    value_moving = float(stagewise_hocbf(*args, ca.DM(moving), 3, TS, 0.4, 0.04))
    assert abs(value_static - value_moving) > 1e-3
    # Constant-velocity prediction of the obstacle position.
    np.testing.assert_allclose(as_array(obstacle_position(ca.DM(moving), 3, TS)),
                               moving[0:2] + 3 * TS * moving[2:4], atol=1e-15)


@pytest.mark.parametrize("seed", range(4))
def test_hocbf_condition_is_the_nested_second_order_barrier(seed: int) -> None:
    """psi1_k = h_{k+1} - (1 - a1) h_k, psi2_k = psi1_{k+1} - (1 - a2) psi1_k (DT-HOCBF)."""
    rng = np.random.default_rng(seed)
    h0, h1, h2 = rng.normal(size=3)
    a1, a2 = rng.uniform(0.01, 1.0, size=2)
    psi1_0 = h1 - (1 - a1) * h0
    psi1_1 = h2 - (1 - a1) * h1
    psi2_0 = psi1_1 - (1 - a2) * psi1_0
    assert float(hocbf_condition(h0, h1, h2, a1, a2)) == pytest.approx(psi2_0, abs=1e-12)


def test_safety_function_is_signed_clearance() -> None:
    assert float(safety_function(ca.DM([3.0, 4.0]), ca.DM([0.0, 0.0]), 1.0)) == pytest.approx(4.0)
    assert float(safety_function(ca.DM([0.1, 0.0]), ca.DM([0.0, 0.0]), 0.6)) == pytest.approx(-0.5)


def test_parked_obstacle_slot_is_inactive() -> None:
    assert len(PARKED_OBSTACLE) == OBSTACLE_PARAMETER_SIZE
    rng = np.random.default_rng(2)
    x_k = random_state(rng, tilt=0.5)
    value = float(stagewise_hocbf(ca.DM(x_k), ca.DM(rng.normal(size=3) * 50),
                                  ca.DM(PARKED_OBSTACLE), 7, TS, 0.4, 0.04))
    # Far away the condition is ~ a1 a2 h > 0 with h ~ 1.4e4 m.
    assert value > 100.0
