"""Closed loop without physics: the coupled robots + payload SRB model integrated at a fine step.

Each robot is driven by its (held) ground reaction forces at fixed feet, plus optional external
pushes. The interaction wrenches are not inputs: they are the constraint wrenches that keep every
yaw-free coupling closed, solved at each fine step from the acceleration-level constraint with
Baumgarte stabilization (so numerical drift stays bounded) and zero torque about the free yaw
axis. This is the centralized model of the NMPC, used as a plant; its payload mass may differ
from the controller's.
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from core.model.coupling import acceleration_level_constraint, coupling_kinematics, yaw_torque
from core.model.srb_model import (
    STATE_SIZE,
    payload_acceleration,
    robot_acceleration,
    rotation_body_to_world,
    semi_implicit_euler_step,
)
from core.model.team import TeamModel


class SrbPlant:
    """Coupled SRB team; ``step`` advances ``substeps`` fine steps of ``dt_s`` each."""

    def __init__(self, team: TeamModel, dt_s: float, gravity_m_s2: float = 9.81,
                 stabilization_frequency_rad_s: float = 30.0) -> None:
        self.team = team
        self.dt_s = dt_s
        na = team.agent_count
        x_robots = [ca.SX.sym(f"x{i}", STATE_SIZE) for i in range(na)]
        x_payload = ca.SX.sym("xL", STATE_SIZE)
        grfs = [ca.SX.sym(f"u{i}", 12) for i in range(na)]
        feet = [ca.SX.sym(f"feet{i}", 3, 4) for i in range(na)]
        pushes = ca.SX.sym("push", 3, na + 1)  # external forces at the CoMs [N], payload last
        wrenches = [ca.SX.sym(f"lam{i}", 6) for i in range(na)]

        payload = team.payload
        rotation_l = rotation_body_to_world(x_payload[6:9])
        points_payload = [ca.DM(c) for c in team.coupling_points_in_payload_m]
        acc_l = payload_acceleration(
            payload.mass_kg, ca.DM(payload.inertia_in_body_kg_m2), x_payload,
            [x_payload[0:3] + rotation_l @ c for c in points_payload], wrenches, gravity_m_s2)
        acc_l.linear = acc_l.linear + pushes[:, na] / payload.mass_kg
        residuals, next_states = [], []
        for i, robot in enumerate(team.robots):
            point = ca.DM(team.coupling_points_in_robot_m[i])
            on_robot = x_robots[i][0:3] + rotation_body_to_world(x_robots[i][6:9]) @ point
            acc = robot_acceleration(robot.mass_kg, ca.DM(robot.inertia_in_body_kg_m2),
                                     x_robots[i], grfs[i], feet[i], on_robot, wrenches[i],
                                     gravity_m_s2)
            acc.linear = acc.linear + pushes[:, i] / robot.mass_kg
            kin = coupling_kinematics(x_robots[i], acc, point, x_payload, acc_l, points_payload[i])
            w = stabilization_frequency_rad_s
            residuals.append(acceleration_level_constraint(kin, True, 1.0, w))
            residuals.append(yaw_torque(x_payload, wrenches[i]))
            next_states.append(semi_implicit_euler_step(x_robots[i], acc, dt_s))
        next_states.append(semi_implicit_euler_step(x_payload, acc_l, dt_s))
        lam = ca.vertcat(*wrenches)
        residual = ca.vertcat(*residuals)
        inputs = [ca.vertcat(*x_robots), x_payload, ca.vertcat(*grfs),
                  ca.horzcat(*feet), pushes]
        # The residual is affine in the wrenches: residual = A lam + b.
        self._linear = ca.Function("coupling_linear", inputs,
                                   [ca.jacobian(residual, lam),
                                    ca.substitute(residual, lam, ca.DM.zeros(lam.shape))])
        self._step = ca.Function("plant_step", [*inputs, lam], [ca.vertcat(*next_states)])
        self._phi = ca.Function("coupling_error", inputs[:2], [ca.vertcat(*[
            coupling_kinematics(x_robots[i], None, ca.DM(team.coupling_points_in_robot_m[i]),
                                x_payload, None, points_payload[i]).phi for i in range(na)])])

    def step(self, robot_states: np.ndarray, payload_state: np.ndarray, grf: np.ndarray,
             feet: np.ndarray, substeps: int, pushes_n: np.ndarray | None = None
             ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Advance; returns robot states (n_A, 12), payload state (12,), last wrenches (n_A, 6).

        ``grf`` (n_A, 12) world GRFs [N], ``feet`` (n_A, 4, 3) foot positions [m],
        ``pushes_n`` (n_A + 1, 3) external forces [N] (robots, then payload).
        """
        na = self.team.agent_count
        x_r = np.asarray(robot_states, float).reshape(-1)
        x_l = np.asarray(payload_state, float)
        feet_matrix = np.hstack([np.asarray(f, float).T for f in feet])
        push = np.zeros((3, na + 1)) if pushes_n is None else np.asarray(pushes_n, float).T
        u = np.asarray(grf, float).reshape(-1)
        lam = np.zeros(6 * na)
        for _ in range(substeps):
            a, b = self._linear(x_r, x_l, u, feet_matrix, push)
            lam = np.linalg.solve(np.asarray(a), -np.asarray(b).ravel())
            nxt = np.asarray(self._step(x_r, x_l, u, feet_matrix, push, lam)).ravel()
            x_r, x_l = nxt[: STATE_SIZE * na], nxt[STATE_SIZE * na :]
        return x_r.reshape(na, STATE_SIZE), x_l, lam.reshape(na, 6)

    def coupling_error(self, robot_states: np.ndarray, payload_state: np.ndarray) -> np.ndarray:
        """phi of every edge, (n_A, 5): translational [m] then rotational [-]."""
        phi = self._phi(np.asarray(robot_states, float).reshape(-1), payload_state)
        return np.asarray(phi).reshape(self.team.agent_count, 5)
