"""The safety supervisor: its state machine, fault checks, pre-flight, postures, watchdog.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["checks", "posture", "preflight", "run_sequence", "settings", "supervisor", "watchdog"]
