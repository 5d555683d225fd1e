"""Centralized NMPC in closed loop on the SRB plant."""

from __future__ import annotations

import numpy as np
import pytest

from core.model.obstacles import Obstacle
from core.nmpc.centralized_mpc import CentralizedMpc
from core.plant.closed_loop import run_closed_loop
from tests.core.controller_fixtures import reference, settings, team


@pytest.mark.slow
def test_closed_loop_follows_reference_and_stays_safe() -> None:
    mpc = settings()
    model = team()
    # The straight reference runs through this obstacle's safety margin: the CBFs must bend it.
    obstacles = [Obstacle((1.0, 0.45))]
    result = run_closed_loop(CentralizedMpc(model, mpc), model, model, mpc, reference(),
                             obstacles, duration_s=4.0)
    min_h = np.min(result.min_h_m)
    assert min_h >= -1e-3
    assert min_h < 0.05  # the barrier was active, not just far away
    final = result.final_payload_state
    assert final is not None
    assert final[0] > 0.9  # carried forward at ~0.3 m/s
    assert abs(final[0] - reference().payload_state(4.0)[0]) < 0.3
    assert np.max(result.coupling_error_m) < 1e-3
    assert all(result.success)


def test_update_reports_solver_figures() -> None:
    from tests.core.controller_fixtures import inputs_at_start

    mpc = settings()
    model = team()
    plan = CentralizedMpc(model, mpc).update(inputs_at_start(model, mpc))
    (stats,) = plan.solves
    assert stats.success and plan.success
    assert stats.iterations > 0 and stats.wall_time_s > 0
    assert np.isfinite(stats.objective)
    assert stats.constraint_violation < 1e-4
    assert plan.grf.shape == (2, 12) and plan.wrench.shape == (2, 6)
    # The team holds the payload up: the wrenches' vertical forces carry its weight.
    weight = model.payload.mass_kg * mpc.gravity_m_s2
    assert plan.wrench[:, 2].sum() == pytest.approx(weight, rel=0.2)
