"""``porter bench KIND``: each benchmark's command line and how its table and JSON come out
(``deploy.cli.conventions``); the benches themselves are ``deploy.bench.*``."""

from __future__ import annotations

import argparse
from collections.abc import Callable

from deploy.cli.conventions import Output, add_output_options, number_in, whole_number_in
from deploy.cli.sim_arguments import add_delay_arguments, delay_settings

__all__ = ["add_bench_parser"]

Number = Callable[[str], float]


def _bench_nmpc(args: argparse.Namespace) -> int:
    from deploy.bench.nmpc import format_accuracy, format_fidelity, format_table, run_bench
    from deploy.cli.porter import mpc_settings

    out = Output(args)
    out.progress(f"porter bench nmpc: agents {args.agents}, solvers {', '.join(args.solvers)}, "
                 f"{args.duration} s closed loop each, "
                 f"{'process' if args.parallel else 'serial'} executor")
    rows, checks, fidelity = run_bench(
        args.agents, args.solvers, args.duration, args.parallel, not args.no_reference,
        compiled=not args.interpreted, base_settings=mpc_settings(args))
    out.report(format_table(rows))
    if checks:
        out.report(format_accuracy(checks))
    if fidelity:
        out.report(format_fidelity(fidelity))
    out.write_json({"rows": [r.as_dict() for r in rows], "accuracy": [c.__dict__ for c in checks],
                    "rti_fidelity": [f.__dict__ for f in fidelity or []]})
    return 0


def _bench_sim(args: argparse.Namespace) -> int:
    from deploy.bench.sim import bench_scenario, format_table
    from deploy.cli.porter import mpc_settings
    from deploy.compute.codegen_cache import CompiledCodeCache
    from deploy.config.scenario import shipped_scenarios

    out = Output(args)
    names = args.scenarios or shipped_scenarios()
    delay, executor = delay_settings(args), args.executor or "default"
    out.progress(f"porter bench sim: {', '.join(names)}; {args.duration} s each, {executor} "
                 f"ADMM executor{''.join(f', {k} {v}' for k, v in delay.items())}")
    cache = CompiledCodeCache()
    settings = mpc_settings(args)
    rows = [bench_scenario(name, args.duration, args.executor, settings, cache, delay)
            for name in names]
    out.report(format_table(rows))
    out.write_json({"rows": rows})
    return 0


def _bench_obstacles(args: argparse.Namespace) -> int:
    from deploy.bench.obstacle_family import run_bench

    return run_bench(args.cases, args.baseline, Output(args))


def _bench_recorder(args: argparse.Namespace) -> int:
    from deploy.bench.recorder import bench_memory, bench_overhead, format_tables
    from deploy.cli.porter import mpc_settings
    from deploy.compute.codegen_cache import CompiledCodeCache

    out = Output(args)
    out.progress(f"porter bench recorder: {args.scenario}, {args.duration} s x {args.repeats} "
                 f"runs each with and without the recorder ({args.executor} ADMM executor); "
                 f"memory over {args.memory_minutes} simulated minutes")
    rows, messages = bench_overhead(args.scenario, args.duration, args.repeats, args.executor,
                                    mpc_settings(args), CompiledCodeCache())
    memory = bench_memory(messages, args.memory_minutes) if args.memory_minutes > 0 else None
    out.report(format_tables(rows, memory))
    out.write_json({"rows": rows, "memory": memory})
    return 0


def _bench_drivers(args: argparse.Namespace) -> int:
    from deploy.bench.drivers import format_table, run_bench

    out = Output(args)
    out.progress(f"porter bench drivers: each shim against its fake on loopback; "
                 f"{args.samples} round trips per Unitree link at 500 Hz, {args.stream_samples} "
                 "NatNet frames (120 Hz) and CAN samples (100 Hz)")
    rows, counters = run_bench(args.samples, args.stream_samples, args.domain)
    out.report(format_table(rows))
    out.write_json({"rows": rows, "peers": counters})
    return 0


