"""The SRB plant and the closed-loop harness for tests and benchmarks (no physics engine).

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["closed_loop", "srb_plant", "standard_scenarios"]
