"""The ``porter`` command line."""

from __future__ import annotations

import argparse
import math
import os
import signal
import sys
from typing import TYPE_CHECKING

from deploy.cli.agent_command import add_agent_parser
from deploy.cli.bench_command import add_bench_parser
from deploy.cli.conventions import (
    STOPPED,
    USAGE,
    add_output_options,
    add_record_options,
    error,
    existing_record,
    number_in,
    os_error,
    whole_number_in,
)
from deploy.cli.log_arguments import add_log_parsers
from deploy.cli.paper_command import add_paper_parser
from deploy.cli.sim_arguments import add_sim_parser

if TYPE_CHECKING:
    from core.nmpc.settings import MpcSettings


# durations and time scales: positive and finite
positive_number = number_in(0.0, math.inf, low_open=True)


def loop_priority(text: str) -> int | None:
    """A SCHED_FIFO priority 1-99, or ``none`` (normal scheduling)."""
    if text.lower() in ("none", "null"):
        return None
    if not (text.isdigit() and 1 <= int(text) <= 99):
        raise argparse.ArgumentTypeError(f"must be 1-99 or none, got {text!r}")
    return int(text)


# runs, samples, agents
count = whole_number_in(1)


def mpc_settings(args: argparse.Namespace) -> MpcSettings:
    """``MpcSettings`` from ``--config`` (YAML overrides of the defaults, or a shipped
    profile's name: ``paper``, ``porter``) or the defaults."""
    from core.nmpc.settings import MpcSettings
    from deploy.config.profiles import load_profile

    return load_profile(args.config)[1] if args.config else MpcSettings()


def _sim(args: argparse.Namespace) -> int:
    from deploy.cli.sim_command import run_sim

    if problem := existing_record(args):
        return error(problem)
    return run_sim(args, mpc_settings(args))


def _deploy(args: argparse.Namespace) -> int:
    from deploy.cli.deploy_command import run_deploy

    if problem := existing_record(args):  # refused before any robot stands up
        return error(problem)
    return run_deploy(args)


def _drill(args: argparse.Namespace) -> int:
    from deploy.cli.drill_command import run_drill

    return run_drill(args)


def _replay(args: argparse.Namespace) -> int:
    from deploy.cli.replay_command import run_replay

    return run_replay(args)


def _regress(args: argparse.Namespace) -> int:
    from deploy.cli.regress_command import run_regress

    return run_regress(args)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="porter", description="Quadruped teams carrying one payload: simulate, deploy, "
        "replay and check runs.", epilog="Every command: --json FILE ('-': stdout) writes its "
        "report as JSON, --quiet prints nothing but errors. Exit codes: 0 done as expected, 1 "
        "done but not as expected, 2 bad argument, config or file (nothing run), 3 safe stop "
        "(deploy), 130 stopped by the operator.")
    parser.add_argument("--version", action="version", version=f"porter {_porter_version()}")
    commands = parser.add_subparsers(dest="command", required=True)

    drill = commands.add_parser(
        "drill", help="the fault suite on the sim backend: every fault detected, only damping "
        "after detection, logs readable",
        description="Inject each fault into a short porter deploy on the sim backend and judge "
        "it from outside; prints one table row per fault. Exit 0 when all were handled as "
        "expected, 1 when one was not, 2 when no fault matches the names given.")
    drill.add_argument("faults", nargs="*", help="run the faults whose names contain these "
                       "(default: all)")
    drill.add_argument("--keep", help="folder for each fault's config, log and output "
                       "(default: a temporary one)")
    add_output_options(drill, "the rows {rows: [...]}")
    drill.set_defaults(handler=_drill)

    add_bench_parser(commands, positive_number, count, loop_priority)
    add_sim_parser(commands, _sim, positive_number, count)

    deploy = commands.add_parser(
        "deploy", help="run the team on robots (or on the simulated world behind the same "
        "drivers)", description="Pre-flight, stand up, arm (asks unless --yes), carry the "
        "payload, sit down; any fault safe-stops the team. Exit 0 done, 1 pre-flight failed, "
        "3 safe stop, 130 stopped by the operator (or arming declined).")
    deploy.add_argument("--config", required=True, metavar="CONFIG.yaml",
                        help="deploy config (deploy/config/deployments/*.yaml) or a shipped "
                             "config's name")
    deploy.add_argument("--backend", choices=["hw", "sim"], default="hw",
                        help="hw: the robots; sim: MuJoCo behind fakes on loopback (default hw)")
    deploy.add_argument("--yes", action="store_true", help="arm without asking the operator")
    deploy.add_argument("--duration", type=positive_number, metavar="S",
                        help="seconds to run once armed (default: the scenario's duration_s)")
    add_record_options(deploy, "runs/deploy-<scenario>-<time>.mcap")
    deploy.add_argument("--no-record", action="store_true",
                        help="no flight log (--backend sim only)")
    add_output_options(deploy, "the summary")
    deploy.set_defaults(handler=_deploy)

    replay = commands.add_parser(
        "replay", help="play a flight log in Rerun", description="Show a flight log in "
        "Rerun: the robots' models, payload, obstacles and plans in 3D beside the time series.")
    replay.add_argument("log", help="LOG.mcap written by porter")
    target = replay.add_mutually_exclusive_group()
    target.add_argument("--rrd", metavar="FILE", help="write a Rerun recording instead of "
                        "opening a viewer (headless)")
    target.add_argument("--connect", nargs="?", const="", metavar="URL",
                        help="send to a running viewer (default URL: Rerun's local one)")
    add_output_options(replay, "what was shown or written")
    replay.set_defaults(handler=_replay)

    add_log_parsers(commands, _regress, count)
    add_agent_parser(commands)
    add_paper_parser(commands)
    return parser


def _porter_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("porter")
    except PackageNotFoundError:
        return "unknown (not installed)"


def _terminate(signum: int, frame: object) -> None:
    raise KeyboardInterrupt(f"signal {signum}")


def main(argv: list[str] | None = None) -> int:
    from deploy.config.files import ConfigError

    args = build_parser().parse_args(argv)
    # Outside loops that poll a StopRequest, SIGTERM unwinds like Ctrl-C: ``finally`` blocks run.
    signal.signal(signal.SIGTERM, _terminate)
    try:
        return int(args.handler(args))
    except ConfigError as failure:
        return error(str(failure), USAGE)
    except (FileNotFoundError, IsADirectoryError, PermissionError) as failure:
        return error(os_error(failure, "check the path"), USAGE)
    except KeyboardInterrupt:
        return error("interrupted", STOPPED)
    except BrokenPipeError:
        # The reader went away (`porter log info LOG | head`): what it wanted was printed.
        # Point stdout at /dev/null so the interpreter's final flush does not fail again.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    sys.exit(main())
