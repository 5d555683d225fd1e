"""The ``porter sim`` command line (kept apart so that ``porter`` starts without importing
the simulation)."""

from __future__ import annotations

import argparse
from collections.abc import Callable


def add_sim_parser(commands: argparse._SubParsersAction,
                   handler: Callable[[argparse.Namespace], int],
                   positive_number: Callable[[str], float], count: Callable[[str], int]) -> None:
    sim = commands.add_parser("sim", help="run a scenario on the embedded MuJoCo backend")
    sim.add_argument("scenario", nargs="?", default="two_go2",
                     help="shipped scenario name or path of a scenario YAML (default two_go2)")
    sim.add_argument("--json", help="write the summary metrics as JSON")
    sim.add_argument("--config", help="YAML file overriding MpcSettings fields")
    sim.add_argument("--duration", type=positive_number,
                     help="override the scenario's duration_s")
    sim.add_argument("--seed", type=int, help="override the scenario's seed")
    sim.add_argument("--mode", choices=["distributed", "centralized", "wrench-only"],
                     help="override the scenario's controller.mode")
    sim.add_argument("--serial", action="store_true",
                     help="run ADMM local solves in this process instead of one per agent")
    sim.add_argument("--executor", choices=["process", "serial", "zenoh"],
                     help="where ADMM local solves run (zenoh: `porter agent` processes)")
    sim.add_argument("--delay", action="store_true",
                     help="model computation delay (apply each plan after its solve time)")
    sim.add_argument("--quiet", action="store_true", help="no progress bar")
    sim.add_argument("--record", metavar="LOG.mcap",
                     help="flight-recorder file (default runs/<scenario>-<time>.mcap)")
    sim.add_argument("--no-record", action="store_true", help="do not write a flight log")
    sim.add_argument("--keyframe-every", type=count, metavar="N",
                     help="log the NMPC warm start every N updates (default 60)")
    sim.add_argument("--rerun", nargs="?", const="spawn", metavar="TARGET",
                     help="stream live to Rerun: spawn a viewer (default), 'connect' to a "
                          "running one (or a rerun+http:// URL), or a FILE.rrd")
    sim.add_argument("--channel-delay-rounds", type=int, metavar="D",
                     help="ADMM messages arrive up to D communication rounds late "
                          "(admm.channel.max_delay_rounds; hold-last)")
    sim.add_argument("--channel-drop", type=float, metavar="P",
                     help="ADMM messages are dropped with probability P "
                          "(admm.channel.drop_probability)")
    sim.set_defaults(handler=handler)
