"""``porter drill``: a fault suite run end to end on the sim backend, one ``porter deploy`` per
fault, judged from the outside (exit code, summary, the simulator's truth, the log).

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["catalogue", "runner"]
