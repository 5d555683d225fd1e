"""``porter bench agents``: ADMM messages over Zenoh beside the pipe executor, in one run.

1. Round trip of one local-solve message on loopback: a request of the scenario's local NLP
   (its real sizes) to a peer process that decodes it and answers with a solution of the real
   size, back and decoded: over Zenoh (protobuf, ``deploy.agents.wire``) and over a
   multiprocessing pipe (pickled, as ``deploy.nmpc_runtime.process_executor`` sends them).
2. The closed-loop 2-agent ADMM update of a scenario with each executor, alternated.
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import threading
import time
from multiprocessing.connection import Connection

import numpy as np

from core.admm.admm_executor import LocalSolveRequest
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from core.nmpc.transport_problem import build_transport_problem
from deploy.agents import wire
from deploy.agents.zenoh_session import concrete_endpoint, open_session
from deploy.bench.sim import bench_scenario
from deploy.cli.conventions import Output
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.reports.table import Column, render_table

TEAM = "bench"
_STATS = SolveStats("Solve_Succeeded", True, 1, 0.0, 0.0, 0.0)


def _solution(sizes: wire.ProblemSizes) -> NlpSolution:
    return NlpSolution(np.ones(sizes.decision), np.ones(sizes.constraints),
                       np.ones(sizes.decision), _STATS)


def _request(sizes: wire.ProblemSizes) -> LocalSolveRequest:
    rng = np.random.default_rng(0)
    n = sizes.decision
    return LocalSolveRequest(0, rng.normal(size=n), rng.normal(size=sizes.parameters),
                             np.full(n, -1e3), np.full(n, 1e3),
                             rng.normal(size=sizes.constraints), rng.normal(size=n))


def _pipe_peer(connection: Connection, sizes: wire.ProblemSizes) -> None:
    answer = _solution(sizes)
    while (message := connection.recv()) is not None:
        connection.send((message[0], answer))


def _zenoh_peer(endpoint: str, sizes: wire.ProblemSizes, ready: object) -> None:
    session = open_session([], [endpoint])
    answer = _solution(sizes)
    done = threading.Event()

    def on_request(sample: object) -> None:
        sequence, request = wire.decode_request(sample.payload.to_bytes(),  # type: ignore[attr-defined]
                                                TEAM, 1, "bench", sizes)
        if request is None:
            done.set()
            return
        assert isinstance(request, LocalSolveRequest)  # the bench sends no peer requests
        session.put("bench/reply", wire.encode_reply(answer, TEAM, 0, sequence, request))

    session.declare_subscriber("bench/request", on_request)
    ready.set()  # type: ignore[attr-defined]
    done.wait()
    session.close()


WARMUP = 20  # round trips not counted: the peer's first messages include its start


def round_trips(sizes: wire.ProblemSizes, count: int) -> dict[str, list[float]]:
    """Round-trip times [s] of one local-solve message over a pipe and over Zenoh (after
    ``WARMUP`` uncounted ones each)."""
    context = mp.get_context("spawn")
    request = _request(sizes)
    times: dict[str, list[float]] = {"pipe": [], "zenoh": []}
    parent, child = context.Pipe()
    peer = context.Process(target=_pipe_peer, args=(child, sizes), daemon=True)
    peer.start()
    for i in range(WARMUP + count):
        start = time.perf_counter()
        parent.send((i, request))
        parent.recv()
        times["pipe"].append(time.perf_counter() - start)
    del times["pipe"][:WARMUP]
    parent.send(None)
    peer.join(5)

    endpoint = concrete_endpoint("tcp/127.0.0.1:0")
    session = open_session([endpoint], [])
    ready = context.Event()
    peer = context.Process(target=_zenoh_peer, args=(endpoint, sizes, ready), daemon=True)
    peer.start()
    arrived = threading.Event()

    def on_reply(sample: object) -> None:
        wire.decode_reply(sample.payload.to_bytes(), TEAM, 1, sizes)  # type: ignore[attr-defined]
        arrived.set()

    session.declare_subscriber("bench/reply", on_reply)
    publisher = session.declare_publisher("bench/request")
    ready.wait(60)
    time.sleep(0.5)  # the peers' routes settle
    for i in range(WARMUP + count):
        arrived.clear()
        start = time.perf_counter()
        publisher.put(wire.encode_request(request, TEAM, i + 1, "bench"))
        if not arrived.wait(5.0):
            raise RuntimeError("the Zenoh peer did not answer in 5 s")
        times["zenoh"].append(time.perf_counter() - start)
    del times["zenoh"][:WARMUP]
    publisher.put(wire.encode_stop(TEAM, 0, "bench"))
    peer.join(5)
    session.close()
    return times


def _figures(values: list[float], scale: float = 1e3) -> dict[str, float]:
    array = np.asarray(values) * scale
    return {"median": float(np.median(array)), "p95": float(np.percentile(array, 95)),
            "p99": float(np.percentile(array, 99)), "count": len(values)}


def run_bench(args: argparse.Namespace, out: Output) -> int:
    scenario = load_scenario(args.scenario)
    settings = scenario.mpc_settings()
    sizes = wire.ProblemSizes.of(
        build_transport_problem(settings, len(scenario.team), local=True).nlp)
    request_bytes = len(wire.encode_request(_request(sizes), TEAM, 1, "bench"))
    out.progress(f"porter bench agents: {args.scenario}, local NLP {sizes.decision} variables, "
                 f"request {request_bytes} bytes; {args.messages} round trips; then "
                 f"{args.repeats} x {args.duration:g} s closed loop per executor, alternated")
    trips = {k: _figures(v) for k, v in round_trips(sizes, args.messages).items()}
    cache = CompiledCodeCache()
    updates: dict[str, list[float]] = {"process": [], "zenoh": []}
    loops: dict[str, list[dict]] = {"process": [], "zenoh": []}
    for _ in range(args.repeats):
        for executor in ("process", "zenoh"):
            summary = bench_scenario(args.scenario, args.duration, executor, settings, cache)
            loops[executor].append(summary)
            updates[executor].append(summary["nmpc_update_ms"]["median"])
    cells = []
    for executor, label in (("pipe", "round trip, pipe"), ("zenoh", "round trip, Zenoh")):
        f = trips[executor]
        cells.append([label, f"{f['median']:.3f}", f"{f['p95']:.3f}", f"{f['p99']:.3f}"])
    for executor, label in (("process", "ADMM update, pipe executor"),
                            ("zenoh", "ADMM update, Zenoh agents")):
        median = float(np.median(updates[executor]))
        p95 = float(np.median([s["nmpc_update_ms"]["p95"] for s in loops[executor]]))
        cells.append([label, f"{median:.2f}", f"{p95:.2f}", ""])
    gap = float(np.median(updates["zenoh"]) - np.median(updates["process"]))
    out.report(render_table(
        ["", *(Column(n, "right") for n in ("median ms", "p95 ms", "p99 ms"))], cells)
        + f"\nZenoh - pipe, ADMM update median: {gap:+.2f} ms (target within 1.5 ms); update "
        "figures are the median over repeats of each run's median (p95 likewise)")
    out.write_json({
        "round_trip_ms": trips, "request_bytes": request_bytes,
        "admm_update_ms": {k: [s["nmpc_update_ms"] for s in v] for k, v in loops.items()},
        "zenoh_minus_pipe_update_median_ms": gap})
    return 0
