"""The bench nmpc table: ratios against the same run's rows."""

from __future__ import annotations

from deploy.bench.nmpc import BenchRow, format_table


def _row(mode: str, solver: str, update_ms: float, local_ms: float | None) -> BenchRow:
    times = {"mean": update_ms, "std": 0.0, "median": update_ms, "p95": update_ms}
    local = None if local_ms is None else {**times, "median": local_ms}
    return BenchRow(mode, 2, solver, 408, 5.0, times, times, local, 1.0, 0.0)


def test_todays_path_row_gives_the_same_run_cost_ratios() -> None:
    rows = [_row("centralized", "fatrop", 20.0, None),
            _row("distributed", "fatrop", 10.0, 4.0),
            _row("distributed", "fatrop/generic-blas", 30.0, 12.0),
            _row("centralized", "rti", 8.0, None),
            _row("distributed", "rti", 4.0, 2.0),
            _row("distributed", "ipopt-reference", 100.0, 40.0)]
    lines = format_table(rows).splitlines()
    fast = next(line for line in lines if " fatrop " in line and "distributed" in line)
    assert fast.split()[-3:] == ["0.50", "10.0x", "3.00x"]  # dist/cent, ref/this, today/this
    rti = next(line for line in lines if " rti " in line and "distributed" in line)
    assert rti.split()[-3:] == ["0.50", "20.0x", "6.00x"]  # against its own centralized row
    generic = next(line for line in lines if "generic-blas" in line)
    assert generic.split()[-1] == "3.3x"  # ref/this only: it is the baseline itself
    assert "today/this" in lines[0]
