"""From plan to torques: trot gait, swing trajectories, plan tracking, whole-body control.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["buffered_function", "gait", "plan_tracking", "settings", "swing_trajectory",
           "wbc_qp", "whole_body_control"]
