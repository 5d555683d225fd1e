"""Summary metrics of a simulated run, from the simulator's ground truth (never the estimate).

``RunMetrics`` is fed once per WBC tick (ground truth, tick times) and once per NMPC update
(plan statistics); ``summary()`` gives the JSON-ready dict documented in README (``porter
sim`` summary keys). Timing fields (``nmpc_update_ms``, ``wbc_tick_ms``, ``real_time_factor``)
are wall-clock measurements and differ between runs; every other field is a function of the
scenario and seed.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from core.nmpc.mpc_plan import MpcPlan

DEADLINE_S = 1.0 / 60.0
# A robot has fallen when its trunk is below this fraction of its nominal height, or tilted more
# than MAX_TILT_RAD (roll or pitch).
FALL_HEIGHT_FRACTION = 0.5
MAX_TILT_RAD = 0.7


@dataclass
class RunMetrics:
    """Accumulates a run's metrics; ``pair_names`` label the (body, obstacle) pairs of h."""

    scenario: str
    goal_m: np.ndarray
    goal_tolerance_m: float
    pair_names: list[str]
    position_error_m: list[float] = field(default_factory=list)
    # xy of the payload and of each robot [m], world frame, per ground-truth sample
    body_xy_m: list[np.ndarray] = field(default_factory=list)
    yaw_error_rad: list[float] = field(default_factory=list)
    min_h_m: list[float] = field(default_factory=list)  # per sample: min over the pairs
    min_h_by_pair_m: np.ndarray | None = None
    max_coupling_error_m: float = 0.0
    fallen: set[str] = field(default_factory=set)
    update_ms: list[float] = field(default_factory=list)
    failed_solves: int = 0
    solve_iterations: list[int] = field(default_factory=list)
    solve_ms: list[float] = field(default_factory=list)
    flagged_plans: int = 0
    relaxed_plans: int = 0  # plans whose soft barriers used slack (safety infeasible)
    max_barrier_slack_m: float = 0.0
    payload_residual: list[float] = field(default_factory=list)
    wrench_residual: list[float] = field(default_factory=list)
    position_residual_m: list[float] = field(default_factory=list)
    force_residual_n: list[float] = field(default_factory=list)
    dual_residual: list[float] = field(default_factory=list)  # ||P (s-bar_r - s-bar_r-1)||
    # per update: the planned first-stage GRFs (n_A, 12) [N], world frame, and their RMS
    # change from the previous update's over the feet in stance in both (the plan's
    # smoothness; a touch-down or lift-off is the gait's, not a jump; 0 for the first)
    grf_n: list[np.ndarray] = field(default_factory=list)
    grf_change_n: list[float] = field(default_factory=list)
    wbc_tick_ms: list[float] = field(default_factory=list)
    loop_tick_ms: list[float] = field(default_factory=list)  # whole 2 ms loop ticks, wall
    estimate_position_error_m: list[float] = field(default_factory=list)
    wrench_force_error_n: list[float] = field(default_factory=list)
    wrench_force_n: list[float] = field(default_factory=list)
    estimate_tilt_error_rad: list[float] = field(default_factory=list)
    estimate_yaw_error_rad: list[float] = field(default_factory=list)
    wbc_failures: int = 0
    duration_s: float = 0.0
    wall_s: float = 0.0
    final_payload_xy_m: np.ndarray | None = None
    plans_applied: int = 0  # NMPC plans that took effect (all of them without a delay)
    stopped_early: bool = False  # a stop was requested (Ctrl-C, SIGTERM) before the end

    def record_ground_truth(self, time_s: float, payload_xy_m: np.ndarray, payload_yaw_rad: float,
                            desired_xy_m: np.ndarray, desired_yaw_rad: float,
                            safety_values_m: np.ndarray, coupling_errors_m: np.ndarray) -> None:
        """One sample: payload pose vs reference, h of every pair (flattened as ``pair_names``),
        coupling point distances per robot [m]."""
        self.duration_s = time_s
        self.position_error_m.append(float(np.linalg.norm(payload_xy_m - desired_xy_m)))
        yaw_error = payload_yaw_rad - desired_yaw_rad
        self.yaw_error_rad.append(float(np.arctan2(np.sin(yaw_error), np.cos(yaw_error))))
        h = np.asarray(safety_values_m, dtype=float).reshape(-1)
        if h.size:
            self.min_h_m.append(float(np.min(h)))
        self.min_h_by_pair_m = h if self.min_h_by_pair_m is None else np.minimum(
            self.min_h_by_pair_m, h)
        self.max_coupling_error_m = max(self.max_coupling_error_m,
                                        float(np.max(coupling_errors_m)))
        self.final_payload_xy_m = np.asarray(payload_xy_m, dtype=float)

    def record_fall(self, robot: str) -> None:
        self.fallen.add(robot)

    def record_plan(self, plan: MpcPlan) -> None:
        self.update_ms.append(1e3 * plan.update_time_s)
        self.failed_solves += sum(not s.success for s in plan.solves)
        self.solve_iterations.extend(s.iterations for s in plan.solves)
        self.solve_ms.extend(1e3 * s.wall_time_s for s in plan.solves)
        self.flagged_plans += int(plan.flagged)
        self.relaxed_plans += int(plan.relaxed)
        self.max_barrier_slack_m = max(self.max_barrier_slack_m, plan.barrier_slack_m)
        grf = np.array(plan.grf, dtype=float)
        self.grf_change_n.append(_stance_change_n(self.grf_n[-1] if self.grf_n else None, grf))
        self.grf_n.append(grf)
        if plan.admm_iterations:
            last = plan.admm_iterations[-1]
            self.payload_residual.append(float(np.sqrt(np.mean(last.primal_payload_rms ** 2))))
            self.wrench_residual.append(float(np.sqrt(np.mean(last.primal_wrench_rms ** 2))))
            self.position_residual_m.append(
                float(np.sqrt(np.mean(last.primal_position_rms_m ** 2))))
            self.force_residual_n.append(float(np.sqrt(np.mean(last.primal_force_rms_n ** 2))))
            self.dual_residual.append(float(last.dual_norm))

    def record_estimate(self, estimate: np.ndarray, position_m: np.ndarray,
                        euler_rad: np.ndarray) -> None:
        """Payload estimate (12,) vs the true payload position and XYZ Euler angles."""
        self.estimate_position_error_m.append(float(np.linalg.norm(estimate[0:3] - position_m)))
        self.estimate_tilt_error_rad.append(float(np.max(np.abs(estimate[6:8] - euler_rad[0:2]))))
        yaw = estimate[8] - euler_rad[2]
        self.estimate_yaw_error_rad.append(float(abs(np.arctan2(np.sin(yaw), np.cos(yaw)))))

    def record_wrench(self, predicted_force_n: np.ndarray, measured_force_n: np.ndarray) -> None:
        """One robot's planned first-stage coupling force on the payload vs the force the
        simulated coupling transmitted [N], world frame."""
        self.wrench_force_error_n.append(float(np.linalg.norm(predicted_force_n
                                                              - measured_force_n)))
        self.wrench_force_n.append(float(np.linalg.norm(measured_force_n)))

    def record_wbc(self, tick_s: float, success: bool) -> None:
        self.wbc_tick_ms.append(1e3 * tick_s)
        self.wbc_failures += int(not success)

    def summary(self) -> dict:
        """The run's summary (README: ``porter sim`` summary keys)."""
        updates = np.asarray(self.update_ms) if self.update_ms else np.zeros(1)
        ticks = np.asarray(self.wbc_tick_ms) if self.wbc_tick_ms else np.zeros(1)
        by_pair = ({name: float(h) for name, h in zip(self.pair_names, self.min_h_by_pair_m,
                                                         strict=True)}
                   if self.min_h_by_pair_m is not None else {})
        final = self.final_payload_xy_m
        reached = bool(final is not None and not self.fallen
                       and np.linalg.norm(final - self.goal_m) <= self.goal_tolerance_m)
        return {
            "scenario": self.scenario,
            "backend": "mujoco",
            "duration_s": round(self.duration_s, 6),
            "stopped_early": self.stopped_early,
            "nmpc_plans_applied": self.plans_applied,
            "falls": len(self.fallen),
            "fallen_robots": sorted(self.fallen),
            "reached_goal": reached,
            "final_goal_distance_m": float(np.linalg.norm(final - self.goal_m))
            if final is not None else None,
            "min_h_m": min(by_pair.values()) if by_pair else None,
            "min_h_by_pair_m": by_pair,
            "rms_payload_position_error_m": _rms(self.position_error_m),
            "rms_payload_yaw_error_rad": _rms(self.yaw_error_rad),
            "max_coupling_error_m": self.max_coupling_error_m,
            "admm_residual_rms": {"payload_state": _rms(self.payload_residual),
                                  "wrench": _rms(self.wrench_residual),
                                  "payload_position_m": _rms(self.position_residual_m),
                                  "force_n": _rms(self.force_residual_n)},
            # the paper's Table II aggregate: the per-update RMS averaged over time
            "admm_residual_mean": {"payload_state": _mean(self.payload_residual),
                                   "wrench": _mean(self.wrench_residual),
                                   "payload_position_m": _mean(self.position_residual_m),
                                   "force_n": _mean(self.force_residual_n)},
            "nmpc_update_ms": {"median": float(np.median(updates)),
                               "p95": float(np.percentile(updates, 95)),
                               "max": float(np.max(updates))},
            "nmpc_updates": len(self.update_ms),
            "deadline_misses": int(np.sum(updates > 1e3 * DEADLINE_S)),
            "failed_solves": self.failed_solves,
            "nlp_solve_ms_median": float(np.median(self.solve_ms)) if self.solve_ms else None,
            "nlp_iterations_mean": float(np.mean(self.solve_iterations))
            if self.solve_iterations else None,
            "flagged_plans": self.flagged_plans,
            "relaxed_plans": self.relaxed_plans,
            "max_barrier_slack_m": self.max_barrier_slack_m,
            "loop_tick_ms": _distribution(self.loop_tick_ms),
            "wbc_tick_ms": {"median": float(np.median(ticks)),
                            "p95": float(np.percentile(ticks, 95))},
            "wbc_failures": self.wbc_failures,
            "coupling_force_rms_n": {"measured": _rms(self.wrench_force_n),
                                      "predicted_minus_measured": _rms(
                                          self.wrench_force_error_n)},
            "payload_estimate_error": {
                "position_rms_m": _rms(self.estimate_position_error_m),
                "tilt_max_rad": max(self.estimate_tilt_error_rad, default=None),
                "yaw_rms_rad": _rms(self.estimate_yaw_error_rad)},
            "real_time_factor": self.duration_s / self.wall_s if self.wall_s > 0 else None,
            "wall_s": self.wall_s,
            "nmpc_wall_s": float(np.sum(self.update_ms)) / 1e3,
            "wbc_wall_s": float(np.sum(self.wbc_tick_ms)) / 1e3,
        }


