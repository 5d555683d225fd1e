"""Delay compensation: plan from the state the team will be in when the plan takes effect.

An NMPC update that takes ``delay_s`` to compute is applied ``delay_s`` after the state it was
computed from was measured. Planning from the measured state then applies a plan for a state
that is ``delay_s`` old. Instead, the measured states are moved forward by the motion the
active plan predicts over the delay,

    x_predicted = x_measured + x_plan(elapsed + delay_s) - x_plan(elapsed),

with ``elapsed`` the time since the active plan's stage 0 and ``x_plan`` its trajectory
interpolated between stages (held at the last one). The plan's own dynamics model (the SRB
model under the GRFs and wrenches it applies) predicts the motion; the measurement keeps its
offset from the plan, so a disturbance that moved the team is not forgotten. World frame,
SI units, the SRB state order (p, v, Theta, omega).
"""

from __future__ import annotations

import numpy as np

from core.nmpc.mpc_plan import MpcPlan


def interpolate_trajectory(trajectory: np.ndarray, elapsed_s: float, sample_period_s: float
                           ) -> np.ndarray:
    """State of a (N + 1, 12) stage trajectory ``elapsed_s`` after stage 0, linear between
    stages, held at the ends."""
    position = float(np.clip(elapsed_s / sample_period_s, 0.0, trajectory.shape[0] - 1))
    k = min(int(position), trajectory.shape[0] - 2)
    fraction = position - k
    return (1.0 - fraction) * trajectory[k] + fraction * trajectory[k + 1]


def predict_states(plan: MpcPlan, elapsed_s: float, delay_s: float, robot_states: np.ndarray,
                   payload_state: np.ndarray, sample_period_s: float
                   ) -> tuple[np.ndarray, np.ndarray]:
    """(robot states (n_A, 12), payload state (12,)) predicted ``delay_s`` ahead of the
    measured ones, by the motion ``plan`` predicts from ``elapsed_s`` after its stage 0."""
    def motion(trajectory: np.ndarray) -> np.ndarray:
        return (interpolate_trajectory(trajectory, elapsed_s + delay_s, sample_period_s)
                - interpolate_trajectory(trajectory, elapsed_s, sample_period_s))

    robots = np.array([state + motion(trajectory) for state, trajectory
                       in zip(robot_states, plan.robot_trajectories, strict=True)])
    return robots, payload_state + motion(plan.payload_trajectory)
