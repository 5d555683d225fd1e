"""Rerun views of live runs and recorded logs.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["layout", "rerun_view", "robot_models", "series"]
