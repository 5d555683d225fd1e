"""From plan to torques: trot gait, swing trajectories, plan tracking, whole-body control.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "core.locomotion.gait": ["TrotGait", "FootholdPlanner"],
    "core.locomotion.plan_tracking": ["LegCoordinator", "plan_set_point", "wbc_target"],
    "core.locomotion.buffered_function": ["BufferedFunction", "ParameterVector"],
    "core.locomotion.settings": ["WbcSettings"],
    "core.locomotion.state_conversion": ["StateConversion"],
    "core.locomotion.swing_targets": ["SwingTargets"],
    "core.locomotion.swing_trajectory": ["SwingPoint", "swing_point"],
    "core.locomotion.wbc_qp": ["WbcQpArrays", "WbcQpAssembly", "so3_log"],
    "core.locomotion.whole_body_control": ["FloatingBaseState", "WbcTarget", "WbcOutput",
        "WholeBodyController"],
}
__all__ = ["BufferedFunction", "FloatingBaseState", "FootholdPlanner", "LegCoordinator",
           "ParameterVector", "StateConversion", "SwingPoint", "SwingTargets", "TrotGait", "WbcOutput",
           "WbcQpArrays", "WbcQpAssembly", "WbcSettings", "WbcTarget", "WholeBodyController",
           "plan_set_point", "so3_log", "swing_point", "wbc_target"]
__getattr__ = lazy_exports(__name__, _SOURCES)
