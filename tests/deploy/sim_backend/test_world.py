"""The sim world's holds: a world process that stops for a while steps its physics on the last
commands when it resumes, and its ground truth says so (the longest hold, the count)."""

from __future__ import annotations

import contextlib
import os
import signal
import time

from deploy.config.deploy_config import load_deploy_config
from deploy.sim_backend.backend import SimBackend
from deploy.sim_backend.world import MAX_CATCH_UP_STEPS
from tests.deploy.deploy_fixtures import TEST_TIME_SCALE


def test_a_stalled_world_reports_its_hold() -> None:
    config, scenario = load_deploy_config("two_go2")
    config = config.model_copy(update={"sim": config.sim.model_copy(
        update={"time_scale": TEST_TIME_SCALE})})
    scale = config.sim.time_scale
    backend = SimBackend(config, scenario)
    try:
        assert backend.pid is not None
        time.sleep(0.2)
        before = backend.ground_truth()
        assert before is not None and before["physics_steps"] > 0
        stall_wall_s = 0.06  # 12 simulated ms at 0.2: three state periods
        os.kill(backend.pid, signal.SIGSTOP)
        time.sleep(stall_wall_s)
        os.kill(backend.pid, signal.SIGCONT)
        time.sleep(0.1)
        after = backend.ground_truth()
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.kill(backend.pid, signal.SIGCONT)  # whatever happened above
        backend.close()
    assert after is not None
    holds = after["holds"]
    assert holds["over_4_ms"] >= before["holds"]["over_4_ms"] + 1
    # at least the stall (less a cycle's sleep), at most the catch-up cap
    step_s = 1.0 / 1000.0
    assert stall_wall_s * scale - 2 * step_s <= holds["longest_s"] <= MAX_CATCH_UP_STEPS * step_s
