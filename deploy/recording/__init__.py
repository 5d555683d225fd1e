"""The flight log: MCAP recorder, message format, reader, expectations and regression.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.recording.expectations": ["expectations_path", "check_expectations",
        "draft_expectations"],
    "deploy.recording.flight_recorder": ["RecorderSettings", "FlightRecorder"],
    "deploy.recording.log_format": ["robot_topic", "mocap_topic", "to_nanoseconds", "timestamp",
        "array", "from_array", "robot_state", "joint_command", "as_list", "pose_in_frame",
        "frame_transforms", "mocap_messages", "obstacle_scene", "payload_box", "on_log_clock"],
    "deploy.recording.log_reader": ["LogError", "DecodedMessage", "LogFile", "Recovery", "recover"],
    "deploy.recording.loop_recording": ["LoopRecording", "update_message", "warm_start_message"],
    "deploy.recording.regression": ["LogRegression", "controller_from_log", "inputs_from_message",
        "memory_from_message", "compare", "regress_log", "format_report", "refresh_expectations",
        "run_regress"],
    "deploy.recording.robot_scene": ["LINK_TF", "ROBOT_SCENE", "LinkTransforms", "link_frame",
        "robot_scene"],
    "deploy.recording.run_record": ["git_revision", "run_metadata", "run_attachments",
        "open_run_recorder", "default_log_path", "safe_file_stem"],
}
__all__ = ["LINK_TF", "ROBOT_SCENE", "DecodedMessage", "FlightRecorder", "LinkTransforms",
           "LogError", "LogFile", "LogRegression", "link_frame", "on_log_clock", "robot_scene",
           "LoopRecording", "RecorderSettings", "Recovery", "array", "as_list",
           "check_expectations", "compare", "controller_from_log", "default_log_path",
           "draft_expectations", "expectations_path", "format_report", "frame_transforms",
           "from_array", "git_revision", "inputs_from_message", "joint_command",
           "memory_from_message", "mocap_messages", "mocap_topic", "obstacle_scene",
           "open_run_recorder", "payload_box", "pose_in_frame", "recover", "refresh_expectations",
           "safe_file_stem",
           "regress_log", "robot_state", "robot_topic", "run_attachments", "run_metadata",
           "run_regress", "timestamp", "to_nanoseconds", "update_message", "warm_start_message"]
__getattr__ = lazy_exports(__name__, _SOURCES)
