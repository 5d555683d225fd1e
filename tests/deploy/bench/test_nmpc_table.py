"""The bench nmpc table: ratios against the same run's rows."""

from __future__ import annotations

from deploy.bench.nmpc import BenchRow, format_table


def _row(mode: str, solver: str, update_ms: float, local_ms: float | None) -> BenchRow:
    times = {"mean": update_ms, "std": 0.0, "median": update_ms, "p95": update_ms}
    local = None if local_ms is None else {**times, "median": local_ms}
    return BenchRow(mode, 2, solver, 408, 5.0, times, times, local, 1.0, 0.0)


def test_generic_kernel_row_gives_the_same_run_cost_ratio() -> None:
    rows = [_row("centralized", "fatrop", 20.0, None),
            _row("distributed", "fatrop", 10.0, 4.0),
            _row("distributed", "fatrop/generic-blas", 30.0, 12.0),
            _row("distributed", "ipopt-reference", 100.0, 40.0)]
    lines = format_table(rows).splitlines()
    fast = next(line for line in lines if " fatrop " in line and "distributed" in line)
    assert fast.split()[-3:] == ["0.50", "10.0x", "3.00x"]  # dist/cent, ref/this, generic/this
    generic = next(line for line in lines if "generic-blas" in line)
    assert generic.split()[-1] == "3.3x"  # ref/this only: it is the baseline itself
    assert "generic/this" in lines[0]
