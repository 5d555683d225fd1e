"""Typed controller settings with the paper's values as defaults.

Every number here is in SI units. Settings are plain pydantic models: the caller loads YAML
(see ``deploy/``), validates it into these models, and passes them to constructors. Nothing
here reads files.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from core.model.strict_model import StrictModel


class SrbWeights(StrictModel):
    """Diagonal SRB tracking weights Q = blkdiag(Q_p, Q_v, Q_theta, Q_omega) (paper, Sec. IV-A)."""

    position: tuple[float, float, float] = (1e7, 1e7, 16e7)
    velocity: tuple[float, float, float] = (1e6, 1e6, 1e6)
    euler: tuple[float, float, float] = (1e7, 1e7, 1e7)
    angular_velocity: tuple[float, float, float] = (1e5, 1e5, 1e5)

    def diagonal(self) -> list[float]:
        """The 12 diagonal entries in state order (p, v, Theta, omega)."""
        return [*self.position, *self.velocity, *self.euler, *self.angular_velocity]


class CostSettings(StrictModel):
    """Cost weights of the NMPC; defaults are the paper's."""

    robot_state: SrbWeights = SrbWeights()
    payload_state: SrbWeights = SrbWeights()
    terminal_factor: float = Field(10.0, gt=0)
    ground_reaction_force: float = Field(20.0, gt=0)
    wrench_force: float = Field(50.0, gt=0)
    wrench_torque: float = Field(500.0, gt=0)


class CouplingSettings(StrictModel):
    """Yaw-free rigid coupling between each robot and the payload. ``enabled`` False removes
    every coupling constraint of the NLP (the holonomic constraints and the yaw-torque
    equality): the robots and the payload then interact through the wrenches alone."""

    enabled: bool = True
    yaw_torque: Literal["constrain", "penalize"] = "constrain"
    baumgarte: bool = False
    baumgarte_damping_ratio: float = Field(1.0, gt=0)
    baumgarte_natural_frequency_rad_s: float = Field(10.0, gt=0)


class SafetySettings(StrictModel):
    """Discrete-time HOCBF obstacle avoidance."""

    alpha1: float = Field(0.4, gt=0, le=1)
    alpha2: float = Field(0.04, gt=0, le=1)
    safety_distance_m: float = Field(0.6, gt=0)
    max_obstacles: int = Field(8, ge=0)  # obstacles a scene may hold
    # Obstacle slots of each built problem: the K obstacles nearest to its bodies over the
    # horizon, chosen per update (core.nmpc.obstacle_selection); at most max_obstacles.
    obstacle_slots: int = Field(3, ge=0)
    # Also enforce psi1 = h_{k+1} - (1 - alpha1) h_k >= 0 at stages 1..N-1 (see
    # core.nmpc.cbf.stagewise_first_order): robustness to model mismatch; not in the paper.
    first_order_condition: bool = True
    # Soft barriers: every barrier row of stage k reads c(x_k, u_k) + sigma_k >= 0 with one
    # slack sigma_k >= 0 per stage, priced by an exact penalty rho1 sigma + rho2 sigma^2 (per
    # metre, unscaled cost units). While the hard problem is feasible the linear price exceeds
    # every barrier multiplier, so the solution is the hard one (sigma = 0); when it is not, the
    # solver still returns the plan that violates the barriers least, and the slack it used is
    # reported (``MpcPlan.barrier_slack_m``) instead of a failed solve.
    soft_barriers: bool = True
    slack_penalty_linear: float = Field(1e10, gt=0)
    slack_penalty_quadratic: float = Field(1e7, gt=0)
    # A plan whose slack exceeds this is ``relaxed`` (the safety constraints were infeasible).
    slack_tolerance_m: float = Field(0.01, gt=0, le=0.1)

    @model_validator(mode="before")
    @classmethod
    def _default_slots_within_scene(cls, data: object) -> object:
        # The default K never conflicts with an explicit, smaller max_obstacles.
        if isinstance(data, dict) and "obstacle_slots" not in data and "max_obstacles" in data:
            default = cls.model_fields["obstacle_slots"].default
            return {**data, "obstacle_slots": min(default, data["max_obstacles"])}
        return data

    @model_validator(mode="after")
    def _slots_within_scene(self) -> SafetySettings:
        if self.obstacle_slots > self.max_obstacles:
            raise ValueError(f"obstacle_slots ({self.obstacle_slots}) must be at most "
                             f"max_obstacles ({self.max_obstacles})")
        return self


class ContactSettings(StrictModel):
    friction_coefficient: float = Field(0.4, gt=0)
    max_normal_force_n: float = Field(250.0, gt=0)


class ChannelSettings(StrictModel):
    """The ADMM messages as a lossy network delivers them (the paper's study: delays of up to
    20 communication rounds, drop probability 0.5, hold-last, in both directions).

    Each ADMM round every message is dropped with ``drop_probability`` or arrives after a
    delay drawn uniformly from 0..``max_delay_rounds`` rounds (one round = one ADMM
    iteration); the receiver holds the newest one that arrived, shifted one stage per MPC
    update since it was sent. The messages: uplink, each agent's shared trajectory s^i to
    the consensus; downlink (``downlink``, the paper's bidirectional channel), the
    coordinator's target s-bar - w^i to agent i, which solves with the newest target it
    holds. The default (0, 0) is a perfect network. ``seed`` makes a run repeatable (the two
    directions draw independently). ``max_age_rounds`` (porter's, not the paper's): an
    uplink message held longer than this is left out of the consensus and its agent's dual
    waits; None is the paper's pure hold-last. The downlink is always pure hold-last."""

    max_delay_rounds: int = Field(0, ge=0, le=1000)
    drop_probability: float = Field(0.0, ge=0.0, lt=1.0)
    seed: int = Field(0, ge=0)
    max_age_rounds: int | None = Field(2, ge=0)
    downlink: bool = True

    @property
    def perfect(self) -> bool:
        return self.max_delay_rounds == 0 and self.drop_probability == 0.0


