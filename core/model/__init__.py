"""The physical model: conventions, rotations, SRB bodies, coupling, team, obstacles, settings.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["conventions", "coupling", "obstacles", "robot_parameters", "rotations", "srb_model",
           "strict_model", "team", "team_settings"]
