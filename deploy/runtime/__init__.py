"""The control loop: time, real-time priority, the team controller, links, process names, CPU and
GC metering.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["blas_kernels", "clock", "codegen_cache", "controller", "cpu_meter", "gc_pauses",
           "links", "loop", "loop_interfaces", "process_names", "realtime", "run_metrics",
           "sim_run", "stale_state", "stop_request", "timing"]
