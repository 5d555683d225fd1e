"""The CAN bus: e-stop heartbeat and coupling force/torque sensors, with a fake node.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "drivers.can.bus": ["CanCounters", "EstopMonitor", "ForceTorqueSensors"],
    "drivers.can.fake": ["FakeCanNode"],
    "drivers.can.protocol": ["EstopState", "CanFrameError", "EstopHeartbeat", "WrenchHalf",
        "encode_estop_heartbeat", "decode_estop_heartbeat", "is_force_torque_id", "encode_wrench",
        "decode_wrench_half"],
}
__all__ = ["CanCounters", "CanFrameError", "EstopHeartbeat", "EstopMonitor", "EstopState",
           "FakeCanNode", "ForceTorqueSensors", "WrenchHalf", "decode_estop_heartbeat",
           "decode_wrench_half", "encode_estop_heartbeat", "encode_wrench", "is_force_torque_id"]
__getattr__ = lazy_exports(__name__, _SOURCES)
