"""``porter bench wbc``: the work of the 500 Hz WBC tick (both robots' ``wbc_steps``: gait,
targets, Pinocchio, QP) back to back and paced, as a table (and JSON).

The same ticks on the same plan and measurements cost different wall time depending on what
the core did in between: back to back the interpreter and the CPU's caches and predictors stay
warm; paced at 2 ms (the deploy loop at real time) or 20 ms (the loop at time scale 0.1) they
do not. The table shows that factor, which every per-stage figure of ``porter bench deploy``
carries.
"""

from __future__ import annotations

import time

import numpy as np

from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun

__all__ = ["PACES_S", "format_table", "run_bench"]

PACES_S = (0.0, 0.002, 0.02)  # back to back; the loop at real time; at time scale 0.1


def run_bench(ticks: int, scenario_name: str = "two_go2",
              cache: CompiledCodeCache | None = None) -> list[dict]:
    """One row per pace: ``ticks`` WBC ticks of ``scenario_name``'s team (its first plan,
    the standing measurements), work per tick [ms wall] and the ratio to back to back."""
    scenario = load_scenario(scenario_name)
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, cache or CompiledCodeCache())
    try:
        control = run.control
        measurements = [run.links.drivers[name].read() for name in control.robot_names]
        control.reset(measurements, start_s=0.0)
        frame = run.simulation.mocap().latest()
        assert frame is not None  # the simulation's MoCap always has a frame
        decision = control.nmpc_inputs(0.0, measurements, frame)
        plan = control.update(decision)
        rows = []
        for pace_s in PACES_S:
            work_s = []
            next_s = time.perf_counter()
            for tick in range(ticks):
                t = 0.5 + 0.002 * tick  # walking: the gait lifts feet
                start = time.perf_counter()
                control.wbc_steps(t, plan, 0.5, measurements)
                work_s.append(time.perf_counter() - start)
                if pace_s:
                    next_s += pace_s
                    time.sleep(max(0.0, next_s - time.perf_counter()))
            ms = np.asarray(work_s[ticks // 10:]) * 1e3  # the first tenth warms up
            rows.append({"pace_ms": pace_s * 1e3, "ticks": ticks, "robots": len(measurements),
                         "median_ms": float(np.median(ms)),
                         "p99_ms": float(np.percentile(ms, 99))})
    finally:
        run.close()
    for row in rows:
        row["ratio"] = row["median_ms"] / rows[0]["median_ms"]
    return rows


def format_table(rows: list[dict]) -> str:
    cells = [["back to back" if not row["pace_ms"] else f"every {row['pace_ms']:g} ms",
              str(row["ticks"]), str(row["robots"]), f"{row['median_ms']:.3f}",
              f"{row['p99_ms']:.3f}", f"{row['ratio']:.2f}"] for row in rows]
    return render_table([Column(name, "right") for name in (
        "pace", "ticks", "robots", "median ms", "p99 ms", "ratio")], cells,
        ["work of one WBC tick (every robot's wbc_steps), wall ms; ratio = median / "
         "back-to-back median"])