def _bench_wbc(args: argparse.Namespace) -> int:
    from deploy.bench.wbc_tick import format_table, run_bench

    out = Output(args)
    out.progress(f"porter bench wbc: {args.ticks} WBC ticks of {args.scenario}'s team per pace")
    rows = run_bench(args.ticks, args.scenario)
    out.report(format_table(rows))
    out.write_json({"rows": rows})
    return 0


def _bench_deploy(args: argparse.Namespace) -> int:
    from deploy.bench.deploy_runs import completion, format_budget, format_table, run_bench

    out = Output(args)
    out.progress(f"porter bench deploy: {args.config} on the sim backend, time scales "
                 f"{', '.join(f'{s:g}' for s in args.time_scales)}, {args.runs} run(s) each, "
                 f"{args.duration:g} s running (plus pre-flight, stand-up and sit-down)")
    rows = run_bench(args.config, args.time_scales, args.runs, args.duration,
                     args.loop_priority)
    out.report(format_table(rows) + "\n\n" + format_budget(rows))
    out.write_json({"rows": rows, "completion": completion(rows)})
    return 0


def _bench_agents(args: argparse.Namespace) -> int:
    from deploy.bench.agents import run_bench

    return run_bench(args, Output(args))


def add_bench_parser(commands: argparse._SubParsersAction, positive_number: Number,
                     count: Callable[[str], int],
                     loop_priority: Callable[[str], int | None]) -> None:
    bench = commands.add_parser(
        "bench", help="benchmarks that print tables",
        description="Measure one part of porter and print its table (run a bench alone: "
                    "timings on a shared machine measure the machine).")
    kinds = bench.add_subparsers(dest="bench", required=True, metavar="KIND")

    def kind(name: str, help_text: str, description: str, handler: Callable, report: str
             ) -> argparse.ArgumentParser:
        parser = kinds.add_parser(name, help=help_text, description=description)
        add_output_options(parser, report)
        parser.set_defaults(handler=handler)
        return parser

    agents = kind("agents", "ADMM messages over Zenoh vs the pipe executor",
                  "Round trips of one ADMM request over Zenoh and over the process "
                  "executor's pipes, then closed-loop ADMM updates with each, alternated.",
                  _bench_agents, "the figures")
    agents.add_argument("scenario", nargs="?", default="two_go2",
                        help="shipped scenario whose team and NLP to use (default two_go2)")
    agents.add_argument("--messages", type=count, default=500, help="round trips per transport")
    agents.add_argument("--duration", type=positive_number, default=3.0,
                        help="closed-loop seconds per run")
    agents.add_argument("--repeats", type=count, default=2, help="runs per executor")

    nmpc = kind("nmpc", "centralized vs ADMM NMPC update times",
                "Closed-loop NMPC update times per team size and solver, centralized and "
                "distributed, with accuracy checks against a converged reference.",
                _bench_nmpc, "the rows, accuracy checks and rti fidelity")
    nmpc.add_argument("--agents", type=count, nargs="+", default=[2, 3, 4],
                      help="team sizes, one row each (default 2 3 4)")
    nmpc.add_argument("--solvers", nargs="+", default=["fatrop", "rti"],
                      choices=["fatrop", "rti", "ipopt"],
                      help="solvers with centralized and distributed rows")
    nmpc.add_argument("--duration", type=positive_number, default=6.0,
                      help="closed-loop seconds per row")
    nmpc.add_argument("--serial", dest="parallel", action="store_false",
                      help="run ADMM local solves serially instead of one process per agent")
    nmpc.add_argument("--no-reference", action="store_true",
                      help="skip the paper-faithful ipopt-reference rows")
    nmpc.add_argument("--interpreted", action="store_true",
                      help="do not compile derivative code (quick smoke runs; slower solves)")
    nmpc.add_argument("--config", help="YAML file overriding MpcSettings fields")

    sim = kind("sim", "real-time factor and loop times in MuJoCo",
               "Each scenario in lockstep on MuJoCo: real-time factor, WBC tick and NMPC "
               "update times, deadline misses, and where the loop's time goes.",
               _bench_sim, "the rows")
    sim.add_argument("scenarios", nargs="*", help="scenario names (default: all shipped)")
    sim.add_argument("--duration", type=positive_number, default=5.0,
                     help="simulated seconds per scenario")
    sim.add_argument("--executor", choices=["process", "serial", "zenoh"],
                     help="where local solves run (default: process; serial with --overlap)")
    sim.add_argument("--config", help="YAML file overriding MpcSettings fields")
    add_delay_arguments(sim)

    obstacles = kind("obstacles", "moving, head-on and symmetric obstacle cases",
                     "Each obstacle case in closed loop: outcome, smallest barrier value, "
                     "relaxed plans, braking and the stop's cause.", _bench_obstacles,
                     "the rows")
    obstacles.add_argument("cases", nargs="*", help="case names (default: all)")
    obstacles.add_argument("--baseline", action="store_true",
                           help="hard barriers, no braking backup, no reference governor")

    recorder = kind("recorder", "flight-recorder overhead, rate, size, memory",
                    "A scenario with and without the flight recorder (its cost per tick), "
                    "the log's rate and size, and the writer's memory over a long run.",
                    _bench_recorder, "the figures")
    recorder.add_argument("--scenario", default="two_go2", help="shipped scenario name")
    recorder.add_argument("--duration", type=positive_number, default=4.0,
                          help="simulated s per run")
    recorder.add_argument("--repeats", type=count, default=2, help="runs per configuration")
    recorder.add_argument("--executor", default="process", choices=["process", "serial"],
                          help="where the ADMM local solves run")
    recorder.add_argument("--memory-minutes", type=number_in(0.0, 1440.0), default=30.0,
                          help="simulated minutes for the memory check (0: skip)")
    recorder.add_argument("--config", help="YAML file overriding MpcSettings fields")

    drivers = kind("drivers", "latency and jitter of each driver shim against its fake",
                   "Round trips of the Go2 DDS and A1 UDP drivers against their fakes on "
                   "loopback, and NatNet and CAN streams, with the peers' counters.",
                   _bench_drivers, "the rows and the peers' counters")
    drivers.add_argument("--samples", type=count, default=2000,
                         help="round trips per Unitree link (Go2 DDS, A1 UDP)")
    drivers.add_argument("--stream-samples", type=count, default=600,
                         help="NatNet frames and CAN samples")
    drivers.add_argument("--domain", type=whole_number_in(0, 232), default=0,
                         help="DDS domain id (loopback)")

    deploy = kind("deploy", "WBC and NMPC loop timing of porter deploy --backend sim",
                  "porter deploy --backend sim per time scale and run: completion, loop and "
                  "NMPC rates, late updates, world holds and CPU per simulated second.",
                  _bench_deploy, "the rows and the completion count")
    deploy.add_argument("--config", default="two_go2",
                        help="deploy config (path or shipped name; default two_go2)")
    deploy.add_argument("--time-scales", type=positive_number, nargs="+", default=[0.1, 1.0],
                        help="sim.time_scale values (default 0.1 1.0)")
    deploy.add_argument("--runs", type=count, default=1, help="runs per time scale")
    deploy.add_argument("--loop-priority", type=loop_priority, nargs="+", default=None,
                        help="rates.loop_priority values to compare, alternating: 1-99 or "
                             "none (default: the config's own)")
    deploy.add_argument("--duration", type=positive_number, default=3.0,
                        help="seconds running once armed (simulated)")

    wbc = kind("wbc", "work of the 500 Hz WBC tick, back to back and paced",
               "The team's WBC tick stage by stage, back to back and paced at 500 Hz.",
               _bench_wbc, "the rows")
    wbc.add_argument("--ticks", type=count, default=1000, help="ticks per pace")
    wbc.add_argument("--scenario", default="two_go2", help="whose team (shipped name)")
