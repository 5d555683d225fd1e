"""``porter paper CLAIM``: the paper's claims reproduced (see ``deploy.paper``)."""

from __future__ import annotations

import argparse

from deploy.cli.conventions import Output, add_output_options, error

PAPER_CLAIMS = ("table1", "delay", "iterations", "consensus", "experiments", "closed-loop")


def add_paper_parser(commands: argparse._SubParsersAction) -> None:
    paper = commands.add_parser(
        "paper", help="reproduce one of the paper's ablations beside its figures",
        description="Run the variants of one of the paper's claims (on the MuJoCo backend; "
                    "table1 times the NLPs alone, without the simulation) under each "
                    "controller profile and print porter's figures beside the paper's; "
                    "writes CLAIM.json and CLAIM.png (the ablation figure's panels) into "
                    "--out. Exit 0 when every run was safe and reached its scenario's "
                    "expected outcome, 1 when one did not.")
    paper.add_argument("claim", choices=PAPER_CLAIMS, help="which claim: "
                       + ", ".join(PAPER_CLAIMS))
    paper.add_argument("--profile", nargs="+", default=None, metavar="PROFILE",
                       help="controller profiles to run, each a row set: porter (porter's "
                       "NLP, rti), paper (the paper's NLP, IPOPT to convergence) or a YAML "
                       "file of MpcSettings (default: porter paper)")
    paper.add_argument("--config", metavar="YAML", help="one more profile: a YAML file of "
                       "MpcSettings fields (its rows are labelled by the file's name)")
    paper.add_argument("--scenario", default="two_go2",
                       help="shipped scenario the ablations run on (default two_go2)")
    paper.add_argument("--duration", type=float, help="seconds per run (default: the "
                       "scenario's)")
    paper.add_argument("--out", default="paper", help="folder for the JSON and PNG")
    paper.add_argument("--agents", type=int, nargs="+", default=[2, 3, 4],
                       help="team sizes (table1)")
    paper.add_argument("--scenarios", nargs="+", help="experiments: these scenarios only "
                       "(default: all seven); closed-loop: these shipped scenarios (default: "
                       "two_go2 mixed_three four_go2)")
    add_output_options(paper, "the claim's document (as CLAIM.json)")
    paper.set_defaults(handler=_paper)


def _paper(args: argparse.Namespace) -> int:
    import math
    from pathlib import Path

    from deploy.config.profiles import DEFAULT_PROFILES, load_profile
    from deploy.config.scenario import shipped_scenarios
    from deploy.paper.closed_loop import DEFAULT_SCENARIOS, reproduce_closed_loop
    from deploy.paper.experiments import EXPERIMENTS, reproduce_experiments
    from deploy.paper.reproduce import reproduce
    from deploy.paper.table1 import reproduce_table1

    output = Output(args)
    if args.duration is not None and not (math.isfinite(args.duration) and args.duration > 0):
        return error(f"paper --duration must be positive and finite, got {args.duration}")
    names = list(args.profile or ([] if args.config else DEFAULT_PROFILES))
    if args.config:
        names.append(args.config)
    profiles = [load_profile(name) for name in names]  # a bad file is a ConfigError (exit 2)
    labels = [label for label, _ in profiles]
    if len(set(labels)) != len(labels):
        return error(f"paper --profile: each profile once, got {labels}")
    if args.claim == "table1":
        if not all(2 <= n <= 8 for n in args.agents):
            return error(f"paper --agents must be in [2, 8], got {args.agents}")
        return reproduce_table1(args.agents, args.duration or 3.0, Path(args.out), output,
                                profiles)
    if args.claim == "experiments":
        unknown = sorted(set(args.scenarios or []) - set(EXPERIMENTS))
        if unknown:
            return error(f"paper experiments: unknown scenarios {unknown}; choose from "
                         f"{sorted(EXPERIMENTS)}")
        return reproduce_experiments(args.scenarios or list(EXPERIMENTS), args.duration,
                                     Path(args.out), output, profiles)
    if args.claim == "closed-loop":
        unknown = sorted(set(args.scenarios or []) - set(shipped_scenarios()))
        if unknown:
            return error(f"paper closed-loop: unknown scenarios {unknown}; choose from "
                         f"{shipped_scenarios()}")
        return reproduce_closed_loop(args.scenarios or list(DEFAULT_SCENARIOS), args.duration,
                                     Path(args.out), output, profiles)
    return reproduce(args.claim, args.scenario, args.duration, Path(args.out), output,
                     profiles)
