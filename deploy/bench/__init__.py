"""``porter bench``: one module per bench, each with its runner and ``format_table``."""

__all__ = ["agents", "deploy_runs", "driver_peers", "drivers", "nmpc", "obstacle_family",
           "recorder", "rti_fidelity", "sim", "wbc_tick"]
