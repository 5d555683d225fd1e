"""The ``porter log`` and ``porter regress`` command lines (kept apart so that ``porter``
starts without importing the recorder)."""

from __future__ import annotations

import argparse
from collections.abc import Callable

from deploy.cli.conventions import add_output_options, number_in

Handler = Callable[[argparse.Namespace], int]


def _log_info(args: argparse.Namespace) -> int:
    from deploy.cli.log_commands import run_log_info

    return run_log_info(args)


def _log_recover(args: argparse.Namespace) -> int:
    from deploy.cli.log_commands import run_log_recover

    return run_log_recover(args)


def _log_timeline(args: argparse.Namespace) -> int:
    from deploy.cli.log_commands import run_log_timeline

    return run_log_timeline(args)


def add_log_parsers(commands: argparse._SubParsersAction, regress_handler: Handler,
                    count: Callable[[str], int]) -> None:
    log = commands.add_parser("log", help="inspect and repair flight logs",
                              description="Read a flight log: what it holds, what was late "
                              "before a safe stop; make a killed run's log readable.")
    log_kinds = log.add_subparsers(dest="log_command", required=True, metavar="KIND")
    info = log_kinds.add_parser(
        "info", help="duration, topics, counts, summary metrics",
        description="What LOG holds: its duration, topics with counts and rates, metadata, "
        "attachments, the fastest calf while running and the run's summary metrics. Exit 2 "
        "when LOG cannot be read.")
    info.add_argument("log", help="LOG.mcap")
    add_output_options(info, "the record (path, size_bytes, duration_s, messages, topics, "
                             "metadata, attachments, summary, calf_speed_running)")
    info.set_defaults(handler=_log_info)
    recover = log_kinds.add_parser(
        "recover", help="make a killed run's log readable",
        description="Copy every complete record of a log that was never closed (a killed "
        "run) into a new, indexed file. Exit 2 when LOG cannot be read.")
    recover.add_argument("log", help="LOG.mcap left by a run that did not close it")
    recover.add_argument("-o", "--output", help="recovered file (default LOG.recovered.mcap)")
    add_output_options(recover, "what was copied")
    recover.set_defaults(handler=_log_recover)
    timeline = log_kinds.add_parser(
        "timeline", help="what was late before each safe stop",
        description="For each safe stop in LOG: per robot, the held states (the state did not "
        "advance), late loop ticks, the gait's stance and the fastest joint, and the team's "
        "late or missing NMPC plans, in the window before it. Exit 0 whether or not the log "
        "has a safe stop; 2 when LOG cannot be read.")
    timeline.add_argument("log", help="LOG.mcap")
    timeline.add_argument("--around-fault", action="store_true", required=True,
                          help="the window before each safe stop (the only view so far)")
    timeline.add_argument("--window-ms", type=number_in(0.0, 10_000.0, low_open=True),
                          default=50.0,
                          help="how far before each stop to look [ms] (default 50)")
    add_output_options(timeline, "the timelines")
    timeline.set_defaults(handler=_log_timeline)

    regress = commands.add_parser(
        "regress", help="re-run logged NMPC decisions and compare",
        description="Replay every logged NMPC decision and compare it with the log, then "
        "simulate the run again and check its metrics against LOG.expect.json. Exit 1 on a "
        "difference.")
    regress.add_argument("logs", nargs="+", metavar="LOG", help="LOG.mcap files")
    regress.add_argument("--settings", metavar="YAML",
                         help="MpcSettings overriding the log's attached ones (what-if)")
    regress.add_argument("--max-decisions", type=count,
                         help="replay only the first N decisions of each log")
    add_output_options(regress, "the per-log report")
    regress.add_argument("--wbc-settings", help="YAML WbcSettings replacing the logged ones "
                         "in the re-simulation (a changed WBC)")
    regress.add_argument("--no-resimulate", action="store_true",
                         help="check the expectations on the summary stored in the log "
                              "instead of re-simulating the run (faster, blind to changes "
                              "outside the NMPC)")
    regress.add_argument("--refresh-expectations", action="store_true",
                         help="(re)write LOG.expect.json from each log's summary instead of "
                              "replaying: review and commit the result deliberately")
    regress.set_defaults(handler=regress_handler)
