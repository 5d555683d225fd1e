"""How messages between ADMM agents travel: a seeded lossy, delaying channel with hold-last.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["lossy_channel"]