def _stance_change_n(previous: np.ndarray | None, grf: np.ndarray) -> float:
    """RMS change [N] of the GRF components of the feet loaded (normal force > 1 N) in both."""
    if previous is None or previous.shape != grf.shape:
        return 0.0
    before, now = previous.reshape(-1, 3), grf.reshape(-1, 3)
    stance = (before[:, 2] > 1.0) & (now[:, 2] > 1.0)
    return float(np.sqrt(np.mean(np.square(now[stance] - before[stance])))) if stance.any() \
        else 0.0


def _rms(values: list[float]) -> float | None:
    return float(np.sqrt(np.mean(np.square(values)))) if values else None


def _mean(values: list[float]) -> float | None:
    return float(np.mean(values)) if values else None


def _distribution(values_ms: list[float]) -> dict[str, float]:
    values = np.asarray(values_ms) if values_ms else np.zeros(1)
    return {"median": float(np.median(values)), "p95": float(np.percentile(values, 95)),
            "max": float(np.max(values))}


def run_outcome(summary: dict) -> str:
    """How a run ended, from its summary (with ``safety``, the loop's outcome): ``goal``,
    ``time out`` (ran its duration short of the goal), ``controlled stop`` (braked and sat
    down, no fault) or ``safe stop`` (a fault: damping); ``, N fell`` when robots fell."""
    safety = summary["safety"]
    if safety["safe_stop"]:
        text = "safe stop"
    elif safety.get("controlled_stop"):
        text = "controlled stop"
    else:
        text = "goal" if summary["reached_goal"] else "time out"
    return text + (f", {summary['falls']} fell" if summary["falls"] else "")
