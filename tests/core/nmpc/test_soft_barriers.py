"""Soft barriers: while the safety constraints are feasible the slack stays zero and the plan is
the hard problem's; when they are not, the solve still succeeds with the least violation and
the plan says so (``MpcPlan.relaxed``)."""

from __future__ import annotations

import numpy as np
import pytest

from core.model.obstacles import Obstacle
from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.settings import SafetySettings, SolverSettings
from tests.core.controller_fixtures import inputs_at_start, settings, team

RTI = SolverSettings(name="rti", compiled=False)


def _mpc(soft: bool) -> tuple[CentralizedMpc, object]:
    mpc_settings = settings(solver=RTI, safety=SafetySettings(soft_barriers=soft,
                                                               max_obstacles=2,
                                                               obstacle_slots=1))
    model = team()
    return CentralizedMpc(model, mpc_settings), mpc_settings


@pytest.mark.parametrize("obstacle", [
    Obstacle(position_m=(1.25, 0.1), radius_m=0.1),  # 7 mm outside the front robot's margin
    Obstacle(position_m=(1.3, 0.0), radius_m=0.1, velocity_m_s=(-0.5, 0.0)),  # closing in
], ids=["static", "moving"])
def test_feasible_barriers_use_no_slack_and_match_the_hard_problem(obstacle: Obstacle) -> None:
    # The barriers are active over the whole horizon (multipliers up to ~5e4 per stage in the
    # scaled problem): the exact penalty must price a violation above them.
    plans, multipliers = {}, []
    for soft in (True, False):
        mpc, mpc_settings = _mpc(soft)
        inputs = inputs_at_start(mpc.team, mpc_settings, [obstacle])
        plans[soft] = mpc.update(inputs)
        lam = mpc.memory().previous[0].constraint_multipliers  # type: ignore[union-attr]
        multipliers.append(max(np.abs(lam[start:start + rows]).sum() for name, (start, rows)
                               in mpc.problem.nlp.constraint_blocks.items()
                               if name.startswith("barriers")))
    assert min(multipliers) > 1e3  # the barriers are active
    soft_plan, hard_plan = plans[True], plans[False]
    assert soft_plan.success and hard_plan.success
    assert soft_plan.barrier_slack_m <= 1e-6
    assert not soft_plan.relaxed and hard_plan.barrier_slack_m == 0.0
    np.testing.assert_allclose(soft_plan.grf, hard_plan.grf, atol=0.05)
    np.testing.assert_allclose(soft_plan.payload_trajectory, hard_plan.payload_trajectory,
                               atol=1e-4)


def test_infeasible_barriers_give_the_least_violating_plan_and_say_so() -> None:
    # An obstacle rushing at the front robot at 4 m/s, just outside its margin: no force the
    # robots can exert keeps every body out of its margin over the horizon.
    model = team()
    front = model.coupling_points_in_payload_m[0][0]
    position = (front + 0.6 + 0.1 + 0.02, 0.0)
    obstacle = Obstacle(position_m=position, radius_m=0.1, velocity_m_s=(-4.0, 0.0))
    plans = {}
    for soft in (True, False):
        mpc, mpc_settings = _mpc(soft)
        inputs = inputs_at_start(mpc.team, mpc_settings, [obstacle])
        plans[soft] = mpc.update(inputs)
    soft_plan, hard_plan = plans[True], plans[False]
    assert soft_plan.success
    assert soft_plan.relaxed and soft_plan.flagged
    assert soft_plan.barrier_slack_m > mpc_settings.safety.slack_tolerance_m
    assert any("safety constraints relaxed" in w for w in soft_plan.warnings)
    # The hard problem has no solution: its solve fails or leaves its constraints violated.
    assert (not hard_plan.success
            or hard_plan.solves[0].constraint_violation > 1e-3), hard_plan.solves[0]


def test_soft_barriers_need_obstacle_slots() -> None:
    mpc_settings = settings(solver=RTI, safety=SafetySettings(max_obstacles=0))
    mpc = CentralizedMpc(team(), mpc_settings)
    assert not mpc.problem.soft_barriers
    assert mpc.update(inputs_at_start(mpc.team, mpc_settings)).barrier_slack_m == 0.0


@pytest.mark.parametrize("field", ["slack_penalty_linear", "slack_penalty_quadratic"])
def test_slack_penalties_must_be_positive(field: str) -> None:
    with pytest.raises(ValueError, match=field):
        SafetySettings(**{field: 0.0})
