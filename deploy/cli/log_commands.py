"""``porter log info LOG``, ``porter log recover LOG`` and ``porter log timeline LOG``."""

from __future__ import annotations

import argparse
from pathlib import Path

from deploy.cli.conventions import OK, Output, error, os_error
from deploy.recording.fault_timeline import fault_timelines, format_timelines
from deploy.recording.joint_speeds import calf_speed_running
from deploy.recording.log_format import RUN_METADATA
from deploy.recording.log_reader import LogError, LogFile, recover
from deploy.reports.table import Column, render_table

SUMMARY_KEYS = ("scenario", "duration_s", "reached_goal", "falls", "final_goal_distance_m",
                "min_h_m", "rms_payload_position_error_m", "max_coupling_error_m",
                "admm_residual_rms", "nmpc_update_ms", "nmpc_updates", "deadline_misses",
                "failed_solves", "wbc_tick_ms", "real_time_factor")


def describe(log: LogFile) -> str:
    """Duration, topics with counts and rates, metadata and the run's summary metrics."""
    record = info_record(log)
    topics = record["topics"]
    lines = [f"{log.path}: {record['size_bytes'] / 1e6:.2f} MB, {record['duration_s']:.3f} s, "
             f"{record['messages']} messages on {len(topics)} topics"]
    metadata = record["metadata"]
    run = metadata.get(RUN_METADATA, {})
    lines.append("run: " + ", ".join(f"{key} {run[key]}" for key in (
        "scenario", "seed", "backend", "controller_mode", "git_revision", "porter_version",
        "started_utc") if key in run))
    recorder = metadata.get("recorder")
    if recorder:
        lines.append(f"recorder: {recorder.get('messages_written')} written, "
                     f"{recorder.get('messages_dropped')} dropped"
                     + (f", error {recorder['writer_error']}" if recorder.get("writer_error")
                        else ""))
    lines.append(render_table(
        ["topic", Column("messages", "right"), Column("rate [Hz]", "right")],
        [[topic, str(row["messages"]), f"{row['rate_hz']:.1f}"] for topic, row in topics.items()]))
    lines.append("attachments: " + ", ".join(record["attachments"]))
    calf = record["calf_speed_running"]
    if calf is not None:
        lines.append(f"fastest calf while running: p99.9 {calf['p99_9_rad_s']:.1f} rad/s, max "
                     f"{calf['max_rad_s']:.1f} rad/s ({calf['states']} robot states)")
    summary = record["summary"]
    if summary is None:
        lines.append("summary: none (the run ended before writing one)")
    else:
        lines.append("summary:")
        for key in SUMMARY_KEYS:
            if key not in summary:
                continue
            value = summary[key]
            if isinstance(value, dict):  # one line, its entries named: "median 13.4, p95 20.4"
                value = ", ".join(f"{name} {_number(item)}" for name, item in value.items())
            lines.append(f"  {key}: {_number(value)}")
    return "\n".join(lines)


def _number(value: object) -> str:
    """Floats to 4 significant digits, flags as yes/no, everything else as written."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.4g}"
    return str(value)


def info_record(log: LogFile) -> dict:
    """``porter log info --json``: ``{path, size_bytes, duration_s, messages, topics:
    {topic: {messages, rate_hz}}, metadata: {name: {key: value}}, attachments: [names],
    summary: the run's summary metrics or null, calf_speed_running: the fastest calf's speed
    while RUNNING (``deploy.recording.joint_speeds``) or null}`` (JSON types only)."""
    counts, start_ns, end_ns = log.message_counts()
    duration_s = (end_ns - start_ns) * 1e-9
    return {"path": str(log.path), "size_bytes": log.path.stat().st_size,
            "duration_s": duration_s, "messages": sum(counts.values()),
            "topics": {topic: {"messages": n, "rate_hz": n / duration_s if duration_s > 0
                               else 0.0} for topic, n in sorted(counts.items())},
            "metadata": log.metadata(), "attachments": sorted(log.attachments()),
            "summary": log.summary(), "calf_speed_running": calf_speed_running(log)}


def run_log_info(args: argparse.Namespace) -> int:
    out = Output(args)
    try:
        log = LogFile(args.log)
        out.report(describe(log))
        out.write_json(info_record(log))
    except LogError as failure:
        return error(f"{failure}; give the path of a flight log porter wrote")
    return OK


def run_log_recover(args: argparse.Namespace) -> int:
    out = Output(args)
    source = Path(args.log)
    output = Path(args.output) if args.output else source.with_suffix(".recovered.mcap")
    if output.resolve() == source.resolve():
        return error("the recovered file must not overwrite the original; name another with "
                     "--output")
    try:
        result = recover(source, output)
    except LogError as failure:
        return error(f"{failure}; give the path of the log the run left")
    except OSError as failure:
        return error(os_error(failure, "give the path of the log the run left and a writable "
                                       "--output"))
    ending = (f"the stream ended inside a record ({result.error}); the unfinished chunk is lost"
              if result.chunks_lost else "the file was complete")
    out.report(f"porter log recover: {result.messages} messages copied to {output}; {ending}")
    out.write_json({"output": str(output), "messages": result.messages,
                    "chunks_lost": result.chunks_lost, "error": result.error})
    return OK


def run_log_timeline(args: argparse.Namespace) -> int:
    out = Output(args)
    try:
        timelines = fault_timelines(LogFile(args.log), 1e-3 * args.window_ms)
    except LogError as failure:
        return error(f"{failure}; give the path of a flight log porter wrote")
    except OSError as failure:
        return error(os_error(failure, "give the path of a flight log porter wrote"))
    out.report(format_timelines(timelines))
    out.write_json([t.to_json() for t in timelines])
    return OK
