"""``porter deploy``: end to end on the simulated world behind the real drivers (CycloneDDS,
NatNet over UDP, python-can), pre-flight reports, config errors; and its parts (postures, the
MoCap tracker, the base velocity estimate, pacing) on their own."""

from __future__ import annotations

import os
import platform
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
import yaml

from core.estimation.base_velocity import BaseVelocityEstimator
from core.model.conventions import LEG_NAMES
from deploy.bench.deploy_runs import deploy_row, format_budget, format_table, scaled_config
from deploy.cli.porter import main
from deploy.compute import realtime
from deploy.compute.blas_kernels import GENERIC, cpu_target, host_cpu_flags
from deploy.config.deploy_config import CONFIG_DIR, load_deploy_config
from deploy.config.files import ConfigError
from deploy.config.scenario import load_scenario
from deploy.recording.flight_recorder import RecorderSettings
from deploy.recording.log_reader import LogFile
from deploy.runtime.clock import Pacer, PeriodStats
from deploy.safety.posture import PostureMove, sitting_posture, standing_posture
from drivers.interfaces import JointCommand
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import load_pinocchio_model
from tests.deploy.deploy_fixtures import shipped_config_data, write_config

TWO_GO2 = CONFIG_DIR / "two_go2.yaml"
STATES = ["PREFLIGHT", "STANDING_UP", "ARMED", "RUNNING", "SITTING_DOWN", "DONE"]


def _config(tmp_path: Path, **changes: dict) -> Path:
    """The shipped two-Go2 config at the tests' time scale (``TEST_TIME_SCALE``, unless
    ``sim`` names one) with sections updated (merged one level deep)."""
    data = shipped_config_data("two_go2")
    for section, values in changes.items():
        data[section] = {**data.get(section, {}), **values}
    return write_config(data, tmp_path / "deploy.yaml")


