"""The control loop: time, the team controller, NMPC scheduling, links and workers.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.runtime.clock": ["LockstepClock", "LoopClock", "PacedClock"],
    "deploy.runtime.codegen_cache": ["CompilationError", "default_cache_directory",
        "CompiledCodeCache"],
    "deploy.runtime.controller": ["RobotControl", "NmpcDecision", "WbcStep", "measurement_state",
        "mocap_state", "TeamController"],
    "deploy.runtime.links": ["MocapTracker", "TeamLinks", "open_links", "finite_or_none"],
    "deploy.runtime.loop": ["ControlLoop", "LoopHooks", "LoopSettings", "SATURATION_MARGIN"],
    "deploy.runtime.nmpc_lockstep": ["LockstepNmpc"],
    "deploy.runtime.nmpc_schedule": ["Flags", "NmpcHooks", "NmpcRunner", "NmpcSchedule"],
    "deploy.runtime.nmpc_thread": ["NmpcResult", "NmpcThread"],
    "deploy.runtime.process_executor": ["ProcessExecutor"],
    "deploy.runtime.run_metrics": ["RunMetrics"],
    "deploy.runtime.sim_run": ["WBC_DECIMATION", "SimRun", "summary_line"],
    "deploy.runtime.stop_request": ["StopRequest"],
    "deploy.runtime.timing": ["Pacer", "PeriodStats"],
}
__all__ = ["CompilationError", "CompiledCodeCache", "ControlLoop", "Flags", "LockstepClock",
           "LockstepNmpc", "LoopClock", "LoopHooks", "LoopSettings", "MocapTracker", "NmpcDecision",
           "NmpcHooks", "NmpcResult", "NmpcRunner", "NmpcSchedule", "NmpcThread", "PacedClock",
           "Pacer", "PeriodStats", "ProcessExecutor", "RobotControl", "RunMetrics",
           "SATURATION_MARGIN", "SimRun", "StopRequest", "TeamController", "TeamLinks",
           "WBC_DECIMATION", "WbcStep", "default_cache_directory", "finite_or_none",
           "measurement_state", "mocap_state", "open_links", "summary_line"]
__getattr__ = lazy_exports(__name__, _SOURCES)
