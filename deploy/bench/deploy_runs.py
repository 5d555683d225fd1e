"""``porter bench deploy``: loop timing of ``porter deploy --backend sim`` per time scale.

Each run is ``porter deploy --config C --backend sim --yes --duration D --no-record`` in a
process of its own, with the config's ``sim.time_scale`` replaced; the row comes from the
summary it prints: outcome, WBC (500 Hz) and NMPC (60 Hz) loop rate and its ratio to the
nominal one, period jitter |period - nominal| p50 / p99, the work per WBC tick and the NMPC
update time. Rates and times are in simulated seconds (the loop's clock runs at the time
scale), so rows at different scales compare directly. Two more tables per run: the CPU budget
(CPU-seconds per simulated second over RUNNING for porter's loop process, each ADMM worker
and the world process) and the work of one 500 Hz tick split into its stages (wall time,
both robots, median and p99).
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import yaml

from deploy.config.deploy_config import config_path
from deploy.reports.table import Column, render_table

RUN_TIMEOUT_S = 900.0


CONFIGURED = "configured"  # a loop priority left as the config has it


def scaled_config(config: Path | str, time_scale: float, directory: Path,
                  loop_priority: int | None | str = CONFIGURED) -> Path:
    """A copy of deploy config ``config`` (path or shipped name) in ``directory`` with
    ``sim.time_scale`` = ``time_scale`` and, unless ``CONFIGURED``, ``rates.loop_priority`` =
    ``loop_priority``; a relative scenario file path is made absolute."""
    source = config_path(config)
    data = yaml.safe_load(source.read_text())
    scenario = Path(str(data.get("scenario", "")))
    if scenario.suffix in (".yaml", ".yml") and not scenario.is_absolute() \
            and (source.parent / scenario).exists():
        data["scenario"] = str((source.parent / scenario).resolve())
    data["sim"] = {**(data.get("sim") or {}), "time_scale": time_scale}
    if loop_priority != CONFIGURED:
        data["rates"] = {**(data.get("rates") or {}), "loop_priority": loop_priority}
        if loop_priority is None:  # the world's priority must stay below the loop's: none
            data["sim"]["world_priority"] = None
    path = directory / f"{source.stem}-x{time_scale:g}-p{loop_priority}.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def run_once(config: Path, duration_s: float) -> dict[str, Any]:
    """The summary of one ``porter deploy --backend sim`` run (its stdout JSON)."""
    completed = subprocess.run(
        [sys.executable, "-m", "deploy.cli", "deploy", "--config", str(config), "--backend",
         "sim", "--yes", "--duration", f"{duration_s:g}", "--no-record"],
        capture_output=True, text=True, timeout=RUN_TIMEOUT_S, check=False)
    try:
        summary: dict[str, Any] = json.loads(completed.stdout)
    except json.JSONDecodeError:
        raise RuntimeError(f"porter bench deploy: the run printed no summary (exit "
                           f"{completed.returncode}):\n{completed.stderr[-2000:]}") from None
    summary["exit_code"] = completed.returncode
    return summary


def deploy_row(summary: dict[str, Any]) -> dict[str, Any]:
    """One table row from a ``porter deploy`` summary."""
    wbc, nmpc = summary["wbc_loop"], summary["nmpc_loop"]

    def ratio(loop: dict[str, Any]) -> float | None:
        rate, nominal = loop.get("rate_hz"), loop.get("nominal_hz")
        return rate / nominal if rate and nominal else None
    outcome = ("completed" if summary["safe_stop"] is None and summary["final_state"] == "DONE"
               else f"safe stop: {summary['safe_stop']}" if summary["safe_stop"]
               else summary["result"])
    return {"config": Path(str(summary["config"])).stem, "time_scale": summary["time_scale"],
            "loop_priority": summary.get("loop_priority"),
            "outcome": outcome, "exit_code": summary.get("exit_code"),
            "run_s": summary["run_s"], "wbc": wbc, "nmpc": nmpc,
            "wbc_rate_ratio": ratio(wbc), "nmpc_rate_ratio": ratio(nmpc),
            "nmpc_deadline_misses": summary["nmpc_deadline_misses"],
            "wbc_overruns": summary["wbc_overruns"],
            "progress_toward_goal_m": summary["payload"]["progress_toward_goal_m"],
            "cpu_per_running_s": summary.get("cpu_per_running_s", {}),
            "tick_stages_wall": summary.get("tick_stages_wall", {}),
            "gc_pauses": summary.get("gc_pauses", {}),
            "world_holds": (summary.get("sim_ground_truth") or {}).get("holds")}


def run_bench(config: str, time_scales: list[float], runs: int, duration_s: float,
              loop_priorities: list[int | None | str] | None = None) -> list[dict[str, Any]]:
    """Rows for every time scale x loop priority (default: the config's) x run, in that
    order; runs of one scale alternate the priorities (pairs of one sitting)."""
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for time_scale in time_scales:
            scaled = [scaled_config(config, time_scale, Path(directory), priority)
                      for priority in (loop_priorities or [CONFIGURED])]
            for _ in range(runs):
                for path in scaled:
                    row = deploy_row(run_once(path, duration_s))
                    row["config"] = config_path(config).stem  # not the scaled copy's name
                    rows.append(row)
    return rows


def _number(value: float | None, digits: int) -> str:
    return "-" if value is None else f"{value:.{digits}f}"


def format_table(rows: list[dict[str, Any]]) -> str:
    cells = []
    for row in rows:
        wbc, nmpc = row["wbc"], row["nmpc"]
        cells.append([
            row["config"], f"{row['time_scale']:.2f}",
            "-" if row.get("loop_priority") is None else str(row["loop_priority"]),
            _number(row["run_s"], 1),
            _number(wbc.get("rate_hz"), 0), _number(row["wbc_rate_ratio"], 2),
            _number(wbc.get("jitter_p50_ms"), 3), _number(wbc.get("jitter_p99_ms"), 3),
            _number(wbc.get("busy_p50_ms"), 3), _number(nmpc.get("rate_hz"), 1),
            _number(row["nmpc_rate_ratio"], 2), _number(nmpc.get("jitter_p50_ms"), 2),
            _number(nmpc.get("jitter_p99_ms"), 2), _number(nmpc.get("busy_p50_ms"), 1),
            _number(nmpc.get("busy_p99_ms"), 1), str(row["nmpc_deadline_misses"]),
            _holds_over_4ms(row), row["outcome"]])
    numbers = [Column(name, "right") for name in (
        "scale", "prio", "run s", "wbc Hz", "ratio", "jit p50", "jit p99", "busy p50", "nmpc Hz",
        "ratio", "jit p50", "jit p99", "upd p50", "upd p99", "miss", "holds>4ms")]
    table = render_table(["config", *numbers, "outcome"], cells, [
        "ms and Hz in simulated time; prio = the loop thread's SCHED_FIFO priority (-: normal "
        "scheduling); ratio = achieved / nominal rate; jit = |period - nominal|; busy = work "
        "per WBC tick; upd = NMPC update time; miss = updates over 1/60 s; holds>4ms = the "
        "world's states held longer than 4 ms (a run with any measured the machine, not "
        "porter)"])
    lines = [f"{s['config']} at {s['time_scale']:g}: {s['completed']} of {s['runs']} runs "
             f"completed, {s['world_held']} with world holds > 4 ms" for s in completion(rows)]
    return "\n".join([table, *lines])


def completion(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Per config, time scale and loop priority: how many runs completed (safe stop none,
    DONE), of how many, and in how many the world held a state longer than 4 ms."""
    groups: dict[tuple[Any, ...], dict[str, Any]] = {}
    for row in rows:
        key = (row["config"], row["time_scale"], row.get("loop_priority"))
        group = groups.setdefault(key, {"config": key[0], "time_scale": key[1],
                                        "loop_priority": key[2], "runs": 0, "completed": 0,
                                        "world_held": 0})
        group["runs"] += 1
        group["completed"] += row["outcome"] == "completed"
        group["world_held"] += bool((row.get("world_holds") or {}).get("over_4_ms"))
    return list(groups.values())


STAGES = ("read", "estimate", "nmpc", "check", "control", "filter", "send", "record", "total")


def _gc_cell(row: dict[str, Any]) -> str:
    pauses = row.get("gc_pauses") or {}
    if not pauses:
        return "-"
    counts = "/".join(str(pauses.get(f"gen{g}", {}).get("collections", 0)) for g in range(3))
    longest = max(float(p.get("max_ms", 0.0)) for p in pauses.values())
    return f"{counts} {longest:.2f}"


def _holds_over_4ms(row: dict[str, Any]) -> str:
    holds = row.get("world_holds")
    return "-" if not holds else str(holds["over_4_ms"])


def _holds_cell(row: dict[str, Any]) -> str:
    holds = row.get("world_holds")
    if not holds:
        return "-"
    return f"{holds['over_4_ms']} {1e3 * holds['longest_s']:.0f}"


def format_budget(rows: list[dict[str, Any]]) -> str:
    """CPU-s per simulated second by process, and the tick's stages [ms wall, p50 / p99]."""
    cpu_cells = []
    for row in rows:
        cpu = row.get("cpu_per_running_s") or {}
        workers = sum(v for k, v in cpu.items() if k.startswith("porter-admm"))
        nmpc = cpu.get("porter-nmpc", 0.0 if cpu else None)
        cpu_cells.append([row["config"], f"{row['time_scale']:.2f}", _number(cpu.get("porter"), 2),
                          _number(nmpc, 2), _number(workers if cpu else None, 2),
                          _number(cpu.get("porter-sim-world"), 2),
                          _number(sum(cpu.values()) if cpu else None, 2), _gc_cell(row),
                          _holds_cell(row)])
    cpu_table = render_table(
        ["config", *(Column(name, "right") for name in (
            "scale", "porter", "nmpc", "workers", "world", "total", "loop gc",
            "world holds"))], cpu_cells,
        ["CPU-s per simulated s over RUNNING (porter: the loop's process; nmpc: its process; "
         "workers: the ADMM workers, summed); loop gc: the loop's collections over the whole "
         "run, gen0/gen1/gen2 count, and the longest pause [ms wall]; world holds: the sim "
         "world's late cycles, stepping on its last commands with no state sent, over two state "
         "periods (count) and the longest [simulated ms]"])
    stage_cells = []
    for row in rows:
        stages = row.get("tick_stages_wall") or {}
        stage_cells.append([row["config"], f"{row['time_scale']:.2f}", *(
            f"{stages[s]['p50_ms']:.3f}/{stages[s]['p99_ms']:.3f}"
            if isinstance(stages.get(s), dict) else "-" for s in STAGES)])
    stage_table = render_table(
        ["config", Column("scale", "right"), *(Column(s, "right") for s in STAGES)],
        stage_cells, ["tick stages: wall ms per 500 Hz tick while RUNNING, both robots, p50/p99"])
    return f"{cpu_table}\n\n{stage_table}"
