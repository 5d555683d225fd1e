"""The safety supervisor: its state machine, fault checks, pre-flight, postures, watchdog.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.safety.checks": ["SupervisorSettings", "RobotLimits", "robot_limits",
        "non_finite_fault", "tilt_rad", "orientation_fault", "base_height_fault",
        "joint_velocity_fault", "joint_position_fault", "torque_fault", "mocap_fault",
        "SolverFailureCounter", "DeadlineOverrunWindow", "WbcFailureCounter"],
    "deploy.safety.posture": ["standing_posture", "sitting_posture", "smoothstep", "PostureMove"],
    "deploy.safety.preflight": ["PreflightCheck", "PreflightReport", "evaluate"],
    "deploy.safety.supervisor": ["SafetyError", "SafetyInputs", "SafetyState", "SafetySupervisor",
        "Transition"],
    "deploy.safety.watchdog": ["Watchdog", "WatchdogSettings", "WatchdogSpec"],
}
__all__ = ["DeadlineOverrunWindow", "PostureMove", "PreflightCheck", "PreflightReport",
           "RobotLimits", "SafetyError", "SafetyInputs", "SafetyState", "SafetySupervisor",
           "SolverFailureCounter", "SupervisorSettings", "Transition", "base_height_fault",
           "evaluate", "joint_position_fault", "joint_velocity_fault", "mocap_fault",
           "non_finite_fault", "orientation_fault", "robot_limits", "sitting_posture", "smoothstep",
           "standing_posture", "tilt_rad", "torque_fault", "Watchdog", "WatchdogSettings",
           "WatchdogSpec", "WbcFailureCounter"]
__getattr__ = lazy_exports(__name__, _SOURCES)
