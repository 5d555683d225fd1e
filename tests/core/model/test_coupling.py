"""Yaw-free coupling: phi, its analytic derivatives against finite differences along a trajectory,
the consistent (phi = 0) configurations, Baumgarte form and the yaw torque."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from core.model.coupling import (
    COUPLING_SIZE,
    acceleration_level_constraint,
    coupling_kinematics,
    coupling_point_in_world,
    yaw_torque,
)
from core.model.srb_model import (
    BodyAcceleration,
    euler_rates_from_angular_velocity,
    payload_acceleration,
    robot_acceleration,
)
from tests.core.rigid_body_math import (
    GRAVITY_M_S2,
    as_array,
    euler_from_rotation,
    expm_so3,
    random_euler,
    random_inertia,
    random_state,
    rot_z,
    rotation,
    skew,
)


def _propagate(x: np.ndarray, linear: np.ndarray, angular: np.ndarray, t: float) -> np.ndarray:
    """State after time t under constant world-frame accelerations.

    p(t) = p + v t + a t^2 / 2 and R(t) = exp(skew(w t + alpha t^2 / 2)) R agree with the exact
    rigid-body motion (R_dot = skew(w(t)) R, w(t) = w + alpha t) up to and including t^2, which is
    all that first and second central differences at t = 0 see.
    """
    p, v, euler, w = x[0:3], x[3:6], x[6:9], x[9:12]
    r = expm_so3(w * t + 0.5 * angular * t * t) @ rotation(euler)
    return np.concatenate([
        p + v * t + 0.5 * linear * t * t, v + linear * t, euler_from_rotation(r), w + angular * t,
    ])


class _Edge:
    """Compiled phi, phi_dot, phi_ddot of one robot-payload edge with numeric parameters."""

    def __init__(self) -> None:
        self.x_r, self.x_l = ca.SX.sym("xr", 12), ca.SX.sym("xl", 12)
        self.c_r, self.c_l = ca.SX.sym("cr", 3), ca.SX.sym("cl", 3)
        self.a_r, self.al_r = ca.SX.sym("ar", 3), ca.SX.sym("alr", 3)
        self.a_l, self.al_l = ca.SX.sym("al", 3), ca.SX.sym("all", 3)
        kin = coupling_kinematics(
            self.x_r, BodyAcceleration(self.a_r, self.al_r), self.c_r,
            self.x_l, BodyAcceleration(self.a_l, self.al_l), self.c_l,
        )
        args = [self.x_r, self.c_r, self.x_l, self.c_l, self.a_r, self.al_r, self.a_l, self.al_l]
        self.kin = kin
        self.all = ca.Function("kin", args, [kin.phi, kin.phi_dot, kin.phi_ddot])
        self.phi = ca.Function("phi", [self.x_r, self.c_r, self.x_l, self.c_l], [kin.phi])

    def evaluate(self, *args) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        phi, phi_dot, phi_ddot = self.all(*args)
        return as_array(phi), as_array(phi_dot), as_array(phi_ddot)


@pytest.fixture(scope="module")
def edge() -> _Edge:
    return _Edge()


def _random_scene(rng: np.random.Generator):
    """Random robot/payload states, GRFs, feet and wrench; accelerations from the SRB model."""
    x_r, x_l = random_state(rng, tilt=0.6), random_state(rng, tilt=0.6)
    c_r = rng.normal(size=3) * 0.2
    c_l = rng.normal(size=3) * 0.4
    grf = rng.normal(size=12) * 20 + np.tile([0, 0, 40.0], 4)
    feet = x_r[0:3, None] + rng.normal(size=(3, 4)) * 0.3
    wrench = rng.normal(size=6) * np.array([10, 10, 10, 2, 2, 2])
    m_r, i_r = ca.DM(15.0), ca.DM(random_inertia(rng, 0.1))
    m_l, i_l = ca.DM(5.0), ca.DM(random_inertia(rng, 0.2))
    point_r = coupling_point_in_world(ca.DM(x_r), ca.DM(c_r))
    point_l = coupling_point_in_world(ca.DM(x_l), ca.DM(c_l))
    acc_r = robot_acceleration(m_r, i_r, ca.DM(x_r), ca.DM(grf), ca.DM(feet), point_r,
                               ca.DM(wrench), GRAVITY_M_S2)
    acc_l = payload_acceleration(m_l, i_l, ca.DM(x_l), [point_l], [ca.DM(wrench)], GRAVITY_M_S2)
    accelerations = [as_array(a) for a in (acc_r.linear, acc_r.angular, acc_l.linear,
                                           acc_l.angular)]
    return x_r, c_r, x_l, c_l, accelerations


def test_propagation_helper_is_consistent() -> None:
    """The test's own trajectory: Euler angles round-trip and R(t) follows R_dot = skew(w) R."""
    rng = np.random.default_rng(0)
    euler = random_euler(rng, tilt=1.2)
    np.testing.assert_allclose(euler_from_rotation(rotation(euler)), euler, atol=1e-12)
    x = np.concatenate([np.zeros(6), euler, rng.normal(size=3)])
    h = 1e-6
    r_plus = rotation(_propagate(x, np.zeros(3), np.ones(3), h)[6:9])
    r_minus = rotation(_propagate(x, np.zeros(3), np.ones(3), -h)[6:9])
    np.testing.assert_allclose((r_plus - r_minus) / (2 * h), skew(x[9:12]) @ rotation(euler),
                               atol=1e-7)


