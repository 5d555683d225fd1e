"""Typed whole-body-controller settings: task gains and QP weights (SI units)."""

from __future__ import annotations

from pydantic import Field

from core.model.strict_model import StrictModel

__all__ = ["WbcSettings"]


class WbcSettings(StrictModel):
    """Whole-body controller (core/locomotion/whole_body_control.py): task gains and QP weights.

    Gains are per axis (x, y, z) in the world frame; weights scale squared task errors in the
    QP cost (accelerations [m/s^2, rad/s^2] for motion tasks, [N] for forces).
    """

    base_position_gain: tuple[float, float, float] = (150.0, 150.0, 250.0)  # [1/s^2]
    base_velocity_gain: tuple[float, float, float] = (20.0, 20.0, 30.0)  # [1/s]
    base_orientation_gain: tuple[float, float, float] = (250.0, 250.0, 150.0)  # [1/s^2]
    base_angular_velocity_gain: tuple[float, float, float] = (25.0, 25.0, 20.0)  # [1/s]
    swing_position_gain: float = Field(500.0, ge=0)  # [1/s^2]
    swing_velocity_gain: float = Field(40.0, ge=0)  # [1/s]
    stance_velocity_damping: float = Field(10.0, ge=0)  # [1/s], stance feet pushed to rest
    base_weight: float = Field(1.0, gt=0)
    swing_weight: float = Field(1.0, gt=0)
    force_weight: float = Field(1e-4, gt=0)  # tracking of the planned GRFs
    regularization: float = Field(1e-6, gt=0)
    friction_coefficient: float = Field(0.4, gt=0)
    min_normal_force_n: float = Field(1.0, ge=0)
    max_normal_force_n: float = Field(250.0, gt=0)
    # The hybrid joint command (Unitree's q, dq, kp, kd, tau): beside the QP's torque, the
    # motor's own PD holds the position and velocity the QP's accelerations integrate to one
    # tick ahead, so that a command applied longer than planned (a late state, tick or plan)
    # holds the leg instead of driving it with an open torque.
    joint_stiffness_nm_rad: float = Field(10.0, ge=0)  # firmware kp toward the position target
    joint_damping_nm_s: float = Field(0.5, ge=0)  # firmware kd toward the velocity target
