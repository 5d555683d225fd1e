"""The ``porter`` command line: one module per command; the entry point is ``porter.main``."""

__all__ = ["agent_command", "bench_command", "conventions", "deploy_command", "drill_command",
           "log_arguments", "log_commands", "paper_command", "porter",
           "regress_command", "replay_command", "sim_arguments", "sim_command"]
