"""The SRB plant and the closed-loop harness for tests and benchmarks (no physics engine).

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "core.plant.closed_loop": ["Controller", "ClosedLoopResult", "run_closed_loop"],
    "core.plant.srb_plant": ["SrbPlant"],
    "core.plant.standard_scenarios": ["StandardScenario", "ring_team_settings", "standard_scenario"],
}
__all__ = ["ClosedLoopResult", "Controller", "SrbPlant", "StandardScenario", "ring_team_settings",
           "run_closed_loop", "standard_scenario"]
__getattr__ = lazy_exports(__name__, _SOURCES)
