"""Leg odometry with Pinocchio's arrays filled in place: the same velocities (to round-off: the
quaternion's norm is summed in another order) as the fresh-array formulation it replaced (kept
here as the reference), on Go2 and A1, for every contact pattern."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pinocchio as pin
import pytest

from core.estimation.base_velocity import BaseVelocityEstimator
from drivers.robot_descriptions import load_pinocchio_model


@dataclass
class _Measurement:
    quaternion_wxyz: np.ndarray
    angular_velocity_in_body_rad_s: np.ndarray
    linear_velocity_in_world_m_s: np.ndarray
    position_rad: np.ndarray
    velocity_rad_s: np.ndarray
    foot_contact: np.ndarray


def _reference(estimator: BaseVelocityEstimator, m: _Measurement) -> np.ndarray | None:
    model, data = estimator.model, estimator.model.createData()
    stance = np.flatnonzero(m.foot_contact)
    if stance.size == 0:
        return None
    q = pin.neutral(model)
    w, x, y, z = m.quaternion_wxyz
    q[3:7] = np.array([x, y, z, w]) / np.linalg.norm(m.quaternion_wxyz)
    q[estimator.q_indices] = m.position_rad
    v = np.zeros(model.nv)
    v[3:6] = m.angular_velocity_in_body_rad_s
    v[estimator.v_indices] = m.velocity_rad_s
    pin.forwardKinematics(model, data, q, v)
    pin.updateFramePlacements(model, data)
    velocities = [pin.getFrameVelocity(model, data, estimator.feet[i],
                                       pin.ReferenceFrame.LOCAL_WORLD_ALIGNED).linear
                  for i in stance]
    return -np.mean(velocities, axis=0)


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_leg_odometry_equals_the_fresh_array_formulation(robot_type: str) -> None:
    estimator = BaseVelocityEstimator(load_pinocchio_model(robot_type))
    rng = np.random.default_rng(2)
    for pattern in range(16):  # every contact pattern, several states each
        for _ in range(10):
            quaternion = rng.normal(size=4)
            m = _Measurement(quaternion * rng.uniform(0.9, 1.1) / np.linalg.norm(quaternion),
                             rng.normal(size=3), rng.normal(size=3), rng.normal(size=12) * 0.5,
                             rng.normal(size=12) * 3.0,
                             np.array([bool(pattern >> leg & 1) for leg in range(4)]))
            expected = _reference(estimator, m)
            got = estimator.leg_odometry(m)
            if expected is None:
                assert got is None
            else:
                assert got is not None
                np.testing.assert_allclose(got, expected, rtol=0, atol=1e-14)
