"""The NMPC beside the control loop: its 60 Hz schedule, its runners and the ADMM workers.

``nmpc_schedule`` (the grid, the hand-off, the supervisor's flags) drives one runner:
``nmpc_process`` (a process of its own), ``nmpc_thread`` (a thread of the loop's process) or
``nmpc_lockstep`` (simulated time); ``process_executor`` runs ADMM local solves in worker
processes, their arrays in shared memory (``solve_slots``). Names load on first use
(``core.lazy_exports``), so importing the package imports nothing else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.nmpc_runtime.nmpc_lockstep": ["LockstepNmpc"],
    "deploy.nmpc_runtime.nmpc_process": ["NmpcProcess", "NmpcProcessError"],
    "deploy.nmpc_runtime.nmpc_schedule": ["Flags", "NmpcHooks", "NmpcRunner", "NmpcSchedule"],
    "deploy.nmpc_runtime.nmpc_thread": ["NmpcResult", "NmpcThread"],
    "deploy.nmpc_runtime.process_executor": ["ProcessExecutor"],
}
__all__ = ["Flags", "LockstepNmpc", "NmpcHooks", "NmpcProcess", "NmpcProcessError", "NmpcResult",
           "NmpcRunner", "NmpcSchedule", "NmpcThread", "ProcessExecutor"]
__getattr__ = lazy_exports(__name__, _SOURCES)
