"""OptiTrack NatNet motion capture: protocol, client and a fake Motive server.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["client", "fake", "protocol"]