# --- end to end ---------------------------------------------------------------------------
@pytest.mark.slow
def test_deploy_on_the_sim_backend_stands_walks_carries_and_sits_down(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The main job at the scenario's full length (16 s): it must complete, not stop itself
    (the shipped config with the robots' safety budgets, at the tests' time scale)."""
    log_path = tmp_path / "run.mcap"
    code = main(["deploy", "--config", str(_config(tmp_path)), "--backend", "sim", "--yes",
                 "--record", str(log_path)])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    log = LogFile(log_path)
    summary = log.summary()
    assert summary is not None and summary["final_state"] == "DONE"
    assert summary["safe_stop"] is None
    # the shipped config's SCHED_FIFO priority where this machine allows it (else a warning),
    # the watchdog's with it
    allowed = realtime.check(50) is None
    assert summary["loop_priority"] == (50 if allowed else None)
    assert summary["watchdog"] == {"enabled": True, "tripped": False,
                                   "priority": summary["loop_priority"]}
    assert ("rates.loop_priority: cannot run the loop" in captured.err) is not allowed
    assert summary["nmpc_nice"] == 10  # the shipped config's: yields its core to the world
    cpus = os.sched_getaffinity(0)  # the shipped CPUs where this machine has them
    assert summary["loop_cpu"] == (0 if 0 in cpus else None)
    assert summary["nmpc_cpus"] == ([1] if 1 in cpus else None)
    assert summary["wbc_failed_ticks"] == 0
    assert summary["run_s"] == pytest.approx(load_deploy_config(TWO_GO2)[1].duration_s, abs=0.1)
    # margin flags are counted and logged, never counted as failed solves
    assert summary["nmpc_margin_flags"] <= summary["nmpc_updates"]
    margin_events = [m.message.text for m in log.messages(["/events"])
                     if "inside safety margin" in m.message.text]
    assert len(margin_events) >= summary["nmpc_margin_flags"]
    # every state, in order, as recorded events
    events = [m.message.text for m in log.messages(["/events"]) if m.message.source == "safety"]
    assert [e.split(":")[0] for e in events] == [
        f"{a} -> {b}" for a, b in zip(STATES[:-1], STATES[1:], strict=True)]
    counts, _, _ = log.message_counts()
    for robot in ("go2_0", "go2_1"):
        for kind in ("state", "command", "wbc", "wrench"):
            assert counts.get(f"/robot/{robot}/{kind}", 0) > 0, (robot, kind)
        assert counts[f"/robot/{robot}/state"] >= counts[f"/robot/{robot}/wbc"]
    # 16 s at 60 Hz nominal, late updates skip instants: 60 Hz here at the tests' 0.2; a 2x
    # slower machine (they differ that much) runs like 0.4 here, where the NMPC kept 60 Hz
    assert counts["/nmpc/update"] >= 16 * 30
    # every decision's outcome is logged, but for one still running when the team sat down
    assert counts["/nmpc/inputs"] - counts["/nmpc/update"] in (0, 1)
    # a warm-start keyframe every recorder.warm_start_every updates (60): the NMPC's process
    # sends its warm start back for those updates only
    every = RecorderSettings().warm_start_every
    keyframes = [m.message.update for m in log.messages(["/nmpc/warm_start"])]
    assert keyframes == list(range(0, counts["/nmpc/update"], every))
    assert log.metadata()["porter"]["backend"] == "sim"
    # the kernels its solvers ran on, for a later replay: this CPU's, or CasADi's where this
    # process had loaded those first
    assert log.metadata()["porter"]["blas_kernels"] in {
        GENERIC, cpu_target(platform.machine(), host_cpu_flags())}
    as_run = yaml.safe_load(log.attachment_text("deploy_config.yaml"))
    assert as_run["scenario"] == "two_go2" and as_run["nmpc"]["runner"] == "process"
    # walked and carried: the payload moved toward the goal (MoCap), nobody fell (truth)
    assert summary["payload"]["progress_toward_goal_m"] > 0.9 * np.hypot(4.2, 0.35)
    truth = summary["sim_ground_truth"]
    # the world's process ran where sim.world_cpus put it (CPU 1; any CPU where there is none)
    available = sorted(os.sched_getaffinity(0))
    assert truth["cpus"] == ([1] if 1 in available else available)
    for robot in truth["robots"].values():
        assert robot["max_tilt_rad"] < 0.3
        assert robot["commands_rejected"] == 0
        assert robot["position_m"][2] < 0.2  # sat down: lying on its belly at the end
    assert min(summary["robot_min_height_running_m"].values()) > 0.25
    # loop timing is reported (simulated seconds when time_scale < 1)
    for loop in ("wbc_loop", "nmpc_loop"):
        assert {"rate_hz", "jitter_p50_ms", "jitter_p99_ms"} <= set(summary[loop])
    assert "wbc_loop" in captured.out
    # porter bench deploy reads exactly this summary
    row = deploy_row(summary)
    assert row["outcome"] == "completed" and row["time_scale"] == summary["time_scale"]
    assert row["wbc_rate_ratio"] == pytest.approx(summary["wbc_loop"]["rate_hz"] / 500.0)
    assert row["nmpc_rate_ratio"] == pytest.approx(summary["nmpc_loop"]["rate_hz"] / 60.0)
    assert "completed" in format_table([row])
    # the loop's collections: counted by generation (start-up frozen out of them), in the budget
    assert set(summary["gc_pauses"]) == {"gen0", "gen1", "gen2"}
    assert summary["gc_pauses"]["gen0"]["collections"] > 0
    gen = summary["gc_pauses"]
    cell = "/".join(str(gen[f"gen{g}"]["collections"]) for g in range(3))
    assert "loop gc" in format_budget([row]) and f" {cell} " in format_budget([row])
    holds = truth["holds"]  # the world's late cycles, in the budget table too
    assert holds["longest_s"] >= 0.0 and holds["over_4_ms"] >= 0
    assert (f" {holds['over_4_ms']} {1e3 * holds['longest_s']:.0f}"
            in format_budget([row]))


@pytest.mark.slow
def test_the_mixed_team_completes_the_full_scenario(tmp_path: Path) -> None:
    """Two Go2 + one A1 over the whole scenario: completes, sits down, reaches the goal."""
    config = write_config(shipped_config_data("two_go2_a1"), tmp_path / "deploy.yaml")
    _, scenario = load_deploy_config(config)
    code = main(["deploy", "--config", str(config), "--backend", "sim", "--yes",
                 "--record", str(tmp_path / "run.mcap")])
    assert code == 0
    summary = LogFile(tmp_path / "run.mcap").summary()
    assert summary is not None and summary["final_state"] == "DONE"
    assert summary["safe_stop"] is None
    assert summary["run_s"] == pytest.approx(scenario.duration_s, abs=0.1)
    goal = np.asarray(scenario.reference.waypoints_m[-1])
    assert np.linalg.norm(np.asarray(summary["payload"]["end_m"][0:2]) - goal) < 0.3


def test_the_four_robot_config_names_every_robot_of_its_scenario() -> None:
    """four_go2.yaml: one Go2 entry and one MoCap body per agent of ``four_go2``, F/T sensor i
    on robot i, at the half speed it is measured at (README, "Four robots")."""
    config, scenario = load_deploy_config(CONFIG_DIR / "four_go2.yaml")
    names = [agent.name for agent in scenario.team]
    assert list(config.robots) == names and len(names) == 4
    assert {config.robots[name].driver for name in names} == {"go2"}
    assert set(config.mocap.bodies) == {*names, "payload"}
    assert config.sim.time_scale == 0.5 and config.nmpc.admm_iterations == 1


@pytest.mark.slow
def test_four_robots_carry_the_payload_and_sit_down(tmp_path: Path) -> None:
    """Four Go2 through the whole deploy sequence for 2 s of RUNNING: done, no safe stop."""
    config = write_config(shipped_config_data("four_go2"), tmp_path / "deploy.yaml")
    code = main(["deploy", "--config", str(config), "--backend", "sim", "--yes",
                 "--duration", "2", "--record", str(tmp_path / "run.mcap")])
    assert code == 0
    summary = LogFile(tmp_path / "run.mcap").summary()
    assert summary is not None and summary["final_state"] == "DONE"
    assert summary["safe_stop"] is None and len(summary["sim_ground_truth"]["robots"]) == 4


FAULT_AT_S = 3.0  # simulated s after the world starts: running by then (stand-up 1.2 s)


@pytest.mark.slow
@pytest.mark.parametrize(("fault", "cause", "reaction_s"), [
    ({"kind": "estop_press"}, "e-stop: run not allowed (e-stop pressed", 0.05),
    ({"kind": "mocap_loss"}, "MoCap lost: no frame for", 0.1 + 0.05),
    # the stale-state budget (50 ms) trips before the link budget (0.1 s)
    ({"kind": "robot_silent", "robot": "go2_1"}, "robot state stale: go2_1", 0.05 + 0.05),
    ({"kind": "robot_frozen", "robot": "go2_0"}, "'frozen tick'", 0.05 + 0.05),
    # 12 repeated frames at 120 Hz make a body unseen, then the MoCap timeout
    ({"kind": "mocap_frozen"}, "MoCap lost: no frame for", 12 / 120 + 0.1 + 0.05),
], ids=["estop", "mocap", "link", "frozen", "mocap_frozen"])
def test_a_fault_while_running_leaves_only_damping_reaching_the_motors(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], fault: dict, cause: str,
        reaction_s: float) -> None:
    """The fake world injects the fault; porter must stop the team (exit 3) and from its
    reaction time on every command the fakes apply is joint damping, until the end."""
    config = _config(tmp_path, posture={"stand_up_s": 1.0, "settle_s": 0.2},
                     sim={"faults": [{"at_s": FAULT_AT_S, **fault}]})
    log_path = tmp_path / "run.mcap"
    code = main(["deploy", "--config", str(config), "--backend", "sim", "--yes",
                 "--duration", "5", "--record", str(log_path)])
    captured = capsys.readouterr()
    assert code == 3, captured.err
    log = LogFile(log_path)
    summary = log.summary()
    assert summary is not None and summary["final_state"] == "DONE"
    assert cause in summary["safe_stop"]
    events = [m.message.text for m in log.messages(["/events"]) if m.message.source == "safety"]
    assert [e.split(":")[0] for e in events][-2:] == ["RUNNING -> SAFE_STOP", "SAFE_STOP -> DONE"]
    truth = summary["sim_ground_truth"]
    assert [f["kind"] for f in truth["faults_applied"]] == [fault["kind"]]
    for name, robot in truth["robots"].items():
        after = robot["after_fault"]
        # damping kept arriving through SAFE_STOP and DONE (0.5 s each at 500 Hz) ...
        assert after["commands"] > 200, (name, after)
        # ... and nothing else once the supervisor could have seen the fault
        assert after["non_damping"] == 0 or after["last_non_damping_s"] < reaction_s, (
            name, after)


def test_ctrl_c_sits_the_team_down_and_closes_the_log(tmp_path: Path) -> None:
    """SIGINT while standing up (real time: the posture phases need little CPU)."""
    config = _config(tmp_path, sim={"time_scale": 1.0})
    log_path = tmp_path / "run.mcap"
    process = subprocess.Popen(
        [sys.executable, "-m", "deploy.cli", "deploy", "--config", str(config), "--backend",
         "sim", "--yes", "--record", str(log_path)], stdout=subprocess.PIPE,
        stderr=subprocess.PIPE, text=True, cwd=Path(__file__).parents[3])
    assert process.stderr is not None
    lines = []
    for line in process.stderr:
        lines.append(line)
        if "PREFLIGHT -> STANDING_UP" in line:
            process.send_signal(signal.SIGINT)
            break
    _, rest = process.communicate(timeout=120)
    err = "".join(lines) + rest
    assert process.returncode == 130, err
    assert "STANDING_UP -> SITTING_DOWN: requested: begin_sit_down" in err
    assert "SITTING_DOWN -> DONE" in err and "stop requested while standing up" in err
    summary = LogFile(log_path).summary()
    assert summary is not None and summary["result"] == "stop requested while standing up"


def test_preflight_reports_what_is_missing(tmp_path: Path,
                                           capsys: pytest.CaptureFixture[str]) -> None:
    """No CAN node (no e-stop heartbeat, no F/T) and a robot Motive does not track."""
    config = _config(tmp_path, sim={"can_node": False, "untracked_bodies": ["go2_1"],
                                    "time_scale": 1.0},
                     preflight={"timeout_s": 1.0})
    code = main(["deploy", "--config", str(config), "--backend", "sim", "--yes",
                 "--no-record"])
    err = capsys.readouterr().err
    assert code == 1, err
    assert "[MISSING] e-stop heartbeat: no e-stop heartbeat received yet" in err
    assert "[MISSING] coupling F/T sensors: no sample from go2_0, go2_1" in err
    assert "[MISSING] MoCap rigid bodies: not tracked: go2_1 (rigid body 'go2_1')" in err
    assert "[ok] robot go2_0 link" in err and "[ok] MoCap server" in err
    assert "STANDING_UP" not in err  # never stood up


def test_on_robots_with_nothing_connected_preflight_names_every_link(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = yaml.safe_load(TWO_GO2.read_text())
    for link in data["robots"].values():
        link.update(release_sport_mode=False, topic_prefix=f"test_{id(tmp_path)}")
    data["mocap"]["data_port"] = 0  # any free port
    data["preflight"]["timeout_s"] = 0.3
    path = tmp_path / "hw.yaml"
    path.write_text(yaml.safe_dump(data))
    code = main(["deploy", "--config", str(path), "--yes", "--record", str(tmp_path / "hw.mcap")])
    err = capsys.readouterr().err
    assert code == 1, err
    assert "[MISSING] link: CAN: cannot open socketcan channel 'can0'" in err
    assert "[MISSING] robot go2_0 link: go2_0: " in err and "no valid state received yet" in err
    assert "[MISSING] MoCap server: no answer from NatNet server 127.0.0.1:1510" in err
    events = [m.message.text for m in LogFile(tmp_path / "hw.mcap").messages(["/events"])]
    assert "PREFLIGHT -> DONE: requested: finish" in events


def test_an_invalid_config_field_is_named(tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    data = yaml.safe_load(TWO_GO2.read_text())
    data["robots"]["go2_0"]["domain"] = 3
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["deploy", "--config", str(path), "--backend", "sim", "--yes"]) == 2
    err = capsys.readouterr().err
    assert "robots.go2_0.go2.domain" in err and "Extra inputs are not permitted" in err


def test_network_interface_must_exist_on_this_host(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    data = yaml.safe_load(TWO_GO2.read_text())
    data["network_interface"] = "enp9s9-absent"
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    assert main(["deploy", "--config", str(path), "--backend", "sim", "--yes"]) == 2
    err = capsys.readouterr().err
    assert "network_interface" in err and "no network interface 'enp9s9-absent'" in err
    assert "lo" in err  # the interfaces it has are listed
    data["network_interface"] = "lo"
    path.write_text(yaml.safe_dump(data))
    assert load_deploy_config(path)[0].network_interface == "lo"


def test_config_cross_checks_name_the_field(tmp_path: Path) -> None:
    data = yaml.safe_load(TWO_GO2.read_text())
    data["robots"]["a1_9"] = data["robots"].pop("go2_1")
    path = tmp_path / "team.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=r"robots: must name the scenario's team.*missing "
                       r"\['go2_1'\], unknown \['a1_9'\]"):
        load_deploy_config(path)
    data = yaml.safe_load(TWO_GO2.read_text())
    data["mocap"]["local_address"] = "192.168.1.5"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="mocap.local_address: 192.168.1.5 is not a loopback"):
        load_deploy_config(path)
    data["network_interface"] = "eth0"
    path.write_text(yaml.safe_dump(data))
    assert load_deploy_config(path)[0].mocap.local_address == "192.168.1.5"


def test_the_nmpc_executor_overrides_the_scenario_default_and_conflicts_are_named(
        tmp_path: Path) -> None:
    scenario = yaml.safe_load((CONFIG_DIR.parent / "scenarios" / "two_go2.yaml").read_text())
    (tmp_path / "mine.yaml").write_text(yaml.safe_dump(scenario))
    path = _config(tmp_path, nmpc={"runner": "process", "executor": "serial"})
    data = yaml.safe_load(path.read_text())
    data["scenario"] = "mine.yaml"
    path.write_text(yaml.safe_dump(data))
    config, loaded = load_deploy_config(path)
    assert config.nmpc.runner == "process" and loaded.controller.executor == "serial"
    scenario["controller"] = {**scenario.get("controller", {}), "executor": "process"}
    (tmp_path / "mine.yaml").write_text(yaml.safe_dump(scenario))
    with pytest.raises(ConfigError, match=r"nmpc.executor: 'serial', but the scenario sets "
                       r"controller.executor: 'process'"):
        load_deploy_config(path)
    data["nmpc"] = {"runner": "thread"}  # no executor: the scenario's stands
    path.write_text(yaml.safe_dump(data))
    assert load_deploy_config(path)[1].controller.executor == "process"
    data["nmpc"] = {"runner": "fiber"}
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="nmpc.runner"):
        load_deploy_config(path)
    data["nmpc"] = {"runner": "thread", "nice": -10}  # a thread has the loop's process
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="nmpc.nice: -10 needs nmpc.runner: process"):
        load_deploy_config(path)
    data["nmpc"] = {"runner": "thread", "cpus": [1]}  # so do its CPUs
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match=re.escape("nmpc.cpus: [1] needs nmpc.runner: process")):
        load_deploy_config(path)


def test_the_nmpc_admm_iterations_override_the_scenario_default_and_conflicts_are_named(
        tmp_path: Path) -> None:
    scenario = yaml.safe_load((CONFIG_DIR.parent / "scenarios" / "two_go2.yaml").read_text())
    (tmp_path / "mine.yaml").write_text(yaml.safe_dump(scenario))
    path = _config(tmp_path, nmpc={"admm_iterations": 3})
    data = yaml.safe_load(path.read_text())
    data["scenario"] = "mine.yaml"
    path.write_text(yaml.safe_dump(data))
    loaded = load_deploy_config(path)[1]
    assert loaded.controller.admm_iterations == 3
    assert loaded.mpc_settings().admm.iterations == 3  # what the NMPC is built with
    scenario["controller"] = {**scenario.get("controller", {}), "admm_iterations": 2}
    (tmp_path / "mine.yaml").write_text(yaml.safe_dump(scenario))
    with pytest.raises(ConfigError, match=r"nmpc.admm_iterations: 3, but the scenario sets "
                       r"controller.admm_iterations: 2"):
        load_deploy_config(path)
    data["nmpc"]["admm_iterations"] = 2  # the same value twice is no conflict
    path.write_text(yaml.safe_dump(data))
    assert load_deploy_config(path)[1].controller.admm_iterations == 2
    data["nmpc"]["admm_iterations"] = 0
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(ConfigError, match="nmpc.admm_iterations"):
        load_deploy_config(path)


@pytest.mark.parametrize(("values", "message"), [
    ({"cpus": []}, "nmpc.cpus"),
    ({"cpus": [1, 1]}, "nmpc.cpus.*names a CPU twice"),
    ({"cpus": [0, 1]}, r"nmpc.cpus: \[0, 1\] includes rates.loop_cpu 0"),  # the shipped loop's
])
def test_the_nmpc_cpus_are_distinct_and_apart_from_the_loops(tmp_path: Path, values: dict,
                                                             message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        load_deploy_config(_config(tmp_path, nmpc=values))


@pytest.mark.parametrize(("rates", "sim", "message"), [
    ({"loop_priority": 50}, {"world_priority": 50}, r"sim.world_priority: 50 must be below "
                                                    r"rates.loop_priority \(50\)"),
    ({"loop_priority": None}, {"world_priority": 10}, r"sim.world_priority: 10 must be below "
                                                      r"rates.loop_priority \(None\)"),
    ({"loop_priority": 50}, {"world_priority": 99}, "sim.world_priority"),
])
def test_the_world_priority_stays_below_the_loops(tmp_path: Path, rates: dict, sim: dict,
                                                  message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        load_deploy_config(_config(tmp_path, rates=rates, sim=sim))
    fine, _ = load_deploy_config(_config(tmp_path, rates={"loop_priority": 50},
                                         sim={"world_priority": 40}))
    assert fine.sim.world_priority == 40


@pytest.mark.parametrize(("sim", "message"), [
    ({"world_cpus": [0]}, r"sim.world_cpus: \[0\] includes rates.loop_cpu 0"),
    ({"world_cpus": [1, 1]}, r"sim.world_cpus.*names a CPU twice"),
    ({"world_cpus": []}, "sim.world_cpus"),
])
def test_the_world_keeps_off_the_loops_core(tmp_path: Path, sim: dict, message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        load_deploy_config(_config(tmp_path, rates={"loop_cpu": 0}, sim=sim))
    fine, _ = load_deploy_config(_config(tmp_path, rates={"loop_cpu": 0}, sim={"world_cpus": [1]}))
    assert fine.sim.world_cpus == [1]


@pytest.mark.parametrize(("section", "values", "field"), [
    ("safety", {"damping_kd": 0.0}, "safety.damping_kd"),
    ("safety", {"max_tilt_rad": 100.0}, "safety.max_tilt_rad"),
    ("safety", {"max_consecutive_solver_failures": 1000000000},
     "safety.max_consecutive_solver_failures"),
    ("safety", {"mocap_timeout_s": float("inf")}, "safety.mocap_timeout_s"),
    ("rates", {"max_plan_age_s": float("nan")}, "rates.max_plan_age_s"),
    ("rates", {"loop_priority": 0}, "rates.loop_priority"),
    ("rates", {"loop_priority": 100}, "rates.loop_priority"),
    ("rates", {"loop_cpu": -1}, "rates.loop_cpu"),
    ("nmpc", {"cpus": [-1]}, "nmpc.cpus"),
    ("nmpc", {"nice": -21}, "nmpc.nice"),
    ("mocap", {"stale_timeout_s": 30.0}, "mocap.stale_timeout_s"),
    ("posture", {"kd": 0.0}, "posture.kd"),
    ("safety", {"deadline_overrun_budget": 200}, "deadline_overrun_budget 200 can never"),
    ("safety", {"deadline_overrun_budget": 60}, "deadline_overrun_budget 60 can never"),
    # 500 late ticks can never be more than the 500 ticks of a 1 s window at 500 Hz
    ("safety", {"loop_overrun_budget": 500}, "loop_overrun_budget 500 can never"),
    ("safety", {"loop_overrun_budget": 300, "deadline_window_s": 0.5,
                "deadline_overrun_budget": 10},
     "loop_overrun_budget 300 can never"),
])
def test_configs_cannot_switch_safety_off(tmp_path: Path, section: str, values: dict,
                                          field: str) -> None:
    """Every float finite, every timeout, gain and budget within its physical range: the
    message names the field and the range."""
    path = _config(tmp_path, **{section: values})
    with pytest.raises(ConfigError, match=re.escape(field)) as error:
        load_deploy_config(path)
    assert any(word in str(error.value) for word in ("less than", "greater than", "finite",
                                                      "never be used up"))


@pytest.mark.parametrize("duration", ["-1", "0", "inf", "nan", "soon"])
def test_command_line_numbers_are_validated(duration: str,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["deploy", "--config", str(TWO_GO2), "--backend", "sim", "--yes",
              "--duration", duration])
    assert exit_info.value.code == 2
    assert "argument --duration" in capsys.readouterr().err


def test_shipped_configs_load() -> None:
    for path in sorted(CONFIG_DIR.glob("*.yaml")):
        config, scenario = load_deploy_config(path)
        assert sorted(config.robots) == sorted(agent.name for agent in scenario.team)
        assert config.network_interface is None  # loopback unless a user names one
        # the sim backend keeps the robots' safety budgets (README: real time on two cores)
        assert config.sim.safety_overrides == {}
        assert config.sim_safety() == config.safety


def test_bench_deploy_scales_a_copy_of_the_config(tmp_path: Path) -> None:
    scenario_file = tmp_path / "mine.yaml"
    scenario_file.write_text(yaml.safe_dump(
        yaml.safe_load((CONFIG_DIR.parent / "scenarios" / "two_go2.yaml").read_text())))
    original = _config(tmp_path)
    data = yaml.safe_load(original.read_text())
    data["scenario"] = "mine.yaml"  # relative to the config: must survive the copy
    original.write_text(yaml.safe_dump(data))
    copies = tmp_path / "copies"
    copies.mkdir()
    config, scenario = load_deploy_config(scaled_config(original, 0.35, copies))
    assert config.sim.time_scale == 0.35
    assert config.robots == load_deploy_config(original)[0].robots
    assert scenario == load_deploy_config(original)[1]
    assert config.rates == load_deploy_config(original)[0].rates  # the config's own priority
    for priority in (None, 7):  # --loop-priority none / 7: the copy's only other change
        changed, _ = load_deploy_config(scaled_config(original, 0.35, copies, priority))
        assert changed.rates.loop_priority == priority
        assert changed.sim == config.sim and changed.robots == config.robots


@pytest.mark.parametrize(("text", "ok"), [("none", True), ("50", True), ("0", False),
                                          ("100", False), ("high", False)])
def test_bench_deploy_loop_priorities_are_validated(text: str, ok: bool,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    from deploy.cli.porter import build_parser
    parser = build_parser()
    if ok:
        args = parser.parse_args(["bench", "deploy", "--loop-priority", text])
        assert args.loop_priority == [None if text == "none" else int(text)]
    else:
        with pytest.raises(SystemExit):
            parser.parse_args(["bench", "deploy", "--loop-priority", text])
        assert "argument --loop-priority" in capsys.readouterr().err


def test_no_record_is_refused_on_robots(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["deploy", "--config", str(TWO_GO2), "--no-record"]) == 2
    assert "every run on robots is recorded" in capsys.readouterr().err


def test_robots_never_run_without_the_watchdog(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    path = _config(tmp_path, watchdog={"enabled": False})
    assert main(["deploy", "--config", str(path), "--yes"]) == 2
    assert "watchdog.enabled: false is refused on robots" in capsys.readouterr().err


# --- parts ----------------------------------------------------------------------------------
@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_sitting_posture_lowers_the_trunk_with_the_feet_in_place(robot_type: str) -> None:
    model = load_pinocchio_model(robot_type)
    data = model.createData()
    feet = [model.getFrameId(f"{leg}_foot") for leg in LEG_NAMES]

    def feet_in_base(legs: np.ndarray) -> np.ndarray:
        q = pin.neutral(model)
        q[7:] = legs  # LEG_JOINT_NAMES order is the URDF's
        pin.framesForwardKinematics(model, data, q)
        return np.array([data.oMf[f].translation for f in feet])

    standing = feet_in_base(standing_posture(robot_type))
    sitting = feet_in_base(sitting_posture(robot_type, 0.1))
    np.testing.assert_allclose(sitting - standing, np.tile([0.0, 0.0, 0.1], (4, 1)), atol=1e-5)


def test_posture_move_is_smooth_and_ends_at_the_goal() -> None:
    start, goal = np.zeros(12), np.full(12, 1.0)
    move = PostureMove(start, goal, start_s=10.0, duration_s=2.0, kp=60.0, kd=3.0)
    assert np.allclose(move.command(10.0).position_rad, 0.0)
    assert np.allclose(move.command(11.0).position_rad, 0.5)
    assert np.allclose(move.command(11.0).velocity_rad_s, 0.75)  # 6 s (1 - s) / T at s = 1/2
    assert np.allclose(move.command(13.0).position_rad, 1.0) and move.done(12.0)
    assert np.allclose(move.command(12.0).velocity_rad_s, 0.0)


def test_leg_odometry_matches_the_simulated_base_velocity() -> None:
    scenario = load_scenario("two_go2")
    scene = build_team_scene(scenario.team_settings(), timestep_s=0.001)
    simulation = TeamSimulation(scene)
    for name in ("go2_0", "go2_1"):
        simulation.set_command(name, JointCommand.hold(standing_posture("go2"), 60.0, 3.0))
    simulation.apply_push("payload", np.array([40.0, 20.0, 0.0]), 0.3)
    estimator = BaseVelocityEstimator(load_pinocchio_model("go2"))
    driver = simulation.robot_driver("go2_0")
    errors, speeds = [], []
    for _ in range(400):
        simulation.step(2)
        measurement = driver.read()
        legs = estimator.leg_odometry(measurement)
        assert legs is not None
        errors.append(np.linalg.norm(legs - measurement.linear_velocity_in_world_m_s))
        speeds.append(np.linalg.norm(measurement.linear_velocity_in_world_m_s))
    assert max(speeds) > 0.05  # it moved
    assert np.sqrt(np.mean(np.square(errors))) < 0.015  # m/s (feet slip a little)


def test_pacer_keeps_the_period_and_reanchors_when_late() -> None:
    now = [0.0]
    pacer = Pacer(0.002, clock=lambda: now[0], sleep=lambda s: now.__setitem__(0, now[0] + s))
    stats = PeriodStats(0.002)
    for tick in range(5):
        stats.tick(now[0])
        now[0] += 0.0005 if tick != 2 else 0.0065  # tick 2 takes 6.5 ms
        pacer.wait()
    assert pacer.overruns == 1
    summary = stats.summary()
    assert summary["ticks"] == 5 and summary["late_ticks"] == 1
    assert summary["period_p50_ms"] == pytest.approx(2.0)


def test_period_stats_of_a_real_sleep_loop() -> None:
    pacer = Pacer(0.005)
    stats = PeriodStats(0.005)
    for _ in range(20):
        stats.tick(time.monotonic())
        pacer.wait()
    # never faster than its period; slower only as far as a loaded machine makes it
    assert 50.0 <= stats.summary()["rate_hz"] <= 200.0 * 1.02
