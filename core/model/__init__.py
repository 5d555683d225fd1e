"""The physical model: conventions, rotations, SRB bodies, coupling, team, obstacles, settings.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "core.model.conventions": ["FOOT_COUNT", "JOINT_COUNT", "LEG_JOINT_KINDS", "LEG_JOINT_NAMES",
        "LEG_NAMES", "PAYLOAD_NAME"],
    "core.model.coupling": ["CouplingKinematics", "coupling_point_in_world", "coupling_kinematics",
        "acceleration_level_constraint", "yaw_torque"],
    "core.model.obstacles": ["Obstacle"],
    "core.model.robot_parameters": ["leg_joint_indices", "srb_parameters_from_model"],
    "core.model.rotations": ["rotation_from_euler", "euler_from_rotation", "yaw_rotation",
        "rotation_from_quaternion_wxyz"],
    "core.model.srb_model": ["SrbParameters", "split_state", "rotation_body_to_world",
        "euler_rates_from_angular_velocity", "BodyAcceleration", "inertia_matrix",
        "inertia_entries", "rigid_body_acceleration", "robot_acceleration", "payload_acceleration",
        "semi_implicit_euler_step", "payload_parameters"],
    "core.model.strict_model": ["StrictModel"],
    "core.model.team": ["TeamModel"],
    "core.model.team_settings": ["ROBOT_TYPES", "AgentSettings", "PayloadSettings", "TeamSettings"],
}
__all__ = ["AgentSettings", "BodyAcceleration", "CouplingKinematics", "FOOT_COUNT", "JOINT_COUNT",
           "LEG_JOINT_KINDS", "LEG_JOINT_NAMES", "LEG_NAMES", "Obstacle", "PAYLOAD_NAME",
           "PayloadSettings", "ROBOT_TYPES", "SrbParameters", "StrictModel", "TeamModel",
           "TeamSettings", "acceleration_level_constraint", "coupling_kinematics",
           "coupling_point_in_world", "euler_from_rotation", "euler_rates_from_angular_velocity",
           "inertia_entries", "inertia_matrix", "leg_joint_indices", "payload_acceleration",
           "payload_parameters", "rigid_body_acceleration", "robot_acceleration",
           "rotation_body_to_world", "rotation_from_euler", "rotation_from_quaternion_wxyz",
           "semi_implicit_euler_step", "split_state", "srb_parameters_from_model", "yaw_rotation",
           "yaw_torque"]
__getattr__ = lazy_exports(__name__, _SOURCES)
