"""The cooperative-transport NMPC problem, centralized or one ADMM local problem, from one builder.

Both problems share the model, the constraint builders and the cost; they differ only in which
robots they contain and in the ADMM consensus penalty:

* centralized: every robot, the payload, every wrench, every coupling constraint;
* local (agent i): robot i, a local copy of the payload, local copies of all wrenches, robot i's
  coupling constraint, CBFs of robot i and the payload, plus 1/2 ||s - (s_bar - w)||_P^2.

Decision variables per stage k < N: x_k = (robots in the problem, payload), u_k = (their GRFs,
then the wrenches of all n_A agents); x_N at the end. Wrenches lambda^{iL} = (force, torque) act
on the payload at its coupling point and with opposite sign on the robot (world frame).

Model parameters (masses, inertias, coupling points) and, in a local problem, which agent is
"self" (a one-hot vector) are NLP parameters, not constants: one built (and compiled) problem
serves every agent of a team of n_A and every robot type, so a team needs two compiled
problems (local, centralized) instead of n_A + 1 per robot mix.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import casadi as ca
import numpy as np

from core.model.coupling import acceleration_level_constraint, coupling_kinematics, yaw_torque
from core.model.srb_model import (
    GRF_SIZE,
    STATE_SIZE,
    WRENCH_SIZE,
    inertia_entries,
    inertia_matrix,
    payload_acceleration,
    robot_acceleration,
    rotation_body_to_world,
    semi_implicit_euler_step,
)
from core.model.team import TeamModel
from core.nmpc.cbf import OBSTACLE_PARAMETER_SIZE, stagewise_first_order, stagewise_hocbf
from core.nmpc.layout import DecisionRows, shared_indices
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.obstacle_selection import ObstacleSelection, select_obstacles
from core.nmpc.settings import MpcSettings
from core.nmpc.stagewise_nlp import NlpProblem, StagewiseBuilder


def _quadratic(error: ca.SX, weights: list[float] | np.ndarray) -> ca.SX:
    return ca.sum1(ca.DM(weights) * error * error)


ROBOT_MODEL_SIZE = 1 + 6 + 3  # mass, inertia entries, coupling point in robot
SELF = "self"
# Upper bound on a swing foot's normal force [N] (see TransportProblem.decision_bounds).
SWING_FORCE_BOUND_N = 1e-5
# Decision block of the per-stage barrier slack (``SafetySettings.soft_barriers``), in units
# of SLACK_UNIT_M: a slack in millimetres keeps the dual of its bound (the exact penalty's price
# per unit) near the other multipliers' scale, which HPIPM's fast mode needs to stay accurate.
SLACK_BLOCK = "barrier_slack"
SLACK_UNIT_M = 1e-3


@dataclass
class TransportProblem:
    """A built NLP plus the index maps the controllers need to read and write it."""

    nlp: NlpProblem
    settings: MpcSettings
    agent_count: int
    local: bool

    @property
    def horizon_steps(self) -> int:
        return self.settings.horizon_steps

    def robot_keys(self) -> list[str]:
        """Block-name keys of the robots in this problem (``self`` in a local problem)."""
        return [SELF] if self.local else [str(r) for r in range(self.agent_count)]

    def robot_indices(self, agent: int | None) -> list[int]:
        return [self._agent(agent)] if self.local else list(range(self.agent_count))

    def _agent(self, agent: int | None) -> int:
        if agent is None or not 0 <= agent < self.agent_count:
            raise ValueError(f"a local problem needs an agent index in [0, {self.agent_count})")
        return agent

    @cached_property
    def _rows(self) -> DecisionRows:
        return DecisionRows.of(self.nlp.decision, self.horizon_steps, self.robot_keys(),
                               SLACK_BLOCK)

    @cached_property
    def _shared_indices(self) -> np.ndarray:
        return shared_indices(self.nlp.decision, self.horizon_steps, self.agent_count)

    def shared_trajectory(self, solution: np.ndarray) -> np.ndarray:
        """s = (payload states k = 1..N, then wrench j = 1..n_A over k = 0..N-1) from a solution."""
        return np.asarray(solution)[self._shared_indices]

    def consensus_weights(self) -> np.ndarray:
        return consensus_weights(self.settings, self.agent_count)

    def validate(self, inputs: MpcInputs) -> None:
        """``inputs.validate`` for this problem's team, horizon and obstacle capacity."""
        inputs.validate(self.agent_count, self.horizon_steps, self.settings.safety.max_obstacles)

    def decision_bounds(self, contacts: np.ndarray, agent: int | None = None,
                        inputs: MpcInputs | None = None) -> tuple[np.ndarray, np.ndarray]:
        """lbx, ubx: 0 <= f_z <= f_max on stance feet, 0 <= f_z <= 1e-5 N on swing feet,
        sigma >= 0 on the barrier slacks (soft barriers), and with ``inputs`` the robots'
        capability limits (``MpcSettings.capability``) from stage ``from_stage`` on. A robot
        measured beyond a limit gets what it can reach (a speed falling at ``deceleration_m_s2``
        to the limit; the height it has plus the ballistic rise or drop of its vertical speed),
        so a plan never goes further out but the limits never make it infeasible.

        Swing feet get a tiny interval rather than lbx = ubx = 0: fatrop warm-started from a
        previous solve took 18.3 iterations per local solve with fixed variables against 5.1
        with the interval (measured on a trotting MuJoCo run); 1e-5 N is physically zero.

        ``contacts`` is the team's (n_A, N, 4) stance-flag array (legs FL, FR, RL, RR).
        """
        d = self.nlp.decision
        lower, upper = np.full(d.size, -np.inf), np.full(d.size, np.inf)
        f_max = self.settings.contact.max_normal_force_n
        lower[self._rows.slack] = 0.0
        limits, ts = self.settings.capability, self.settings.sample_period_s
        g = self.settings.gravity_m_s2
        stages = np.arange(limits.from_stage, self.horizon_steps + 1)
        for key, r in zip(self.robot_keys(), self.robot_indices(agent), strict=True):
            rows, stance = self._rows.grf_z[key], np.asarray(contacts[r], dtype=float)
            lower[rows] = 0.0
            upper[rows] = f_max * stance + SWING_FORCE_BOUND_N * (1.0 - stance)
            if inputs is None:
                continue
            now, references = inputs.robot_states[r], inputs.robot_references[r]
            starts = self._rows.robot_state[key][stages]  # state (p, v, Theta, omega)
            if limits.max_planar_speed_m_s is not None:  # faster now: slow down to it
                speed = np.maximum(limits.max_planar_speed_m_s, np.abs(now[3:5])
                                   - limits.deceleration_m_s2 * stages[:, None] * ts)
                planar = starts[:, None] + np.array([3, 4])
                lower[planar], upper[planar] = -speed, speed
            if limits.max_height_deviation_m is not None:  # outside: go no further out
                heights, band = references[stages - 1, 2], limits.max_height_deviation_m
                lower[starts + 2] = np.minimum(heights - band,
                                               now[2] - min(now[5], 0.0) ** 2 / (2 * g))
                upper[starts + 2] = np.maximum(heights + band,
                                               now[2] + max(now[5], 0.0) ** 2 / (2 * g))
        return lower, upper

    @property
    def soft_barriers(self) -> bool:
        """Whether the barriers carry a slack (``SafetySettings.soft_barriers``, with slots)."""
        return f"{SLACK_BLOCK}@0" in self.nlp.decision.offsets

    def barrier_slack(self, solution: np.ndarray) -> float:
        """Largest barrier slack of ``solution`` [m] (0 without soft barriers)."""
        if not self.soft_barriers:
            return 0.0
        d = self.nlp.decision
        return SLACK_UNIT_M * float(max(d.get(solution, f"{SLACK_BLOCK}@{k}")[0]
                                        for k in range(self.horizon_steps)))

    def select_obstacles(self, inputs: MpcInputs, guess: np.ndarray | None = None,
                         agent: int | None = None, validated: bool = False
                         ) -> ObstacleSelection:
        """The obstacles this problem constrains at this update: the ``obstacle_slots`` with
        the smallest predicted h over its bodies along the reference and, if given, the warm
        start ``guess`` (``core.nmpc.obstacle_selection``). ``validated``: the caller has
        validated ``inputs`` for this problem (else they are, first)."""
        if not validated:
            self.validate(inputs)
        paths = [np.vstack([inputs.payload_state[None, 0:2], inputs.payload_reference[:, 0:2]])]
        if guess is not None:
            paths.append(np.asarray(guess)[self._rows.payload_state[:, None] + [0, 1]])
        for key, r in zip(self.robot_keys(), self.robot_indices(agent), strict=True):
            paths.append(np.vstack([inputs.robot_states[r][None, 0:2],
                                    inputs.robot_references[r][:, 0:2]]))
            if guess is not None:
                paths.append(np.asarray(guess)[self._rows.robot_state[key][:, None] + [0, 1]])
        return select_obstacles(np.array(paths), inputs.obstacles,
                                self.settings.safety.obstacle_slots,
                                self.settings.sample_period_s)

    def parameter_vector(
        self,
        team: TeamModel,
        inputs: MpcInputs,
        agent: int | None = None,
        consensus_target: np.ndarray | None = None,
        selection: ObstacleSelection | None = None,
        validated: bool = False,
    ) -> np.ndarray:
        """Numeric parameter vector for ``inputs`` (validated first unless ``validated``, as
        in ``select_obstacles``). ``selection``: the obstacles in the slots (default: chosen
        along the reference alone)."""
        if team.agent_count != self.agent_count:
            raise ValueError(f"team has {team.agent_count} agents, problem {self.agent_count}")
        if not validated:
            self.validate(inputs)
        layout = self.nlp.parameters
        values = np.zeros(layout.size)
        for key, r in zip(self.robot_keys(), self.robot_indices(agent), strict=True):
            robot = team.robots[r]
            layout.put(values, f"model_{key}", np.concatenate([
                [robot.mass_kg], inertia_entries(robot.inertia_in_body_kg_m2),
                team.coupling_points_in_robot_m[r],
            ]))
            layout.put(values, f"x0_{key}", inputs.robot_states[r])
            layout.put(values, f"ref_{key}", inputs.robot_references[r])
            layout.put(values, f"feet_{key}", inputs.feet_positions[r])
        layout.put(values, "model_payload", np.concatenate([
            [team.payload.mass_kg], inertia_entries(team.payload.inertia_in_body_kg_m2),
            team.coupling_points_in_payload_m.reshape(-1),
        ]))
        layout.put(values, "x0_payload", inputs.payload_state)
        layout.put(values, "ref_payload", inputs.payload_reference)
        slots = self.settings.safety.obstacle_slots
        if selection is None:
            selection = self.select_obstacles(inputs, None, agent, validated=True)
        layout.put(values, "obstacles", selection.parameters(inputs.obstacles, slots))
        if self.local:
            layout.put(values, "self_selector", np.eye(self.agent_count)[self._agent(agent)])
            if consensus_target is None:
                raise ValueError("a local problem needs the consensus target s_bar - w")
            layout.put(values, "consensus_target", consensus_target)
        return values


