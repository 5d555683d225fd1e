"""The MuJoCo team: the scene built from the URDFs, the simulation and its driver ends.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["scene", "sim_links", "simulation"]
