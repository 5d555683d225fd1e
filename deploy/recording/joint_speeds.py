"""The fastest calf's speed in a flight log while the team ran: the figure that holds a
real-time run against its lockstep run (``porter sim``), since a leg whipped by late states or
plans shows there first (``porter log info``).

Over every ``/robot/<name>/state`` message between the ``-> RUNNING`` and the ``RUNNING ->``
safety events (the whole log when it has none, as a lockstep ``porter sim`` log): per state,
the largest calf joint speed |dq| [rad/s] of that robot; then the 99.9th percentile and the
maximum over all robots' states.
"""

from __future__ import annotations

import math

import numpy as np

from core.model.conventions import LEG_JOINT_NAMES
from deploy.recording.log_reader import LogFile

__all__ = ["CALF_JOINTS", "calf_speed_running", "running_window"]

CALF_JOINTS = [i for i, name in enumerate(LEG_JOINT_NAMES) if "_calf_" in name]


def running_window(log: LogFile) -> tuple[float, float]:
    """(start, end) [s, log time] of RUNNING from the safety events; +-inf where the log has
    no such event (the last RUNNING period where it has several)."""
    start_s, end_s = -math.inf, math.inf
    for decoded in log.messages(["/events"]):
        if decoded.message.source != "safety":
            continue
        transition = decoded.message.text.split(":")[0]
        if transition.endswith("-> RUNNING"):
            start_s, end_s = decoded.time_s, math.inf
        elif transition.startswith("RUNNING ->"):
            end_s = decoded.time_s
    return start_s, end_s


def calf_speed_running(log: LogFile) -> dict | None:
    """``{"p99_9_rad_s", "max_rad_s", "states"}`` of the fastest calf's speed while RUNNING,
    over every robot's states; None if the log has no robot state then."""
    counts, _, _ = log.message_counts()
    topics = sorted(t for t in counts if t.startswith("/robot/") and t.endswith("/state"))
    start_s, end_s = running_window(log)
    speeds = [float(np.max(np.abs(np.asarray(decoded.message.joint_velocity_rad_s)[CALF_JOINTS])))
              for decoded in log.messages(topics) if start_s <= decoded.time_s <= end_s]
    if not topics or not speeds:
        return None
    return {"p99_9_rad_s": float(np.percentile(speeds, 99.9)), "max_rad_s": max(speeds),
            "states": len(speeds)}
