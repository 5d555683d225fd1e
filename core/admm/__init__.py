"""ADMM distributed NMPC: the local solves' protocol and executors, the coordinated
iterations and the agents' own.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["admm_executor", "admm_mpc", "admm_peer_mpc"]
