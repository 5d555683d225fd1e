"""``porter bench nmpc``: closed-loop NMPC timing in the shape of the paper's Table I.

For each team size, in one run: the centralized NMPC and the ADMM distributed NMPC (process
executor: local solves in parallel, as on the robots) with the chosen solver, plus the ADMM
distributed NMPC with the paper-faithful ``ipopt-reference`` configuration. Every controller
drives the SRB plant through the standard scenario (0.3 m/s past CBF-active obstacles).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from core.admm_executor import LocalSolverSpec, SerialExecutor
from core.admm_mpc import DistributedMpc
from core.centralized_mpc import CentralizedMpc
from core.closed_loop import ClosedLoopResult, run_closed_loop
from core.settings import MpcSettings, SolverSettings
from core.standard_scenarios import standard_scenario
from deploy.codegen_cache import CompiledCodeCache
from deploy.process_executor import ProcessExecutor
from drivers.robot_descriptions import srb_parameters


@dataclass
class BenchRow:
    mode: str
    agents: int
    solver: str
    variables: int
    iterations_mean: float
    update_ms: dict[str, float]
    local_ms: dict[str, float] | None
    success_rate: float
    min_h_m: float

    def as_dict(self) -> dict:
        row = dict(self.__dict__)
        if row["local_ms"] is None:
            del row["local_ms"]
        return row


def _summary(values_s: list[float]) -> dict[str, float]:
    ms = 1e3 * np.asarray(values_s[1:] or values_s)  # the cold first update is not timed
    return {"mean": float(ms.mean()), "std": float(ms.std()), "median": float(np.median(ms)),
            "p95": float(np.percentile(ms, 95))}


def _row(mode: str, agents: int, solver: str, variables: int, result: ClosedLoopResult
         ) -> BenchRow:
    local = _summary(result.local_solve_time_s) if mode == "distributed" else None
    return BenchRow(mode, agents, solver, variables, float(np.mean(result.iterations[1:])),
                    _summary(result.update_time_s), local, float(np.mean(result.success)),
                    float(np.min(result.min_h_m)))


def run_bench(agent_counts: list[int], solver: str, duration_s: float, parallel: bool,
              include_reference: bool, compiled: bool = True, log=print) -> list[BenchRow]:
    rows = []
    cache = CompiledCodeCache()
    for agents in agent_counts:
        scenario = standard_scenario(agents, srb_parameters)
        team = scenario.team
        configs = [("centralized", solver), ("distributed", solver)]
        if include_reference:
            configs.append(("distributed", "ipopt-reference"))
        for mode, name in configs:
            settings = MpcSettings(solver=SolverSettings(
                name=name, compiled=compiled))
            log(f"  {agents} agents, {mode}, {name}: building (compiled code is cached)...")
            controller: CentralizedMpc | DistributedMpc
            if mode == "centralized":
                controller = CentralizedMpc(team, settings, compiler=cache)
                variables = controller.problem.nlp.variable_count
            else:
                spec = LocalSolverSpec(settings, agents, cache)
                executor = ProcessExecutor(spec) if parallel else SerialExecutor(spec)
                controller = DistributedMpc(team, settings, executor=executor)
                variables = controller.problem.nlp.variable_count
            try:
                result = run_closed_loop(controller, team, team, settings, scenario.reference,
                                         scenario.obstacles, duration_s)
            finally:
                if isinstance(controller, DistributedMpc):
                    controller.close()
            row = _row(mode, agents, name, variables, result)
            log(f"    median update {row.update_ms['median']:.2f} ms, "
                f"success {row.success_rate:.0%}, min h {row.min_h_m:.3f} m")
            rows.append(row)
    return rows


def format_table(rows: list[BenchRow]) -> str:
    """Table I layout plus local NLP time and the ratios measured in this run."""
    header = (f"{'n_A':>3} {'mode':<12} {'solver':<16} {'vars':>5} {'iters':>6} "
              f"{'upd mean':>9} {'std':>6} {'median':>7} {'p95':>7} {'local med':>9} "
              f"{'dist/cent':>9} {'ref/this':>8}")
    lines = [header, "-" * len(header)]
    for row in rows:
        cent = next((r for r in rows if r.agents == row.agents and r.mode == "centralized"
                     and r.solver == row.solver), None)
        ref = next((r for r in rows if r.agents == row.agents and r.mode == "distributed"
                    and r.solver == "ipopt-reference"), None)
        ratio = (f"{row.update_ms['mean'] / cent.update_ms['mean']:.2f}"
                 if row.mode == "distributed" and cent else "")
        speedup = (f"{ref.local_ms['median'] / row.local_ms['median']:.1f}x"  # type: ignore[index]
                   if row.local_ms and ref and ref is not row else "")
        local = f"{row.local_ms['median']:.2f}" if row.local_ms else ""
        u = row.update_ms
        lines.append(f"{row.agents:>3} {row.mode:<12} {row.solver:<16} {row.variables:>5} "
                     f"{row.iterations_mean:>6.1f} {u['mean']:>9.2f} {u['std']:>6.2f} "
                     f"{u['median']:>7.2f} {u['p95']:>7.2f} {local:>9} {ratio:>9} {speedup:>8}")
    lines.append("times in ms; 'ref/this' = ipopt-reference local NLP median / this local NLP "
                 "median; 'dist/cent' = mean update-time ratio")
    return "\n".join(lines)


def write_json(rows: list[BenchRow], path: Path) -> None:
    path.write_text(json.dumps({"rows": [r.as_dict() for r in rows]}, indent=2))
