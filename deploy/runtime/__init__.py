"""The control loop: its clocks, the estimator pipeline, the team controller, commands and links.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["clock", "controller", "links", "loop", "loop_interfaces", "run_metrics", "sim_run",
           "state_pipeline", "stop_request", "team_commands"]
