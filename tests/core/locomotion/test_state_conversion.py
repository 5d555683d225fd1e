"""The state conversions as one CasADi function: the same (q, v), rotation and SRB state as the
NumPy conversions they replace in ``observe``, interpreted and compiled, for Go2 and A1."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from core.locomotion.state_conversion import StateConversion
from core.locomotion.whole_body_control import FloatingBaseState, WholeBodyController
from deploy.runtime.codegen_cache import CompiledCodeCache
from drivers.robot_descriptions import FOOT_RADIUS_M, load_pinocchio_model, standing_configuration


def _controller(robot_type: str) -> WholeBodyController:
    model = load_pinocchio_model(robot_type)
    return WholeBodyController(model, standing_configuration(robot_type, model),
                               np.array([0.05, -0.02, 0.1]), FOOT_RADIUS_M[robot_type])


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
        q_ref, v_ref = wbc.pinocchio_state(state, rotation)
        srb_ref = wbc.srb_state(state, rotation)
        results = [convert(state) for convert in (interpreted, compiled)]
        for q, v, r, srb in results:
            np.testing.assert_array_equal(q, q_ref)  # copies: exact
            np.testing.assert_allclose(v, v_ref, rtol=0, atol=1e-12)
            np.testing.assert_allclose(r, rotation, rtol=0, atol=1e-14)
            np.testing.assert_allclose(srb, srb_ref, rtol=0, atol=1e-12)
        for first, second in zip(results[0], results[1], strict=True):
            np.testing.assert_array_equal(first, second)  # compiled = interpreted, bit for bit


def test_the_srb_state_is_the_callers_own_and_observe_uses_the_function() -> None:
    wbc = _controller("go2")
    rng = np.random.default_rng(5)
    first, second = _random_state(rng), _random_state(rng)
    srb_first, feet_first = wbc.observe(first)
    kept = srb_first.copy()
    srb_second, _ = wbc.observe(second)
    np.testing.assert_array_equal(srb_first, kept)  # not overwritten by the next call
    np.testing.assert_allclose(srb_second, wbc.srb_state(second), rtol=0, atol=1e-12)
    np.testing.assert_allclose(feet_first, _controller("go2").foot_positions(first),
                               rtol=0, atol=1e-12)
