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
The QP has a fixed size (all four feet's forces, a swing foot's pinned to zero) and is
assembled by one CasADi function (``core.locomotion.wbc_qp``), compiled C when the controller
is given a code cache.

**The state conversion** (``StateConversion``): a robot's measured state in the forms the WBC
needs (Pinocchio's (q, v), the base rotation and the NMPC's SRB state) as one CasADi function
per robot, so that the 500 Hz tick makes one call instead of ~25 small NumPy operations per
robot (~65 us at real-time pace, measured in ``observe``); tested against NumPy references. It
is the one place a robot's Pinocchio ``q`` is built, once per robot and tick (``observe``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

import casadi as ca
import daqp
import numpy as np
import pinocchio as pin

from core.locomotion.buffered_function import BufferedFunction, ParameterVector
from core.locomotion.settings import WbcSettings
from core.locomotion.wbc_qp import FORCES, TORQUE_ROWS, WbcQpAssembly
from core.model.conventions import JOINT_COUNT, LEG_NAMES
from core.model.rotations import (
    euler_angles,
    quaternion_rotation_rows,
    rotation_from_quaternion_wxyz,
)

if TYPE_CHECKING:  # a protocol only; the NMPC package need not load
    from core.nmpc.nlp_solver import NlpCompiler



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


_NQ, _NV = 7 + JOINT_COUNT, 6 + JOINT_COUNT


