"""The ``porter`` command line."""

from __future__ import annotations

import argparse
import math
import os
import signal
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from deploy.cli.agent_command import add_agent_parser, add_bench_agents_parser
from deploy.cli.log_arguments import add_log_parsers
from deploy.cli.paper_command import add_paper_parser
from deploy.cli.sim_arguments import add_delay_arguments, add_sim_parser, delay_settings

if TYPE_CHECKING:
    from core.nmpc.settings import MpcSettings


def positive_number(text: str) -> float:
    """An argument that must be a positive, finite number (durations, time scales)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (math.isfinite(value) and value > 0.0):
        raise argparse.ArgumentTypeError(f"must be a positive finite number, got {text}")
    return value


def loop_priority(text: str) -> int | None:
    """A SCHED_FIFO priority 1-99, or ``none`` (normal scheduling)."""
    if text.lower() in ("none", "null"):
        return None
    if not (text.isdigit() and 1 <= int(text) <= 99):
        raise argparse.ArgumentTypeError(f"must be 1-99 or none, got {text!r}")
    return int(text)


def count(text: str) -> int:
    """An argument that must be a whole number >= 1 (runs, samples, agents)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {text}")
    return value


def mpc_settings(args: argparse.Namespace) -> MpcSettings:
    """``MpcSettings`` from ``--config`` (YAML overrides of the paper defaults) or defaults."""
    from core.nmpc.settings import MpcSettings
    from deploy.config.files import load_settings

    return load_settings(args.config, MpcSettings) if args.config else MpcSettings()


def _bench_nmpc(args: argparse.Namespace) -> int:
    from deploy.bench.nmpc import (
        format_accuracy,
        format_fidelity,
        format_table,
        run_bench,
        write_json,
    )

    print(f"porter bench nmpc: agents {args.agents}, solvers {', '.join(args.solvers)}, "
          f"{args.duration} s closed loop each, {'process' if args.parallel else 'serial'} "
          "executor")
    rows, checks, fidelity = run_bench(
        args.agents, args.solvers, args.duration, args.parallel, not args.no_reference,
        compiled=not args.interpreted, base_settings=mpc_settings(args))
    print(format_table(rows))
    if checks:
        print(format_accuracy(checks))
    if fidelity:
        print(format_fidelity(fidelity))
    if args.json:
        write_json(rows, checks, Path(args.json), fidelity)
        print(f"wrote {args.json}")
    return 0


def _bench_sim(args: argparse.Namespace) -> int:
    from deploy.bench.sim import bench_scenario, format_table, write_json
    from deploy.config.scenario import shipped_scenarios
    from deploy.runtime.codegen_cache import CompiledCodeCache

    names = args.scenarios or shipped_scenarios()
    delay, executor = delay_settings(args), args.executor or "default"
    print(f"porter bench sim: {', '.join(names)}; {args.duration} s each, {executor} ADMM "
          f"executor{''.join(f', {k} {v}' for k, v in delay.items())}")
    cache = CompiledCodeCache()
    settings = mpc_settings(args)
    rows = [bench_scenario(name, args.duration, args.executor, settings, cache, delay)
            for name in names]
    print(format_table(rows))
    if args.json:
        write_json(rows, Path(args.json))
        print(f"wrote {args.json}")
    return 0


def _bench_obstacles(args: argparse.Namespace) -> int:
    from deploy.bench.obstacle_family import run_bench

    return run_bench(args.cases, args.baseline, Path(args.json) if args.json else None)


def _bench_recorder(args: argparse.Namespace) -> int:
    import json

    from deploy.bench.recorder import bench_memory, bench_overhead, format_tables
    from deploy.runtime.codegen_cache import CompiledCodeCache

    print(f"porter bench recorder: {args.scenario}, {args.duration} s x {args.repeats} runs "
          f"each with and without the recorder ({args.executor} ADMM executor); memory over "
          f"{args.memory_minutes} simulated minutes")
    rows, messages = bench_overhead(args.scenario, args.duration, args.repeats, args.executor,
                                    mpc_settings(args), CompiledCodeCache())
    memory = bench_memory(messages, args.memory_minutes) if args.memory_minutes > 0 else None
    print(format_tables(rows, memory))
    if args.json:
        Path(args.json).write_text(json.dumps({"rows": rows, "memory": memory}, indent=2) + "\n")
        print(f"wrote {args.json}")
    return 0


