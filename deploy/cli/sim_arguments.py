"""The ``porter sim`` command line (kept apart so that ``porter`` starts without importing
the simulation)."""

from __future__ import annotations

import argparse
from collections.abc import Callable

from deploy.cli.conventions import (
    add_output_options,
    add_record_options,
    number_in,
    whole_number_in,
)


def add_sim_parser(commands: argparse._SubParsersAction,
                   handler: Callable[[argparse.Namespace], int],
                   positive_number: Callable[[str], float], count: Callable[[str], int]) -> None:
    sim = commands.add_parser(
        "sim", help="run a scenario on the embedded MuJoCo backend",
        description="Run a scenario in closed loop on MuJoCo, in lockstep: the NMPC plans, the "
        "WBC turns plans into torques, every message goes to a flight log. Prints the summary. "
        "Exit 0 when the team reached the scenario's expected outcome without a fall, 1 when "
        "not, 130 when stopped.")
    sim.add_argument("scenario", nargs="?", default="two_go2",
                     help="shipped name or YAML path (default two_go2)")
    sim.add_argument("--config", metavar="YAML",
                     help="MpcSettings fields to override, or a shipped profile: paper "
                     "(the paper's NLP, IPOPT to convergence), porter (the defaults)")
    sim.add_argument("--duration", type=positive_number, metavar="S",
                     help="instead of the scenario's duration_s")
    sim.add_argument("--seed", type=whole_number_in(0, 2**32 - 1),
                     help="instead of the scenario's seed")
    sim.add_argument("--mode", choices=["distributed", "centralized", "wrench-only"],
                     help="instead of the scenario's controller.mode")
    sim.add_argument("--executor", choices=["process", "serial", "zenoh"],
                     help="where local solves run (zenoh: porter agents)")
    sim.add_argument("--serial", action="store_true", help="the same as --executor serial")
    sim.add_argument("--delay", action="store_true", help="apply each plan after its solve")
    add_delay_arguments(sim)
    add_output_options(sim, "the summary")
    add_record_options(sim, "runs/<scenario>-<time>.mcap")
    sim.add_argument("--no-record", action="store_true", help="write no flight log")
    sim.add_argument("--keyframe-every", type=count, metavar="N",
                     help="warm start logged every N updates (60)")
    sim.add_argument("--rerun", nargs="?", const="spawn", metavar="TARGET",
                     help="live view: spawn (default), connect, URL or FILE.rrd")
    sim.add_argument("--channel-delay-rounds", type=whole_number_in(0, 1000), metavar="D",
                     help="ADMM messages up to D rounds late: the newest one that arrived "
                     "is held, and left out of the consensus once older than the channel's "
                     "max_age_rounds (2 by default; null in a scenario: pure hold-last)")
    sim.add_argument("--channel-drop", type=number_in(0.0, 1.0, high_open=True), metavar="P",
                     help="ADMM messages dropped with probability P")
    sim.set_defaults(handler=handler)


def add_delay_arguments(parser: argparse.ArgumentParser) -> None:
    """``--delay-s`` and ``--overlap`` (``porter sim``, ``porter bench sim``)."""
    parser.add_argument("--delay-s", type=number_in(0.0, 0.5), metavar="S",
                        help="apply each plan S seconds after its decision (deterministic)")
    parser.add_argument("--overlap", action="store_true",
                        help="with a fixed delay: the NMPC computes in its own process while "
                        "the world steps (the same results, less wall time)")


def delay_settings(args: argparse.Namespace) -> dict:
    """The ``controller`` fields that ``--delay`` / ``--delay-s`` / ``--overlap`` set."""
    controller: dict = {}
    if getattr(args, "delay", False):
        controller["model_computation_delay"] = True
    if getattr(args, "delay_s", None) is not None:
        controller.update(model_computation_delay=True, computation_delay_s=args.delay_s)
    if getattr(args, "overlap", False):
        controller["overlap_computation"] = True
    return controller