def build_transport_problem(
    settings: MpcSettings,
    agent_count: int,
    local: bool = False,
    shared_cost_copies: float = 1.0,
) -> TransportProblem:
    """Build the centralized problem or the (agent-independent) ADMM local problem.

    ``shared_cost_copies`` multiplies the payload and wrench cost terms; the sum of the n_A local
    costs counts them n_A times, so a centralized problem with ``shared_cost_copies=n_A`` is the
    exact equivalent of the distributed one.
    """
    n = settings.horizon_steps
    ts = settings.sample_period_s
    g = settings.gravity_m_s2
    na = agent_count
    keys = [SELF] if local else [str(r) for r in range(na)]
    name = f"{'local' if local else 'centralized'}_{na}agents"
    b = StagewiseBuilder(name, n)
    slots = settings.safety.obstacle_slots
    soft = settings.safety.soft_barriers and slots > 0
    slack: list[ca.SX] = []

    # -- variables, stage by stage
    x_robot: dict[str, list[ca.SX]] = {key: [] for key in keys}
    u_robot: dict[str, list[ca.SX]] = {key: [] for key in keys}
    x_payload: list[ca.SX] = []
    wrench: list[list[ca.SX]] = [[] for _ in range(na)]
    for k in range(n + 1):
        for key in keys:
            x_robot[key].append(b.state(k, f"robot_{key}", STATE_SIZE))
        x_payload.append(b.state(k, "payload", STATE_SIZE))
        if k == n:
            break
        for key in keys:
            u_robot[key].append(b.input(k, f"grf_{key}", GRF_SIZE))
        for j in range(na):
            wrench[j].append(b.input(k, f"wrench_{j}", WRENCH_SIZE))
        if soft:
            slack.append(b.input(k, SLACK_BLOCK, 1))

    # -- parameters
    model_robot = {key: b.parameter(f"model_{key}", ROBOT_MODEL_SIZE) for key in keys}
    model_payload = b.parameter("model_payload", 7 + 3 * na)
    x0_robot = {key: b.parameter(f"x0_{key}", STATE_SIZE) for key in keys}
    x0_payload = b.parameter("x0_payload", STATE_SIZE)
    ref_robot = {key: b.parameter(f"ref_{key}", STATE_SIZE * n) for key in keys}
    ref_payload = b.parameter("ref_payload", STATE_SIZE * n)
    feet = {key: b.parameter(f"feet_{key}", 12 * n) for key in keys}
    obstacles = b.parameter("obstacles", OBSTACLE_PARAMETER_SIZE * slots)
    selector = b.parameter("self_selector", na) if local else None

    payload_mass, payload_inertia = model_payload[0], inertia_matrix(model_payload[1:7])
    points_in_payload = [model_payload[7 + 3 * j : 10 + 3 * j] for j in range(na)]

    def own(key: str, items: list[ca.SX]) -> ca.SX:
        """Robot ``key``'s entry of a per-agent list (selected by the one-hot in a local problem)."""
        if selector is None:
            return items[int(key)]
        return sum((selector[j] * items[j] for j in range(na)), ca.SX.zeros(items[0].shape))

    # -- constraints
    mu = settings.contact.friction_coefficient
    coupling = settings.coupling
    safety = settings.safety
    for key in keys:
        b.path(0, f"x0_{key}", x_robot[key][0] - x0_robot[key], 0.0, 0.0)
    b.path(0, "x0_payload", x_payload[0] - x0_payload, 0.0, 0.0)
    for k in range(n):
        rotation_payload = rotation_body_to_world(x_payload[k][6:9])
        acc_payload = payload_acceleration(
            payload_mass, payload_inertia, x_payload[k],
            [x_payload[k][0:3] + rotation_payload @ c for c in points_in_payload],
            [wrench[j][k] for j in range(na)], g,
        )
        b.dynamics(k, x_payload[k + 1], semi_implicit_euler_step(x_payload[k], acc_payload, ts))
        bodies = [(x_payload[k], acc_payload.linear)]
        for key in keys:
            x = x_robot[key][k]
            point_in_robot = model_robot[key][7:10]
            point_on_robot = x[0:3] + rotation_body_to_world(x[6:9]) @ point_in_robot
            acc = robot_acceleration(
                model_robot[key][0], inertia_matrix(model_robot[key][1:7]), x, u_robot[key][k],
                ca.reshape(feet[key][12 * k : 12 * k + 12], 3, 4), point_on_robot,
                own(key, [wrench[j][k] for j in range(na)]), g,
            )
            b.dynamics(k, x_robot[key][k + 1], semi_implicit_euler_step(x, acc, ts))
            bodies.append((x, acc.linear))
            grf = ca.reshape(u_robot[key][k], 3, 4)
            friction = ca.vertcat(
                grf[0, :].T - mu * grf[2, :].T, -grf[0, :].T - mu * grf[2, :].T,
                grf[1, :].T - mu * grf[2, :].T, -grf[1, :].T - mu * grf[2, :].T,
            )
            b.path(k, f"friction_{key}", friction, -np.inf, 0.0)
            if coupling.enabled:
                kin = coupling_kinematics(
                    x, acc, point_in_robot, x_payload[k], acc_payload,
                    own(key, points_in_payload),
                )
                b.path(k, f"coupling_{key}", acceleration_level_constraint(
                    kin, coupling.baumgarte, coupling.baumgarte_damping_ratio,
                    coupling.baumgarte_natural_frequency_rad_s,
                ), 0.0, 0.0)
        # the yaw-torque equality is the coupling's too (its yaw is free): without the
        # coupling constraints (the paper's wrench-only ablation) it goes with them
        if coupling.enabled and coupling.yaw_torque == "constrain":
            for j in range(na):
                b.path(k, f"yaw_torque_{j}", yaw_torque(x_payload[k], wrench[j][k]), 0.0, 0.0)
        if k >= 1 and slots > 0:
            size = OBSTACLE_PARAMETER_SIZE
            barriers = [
                stagewise_hocbf(x, a, obstacles[size * o : size * (o + 1)], k, ts,
                                safety.alpha1, safety.alpha2)
                for x, a in bodies
                for o in range(slots)
            ]
            if safety.first_order_condition:
                barriers += [
                    stagewise_first_order(x, a, obstacles[size * o : size * (o + 1)], k, ts,
                                          safety.alpha1)
                    for x, a in bodies
                    for o in range(slots)
                ]
            rows = ca.vertcat(*barriers)
            b.path(k, "barriers", rows + SLACK_UNIT_M * slack[k] if soft else rows, 0.0,
                   np.inf)

    # -- cost
    cost = settings.cost
    q_robot = np.array(cost.robot_state.diagonal())
    q_payload = np.array(cost.payload_state.diagonal())
    r_wrench = np.array([cost.wrench_force] * 3 + [cost.wrench_torque] * 3)
    for k in range(1, n + 1):
        factor = cost.terminal_factor if k == n else 1.0
        window = slice(STATE_SIZE * (k - 1), STATE_SIZE * k)
        for key in keys:
            b.cost(factor * _quadratic(x_robot[key][k] - ref_robot[key][window], q_robot))
        b.cost(shared_cost_copies * factor
               * _quadratic(x_payload[k] - ref_payload[window], q_payload))
    for k in range(n):
        for key in keys:
            b.cost(cost.ground_reaction_force * ca.sumsqr(u_robot[key][k]))
        for j in range(na):
            b.cost(shared_cost_copies * _quadratic(wrench[j][k], r_wrench))
    for sigma in (SLACK_UNIT_M * s for s in slack):
        b.cost(safety.slack_penalty_linear * sigma
               + safety.slack_penalty_quadratic * sigma * sigma)
    if local:
        weights = consensus_weights(settings, na)
        target = b.parameter("consensus_target", weights.size)
        shared = ca.vertcat(*x_payload[1:], *[wrench[j][k] for j in range(na) for k in range(n)])
        b.cost(0.5 * _quadratic(shared - target, weights))
    return TransportProblem(
        nlp=b.build(objective_scale=settings.solver.objective_scale),
        settings=settings,
        agent_count=na,
        local=local,
    )


def consensus_weights(settings: MpcSettings, agent_count: int) -> np.ndarray:
    """Diagonal of P = blkdiag(rho_x I, rho_lambda I) over s = (payload states, wrenches)."""
    n = settings.horizon_steps
    admm = settings.admm
    return np.concatenate([
        np.full(n * STATE_SIZE, admm.rho_state),
        np.full(n * WRENCH_SIZE * agent_count, admm.rho_wrench),
    ])

