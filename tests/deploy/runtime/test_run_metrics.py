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
