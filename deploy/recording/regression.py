"""``porter regress LOG...``: re-run every logged NMPC decision and compare with the log.

For each log: rebuild the controller from the log's attached scenario and effective NMPC
settings (or ``--settings``), then for every decision in order restore the warm-start keyframe
when one was logged for it, feed the logged ``MpcInputs`` and compare the outputs with the
logged ones: first-stage GRFs and wrenches, predicted payload (with ADMM: the consensus) and
robot trajectories and wrenches (with ADMM: each robot's own local solution), ADMM residuals
per iteration, and every solve's status.
Between keyframes the warm start is the replayed previous decision, which is exact as long as
the replay is. The replay loads the BLASFEO kernels the log was recorded on (its
``blas_kernels`` metadata) when this CPU has them and no other BLASFEO is loaded in the process
yet; otherwise the report names both, because other kernels round differently and the RTI's
single QP step carries that into the plan (measured on ``two_go2``: up to 1.1 N GRF, 0.2 rad/s
terminal angular rate). Then the log's summary metrics are checked against the expectations
stored next to it (``LOG.expect.json``). Exit code 1 when anything is outside its tolerance.
"""

from __future__ import annotations

import math
import platform
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from core.admm.admm_mpc import DistributedMpc
from core.locomotion.settings import WbcSettings
from core.model.team import TeamModel
from core.nmpc.centralized_mpc import CentralizedMpc
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.nlp_solver import NlpSolution, SolveStats
from core.nmpc.settings import MpcSettings
from core.nmpc.warm_start import ControllerMemory
from deploy.compute.blas_kernels import GENERIC, cpu_target, host_cpu_flags
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.recording import log_format as fmt
from deploy.recording.expectations import (
    check_expectations,
    expectation_margins,
    expectations_path,
)
from deploy.recording.log_reader import LogFile
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.recording.resimulation import logged_run
from deploy.recording.resimulation import resimulate as resimulate_run
from deploy.reports.table import Column, render_table
from drivers.robot_descriptions import srb_parameters

# Tolerances of a replay. The same compiled solver on the same inputs is deterministic only up
# to the last bits (measured: 0 on one machine, 2.2e-16 relative dual residual on another);
# the tolerances absorb floating-point differences between machines (BLAS kernels,
# compilers) that may change an interior-point iteration count, so they sit near the
# solver's tolerance. Doubling one cost weight deviates by 100x to 1000x more
# (measured: GRF 2.7 N, payload trajectory 2 cm, relative dual residual 0.3).
# Absolute [N, N m, m, mixed units of the residuals] except the relative dual residual.
TOLERANCES = {"grf_n": 0.02, "wrench": 0.02, "payload_trajectory": 1e-4,
              "robot_trajectories": 1e-4, "wrench_trajectories": 0.02, "admm_primal": 1e-3,
              "admm_dual_relative": 1e-3}


@dataclass
class LogRegression:
    """One log's replay: max absolute deviation per quantity, status mismatches, verdict."""

    log: str
    decisions: int = 0
    keyframes: int = 0
    max_deviation: dict[str, float] = field(default_factory=lambda: dict.fromkeys(TOLERANCES, 0.0))
    status_mismatches: int = 0
    first_failure: str = ""
    expectation_failures: list[str] = field(default_factory=list)
    resimulated: bool = False  # expectations checked on a re-simulation of the logged run
    expectation_margins: dict[str, float] = field(default_factory=dict)
    kernels_recorded: str = "unknown"  # BLASFEO target of the recording (its metadata)
    kernels_replayed: str = "unknown"  # BLASFEO target of this replay

    @property
    def kernel_mismatch(self) -> bool:
        return self.kernels_recorded not in ("unknown", self.kernels_replayed)

    @property
    def passed(self) -> bool:
        within = all(self.max_deviation[k] <= TOLERANCES[k] for k in TOLERANCES)
        return (within and self.status_mismatches == 0 and self.decisions > 0
                and not self.expectation_failures)


def controller_from_log(log: LogFile, cache: CompiledCodeCache,
                        settings: MpcSettings | None = None
                        ) -> tuple[CentralizedMpc | DistributedMpc, TeamModel]:
    """The NMPC the log's run used, rebuilt from its attachments (serial ADMM executor)."""
    scenario, settings, _ = logged_run(log, settings)
    team = TeamModel.from_settings(scenario.team_settings(), srb_parameters)
    if scenario.controller.mode == "centralized":
        return CentralizedMpc(team, settings, compiler=cache), team
    return DistributedMpc(team, settings, compiler=cache), team


