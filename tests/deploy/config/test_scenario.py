"""Scenario files: the shipped ones load and are consistent; bad files name the bad field."""

from __future__ import annotations

import copy
import re
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

from core.model.obstacles import Obstacle
from core.nmpc.settings import MpcSettings, SafetySettings
from deploy.bench.obstacle_family import family
from deploy.cli.porter import main
from deploy.config.files import ConfigError, load_settings
from deploy.config.scenario import (
    DEFAULT_SCENARIO,
    SCENARIO_DIR,
    ObstacleSpec,
    ReferenceSpec,
    Scenario,
    load_scenario,
    shipped_scenarios,
)

SHIPPED = ["crossing_heavy", "four_go2", "heavy_payload_pushes", "mixed_three",
           "mixed_three_pushes",
           "moving_obstacle", "narrow_passage", "obstacle_on_line", "two_go2"]
# The paper's scenarios; the others are the hardest cases of `porter bench obstacles` that end
# safely (crossing_heavy at the goal, obstacle_on_line in a controlled stop).
PAPER = [name for name in SHIPPED if name not in ("crossing_heavy", "obstacle_on_line")]


def base_document() -> dict[str, Any]:
    """A minimal valid scenario: two robots, straight 3 m path, 12 s."""
    return {
        "name": "test",
        "team": [
            {"name": "front", "robot_type": "go2", "coupling_point_in_payload_m": [0.55, 0, 0],
             "coupling_point_in_robot_m": [0, 0, 0.1343]},
            {"name": "rear", "robot_type": "go2", "coupling_point_in_payload_m": [-0.55, 0, 0],
             "coupling_point_in_robot_m": [0, 0, 0.1343]},
        ],
        "payload": {"mass_kg": 5.0},
        "reference": {"waypoints_m": [[0, 0], [3, 0]], "speed_m_s": 0.3},
        "obstacles": [{"position_m": [1.5, 0.65], "radius_m": 0.1}],
        "duration_s": 12.0,
    }


def write(tmp_path: Path, document: dict[str, Any], name: str = "scenario.yaml") -> Path:
    path = tmp_path / name
    path.write_text(yaml.safe_dump(document))
    return path


def test_base_document_is_valid(tmp_path: Path) -> None:
    scenario = load_scenario(write(tmp_path, base_document()))
    assert scenario.payload.true_mass_kg is None and scenario.true_payload_mass_kg == 5.0
    assert scenario.controller.mode == "distributed" and scenario.gait.duty_factor == 0.5
    assert scenario.disturbances.mocap_position_noise_m == 0.002


def test_shipped_scenarios_listed_and_default_exists() -> None:
    assert shipped_scenarios() == SHIPPED
    assert DEFAULT_SCENARIO in shipped_scenarios()
    assert load_scenario().name == DEFAULT_SCENARIO


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_scenario_loads_and_is_consistent(name: str) -> None:
    scenario = load_scenario(name)
    assert scenario.name == name
    assert scenario == load_scenario(SCENARIO_DIR / f"{name}.yaml")
    if name not in PAPER:
        return  # see test_the_obstacle_family_scenarios_are_what_they_say
    assert scenario.expected_outcome == "goal"
    assert "Paper" in scenario.description
    assert scenario.duration_s <= 16.0
    # The reference reaches its goal about 2 s before the end.
    travel = scenario.reference.path_length_m / scenario.reference.speed_m_s
    assert 1.5 <= scenario.duration_s - travel <= 2.5
    assert scenario.reference.speed_m_s == 0.3 and scenario.reference.payload_height_m == 0.45
    team = scenario.team_settings()
    assert [a.name for a in team.agents] == [a.name for a in scenario.team]
    assert team.payload.mass_kg == scenario.payload.mass_kg
    # Ring layout: coupling points 0.55 m from the payload centre, at the payload's height.
    for agent in scenario.team:
        assert np.hypot(*agent.coupling_point_in_payload_m[:2]) == pytest.approx(0.55, abs=1e-4)
    obstacles = scenario.core_obstacles()
    assert all(isinstance(o, Obstacle) for o in obstacles) and len(obstacles) >= 2
    # Every obstacle's margin is clear at the start and at the goal (the robots can stop there).
    goal = scenario.reference.to_reference().goal_m()
    for obstacle in obstacles:
        end = np.asarray(obstacle.position_m) + scenario.duration_s * np.asarray(
            obstacle.velocity_m_s)
        for xy in scenario.initial_positions_m().values():
            margin = scenario.safety_distance_m + obstacle.radius_m
            assert np.linalg.norm(np.asarray(xy) - obstacle.position_m) > margin
            assert np.linalg.norm(goal + np.asarray(xy) - end) > margin


