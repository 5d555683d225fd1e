"""Single-rigid-body (SRB) dynamics of a robot trunk or the payload, in CasADi.

State x in R^12, all in the world frame: x = (p, v, Theta, omega) with p the CoM position [m],
v its velocity [m/s], Theta = (roll, pitch, yaw) XYZ Euler angles [rad] and omega the angular
velocity [rad/s]. The rotation body -> world is R(Theta) = Rz(yaw) Ry(pitch) Rx(roll).

Discrete time uses the semi-implicit (symplectic) Euler integrator with step Ts:

    v+ = v + Ts a(x, forces),     p+ = p + Ts v+,
    w+ = w + Ts alpha(x, forces), Theta+ = Theta + Ts E(Theta)^-1 w+,

where E maps Euler rates to world angular velocity. Semi-implicit Euler keeps energy bounded
and makes p_k = p_{k+1} - Ts v_{k+1} exact, which the HOCBF builder uses to write each
barrier condition in terms of a single stage.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, TypeAlias

import casadi as ca
import numpy as np

from core.model.conventions import FOOT_COUNT
from core.model.rotations import euler_rotation_rows

# A CasADi SX/DM expression or a float: the model functions accept constants (the plant's fixed
# masses) as well as symbols. Typed as Any because CasADi's stubs reject mixed SX/DM/float
# arithmetic that CasADi itself accepts.
Expr: TypeAlias = Any

STATE_SIZE = 12
GRF_SIZE = 12
WRENCH_SIZE = 6


@dataclass(frozen=True)
class SrbParameters:
    """Rigid-body parameters of one body.

    ``inertia_in_body_kg_m2`` is about the CoM in body axes; ``hip_positions_in_body_m`` are the
    four hip joint positions (FL, FR, RL, RR) relative to the CoM in body axes (zeros for the
    payload); ``nominal_feet_in_body_m`` the standing foot contact points relative to the CoM
    (the neutral footholds of Raibert's rule); ``nominal_height_m`` is the standing CoM height
    above the ground.
    """

    name: str
    mass_kg: float
    inertia_in_body_kg_m2: np.ndarray
    hip_positions_in_body_m: np.ndarray
    nominal_height_m: float
    nominal_feet_in_body_m: np.ndarray | None = None

    def __post_init__(self) -> None:
        if not np.isfinite(self.mass_kg) or self.mass_kg <= 0:
            raise ValueError(f"{self.name}: mass must be positive, got {self.mass_kg}")
        inertia = np.asarray(self.inertia_in_body_kg_m2, dtype=float)
        if inertia.shape != (3, 3) or np.any(np.linalg.eigvalsh(inertia) <= 0):
            raise ValueError(f"{self.name}: inertia must be a 3x3 positive definite matrix")


def split_state(x: Expr) -> tuple[ca.SX, ca.SX, ca.SX, ca.SX]:
    """(p, v, Theta, omega) slices of a 12-vector."""
    return x[0:3], x[3:6], x[6:9], x[9:12]


def rotation_body_to_world(euler: Expr) -> Expr:
    """R = Rz(yaw) Ry(pitch) Rx(roll) for Theta = (roll, pitch, yaw)."""
    rows = euler_rotation_rows(ca.cos(euler[0]), ca.sin(euler[0]), ca.cos(euler[1]),
                               ca.sin(euler[1]), ca.cos(euler[2]), ca.sin(euler[2]))
    return ca.vertcat(*(ca.horzcat(*row) for row in rows))


def euler_rates_from_angular_velocity(euler: Expr, omega_in_world: Expr) -> Expr:
    """Theta_dot = E(Theta)^-1 omega for the Rz Ry Rx convention (singular at pitch = +-90 deg)."""
    cp, sp = ca.cos(euler[1]), ca.sin(euler[1])
    cy, sy = ca.cos(euler[2]), ca.sin(euler[2])
    wx, wy, wz = omega_in_world[0], omega_in_world[1], omega_in_world[2]
    roll_rate = (cy * wx + sy * wy) / cp
    pitch_rate = -sy * wx + cy * wy
    yaw_rate = wz + sp * roll_rate
    return ca.vertcat(roll_rate, pitch_rate, yaw_rate)


@dataclass
class BodyAcceleration:
    """Linear [m/s^2] and angular [rad/s^2] acceleration of a body, world frame."""

    linear: Expr
    angular: Expr


def inertia_matrix(entries: Expr) -> Expr:
    """3x3 symmetric inertia from its 6 entries (Ixx, Ixy, Ixz, Iyy, Iyz, Izz)."""
    xx, xy, xz, yy, yz, zz = (entries[i] for i in range(6))
    return ca.vertcat(ca.horzcat(xx, xy, xz), ca.horzcat(xy, yy, yz), ca.horzcat(xz, yz, zz))


def inertia_entries(inertia: np.ndarray) -> np.ndarray:
    """The 6 entries (Ixx, Ixy, Ixz, Iyy, Iyz, Izz) of a symmetric 3x3 inertia."""
    i = np.asarray(inertia, dtype=float)
    return np.array([i[0, 0], i[0, 1], i[0, 2], i[1, 1], i[1, 2], i[2, 2]])


def rigid_body_acceleration(
    mass_kg: Expr,
    inertia_in_body: Expr,
    x: Expr,
    force_in_world: Expr,
    torque_about_com_in_world: Expr,
    gravity_m_s2: float,
) -> BodyAcceleration:
    """Newton-Euler for one rigid body given the total external force and torque (no gravity).

    Mass [kg] and body-frame inertia [kg m^2] may be symbolic, so one built problem serves every
    robot type and payload mass.
    """
    _, _, euler, omega = split_state(x)
    rotation = rotation_body_to_world(euler)
    inertia_world = rotation @ inertia_in_body @ rotation.T
    linear = force_in_world / mass_kg + ca.vertcat(0, 0, -gravity_m_s2)
    gyroscopic = ca.cross(omega, inertia_world @ omega)
    angular = ca.solve(inertia_world, torque_about_com_in_world - gyroscopic)
    return BodyAcceleration(linear, angular)


def robot_acceleration(
    mass_kg: Expr,
    inertia_in_body: Expr,
    x: Expr,
    grf: Expr,
    feet_in_world: Expr,
    coupling_point_in_world: Expr,
    wrench_on_payload: Expr,
    gravity_m_s2: float,
) -> BodyAcceleration:
    """Trunk acceleration under 4 GRFs (12-vector, world) at feet_in_world (3x4 matrix, world)
    and the reaction -wrench_on_payload applied at the robot's coupling point."""
    p = x[0:3]
    force = -wrench_on_payload[0:3]
    torque = ca.cross(coupling_point_in_world - p, -wrench_on_payload[0:3]) - wrench_on_payload[3:6]
    for leg in range(FOOT_COUNT):
        f_leg = grf[3 * leg : 3 * leg + 3]
        force = force + f_leg
        torque = torque + ca.cross(feet_in_world[:, leg] - p, f_leg)
    return rigid_body_acceleration(mass_kg, inertia_in_body, x, force, torque, gravity_m_s2)


def payload_acceleration(
    mass_kg: Expr,
    inertia_in_body: Expr,
    x: Expr,
    coupling_points_in_world: list[ca.SX],
    wrenches_on_payload: list[ca.SX],
    gravity_m_s2: float,
) -> BodyAcceleration:
    """Payload acceleration under every robot's wrench (force, torque; world) at its coupling point."""
    p = x[0:3]
    force = ca.SX.zeros(3)
    torque = ca.SX.zeros(3)
    for point, wrench in zip(coupling_points_in_world, wrenches_on_payload, strict=True):
        force = force + wrench[0:3]
        torque = torque + ca.cross(point - p, wrench[0:3]) + wrench[3:6]
    return rigid_body_acceleration(mass_kg, inertia_in_body, x, force, torque, gravity_m_s2)


def semi_implicit_euler_step(x: Expr, acceleration: BodyAcceleration, dt_s: float) -> Expr:
    """One semi-implicit Euler step of the SRB state (see module docstring)."""
    p, v, euler, omega = split_state(x)
    v_next = v + dt_s * acceleration.linear
    omega_next = omega + dt_s * acceleration.angular
    p_next = p + dt_s * v_next
    euler_next = euler + dt_s * euler_rates_from_angular_velocity(euler, omega_next)
    return ca.vertcat(p_next, v_next, euler_next, omega_next)


def payload_parameters(
    mass_kg: float, principal_inertia_kg_m2: tuple[float, float, float]
) -> SrbParameters:
    """SRB parameters of the payload (no hips; nominal height is unused and set to 0)."""
    return SrbParameters(
        name="payload",
        mass_kg=mass_kg,
        inertia_in_body_kg_m2=np.diag(principal_inertia_kg_m2),
        hip_positions_in_body_m=np.zeros((4, 3)),
        nominal_height_m=0.0,
    )
