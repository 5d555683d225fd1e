"""Unitree robots: Go2 over DDS, A1 over UDP, their conventions and their fakes.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "drivers.unitree.a1_driver": ["A1Driver"],
    "drivers.unitree.a1_fake": ["FakeA1"],
    "drivers.unitree.firmware_timeout": ["CommandTimeout"],
    "drivers.unitree.a1_udp_layout": ["LayoutError", "encode_low_cmd", "decode_low_cmd",
        "encode_low_state", "decode_low_state"],
    "drivers.unitree.conventions": ["WireState", "WireCommand", "wire_state_from_measurement",
        "measurement_from_wire_state", "state_problem", "wire_command_from_joint_command",
        "damping_wire_command", "joint_command_from_wire_command", "command_problem",
        "rpy_from_quaternion_wxyz", "crc32_mpeg2", "unitree_crc32", "unitree_crc32_of_packed"],
    "drivers.unitree.go2_dds_types": ["MotorCmd_", "MotorState_", "IMUState_", "BmsCmd_",
        "BmsState_", "LowCmd_", "LowState_", "RequestIdentity_", "RequestLease_", "RequestPolicy_",
        "RequestHeader_", "Request_", "ResponseStatus_", "ResponseHeader_", "Response_",
        "low_cmd_from_wire", "wire_from_low_cmd", "low_state_from_wire", "wire_from_low_state",
        "low_cmd_header_ok", "api_request", "api_response", "low_cmd_crc", "low_state_crc"],
    "drivers.unitree.go2_driver": ["cyclonedds_config", "open_participant", "topic_name",
        "Go2Driver"],
    "drivers.unitree.go2_fake": ["FakeGo2"],
    "drivers.unitree.peer": ["UnitreeLowLevelDriver", "PeriodicThread"],
}
__all__ = ["A1Driver", "BmsCmd_", "BmsState_", "CommandTimeout", "FakeA1", "FakeGo2", "Go2Driver",
           "IMUState_",
           "LayoutError", "LowCmd_", "LowState_", "MotorCmd_", "MotorState_", "PeriodicThread",
           "RequestHeader_", "RequestIdentity_", "RequestLease_", "RequestPolicy_", "Request_",
           "ResponseHeader_", "ResponseStatus_", "Response_", "UnitreeLowLevelDriver",
           "WireCommand", "WireState", "api_request", "api_response", "command_problem",
           "crc32_mpeg2", "cyclonedds_config", "damping_wire_command", "decode_low_cmd",
           "decode_low_state", "encode_low_cmd", "encode_low_state",
           "joint_command_from_wire_command", "low_cmd_crc", "low_cmd_from_wire", "low_state_crc",
           "low_cmd_header_ok", "low_state_from_wire", "measurement_from_wire_state",
           "open_participant", "rpy_from_quaternion_wxyz", "state_problem", "topic_name",
           "unitree_crc32", "unitree_crc32_of_packed", "wire_command_from_joint_command",
           "wire_from_low_cmd", "wire_from_low_state", "wire_state_from_measurement"]
__getattr__ = lazy_exports(__name__, _SOURCES)