def test_the_obstacle_family_scenarios_are_what_they_say() -> None:
    """obstacle_on_line: a static obstacle whose margin covers the reference line, far enough
    that the team starts outside it; a controlled stop is expected after the blocked-team
    timeout and before the end. crossing_heavy: the family's cross_3r_12kg_0.3 case (same
    team, payload, obstacle), run long enough to reach the goal after yielding."""
    scenario = load_scenario("obstacle_on_line")
    assert scenario.expected_outcome == "controlled stop"
    (obstacle,) = scenario.core_obstacles()
    assert obstacle.velocity_m_s == (0.0, 0.0) and obstacle.position_m[1] == 0.0
    start, goal = scenario.reference.waypoints_m[0][0], scenario.reference.waypoints_m[-1][0]
    assert start < obstacle.position_m[0] < goal
    blocked_s = scenario.mpc_settings(MpcSettings()).braking.blocked_stop_s
    assert blocked_s is not None
    # the team reaches the obstacle within ~6 s (0.3 m/s), then waits blocked_s, brakes for
    # controlled_stop_s and sits down (2 s) before the end
    assert scenario.duration_s >= 6.0 + blocked_s + 2.0 + 2.0
    heavy = load_scenario("crossing_heavy")
    case = next(s for s in family() if s.name == "cross_3r_12kg_0.3")
    assert heavy.expected_outcome == "goal"
    for field in ("team", "payload", "obstacles", "reference", "safety_distance_m"):
        assert getattr(heavy, field) == getattr(case, field), field
    assert heavy.duration_s > case.duration_s


def test_shipped_scenarios_mirror_the_paper() -> None:
    two = load_scenario("two_go2")
    assert len(two.obstacles) == 7 and [a.robot_type for a in two.team] == ["go2", "go2"]
    mixed = load_scenario("mixed_three")
    assert len(mixed.obstacles) == 6
    assert sorted(a.robot_type for a in mixed.team) == ["a1", "go2", "go2"]
    assert len(load_scenario("four_go2").team) == 4
    heavy = load_scenario("heavy_payload_pushes")
    assert heavy.payload.mass_kg == 5.0 and heavy.true_payload_mass_kg == 12.0
    assert {p.target for p in heavy.disturbances.pushes} == {"go2_0", "payload"}
    moving = load_scenario("moving_obstacle")
    assert any(o.velocity_m_s != (0.0, 0.0) for o in moving.obstacles)
    narrow = load_scenario("narrow_passage")
    assert narrow.safety_distance_m == 0.45
    left, right = sorted(narrow.obstacles, key=lambda o: o.position_m[1])
    gap = right.position_m[1] - left.position_m[1] - left.radius_m - right.radius_m
    assert gap >= 2 * narrow.safety_distance_m + 0.2


def test_mpc_settings_map_the_scenario_fields(tmp_path: Path) -> None:
    document = base_document()
    document["safety_distance_m"] = 0.45
    document["controller"] = {"admm_iterations": 3, "rho_state": 5e3, "rho_wrench": 2e3}
    scenario = load_scenario(write(tmp_path, document))
    base = MpcSettings(horizon_steps=10)
    settings = scenario.mpc_settings(base)
    assert settings.horizon_steps == 10 and settings.cost == base.cost
    assert settings.safety.safety_distance_m == 0.45
    assert settings.safety.alpha1 == base.safety.alpha1
    assert (settings.admm.iterations, settings.admm.rho_state, settings.admm.rho_wrench) == (
        3, 5e3, 2e3)
    assert settings.coupling.enabled
    assert scenario.mpc_settings().solver == MpcSettings().solver


