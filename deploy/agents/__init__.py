"""ADMM agents on the network: the wire schema, ``porter agent`` and the Zenoh executor.

``wire`` (protobuf messages, checked on receipt), ``zenoh_session`` (settings, keys, peer
sessions), ``agent`` (one robot's local solver served over Zenoh), ``zenoh_executor`` (the
coordinator's side: a ``LocalSolveExecutor`` whose agents are processes).

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["agent", "messages", "wire", "zenoh_executor", "zenoh_session"]
