"""The CAN bus: e-stop heartbeat and coupling force/torque sensors, with a fake node.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["bus", "fake", "protocol"]
