"""Base linear velocity for robots that do not measure it (Go2, A1): leg odometry fused with MoCap.

The MoCap velocity (``deploy.runtime.links.MocapTracker``: least squares over ~80 ms of poses) is
drift-free but ~40 ms late; fed to the WBC's base velocity feedback (gains 20-30 /s) that lag
makes the trunk bounce (measured on ``--backend sim``: growing vertical oscillation within
0.6 s). Leg odometry is immediate: a stance foot does not move, so

    v_base = -(omega x (p_foot - p_base) + R J_leg(q) dq)   (world frame)

from the joint angles and speeds and the gyroscope, averaged over the feet in contact
(measured contact flags). The estimate is ``v_legs + c`` where the correction ``c`` follows
``v_mocap - v_legs`` through a first-order low-pass of time constant ``correction_time_s``:
high frequencies from the legs, the mean from the MoCap. With no foot in contact the last
odometry velocity is held. The feet's velocities relative to the base come from Pinocchio in
the base frame (its free-flyer at the identity, base angular velocity in v[3:6]); the base
rotation (``rotation_from_quaternion_wxyz``) turns their mean into the world frame.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
import pinocchio as pin

from core.model.conventions import LEG_NAMES
from core.model.robot_parameters import leg_joint_indices
from core.model.rotations import rotation_from_quaternion_wxyz

__all__ = ["BaseVelocityEstimator", "LegMeasurement"]


class LegMeasurement(Protocol):
    """What the estimator reads of a robot's measurement (``drivers.interfaces.RobotMeasurement``
    has it): world frame, SI units, joints in ``LEG_JOINT_NAMES`` order, feet in ``LEG_NAMES``."""

    @property
    def quaternion_wxyz(self) -> np.ndarray: ...
    @property
    def angular_velocity_in_body_rad_s(self) -> np.ndarray: ...
    @property
    def position_rad(self) -> np.ndarray: ...
    @property
    def velocity_rad_s(self) -> np.ndarray: ...
    @property
    def foot_contact(self) -> np.ndarray: ...


class BaseVelocityEstimator:
    """One robot's base velocity [m/s], world frame; ``update`` once per loop tick.

    ``model``: the robot's free-flyer Pinocchio model (``drivers.robot_descriptions``)."""

    def __init__(self, model: pin.Model, correction_time_s: float = 0.2) -> None:
        self.model = model
        self.data = self.model.createData()
        self.q_indices, self.v_indices = leg_joint_indices(model)
        self.feet = [self.model.getFrameId(f"{leg}_foot") for leg in LEG_NAMES]
        self.correction_time_s = correction_time_s
        self.correction = np.zeros(3)
        self.legs_velocity = np.zeros(3)
        self._last_time_s: float | None = None
        # Pinocchio's (q, v) in the base frame, refilled in place each tick: the base pose stays
        # the identity and its linear velocity zero (they do not change a foot's velocity
        # relative to the base), so only the joints and the gyroscope enter; the robot's pose
        # in world is the WBC's q alone (``core.locomotion.whole_body_control``)
        self._q = pin.neutral(self.model)
        self._v = np.zeros(self.model.nv)

    def leg_odometry(self, measurement: LegMeasurement) -> np.ndarray | None:
        """Base velocity from the stance feet, or None when no foot is in contact."""
        stance = [i for i, contact in enumerate(measurement.foot_contact) if contact]
        if not stance:
            return None
        q, v = self._q, self._v
        q[self.q_indices] = measurement.position_rad
        v[3:6] = measurement.angular_velocity_in_body_rad_s
        v[self.v_indices] = measurement.velocity_rad_s
        # the feet's velocities need the joints' placements and velocities only, not the
        # frames' placements (getFrameVelocity composes them from the parent joint); with the
        # base at the identity, "world aligned" is the base frame
        pin.forwardKinematics(self.model, self.data, q, v)
        aligned = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
        total_in_base = np.zeros(3)
        for i in stance:
            total_in_base += pin.getFrameVelocity(self.model, self.data, self.feet[i],
                                                  aligned).linear
        rotation = rotation_from_quaternion_wxyz(measurement.quaternion_wxyz)
        return rotation @ total_in_base / -len(stance)

    def update(self, time_s: float, measurement: LegMeasurement,
               mocap_velocity_m_s: np.ndarray) -> np.ndarray:
        """The fused velocity [m/s] at ``time_s`` [s], world frame, from the legs of
        ``measurement`` and the MoCap velocity ``mocap_velocity_m_s`` [m/s] (3,)."""
        legs = self.leg_odometry(measurement)
        if legs is not None:
            self.legs_velocity = legs
        mocap = np.asarray(mocap_velocity_m_s, dtype=float)
        if self._last_time_s is None:
            self.correction = mocap - self.legs_velocity
        else:
            step = min(max(time_s - self._last_time_s, 0.0) / self.correction_time_s, 1.0)
            self.correction += step * (mocap - self.legs_velocity - self.correction)
        self._last_time_s = time_s
        return self.legs_velocity + self.correction