def recorded_kernels(log: LogFile) -> str:
    """The BLASFEO target the log's solvers ran on (``unknown`` for logs older than the key)."""
    return log.metadata().get(fmt.RUN_METADATA, {}).get("blas_kernels", "unknown")


def replay_blas_target(recorded: str) -> str:
    """The ``CompiledCodeCache.blas_target`` that reproduces ``recorded`` kernels on this CPU:
    that target when this CPU runs it, else this CPU's own (``auto``)."""
    if recorded == GENERIC:
        return "generic"
    if recorded == cpu_target(platform.machine(), host_cpu_flags()):
        return recorded
    return "auto"


def inputs_from_message(message: pb.NmpcInputs) -> MpcInputs:
    a = fmt.from_array
    return MpcInputs(a(message.robot_states), a(message.payload_state),
                     a(message.robot_references), a(message.payload_reference),
                     a(message.feet_positions), a(message.contacts),
                     a(message.obstacles).reshape(-1, 5))


def memory_from_message(message: pb.WarmStart) -> ControllerMemory:
    a = fmt.from_array
    no_stats = SolveStats("logged", True, 0, 0.0, math.nan, 0.0)
    previous = [NlpSolution(a(agent.decision), a(agent.constraint_multipliers),
                            a(agent.bound_multipliers), no_stats) if agent.present else None
                for agent in message.agents]
    return ControllerMemory(previous, a(message.consensus) if message.has_consensus else None,
                            a(message.duals) if message.has_consensus else None)


def compare(report: LogRegression, update: int, plan: MpcPlan, logged: pb.NmpcUpdate,
            iterations: list[pb.AdmmIteration]) -> None:
    """Fold one decision's deviations into ``report``."""
    a = fmt.from_array
    pairs = {"grf_n": (plan.grf, a(logged.grf)), "wrench": (plan.wrench, a(logged.wrench)),
             "payload_trajectory": (plan.payload_trajectory, a(logged.payload_trajectory)),
             "robot_trajectories": (plan.robot_trajectories, a(logged.robot_trajectories))}
    pairs["wrench_trajectories"] = (plan.wrench_trajectories, a(logged.wrench_trajectories))
    for r, (replayed, recorded) in enumerate(zip(plan.admm_iterations, iterations,
                                                 strict=False)):
        _fold(report, "admm_primal", np.concatenate([replayed.primal_payload_rms,
                                                     replayed.primal_wrench_rms]),
              np.concatenate([recorded.primal_payload_rms, recorded.primal_wrench_rms]), update,
              r)
        scale = max(abs(recorded.dual_norm), 1.0)
        _fold(report, "admm_dual_relative", np.array([replayed.dual_norm / scale]),
              np.array([recorded.dual_norm / scale]), update, r)
    for key, (ours, theirs) in pairs.items():
        _fold(report, key, ours, theirs, update)
    logged_status = [(s.status, s.success) for s in logged.solves]
    replay_status = [(s.status, s.success) for s in plan.solves]
    if len(plan.admm_iterations) != len(iterations) or logged_status != replay_status:
        report.status_mismatches += 1
        if not report.first_failure:
            report.first_failure = (f"update {update}: solver status {replay_status} vs "
                                    f"logged {logged_status}")


def array_deviation(ours: np.ndarray, theirs: np.ndarray) -> float:
    """The largest |ours - theirs| over finite values; NaN matches only NaN in the same place
    and an infinity only the same infinity there, anything else (or another shape) is inf."""
    ours, theirs = np.asarray(ours, float), np.asarray(theirs, float)
    if ours.shape != theirs.shape:
        return math.inf
    missing = np.isnan(ours)
    if not np.array_equal(missing, np.isnan(theirs)):
        return math.inf
    a, b = ours[~missing], theirs[~missing]
    infinite = np.isinf(a) | np.isinf(b)
    if np.any(a[infinite] != b[infinite]):
        return math.inf
    return float(np.max(np.abs(a[~infinite] - b[~infinite]), initial=0.0))


