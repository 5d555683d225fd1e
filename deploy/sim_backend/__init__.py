"""The simulated world behind the real drivers' protocols, in its own process.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.sim_backend.backend": ["free_udp_port", "loopback_config", "SimBackend"],
    "deploy.sim_backend.world": ["ScaledClock", "CommandsAfterFault", "WorldSpec", "PipeBus",
        "lay_down", "SimWorld", "serve"],
    "deploy.sim_backend.world_faults": ["inject_due_faults", "network_faults"],
}
__all__ = ["CommandsAfterFault", "PipeBus", "ScaledClock", "SimBackend", "SimWorld", "WorldSpec",
           "free_udp_port", "inject_due_faults", "lay_down", "loopback_config", "network_faults",
           "serve"]
__getattr__ = lazy_exports(__name__, _SOURCES)
