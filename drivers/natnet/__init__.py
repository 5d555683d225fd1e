"""OptiTrack NatNet motion capture: protocol, client and a fake Motive server.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "drivers.natnet.client": ["NatNetError", "MocapLostError", "NatNetClientConfig",
        "NatNetCounters", "NatNetClient"],
    "drivers.natnet.fake": ["FakeNatNetServer", "simulation_pose_source"],
    "drivers.natnet.protocol": ["MessageId", "NatNetProtocolError", "RigidBodySample",
        "FrameOfData", "RigidBodyDescription", "ServerInfo", "pack_message", "unpack_message",
        "pack_connect", "pack_server_info", "unpack_server_info", "pack_model_definitions",
        "unpack_model_definitions", "pack_frame_of_data", "unpack_frame_of_data"],
}
__all__ = ["FakeNatNetServer", "FrameOfData", "MessageId", "MocapLostError", "NatNetClient",
           "NatNetClientConfig", "NatNetCounters", "NatNetError", "NatNetProtocolError",
           "RigidBodyDescription", "RigidBodySample", "ServerInfo", "pack_connect",
           "pack_frame_of_data", "pack_message", "pack_model_definitions", "pack_server_info",
           "simulation_pose_source", "unpack_frame_of_data", "unpack_message",
           "unpack_model_definitions", "unpack_server_info"]
__getattr__ = lazy_exports(__name__, _SOURCES)
