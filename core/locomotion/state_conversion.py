"""A robot's measured state in the forms the WBC needs, as one CasADi function per robot:
Pinocchio's (q, v), the base rotation and the NMPC's SRB state. World frame, SI units.

The same arithmetic as ``WholeBodyController.pinocchio_state`` and ``srb_state`` (tested against
them), written once as an expression so that the 500 Hz tick makes one call instead of ~25
small NumPy operations per robot (~65 us at real-time pace, measured in ``observe``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from core.locomotion.buffered_function import BufferedFunction, ParameterVector
from core.model.conventions import JOINT_COUNT
from core.model.rotations import euler_angles, quaternion_rotation_rows

if TYPE_CHECKING:  # a protocol only; the NMPC package need not load
    from core.locomotion.whole_body_control import FloatingBaseState
    from core.nmpc.nlp_solver import NlpCompiler

__all__ = ["StateConversion"]

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