@pytest.mark.parametrize("seed", range(10))
def test_phi_derivatives_match_finite_differences_along_trajectory(edge: _Edge, seed: int) -> None:
    rng = np.random.default_rng(seed)
    x_r, c_r, x_l, c_l, (a_r, al_r, a_l, al_l) = _random_scene(rng)
    phi, phi_dot, phi_ddot = edge.evaluate(x_r, c_r, x_l, c_l, a_r, al_r, a_l, al_l)

    def phi_at(t: float) -> np.ndarray:
        x_r_t, x_l_t = _propagate(x_r, a_r, al_r, t), _propagate(x_l, a_l, al_l, t)
        return as_array(edge.phi(x_r_t, c_r, x_l_t, c_l))

    np.testing.assert_allclose(phi_at(0.0), phi, atol=1e-12)

    def first(h: float) -> np.ndarray:
        return (phi_at(h) - phi_at(-h)) / (2 * h)

    def second(h: float) -> np.ndarray:
        return (phi_at(h) - 2 * phi_at(0.0) + phi_at(-h)) / (h * h)

    # Central differences, Richardson-extrapolated (truncation error O(h^4)), element-wise.
    h = 2e-3
    np.testing.assert_allclose((4 * first(h / 2) - first(h)) / 3, phi_dot, rtol=0, atol=1e-6)
    np.testing.assert_allclose((4 * second(h / 2) - second(h)) / 3, phi_ddot, rtol=0, atol=1e-4)
    # Plain central differences agree too, within their O(h^2) truncation error.
    np.testing.assert_allclose(first(1e-4), phi_dot, rtol=0, atol=1e-5)
    np.testing.assert_allclose(second(1e-3), phi_ddot, rtol=0,
                               atol=1e-3 * (1 + np.max(np.abs(phi_ddot))))
    # The accelerations matter: phi_ddot is not just the velocity-product (J_dot q_dot) part.
    _, _, drift = edge.evaluate(x_r, c_r, x_l, c_l, *[np.zeros(3)] * 4)
    assert np.max(np.abs(phi_ddot - drift)) > 1.0