class AdmmSettings(StrictModel):
    """ADMM consensus over payload-state and wrench trajectories."""

    iterations: int = Field(2, ge=1)
    rho_state: float = Field(1e4, ge=0)
    rho_wrench: float = Field(1e3, gt=0)
    channel: ChannelSettings = ChannelSettings()


class BrakingSettings(StrictModel):
    """The braking backup: when plans stay infeasible, stop the team instead of pressing on.

    ``after_flagged_updates`` plans in a row that relaxed their safety constraints (soft
    barriers used slack) or failed to solve start braking: the payload reference becomes
    ``core.nmpc.reference.BrakingReference`` (decelerate along the current heading at
    ``deceleration_m_s2``, then hold), latched for the rest of the run; ``controlled_stop_s``
    after braking began the team sits down (a controlled stop, not a safe stop).
    ``blocked_stop_s``: a team that the reference governor has held back this long without a
    break (no progress along the reference: an obstacle it cannot pass, the CBF deadlock in
    front of an obstacle on the line) brakes as well, and sits down; None: it waits forever."""

    enabled: bool = True
    after_flagged_updates: int = Field(3, ge=1, le=60)
    deceleration_m_s2: float = Field(0.5, gt=0.0, le=5.0)
    controlled_stop_s: float = Field(2.0, gt=0.0, le=30.0)
    blocked_stop_s: float | None = Field(15.0, gt=1.0, le=600.0)


class CapabilitySettings(StrictModel):
    """What a trotting robot can follow, as bounds on each robot's planned SRB state from stage
    ``from_stage`` on (earlier stages stay reachable from any measured state): CoM speed per
    horizontal axis (world) at most ``max_planar_speed_m_s``, CoM height within
    ``max_height_deviation_m`` of its reference. None lifts a bound. Without them an evasion
    the barriers demand was planned at 0.9 m/s sideways, or braking pressed the feet down
    until the trunk rose 6 cm, and the legs could not follow (calves past their limits: falls).
    A robot measured faster than the limit is planned to slow down to it at
    ``deceleration_m_s2`` (so the limit can never make the plan infeasible)."""

    max_planar_speed_m_s: float | None = Field(0.5, ge=0.1, le=5.0)
    max_height_deviation_m: float | None = Field(0.03, ge=0.005, le=0.3)
    deceleration_m_s2: float = Field(2.0, gt=0.0, le=20.0)
    from_stage: int = Field(2, ge=1, le=50)


SolverName = Literal["fatrop", "rti", "ipopt", "ipopt-reference"]


class SolverSettings(StrictModel):
    """Which NLP solver runs the problems, and whether its derivatives are compiled.

    ``rti`` (default): one SQP step per solve on HPIPM's stage-wise QP (real-time iteration);
    ``fatrop``: the structure-exploiting interior point run to convergence; ``ipopt-reference``
    is the paper-faithful configuration (IPOPT + MUMPS, CasADi expressions interpreted, primal
    warm start, adaptive mu, tol 1e-6) kept for comparison.
    """

    name: SolverName = "rti"
    compiled: bool = True
    max_iterations: int = Field(50, ge=1)
    tolerance: float = Field(1e-4, gt=0)
    objective_scale: float = Field(1e-5, gt=0)
    # Interior-point warm start of fatrop (measured: 14.4 -> 4.3 iterations per local solve in
    # closed loop versus fatrop's defaults mu_init 1e-1, bound_push 1e-2).
    initial_barrier: float = Field(1e-4, gt=0)
    bound_push: float = Field(1e-5, gt=0)
    # ``rti``: SQP steps per solve (1 = real-time iteration) on HPIPM's stage-wise QP. HPIPM
    # mode by measurement on closed-loop QPs: ``speed`` matched ``robust`` within 0.03 N at a
    # quarter of its time; ``speed_abs`` was off by up to 7 N and stalled the iterated SQP.
    sqp_steps: int = Field(1, ge=1)
    qp_mode: Literal["speed_abs", "speed", "balance", "robust"] = "speed"
    qp_max_iterations: int = Field(30, ge=1)
    # ``rti`` warm steps: HPIPM's initial barrier (mu0) and its exit tolerance on every
    # residual (stationarity, equality, inequality, complementarity; in the scaled problem's
    # units). Measured on 718 closed-loop local QPs against converged fatrop (first-stage GRF):
    # HPIPM's speed-mode defaults (mu0 10, tolerances 1e-6 / 1e-8) gave p95 0.22 N, max 24.3 N;
    # mu0 1 with 1e-3 gave p95 0.045 N, max 0.29 N at ~0.6x the QP time (fewer iterations).
    qp_initial_barrier: float = Field(1.0, gt=0)
    qp_tolerance: float = Field(1e-3, gt=0, le=1.0)


class MpcSettings(StrictModel):
    """Everything the centralized and distributed NMPC builders need besides the models."""

    horizon_steps: int = Field(8, ge=2)
    sample_period_s: float = Field(1.0 / 60.0, gt=0)
    gravity_m_s2: float = 9.81
    cost: CostSettings = CostSettings()
    coupling: CouplingSettings = CouplingSettings()
    safety: SafetySettings = SafetySettings()
    contact: ContactSettings = ContactSettings()
    admm: AdmmSettings = AdmmSettings()
    solver: SolverSettings = SolverSettings()
    braking: BrakingSettings = BrakingSettings()
    capability: CapabilitySettings = CapabilitySettings()
