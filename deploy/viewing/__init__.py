"""Rerun views of live runs and recorded logs.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.viewing.layout": ["robot_entity", "blueprint"],
    "deploy.viewing.rerun_view": ["RerunLogView", "open_recording", "LiveSink", "live_sink"],
    "deploy.viewing.robot_models": ["RobotModels", "model_entity"],
    "deploy.viewing.series": ["SeriesLogger"],
}
__all__ = ["LiveSink", "RerunLogView", "RobotModels", "SeriesLogger", "blueprint", "live_sink",
           "model_entity", "open_recording", "robot_entity"]
__getattr__ = lazy_exports(__name__, _SOURCES)