@pytest.mark.parametrize("seed", range(5))
def test_phi_derivatives_match_symbolic_chain_rule(edge: _Edge, seed: int) -> None:
    """phi_dot = dphi/dx x_dot and phi_ddot = dphi_dot/dx x_dot with x_dot = (v, a, E^-1 w, alpha)."""
    rng = np.random.default_rng(50 + seed)
    x_r, c_r, x_l, c_l, (a_r, al_r, a_l, al_l) = _random_scene(rng)

    def x_dot(x, linear, angular) -> np.ndarray:
        rates = as_array(euler_rates_from_angular_velocity(ca.DM(x[6:9]), ca.DM(x[9:12])))
        return np.concatenate([x[3:6], linear, rates, angular])

    x_both = ca.vertcat(edge.x_r, edge.x_l)
    jacobians = ca.Function(
        "jacobians", [edge.x_r, edge.c_r, edge.x_l, edge.c_l],
        [ca.jacobian(edge.kin.phi, x_both), ca.jacobian(edge.kin.phi_dot, x_both)],
    )
    j_phi, j_phi_dot = (np.array(m) for m in jacobians(x_r, c_r, x_l, c_l))
    q_dot = np.concatenate([x_dot(x_r, a_r, al_r), x_dot(x_l, a_l, al_l)])
    _, phi_dot, phi_ddot = edge.evaluate(x_r, c_r, x_l, c_l, a_r, al_r, a_l, al_l)
    np.testing.assert_allclose(j_phi @ q_dot, phi_dot, atol=1e-10)
    np.testing.assert_allclose(j_phi_dot @ q_dot, phi_ddot, atol=1e-9)


