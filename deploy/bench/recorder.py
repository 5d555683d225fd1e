"""``porter bench recorder``: what the flight recorder costs the loop, how much it writes, and
whether a long run grows the process.

1. The same scenario (deterministic: identical work) with and without the recorder, alternated
   ``repeats`` times: wall time per simulated second, loop tick (2 ms of simulated time) median
   and p95, and their ratios recorder-on / recorder-off.
2. Messages per simulated and per wall second, log size per simulated minute.
3. Memory: one simulated second of the run's real messages fed again and again through a
   recorder (to ``/dev/null``: the file is irrelevant to the process's memory) for
   ``memory_minutes`` simulated minutes, as fast as the writer drains them; resident set size
   sampled every simulated minute.
"""

from __future__ import annotations

import os
import statistics
import tempfile
import time
from pathlib import Path
from typing import Any

import psutil

from core.nmpc.settings import MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.recording.flight_recorder import FlightRecorder, RecorderSettings
from deploy.recording.log_format import LOG_FORMAT_VERSION, RUN_METADATA
from deploy.recording.run_record import open_run_recorder
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun


def _run(name: str, duration_s: float, executor: str, base: MpcSettings,
         cache: CompiledCodeCache, log: Path | None, capture: list | None = None) -> dict:
    scenario = load_scenario(name)
    scenario = scenario.model_copy(update={
        "duration_s": min(duration_s, scenario.duration_s),
        "controller": scenario.controller.model_copy(update={"executor": executor})})
    loop = SimRun(scenario, cache, base)
    recorder = None
    if log is not None:
        sinks = [] if capture is None else [
            lambda topic, message, t: capture.append((topic, message, t))
            if t <= 1_000_000_000 else None]
        recorder = open_run_recorder(log, scenario, loop.settings, loop.wbc_settings, "mujoco",
                                     sinks=sinks, blas_kernels=cache.blas_kernels().target)
        loop.attach_recorder(recorder)
    try:
        summary = loop.run()
    finally:
        loop.close()
        if recorder is not None:
            recorder.close(summary)
    summary["recorder"] = None if recorder is None else {
        "messages": recorder.written, "dropped": recorder.dropped,
        "bytes": log.stat().st_size if log else 0}
    return summary


def bench_overhead(name: str, duration_s: float, repeats: int, executor: str,
                   base: MpcSettings, cache: CompiledCodeCache) -> tuple[list[dict], list]:
    """Rows for recorder off and on (medians over ``repeats`` alternated runs) and one
    simulated second of recorded messages."""
    runs: dict[str, list[dict]] = {"off": [], "on": []}
    capture: list = []
    with tempfile.TemporaryDirectory() as directory:
        for repeat in range(repeats):
            for mode in ("off", "on"):
                log = Path(directory) / f"run{repeat}.mcap" if mode == "on" else None
                runs[mode].append(_run(name, duration_s, executor, base, cache, log,
                                       capture if (mode == "on" and repeat == 0) else None))
    rows = []
    for mode, summaries in runs.items():
        simulated = summaries[0]["duration_s"]
        wall = statistics.median(s["wall_s"] for s in summaries)
        row: dict[str, Any] = {
            "recorder": mode, "runs": len(summaries), "sim_s": simulated,
            "wall_per_sim_s": wall / simulated,
            "tick_median_ms": statistics.median(s["loop_tick_ms"]["median"] for s in summaries),
            "tick_p95_ms": statistics.median(s["loop_tick_ms"]["p95"] for s in summaries)}
        if mode == "on":
            recorded = summaries[0]["recorder"]
            row |= {"messages": recorded["messages"], "dropped": recorded["dropped"],
                    "messages_per_sim_s": recorded["messages"] / simulated,
                    "messages_per_wall_s": recorded["messages"] / wall,
                    "mb_per_sim_min": recorded["bytes"] / simulated * 60 / 1e6}
        rows.append(row)
    off, on = rows
    on["wall_ratio"] = on["wall_per_sim_s"] / off["wall_per_sim_s"]
    on["tick_median_ratio"] = on["tick_median_ms"] / off["tick_median_ms"]
    on["tick_p95_ratio"] = on["tick_p95_ms"] / off["tick_p95_ms"]
    return rows, capture


def bench_memory(messages: list, minutes: float) -> dict:
    """Feed the captured window of messages (up to one simulated second) again and again, time
    shifted, for ``minutes`` simulated minutes; RSS sampled every simulated minute [MB]."""
    process = psutil.Process(os.getpid())
    recorder = FlightRecorder(os.devnull, RecorderSettings(),
                              {RUN_METADATA: {"log_format_version": str(LOG_FORMAT_VERSION)}})
    window_ns = max(t for _, _, t in messages) + 2_000_000  # one 2 ms tick past the last
    total_ns = int(minutes * 60e9)
    rss_mb = [process.memory_info().rss / 1e6]
    next_sample_ns = 60_000_000_000
    start = time.perf_counter()
    for offset_ns in range(0, total_ns, window_ns):
        for topic, message, t in messages:
            while recorder.pending > recorder.settings.queue_size // 2:
                time.sleep(0.001)  # pace to the writer: measure memory, not drops
            recorder.log(topic, message, (t + offset_ns) * 1e-9)
        if offset_ns + window_ns >= next_sample_ns:
            rss_mb.append(process.memory_info().rss / 1e6)
            next_sample_ns += 60_000_000_000
    recorder.close()
    after_first_minute = rss_mb[min(1, len(rss_mb) - 1)]
    return {"simulated_minutes": total_ns / 60e9, "messages": recorder.written,
            "dropped": recorder.dropped, "wall_s": time.perf_counter() - start,
            "rss_mb": rss_mb, "growth_after_first_minute_mb": rss_mb[-1] - after_first_minute}


def format_tables(rows: list[dict], memory: dict | None) -> str:
    cells = []
    for row in rows:
        on = row["recorder"] == "on"
        cells.append([row["recorder"], str(row["runs"]), f"{row['wall_per_sim_s']:.3f}",
                      f"{row['tick_median_ms']:.3f}", f"{row['tick_p95_ms']:.3f}",
                      f"{row['messages_per_sim_s']:.0f}" if on else "",
                      f"{row['messages_per_wall_s']:.0f}" if on else "",
                      f"{row['mb_per_sim_min']:.1f}" if on else "",
                      str(row["dropped"]) if on else ""])
    on = rows[1]
    notes = [f"ratio on/off: wall {on['wall_ratio']:.3f}, tick median "
             f"{on['tick_median_ratio']:.3f}, tick p95 {on['tick_p95_ratio']:.3f} "
             "(target: overhead <= 5 %, i.e. wall ratio <= 1.05)"]
    if memory is not None:
        rss = memory["rss_mb"]
        notes.append(
            f"memory: {memory['simulated_minutes']:.0f} simulated minutes, "
            f"{memory['messages']} messages in {memory['wall_s']:.0f} s, dropped "
            f"{memory['dropped']}; RSS start {rss[0]:.0f} MB, after 1 min "
            f"{rss[min(1, len(rss) - 1)]:.0f} MB, "
            f"end {rss[-1]:.0f} MB (growth after the first minute "
            f"{memory['growth_after_first_minute_mb']:+.1f} MB)")
    numbers = [Column(name, "right") for name in (
        "runs", "wall/sim s", "tick med ms", "tick p95 ms", "msg/sim s", "msg/wall s",
        "MB/sim min", "dropped")]
    return render_table(["recorder", *numbers], cells, notes)

