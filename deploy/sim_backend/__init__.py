"""The simulated world behind the real drivers' protocols, in its own process.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["backend", "porter_faults", "world", "world_faults"]
