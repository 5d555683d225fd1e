"""``porter sim [SCENARIO]``: one scenario on the embedded MuJoCo backend, with a progress bar
(simulated time, real-time factor) on stderr and the summary metrics as JSON on stdout."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from pydantic import ValidationError
from rich.console import Console
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

from core.nmpc.settings import ChannelSettings, MpcSettings
from deploy.cli.conventions import DIFFERS, OK, STOPPED, Output
from deploy.cli.sim_arguments import delay_settings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.files import ConfigError
from deploy.config.scenario import Scenario, load_scenario
from deploy.recording.flight_recorder import FlightRecorder, RecorderSettings
from deploy.recording.run_record import default_log_path, open_run_recorder
from deploy.runtime.sim_run import SimRun
from deploy.runtime.stop_request import StopRequest


def scenario_from_args(args: argparse.Namespace) -> Scenario:
    """The scenario named on the command line with ``--duration`` / ``--mode`` / ``--seed`` /
    ``--serial`` overrides applied."""
    scenario = load_scenario(args.scenario)
    update: dict = {}
    if args.duration is not None:
        update["duration_s"] = args.duration
    if args.seed is not None:
        update["seed"] = args.seed
    controller: dict = {}
    if args.mode is not None:
        controller["mode"] = args.mode
    executor = getattr(args, "executor", None)
    if args.serial and executor not in (None, "serial"):
        raise ConfigError(f"--serial and --executor {executor} contradict each other")
    if args.serial or executor:
        controller["executor"] = executor or "serial"
    controller.update(delay_settings(args))
    channel = {key: value for key, value in (
        ("max_delay_rounds", getattr(args, "channel_delay_rounds", None)),
        ("drop_probability", getattr(args, "channel_drop", None))) if value is not None}
    if channel:
        current = scenario.controller.channel
        try:
            controller["channel"] = ChannelSettings.model_validate(
                {**current.model_dump(include=current.model_fields_set), **channel})
        except ValidationError as error:
            detail = error.errors()[0]
            raise ConfigError(f"--channel: {detail['loc'][0]}: {detail['msg']} (allowed: "
                              "delay 0 to 1000 rounds, drop probability in [0, 1))") from None
    if controller:
        scenario = scenario.with_controller(**controller)
    return scenario.model_copy(update=update)


def run_sim(args: argparse.Namespace, base_settings: MpcSettings) -> int:
    scenario = scenario_from_args(args)
    out = Output(args)
    out.progress(f"porter sim: scenario {scenario.name!r}, {len(scenario.team)} robots, "
                 f"{scenario.controller.mode} NMPC, {scenario.duration_s:g} s on MuJoCo "
                 "(the first start compiles the NLPs, about a minute each)")
    loop = SimRun(scenario, CompiledCodeCache(), base_settings)
    recorder: FlightRecorder | None = None
    if not args.no_record:
        path = Path(args.record) if args.record else default_log_path(scenario)
        settings = RecorderSettings()
        if getattr(args, "keyframe_every", None):
            settings = settings.model_copy(update={"warm_start_every": args.keyframe_every})
        recorder = open_run_recorder(path, scenario, loop.settings, loop.wbc_settings, "mujoco",
                                     settings, sinks=live_view_sinks(args, scenario),
                                     blas_kernels=loop.control.cache.blas_kernels().target)
        loop.attach_recorder(recorder)
        out.progress(f"porter sim: recording to {path}")
    show = not out.quiet
    # A live bar only on a terminal: piped or logged stderr gets the transitions, no redraws.
    bar = Progress(TextColumn("porter sim"), BarColumn(),
                   TextColumn("{task.completed:5.1f}/{task.total:.1f} s simulated"),
                   TextColumn("RTF {task.fields[rtf]:.2f}"), TimeElapsedColumn(),
                   console=Console(stderr=True), disable=not (show and sys.stderr.isatty()))
    task = bar.add_task("sim", total=scenario.duration_s, rtf=0.0)

    def progress(time_s: float, duration_s: float, wall_s: float) -> None:
        bar.update(task, completed=time_s, rtf=time_s / wall_s if wall_s > 0 else 0.0)

    summary: dict | None = None
    stop = StopRequest()
    try:
        with stop.installed(), bar:
            summary = loop.run(progress, stop, verbose=show)
    finally:  # Ctrl-C, SIGTERM (raised as KeyboardInterrupt by the CLI) and errors alike
        loop.close()
        if recorder is not None:
            recorder.close(summary)
            if recorder.dropped:
                print(f"porter sim: the recorder dropped {recorder.dropped} messages",
                      file=sys.stderr)
    assert summary is not None
    out.report(json.dumps(summary, indent=2))
    out.write_json(summary)
    verdict, as_expected = sim_verdict(summary, args.duration)
    out.progress(f"porter sim: {verdict}")
    if stop():
        out.progress(f"porter sim: stopped by {stop.reason} at {summary['duration_s']:.2f} s")
        return STOPPED
    return OK if as_expected else DIFFERS


def sim_verdict(summary: dict, duration_s: float | None) -> tuple[str, bool]:
    """One line on the run, and whether it is as its scenario expects: its expected outcome
    and no fall (a run shortened by ``--duration``, ``duration_s``, may time out)."""
    verdict = ("reached the goal" if summary["reached_goal"] else "did NOT reach the goal")
    if summary["safety"].get("controlled_stop"):
        verdict += (f" (controlled stop: braking since {summary['safety']['braking_since_s']:.2f} s,"
                    " then the team sat down; the cause is in the transitions)")
    expected = summary.get("expected_outcome", "goal")
    verdict += f"; outcome {summary['outcome']!r}"
    as_expected = summary["outcome"] == expected
    if as_expected:
        verdict += " as the scenario expects"
    elif duration_s is not None and summary["outcome"] == "time out":
        as_expected = True  # a shortened run is not expected to arrive
        verdict += f" (--duration {duration_s:g} s: the scenario's own length expects {expected!r})"
    else:
        verdict += f", the scenario expects {expected!r}"
    return (f"{verdict}; falls {summary['falls']}; min h {summary['min_h_m']}",
            as_expected and not summary["falls"])


def live_view_sinks(args: argparse.Namespace, scenario: Scenario) -> list:
    """``--rerun``: stream every recorded message to a Rerun viewer as it is written."""
    if not getattr(args, "rerun", None):
        return []
    from deploy.viewing.rerun_view import live_sink

    return [live_sink(args.rerun, scenario.name,
                      {agent.name: agent.robot_type for agent in scenario.team})]
