"""Yaw-free rigid coupling between a robot and the payload, and its acceleration-level form.

phi in R^5: three translational components (robot coupling point minus payload coupling point,
world frame [m]) and two rotational ones, (z_robot . x_payload, z_robot . y_payload), which vanish
when the robot's z-axis is parallel to the payload's z-axis (relative yaw stays free).

Everything is written with world-frame kinematics: for a point d = R r fixed in a body,
d_dot = omega x d and d_ddot = alpha x d + omega x (omega x d). This gives the same function as
J q_ddot + J_dot q_dot with far fewer operations than differentiating phi symbolically.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from core.model.srb_model import BodyAcceleration, Expr, rotation_body_to_world, split_state

COUPLING_SIZE = 5


@dataclass
class CouplingKinematics:
    """phi [m, -], phi_dot [m/s, 1/s] and phi_ddot [m/s^2, 1/s^2] of one robot-payload edge."""

    phi: Expr
    phi_dot: Expr
    phi_ddot: Expr | None


def _body_vector(x: Expr, vector_in_body: Expr, acceleration: BodyAcceleration | None):
    """World-frame vector fixed in a body, its first and (if given acceleration) second derivative."""
    _, _, euler, omega = split_state(x)
    d = rotation_body_to_world(euler) @ vector_in_body
    d_dot = ca.cross(omega, d)
    if acceleration is None:
        return d, d_dot, None
    d_ddot = ca.cross(acceleration.angular, d) + ca.cross(omega, ca.cross(omega, d))
    return d, d_dot, d_ddot


def coupling_point_in_world(x: Expr, point_in_body: Expr) -> Expr:
    """World position [m] of a point fixed in the body with SRB state x."""
    return x[0:3] + rotation_body_to_world(x[6:9]) @ point_in_body


def coupling_kinematics(
    x_robot: Expr,
    acceleration_robot: BodyAcceleration | None,
    point_in_robot: Expr,
    x_payload: Expr,
    acceleration_payload: BodyAcceleration | None,
    point_in_payload: Expr,
) -> CouplingKinematics:
    """phi and its derivatives; phi_ddot is None unless both accelerations are given."""
    e_x, e_y, e_z = ca.DM([1, 0, 0]), ca.DM([0, 1, 0]), ca.DM([0, 0, 1])
    d_r, d_r_dot, d_r_ddot = _body_vector(x_robot, point_in_robot, acceleration_robot)
    d_l, d_l_dot, d_l_ddot = _body_vector(x_payload, point_in_payload, acceleration_payload)
    z_r, z_r_dot, z_r_ddot = _body_vector(x_robot, e_z, acceleration_robot)
    x_l, x_l_dot, x_l_ddot = _body_vector(x_payload, e_x, acceleration_payload)
    y_l, y_l_dot, y_l_ddot = _body_vector(x_payload, e_y, acceleration_payload)

    translation = x_robot[0:3] + d_r - x_payload[0:3] - d_l
    translation_dot = x_robot[3:6] + d_r_dot - x_payload[3:6] - d_l_dot
    phi = ca.vertcat(translation, ca.dot(z_r, x_l), ca.dot(z_r, y_l))
    phi_dot = ca.vertcat(
        translation_dot,
        ca.dot(z_r_dot, x_l) + ca.dot(z_r, x_l_dot),
        ca.dot(z_r_dot, y_l) + ca.dot(z_r, y_l_dot),
    )
    if acceleration_robot is None or acceleration_payload is None:
        return CouplingKinematics(phi, phi_dot, None)
    translation_ddot = acceleration_robot.linear + d_r_ddot - acceleration_payload.linear - d_l_ddot
    phi_ddot = ca.vertcat(
        translation_ddot,
        ca.dot(z_r_ddot, x_l) + 2 * ca.dot(z_r_dot, x_l_dot) + ca.dot(z_r, x_l_ddot),
        ca.dot(z_r_ddot, y_l) + 2 * ca.dot(z_r_dot, y_l_dot) + ca.dot(z_r, y_l_ddot),
    )
    return CouplingKinematics(phi, phi_dot, phi_ddot)


def acceleration_level_constraint(
    kinematics: CouplingKinematics,
    baumgarte: bool,
    damping_ratio: float,
    natural_frequency_rad_s: float,
) -> Expr:
    """phi_ddot = 0, or with Baumgarte stabilization phi_ddot + 2 zeta w phi_dot + w^2 phi = 0."""
    assert kinematics.phi_ddot is not None
    if not baumgarte:
        return kinematics.phi_ddot
    w = natural_frequency_rad_s
    return kinematics.phi_ddot + 2 * damping_ratio * w * kinematics.phi_dot + w * w * kinematics.phi


def yaw_torque(x_payload: Expr, wrench_on_payload: Expr) -> Expr:
    """Torque [N m] of the wrench about the coupling's free yaw axis (payload z-axis, world)."""
    axis = rotation_body_to_world(x_payload[6:9]) @ ca.DM([0, 0, 1])
    return ca.dot(wrench_on_payload[3:6], axis)
