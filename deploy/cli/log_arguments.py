"""The ``porter log`` and ``porter regress`` command lines (kept apart so that ``porter``
starts without importing the recorder)."""

from __future__ import annotations

import argparse
from collections.abc import Callable

Handler = Callable[[argparse.Namespace], int]


def add_log_parsers(commands: argparse._SubParsersAction, info_handler: Handler,
                    recover_handler: Handler, regress_handler: Handler,
                    count: Callable[[str], int]) -> None:
    log = commands.add_parser("log", help="inspect and repair flight logs")
    log_kinds = log.add_subparsers(dest="log_command", required=True)
    info = log_kinds.add_parser("info", help="duration, topics, counts, summary metrics")
    info.add_argument("log", help="LOG.mcap")
    info.add_argument("--json", action="store_true", help="print it as one JSON document "
                      "(path, size_bytes, duration_s, messages, topics, metadata, attachments, "
                      "summary)")
    info.set_defaults(handler=info_handler)
    recover = log_kinds.add_parser("recover", help="make a killed run's log readable")
    recover.add_argument("log", help="LOG.mcap left by a run that did not close it")
    recover.add_argument("-o", "--output", help="recovered file (default LOG.recovered.mcap)")
    recover.set_defaults(handler=recover_handler)

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
    regress.add_argument("--json", help="also write the per-log report as JSON")
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
