"""The control loop: time, real-time priority, the team controller, links, process names, CPU and
GC metering.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["clock", "controller", "links", "loop", "loop_interfaces", "run_metrics", "sim_run",
           "stale_state", "state_pipeline", "stop_request", "team_commands", "timing"]
