"""``porter bench nmpc``: closed-loop NMPC timing in the shape of the paper's Table I.

For each team size, in one run: the centralized NMPC and the ADMM distributed NMPC (process
executor: local solves in parallel, as on the robots) with each chosen solver (default
``fatrop`` and ``rti``), today's fatrop path (CasADi's generic BLASFEO), and the ADMM
distributed NMPC with the paper-faithful ``ipopt-reference`` configuration. Every controller
drives the SRB plant through the standard scenario (0.3 m/s past CBF-active obstacles).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from core.admm.admm_executor import LocalSolverSpec, SerialExecutor
from core.admm.admm_mpc import DistributedMpc
from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.settings import MpcSettings, SolverSettings
from core.nmpc.transport_problem import build_transport_problem
from core.nmpc.warm_start import initial_guess
from core.plant.closed_loop import ClosedLoopResult, run_closed_loop
from core.plant.standard_scenarios import standard_scenario
from deploy.bench.rti_fidelity import RtiFidelity, rti_fidelity
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.nmpc_runtime.process_executor import ProcessExecutor
from deploy.reports.table import Column, render_table
from drivers.robot_descriptions import srb_parameters

GENERIC_SUFFIX = "/generic-blas"  # label of the rows on CasADi's generic BLASFEO


@dataclass
class AccuracyCheck:
    """Same local NLP, same parameters and initial guess, solved by this solver and by
    ipopt-reference: largest differences over the sampled NMPC decisions."""

    agents: int
    solver: str
    samples: int
    max_grf_difference_n: float
    max_payload_position_difference_m: float
    max_objective_relative_difference: float


def accuracy_check(team, settings: MpcSettings, inputs_samples: list, cache
                   ) -> AccuracyCheck:
    """Solve agent 0's local NLP of each sampled decision with both configurations."""
    reference = MpcSettings(solver=SolverSettings(name="ipopt-reference"))
    fast = LocalSolverSpec(settings, team.agent_count, cache).build()
    slow = LocalSolverSpec(reference, team.agent_count, cache).build()
    problem = build_transport_problem(settings, team.agent_count, local=True)
    grf, payload, objective = 0.0, 0.0, 0.0
    layout = problem.nlp.decision
    for inputs in inputs_samples:
        guess = initial_guess(problem, team, inputs, None, agent=0)
        target = problem.shared_trajectory(guess)
        parameters = problem.parameter_vector(team, inputs, agent=0, consensus_target=target)
        bounds = problem.decision_bounds(inputs.contacts, agent=0, inputs=inputs)
        a = fast.solve(guess, parameters, *bounds, warm_start=False)
        b = slow.solve(guess, parameters, *bounds, warm_start=False)
        grf = max(grf, float(np.max(np.abs(layout.get(a.decision, "grf_self@0")
                                           - layout.get(b.decision, "grf_self@0")))))
        payload = max(payload, max(float(np.max(np.abs(
            layout.get(a.decision, f"payload@{k}")[0:3] - layout.get(b.decision, f"payload@{k}")[0:3])))
            for k in range(problem.horizon_steps + 1)))
        objective = max(objective, abs(a.stats.objective - b.stats.objective)
                        / max(abs(b.stats.objective), 1e-12))
    return AccuracyCheck(team.agent_count, settings.solver.name, len(inputs_samples), grf,
                         payload, objective)


class _SampleRecorder:
    """Wraps ``update``: keeps every 20th decision's inputs (at most 10) and each update's CPU
    time [s], this process's plus, with worker processes (``workers``), their solves'."""

    def __init__(self, update, workers: bool, here: tuple[int, ...] = (), agents: int = 1
                 ) -> None:
        self.update = update
        self.workers = workers
        self.here, self.agents = here, agents  # solves of these agents are this process's CPU
        self.samples: list = []
        self.cpu_s: list[float] = []
        self.seen = 0

    def __call__(self, inputs):
        if self.seen % 20 == 0 and len(self.samples) < 10:
            self.samples.append(inputs)
        self.seen += 1
        start = time.process_time()
        plan = self.update(inputs)
        cpu = time.process_time() - start
        if self.workers:  # solves are ordered agent by agent within each ADMM iteration
            cpu += sum(s.cpu_time_s for i, s in enumerate(plan.solves)
                       if i % self.agents not in self.here)
        self.cpu_s.append(cpu)
        return plan


