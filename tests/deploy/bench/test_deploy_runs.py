"""``porter bench deploy``'s completion count and world-hold column, from rows of the form
``deploy_row`` gives (the row itself is checked on a real run in tests/deploy/cli)."""

from __future__ import annotations

from typing import Any

from deploy.bench.deploy_runs import completion, format_table


def row(outcome: str, holds: int | None, time_scale: float = 1.0) -> dict[str, Any]:
    loop = {"rate_hz": 500.0, "jitter_p50_ms": 0.1, "jitter_p99_ms": 0.5, "busy_p50_ms": 0.9,
            "busy_p99_ms": 1.5}
    return {"config": "two_go2", "time_scale": time_scale, "loop_priority": None,
            "outcome": outcome, "run_s": 10.0, "wbc": loop, "nmpc": loop,
            "wbc_rate_ratio": 1.0, "nmpc_rate_ratio": 1.0, "nmpc_deadline_misses": 0,
            "world_holds": None if holds is None else {"over_4_ms": holds, "longest_s": 0.01}}


def test_completion_counts_runs_completed_and_runs_the_world_held() -> None:
    rows = [row("completed", 0), row("safe stop: joint speed", 12), row("completed", 3),
            row("completed", 0, time_scale=0.5)]
    groups = completion(rows)
    assert groups == [
        {"config": "two_go2", "time_scale": 1.0, "loop_priority": None, "runs": 3,
         "completed": 2, "world_held": 2},
        {"config": "two_go2", "time_scale": 0.5, "loop_priority": None, "runs": 1,
         "completed": 1, "world_held": 0}]
    table = format_table(rows)
    assert "two_go2 at 1: 2 of 3 runs completed, 2 with world holds > 4 ms" in table
    assert "two_go2 at 0.5: 1 of 1 runs completed, 0 with world holds > 4 ms" in table
    assert "holds>4ms" in table
    lines = [line for line in table.splitlines() if "joint speed" in line]
    assert len(lines) == 1 and " 12 " in lines[0]


def test_a_run_without_world_holds_shows_a_dash() -> None:
    table = format_table([row("completed", None)])
    assert "1 of 1 runs completed, 0 with world holds" in table
