"""Closed loop of an NMPC controller on the SRB plant (no physics engine): tests and benchmarks.

Each MPC period: measure the plant (ground truth here), plan footholds and contacts with the
trot gait, build ``MpcInputs``, update the controller, apply the first GRFs for one period.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

from core.locomotion.gait import FootholdPlanner, TrotGait
from core.model.obstacles import Obstacle
from core.model.team import TeamModel
from core.nmpc.inputs_builder import build_mpc_inputs
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.reference import WaypointReference, robot_state_from_payload
from core.nmpc.settings import MpcSettings
from core.plant.srb_plant import SrbPlant


class Controller(Protocol):
    def update(self, inputs: MpcInputs) -> MpcPlan: ...


@dataclass
class ClosedLoopResult:
    """Per-update histories (length = number of MPC updates)."""

    times_s: list[float] = field(default_factory=list)
    payload_position_error_m: list[float] = field(default_factory=list)
    payload_yaw_error_rad: list[float] = field(default_factory=list)
    min_h_m: list[np.ndarray] = field(default_factory=list)  # (1 + n_A,) per update
    coupling_error_m: list[float] = field(default_factory=list)
    update_time_s: list[float] = field(default_factory=list)
    local_solve_time_s: list[float] = field(default_factory=list)
    iterations: list[float] = field(default_factory=list)
    success: list[bool] = field(default_factory=list)
    failed_solves: list[int] = field(default_factory=list)  # NLP solves not converged
    primal_payload_rms: list[float] = field(default_factory=list)
    primal_wrench_rms: list[float] = field(default_factory=list)
    final_payload_state: np.ndarray | None = None


def run_closed_loop(
    controller: Controller,
    team: TeamModel,
    plant_team: TeamModel,
    settings: MpcSettings,
    reference: WaypointReference,
    obstacles: list[Obstacle],
    duration_s: float,
    gait: TrotGait | None = None,
    plant_substeps: int = 10,
) -> ClosedLoopResult:
    """Run ``controller`` against an ``SrbPlant`` of ``plant_team`` (its true payload may differ
    from the controller's ``team``) for ``duration_s``."""
    gait = gait or TrotGait()
    ts = settings.sample_period_s
    n = settings.horizon_steps
    plant = SrbPlant(plant_team, ts / plant_substeps, settings.gravity_m_s2)
    payload = reference.payload_state(0.0)
    payload[3:6] = 0.0
    robots = np.array([robot_state_from_payload(team, i, payload)
                       for i in range(team.agent_count)])
    planners = [FootholdPlanner(robot, gait) for robot in team.robots]
    for planner, state in zip(planners, robots, strict=True):
        planner.reset(state)
    result = ClosedLoopResult()
    for step in range(int(round(duration_s / ts))):
        t = step * ts

        def foot_horizon(i: int, state: np.ndarray, refs: np.ndarray, t: float = t
                         ) -> tuple[np.ndarray, np.ndarray]:
            planners[i].update(t, state, refs[0])
            return planners[i].horizon(t, n, ts, state, refs)

        inputs = build_mpc_inputs(team, reference, settings, robots.copy(), payload.copy(), t,
                                  foot_horizon, obstacles, t)
        feet = inputs.feet_positions
        plan = controller.update(inputs)
        _record(result, t, inputs, plan, reference)
        result.coupling_error_m.append(
            float(np.max(np.abs(plant.coupling_error(robots, payload)[:, 0:3]))))
        robots, payload, _ = plant.step(robots, payload, plan.grf, feet[:, 0],
                                        plant_substeps)
        if not np.all(np.isfinite(payload)):
            break
    result.final_payload_state = payload
    return result


def _record(result: ClosedLoopResult, t: float, inputs: MpcInputs, plan: MpcPlan,
            reference: WaypointReference) -> None:
    desired = reference.payload_state(t)
    result.times_s.append(t)
    result.payload_position_error_m.append(
        float(np.linalg.norm(inputs.payload_state[0:2] - desired[0:2])))
    yaw_error = inputs.payload_state[8] - desired[8]
    result.payload_yaw_error_rad.append(float(np.arctan2(np.sin(yaw_error), np.cos(yaw_error))))
    h = inputs.safety_values()
    result.min_h_m.append(h.min(axis=1) if h.size else np.full(h.shape[0], np.inf))
    result.update_time_s.append(plan.update_time_s)
    result.success.append(plan.success)
    result.failed_solves.append(sum(not s.success for s in plan.solves))
    result.iterations.append(float(np.mean([s.iterations for s in plan.solves])))
    result.local_solve_time_s.append(float(np.mean([s.wall_time_s for s in plan.solves])))
    if plan.admm_iterations:
        last = plan.admm_iterations[-1]
        result.primal_payload_rms.append(float(np.sqrt(np.mean(last.primal_payload_rms ** 2))))
        result.primal_wrench_rms.append(float(np.sqrt(np.mean(last.primal_wrench_rms ** 2))))
