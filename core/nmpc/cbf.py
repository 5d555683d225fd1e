"""Obstacle-avoidance safety functions and their discrete-time HOCBF (relative degree two).

h(x) = ||g(x) - o|| - d_safe with g(x) the planar CoM position [m]. The DT-HOCBF condition of
[DT-HOCBF] over the horizon is

    h_{k+2} - (2 - a1 - a2) h_{k+1} + (1 - a1)(1 - a2) h_k >= 0,  k = 0 .. N-2.

With the semi-implicit Euler model (core.model.srb_model), p_{j-1} = p_j - Ts v_j and
p_{j+1} = p_j + Ts (v_j + Ts a_j), so the condition centred on stage j = k+1 depends only on
stage j's state and acceleration (hence inputs): the constraint is stage-wise, as structure-
exploiting solvers need, and exactly equal to the three-stage form.

Obstacles are parameters: (o_x, o_y, vo_x, vo_y, d) per obstacle with o the position at the
first stage [m], vo a constant velocity [m/s] used to predict o over the horizon, and d the
safety distance [m] (d_safe plus the obstacle radius, if any).
"""

from __future__ import annotations

import casadi as ca

from core.model.srb_model import Expr

OBSTACLE_PARAMETER_SIZE = 5
# An unused obstacle slot is parked here: far away, so its barrier is inactive.
PARKED_OBSTACLE = (1e4, 1e4, 0.0, 0.0, 0.0)


def obstacle_position(obstacle: Expr, stage: int, sample_period_s: float) -> Expr:
    """Predicted planar obstacle position [m] at ``stage`` (constant-velocity model)."""
    return obstacle[0:2] + stage * sample_period_s * obstacle[2:4]


def safety_function(position_xy: Expr, obstacle_xy: Expr, distance_m: Expr) -> Expr:
    """h = ||p - o|| - d [m]."""
    return ca.norm_2(position_xy - obstacle_xy) - distance_m


def hocbf_condition(h0: Expr, h1: Expr, h2: Expr, alpha1: float, alpha2: float) -> Expr:
    """Left-hand side of the DT-HOCBF condition (>= 0 is safe)."""
    return h2 - (2 - alpha1 - alpha2) * h1 + (1 - alpha1) * (1 - alpha2) * h0


def stage_safety_values(
    x: Expr, linear_acceleration: Expr, obstacle: Expr, stage: int, sample_period_s: float
) -> tuple[Expr, Expr, Expr]:
    """(h_{k-1}, h_k, h_{k+1}) for k = ``stage`` (>= 1) from stage k's state and acceleration."""
    ts = sample_period_s
    p, v = x[0:2], x[3:5]
    p_prev = p - ts * v
    p_next = p + ts * (v + ts * linear_acceleration[0:2])
    d = obstacle[4]
    h_prev, h, h_next = (
        safety_function(pos, obstacle_position(obstacle, s, ts), d)
        for pos, s in ((p_prev, stage - 1), (p, stage), (p_next, stage + 1))
    )
    return h_prev, h, h_next


def stagewise_hocbf(
    x: Expr,
    linear_acceleration: Expr,
    obstacle: Expr,
    stage: int,
    sample_period_s: float,
    alpha1: float,
    alpha2: float,
) -> Expr:
    """DT-HOCBF centred on ``stage`` (>= 1) from that stage's state and acceleration only."""
    h = stage_safety_values(x, linear_acceleration, obstacle, stage, sample_period_s)
    return hocbf_condition(*h, alpha1, alpha2)


def first_order_condition(h: Expr, h_next: Expr, alpha1: float) -> Expr:
    """psi1_k = h_{k+1} - (1 - a1) h_k (>= 0 is safe).

    The DT-HOCBF keeps {psi1 >= 0} invariant only for an exact model. Against a plant whose
    motion differs from the semi-implicit Euler prediction (by Ts^2 a / 2 per step for a held
    force), the small alpha2 lets psi1 drift negative step after step; enforcing psi1 >= 0 from
    stage 1 on (stage 0 is fixed by the measurement) bounds that drift.
    """
    return h_next - (1 - alpha1) * h


def stagewise_first_order(
    x: Expr,
    linear_acceleration: Expr,
    obstacle: Expr,
    stage: int,
    sample_period_s: float,
    alpha1: float,
) -> Expr:
    """psi1 at ``stage`` (>= 1) from that stage's state and acceleration only."""
    _, h, h_next = stage_safety_values(x, linear_acceleration, obstacle, stage, sample_period_s)
    return first_order_condition(h, h_next, alpha1)
