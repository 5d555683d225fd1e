"""The NMPC beside the control loop: its 60 Hz schedule, its runners and the ADMM workers.

``nmpc_schedule`` (the grid, the hand-off, the supervisor's flags) drives one runner:
``nmpc_process`` (a process of its own), ``nmpc_thread`` (a thread of the loop's process) or
``nmpc_lockstep`` (simulated time); ``process_executor`` runs ADMM local solves in worker
processes, their arrays in shared memory (``solve_slots``).

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["nmpc_lockstep", "nmpc_process", "nmpc_schedule", "nmpc_thread", "process_executor",
           "solve_slots"]
