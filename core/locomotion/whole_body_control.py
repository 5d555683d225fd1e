"""Whole-body controller (WBC) of one quadruped: a QP turning the NMPC plan into joint torques.

Decentralized: each robot uses only its own measured state and its part of the plan (trunk
motion, ground reaction forces, interaction wrench). Pinocchio gives the rigid-body dynamics
M(q) qdd + h(q, v) = S^T tau + J_c^T f + J_w^T w, with v the free-flyer velocity (base linear
velocity and angular velocity in the base frame, then the 12 joint rates in FL, FR, RL, RR x
(hip, thigh, calf) order) and w the interaction wrench the payload exerts on the robot.

QP over x = (f, qdd), f the world-frame forces of the stance feet [N], solved with DAQP:

    min  w_b ||qdd_base - a_base*||^2 + w_s sum_swing ||J_i qdd + Jdot_i v - a_i*||^2
         + w_f ||f - f_plan||^2 + eps ||x||^2
    s.t. M_base qdd + h_base = J_c,base^T f + J_w,base^T w_plan     (floating-base dynamics)
         J_c qdd + Jdot_c v = -k_d J_c v                           (stance feet stay still)
         |f_x|, |f_y| <= mu f_z,  f_min <= f_z <= f_max             (friction pyramid)
         |M_j qdd + h_j - J_c,j^T f| <= tau_max                      (torque limits)

and tau = M_j qdd + h_j - J_c,j^T f. Targets a* are PD laws on the planned trunk and the swing
trajectories plus their feed-forward accelerations. The NMPC's SRB "position" is the CoM of the
standing robot; the WBC places it at a fixed offset from the base (``com_offset_in_base_m``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import daqp
import numpy as np
import pinocchio as pin

from core.locomotion.settings import WbcSettings
from core.model.conventions import JOINT_COUNT, LEG_NAMES
from core.model.rotations import (
    cross3,
    euler_from_rotation,
    rotation_from_euler,
    rotation_from_quaternion_wxyz,
)

_INF = 1e30
_EQUALITY = 5  # DAQP constraint sense: equality


@dataclass(frozen=True)
class FloatingBaseState:
    """A robot's measured state: base pose and twist, joints. World frame, SI units.

    ``quaternion_wxyz`` rotates base vectors into the world; ``angular_velocity_in_body_rad_s``
    is in the base frame (as a gyroscope measures it); joints in FL, FR, RL, RR x (hip, thigh,
    calf) order.
    """

    position_base_in_world_m: np.ndarray
    quaternion_wxyz: np.ndarray
    linear_velocity_in_world_m_s: np.ndarray
    angular_velocity_in_body_rad_s: np.ndarray
    joint_position_rad: np.ndarray
    joint_velocity_rad_s: np.ndarray

    def rotation(self) -> np.ndarray:
        return rotation_from_quaternion_wxyz(self.quaternion_wxyz)


@dataclass(frozen=True)
class WbcTarget:
    """What the WBC tracks this tick, world frame.

    Trunk: CoM position/velocity/acceleration and XYZ Euler angles, angular velocity and
    acceleration (world) from the NMPC plan. Feet (4, 3), legs FL, FR, RL, RR: ``stance``
    flags, planned GRFs [N] of stance feet, and swing-foot contact-point position, velocity and
    acceleration. ``wrench_on_robot``: force [N] and torque [N m] (about the coupling point)
    the payload exerts on the robot (minus the plan's wrench on the payload).
    """

    com_position_m: np.ndarray
    com_velocity_m_s: np.ndarray
    com_acceleration_m_s2: np.ndarray
    euler_rad: np.ndarray
    angular_velocity_rad_s: np.ndarray
    angular_acceleration_rad_s2: np.ndarray
    stance: np.ndarray
    planned_grf_n: np.ndarray
    foot_position_m: np.ndarray
    foot_velocity_m_s: np.ndarray
    foot_acceleration_m_s2: np.ndarray
    wrench_on_robot: np.ndarray


@dataclass(frozen=True)
class WbcOutput:
    """Joint torques [N m] and the QP's joint accelerations [rad/s^2] and stance forces [N]
    (4, 3) (zero rows for swing feet). ``success`` False: the QP failed (``status`` is DAQP's
    exit flag) and the outputs are the last successful tick's."""

    torque_nm: np.ndarray
    joint_acceleration_rad_s2: np.ndarray
    contact_force_n: np.ndarray
    success: bool
    status: int
    solve_time_s: float


class WholeBodyController:
    """WBC of one robot, built once per robot from its Pinocchio model.

    ``standing_configuration``: Pinocchio q of the standing pose (defines the CoM offset in the
    base); ``coupling_point_in_robot_m``: coupling point relative to that CoM, body axes;
    ``foot_radius_m``: foot sphere radius (contact point = foot frame - radius along z).
    """

    def __init__(self, model: pin.Model, standing_configuration: np.ndarray,
                 coupling_point_in_robot_m: np.ndarray, foot_radius_m: float,
                 settings: WbcSettings | None = None) -> None:
        self.model = model
        self.data = model.createData()
        self.settings = settings or WbcSettings()
        q = np.array(standing_configuration, dtype=float)
        q[0:7] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
        self.com_offset_in_base_m = np.array(pin.centerOfMass(model, self.data, q))
        self.coupling_in_base_m = self.com_offset_in_base_m + np.asarray(coupling_point_in_robot_m)
        self.foot_radius_m = foot_radius_m
        self.foot_frame_ids = [model.getFrameId(f"{leg}_foot") for leg in LEG_NAMES]
        self.torque_limit_nm = np.array(model.effortLimit[6:], dtype=float)
        s = self.settings
        self._kp_base = np.array(s.base_position_gain)
        self._kd_base = np.array(s.base_velocity_gain)
        self._kp_rot = np.array(s.base_orientation_gain)
        self._kd_rot = np.array(s.base_angular_velocity_gain)
        self._last: WbcOutput | None = None
        self._lower = np.tril_indices(model.nv, -1)

    # --- state conversions ---------------------------------------------------------------
    def pinocchio_state(self, state: FloatingBaseState) -> tuple[np.ndarray, np.ndarray]:
        """(q, v) in Pinocchio's convention (quaternion xyzw, base twist in the base frame)."""
        w, x, y, z = state.quaternion_wxyz
        rotation = state.rotation()
        q = np.concatenate([state.position_base_in_world_m, (x, y, z, w),
                            state.joint_position_rad])
        v = np.concatenate([rotation.T @ state.linear_velocity_in_world_m_s,
                            state.angular_velocity_in_body_rad_s, state.joint_velocity_rad_s])
        return q, v

    def srb_state(self, state: FloatingBaseState) -> np.ndarray:
        """The NMPC's SRB state (p, v, Theta, omega) of this robot: CoM at the standing offset
        from the base, omega in world."""
        rotation = state.rotation()
        offset = rotation @ self.com_offset_in_base_m
        omega = rotation @ state.angular_velocity_in_body_rad_s
        return np.concatenate([state.position_base_in_world_m + offset,
                               state.linear_velocity_in_world_m_s + cross3(omega, offset),
                               euler_from_rotation(rotation), omega])

    def foot_positions(self, state: FloatingBaseState) -> np.ndarray:
        """(4, 3) foot contact points [m] in world (foot frame minus the foot radius in z)."""
        q, _ = self.pinocchio_state(state)
        pin.framesForwardKinematics(self.model, self.data, q)
        feet = np.array([self.data.oMf[i].translation for i in self.foot_frame_ids])
        feet[:, 2] -= self.foot_radius_m
        return feet

    # --- control -------------------------------------------------------------------------
    def compute(self, state: FloatingBaseState, target: WbcTarget) -> WbcOutput:
        """One WBC tick: joint torques tracking ``target`` from the measured ``state``."""
        start = time.perf_counter()
        s = self.settings
        model, data = self.model, self.data
        q, v = self.pinocchio_state(state)
        pin.computeAllTerms(model, data, q, v)
        mass = np.array(data.M)  # Pinocchio fills the upper triangle; mirror it
        mass[self._lower] = mass.T[self._lower]
        bias = np.array(data.nle)
        pin.forwardKinematics(model, data, q, v, np.zeros(model.nv))  # data.a = Jdot v
        rotation = state.rotation()
        world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        jacobians = [pin.getFrameJacobian(model, data, i, world)[0:3] for i in self.foot_frame_ids]
        drifts = [pin.getFrameClassicalAcceleration(model, data, i, world).linear
                  for i in self.foot_frame_ids]
        stance = np.flatnonzero(np.asarray(target.stance, dtype=bool))
        swing = [leg for leg in range(4) if leg not in stance]
        nf = 3 * len(stance)
        n = nf + model.nv

        # Cost 0.5 x'Hx + g'x as a sum of weighted least-squares terms.
        hessian = s.regularization * np.eye(n)
        gradient = np.zeros(n)

        def add_task(rows: np.ndarray, value: np.ndarray, weight: float) -> None:
            nonlocal gradient
            hessian[:] += weight * rows.T @ rows
            gradient = gradient - weight * rows.T @ value

        base_rows = np.zeros((6, n))
        base_rows[:, nf:nf + 6] = np.eye(6)
        add_task(base_rows, self._base_acceleration(state, target, rotation, v), s.base_weight)
        feet_now = np.array([data.oMi[model.frames[i].parentJoint].act(
            model.frames[i].placement).translation for i in self.foot_frame_ids])
        for leg in swing:
            rows = np.zeros((3, n))
            rows[:, nf:] = jacobians[leg]
            velocity = jacobians[leg] @ v
            desired = (target.foot_acceleration_m_s2[leg]
                       + s.swing_position_gain * (target.foot_position_m[leg]
                                                  + (0, 0, self.foot_radius_m) - feet_now[leg])
                       + s.swing_velocity_gain * (target.foot_velocity_m_s[leg] - velocity))
            add_task(rows, desired - drifts[leg], s.swing_weight)
        if nf:
            force_rows = np.zeros((nf, n))
            force_rows[:, 0:nf] = np.eye(nf)
            add_task(force_rows, np.asarray(target.planned_grf_n)[stance].reshape(-1),
                     s.force_weight)

        # Constraints: simple bounds on f, then friction, dynamics, stance, torque rows.
        contact_jacobian = (np.vstack([jacobians[leg] for leg in stance]) if nf
                            else np.zeros((0, model.nv)))
        rows_list, upper_list, lower_list, sense_list = [], [], [], []

        def add_rows(rows: np.ndarray, lower: np.ndarray, upper: np.ndarray,
                     equality: bool = False) -> None:
            rows_list.append(rows)
            lower_list.append(lower)
            upper_list.append(upper)
            sense_list.append(np.full(len(rows), _EQUALITY if equality else 0, dtype=np.int32))

        mu = s.friction_coefficient
        pyramid = np.array([[1.0, 0.0, -mu], [-1.0, 0.0, -mu], [0.0, 1.0, -mu], [0.0, -1.0, -mu]])
        for k in range(len(stance)):
            rows = np.zeros((4, n))
            rows[:, 3 * k:3 * k + 3] = pyramid
            add_rows(rows, np.full(4, -_INF), np.zeros(4))
        dynamics = np.zeros((6, n))
        dynamics[:, 0:nf] = -contact_jacobian[:, 0:6].T
        dynamics[:, nf:] = mass[0:6]
        base_force = self._coupling_generalized_force(target.wrench_on_robot, rotation)
        add_rows(dynamics, base_force - bias[0:6], base_force - bias[0:6], equality=True)
        if nf:
            stance_rows = np.zeros((nf, n))
            stance_rows[:, nf:] = contact_jacobian
            stance_drift = np.concatenate([drifts[leg] for leg in stance])
            rhs = -stance_drift - s.stance_velocity_damping * (contact_jacobian @ v)
            add_rows(stance_rows, rhs, rhs, equality=True)
        torque_rows = np.zeros((JOINT_COUNT, n))
        torque_rows[:, 0:nf] = -contact_jacobian[:, 6:].T
        torque_rows[:, nf:] = mass[6:]
        add_rows(torque_rows, -self.torque_limit_nm - bias[6:], self.torque_limit_nm - bias[6:])

        bound_lower = np.tile([-_INF, -_INF, s.min_normal_force_n], len(stance))
        bound_upper = np.tile([_INF, _INF, s.max_normal_force_n], len(stance))
        constraint = np.vstack(rows_list)
        upper = np.concatenate([bound_upper, *upper_list])
        lower = np.concatenate([bound_lower, *lower_list])
        sense = np.concatenate([np.zeros(nf, dtype=np.int32), *sense_list])
        x, _, status, _ = daqp.solve(hessian, gradient, constraint, upper, lower, sense)
        elapsed = time.perf_counter() - start
        if status < 1 or not np.all(np.isfinite(x)):
            return self._failed(int(status), elapsed)
        forces = x[0:nf]
        acceleration = x[nf:]
        torque = mass[6:] @ acceleration + bias[6:] - contact_jacobian[:, 6:].T @ forces
        contact_force = np.zeros((4, 3))
        contact_force[stance] = forces.reshape(-1, 3)
        output = WbcOutput(np.clip(torque, -self.torque_limit_nm, self.torque_limit_nm),
                           acceleration[6:], contact_force, True, int(status),
                           time.perf_counter() - start)
        self._last = output
        return output

    def _failed(self, status: int, elapsed_s: float) -> WbcOutput:
        last = self._last
        torque = last.torque_nm if last is not None else np.zeros(JOINT_COUNT)
        return WbcOutput(torque, np.zeros(JOINT_COUNT), np.zeros((4, 3)), False, status,
                         elapsed_s)

    def _base_acceleration(self, state: FloatingBaseState, target: WbcTarget,
                           rotation: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Desired free-flyer acceleration (base frame; Pinocchio's spatial convention) from PD
        on the planned trunk plus the plan's accelerations."""
        rotation_desired = rotation_from_euler(np.asarray(target.euler_rad))
        offset_desired = rotation_desired @ self.com_offset_in_base_m
        position_desired = np.asarray(target.com_position_m) - offset_desired
        velocity_desired = (np.asarray(target.com_velocity_m_s)
                            - cross3(target.angular_velocity_rad_s, offset_desired))
        omega = rotation @ state.angular_velocity_in_body_rad_s
        linear = (np.asarray(target.com_acceleration_m_s2)
                  + self._kp_base * (position_desired - state.position_base_in_world_m)
                  + self._kd_base * (velocity_desired - state.linear_velocity_in_world_m_s))
        angular = (np.asarray(target.angular_acceleration_rad_s2)
                   + self._kp_rot * pin.log3(rotation_desired @ rotation.T)
                   + self._kd_rot * (np.asarray(target.angular_velocity_rad_s) - omega))
        # Classical -> spatial linear acceleration in the base frame: a_s = a_c - w x v.
        linear_local = rotation.T @ linear - cross3(v[3:6], v[0:3])
        return np.concatenate([linear_local, rotation.T @ angular])

    def _coupling_generalized_force(self, wrench_on_robot: np.ndarray, rotation: np.ndarray
                                    ) -> np.ndarray:
        """Free-flyer generalized force of a world wrench (force, torque about the coupling
        point) applied at the coupling point on the base."""
        force = np.asarray(wrench_on_robot[0:3], dtype=float)
        torque = np.asarray(wrench_on_robot[3:6], dtype=float)
        lever = rotation @ self.coupling_in_base_m
        return np.concatenate([rotation.T @ force, rotation.T @ (torque + cross3(lever, force))])
