"""Typed scenario and deploy configs, their YAML loading and the shipped files.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["deploy_config", "files", "profiles", "scenario", "sim_faults"]
