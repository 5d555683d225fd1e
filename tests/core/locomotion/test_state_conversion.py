"""The state conversions as one CasADi function: the same (q, v), rotation and SRB state as
their NumPy formulation (kept here as the reference), interpreted and compiled, for Go2 and A1;
the controller's ``srb_state`` / ``pinocchio_state`` are the function's."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from core.locomotion.whole_body_control import FloatingBaseState, StateConversion, WholeBodyController
from core.model.rotations import cross3, euler_from_rotation
from deploy.compute.codegen_cache import CompiledCodeCache
from drivers.robot_descriptions import FOOT_RADIUS_M, load_pinocchio_model, standing_configuration


def _controller(robot_type: str) -> WholeBodyController:
    model = load_pinocchio_model(robot_type)
    return WholeBodyController(model, standing_configuration(robot_type, model),
                               np.array([0.05, -0.02, 0.1]), FOOT_RADIUS_M[robot_type])


def _numpy_pinocchio_state(state: FloatingBaseState, rotation: np.ndarray
                           ) -> tuple[np.ndarray, np.ndarray]:
    """Reference (q, v): quaternion reordered to xyzw, base velocity rotated into the base."""
    w, x, y, z = state.quaternion_wxyz
    q = np.concatenate([state.position_base_in_world_m, (x, y, z, w), state.joint_position_rad])
    v = np.concatenate([rotation.T @ state.linear_velocity_in_world_m_s,
                        state.angular_velocity_in_body_rad_s, state.joint_velocity_rad_s])
    return q, v


def _numpy_srb_state(state: FloatingBaseState, rotation: np.ndarray,
                     com_offset_in_base_m: np.ndarray) -> np.ndarray:
    """Reference SRB state: CoM at the standing offset, its velocity, XYZ Euler, omega in world."""
    offset = rotation @ com_offset_in_base_m
    omega = rotation @ state.angular_velocity_in_body_rad_s
    return np.concatenate([state.position_base_in_world_m + offset,
                           state.linear_velocity_in_world_m_s + cross3(omega, offset),
                           euler_from_rotation(rotation), omega])


def _random_state(rng: np.random.Generator) -> FloatingBaseState:
    """A state with a measured quaternion that is not quite unit (as a sensor's), large
    attitudes (pitch near +-pi/2 included) and random twists and joints."""
    quaternion = rng.normal(size=4)
    quaternion *= rng.uniform(0.98, 1.02) / np.linalg.norm(quaternion)
    return FloatingBaseState(rng.normal(size=3), quaternion, rng.normal(size=3),
                             rng.normal(size=3) * 2.0, rng.normal(size=12),
                             rng.normal(size=12) * 5.0)


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_the_function_equals_the_numpy_conversions(robot_type: str, tmp_path: Path) -> None:
    wbc = _controller(robot_type)
    interpreted = StateConversion(wbc.com_offset_in_base_m)
    compiled = StateConversion(wbc.com_offset_in_base_m, CompiledCodeCache(tmp_path))
    assert compiled.compiled and not interpreted.compiled
    rng = np.random.default_rng(3)
    states = [_random_state(rng) for _ in range(200)]
    pitched = _random_state(rng)  # Ry(pi/2): R[2, 0] = -1 exactly, arcsin's clipped edge
    pitched.quaternion_wxyz[:] = (np.sqrt(0.5), 0.0, np.sqrt(0.5), 0.0)
    for state in [*states, pitched]:
        rotation = state.rotation()
        q_ref, v_ref = _numpy_pinocchio_state(state, rotation)
        srb_ref = _numpy_srb_state(state, rotation, wbc.com_offset_in_base_m)
        results = [convert(state) for convert in (interpreted, compiled)]
        for q, v, r, srb in results:
            np.testing.assert_array_equal(q, q_ref)  # copies: exact
            np.testing.assert_allclose(v, v_ref, rtol=0, atol=1e-12)
            np.testing.assert_allclose(r, rotation, rtol=0, atol=1e-14)
            np.testing.assert_allclose(srb, srb_ref, rtol=0, atol=1e-12)
        for first, second in zip(results[0], results[1], strict=True):
            np.testing.assert_array_equal(first, second)  # compiled = interpreted, bit for bit
        q, v = wbc.pinocchio_state(state)  # the controller's own: the same function
        np.testing.assert_array_equal(q, results[0][0])
        np.testing.assert_array_equal(v, results[0][1])
        np.testing.assert_array_equal(wbc.srb_state(state), results[0][3])


def test_the_srb_state_is_the_callers_own_and_observe_uses_the_function() -> None:
    wbc = _controller("go2")
    rng = np.random.default_rng(5)
    first, second = _random_state(rng), _random_state(rng)
    srb_first, feet_first = wbc.observe(first)
    kept = srb_first.copy()
    srb_second, _ = wbc.observe(second)
    np.testing.assert_array_equal(srb_first, kept)  # not overwritten by the next call
    np.testing.assert_array_equal(srb_second, wbc.srb_state(second))
    np.testing.assert_allclose(feet_first, _controller("go2").foot_positions(first),
                               rtol=0, atol=1e-12)

