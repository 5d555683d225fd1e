"""Single-rigid-body model: rotation convention, Euler-rate map, Newton-Euler and integrator."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pinocchio as pin
import pytest

from core.model.srb_model import (
    BodyAcceleration,
    SrbParameters,
    euler_rates_from_angular_velocity,
    inertia_entries,
    inertia_matrix,
    payload_acceleration,
    payload_parameters,
    rigid_body_acceleration,
    robot_acceleration,
    semi_implicit_euler_step,
)
from tests.core.rigid_body_math import (
    GRAVITY_M_S2,
    as_array,
    random_euler,
    random_inertia,
    random_state,
    rot_x,
    rot_y,
    rot_z,
    rotation,
    skew,
)


@pytest.mark.parametrize("seed", range(8))
def test_rotation_is_proper_and_matches_rz_ry_rx(seed: int) -> None:
    rng = np.random.default_rng(seed)
    roll, pitch, yaw = rng.uniform(-np.pi, np.pi, size=3)
    r = rotation([roll, pitch, yaw])
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12)
    assert np.linalg.det(r) == pytest.approx(1.0, abs=1e-12)
    # Extrinsic x-y-z (scipy's from_euler('xyz', ...)) composes as Rz Ry Rx.
    np.testing.assert_allclose(r, rot_z(yaw) @ rot_y(pitch) @ rot_x(roll), atol=1e-12)
    # Independent library reference: Pinocchio's rpyToMatrix is Rz(y) Ry(p) Rx(r).
    np.testing.assert_allclose(r, pin.rpy.rpyToMatrix(roll, pitch, yaw), atol=1e-12)


def test_rotation_columns_are_body_axes_in_world() -> None:
    # A pure yaw of 90 deg maps body x to world y; a pure pitch of 90 deg maps body x to -z.
    np.testing.assert_allclose(rotation([0, 0, np.pi / 2]) @ [1, 0, 0], [0, 1, 0], atol=1e-12)
    np.testing.assert_allclose(rotation([0, np.pi / 2, 0]) @ [1, 0, 0], [0, 0, -1], atol=1e-12)
    np.testing.assert_allclose(rotation([np.pi / 2, 0, 0]) @ [0, 1, 0], [0, 0, 1], atol=1e-12)


@pytest.mark.parametrize("seed", range(8))
def test_euler_rates_reproduce_world_angular_velocity(seed: int) -> None:
    """Moving Theta along E^-1 omega rotates the body with R_dot R^T = skew(omega)."""
    rng = np.random.default_rng(100 + seed)
    euler = random_euler(rng)
    omega = rng.normal(size=3) * 2.0
    rates = as_array(euler_rates_from_angular_velocity(ca.DM(euler), ca.DM(omega)))
    h = 1e-6
    r_dot = (rotation(euler + h * rates) - rotation(euler - h * rates)) / (2 * h)
    np.testing.assert_allclose(r_dot @ rotation(euler).T, skew(omega), atol=1e-7)


def test_euler_rates_map_is_linear_and_invertible() -> None:
    rng = np.random.default_rng(7)
    euler = random_euler(rng)
    columns = [as_array(euler_rates_from_angular_velocity(ca.DM(euler), ca.DM(e))) for e in np.eye(3)]
    e_inv = np.column_stack(columns)
    omega = rng.normal(size=3)
    rates = as_array(euler_rates_from_angular_velocity(ca.DM(euler), ca.DM(omega)))
    np.testing.assert_allclose(rates, e_inv @ omega, atol=1e-12)
    # E(Theta) for Rz Ry Rx: omega = Rz Ry e_x roll_rate + Rz e_y pitch_rate + e_z yaw_rate.
    _, pitch, yaw = euler
    e = np.column_stack([rot_z(yaw) @ rot_y(pitch) @ [1, 0, 0], rot_z(yaw) @ [0, 1, 0], [0, 0, 1]])
    np.testing.assert_allclose(e_inv @ e, np.eye(3), atol=1e-12)


def test_free_fall_accelerates_at_minus_g() -> None:
    rng = np.random.default_rng(3)
    x = random_state(rng)
    x[9:12] = 0.0  # not spinning: no gyroscopic acceleration either
    inertia = ca.DM(random_inertia(rng))
    acc = rigid_body_acceleration(ca.DM(7.3), inertia, ca.DM(x), ca.DM.zeros(3), ca.DM.zeros(3),
                                  GRAVITY_M_S2)
    np.testing.assert_allclose(as_array(acc.linear), [0, 0, -GRAVITY_M_S2], atol=1e-12)
    np.testing.assert_allclose(as_array(acc.angular), np.zeros(3), atol=1e-12)

    feet = ca.DM(rng.normal(size=(3, 4)))
    robot = robot_acceleration(ca.DM(15.0), inertia, ca.DM(x), ca.DM.zeros(12), feet,
                               ca.DM(rng.normal(size=3)), ca.DM.zeros(6), GRAVITY_M_S2)
    np.testing.assert_allclose(as_array(robot.linear), [0, 0, -GRAVITY_M_S2], atol=1e-12)
    np.testing.assert_allclose(as_array(robot.angular), np.zeros(3), atol=1e-12)

    points = [ca.DM(rng.normal(size=3)) for _ in range(3)]
    payload = payload_acceleration(ca.DM(5.0), inertia, ca.DM(x), points,
                                   [ca.DM.zeros(6)] * 3, GRAVITY_M_S2)
    np.testing.assert_allclose(as_array(payload.linear), [0, 0, -GRAVITY_M_S2], atol=1e-12)


@pytest.mark.parametrize("seed", range(5))
def test_newton_euler_matches_body_frame_euler_equations(seed: int) -> None:
    """I_b w_b_dot + w_b x I_b w_b = tau_b with w_b = R^T w, w_b_dot = R^T alpha; F = m (a + g)."""
    rng = np.random.default_rng(200 + seed)
    x = random_state(rng)
    mass = rng.uniform(1, 20)
    inertia_body = random_inertia(rng)
    force, torque = rng.normal(size=3) * 20, rng.normal(size=3) * 5
    acc = rigid_body_acceleration(ca.DM(mass), ca.DM(inertia_body), ca.DM(x), ca.DM(force),
                                  ca.DM(torque), GRAVITY_M_S2)
    r = rotation(x[6:9])
    w_b = r.T @ x[9:12]
    w_b_dot = r.T @ as_array(acc.angular)
    np.testing.assert_allclose(inertia_body @ w_b_dot + np.cross(w_b, inertia_body @ w_b),
                               r.T @ torque, atol=1e-9)
    np.testing.assert_allclose(mass * (as_array(acc.linear) + [0, 0, GRAVITY_M_S2]), force, atol=1e-9)


@pytest.mark.parametrize("seed", range(5))
def test_robot_and_payload_wrenches_are_action_reaction(seed: int) -> None:
    """With the coupling points coincident, the wrench is internal: the robot+payload system's
    linear and angular momentum (about the world origin) change only by GRFs and gravity."""
    rng = np.random.default_rng(300 + seed)
    x_r, x_l = random_state(rng), random_state(rng)
    m_r, m_l = 15.0, 5.0
    i_r, i_l = random_inertia(rng), random_inertia(rng)
    point = x_l[0:3] + rng.normal(size=3) * 0.3  # shared coupling point [m]
    grf = rng.normal(size=12) * 30
    feet = rng.normal(size=(3, 4))
    wrench = rng.normal(size=6) * 10
    acc_r = robot_acceleration(ca.DM(m_r), ca.DM(i_r), ca.DM(x_r), ca.DM(grf), ca.DM(feet),
                               ca.DM(point), ca.DM(wrench), GRAVITY_M_S2)
    acc_l = payload_acceleration(ca.DM(m_l), ca.DM(i_l), ca.DM(x_l), [ca.DM(point)],
                                 [ca.DM(wrench)], GRAVITY_M_S2)
    g = np.array([0, 0, -GRAVITY_M_S2])
    f_feet = grf.reshape(4, 3)
    np.testing.assert_allclose(
        m_r * as_array(acc_r.linear) + m_l * as_array(acc_l.linear),
        f_feet.sum(axis=0) + (m_r + m_l) * g, atol=1e-8,
    )

    def momentum_rate(x, mass, inertia_body, acc) -> np.ndarray:
        r = rotation(x[6:9])
        i_w = r @ inertia_body @ r.T
        w = x[9:12]
        return (np.cross(x[0:3], mass * as_array(acc.linear))
                + i_w @ as_array(acc.angular) + np.cross(w, i_w @ w))

    external = sum(np.cross(feet[:, leg], f_feet[leg]) for leg in range(4))
    external = external + np.cross(x_r[0:3], m_r * g) + np.cross(x_l[0:3], m_l * g)
    np.testing.assert_allclose(
        momentum_rate(x_r, m_r, i_r, acc_r) + momentum_rate(x_l, m_l, i_l, acc_l),
        external, atol=1e-7,
    )


def test_symbolic_mass_and_inertia_give_the_numeric_result() -> None:
    rng = np.random.default_rng(11)
    x = random_state(rng)
    inertia = random_inertia(rng)
    force, torque = rng.normal(size=3), rng.normal(size=3)
    mass_sym, entries_sym = ca.SX.sym("m"), ca.SX.sym("i", 6)
    acc = rigid_body_acceleration(mass_sym, inertia_matrix(entries_sym), ca.DM(x), ca.DM(force),
                                  ca.DM(torque), GRAVITY_M_S2)
    f = ca.Function("f", [mass_sym, entries_sym], [acc.linear, acc.angular])
    lin, ang = f(4.0, inertia_entries(inertia))
    ref = rigid_body_acceleration(ca.DM(4.0), ca.DM(inertia), ca.DM(x), ca.DM(force),
                                  ca.DM(torque), GRAVITY_M_S2)
    np.testing.assert_allclose(as_array(lin), as_array(ref.linear), atol=1e-12)
    np.testing.assert_allclose(as_array(ang), as_array(ref.angular), atol=1e-10)


@pytest.mark.parametrize("seed", range(5))
def test_semi_implicit_euler_step(seed: int) -> None:
    rng = np.random.default_rng(400 + seed)
    x = random_state(rng)
    linear, angular = rng.normal(size=3) * 5, rng.normal(size=3) * 5
    ts = 1.0 / 60.0
    x_next = as_array(semi_implicit_euler_step(ca.DM(x), BodyAcceleration(ca.DM(linear),
                                                                     ca.DM(angular)), ts))
    v_next, w_next = x_next[3:6], x_next[9:12]
    np.testing.assert_allclose(v_next, x[3:6] + ts * linear, atol=1e-12)
    np.testing.assert_allclose(w_next, x[9:12] + ts * angular, atol=1e-12)
    # Positions use the *new* velocity: p_{k+1} = p_k + Ts v_{k+1} (so p_k = p_{k+1} - Ts v_{k+1}).
    np.testing.assert_allclose(x_next[0:3], x[0:3] + ts * v_next, atol=1e-12)
    assert not np.allclose(x_next[0:3], x[0:3] + ts * x[3:6], atol=1e-6)
    rates = as_array(euler_rates_from_angular_velocity(ca.DM(x[6:9]), ca.DM(w_next)))
    np.testing.assert_allclose(x_next[6:9], x[6:9] + ts * rates, atol=1e-12)


def test_semi_implicit_euler_free_fall_over_many_steps() -> None:
    """v_n = -g n Ts exactly and p_n = -g Ts^2 n (n + 1) / 2 (positions use the updated velocity);
    explicit Euler would give n (n - 1) / 2 instead."""
    ts, steps = 0.01, 50
    x = ca.DM.zeros(12)
    gravity = BodyAcceleration(ca.DM([0, 0, -GRAVITY_M_S2]), ca.DM.zeros(3))
    for _ in range(steps):
        x = semi_implicit_euler_step(x, gravity, ts)
    t = ts * steps
    xv = as_array(x)
    assert xv[5] == pytest.approx(-GRAVITY_M_S2 * t, abs=1e-12)
    # sum_{k=1..n} Ts (-g k Ts) = -g Ts^2 n (n + 1) / 2
    assert xv[2] == pytest.approx(-GRAVITY_M_S2 * ts * ts * steps * (steps + 1) / 2, abs=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_inertia_entries_round_trip(seed: int) -> None:
    rng = np.random.default_rng(500 + seed)
    inertia = random_inertia(rng)
    entries = inertia_entries(inertia)
    assert entries.shape == (6,)
    np.testing.assert_allclose(as_array(inertia_matrix(ca.DM(entries))), inertia, atol=0)
    np.testing.assert_allclose(inertia_entries(as_array(inertia_matrix(ca.DM(entries)))), entries,
                               atol=0)
    # The symbolic matrix is symmetric by construction.
    sym = inertia_matrix(ca.SX.sym("e", 6))
    assert ca.is_equal(sym, sym.T, 1)


def test_srb_parameters_reject_bad_mass_and_inertia() -> None:
    good = payload_parameters(5.0, (0.1, 0.4, 0.5))
    assert good.mass_kg == 5.0
    with pytest.raises(ValueError, match="mass"):
        SrbParameters("p", -1.0, np.eye(3), np.zeros((4, 3)), 0.0)
    with pytest.raises(ValueError, match="mass"):
        SrbParameters("p", float("nan"), np.eye(3), np.zeros((4, 3)), 0.0)
    with pytest.raises(ValueError, match="positive definite"):
        SrbParameters("p", 1.0, np.diag([1.0, -1.0, 1.0]), np.zeros((4, 3)), 0.0)
    with pytest.raises(ValueError, match="positive definite"):
        SrbParameters("p", 1.0, np.eye(2), np.zeros((4, 3)), 0.0)
