"""This computer: compiled code and its cache, BLAS kernels, real-time scheduling and CPUs, CPU
time, process names, garbage-collection pauses.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["blas_kernels", "codegen_cache", "cpu_meter", "gc_pauses", "process_names", "realtime"]
