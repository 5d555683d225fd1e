"""``porter paper CLAIM``: the paper's claims reproduced (see ``deploy.paper``)."""

from __future__ import annotations

import argparse
import sys

PAPER_CLAIMS = ("table1", "delay", "iterations", "consensus", "experiments")


def add_paper_parser(commands: argparse._SubParsersAction) -> None:
    paper = commands.add_parser(
        "paper", help="reproduce one of the paper's ablations beside its figures",
        description="Run the variants of one of the paper's claims on the MuJoCo backend and "
                    "print porter's figures beside the paper's; writes CLAIM.json and "
                    "CLAIM.png (the ablation figure's panels) into --out.")
    paper.add_argument("claim", choices=PAPER_CLAIMS)
    paper.add_argument("--scenario", default="two_go2")
    paper.add_argument("--duration", type=float, help="seconds per run (default: the "
                       "scenario's)")
    paper.add_argument("--out", default="paper", help="folder for the JSON and PNG")
    paper.add_argument("--agents", type=int, nargs="+", default=[2, 3, 4],
                       help="team sizes (table1)")
    paper.add_argument("--scenarios", nargs="+", help="experiments: these scenarios only "
                       "(default: all five)")
    paper.set_defaults(handler=_paper)


def _paper(args: argparse.Namespace) -> int:
    from pathlib import Path

    from deploy.paper.experiments import EXPERIMENTS, reproduce_experiments
    from deploy.paper.reproduce import reproduce
    from deploy.paper.table1 import reproduce_table1

    if args.duration is not None and not args.duration > 0:
        print(f"porter: paper --duration must be positive, got {args.duration}",
              file=sys.stderr)
        return 2
    if args.claim == "table1":
        if not all(2 <= n <= 8 for n in args.agents):
            print(f"porter: paper --agents must be in [2, 8], got {args.agents}",
                  file=sys.stderr)
            return 2
        return reproduce_table1(args.agents, args.duration or 3.0, Path(args.out))
    if args.claim == "experiments":
        unknown = sorted(set(args.scenarios or []) - set(EXPERIMENTS))
        if unknown:
            print(f"porter: paper experiments: unknown scenarios {unknown}; choose from "
                  f"{sorted(EXPERIMENTS)}", file=sys.stderr)
            return 2
        return reproduce_experiments(args.scenarios or list(EXPERIMENTS), args.duration,
                                     Path(args.out))
    return reproduce(args.claim, args.scenario, args.duration, Path(args.out))
