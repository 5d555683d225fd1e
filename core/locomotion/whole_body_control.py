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


@dataclass(frozen=True)
class _QpLayout:
    """The parts of the QP that depend only on the number of stance feet: the constant
    Hessian (regularization, base and force task weights), the constraint matrix with its
    friction rows filled, the constant bounds and the constraint senses. Copied per tick."""

    hessian: np.ndarray
    constraint: np.ndarray
    upper: np.ndarray
    lower: np.ndarray
    sense: np.ndarray


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
        self._layouts = [self._build_layout(stance_count) for stance_count in range(5)]
        self._zero_acceleration = np.zeros(model.nv)
        # (state, q, v, rotation) whose rigid-body terms the Pinocchio data holds (``observe``)
        self._observed: tuple[FloatingBaseState, np.ndarray, np.ndarray, np.ndarray] | None = None

    # --- state conversions ---------------------------------------------------------------
    def pinocchio_state(self, state: FloatingBaseState, rotation: np.ndarray | None = None
                        ) -> tuple[np.ndarray, np.ndarray]:
        """(q, v) in Pinocchio's convention (quaternion xyzw, base twist in the base frame);
        ``rotation``: the state's base rotation when already at hand."""
        w, x, y, z = state.quaternion_wxyz
        rotation = state.rotation() if rotation is None else rotation
        q = np.concatenate([state.position_base_in_world_m, (x, y, z, w),
                            state.joint_position_rad])
        v = np.concatenate([rotation.T @ state.linear_velocity_in_world_m_s,
                            state.angular_velocity_in_body_rad_s, state.joint_velocity_rad_s])
        return q, v

    def srb_state(self, state: FloatingBaseState, rotation: np.ndarray | None = None
                  ) -> np.ndarray:
        """The NMPC's SRB state (p, v, Theta, omega) of this robot: CoM at the standing offset
        from the base, omega in world."""
        rotation = state.rotation() if rotation is None else rotation
        offset = rotation @ self.com_offset_in_base_m
        omega = rotation @ state.angular_velocity_in_body_rad_s
        return np.concatenate([state.position_base_in_world_m + offset,
                               state.linear_velocity_in_world_m_s + cross3(omega, offset),
                               euler_from_rotation(rotation), omega])

    def foot_positions(self, state: FloatingBaseState) -> np.ndarray:
        """(4, 3) foot contact points [m] in world (foot frame minus the foot radius in z)."""
        self._observed = None  # the Pinocchio data no longer holds an observed state's terms
        q, _ = self.pinocchio_state(state)
        pin.framesForwardKinematics(self.model, self.data, q)
        return self._feet()

    def _feet(self) -> np.ndarray:
        feet = np.array([self.data.oMf[i].translation for i in self.foot_frame_ids])
        feet[:, 2] -= self.foot_radius_m
        return feet

    def observe(self, state: FloatingBaseState) -> tuple[np.ndarray, np.ndarray]:
        """``srb_state`` and ``foot_positions`` of ``state`` from one Pinocchio pass, whose
        rigid-body terms the next ``compute`` on this same state object reuses (one pass per
        robot and tick instead of three)."""
        rotation = state.rotation()
        q, v = self.pinocchio_state(state, rotation)
        pin.computeAllTerms(self.model, self.data, q, v)
        pin.updateFramePlacements(self.model, self.data)
        self._observed = (state, q, v, rotation)
        return self.srb_state(state, rotation), self._feet()

    # --- control -------------------------------------------------------------------------
    def compute(self, state: FloatingBaseState, target: WbcTarget) -> WbcOutput:
        """One WBC tick: joint torques tracking ``target`` from the measured ``state``."""
        start = time.perf_counter()
        s = self.settings
        model, data = self.model, self.data
        observed, self._observed = self._observed, None
        if observed is not None and observed[0] is state:
            _, q, v, rotation = observed
        else:
            rotation = state.rotation()
            q, v = self.pinocchio_state(state, rotation)
            pin.computeAllTerms(model, data, q, v)
            pin.updateFramePlacements(model, data)  # the swing feet's placements (oMf)
        mass = np.array(data.M)  # Pinocchio fills the upper triangle; mirror it
        mass[self._lower] = mass.T[self._lower]
        bias = np.array(data.nle)
        pin.forwardKinematics(model, data, q, v, self._zero_acceleration)  # data.a = Jdot v
        world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        jacobians = [pin.getFrameJacobian(model, data, i, world)[0:3] for i in self.foot_frame_ids]
        drifts = [pin.getFrameClassicalAcceleration(model, data, i, world).linear
                  for i in self.foot_frame_ids]
        stance = np.flatnonzero(np.asarray(target.stance, dtype=bool))
        swing = [leg for leg in range(4) if leg not in stance]
        nf = 3 * len(stance)
        n = nf + model.nv
        layout = self._layouts[len(stance)]

        # Cost 0.5 x'Hx + g'x as a sum of weighted least-squares terms; each task's rows are
        # a block of x (base: qdd_base; swing: J qdd; forces: f), so only that block is added.
        hessian = layout.hessian.copy()
        gradient = np.zeros(n)
        gradient[nf:nf + 6] -= s.base_weight * self._base_acceleration(state, target, rotation, v)
        for leg in swing:
            jacobian = jacobians[leg]
            velocity = jacobian @ v
            foot_now = data.oMf[self.foot_frame_ids[leg]].translation
            desired = (target.foot_acceleration_m_s2[leg]
                       + s.swing_position_gain * (target.foot_position_m[leg]
                                                  + (0, 0, self.foot_radius_m) - foot_now)
                       + s.swing_velocity_gain * (target.foot_velocity_m_s[leg] - velocity))
            weighted = s.swing_weight * jacobian.T
            hessian[nf:, nf:] += weighted @ jacobian
            gradient[nf:] -= weighted @ (desired - drifts[leg])
        if nf:
            gradient[0:nf] -= s.force_weight * np.asarray(target.planned_grf_n)[stance].reshape(-1)

        # Constraints (rows of ``layout``): simple bounds on f, then friction (constant),
        # dynamics, stance, torque rows.
        constraint, upper, lower = (layout.constraint.copy(), layout.upper.copy(),
                                    layout.lower.copy())
        contact_jacobian = (np.vstack([jacobians[leg] for leg in stance]) if nf
                            else np.zeros((0, model.nv)))
        row = 4 * len(stance)
        dynamics = constraint[row:row + 6]
        dynamics[:, 0:nf] = -contact_jacobian[:, 0:6].T
        dynamics[:, nf:] = mass[0:6]
        base_force = self._coupling_generalized_force(target.wrench_on_robot, rotation)
        bound = nf + row
        upper[bound:bound + 6] = lower[bound:bound + 6] = base_force - bias[0:6]
        row, bound = row + 6, bound + 6
        if nf:
            constraint[row:row + nf, nf:] = contact_jacobian
            stance_drift = np.concatenate([drifts[leg] for leg in stance])
            rhs = -stance_drift - s.stance_velocity_damping * (contact_jacobian @ v)
            upper[bound:bound + nf] = lower[bound:bound + nf] = rhs
            row, bound = row + nf, bound + nf
        torque_rows = constraint[row:]
        torque_rows[:, 0:nf] = -contact_jacobian[:, 6:].T
        torque_rows[:, nf:] = mass[6:]
        upper[bound:] = self.torque_limit_nm - bias[6:]
        lower[bound:] = -self.torque_limit_nm - bias[6:]
        sense = layout.sense
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

    def _build_layout(self, stance_count: int) -> _QpLayout:
        s = self.settings
        nv = self.model.nv
        nf = 3 * stance_count
        n = nf + nv
        hessian = s.regularization * np.eye(n)
        hessian[range(nf, nf + 6), range(nf, nf + 6)] += s.base_weight
        hessian[range(nf), range(nf)] += s.force_weight
        friction_rows = 4 * stance_count
        constraint = np.zeros((friction_rows + 6 + nf + JOINT_COUNT, n))
        mu = s.friction_coefficient
        pyramid = np.array([[1.0, 0.0, -mu], [-1.0, 0.0, -mu], [0.0, 1.0, -mu],
                            [0.0, -1.0, -mu]])
        for k in range(stance_count):
            constraint[4 * k:4 * k + 4, 3 * k:3 * k + 3] = pyramid
        bounds = nf + len(constraint)
        upper, lower = np.zeros(bounds), np.zeros(bounds)
        upper[0:nf] = np.tile([_INF, _INF, s.max_normal_force_n], stance_count)
        lower[0:nf] = np.tile([-_INF, -_INF, s.min_normal_force_n], stance_count)
        lower[nf:nf + friction_rows] = -_INF
        sense = np.zeros(bounds, dtype=np.int32)
        equalities = nf + friction_rows
        sense[equalities:equalities + 6 + nf] = _EQUALITY  # dynamics, stance feet
        return _QpLayout(hessian, constraint, upper, lower, sense)

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
