"""What an NMPC update returns: the plan to apply, its predictions, and how the solves went."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from core.model.team import TeamModel
from core.nmpc.nlp_solver import SolveStats
from core.nmpc.obstacle_selection import ObstacleSelection
from core.nmpc.transport_problem import TransportProblem


@dataclass(frozen=True)
class AdmmIteration:
    """Residuals of one ADMM iteration r (paper eq. 17).

    ``primal_position_rms_m`` / ``primal_force_rms_n``: per agent, RMS of s_r^i - s_bar_r over
    the payload positions [m] and over the interaction forces [N] of the horizon (the paper's
    payload-position and interaction-force residuals). ``primal_payload_rms`` /
    ``primal_wrench_rms``: the same over the whole payload state [mixed units of x] and the
    whole wrench [N, N m]. ``dual_norm``: ||P (s_bar_r - s_bar_{r-1})||.
    """

    primal_payload_rms: np.ndarray
    primal_wrench_rms: np.ndarray
    dual_norm: float
    solves: tuple[SolveStats, ...]
    primal_position_rms_m: np.ndarray = field(default_factory=lambda: np.zeros(0))
    primal_force_rms_n: np.ndarray = field(default_factory=lambda: np.zeros(0))


@dataclass
class MpcPlan:
    """Plan of one update, world frame, SI units.

    ``grf``: (n_A, 12) first-stage GRFs to apply; ``wrench``: (n_A, 6) first-stage wrench each
    robot exerts on the payload; trajectories over stages 0..N (states) or 0..N-1 (inputs).
    ``success`` is False when any solve failed or did not converge: the plan is then the best
    available one (the solver's last iterate if finite, else the shifted previous plan).
    ``start_inside_margin`` is True when a body starts inside an obstacle's safety margin (more
    than the flag's tolerance): the plan is still a converged recovery plan, not a failed solve;
    ``warnings`` say which body and obstacle. ``flagged`` is either.
    ``barrier_slack_m``: the largest slack the soft barriers used over the horizon (and over the
    agents' local problems) [m]: 0 while the safety constraints are feasible; above the
    tolerance of ``flag_relaxed_barriers`` the plan is ``relaxed``: the safest plan the solver
    found violates a barrier by that much.
    """

    grf: np.ndarray
    wrench: np.ndarray
    robot_trajectories: np.ndarray
    payload_trajectory: np.ndarray
    grf_trajectories: np.ndarray
    wrench_trajectories: np.ndarray
    solves: list[SolveStats]
    success: bool
    update_time_s: float
    admm_iterations: list[AdmmIteration] = field(default_factory=list)
    consensus_trajectory: np.ndarray | None = None
    warnings: list[str] = field(default_factory=list)
    start_inside_margin: bool = False
    barrier_slack_m: float = 0.0
    relaxed: bool = False

    @property
    def flagged(self) -> bool:
        """A failed solve, a start inside a safety margin or relaxed barriers."""
        return not self.success or self.start_inside_margin or self.relaxed

    def flag_unsafe_start(self, safety_values_m: np.ndarray, tolerance_m: float = 5e-3) -> None:
        """Flag the plan if any body starts inside an obstacle's safety margin.

        The plan is still the solver's (a recovery plan: the DT-HOCBF drives h back up), so
        ``success`` is untouched, but the caller must know the safe set was left.
        ``safety_values_m``: (1 + n_A, n_O), payload first. Violations within ``tolerance_m``
        (model mismatch, sensor noise) are not flagged.
        """
        for body, obstacle in np.argwhere(safety_values_m < -tolerance_m):
            who = "payload" if body == 0 else f"robot {body - 1}"
            self.warnings.append(f"start inside safety margin: {who} vs obstacle {obstacle}, "
                                 f"h = {safety_values_m[body, obstacle]:.3f} m")
            self.start_inside_margin = True


    def flag_relaxed_barriers(self, tolerance_m: float) -> None:
        """Flag the plan ``relaxed`` (with a warning) when its barrier slack exceeds
        ``tolerance_m`` [m]: no plan satisfies every safety constraint from this state."""
        if self.barrier_slack_m > tolerance_m:
            self.relaxed = True
            self.warnings.append(f"safety constraints relaxed: barrier slack "
                                 f"{self.barrier_slack_m:.4f} m (tolerance {tolerance_m} m)")

    def flag_dropped_obstacles(self, selections: list[ObstacleSelection]) -> None:
        """Warn about obstacles left out of a problem's slots although predicted inside their
        margin (more such obstacles than ``safety.obstacle_slots``): the plan stands, but it
        ignores them. ``selections``: one per problem (per agent with ADMM)."""
        for problem, selection in enumerate(selections):
            for obstacle in selection.dropped_near:
                self.warnings.append(
                    f"obstacle {obstacle} left out of problem {problem}'s slots, predicted "
                    f"h = {selection.min_h_m[obstacle]:.3f} m (raise safety.obstacle_slots)")


def decode_plan(problem: TransportProblem, team: TeamModel, decision: np.ndarray,
                agent: int | None = None) -> MpcPlan:
    """Trajectories of the robots in ``problem`` (others left zero), payload and wrenches."""
    layout = problem.nlp.decision
    n = problem.horizon_steps
    na = team.agent_count
    values = np.asarray(decision)
    robots = np.zeros((na, n + 1, 12))
    grfs = np.zeros((na, n, 12))
    for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
        robots[r] = values[layout.stage_rows(f"robot_{key}", n + 1)]
        grfs[r] = values[layout.stage_rows(f"grf_{key}", n)]
    payload = values[layout.stage_rows("payload", n + 1)]
    wrenches = np.array([values[layout.stage_rows(f"wrench_{j}", n)] for j in range(na)])
    return MpcPlan(
        grf=grfs[:, 0].copy(), wrench=wrenches[:, 0].copy(), robot_trajectories=robots,
        payload_trajectory=payload, grf_trajectories=grfs, wrench_trajectories=wrenches,
        solves=[], success=True, update_time_s=0.0,
        barrier_slack_m=problem.barrier_slack(decision),
    )
