"""The team as the controller models it: robot SRBs, the payload SRB and the coupling geometry."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from core.model.srb_model import SrbParameters, payload_parameters
from core.model.team_settings import TeamSettings


@dataclass(frozen=True)
class TeamModel:
    """Robots (in team order), payload and, per robot, the coupling point in both bodies [m]."""

    names: tuple[str, ...]
    robot_types: tuple[str, ...]
    robots: tuple[SrbParameters, ...]
    payload: SrbParameters
    coupling_points_in_robot_m: np.ndarray  # (n_agents, 3), robot body frame
    coupling_points_in_payload_m: np.ndarray  # (n_agents, 3), payload body frame

    @property
    def agent_count(self) -> int:
        return len(self.robots)

    def index(self, name: str) -> int:
        try:
            return self.names.index(name)
        except ValueError:
            raise KeyError(f"no agent {name!r}; team is {list(self.names)}") from None

    @staticmethod
    def from_settings(
        team: TeamSettings, robot_parameters: Callable[[str], SrbParameters]
    ) -> TeamModel:
        """Build from validated settings; ``robot_parameters(robot_type)`` gives each robot's SRB."""
        payload = payload_parameters(team.payload.mass_kg, team.payload.principal_inertia_kg_m2())
        return TeamModel(
            names=tuple(a.name for a in team.agents),
            robot_types=tuple(a.robot_type for a in team.agents),
            robots=tuple(robot_parameters(a.robot_type) for a in team.agents),
            payload=payload,
            coupling_points_in_robot_m=np.array(
                [a.coupling_point_in_robot_m for a in team.agents], dtype=float
            ),
            coupling_points_in_payload_m=np.array(
                [a.coupling_point_in_payload_m for a in team.agents], dtype=float
            ),
        )
