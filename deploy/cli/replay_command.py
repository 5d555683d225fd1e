"""``porter replay LOG.mcap [--rrd FILE | --connect [URL]]``: play a flight log in Rerun.

Every message goes through ``deploy.viewing.rerun_view.RerunLogView`` in log-time order, after the
blueprint and the run's metadata and summary (a static text document). By default a viewer is
spawned; ``--connect`` sends to a running one; ``--rrd`` writes a recording file (headless).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import rerun as rr
import yaml

from deploy.cli.conventions import OK, Output, error
from deploy.recording.log_format import RUN_METADATA, SCENARIO_ATTACHMENT
from deploy.recording.log_reader import LogError, LogFile
from deploy.viewing import layout as paths
from deploy.viewing.rerun_view import RerunLogView, open_recording


def replay_target(args: argparse.Namespace) -> str:
    """``open_recording``'s target from the command line."""
    if args.rrd:
        return str(args.rrd) if str(args.rrd).endswith(".rrd") else f"{args.rrd}.rrd"
    if args.connect is not None:
        return args.connect or "connect"
    return "spawn"


def robot_types(log: LogFile) -> dict[str, str]:
    """Robot name -> type (``go2``, ``a1``) from the attached scenario, if any."""
    try:
        scenario = yaml.safe_load(log.attachment_text(SCENARIO_ATTACHMENT)) or {}
        return {agent["name"]: agent["robot_type"] for agent in scenario.get("team", [])}
    except (LogError, yaml.YAMLError, KeyError, TypeError, AttributeError):
        return {}


def coupling_points(log: LogFile) -> dict[str, tuple[list[float], list[float]]]:
    """Per robot (point in payload, point in robot) [m] from the attached scenario, if any."""
    try:
        scenario = yaml.safe_load(log.attachment_text(SCENARIO_ATTACHMENT)) or {}
        return {agent["name"]: (agent["coupling_point_in_payload_m"],
                                agent["coupling_point_in_robot_m"])
                for agent in scenario.get("team", [])}
    except (LogError, yaml.YAMLError, KeyError, TypeError, AttributeError):
        return {}


def run_document(log: LogFile) -> str:
    """The run's metadata and summary metrics as Markdown."""
    metadata = log.metadata()
    lines = [f"# {log.path.name}", ""]
    for name, record in metadata.items():
        if name == "summary":
            continue
        lines += [f"## {name}", "", "| key | value |", "| --- | --- |"]
        lines += [f"| {key} | {value} |" for key, value in record.items()]
        lines.append("")
    summary = log.summary()
    if summary is not None:
        lines += ["## summary", "", "```json", json.dumps(summary, indent=2), "```"]
    return "\n".join(lines)


def run_replay(args: argparse.Namespace) -> int:
    started = time.perf_counter()
    out = Output(args)
    target = replay_target(args)
    if target not in ("spawn", "connect") and not target.endswith(".rrd") and "://" not in target:
        return error(f"--connect {target!r}: expected a URL such as "
                     "rerun+http://127.0.0.1:9876/proxy")
    messages, last_ns = 0, 0
    try:
        log = LogFile(args.log)
        run = log.metadata().get(RUN_METADATA, {})
        robot_names = [name for name in run.get("robots", "").split(",") if name]
        recording = open_recording(target, f"{run.get('scenario', 'porter')} "
                                           f"({Path(args.log).name})", robot_names)
        view = RerunLogView(recording, robot_names, coupling_points(log),
                            robot_types=robot_types(log))
        recording.log(paths.RUN_INFO, rr.TextDocument(
            run_document(log), media_type=rr.MediaType.MARKDOWN), static=True)
        for item in log.messages():
            view.handle(item.topic, item.message, item.log_time_ns)
            messages += 1
            last_ns = item.log_time_ns
        recording.flush()
        recording.disconnect()
    except LogError as failure:  # not MCAP, incomplete, corrupted, another format version
        return error(f"{failure}; give the path of a flight log porter wrote (porter log "
                     "recover makes a killed run's log readable)")
    output = {"spawn": "a spawned viewer", "connect": "the local viewer"}.get(target, target)
    wall_s = time.perf_counter() - started
    out.report(f"porter replay: {messages} messages, {last_ns * 1e-9:.2f} s of log -> {output} "
               f"({wall_s:.1f} s)")
    out.write_json({"log": args.log, "target": target, "messages": messages,
                    "duration_s": last_ns * 1e-9, "wall_s": wall_s})
    return OK
