"""Warm start: multipliers shift with the same stage map as the primal; the guess's forces
follow the contact schedule; plans decode from stacked rows as block by block."""

from __future__ import annotations

import numpy as np
import pytest

from core.nmpc.mpc_plan import decode_plan
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from core.nmpc.transport_problem import TransportProblem, build_transport_problem
from core.nmpc.warm_start import (
    conform_forces,
    nominal_foot_forces,
    shift_blocks,
    shifted_multipliers,
)
from tests.core.controller_fixtures import settings, team


@pytest.fixture(scope="module")
def problem() -> TransportProblem:
    return build_transport_problem(settings(), 2, local=True)


def test_constraint_blocks_cover_every_row_once_in_stage_order(problem: TransportProblem
                                                                 ) -> None:
    blocks = problem.nlp.constraint_blocks
    rows = sorted(blocks.values())
    assert rows[0][0] == 0
    for (start, size), (following, _) in zip(rows[:-1], rows[1:], strict=True):
        assert start + size == following
    assert sum(size for _, size in rows) == problem.nlp.lower_constraints.size
    stages = [int(name.rsplit("@", 1)[1]) for name in blocks]
    assert stages == sorted(stages)  # grouped by stage, as the structured solvers need
    n = problem.horizon_steps
    assert {"gap_robot_self@0", "gap_payload@0", "x0_payload@0", "friction_self@0",
            "coupling_self@0", "barriers@1", f"barriers@{n - 1}"} <= set(blocks)
    assert "barriers@0" not in blocks and "x0_payload@1" not in blocks


def test_multipliers_shift_one_stage_like_the_primal(problem: TransportProblem) -> None:
    nlp = problem.nlp
    n = problem.horizon_steps
    rng = np.random.default_rng(0)
    lam_g = rng.normal(size=nlp.lower_constraints.size)
    lam_x = rng.normal(size=nlp.variable_count)
    stats = SolveStats("ok", True, 1, 0.0, 0.0, 0.0)
    previous = NlpSolution(rng.normal(size=nlp.variable_count), lam_g, lam_x, stats)
    shifted_g, shifted_x = shifted_multipliers(problem, previous)

    def block(values: np.ndarray, name: str) -> np.ndarray:
        start, size = nlp.constraint_blocks[name]
        return values[start : start + size]

    for name in ("gap_payload", "friction_self", "coupling_self", "yaw_torque_1"):
        for k in range(n - 1):
            np.testing.assert_array_equal(block(shifted_g, f"{name}@{k}"),
                                          block(lam_g, f"{name}@{k + 1}"))
        np.testing.assert_array_equal(block(shifted_g, f"{name}@{n - 1}"),
                                      block(lam_g, f"{name}@{n - 1}"))  # last one repeated
    for k in range(1, n - 1):
        np.testing.assert_array_equal(block(shifted_g, f"barriers@{k}"),
                                      block(lam_g, f"barriers@{k + 1}"))
    # the initial condition exists at stage 0 only: its multiplier stays
    np.testing.assert_array_equal(block(shifted_g, "x0_payload@0"), block(lam_g, "x0_payload@0"))
    # bound multipliers live on the decision layout: exactly the primal's shift
    np.testing.assert_array_equal(shifted_x, shift_blocks(nlp.decision.offsets, lam_x))
    np.testing.assert_array_equal(nlp.decision.get(shifted_x, "grf_self@0"),
                                  nlp.decision.get(lam_x, "grf_self@1"))


def _conform_stage_by_stage(guess: np.ndarray, problem: TransportProblem, contacts: np.ndarray,
                            mass_kg: float, g: float) -> None:
    """The rule per stage and leg, as written down (the reference)."""
    layout = problem.nlp.decision
    for k, flags in enumerate(contacts):
        block = layout.slice(f"grf_self@{k}")
        forces = guess[block].reshape(4, 3)
        nominal = nominal_foot_forces(flags, mass_kg, g).reshape(4, 3)
        for leg in range(4):
            if flags[leg] == 0.0:
                forces[leg] = 0.0
            elif forces[leg, 2] < 1.0:
                forces[leg] = nominal[leg]
        guess[block] = forces.reshape(-1)


def test_forces_conform_to_the_schedule_as_stage_by_stage(problem: TransportProblem) -> None:
    rng = np.random.default_rng(3)
    n, layout = problem.horizon_steps, problem.nlp.decision
    for trial in range(50):
        guess = rng.normal(scale=40.0, size=layout.size)
        guess[rng.random(layout.size) < 0.05] = np.nan  # NaN forces stay as they are
        contacts = (rng.random((n, 4)) < 0.6).astype(float)
        contacts[trial % n] = 0.0  # a stage with every foot in the air
        expected = guess.copy()
        _conform_stage_by_stage(expected, problem, contacts, 17.3, 9.81)
        conform_forces(guess, layout, "grf_self", contacts, 17.3, 9.81)
        np.testing.assert_array_equal(guess, expected)


def test_plans_decode_from_stacked_rows_as_block_by_block(problem: TransportProblem) -> None:
    decision = np.random.default_rng(5).normal(size=problem.nlp.decision.size)
    layout, n = problem.nlp.decision, problem.horizon_steps
    plan = decode_plan(problem, team(), decision, agent=1)
    for k in range(n + 1):
        assert np.array_equal(plan.robot_trajectories[1, k], layout.get(decision, f"robot_self@{k}"))
        assert np.array_equal(plan.payload_trajectory[k], layout.get(decision, f"payload@{k}"))
    for k in range(n):
        assert np.array_equal(plan.grf_trajectories[1, k], layout.get(decision, f"grf_self@{k}"))
        for j in range(2):
            assert np.array_equal(plan.wrench_trajectories[j, k],
                                  layout.get(decision, f"wrench_{j}@{k}"))
    assert not plan.robot_trajectories[0].any()  # agent 0's trajectory is not in this problem
