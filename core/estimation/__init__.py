"""State estimation: the payload's state from the agents, each robot's base velocity.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "core.estimation.base_velocity": ["BaseVelocityEstimator", "LegMeasurement"],
    "core.estimation.payload_estimator": ["PayloadEstimator"],
}
__all__ = ["BaseVelocityEstimator", "LegMeasurement", "PayloadEstimator"]
__getattr__ = lazy_exports(__name__, _SOURCES)
