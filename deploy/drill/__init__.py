"""``porter drill``: a fault suite run end to end on the sim backend, one ``porter deploy`` per
fault, judged from the outside (exit code, summary, the simulator's truth, the log)."""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.drill.catalogue": ["DrillFault", "catalogue"],
    "deploy.drill.runner": ["DrillRow", "format_table", "run_fault"],
}
__all__ = ["DrillFault", "DrillRow", "catalogue", "format_table", "run_fault"]
__getattr__ = lazy_exports(__name__, _SOURCES)
