"""State estimation: the payload's state from the agents, each robot's base velocity.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["base_velocity", "payload_estimator"]
