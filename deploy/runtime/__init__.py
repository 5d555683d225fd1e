"""The control loop: time, real-time priority, the team controller, links, process names, CPU and
GC metering.

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
        "mocap_state", "TeamController", "build_team_mpc"],
    "deploy.runtime.links": ["MocapTracker", "TeamLinks", "open_links", "finite_or_none"],
    "deploy.runtime.loop": ["ControlLoop", "SATURATION_MARGIN"],
    "deploy.runtime.loop_interfaces": ["Heartbeat", "LoopHooks", "LoopSettings"],
    "deploy.runtime.process_names": ["COMM_LENGTH", "name_this_process"],
    "deploy.runtime.realtime": ["RealtimePriorityError"],
    "deploy.runtime.cpu_meter": ["RunningCpu", "cpu_seconds"],
    "deploy.runtime.gc_pauses": ["GcPauses", "freeze_startup_objects"],
    "deploy.runtime.run_metrics": ["RunMetrics"],
    "deploy.runtime.sim_run": ["WBC_DECIMATION", "SimRun"],
    "deploy.runtime.stale_state": ["StaleStateHold"],
    "deploy.runtime.stop_request": ["StopRequest"],
    "deploy.runtime.timing": ["Pacer", "PeriodStats"],
}
__all__ = ["COMM_LENGTH", "CompilationError", "CompiledCodeCache", "ControlLoop", "GcPauses",
           "Heartbeat", "LockstepClock", "LoopClock", "LoopHooks", "LoopSettings", "MocapTracker",
           "NmpcDecision", "PacedClock", "Pacer", "PeriodStats", "RealtimePriorityError",
           "RobotControl", "RunMetrics", "RunningCpu", "build_team_mpc", "cpu_seconds",
           "name_this_process", "SATURATION_MARGIN", "SimRun", "StaleStateHold", "StopRequest",
           "TeamController", "TeamLinks",
           "WBC_DECIMATION", "WbcStep", "default_cache_directory", "finite_or_none",
           "freeze_startup_objects", "measurement_state", "mocap_state", "open_links"]
__getattr__ = lazy_exports(__name__, _SOURCES)