def _fold(report: LogRegression, key: str, ours: np.ndarray, theirs: np.ndarray, update: int,
          iteration: int | None = None) -> None:
    deviation = array_deviation(ours, theirs)
    report.max_deviation[key] = max(report.max_deviation[key], deviation)
    if deviation > TOLERANCES[key] and not report.first_failure:
        where = f"update {update}" + ("" if iteration is None else f", ADMM iteration {iteration}")
        report.first_failure = f"{where}: {key} deviates by {deviation:.3g}"


def regress_log(path: Path | str, cache: CompiledCodeCache | None = None,
                settings: MpcSettings | None = None,
                max_decisions: int | None = None, resimulate: bool = True,
                wbc_settings: WbcSettings | None = None) -> LogRegression:
    """Replay the log's decisions (``settings``: a changed NMPC) and check its expectations on
    a re-simulation of the run (``resimulate``; ``wbc_settings``: a changed WBC) or, without
    one, on the summary stored in the log."""
    log = LogFile(path)
    report = LogRegression(str(path), kernels_recorded=recorded_kernels(log))
    cache = cache or CompiledCodeCache(blas_target=replay_blas_target(report.kernels_recorded))
    report.kernels_replayed = cache.blas_kernels().target
    controller, _ = controller_from_log(log, cache, settings)
    topics = log.by_topic([fmt.NMPC_INPUTS, fmt.NMPC_WARM_START, fmt.NMPC_UPDATE, fmt.ADMM])
    inputs = {m.message.update: m.message for m in topics[fmt.NMPC_INPUTS]}
    keyframes = {m.message.update: m.message for m in topics[fmt.NMPC_WARM_START]}
    updates = {m.message.update: m.message for m in topics[fmt.NMPC_UPDATE]}
    admm: dict[int, list[pb.AdmmIteration]] = {}
    for m in topics[fmt.ADMM]:
        admm.setdefault(m.message.update, []).append(m.message)
    previous: int | None = None
    try:
        for update in sorted(inputs):
            if max_decisions is not None and report.decisions >= max_decisions:
                break
            if update in keyframes:
                controller.restore(memory_from_message(keyframes[update]))
                report.keyframes += 1
            elif previous is None or update != previous + 1 or update not in updates:
                previous = None  # a gap: wait for the next keyframe
                continue
            if update not in updates:
                continue
            plan = controller.update(inputs_from_message(inputs[update]))
            iterations = sorted(admm.get(update, []), key=lambda m: m.iteration)
            compare(report, update, plan, updates[update], iterations)
            report.decisions += 1
            previous = update
    finally:
        controller.close()
    expected = expectations_path(Path(path))
    if expected.exists():
        summary = (resimulate_run(log, cache, settings, wbc_settings) if resimulate
                   else log.summary())
        report.resimulated = resimulate
        report.expectation_failures = check_expectations(summary, expected)
        report.expectation_margins = expectation_margins(summary, expected)
    return report


def format_report(report: LogRegression) -> str:
    verdict = "PASS" if report.passed else "FAIL"
    lines = [f"{verdict} {report.log}: {report.decisions} decisions replayed "
             f"({report.keyframes} keyframes), {report.status_mismatches} status mismatches"]
    table = render_table(
        ["quantity", Column("max deviation", "right"), Column("tolerance", "right"), ""],
        [[key, f"{report.max_deviation[key]:.3g}", f"{tolerance:.1g}",
          "" if report.max_deviation[key] <= tolerance else "<-- exceeds"]
         for key, tolerance in TOLERANCES.items()])
    lines.extend(f"  {line}" for line in table.splitlines())
    lines.append(f"  BLAS kernels: replayed on {report.kernels_replayed}, recorded on "
                 f"{report.kernels_recorded}")
    if report.first_failure:
        lines.append(f"  first failure: {report.first_failure}")
    if report.kernel_mismatch and not report.passed:
        lines.append("  the replay ran on other BLAS kernels than the recording: deviations of "
                     "about a newton are rounding, not a changed controller; replay in a fresh "
                     f"process on a CPU with {report.kernels_recorded} kernels to compare")
    lines.extend(f"  expectation: {failure}" for failure in report.expectation_failures)
    if report.expectation_margins:
        tightest = sorted(report.expectation_margins.items(), key=lambda item: item[1])[:3]
        checked = "a re-simulation" if report.resimulated else "the logged summary"
        lines.append(f"  expectations on {checked}; tightest margins (1 = band centre, 0 = "
                     "edge): " + ", ".join(f"{k} {m:.2f}" for k, m in tightest))
    return "\n".join(lines)
