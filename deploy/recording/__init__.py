"""The flight log: MCAP recorder, message format, reader, expectations and regression.

No names are re-exported: import from the module that defines a name (its modules are
listed in ``__all__``), so importing the package imports nothing else.
"""

__all__ = ["expectations", "fault_timeline", "flight_recorder", "joint_speeds", "log_format",
           "log_reader", "loop_recording", "messages", "regression", "resimulation",
           "robot_scene", "run_record"]