def _bench_drivers(args: argparse.Namespace) -> int:
    from deploy.bench.drivers import format_table, run_bench, write_json

    print(f"porter bench drivers: each shim against its fake on loopback; {args.samples} "
          f"round trips per Unitree link at 500 Hz, {args.stream_samples} NatNet frames "
          "(120 Hz) and CAN samples (100 Hz)")
    rows, counters = run_bench(args.samples, args.stream_samples, args.domain)
    print(format_table(rows))
    if args.json:
        write_json(rows, counters, Path(args.json))
        print(f"wrote {args.json}")
    return 0


def _bench_wbc(args: argparse.Namespace) -> int:
    import json

    from deploy.bench.wbc_tick import format_table, run_bench

    print(f"porter bench wbc: {args.ticks} WBC ticks of {args.scenario}'s team per pace")
    rows = run_bench(args.ticks, args.scenario)
    print(format_table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({"rows": rows}, indent=2))
        print(f"wrote {args.json}")
    return 0


def _bench_deploy(args: argparse.Namespace) -> int:
    import json

    from deploy.bench.deploy_runs import completion, format_budget, format_table, run_bench

    print(f"porter bench deploy: {args.config} on the sim backend, time scales "
          f"{', '.join(f'{s:g}' for s in args.time_scales)}, {args.runs} run(s) each, "
          f"{args.duration:g} s running (plus pre-flight, stand-up and sit-down)")
    rows = run_bench(args.config, args.time_scales, args.runs, args.duration,
                     args.loop_priority)
    print(format_table(rows))
    print()
    print(format_budget(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({"rows": rows, "completion": completion(rows)},
                                              indent=2) + "\n")
        print(f"wrote {args.json}")
    return 0


def _sim(args: argparse.Namespace) -> int:
    from deploy.cli.sim_command import run_sim

    return run_sim(args, mpc_settings(args))


def _deploy(args: argparse.Namespace) -> int:
    from deploy.cli.deploy_command import run_deploy

    return run_deploy(args)


def _drill(args: argparse.Namespace) -> int:
    from deploy.cli.drill_command import run_drill

    return run_drill(args)


def _replay(args: argparse.Namespace) -> int:
    from deploy.cli.replay_command import run_replay

    return run_replay(args)


def _regress(args: argparse.Namespace) -> int:
    from deploy.recording.regression import run_regress

    return run_regress(args)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="porter", description="Quadruped teams carrying one payload: simulate, deploy, "
        "replay and check runs.")
    parser.add_argument("--version", action="version", version=f"porter {_porter_version()}")
    commands = parser.add_subparsers(dest="command", required=True)

    drill = commands.add_parser(
        "drill", help="the fault suite on the sim backend: every fault detected, only damping "
        "after detection, logs readable",
        description="Inject each fault into a short porter deploy on the sim backend and judge "
        "it from outside; prints one table row per fault. Exit 0 when all were handled.")
    drill.add_argument("faults", nargs="*", help="run the faults whose names contain these "
                       "(default: all)")
    drill.add_argument("--keep", help="folder for each fault's config, log and output "
                       "(default: a temporary one)")
    drill.add_argument("--json", help="also write the rows as JSON {rows: [...]}")
    drill.set_defaults(handler=_drill)

    bench = commands.add_parser("bench", help="benchmarks that print tables")
    bench_kinds = bench.add_subparsers(dest="bench", required=True)
    add_bench_agents_parser(bench_kinds)
    nmpc = bench_kinds.add_parser("nmpc", help="centralized vs ADMM NMPC update times")
    nmpc.add_argument("--agents", type=count, nargs="+", default=[2, 3, 4])
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
    nmpc.add_argument("--json", help="also write the figures as JSON {rows: [...]}")
    nmpc.add_argument("--config", help="YAML file overriding MpcSettings fields")
    nmpc.set_defaults(handler=_bench_nmpc)

    bench_sim = bench_kinds.add_parser("sim", help="real-time factor and loop times in MuJoCo")
    bench_sim.add_argument("scenarios", nargs="*", help="scenario names (default: all shipped)")
    bench_sim.add_argument("--duration", type=positive_number, default=5.0,
                           help="simulated seconds per scenario")
    bench_sim.add_argument("--executor", choices=["process", "serial", "zenoh"],
                           help="default: process; serial with --overlap")
    bench_sim.add_argument("--json", help="also write the rows as JSON {rows: [...]}")
    bench_sim.add_argument("--config", help="YAML file overriding MpcSettings fields")
    add_delay_arguments(bench_sim)
    bench_sim.set_defaults(handler=_bench_sim)

    bench_obs = bench_kinds.add_parser("obstacles", help="moving, head-on and symmetric "
                                       "obstacle cases: outcome, min h, relaxed plans")
    bench_obs.add_argument("cases", nargs="*", help="case names (default: all)")
    bench_obs.add_argument("--baseline", action="store_true",
                           help="hard barriers, no braking backup, no reference governor")
    bench_obs.add_argument("--json", help="also write the rows as JSON {rows: [...]}")
    bench_obs.set_defaults(handler=_bench_obstacles)

    bench_rec = bench_kinds.add_parser("recorder", help="flight-recorder overhead, rate, size, "
                                       "memory")
    bench_rec.add_argument("--scenario", default="two_go2")
    bench_rec.add_argument("--duration", type=positive_number, default=4.0,
                           help="simulated s per run")
    bench_rec.add_argument("--repeats", type=count, default=2, help="runs per configuration")
    bench_rec.add_argument("--executor", default="process", choices=["process", "serial"])
    bench_rec.add_argument("--memory-minutes", type=positive_number, default=30.0,
                           help="simulated minutes for the memory check (0: skip)")
    bench_rec.add_argument("--json", help="also write the figures as JSON")
    bench_rec.add_argument("--config", help="YAML file overriding MpcSettings fields")
    bench_rec.set_defaults(handler=_bench_recorder)

    bench_drv = bench_kinds.add_parser("drivers", help="latency and jitter of each driver shim "
                                       "against its fake on loopback")
    bench_drv.add_argument("--samples", type=count, default=2000,
                           help="round trips per Unitree link (Go2 DDS, A1 UDP)")
    bench_drv.add_argument("--stream-samples", type=count, default=600,
                           help="NatNet frames and CAN samples")
    bench_drv.add_argument("--domain", type=int, default=0, help="DDS domain id (loopback)")
    bench_drv.add_argument("--json", help="also write the rows and the peers' counters as JSON")
    bench_drv.set_defaults(handler=_bench_drivers)

    bench_dep = bench_kinds.add_parser("deploy", help="WBC and NMPC loop timing of porter "
                                       "deploy --backend sim per time scale")
    bench_dep.add_argument("--config", default="two_go2",
                           help="deploy config (path or shipped name; default two_go2)")
    bench_dep.add_argument("--time-scales", type=positive_number, nargs="+", default=[0.1, 1.0],
                           help="sim.time_scale values (default 0.1 1.0)")
    bench_dep.add_argument("--runs", type=count, default=1, help="runs per time scale")
    bench_dep.add_argument("--loop-priority", type=loop_priority, nargs="+", default=None,
                           help="rates.loop_priority values to compare, alternating: 1-99 or "
                                "none (default: the config's own)")
    bench_dep.add_argument("--duration", type=positive_number, default=3.0,
                           help="seconds running once armed (simulated)")
    bench_dep.add_argument("--json", help="also write the rows as JSON")
    bench_dep.set_defaults(handler=_bench_deploy)

    bench_wbc = bench_kinds.add_parser("wbc", help="work of the 500 Hz WBC tick, back to "
                                       "back and paced")
    bench_wbc.add_argument("--ticks", type=count, default=1000, help="ticks per pace")
    bench_wbc.add_argument("--scenario", default="two_go2", help="whose team (shipped name)")
    bench_wbc.add_argument("--json", help="also write the rows as JSON {rows: [...]}")
    bench_wbc.set_defaults(handler=_bench_wbc)

    add_sim_parser(commands, _sim, positive_number, count)

    deploy = commands.add_parser(
        "deploy", help="run the team on robots (or on the simulated world behind the same "
        "drivers)", description="Pre-flight, stand up, arm (asks unless --yes), carry the "
        "payload, sit down; any fault safe-stops the team. Exit 0 done, 3 safe stop, 130 "
        "stopped by the operator.")
    deploy.add_argument("--config", required=True, metavar="CONFIG.yaml",
                        help="deploy config (deploy/config/deployments/*.yaml) or a shipped "
                             "config's name")
    deploy.add_argument("--backend", choices=["hw", "sim"], default="hw",
                        help="hw: the robots; sim: MuJoCo behind fakes on loopback (default hw)")
    deploy.add_argument("--yes", action="store_true", help="arm without asking the operator")
    deploy.add_argument("--duration", type=positive_number, metavar="S",
                        help="seconds to run once armed (default: the scenario's duration_s)")
    deploy.add_argument("--record", metavar="LOG.mcap",
                        help="flight log (default runs/deploy-<scenario>-<time>.mcap)")
    deploy.add_argument("--json", metavar="FILE", help="also write the summary as JSON")
    deploy.add_argument("--no-record", action="store_true",
                        help="no flight log (--backend sim only)")
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
    except ConfigError as error:
        print(f"porter: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("porter: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # The reader went away (`porter log info LOG | head`): what it wanted was printed.
        # Point stdout at /dev/null so the interpreter's final flush does not fail again.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    sys.exit(main())