def test_wrench_only_mode_drops_coupling_and_state_consensus(tmp_path: Path) -> None:
    document = base_document()
    document["controller"] = {"mode": "wrench-only"}
    settings = load_scenario(write(tmp_path, document)).mpc_settings()
    assert not settings.coupling.enabled
    assert settings.admm.rho_state == 0.0
    assert settings.admm.rho_wrench == MpcSettings().admm.rho_wrench


def test_an_explicit_config_value_beats_the_scenario_default(tmp_path: Path) -> None:
    # The scenario file sets no ADMM field: --config's must win (it used to be dropped).
    config = tmp_path / "mpc.yaml"
    config.write_text(yaml.safe_dump({"admm": {"iterations": 3, "rho_wrench": 500.0},
                                      "safety": {"safety_distance_m": 0.5}}))
    document = base_document()
    del document["obstacles"]
    settings = load_scenario(write(tmp_path, document)).mpc_settings(
        load_settings(config, MpcSettings), str(config))
    assert (settings.admm.iterations, settings.admm.rho_wrench) == (3, 500.0)
    assert settings.admm.rho_state == MpcSettings().admm.rho_state
    assert settings.safety.safety_distance_m == 0.5
    # ... and the same value given in both places is no conflict
    document["controller"] = {"admm_iterations": 3}
    agreed = load_scenario(write(tmp_path, document)).mpc_settings(
        load_settings(config, MpcSettings), str(config))
    assert agreed.admm.iterations == 3


@pytest.mark.parametrize(("config", "scenario_field", "names"), [
    ({"admm": {"iterations": 1}}, {"controller": {"admm_iterations": 3}},
     ("admm.iterations = 1", "controller.admm_iterations = 3")),
    ({"admm": {"rho_state": 2e4}}, {"controller": {"rho_state": 1e5}},
     ("admm.rho_state = 20000.0", "controller.rho_state = 100000.0")),
    ({"safety": {"safety_distance_m": 0.6}}, {"safety_distance_m": 0.45},
     ("safety.safety_distance_m = 0.6", "safety_distance_m = 0.45")),
], ids=["iterations", "rho_state", "safety_distance"])
def test_a_conflict_between_config_and_scenario_names_both(
        tmp_path: Path, config: dict, scenario_field: dict, names: tuple[str, str]) -> None:
    path = tmp_path / "mpc.yaml"
    path.write_text(yaml.safe_dump(config))
    document = {**base_document(), **scenario_field}
    scenario = load_scenario(write(tmp_path, document))
    with pytest.raises(ConfigError) as error:
        scenario.mpc_settings(load_settings(path, MpcSettings), str(path))
    message = str(error.value)
    assert names[0] in message and names[1] in message
    assert str(path) in message and "'test'" in message


def test_wrench_only_with_an_explicit_state_consensus_is_a_conflict(tmp_path: Path) -> None:
    document = base_document()
    document["controller"] = {"mode": "wrench-only"}
    scenario = load_scenario(write(tmp_path, document))
    with pytest.raises(ConfigError, match="admm.rho_state = 10.0 .*wrench-only"):
        scenario.mpc_settings(MpcSettings.model_validate({"admm": {"rho_state": 10.0}}))


