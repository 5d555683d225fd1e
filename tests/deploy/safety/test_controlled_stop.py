"""A controlled stop (the braking backup's end): a sit-down with its cause, no fault."""

from __future__ import annotations

import numpy as np

from deploy.safety.supervisor import SafetyState as S
from deploy.safety.supervisor import Transition
from drivers.interfaces import JointCommand
from tests.deploy.safety.test_supervisor import (
    _supervisor_in,
)


def test_a_controlled_stop_sits_down_with_its_cause_and_is_no_fault(limits, standing):
    log: list[Transition] = []
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing, log=log)
    cause = "controlled stop: braking since 3.000 s (braking: 3 infeasible NMPC plans in a row)"
    supervisor.begin_sit_down(time_s, cause)
    assert log[-1] == Transition(time_s, S.RUNNING, S.SITTING_DOWN, cause)
    assert supervisor.fault == "" and supervisor.state == S.SITTING_DOWN
    # the sit-down posture's commands pass; only a later fault damps
    commands = {name: JointCommand(kp=np.full(12, 20.0), kd=np.full(12, 1.0),
                                   position_rad=standing[name].position_rad)
                for name in supervisor.limits}
    assert supervisor.filter_commands(time_s, commands, standing) == commands
    supervisor.finish(time_s + 2.0)
    assert supervisor.state == S.DONE and supervisor.fault == ""
