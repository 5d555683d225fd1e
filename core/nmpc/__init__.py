"""The NMPC: stage-wise NLPs, CBFs, solvers, warm start, the centralized controller and
the controller protocol (ADMM: ``core.admm``).

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["cbf", "centralized_mpc", "delay_compensation", "inputs_builder", "layout",
           "mpc_inputs", "mpc_plan", "nlp_solver", "obstacle_selection", "reference",
           "settings", "stagewise_nlp", "team_mpc", "transport_problem", "warm_start"]