@dataclass
class BenchRow:
    mode: str
    agents: int
    solver: str
    variables: int
    iterations_mean: float
    update_ms: dict[str, float]
    cpu_ms: dict[str, float]  # CPU per update, summed over the processes that worked on it
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


def _row(mode: str, agents: int, solver: str, variables: int, result: ClosedLoopResult,
         cpu_s: list[float]) -> BenchRow:
    local = _summary(result.local_solve_time_s) if mode == "distributed" else None
    return BenchRow(mode, agents, solver, variables, float(np.mean(result.iterations[1:])),
                    _summary(result.update_time_s), _summary(cpu_s), local,
                    float(np.mean(result.success)), float(np.min(result.min_h_m)))


def _with_solver(base: MpcSettings | None, name: str, compiled: bool) -> MpcSettings:
    """``base`` (or the defaults) with solver ``name``, compiled or not."""
    base = base or MpcSettings()
    return base.model_copy(update={"solver": base.solver.model_copy(
        update={"name": name, "compiled": compiled})})


def run_bench(agent_counts: list[int], solvers: list[str], duration_s: float, parallel: bool,
              include_reference: bool, compiled: bool = True, log=print,
              base_settings: MpcSettings | None = None,
              reference_modes: tuple[str, ...] = ("distributed",), with_checks: bool = True
              ) -> tuple[list[BenchRow], list[AccuracyCheck], list[RtiFidelity]]:
    """Per team size: centralized and distributed rows of every solver, today's fatrop path
    (CasADi's generic BLASFEO, process executor) and ipopt-reference (in
    ``reference_modes``), in this one run; for ``rti``, its closed-loop distance from
    converged solves at the first team size (``with_checks``: the accuracy and rti checks)."""
    rows = []
    checks = []
    fidelity = []
    cache = CompiledCodeCache()
    kernels = cache.blas_kernels()
    log(f"  BLAS kernels under fatrop/hpipm: BLASFEO {kernels.target}"
        + (f" ({kernels.reason})" if kernels.reason else ""))
    for agents in agent_counts:
        scenario = standard_scenario(agents, srb_parameters)
        team = scenario.team
        configs = []
        for solver in solvers:
            configs += [("centralized", solver, cache), ("distributed", solver, cache)]
        if "fatrop" in solvers and parallel and compiled and kernels.optimized:
            # Today's fatrop path in the same run: workers on CasADi's generic BLASFEO.
            configs.append(("distributed", "fatrop", CompiledCodeCache(blas_target="generic")))
        if include_reference:
            configs += [(mode, "ipopt-reference", cache) for mode in reference_modes]
        for mode, name, row_cache in configs:
            settings = _with_solver(base_settings, name, compiled)
            label = name if row_cache is cache else f"{name}{GENERIC_SUFFIX}"
            log(f"  {agents} agents, {mode}, {label}: building (compiled code is cached)...")
            controller: CentralizedMpc | DistributedMpc
            if mode == "centralized":
                controller = CentralizedMpc(team, settings, compiler=cache)
                variables = controller.problem.nlp.variable_count
            else:
                spec = LocalSolverSpec(settings, agents, row_cache)
                # (today's path keeps every solve in workers: this process loaded the
                # optimized BLASFEO already)
                executor = (ProcessExecutor(spec, solve_first_here=row_cache is cache)
                            if parallel else SerialExecutor(spec))
                controller = DistributedMpc(team, settings, executor=executor)
                variables = controller.problem.nlp.variable_count
            recorder = _SampleRecorder(controller.update,
                                       workers=mode == "distributed" and parallel,
                                       here=getattr(getattr(controller, "executor", None),
                                                    "solves_here", ()), agents=agents)
            controller.update = recorder  # type: ignore[method-assign]
            try:
                result = run_closed_loop(controller, team, team, settings, scenario.reference,
                                         scenario.obstacles, duration_s)
            finally:
                controller.close()
            if (with_checks and mode == "distributed" and name != "ipopt-reference"
                    and include_reference and row_cache is cache):
                checks.append(accuracy_check(team, settings, recorder.samples, cache))
            row = _row(mode, agents, label, variables, result, recorder.cpu_s)
            log(f"    median update {row.update_ms['median']:.2f} ms, "
                f"success {row.success_rate:.0%}, min h {row.min_h_m:.3f} m")
            rows.append(row)
        if with_checks and "rti" in solvers and agents == agent_counts[0]:
            log(f"  {agents} agents, rti against converged fatrop, serial...")
            fidelity.append(rti_fidelity(agents, _with_solver(base_settings, "rti", compiled),
                                         cache, duration_s))
    return rows, checks, fidelity


