"""Porter's own sim faults are due on the world's time line, not from porter's later start-up."""

from __future__ import annotations

import time

from deploy.config.deploy_config import SimFault, load_deploy_config
from deploy.sim_backend.backend import SimBackend
from deploy.sim_backend.porter_faults import PorterFaults


class _Clock:
    def __init__(self, now_s: float) -> None:
        self.now_s = now_s

    def __call__(self) -> float:
        return self.now_s


def test_a_fault_is_due_at_s_after_the_worlds_start_not_after_porters_first_look() -> None:
    clock = _Clock(100.3)  # porter looks 0.3 s after the world started at 100.0
    faults = PorterFaults([SimFault(at_s=2.5, kind="nmpc_failure")], clock, start_s=100.0)
    clock.now_s = 102.49
    assert not faults.active("nmpc_failure")
    clock.now_s = 102.5
    assert faults.active("nmpc_failure")  # counted from porter's first look: only at 102.8
    assert not faults.active("loop_stall")  # not configured
    own = PorterFaults([SimFault(at_s=2.5, kind="nmpc_failure")], _Clock(100.3))
    assert own.start_s == 100.3  # without the world's start: the first look


def test_the_backend_reports_the_worlds_start_on_its_clock() -> None:
    config, scenario = load_deploy_config("two_go2")
    before_s = config.sim.time_scale * time.monotonic()
    backend = SimBackend(config, scenario)
    try:
        after_s = backend.clock()
        assert before_s <= backend.start_s <= after_s
    finally:
        backend.close()
