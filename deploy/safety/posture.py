"""Standing and sitting postures, and the joint PD commands that move between them.

Postures are leg joint angles [rad], (12,) in ``core.model.conventions.LEG_JOINT_NAMES`` order.
Standing: the SRDF ``standing`` group state (what the controller's models assume). Sitting: the
trunk lowered by ``lowering_m`` with a level trunk and every foot where it stands (inverse
kinematics on the Pinocchio model, per leg), so a coupled team sits down and stands up without
dragging its feet or tilting the payload (each robot type lowers by the same height).

``PostureMove`` interpolates PD targets from the measured posture to a goal over a duration
with a smoothstep (zero velocity at both ends), the way Unitree's stand-up examples do.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

import numpy as np
import pinocchio as pin

from core.model.conventions import JOINT_COUNT, LEG_NAMES
from core.model.robot_parameters import leg_joint_indices
from drivers.interfaces import JointCommand
from drivers.robot_descriptions import load_pinocchio_model, standing_configuration

_IK_ITERATIONS = 50
_IK_TOLERANCE_M = 1e-6


@cache
def standing_posture(robot_type: str) -> np.ndarray:
    """SRDF standing joint angles [rad] (12,)."""
    model = load_pinocchio_model(robot_type)
    q_indices, _ = leg_joint_indices(model)
    return standing_configuration(robot_type, model)[q_indices].copy()


@cache
def sitting_posture(robot_type: str, lowering_m: float) -> np.ndarray:
    """Joint angles [rad] (12,) with the trunk ``lowering_m`` [m] below standing, level, each
    foot where it stands. Raises ``ValueError`` when a foot cannot get there within the joint
    limits (lowering too deep for the legs)."""
    model = load_pinocchio_model(robot_type)
    data = model.createData()
    q_indices, v_indices = leg_joint_indices(model)
    q = standing_configuration(robot_type, model)
    q[0:7] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    pin.framesForwardKinematics(model, data, q)
    feet = [model.getFrameId(f"{leg}_foot") for leg in LEG_NAMES]
    targets = [data.oMf[f].translation + np.array([0.0, 0.0, lowering_m]) for f in feet]
    for leg, (frame, target) in enumerate(zip(feet, targets, strict=True)):
        columns = v_indices[3 * leg:3 * leg + 3]
        rows = q_indices[3 * leg:3 * leg + 3]
        for _ in range(_IK_ITERATIONS):
            pin.framesForwardKinematics(model, data, q)
            error = target - data.oMf[frame].translation
            if np.linalg.norm(error) < _IK_TOLERANCE_M:
                break
            jacobian = pin.computeFrameJacobian(model, data, q, frame,
                                                pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)[0:3]
            block = jacobian[:, columns]
            step = np.linalg.solve(block.T @ block + 1e-6 * np.eye(3), block.T @ error)
            q[rows] = np.clip(q[rows] + step, model.lowerPositionLimit[rows],
                              model.upperPositionLimit[rows])
        else:
            raise ValueError(f"{robot_type}: cannot lower the trunk by {lowering_m} m with "
                             f"the {LEG_NAMES[leg]} foot in place (joint limits)")
    return q[q_indices].copy()


def smoothstep(fraction: float) -> float:
    """3 s^2 - 2 s^3 on [0, 1], clipped: 0 -> 0, 1 -> 1, zero slope at both ends."""
    s = min(max(fraction, 0.0), 1.0)
    return s * s * (3.0 - 2.0 * s)


@dataclass
class PostureMove:
    """Joint PD targets from ``start_rad`` to ``goal_rad`` (12,) over ``duration_s`` [s]
    beginning at ``start_s`` (caller's clock), gains ``kp`` [N m/rad], ``kd`` [N m s/rad]."""

    start_rad: np.ndarray
    goal_rad: np.ndarray
    start_s: float
    duration_s: float
    kp: float
    kd: float

    def command(self, time_s: float) -> JointCommand:
        """The PD command at ``time_s`` (target velocity from the smoothstep's slope)."""
        fraction = (time_s - self.start_s) / self.duration_s
        s = smoothstep(fraction)
        slope = 6.0 * fraction * (1.0 - fraction) / self.duration_s if 0 < fraction < 1 else 0.0
        delta = np.asarray(self.goal_rad) - np.asarray(self.start_rad)
        return JointCommand(position_rad=self.start_rad + s * delta,
                            velocity_rad_s=slope * delta,
                            kp=np.full(JOINT_COUNT, self.kp), kd=np.full(JOINT_COUNT, self.kd))

    def done(self, time_s: float) -> bool:
        return time_s >= self.start_s + self.duration_s