def test_porter_sim_refuses_a_conflicting_config(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "mpc.yaml"
    path.write_text(yaml.safe_dump({"safety": {"safety_distance_m": 0.6}}))
    assert main(["sim", "narrow_passage", "--config", str(path), "--no-record",
                 "--duration", "0.1", "--quiet"]) == 2
    assert "safety_distance_m = 0.45" in capsys.readouterr().err


def test_payload_true_mass_and_specs() -> None:
    heavy = load_scenario("heavy_payload_pushes")
    assert heavy.team_settings().payload.mass_kg == 5.0
    spec = ObstacleSpec(position_m=(1.0, 2.0), radius_m=0.1, velocity_m_s=(0.0, 0.2))
    obstacle = spec.to_obstacle()
    assert obstacle.row(1.0, 0.6) == pytest.approx([1.0, 2.2, 0.0, 0.2, 0.7])
    reference = ReferenceSpec(waypoints_m=[(0, 0), (3, 0), (3, 4)], speed_m_s=0.5)
    assert reference.path_length_m == pytest.approx(7.0)
    assert reference.to_reference().payload_state(8.0)[0:3] == pytest.approx([3.0, 1.0, 0.45])


def edit(change: Any) -> dict[str, Any]:
    document = copy.deepcopy(base_document())
    change(document)
    return document


BAD = [
    ("unknown key", lambda d: d.update(colour="red"), r"colour: Extra inputs"),
    ("unknown nested key", lambda d: d["reference"].update(sped=0.3),
     r"reference\.sped: Extra inputs"),
    ("bad robot type", lambda d: d["team"][1].update(robot_type="spot"),
     r"team\.1\.robot_type: .*unknown robot type 'spot'.*go2, a1"),
    ("negative mass", lambda d: d["payload"].update(mass_kg=-1.0), r"payload\.mass_kg: "),
    ("negative true mass", lambda d: d["payload"].update(true_mass_kg=0.0),
     r"payload\.true_mass_kg: "),
    ("one robot", lambda d: d["team"].pop(), r"team: .*at least 2"),
    ("duplicate names", lambda d: d["team"][1].update(name="front"), r"team: .*unique"),
    ("push on unknown robot", lambda d: d.update(disturbances={"pushes": [
        {"time_s": 1, "duration_s": 0.2, "target": "go2_7", "force_n": [0, 30, 0]}]}),
     r"disturbances\.pushes\.0\.target: unknown robot 'go2_7'; team is \['front', 'rear'\]"),
    ("push after the end", lambda d: d.update(disturbances={"pushes": [
        {"time_s": 20, "duration_s": 0.2, "target": "payload", "force_n": [0, 30, 0]}]}),
     r"disturbances\.pushes\.0\.time_s: "),
    ("negative noise", lambda d: d.update(disturbances={"mocap_position_noise_m": -0.1}),
     r"disturbances\.mocap_position_noise_m: "),
    ("obstacle inside the payload's margin", lambda d: d["obstacles"].append(
        {"position_m": [0.3, -0.4], "radius_m": 0.1}),
     r"obstacles\.1: starts inside its safety margin: 0\.500 m from the payload centre"),
    ("obstacle inside a robot's margin", lambda d: d["obstacles"].append(
        {"position_m": [-0.55, 0.65], "radius_m": 0.1}),
     r"obstacles\.1: starts inside its safety margin: .* robot 'rear'"),
    ("too many obstacles", lambda d: d.update(obstacles=[
        {"position_m": [5, 0.8 * i], "radius_m": 0.1}
        for i in range(SafetySettings().max_obstacles + 1)]),
     r"obstacles: 9 obstacles, at most 8"),
    ("zero radius", lambda d: d["obstacles"][0].update(radius_m=0), r"obstacles\.0\.radius_m: "),
    ("too short duration", lambda d: d.update(duration_s=8.0),
     r"duration_s: 8\.0 s is too short: the reference needs 10\.00 s"),
    ("waypoint not at the origin", lambda d: d["reference"].update(waypoints_m=[[1, 0], [3, 0]]),
     r"reference\.waypoints_m: .*first waypoint must be \(0, 0\)"),
    ("single waypoint", lambda d: d["reference"].update(waypoints_m=[[0, 0]]),
     r"reference\.waypoints_m: .*at least 2"),
    ("too fast", lambda d: d["reference"].update(speed_m_s=1.5), r"reference\.speed_m_s: "),
    ("bad mode", lambda d: d.update(controller={"mode": "decentralized"}),
     r"controller\.mode: .*'distributed', 'centralized' or 'wrench-only'"),
    ("bad duty factor", lambda d: d.update(gait={"duty_factor": 1.0}), r"gait\.duty_factor: "),
    ("missing duration", lambda d: d.pop("duration_s"), r"duration_s: Field required"),
    ("NaN payload mass", lambda d: d["payload"].update(mass_kg=float("nan")),
     r"payload\.mass_kg: .*finite"),
    ("overlap without a fixed delay", lambda d: d.update(controller={
        "model_computation_delay": True, "overlap_computation": True}),
     r"controller: .*overlap_computation needs .*computation_delay_s"),
    ("infinite obstacle speed", lambda d: d["obstacles"][0].update(
        velocity_m_s=[float("inf"), 0.0]), r"obstacles\.0\.velocity_m_s\.0: .*finite"),
]


@pytest.mark.parametrize(("change", "message"), [(c, m) for _, c, m in BAD],
                         ids=[label for label, _, _ in BAD])
def test_bad_field_is_named(tmp_path: Path, change: Any, message: str) -> None:
    path = write(tmp_path, edit(change), "bad.yaml")
    with pytest.raises(ConfigError, match=f"bad.yaml: .*{message}"):
        load_scenario(path)


def test_cross_field_errors_are_all_reported(tmp_path: Path) -> None:
    document = base_document()
    document["duration_s"] = 5.0
    document["disturbances"] = {"pushes": [
        {"time_s": 1, "duration_s": 0.2, "target": "nobody", "force_n": [0, 30, 0]}]}
    with pytest.raises(ConfigError) as error:
        load_scenario(write(tmp_path, document))
    assert "disturbances.pushes.0.target" in str(error.value)
    assert "duration_s: 5.0 s is too short" in str(error.value)


def test_unknown_scenario_name_lists_the_shipped_ones() -> None:
    with pytest.raises(ConfigError, match="unknown scenario 'three_spot'") as error:
        load_scenario("three_spot")
    for name in SHIPPED:
        assert name in str(error.value)


def test_missing_and_malformed_files(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match=re.escape(f"{tmp_path / 'missing.yaml'}: cannot read")):
        load_scenario(tmp_path / "missing.yaml")
    broken = tmp_path / "broken.yaml"
    broken.write_text("name: x\nteam: [1, 2\n")
    with pytest.raises(ConfigError, match="broken.yaml: not valid YAML"):
        load_scenario(broken)
    listing = tmp_path / "list.yaml"
    listing.write_text("- two_go2\n")
    with pytest.raises(ConfigError, match="expected a mapping"):
        load_scenario(str(listing))


def test_scenario_model_is_frozen() -> None:
    scenario = load_scenario("two_go2")
    with pytest.raises(ValueError, match="frozen"):
        scenario.duration_s = 1.0  # type: ignore[misc]
    assert isinstance(scenario, Scenario)


def test_with_controller_validates_the_whole_controller() -> None:
    scenario = load_scenario("two_go2")
    overlapped = scenario.with_controller(model_computation_delay=True, computation_delay_s=0.012,
                                          overlap_computation=True, executor="serial")
    assert overlapped.controller.overlap_computation
    assert overlapped.controller.computation_delay_s == 0.012
    assert overlapped.controller.executor == "serial" and scenario.controller.executor == "process"
    with pytest.raises(ConfigError, match=r"controller: .*overlap_computation needs"):
        scenario.with_controller(overlap_computation=True)
    # overlapped, the executor defaults to serial; a set executor wins
    delay = {"model_computation_delay": True, "computation_delay_s": 0.012,
             "overlap_computation": True}
    assert scenario.with_controller(**delay).controller.executor == "serial"
    assert scenario.with_controller(**delay, executor="process").controller.executor == "process"
    explicit = scenario.with_controller(executor="process")
    assert explicit.with_controller(**delay).controller.executor == "process"
    with pytest.raises(ConfigError, match=r"controller\.computation_delay_s: .*less than or equal"):
        scenario.with_controller(model_computation_delay=True, computation_delay_s=0.9)
