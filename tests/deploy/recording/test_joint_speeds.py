"""The fastest calf's speed while RUNNING, read back from a real recorded run."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from deploy.cli.log_commands import describe, info_record
from deploy.recording.joint_speeds import CALF_JOINTS, calf_speed_running, running_window
from deploy.recording.log_reader import LogFile


def test_the_calves_are_the_third_joint_of_every_leg() -> None:
    assert CALF_JOINTS == [2, 5, 8, 11]


def test_the_fastest_calf_is_read_from_every_robot_state(recorded_run: tuple[Path, list, dict]
                                                          ) -> None:
    path, logged, _ = recorded_run
    log = LogFile(path)
    start_s, end_s = running_window(log)  # the run's safety events: RUNNING over 0.4 s
    assert (start_s, end_s) == pytest.approx((0.0, 0.4))
    expected = [np.abs(np.asarray(message.joint_velocity_rad_s)[[2, 5, 8, 11]]).max()
                for topic, message, _ in logged
                if topic.startswith("/robot/") and topic.endswith("/state")
                and start_s <= message.time_s <= end_s]
    calf = calf_speed_running(log)
    assert calf is not None and calf["states"] == len(expected) > 100
    assert calf["max_rad_s"] == pytest.approx(max(expected))
    assert calf["p99_9_rad_s"] == pytest.approx(np.percentile(expected, 99.9))
    assert 0.0 < calf["p99_9_rad_s"] <= calf["max_rad_s"]
    assert info_record(log)["calf_speed_running"] == calf
    assert f"fastest calf while running: p99.9 {calf['p99_9_rad_s']:.1f} rad/s" in describe(log)
