"""``porter bench sim``: real-time factor, WBC tick and NMPC update times of scenarios in the
MuJoCo loop, measured in one run, as a table (and JSON).

Each scenario runs for ``duration_s`` simulated seconds (the lockstep loop is not paced, so the
real-time factor is simulated time / wall time). The wall time is split into NMPC updates, WBC
ticks and the rest (physics, sensor reads, gait, metrics), so the table shows where time goes.
"""

from __future__ import annotations

from core.nmpc.settings import MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun


def bench_scenario(name: str, duration_s: float, executor: str | None, base: MpcSettings,
                   cache: CompiledCodeCache, controller: dict | None = None) -> dict:
    """Run scenario ``name`` for ``duration_s`` and return its summary plus its name;
    ``executor``: None for the scenario's own (``ControllerSpec``: process, serial when
    overlapping); ``controller``: more ``controller`` fields to set (a modelled delay,
    overlapping)."""
    update = dict(controller or {}) | ({} if executor is None else {"executor": executor})
    scenario = load_scenario(name).with_controller(**update)
    scenario = scenario.model_copy(update={"duration_s": min(duration_s, scenario.duration_s)})
    loop = SimRun(scenario, cache, base)
    try:
        summary = loop.run()
    finally:
        loop.close()
    summary["robots"] = len(scenario.team)
    summary["executor"] = scenario.controller.executor
    return summary


def format_table(rows: list[dict]) -> str:
    cells = []
    for row in rows:
        wall = row["wall_s"]
        nmpc = 100 * row["nmpc_wall_s"] / wall
        wbc = 100 * row["wbc_wall_s"] / wall
        cells.append([row["scenario"], str(row["robots"]), f"{row['duration_s']:.1f}",
                      f"{row['real_time_factor']:.2f}", f"{row['wbc_tick_ms']['median']:.3f}",
                      f"{row['wbc_tick_ms']['p95']:.3f}",
                      f"{row['nmpc_update_ms']['median']:.2f}",
                      f"{row['nmpc_update_ms']['p95']:.2f}", str(row["deadline_misses"]),
                      f"{nmpc:.1f}", f"{wbc:.1f}", f"{100 - nmpc - wbc:.1f}"])
    numbers = [Column(name, "right") for name in (
        "n", "sim s", "RTF", "wbc med", "wbc p95", "nmpc med", "nmpc p95", "miss", "nmpc %",
        "wbc %", "rest %")]
    return render_table(["scenario", *numbers], cells, [
        "times in ms per robot WBC tick / per NMPC update; RTF = simulated / wall time; miss = "
        "NMPC updates over 16.7 ms; % = share of the loop's wall time"])
