"""``porter agent``: one robot's ADMM local solves over Zenoh (see ``deploy.agents``)."""

from __future__ import annotations

import argparse

from deploy.cli.conventions import Output, error, number_in, whole_number_in


def add_agent_parser(commands: argparse._SubParsersAction) -> None:
    agent = commands.add_parser(
        "agent", help="serve one robot's ADMM local solves over Zenoh",
        description="Build one robot's local NMPC problem and answer the coordinator's solve "
                    "requests over Zenoh until it says stop. porter starts these itself for "
                    "executor 'zenoh'; start them by hand to put agents on other machines "
                    "(same scenario and --config as the coordinator, its endpoint and key "
                    "prefix).")
    source = agent.add_mutually_exclusive_group(required=True)
    source.add_argument("--scenario", help="the scenario the coordinator runs (its settings)")
    source.add_argument("--settings", help="effective NMPC settings YAML (as porter writes "
                        "them for agents it starts); needs --agents")
    source.add_argument("--new-credentials", metavar="FILE",
                        help="write a new user:password file for a team (readable by its "
                        "owner only) and exit; give the same file to the coordinator "
                        "(controller.network.credentials_file) and every agent")
    agent.add_argument("--credentials", metavar="FILE",
                       help="the team's Zenoh credentials (user:password file): required")
    agent.add_argument("--config", help="YAML overriding MpcSettings fields (with --scenario)")
    agent.add_argument("--agents", type=whole_number_in(2, 64),
                       help="team size (with --settings)")
    agent.add_argument("--index", type=whole_number_in(0, 63),
                       help="this agent's robot, from 0 (required)")
    agent.add_argument("--team", help="team name in every message (default: the scenario's)")
    agent.add_argument("--key-prefix",
                       help="the coordinator's key prefix, e.g. porter/two_go2/4711 "
                       "(required)")
    agent.add_argument("--connect", nargs="+", default=[],
                       help="the coordinator's Zenoh endpoints, e.g. tcp/127.0.0.1:7447")
    agent.add_argument("--listen", nargs="+", default=[],
                       help="endpoints this agent listens on (default: none)")
    agent.add_argument("--peer-timeout", type=number_in(0.0, 60.0, low_open=True),
                       default=1.0, metavar="S",
                       help="coordinator-free topology: a peer silent this long fails the "
                            "update (default 1 s)")
    agent.add_argument("--quiet", action="store_true",
                       help="print nothing but errors (no start and end lines)")
    agent.add_argument("--parent-pid", type=int, help=argparse.SUPPRESS)
    agent.set_defaults(handler=run_agent)


def run_agent(args: argparse.Namespace) -> int:
    from core.admm.admm_executor import LocalSolverSpec
    from core.nmpc.settings import MpcSettings
    from deploy.agents.agent import AdmmAgent, AgentAddress
    from deploy.agents.zenoh_session import load_credentials, write_credentials
    from deploy.compute.codegen_cache import CompiledCodeCache
    from deploy.config.files import load_settings
    from deploy.config.scenario import load_scenario

    if args.new_credentials:
        try:
            credentials = write_credentials(args.new_credentials)
        except FileExistsError:
            return error(f"agent --new-credentials {args.new_credentials}: the file exists; "
                         "give a new path")
        Output(args).progress(f"porter agent: wrote credentials for user {credentials.user} "
                              f"to {credentials.file}")
        return 0
    missing = [option for option, value in (("--index", args.index),
                                            ("--key-prefix", args.key_prefix),
                                            ("--credentials", args.credentials))
               if value is None]
    if missing:
        return error(f"agent: {', '.join(missing)} required (--credentials: the team's "
                     "user:password file, as the coordinator's)")
    try:
        credentials = load_credentials(args.credentials)
    except ValueError as failure:
        return error(str(failure))
    if args.scenario:
        scenario = load_scenario(args.scenario)
        base = load_settings(args.config, MpcSettings) if args.config else MpcSettings()
        settings, agent_count = scenario.mpc_settings(base), len(scenario.team)
        team = args.team or scenario.name
    else:
        if args.agents is None or args.agents < 1:
            return error("agent --settings needs --agents N (N >= 1): the team size the "
                         "settings were written for")
        settings, agent_count = load_settings(args.settings, MpcSettings), args.agents
        team = args.team or "porter"
    if not 0 <= args.index < agent_count:
        return error(f"agent --index must be in [0, {agent_count - 1}], got {args.index}")
    spec = LocalSolverSpec(settings, agent_count, CompiledCodeCache())
    agent = AdmmAgent(spec, AgentAddress(team, args.index, args.key_prefix, args.connect,
                                         args.listen, credentials),
                      parent_pid=args.parent_pid,
                      peer_timeout_s=args.peer_timeout)
    out = Output(args)
    out.progress(f"porter agent {args.index} of team {team!r}: problem {agent.digest}, "
                 f"serving on {args.key_prefix}")
    agent.serve()
    out.progress(f"porter agent {args.index}: {agent.solved} requests answered, "
                 f"{agent.superseded} superseded by a newer one, dropped {dict(agent.rejected)}")
    return 0
