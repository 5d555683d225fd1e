"""Shared builders for controller tests: a two-Go2 team and one set of NMPC inputs."""

from __future__ import annotations

import numpy as np

from core.locomotion.gait import FootholdPlanner, TrotGait
from core.model.obstacles import Obstacle
from core.model.team import TeamModel
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.reference import WaypointReference, horizon_references, robot_state_from_payload
from core.nmpc.settings import MpcSettings, SolverSettings
from core.plant.standard_scenarios import PAYLOAD_HEIGHT_M, ring_team_settings
from drivers.robot_descriptions import srb_parameters

INTERPRETED = SolverSettings(name="fatrop", compiled=False)


def settings(**changes) -> MpcSettings:
    return MpcSettings(**{"solver": INTERPRETED, **changes})


def team(types: tuple[str, ...] = ("go2", "go2")) -> TeamModel:
    return TeamModel.from_settings(ring_team_settings(list(types), srb_parameters),
                                   srb_parameters)


def reference(speed_m_s: float = 0.3) -> WaypointReference:
    return WaypointReference(np.array([[0.0, 0.0], [5.0, 0.0]]), speed_m_s, PAYLOAD_HEIGHT_M)


def inputs_at_start(team_model: TeamModel, mpc: MpcSettings,
                    obstacles: list[Obstacle] | None = None, time_s: float = 0.0) -> MpcInputs:
    """Inputs of the first update: team at rest on the reference start, trot schedule."""
    n, ts = mpc.horizon_steps, mpc.sample_period_s
    ref = reference()
    payload = ref.payload_state(0.0)
    payload[3:6] = 0.0
    robots = np.array([robot_state_from_payload(team_model, i, payload)
                       for i in range(team_model.agent_count)])
    robot_refs, payload_ref = horizon_references(team_model, ref, time_s, n, ts)
    feet, contacts = [], []
    for i, robot in enumerate(team_model.robots):
        planner = FootholdPlanner(robot, TrotGait())
        planner.reset(robots[i])
        f, c = planner.horizon(time_s, n, ts, robots[i], robot_refs[i])
        feet.append(f)
        contacts.append(c)
    rows = np.array([o.row(time_s, mpc.safety.safety_distance_m) for o in obstacles or []])
    return MpcInputs(robots, payload, robot_refs, payload_ref, np.array(feet),
                     np.array(contacts), rows.reshape(-1, 5))