@pytest.mark.parametrize("seed", range(6))
def test_phi_vanishes_for_consistent_configuration_at_any_relative_yaw(edge: _Edge, seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    euler_l = random_euler(rng, tilt=0.6)
    r_l = rotation(euler_l)
    p_l = rng.normal(size=3)
    c_r, c_l = rng.normal(size=3) * 0.2, rng.normal(size=3) * 0.4
    for relative_yaw in np.linspace(-np.pi, np.pi, 7):
        r_r = r_l @ rot_z(relative_yaw)  # robot z-axis parallel to the payload's
        p_r = p_l + r_l @ c_l - r_r @ c_r  # coupling points coincide
        x_r = np.concatenate([p_r, np.zeros(3), euler_from_rotation(r_r), np.zeros(3)])
        x_l = np.concatenate([p_l, np.zeros(3), euler_l, np.zeros(3)])
        phi = as_array(edge.phi(x_r, c_r, x_l, c_l))
        assert phi.shape == (COUPLING_SIZE,)
        np.testing.assert_allclose(phi, np.zeros(COUPLING_SIZE), atol=1e-12)
    # Tilting the robot relative to the payload (roll or pitch about its own axes) breaks it.
    for axis in (0, 1):
        tilt = np.zeros(3)
        tilt[axis] = 0.1
        from_tilt = r_l @ rotation(tilt)
        x_r = np.concatenate([p_l + r_l @ c_l - from_tilt @ c_r, np.zeros(3),
                              euler_from_rotation(from_tilt), np.zeros(3)])
        phi = as_array(edge.phi(x_r, c_r, np.concatenate([p_l, np.zeros(3), euler_l, np.zeros(3)]),
                           c_l))
        np.testing.assert_allclose(phi[0:3], np.zeros(3), atol=1e-12)
        assert np.linalg.norm(phi[3:5]) == pytest.approx(np.sin(0.1), rel=1e-9)
    # Displacing the robot translates phi[0:3] by exactly the displacement.
    shift = rng.normal(size=3)
    x_r = np.concatenate([p_l + r_l @ c_l - r_l @ c_r + shift, np.zeros(3), euler_l, np.zeros(3)])
    phi = as_array(edge.phi(x_r, c_r, np.concatenate([p_l, np.zeros(3), euler_l, np.zeros(3)]), c_l))
    np.testing.assert_allclose(phi, np.concatenate([shift, np.zeros(2)]), atol=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_phi_dot_vanishes_for_coupled_motion_with_free_relative_yaw_rate(
    edge: _Edge, seed: int
) -> None:
    """Robot moving with the payload, plus any yaw rate about the shared coupling axis."""
    rng = np.random.default_rng(200 + seed)
    euler_l = random_euler(rng, tilt=0.6)
    r_l = rotation(euler_l)
    p_l, v_l, w_l = rng.normal(size=3), rng.normal(size=3), rng.normal(size=3)
    c_r, c_l = rng.normal(size=3) * 0.2, rng.normal(size=3) * 0.4
    r_r = r_l @ rot_z(rng.uniform(-np.pi, np.pi))
    d_r, d_l = r_r @ c_r, r_l @ c_l
    p_r = p_l + d_l - d_r
    w_r = w_l + rng.normal() * 3.0 * r_l[:, 2]
    v_r = v_l + np.cross(w_l, d_l) - np.cross(w_r, d_r)
    x_r = np.concatenate([p_r, v_r, euler_from_rotation(r_r), w_r])
    x_l = np.concatenate([p_l, v_l, euler_l, w_l])
    phi, phi_dot, _ = edge.evaluate(x_r, c_r, x_l, c_l, *[np.zeros(3)] * 4)
    np.testing.assert_allclose(phi, np.zeros(COUPLING_SIZE), atol=1e-12)
    np.testing.assert_allclose(phi_dot, np.zeros(COUPLING_SIZE), atol=1e-12)
    # A relative roll rate is not free.
    x_r_rolling = x_r.copy()
    x_r_rolling[9:12] = w_r + 0.5 * r_l[:, 0]
    _, phi_dot_rolling, _ = edge.evaluate(x_r_rolling, c_r, x_l, c_l, *[np.zeros(3)] * 4)
    assert np.linalg.norm(phi_dot_rolling[3:5]) == pytest.approx(0.5, rel=1e-9)


def test_phi_ddot_is_none_without_both_accelerations() -> None:
    x = ca.SX.sym("x", 12)
    acc = BodyAcceleration(ca.SX.sym("a", 3), ca.SX.sym("al", 3))
    c = ca.DM([0, 0, 0.1])
    assert coupling_kinematics(x, None, c, x, acc, c).phi_ddot is None
    assert coupling_kinematics(x, acc, c, x, None, c).phi_ddot is None


@pytest.mark.parametrize("zeta, w", [(1.0, 10.0), (0.7, 3.0)])
def test_baumgarte_form(edge: _Edge, zeta: float, w: float) -> None:
    rng = np.random.default_rng(7)
    x_r, c_r, x_l, c_l, accelerations = _random_scene(rng)
    args = [edge.x_r, edge.c_r, edge.x_l, edge.c_l, edge.a_r, edge.al_r, edge.a_l, edge.al_l]
    stabilized = ca.Function("b", args, [acceleration_level_constraint(edge.kin, True, zeta, w)])
    plain = ca.Function("p", args, [acceleration_level_constraint(edge.kin, False, zeta, w)])
    values = (x_r, c_r, x_l, c_l, *accelerations)
    phi, phi_dot, phi_ddot = edge.evaluate(*values)
    assert np.max(np.abs(phi)) > 0.1 and np.max(np.abs(phi_dot)) > 0.1  # terms are exercised
    np.testing.assert_allclose(as_array(stabilized(*values)),
                               phi_ddot + 2 * zeta * w * phi_dot + w * w * phi, atol=1e-9)
    np.testing.assert_allclose(as_array(plain(*values)), phi_ddot, atol=1e-12)


@pytest.mark.parametrize("seed", range(5))
def test_yaw_torque_is_torque_along_payload_z(seed: int) -> None:
    rng = np.random.default_rng(300 + seed)
    euler = random_euler(rng, tilt=1.0)
    r = rotation(euler)
    x_l = np.concatenate([rng.normal(size=6), euler, rng.normal(size=3)])
    along_z, along_x, along_y = rng.normal(size=3)
    torque = along_z * r[:, 2] + along_x * r[:, 0] + along_y * r[:, 1]
    wrench = np.concatenate([rng.normal(size=3) * 50, torque])
    assert as_array(yaw_torque(ca.DM(x_l), ca.DM(wrench))) == pytest.approx(along_z, abs=1e-12)
    # Forces do not contribute; a torque about world z does not either unless the payload is level.
    wrench[0:3] = 0
    assert as_array(yaw_torque(ca.DM(x_l), ca.DM(wrench))) == pytest.approx(along_z, abs=1e-12)
    x_level = x_l.copy()
    x_level[6:8] = 0.0
    world_z = np.concatenate([np.zeros(3), [0.3, -0.2, 1.5]])
    assert as_array(yaw_torque(ca.DM(x_level), ca.DM(world_z))) == pytest.approx(1.5, abs=1e-12)
