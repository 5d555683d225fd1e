"""The standard closed-loop scenario of tests and ``porter bench nmpc``: a team of 2-4 robots
carries the payload at 0.3 m/s past obstacles close enough to activate the CBFs."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from core.model.obstacles import Obstacle
from core.model.srb_model import SrbParameters
from core.model.team import TeamModel
from core.model.team_settings import AgentSettings, PayloadSettings, TeamSettings
from core.nmpc.reference import WaypointReference

PAYLOAD_HEIGHT_M = 0.45
COUPLING_RADIUS_M = 0.55


@dataclass(frozen=True)
class StandardScenario:
    team: TeamModel
    reference: WaypointReference
    obstacles: list[Obstacle]


def ring_team_settings(robot_types: list[str], robot_parameters: Callable[[str], SrbParameters],
                       payload_mass_kg: float = 5.0) -> TeamSettings:
    """Robots evenly spaced on a circle around the payload, coupling points at one height."""
    count = len(robot_types)
    agents = []
    for i, robot_type in enumerate(robot_types):
        angle = 2 * np.pi * i / count
        height = PAYLOAD_HEIGHT_M - robot_parameters(robot_type).nominal_height_m
        agents.append(AgentSettings(
            name=f"{robot_type}_{i}", robot_type=robot_type,
            coupling_point_in_payload_m=(COUPLING_RADIUS_M * np.cos(angle),
                                         COUPLING_RADIUS_M * np.sin(angle), 0.0),
            coupling_point_in_robot_m=(0.0, 0.0, height),
        ))
    return TeamSettings(agents=agents, payload=PayloadSettings(mass_kg=payload_mass_kg))


def standard_scenario(agent_count: int, robot_parameters: Callable[[str], SrbParameters],
                      safety_distance_m: float = 0.6, intrusion_m: float = 0.1
                      ) -> StandardScenario:
    """Go2 team (two Go2 + one A1 for three agents, as in the paper's experiments).

    Two obstacles, left then right of the straight reference, each placed so that the widest
    body of the team would pass ``intrusion_m`` inside its safety margin: the CBFs must bend the
    path, whatever the team size.
    """
    types = ["go2", "go2", "a1"] if agent_count == 3 else ["go2"] * agent_count
    team = TeamModel.from_settings(ring_team_settings(types, robot_parameters), robot_parameters)
    reference = WaypointReference(np.array([[0.0, 0.0], [3.0, 0.0]]), 0.3, PAYLOAD_HEIGHT_M)
    radius = 0.1
    half_width = float(np.max(np.abs(team.coupling_points_in_payload_m[:, 1])))
    offset = half_width + safety_distance_m + radius - intrusion_m
    obstacles = [Obstacle((1.2, offset), radius_m=radius),
                 Obstacle((2.2, -offset), radius_m=radius)]
    return StandardScenario(team, reference, obstacles)
