"""The one builder of an NMPC decision's inputs, for the MuJoCo/robot loop and the SRB harness.

From the states the caller measured (or predicted), in the world frame: references at stages
1..N from the waypoint reference at ``reference_time_s``, each robot's foot positions and
contacts over the horizon from its own foothold plan, and the obstacles at
``obstacle_time_s``. ``hold_pose`` zeroes the reference velocities (standing still while the
team settles); ``stand_still`` also holds the stage-1 reference pose over the whole horizon (the
reference governor waits for a team that lags behind).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from core.model.obstacles import Obstacle
from core.model.team import TeamModel
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.reference import BrakingReference, WaypointReference, horizon_references
from core.nmpc.settings import MpcSettings

__all__ = ["FootHorizon", "build_mpc_inputs"]

# (agent, its SRB state (12,), its references (N, 12)) -> (feet (N, 4, 3) [m], contacts (N, 4))
FootHorizon = Callable[[int, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]]


def build_mpc_inputs(team: TeamModel, reference: WaypointReference | BrakingReference,
                     settings: MpcSettings,
                     robot_states: np.ndarray, payload_state: np.ndarray,
                     reference_time_s: float, foot_horizon: FootHorizon,
                     obstacles: Sequence[Obstacle], obstacle_time_s: float,
                     hold_pose: bool = False, stand_still: bool = False) -> MpcInputs:
    """``MpcInputs`` for robots at ``robot_states`` (n_A, 12) and the payload at
    ``payload_state`` (12,); times in seconds."""
    n, ts = settings.horizon_steps, settings.sample_period_s
    robot_refs, payload_ref = horizon_references(team, reference, reference_time_s, n, ts)
    if stand_still:
        robot_refs[:] = robot_refs[:, :1]
        payload_ref[:] = payload_ref[:1]
    if hold_pose or stand_still:
        robot_refs[:, :, 3:6] = 0.0
        payload_ref[:, 3:6] = 0.0
    feet, contacts = [], []
    for i in range(team.agent_count):
        f, c = foot_horizon(i, robot_states[i], robot_refs[i])
        feet.append(f)
        contacts.append(c)
    d_safe = settings.safety.safety_distance_m
    obstacle_rows = np.array([o.row(obstacle_time_s, d_safe) for o in obstacles]).reshape(-1, 5)
    return MpcInputs(robot_states, payload_state, robot_refs, payload_ref, np.array(feet),
                     np.array(contacts), obstacle_rows)
