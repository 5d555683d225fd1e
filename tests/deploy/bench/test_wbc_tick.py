"""``porter bench wbc``: real WBC ticks of the two-Go2 team, one row per pace, consistent."""

from __future__ import annotations

from deploy.bench.wbc_tick import PACES_S, format_table, run_bench


def test_every_pace_measures_real_ticks_of_both_robots() -> None:
    rows = run_bench(ticks=40)
    assert [row["pace_ms"] for row in rows] == [p * 1e3 for p in PACES_S]
    for row in rows:
        assert row["ticks"] == 40 and row["robots"] == 2
        # two QPs, two Pinocchio passes and the gait cost something, and far less than a tick
        # of the slowest pace; the p99 of 40 ticks is their slowest, which a busy machine may
        # deschedule (a wall-clock bound there would test the machine)
        assert 0.01 < row["median_ms"] < 20.0 and row["median_ms"] <= row["p99_ms"]
    assert rows[0]["ratio"] == 1.0
    assert rows[1]["ratio"] == rows[1]["median_ms"] / rows[0]["median_ms"]
    table = format_table(rows)
    assert "back to back" in table and "every 20 ms" in table