class StateConversion:
    """``__call__(state)`` -> (q, v, rotation, srb_state) of one robot whose standing CoM sits
    at ``com_offset_in_base_m`` from its base.

    q (19,): base position [m], quaternion (x, y, z, w) as measured (Pinocchio normalizes),
    joints [rad]; v (18,): base linear velocity in the base frame [m/s], angular velocity in
    the base frame [rad/s], joint rates [rad/s]; rotation (3, 3): base to world, from the
    normalized quaternion; srb_state (12,): CoM position, CoM velocity [m/s], XYZ Euler angles
    [rad], angular velocity in world [rad/s].

    q, v and rotation are this converter's own arrays, overwritten by the next call (the WBC
    uses them within one tick); srb_state is a fresh array the caller may keep."""

    def __init__(self, com_offset_in_base_m: np.ndarray,
                 compiler: NlpCompiler | None = None) -> None:
        parameters = ParameterVector([
            ("position", 3, 1), ("quaternion_wxyz", 4, 1), ("linear_velocity", 3, 1),
            ("angular_velocity_in_body", 3, 1), ("joint_position", JOINT_COUNT, 1),
            ("joint_velocity", JOINT_COUNT, 1)])
        self._views = parameters.views
        outputs = _conversion_expressions(parameters.symbols, np.asarray(com_offset_in_base_m,
                                                                         dtype=float))
        self.q, self.v = np.zeros(_NQ), np.zeros(_NV)
        self.rotation = np.zeros((3, 3))  # row-major: the function writes R^T column-major
        self._srb = np.zeros(12)
        self._function = BufferedFunction("state_conversion", parameters, outputs,
                                          [self.q, self.v, self.rotation, self._srb], compiler)

    @property
    def compiled(self) -> bool:
        """Whether the conversion runs as compiled C (else in CasADi's SX virtual machine)."""
        return self._function.compiled

    def __call__(self, state: FloatingBaseState
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        views = self._views
        views["position"][:] = state.position_base_in_world_m
        views["quaternion_wxyz"][:] = state.quaternion_wxyz
        views["linear_velocity"][:] = state.linear_velocity_in_world_m_s
        views["angular_velocity_in_body"][:] = state.angular_velocity_in_body_rad_s
        views["joint_position"][:] = state.joint_position_rad
        views["joint_velocity"][:] = state.joint_velocity_rad_s
        self._function.evaluate()
        return self.q, self.v, self.rotation, self._srb.copy()


def _conversion_expressions(p: dict[str, ca.SX], com_offset_in_base_m: np.ndarray
                            ) -> list[ca.SX]:
    quaternion = p["quaternion_wxyz"]
    # core.model.rotations' formula, normalized first as rotation_from_quaternion_wxyz
    w, x, y, z = ca.vertsplit(quaternion / ca.norm_2(quaternion))
    rotation = ca.vertcat(*(ca.horzcat(*row) for row in quaternion_rotation_rows(w, x, y, z)))
    raw = quaternion  # Pinocchio's q carries the measured quaternion, xyzw
    q = ca.vertcat(p["position"], raw[1], raw[2], raw[3], raw[0], p["joint_position"])
    v = ca.vertcat(rotation.T @ p["linear_velocity"], p["angular_velocity_in_body"],
                   p["joint_velocity"])
    offset = rotation @ ca.DM(com_offset_in_base_m)
    omega = rotation @ p["angular_velocity_in_body"]
    # core.model.rotations' formula: R = Rz(yaw) Ry(pitch) Rx(roll), pitch in [-pi/2, pi/2]
    euler = ca.vertcat(*euler_angles(lambda i, j: rotation[i, j], ca.atan2, ca.asin,
                                     lambda value: ca.fmin(ca.fmax(value, -1.0), 1.0)))
    srb = ca.vertcat(p["position"] + offset, p["linear_velocity"] + ca.cross(omega, offset),
                     euler, omega)
    return [q, v, rotation.T, srb]


def structural_patterns(model: pin.Model, foot_frame_ids: list[int]
                        ) -> tuple[np.ndarray, np.ndarray]:
    """Where the feet's linear Jacobian rows (3 per foot, nv columns) and the mass matrix
    (nv, nv) can be non-zero, from the kinematic tree: a foot moves with the joints that support
    it; M couples two velocities when one joint supports the other."""
    def columns(joint: int) -> list[int]:
        return list(range(model.joints[joint].idx_v,
                          model.joints[joint].idx_v + model.joints[joint].nv))

    jacobian = np.zeros((3 * len(foot_frame_ids), model.nv), dtype=bool)
    for foot, frame_id in enumerate(foot_frame_ids):
        for joint in model.supports[model.frames[frame_id].parentJoint]:
            if joint > 0:  # 0: the universe
                jacobian[3 * foot:3 * foot + 3, columns(joint)] = True
    mass = np.zeros((model.nv, model.nv), dtype=bool)
    for joint in range(1, model.njoints):
        for ancestor in model.supports[joint]:
            if ancestor > 0:
                mass[np.ix_(columns(joint), columns(ancestor))] = True
                mass[np.ix_(columns(ancestor), columns(joint))] = True
    return jacobian, mass


class WholeBodyController:
    """WBC of one robot, built once per robot from its Pinocchio model.

    ``standing_configuration``: Pinocchio q of the standing pose (defines the CoM offset in the
    base); ``coupling_point_in_robot_m``: coupling point relative to that CoM, body axes;
    ``foot_radius_m``: foot sphere radius (contact point = foot frame - radius along z).
    """

    def __init__(self, model: pin.Model, standing_configuration: np.ndarray,
                 coupling_point_in_robot_m: np.ndarray, foot_radius_m: float,
                 settings: WbcSettings | None = None, compiler: NlpCompiler | None = None
                 ) -> None:
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
        self._last: WbcOutput | None = None
        # the QP's arrays, assembled by one CasADi function (``wbc_qp``)
        self._qp = WbcQpAssembly(self.settings, self.com_offset_in_base_m,
                                 self.coupling_in_base_m, foot_radius_m, self.torque_limit_nm,
                                 compiler, *structural_patterns(model, self.foot_frame_ids))
        self._zero_acceleration = np.zeros(model.nv)
        self._foot_frames = np.zeros((len(self.foot_frame_ids), 3))  # of the last ``_feet``
        self._conversion = StateConversion(self.com_offset_in_base_m, compiler)
        # a second converter off the tick's path (``srb_state``, ``pinocchio_state``): its
        # calls never overwrite the arrays ``observe`` hands to this tick's ``compute``
        self._spare_conversion = StateConversion(self.com_offset_in_base_m, compiler)
        # (state, q, v, rotation) whose rigid-body terms the Pinocchio data holds (``observe``)
        self._observed: tuple[FloatingBaseState, np.ndarray, np.ndarray, np.ndarray] | None = None

    # --- state conversions ---------------------------------------------------------------
    def pinocchio_state(self, state: FloatingBaseState) -> tuple[np.ndarray, np.ndarray]:
        """(q, v) in Pinocchio's convention (quaternion xyzw, base twist in the base frame);
        fresh arrays (``StateConversion``)."""
        q, v, _, _ = self._spare_conversion(state)
        return q.copy(), v.copy()

    def srb_state(self, state: FloatingBaseState) -> np.ndarray:
        """The NMPC's SRB state (p, v, Theta, omega) of this robot: CoM at the standing offset
        from the base, omega in world; a fresh array."""
        return self._spare_conversion(state)[3]

    def foot_positions(self, state: FloatingBaseState) -> np.ndarray:
        """(4, 3) foot contact points [m] in world (foot frame minus the foot radius in z)."""
        self._observed = None  # the Pinocchio data no longer holds an observed state's terms
        q, _, _, _ = self._spare_conversion(state)
        pin.framesForwardKinematics(self.model, self.data, q)
        return self._feet()

    def _place_feet(self) -> None:
        """The foot frames' positions [m] from the placements in ``data`` into
        ``_foot_frames`` (``compute`` reads them there)."""
        for leg, frame_id in enumerate(self.foot_frame_ids):
            self._foot_frames[leg] = self.data.oMf[frame_id].translation

    def _feet(self) -> np.ndarray:
        """Contact points (4, 3) [m]: the foot frames placed, minus the foot radius in z."""
        self._place_feet()
        feet = self._foot_frames.copy()
        feet[:, 2] -= self.foot_radius_m
        return feet

    def observe(self, state: FloatingBaseState) -> tuple[np.ndarray, np.ndarray]:
        """``srb_state`` and ``foot_positions`` of ``state`` from one Pinocchio pass, whose
        rigid-body terms the next ``compute`` on this same state object reuses (one pass per
        robot and tick instead of three). The state's conversions are one compiled function
        (``StateConversion``), equal to ``pinocchio_state`` and ``srb_state``
        to round-off."""
        # q, v, rotation: the conversion's own arrays, read by ``compute`` within this tick
        q, v, rotation, srb = self._conversion(state)
        pin.computeAllTerms(self.model, self.data, q, v)
        pin.updateFramePlacements(self.model, self.data)
        self._observed = (state, q, v, rotation)
        return srb, self._feet()

    # --- control -------------------------------------------------------------------------
    def compute(self, state: FloatingBaseState, target: WbcTarget) -> WbcOutput:
        """One WBC tick: joint torques tracking ``target`` from the measured ``state``."""
        start = time.perf_counter()
        model, data = self.model, self.data
        observed, self._observed = self._observed, None
        if observed is not None and observed[0] is state:
            _, q, v, rotation = observed
        else:
            q, v, rotation, _ = self._conversion(state)
            pin.computeAllTerms(model, data, q, v)
            pin.updateFramePlacements(model, data)  # the swing feet's placements (oMf)
            self._place_feet()
        views = self._qp.views
        views["mass"][:] = data.M  # upper triangle filled; the assembly mirrors it
        bias = views["bias"]
        bias[:] = data.nle
        pin.forwardKinematics(model, data, q, v, self._zero_acceleration)  # data.a = Jdot v
        world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        jacobian, drift = views["contact_jacobian"], views["foot_drift"]
        for leg, frame_id in enumerate(self.foot_frame_ids):
            rows = slice(3 * leg, 3 * leg + 3)
            jacobian[rows] = pin.getFrameJacobian(model, data, frame_id, world)[0:3]
            drift[rows] = pin.getFrameClassicalAcceleration(model, data, frame_id, world).linear
        views["foot_frame"][:] = self._foot_frames.reshape(-1)  # placed by ``observe``
        views["velocity"][:] = v
        views["rotation"][:] = rotation
        views["base_position"][:] = state.position_base_in_world_m
        views["base_velocity"][:] = state.linear_velocity_in_world_m_s
        views["angular_velocity_in_body"][:] = state.angular_velocity_in_body_rad_s
        views["com_position"][:] = target.com_position_m
        views["com_velocity"][:] = target.com_velocity_m_s
        views["com_acceleration"][:] = target.com_acceleration_m_s2
        views["euler"][:] = target.euler_rad
        views["angular_velocity"][:] = target.angular_velocity_rad_s
        views["angular_acceleration"][:] = target.angular_acceleration_rad_s2
        stance = np.asarray(target.stance, dtype=bool)
        views["stance"][:] = stance
        # the (4, 3) targets through (4, 3) views of the flat inputs: no reshape call each
        views["planned_grf"].reshape(-1, 3)[:] = target.planned_grf_n
        views["foot_position"].reshape(-1, 3)[:] = target.foot_position_m
        views["foot_velocity"].reshape(-1, 3)[:] = target.foot_velocity_m_s
        views["foot_acceleration"].reshape(-1, 3)[:] = target.foot_acceleration_m_s2
        views["wrench_on_robot"][:] = target.wrench_on_robot
        qp = self._qp.assemble()
        x, _, status, _ = daqp.solve(qp.hessian, qp.gradient, qp.constraint, qp.upper,
                                     qp.lower, self._qp.sense(stance))
        elapsed = time.perf_counter() - start
        if status < 1 or not np.isfinite(x).all():
            return self._failed(int(status), elapsed)
        torque = qp.constraint[TORQUE_ROWS] @ x + bias[6:]
        # swing forces are pinned to zero; the product drops the solver's round-off there
        contact_force = x[0:FORCES].reshape(4, 3) * stance[:, None]
        np.minimum(torque, self.torque_limit_nm, out=torque)
        np.maximum(torque, -self.torque_limit_nm, out=torque)
        output = WbcOutput(torque, x[FORCES + 6:], contact_force, True, int(status),
                           time.perf_counter() - start)
        self._last = output
        return output

    def _failed(self, status: int, elapsed_s: float) -> WbcOutput:
        last = self._last
        torque = last.torque_nm if last is not None else np.zeros(JOINT_COUNT)
        return WbcOutput(torque, np.zeros(JOINT_COUNT), np.zeros((4, 3)), False, status,
                         elapsed_s)
