"""The NMPC: stage-wise NLPs, CBFs, solvers, warm start, ADMM and centralized controllers.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["admm_executor", "admm_mpc", "cbf", "centralized_mpc", "delay_compensation",
           "inputs_builder", "layout", "mpc_inputs", "mpc_plan", "nlp_solver",
           "obstacle_selection", "reference", "settings", "stagewise_nlp", "transport_problem",
           "warm_start"]
