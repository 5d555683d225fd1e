"""How a run ended, from its summary: goal, time out, controlled stop, safe stop, falls."""

from __future__ import annotations

import pytest

from deploy.runtime.run_metrics import run_outcome


def _summary(reached: bool = False, falls: int = 0, safe_stop: str | None = None,
             controlled: bool = False) -> dict:
    return {"reached_goal": reached, "falls": falls,
            "safety": {"safe_stop": safe_stop, "controlled_stop": controlled}}


@pytest.mark.parametrize(("summary", "expected"), [
    (_summary(reached=True), "goal"),
    (_summary(), "time out"),
    (_summary(controlled=True), "controlled stop"),
    (_summary(safe_stop="joint velocity", falls=2), "safe stop, 2 fell"),
    # a fault during the controlled stop is a safe stop; a fall is said whatever the end
    (_summary(safe_stop="tilt", controlled=True), "safe stop"),
    (_summary(reached=True, falls=1), "goal, 1 fell"),
])
def test_outcome_names_how_the_run_ended(summary: dict, expected: str) -> None:
    assert run_outcome(summary) == expected


def test_grf_smoothness_counts_feet_in_stance_in_both_updates_only() -> None:
    import numpy as np

    from deploy.runtime.run_metrics import _stance_change_n

    before = np.zeros((1, 12))
    before[0, 2] = before[0, 5] = 40.0  # feet 0 and 1 loaded, feet 2 and 3 in swing
    now = before.copy()
    now[0, 2] = 43.0  # foot 0: +3 N
    now[0, 8] = 80.0  # foot 2 touches down: the gait's, not a jump
    now[0, 5] = 0.0  # foot 1 lifts off
    # one foot in stance in both, three components: sqrt(3^2 / 3)
    assert _stance_change_n(before, now) == pytest.approx(np.sqrt(3.0))
    assert _stance_change_n(None, now) == 0.0  # the first update
    assert _stance_change_n(np.zeros((1, 12)), now) == 0.0  # no foot loaded in both
