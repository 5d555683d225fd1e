"""``porter sim`` on the SRB plant backend: the standard scenario in closed loop, with a summary.

The MuJoCo backend (issue "The team in physics") is not built yet; until it is, ``porter sim``
runs the controller against the coupled SRB plant of ``core.srb_plant`` and says so.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from core.admm_mpc import DistributedMpc
from core.centralized_mpc import CentralizedMpc
from core.closed_loop import ClosedLoopResult, run_closed_loop
from core.settings import MpcSettings
from core.standard_scenarios import standard_scenario
from deploy.codegen_cache import CompiledCodeCache
from drivers.robot_descriptions import srb_parameters

DEADLINE_S = 1.0 / 60.0


def summarize(name: str, result: ClosedLoopResult, goal_m: np.ndarray, wall_s: float
              ) -> dict:
    duration = len(result.times_s) / 60.0
    updates = 1e3 * np.asarray(result.update_time_s)
    final = result.final_payload_state
    reached = bool(final is not None and np.linalg.norm(final[0:2] - goal_m) < 0.1)
    summary = {
        "scenario": name,
        "backend": "srb-plant",
        "duration_s": duration,
        "reached_goal": reached,
        "min_h_m": float(np.min(result.min_h_m)),
        "rms_payload_position_error_m": float(np.sqrt(np.mean(
            np.square(result.payload_position_error_m)))),
        "rms_payload_yaw_error_rad": float(np.sqrt(np.mean(
            np.square(result.payload_yaw_error_rad)))),
        "max_coupling_error_m": float(np.max(result.coupling_error_m)),
        "admm_residual_rms": {
            "payload_state": float(np.sqrt(np.mean(np.square(result.primal_payload_rms))))
            if result.primal_payload_rms else None,
            "wrench": float(np.sqrt(np.mean(np.square(result.primal_wrench_rms))))
            if result.primal_wrench_rms else None,
        },
        "nmpc_update_ms": {"median": float(np.median(updates)),
                           "p95": float(np.percentile(updates, 95)),
                           "max": float(np.max(updates))},
        "deadline_misses": int(np.sum(updates > 1e3 * DEADLINE_S)),
        "failed_solves": int(np.sum(result.failed_solves)),
        "flagged_plans": int(len(result.success) - np.sum(result.success)),
        "real_time_factor": duration / wall_s if wall_s > 0 else float("inf"),
    }
    return summary


def run_srb_sim(args: argparse.Namespace, settings: MpcSettings) -> int:
    scenario = standard_scenario(args.agents, srb_parameters)
    cache = CompiledCodeCache()
    print(f"porter sim: standard scenario, {args.agents} agents, {args.mode} NMPC, "
          "SRB plant backend (MuJoCo backend not built yet); first start compiles the NLP")
    if args.mode == "centralized":
        controller: CentralizedMpc | DistributedMpc = CentralizedMpc(
            scenario.team, settings, compiler=cache)
    else:
        controller = DistributedMpc(scenario.team, settings, compiler=cache)
    start = time.perf_counter()
    result = run_closed_loop(controller, scenario.team, scenario.team, settings,
                             scenario.reference, scenario.obstacles, args.duration)
    summary = summarize(f"standard-{args.agents}", result, scenario.reference.goal_m(),
                        time.perf_counter() - start)
    print(json.dumps(summary, indent=2))
    if args.json:
        Path(args.json).write_text(json.dumps(summary, indent=2))
    return 0
