"""Size and structure of the centralized and local (ADMM) transport problems (paper, Table I)."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from core.model.srb_model import GRF_SIZE, STATE_SIZE, WRENCH_SIZE
from core.model.team import TeamModel
from core.model.team_settings import AgentSettings, TeamSettings
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.settings import CouplingSettings, MpcSettings, SafetySettings
from core.nmpc.transport_problem import SLACK_BLOCK, TransportProblem, build_transport_problem
from drivers.robot_descriptions import srb_parameters

N_X, N_U, N_LAMBDA = STATE_SIZE, GRF_SIZE, WRENCH_SIZE
# Paper, Table I: decision variables (local, centralized) for N = 8.
PAPER_COUNTS = {2: (408, 612), 3: (456, 864), 4: (504, 1116)}
# The paper's problem has hard barriers; soft barriers (the default) add one slack per stage.
HARD = SafetySettings(soft_barriers=False)


def _centralized_count(agents: int, horizon: int) -> int:
    return (agents + 1) * (horizon + 1) * N_X + agents * horizon * (N_U + N_LAMBDA)


def _local_count(agents: int, horizon: int) -> int:
    return horizon * (2 * N_X + N_U + agents * N_LAMBDA) + 2 * N_X


@pytest.fixture(scope="module")
def problems() -> dict[tuple[int, bool], TransportProblem]:
    return {
        (n, local): build_transport_problem(MpcSettings(safety=HARD), agent_count=n, local=local)
        for n in PAPER_COUNTS
        for local in (False, True)
    }


def test_sizes_are_the_papers() -> None:
    assert (N_X, N_U, N_LAMBDA) == (12, 12, 6)
    assert MpcSettings().horizon_steps == 8
    for agents, (local, centralized) in PAPER_COUNTS.items():
        assert _local_count(agents, 8) == local
        assert _centralized_count(agents, 8) == centralized


@pytest.mark.parametrize("agents", sorted(PAPER_COUNTS))
def test_decision_variable_counts(problems, agents: int) -> None:
    horizon = MpcSettings().horizon_steps
    centralized = problems[(agents, False)]
    local = problems[(agents, True)]
    assert centralized.nlp.variable_count == _centralized_count(agents, horizon)
    assert local.nlp.variable_count == _local_count(agents, horizon)
    assert (local.nlp.variable_count, centralized.nlp.variable_count) == PAPER_COUNTS[agents]
    # The decision vector really has that many symbols.
    assert centralized.nlp.casadi_dict()["x"].numel() == centralized.nlp.variable_count
    assert local.nlp.casadi_dict()["x"].numel() == local.nlp.variable_count


@pytest.mark.parametrize("agents", [2, 3])
@pytest.mark.parametrize("horizon", [3, 5])
def test_counts_follow_the_formula_for_other_horizons(agents: int, horizon: int) -> None:
    settings = MpcSettings(horizon_steps=horizon, safety=HARD)
    assert (build_transport_problem(settings, agents).nlp.variable_count
            == _centralized_count(agents, horizon))
    assert (build_transport_problem(settings, agents, local=True).nlp.variable_count
            == _local_count(agents, horizon))
    # soft barriers: one slack per stage k < N, an input of that stage
    soft = MpcSettings(horizon_steps=horizon)
    assert soft.safety.soft_barriers
    for local, count in ((False, _centralized_count(agents, horizon)),
                         (True, _local_count(agents, horizon))):
        problem = build_transport_problem(soft, agents, local=local)
        assert problem.nlp.variable_count == count + horizon
        assert problem.soft_barriers
        assert [problem.nlp.decision.offsets[f"{SLACK_BLOCK}@{k}"][1]
                for k in range(horizon)] == [1] * horizon


@pytest.mark.parametrize("local", [False, True])
@pytest.mark.parametrize("agents", sorted(PAPER_COUNTS))
def test_stage_structure_sums_to_the_variable_count(problems, agents: int, local: bool) -> None:
    nlp = problems[(agents, local)].nlp
    horizon = MpcSettings().horizon_steps
    structure = nlp.structure
    assert len(structure.state_sizes) == len(structure.input_sizes) == horizon + 1
    assert len(structure.path_constraint_counts) == horizon + 1
    assert sum(structure.state_sizes) + sum(structure.input_sizes) == nlp.variable_count
    bodies = 2 if local else agents + 1
    robots = 1 if local else agents
    assert structure.state_sizes == [bodies * N_X] * (horizon + 1)
    assert structure.input_sizes == [robots * N_U + agents * N_LAMBDA] * horizon + [0]
    # Every constraint row is a dynamics gap or a path constraint of some stage.
    gaps = sum(structure.state_sizes[1:])
    assert nlp.constraints.numel() == gaps + sum(structure.path_constraint_counts)
    assert len(nlp.lower_constraints) == len(nlp.upper_constraints) == nlp.constraints.numel()


@pytest.mark.parametrize("agents", sorted(PAPER_COUNTS))
def test_local_problem_is_agent_independent(problems, agents: int) -> None:
    """One local problem serves every agent: its robot blocks are "self", and which agent that is
    is a one-hot parameter, not part of the built problem."""
    local = problems[(agents, True)].nlp
    robot_blocks = {name.split("@")[0] for name in local.decision.offsets
                    if name.startswith(("robot_", "grf_"))}
    assert robot_blocks == {"robot_self", "grf_self"}
    selector = local.parameters.slice("self_selector")
    assert selector.stop - selector.start == agents
    wrench_blocks = {name.split("@")[0] for name in local.decision.offsets
                     if name.startswith("wrench_")}
    assert wrench_blocks == {f"wrench_{j}" for j in range(agents)}


# -- the one local problem, parameterized for agent i, reproduces the centralized model of robot i


def _team() -> TeamModel:
    settings = TeamSettings(agents=[
        AgentSettings(name="a", robot_type="go2", coupling_point_in_payload_m=(0.5, 0.0, 0.0)),
        AgentSettings(name="b", robot_type="a1", coupling_point_in_payload_m=(-0.3, 0.4, 0.0),
                      coupling_point_in_robot_m=(0.02, 0.0, 0.12)),
        AgentSettings(name="c", robot_type="go2", coupling_point_in_payload_m=(-0.3, -0.4, 0.0),
                      coupling_point_in_robot_m=(-0.01, 0.01, 0.08)),
    ])
    return TeamModel.from_settings(settings, srb_parameters)


def _inputs(rng: np.random.Generator, agents: int, horizon: int) -> MpcInputs:
    def states(*shape: int) -> np.ndarray:
        x = rng.normal(size=(*shape, STATE_SIZE)) * 0.3
        x[..., 2] += 0.3
        return x

    return MpcInputs(
        robot_states=states(agents),
        payload_state=states(),
        robot_references=states(agents, horizon),
        payload_reference=states(horizon),
        feet_positions=rng.normal(size=(agents, horizon, 4, 3)),
        contacts=rng.integers(0, 2, size=(agents, horizon, 4)).astype(float),
        obstacles=np.array([[2.0, 1.0, 0.1, 0.0, 0.6]]),
    )


def _gap_rows(problem: TransportProblem, stage: int, block: int) -> slice:
    """Rows of the dynamics gap of the ``block``-th state block leaving ``stage``: per stage, the
    gaps (in state-declaration order) come first, then the path constraints."""
    s = problem.nlp.structure
    start = sum(s.state_sizes[j + 1] + s.path_constraint_counts[j] for j in range(stage))
    return slice(start + block * N_X, start + (block + 1) * N_X)


def _stage_rows(problem: TransportProblem, stage: int) -> slice:
    """All constraint rows (gaps, then path constraints) of ``stage``."""
    s = problem.nlp.structure
    start = sum(s.state_sizes[j + 1] + s.path_constraint_counts[j] for j in range(stage))
    gaps = s.state_sizes[stage + 1] if stage < len(s.state_sizes) - 1 else 0
    return slice(start, start + gaps + s.path_constraint_counts[stage])


def test_local_problem_reproduces_centralized_constraints_for_every_agent() -> None:
    settings = MpcSettings(horizon_steps=3)
    assert settings.safety.soft_barriers
    horizon, agents = settings.horizon_steps, 3
    team = _team()
    rng = np.random.default_rng(0)
    inputs = _inputs(rng, agents, horizon)
    centralized = build_transport_problem(settings, agents)
    local = build_transport_problem(settings, agents, local=True)

    def constraint_function(problem: TransportProblem) -> ca.Function:
        d = problem.nlp.casadi_dict()
        return ca.Function("g", [d["x"], d["p"]], [d["g"]])

    g_c, g_l = constraint_function(centralized), constraint_function(local)
    dc, dl = centralized.nlp.decision, local.nlp.decision
    w_c = rng.normal(size=dc.size)
    for k in range(horizon + 1):  # keep bodies upright-ish so rotations are well conditioned
        for name in [f"robot_{r}@{k}" for r in range(agents)] + [f"payload@{k}"]:
            block = dc.get(w_c, name).copy()
            block[6:8] *= 0.2
            dc.put(w_c, name, block)
    p_c = centralized.parameter_vector(team, inputs)
    values_c = np.array(g_c(w_c, p_c)).squeeze()

    target = np.zeros(local.consensus_weights().size)
    for agent in range(agents):
        w_l = np.zeros(dl.size)
        for k in range(horizon + 1):
            dl.put(w_l, f"robot_self@{k}", dc.get(w_c, f"robot_{agent}@{k}"))
            dl.put(w_l, f"payload@{k}", dc.get(w_c, f"payload@{k}"))
            if k < horizon:
                dl.put(w_l, f"grf_self@{k}", dc.get(w_c, f"grf_{agent}@{k}"))
                for j in range(agents):
                    dl.put(w_l, f"wrench_{j}@{k}", dc.get(w_c, f"wrench_{j}@{k}"))
                dl.put(w_l, f"{SLACK_BLOCK}@{k}", dc.get(w_c, f"{SLACK_BLOCK}@{k}"))
        p_l = local.parameter_vector(team, inputs, agent=agent, consensus_target=target)
        values_l = np.array(g_l(w_l, p_l)).squeeze()
        for k in range(horizon):
            robot_c = values_c[_gap_rows(centralized, k, agent)]
            payload_c = values_c[_gap_rows(centralized, k, agents)]
            np.testing.assert_allclose(values_l[_gap_rows(local, k, 0)], robot_c, atol=1e-9)
            np.testing.assert_allclose(values_l[_gap_rows(local, k, 1)], payload_c, atol=1e-9)
        # Every local constraint (coupling of agent i, friction, CBFs, ...) is one of the
        # centralized problem's constraints of the same stage, with the same bounds.
        for k in range(horizon + 1):
            rows_l, rows_c = _stage_rows(local, k), _stage_rows(centralized, k)
            for row in range(rows_l.start, rows_l.stop):
                distance = np.abs(values_c[rows_c] - values_l[row])
                match = rows_c.start + int(np.argmin(distance))
                assert distance.min() < 1e-9, f"agent {agent}, stage {k}: local row {row} unmatched"
                assert local.nlp.lower_constraints[row] == centralized.nlp.lower_constraints[match]
                assert local.nlp.upper_constraints[row] == centralized.nlp.upper_constraints[match]
        # Robots differ (types, coupling points), so another agent's dynamics must not match.
        other = (agent + 1) % agents
        assert not np.allclose(values_l[_gap_rows(local, 0, 0)],
                               values_c[_gap_rows(centralized, 0, other)], atol=1e-6)


def test_local_robot_feels_only_its_own_wrench() -> None:
    settings = MpcSettings(horizon_steps=2)
    agents = 3
    local = build_transport_problem(settings, agents, local=True)
    team = _team()
    rng = np.random.default_rng(1)
    inputs = _inputs(rng, agents, settings.horizon_steps)
    d = local.nlp.casadi_dict()
    decision = local.nlp.decision
    robot_gap = d["g"][_gap_rows(local, 0, 0)]
    wrench_jacobians = ca.Function("wrench_jacobians", [d["x"], d["p"]], [
        ca.jacobian(robot_gap, decision.symbols[list(decision.offsets).index(f"wrench_{j}@0")])
        for j in range(agents)
    ])
    w = rng.normal(size=decision.size) * 0.2
    target = np.zeros(local.consensus_weights().size)
    for agent in range(agents):
        p = local.parameter_vector(team, inputs, agent=agent, consensus_target=target)
        norms = [np.abs(np.array(jac)).max() for jac in wrench_jacobians(w, p)]
        assert norms[agent] > 1e-3
        assert all(norms[j] == 0.0 for j in range(agents) if j != agent)


@pytest.mark.parametrize("local", [False, True])
def test_without_the_coupling_no_coupling_constraint_is_left(local: bool) -> None:
    def blocks(enabled: bool) -> set[str]:
        settings = MpcSettings(safety=HARD, coupling=CouplingSettings(enabled=enabled))
        problem = build_transport_problem(settings, agent_count=2, local=local)
        return {name.split("@")[0] for name in problem.nlp.constraint_blocks}
    coupled, free = blocks(True), blocks(False)
    assert {"yaw_torque_0", "yaw_torque_1"} <= coupled
    assert any(name.startswith("coupling_") for name in coupled)
    assert not any(name.startswith(("coupling_", "yaw_torque_")) for name in free), free
