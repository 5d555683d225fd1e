"""The paper's claims reproduced: one ``porter paper CLAIM`` per ablation, porter's figures
beside the paper's.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["claims", "closed_loop", "experiments", "reproduce", "table1"]
