"""Bad input gets a clear error or a failed-solve status, never a crash or a silent bad plan."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from pydantic import ValidationError

from core.model.obstacles import Obstacle
from core.model.team_settings import AgentSettings, TeamSettings
from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.mpc_inputs import InvalidMpcInputError
from tests.core.controller_fixtures import inputs_at_start, settings, team


@pytest.fixture(scope="module")
def controller() -> CentralizedMpc:
    return CentralizedMpc(team(), settings())


def test_wrong_shape_names_the_field(controller: CentralizedMpc) -> None:
    inputs = inputs_at_start(controller.team, controller.settings)
    bad = dataclasses.replace(inputs, robot_states=inputs.robot_states[:, :6])
    with pytest.raises(InvalidMpcInputError, match="robot_states: expected shape"):
        controller.update(bad)


def test_nan_in_state_is_rejected(controller: CentralizedMpc) -> None:
    inputs = inputs_at_start(controller.team, controller.settings)
    state = inputs.payload_state.copy()
    state[4] = np.nan
    with pytest.raises(InvalidMpcInputError, match="payload_state: contains NaN"):
        controller.update(dataclasses.replace(inputs, payload_state=state))


def test_too_many_obstacles_is_rejected(controller: CentralizedMpc) -> None:
    inputs = inputs_at_start(controller.team, controller.settings)
    rows = np.tile([9.0, 9.0, 0, 0, 0.6], (controller.settings.safety.max_obstacles + 1, 1))
    with pytest.raises(InvalidMpcInputError, match="max_obstacles"):
        controller.update(dataclasses.replace(inputs, obstacles=rows))


def test_start_inside_safety_margin_is_flagged_not_a_failed_solve(
        controller: CentralizedMpc) -> None:
    controller.reset()
    inputs = inputs_at_start(controller.team, controller.settings, [Obstacle((0.0, 0.3))])
    plan = controller.update(inputs)
    assert plan.start_inside_margin and plan.flagged
    assert plan.success == all(s.success for s in plan.solves)
    assert any("inside safety margin" in w and "payload" in w for w in plan.warnings)
    assert np.all(np.isfinite(plan.grf))


def test_unknown_robot_type_names_the_field() -> None:
    with pytest.raises(ValidationError, match="robot_type") as error:
        TeamSettings(agents=[AgentSettings(name="a", robot_type="spot",
                                           coupling_point_in_payload_m=(0.5, 0, 0))])
    assert "go2" in str(error.value) and "a1" in str(error.value)


def test_failed_solve_is_reported_not_raised() -> None:
    # One iteration cannot converge from a cold start: the plan must come back flagged.
    model = team()
    mpc = settings(solver=settings().solver.model_copy(update={"max_iterations": 1}))
    plan = CentralizedMpc(model, mpc).update(inputs_at_start(model, mpc))
    assert not plan.success
    assert not plan.solves[0].success
    assert np.all(np.isfinite(plan.grf))


def test_the_problem_validates_unless_told_its_caller_did(controller: CentralizedMpc) -> None:
    # the controllers validate once and tell the problem so; a direct caller is still checked
    inputs = inputs_at_start(controller.team, controller.settings)
    state = inputs.payload_state.copy()
    state[0] = np.inf
    bad = dataclasses.replace(inputs, payload_state=state)
    problem = controller.problem
    with pytest.raises(InvalidMpcInputError, match="payload_state: contains NaN or infinite"):
        problem.select_obstacles(bad)
    with pytest.raises(InvalidMpcInputError, match="payload_state: contains NaN or infinite"):
        problem.parameter_vector(controller.team, bad)
    with pytest.raises(InvalidMpcInputError, match="payload_state: contains NaN or infinite"):
        problem.validate(bad)