def format_table(rows: list[BenchRow]) -> str:
    """Table I layout plus local NLP time and the ratios measured in this run."""
    number = [Column(name, "right") for name in (
        "vars", "iters", "upd mean", "std", "median", "p95", "cpu med", "local med",
        "dist/cent", "ref/this", "today/this")]
    cells = []
    for row in rows:
        cent = next((r for r in rows if r.agents == row.agents and r.mode == "centralized"
                     and r.solver == row.solver), None)
        ref = next((r for r in rows if r.agents == row.agents and r.mode == "distributed"
                    and r.solver == "ipopt-reference"), None)
        today = next((r for r in rows if r.agents == row.agents and r.mode == "distributed"
                      and r.solver == f"fatrop{GENERIC_SUFFIX}"), None)
        ratio = (f"{row.update_ms['mean'] / cent.update_ms['mean']:.2f}"
                 if row.mode == "distributed" and cent else "")
        speedup = (f"{ref.local_ms['median'] / row.local_ms['median']:.1f}x"  # type: ignore[index]
                   if row.local_ms and ref and ref is not row else "")
        cheaper = (f"{today.local_ms['median'] / row.local_ms['median']:.2f}x"  # type: ignore[index]
                   if row.local_ms and today and today is not row else "")
        local = f"{row.local_ms['median']:.2f}" if row.local_ms else ""
        u = row.update_ms
        cells.append([str(row.agents), row.mode, row.solver, str(row.variables),
                      f"{row.iterations_mean:.1f}", f"{u['mean']:.2f}", f"{u['std']:.2f}",
                      f"{u['median']:.2f}", f"{u['p95']:.2f}", f"{row.cpu_ms['median']:.2f}",
                      local, ratio, speedup, cheaper])
    return render_table([Column("n_A", "right"), "mode", "solver", *number], cells, [
        "times in ms; 'cpu med' = median CPU time per update summed over the processes (ADMM "
        "workers included); 'ref/this' = ipopt-reference local NLP median / this local NLP "
        "median; 'dist/cent' = mean update-time ratio against the same solver's centralized "
        "row; 'today/this' = local NLP median of today's fatrop path (CasADi's generic "
        "BLASFEO, same run) / this local NLP median"])


def format_accuracy(checks: list[AccuracyCheck]) -> str:
    lines = ["local NLP accuracy vs ipopt-reference (same parameters and initial guess):"]
    for c in checks:
        lines.append(f"  {c.agents} agents, {c.solver}: {c.samples} decisions, max |dGRF| "
                     f"{c.max_grf_difference_n:.3f} N, max |d payload p| "
                     f"{c.max_payload_position_difference_m:.2e} m, max rel d objective "
                     f"{c.max_objective_relative_difference:.1e}")
    return "\n".join(lines)


def format_fidelity(figures: list[RtiFidelity]) -> str:
    lines = ["rti in closed loop vs converged fatrop from the same request (first-stage GRF):"]
    for f in figures:
        lines.append(f"  {f.agents} agents: {f.solves} warm local solves, |dGRF| median "
                     f"{f.median_n:.3f} N, p95 {f.p95_n:.3f} N, max {f.max_n:.3f} N "
                     f"({f.converged_failures} left out: fatrop did not converge)")
    return "\n".join(lines)
