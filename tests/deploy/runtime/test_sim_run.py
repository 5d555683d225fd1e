"""The team in physics: every shipped scenario walks to its goal; determinism; estimator."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import Scenario, load_scenario, shipped_scenarios
from deploy.runtime.sim_run import LOCKSTEP_EXECUTOR_SPIN_S, SimRun, lockstep_spin_s

ROOT = Path(__file__).resolve().parents[3]
# Wall-clock fields: they differ between runs by nature.
TIMING_KEYS = {"nmpc_update_ms", "deadline_misses", "wbc_tick_ms", "real_time_factor",
               "nlp_solve_ms_median", "wall_s", "nmpc_wall_s", "wbc_wall_s",
               "loop_tick_ms"}


def _short(name: str, duration_s: float, **controller: object) -> Scenario:
    scenario = load_scenario(name)
    update = {"executor": "serial", **controller}
    return scenario.model_copy(update={
        "duration_s": duration_s,
        "controller": scenario.controller.model_copy(update=update)})


def _run(scenario: Scenario) -> dict:
    loop = SimRun(scenario, CompiledCodeCache())
    try:
        return loop.run()
    finally:
        loop.close()


def test_same_seed_gives_identical_summary() -> None:
    first = _run(_short("two_go2", 1.0))
    second = _run(_short("two_go2", 1.0))
    assert first["nmpc_updates"] == 60
    for key in set(first) - TIMING_KEYS:
        assert first[key] == second[key], key


def test_different_seed_changes_the_noisy_run() -> None:
    base = _short("two_go2", 0.5)
    first = _run(base)
    other = _run(base.model_copy(update={"seed": base.seed + 1}))
    assert first["rms_payload_position_error_m"] != other["rms_payload_position_error_m"]


def test_estimator_tracks_ground_truth_while_trotting() -> None:
    summary = _run(_short("two_go2", 1.5))
    error = summary["payload_estimate_error"]
    assert summary["falls"] == 0
    # MoCap noise is 2 mm / 5 mrad; the couplings are stiff welds (< 0.3 mm)
    assert error["position_rms_m"] < 0.006
    assert error["tilt_max_rad"] < 0.03
    assert error["yaw_rms_rad"] < 0.01
    # each coupling carries about half the 5 kg payload's weight; the plan predicts it
    force = summary["coupling_force_rms_n"]
    assert 0.8 * 24.5 < force["measured"] < 1.25 * 24.5
    assert force["predicted_minus_measured"] < 8.0


def test_computation_delay_mode_applies_its_plans_and_still_stands() -> None:
    summary = _run(_short("two_go2", 1.0, model_computation_delay=True))
    assert summary["falls"] == 0
    assert summary["max_coupling_error_m"] < 0.002
    # one NMPC at a time: an update slower than the period skips the instants it covered ...
    updates, applied = summary["nmpc_updates"], summary["nmpc_plans_applied"]
    assert updates <= 60
    if summary["nmpc_update_ms"]["median"] > 1e3 / 60:
        assert updates < 60
    # ... and every finished plan takes effect (the last may still be computing at the end),
    # where replacing the pending plan at every instant applied none but the first.
    assert updates - 1 <= applied <= updates
    assert applied > 10


@pytest.mark.slow
def test_delay_compensation_keeps_tracking_close_to_the_lockstep_run() -> None:
    """Plans applied 35 ms after their decision (about this machine's update time; fixed, so
    the run is deterministic), each planned from the state predicted to that instant: tracking
    within 20 % of the lockstep run's (a few mm of slack for the short run), every finished
    plan applied."""
    lockstep = _run(_short("two_go2", 6.0))
    delayed = _run(_short("two_go2", 6.0, model_computation_delay=True,
                          computation_delay_s=0.035))
    assert delayed["falls"] == 0 and lockstep["falls"] == 0
    assert delayed["nmpc_updates"] - 1 <= delayed["nmpc_plans_applied"]
    for key, slack in (("rms_payload_position_error_m", 0.005),
                       ("rms_payload_yaw_error_rad", 0.005)):
        assert delayed[key] <= 1.2 * lockstep[key] + slack, (key, delayed[key], lockstep[key])
    assert delayed["max_coupling_error_m"] < 0.002


# four_go2 safe-stopped here under fatrop (4 consecutive failed updates near obstacle 0); with
# the rti solver (the default since) it completes with no failed solve.
@pytest.mark.slow
@pytest.mark.parametrize("name", shipped_scenarios())
def test_shipped_scenario_ends_as_expected_and_safely(name: str) -> None:
    """Every shipped scenario ends as it says (``expected_outcome``): at the goal, or in a
    controlled stop (braked, sat down, no fault); never a fall, a margin breached, a fault."""
    scenario = load_scenario(name)
    loop = SimRun(scenario, CompiledCodeCache())
    try:
        summary = loop.run()
    finally:
        loop.close()
    assert summary["outcome"] == scenario.expected_outcome, summary["safety"]["transitions"]
    assert summary["expected_outcome"] == scenario.expected_outcome
    assert summary["falls"] == 0, summary["fallen_robots"]
    assert summary["min_h_m"] >= -0.02, summary["min_h_by_pair_m"]
    assert summary["max_coupling_error_m"] < 0.005
    assert summary["wbc_failures"] == 0
    assert summary["safety"]["final_state"] == "DONE" and summary["safety"]["safe_stop"] is None
    if scenario.expected_outcome == "goal":
        assert summary["duration_s"] == pytest.approx(scenario.duration_s, abs=0.01)
        assert summary["reached_goal"], summary["final_goal_distance_m"]
        assert summary["safety"]["braking_since_s"] is None
    else:  # blocked: held back, braked after blocked_stop_s, sat down before the end
        blocked_s = loop.settings.braking.blocked_stop_s
        assert not summary["reached_goal"] and summary["safety"]["controlled_stop"]
        assert summary["safety"]["reference_held_s"] >= blocked_s
        assert summary["duration_s"] < scenario.duration_s
        assert any("SITTING_DOWN" in text and "no progress" in text
                   for text in summary["safety"]["transitions"])


def test_overlapping_the_nmpc_process_gives_the_same_run(tmp_path: Path) -> None:
    """``porter sim --delay-s --overlap``: the NMPC computes in its own process while the world
    steps; the run is the one computed in the loop's process with the same fixed delay (every
    non-timing summary field equal), and its log replays (the warm starts it logged are the
    NMPC process's). Both runs in fresh processes: a fresh process loads porter's BLASFEO
    kernels (``test_nmpc_process``), as the NMPC's own process does."""
    summaries = []
    log = tmp_path / "overlapped.mcap"
    for record in (["--no-record"], ["--overlap", "--record", str(log)]):
        done = subprocess.run(
            [sys.executable, "-m", "deploy.cli", "sim", "two_go2", "--duration", "1.0",
             "--serial", "--delay-s", "0.012", *record, "--json", "-"],
            cwd=ROOT, capture_output=True, text=True, timeout=600, check=False)
        assert done.returncode == 0, done.stderr
        summaries.append(json.loads(done.stdout))
    inline, overlapped = summaries
    assert inline["nmpc_updates"] == 60 and inline["nmpc_plans_applied"] >= 59
    for key in set(inline) - TIMING_KEYS:
        assert inline[key] == overlapped[key], key
    done = subprocess.run([sys.executable, "-m", "deploy.cli", "regress", str(log)], cwd=ROOT,
                          capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "60 decisions replayed" in done.stdout and "0 status mismatches" in done.stdout


def test_the_process_executor_gives_the_serial_run() -> None:
    """``porter sim two_go2``'s default executor (worker processes, requests in shared memory,
    caller and worker spinning between rounds) runs the serial executor's run: every non-timing
    summary field equal. Fresh processes: the same BLASFEO kernels in both."""
    summaries = []
    for executor in (["--serial"], []):
        done = subprocess.run(
            [sys.executable, "-m", "deploy.cli", "sim", "two_go2", "--duration", "1.0",
             "--no-record", "--json", "-", *executor],
            cwd=ROOT, capture_output=True, text=True, timeout=600, check=False)
        assert done.returncode == 0, done.stderr
        summaries.append(json.loads(done.stdout))
    serial, parallel = summaries
    assert serial["nmpc_updates"] == 60
    for key in set(serial) - TIMING_KEYS:
        assert serial[key] == parallel[key], key


def test_the_lockstep_executor_spins_only_with_two_cpus_or_more() -> None:
    cpus = os.sched_getaffinity(0)
    try:
        os.sched_setaffinity(0, {min(cpus)})
        assert lockstep_spin_s() == 0.0  # one CPU: a spinner would take the other's core
    finally:
        os.sched_setaffinity(0, cpus)
    assert lockstep_spin_s() == (LOCKSTEP_EXECUTOR_SPIN_S if len(cpus) > 1 else 0.0)


@pytest.mark.slow
def test_a_robot_pushed_over_is_a_fall_that_the_supervisor_stops_and_the_summary_says() -> None:
    """A 150 N push for 0.3 s (45 N s) on go2_0's trunk topples the team: the fall detector
    fires, the supervisor safe-stops the run, and the summary names the fallen robot."""
    from deploy.config.scenario import DisturbanceSettings, PushSpec

    scenario = _short("two_go2", 4.0)
    scenario = scenario.model_copy(update={"disturbances": DisturbanceSettings(pushes=[
        PushSpec(time_s=2.0, duration_s=0.3, target="go2_0", force_n=(0.0, 150.0, 0.0))])})
    summary = _run(scenario)
    assert summary["falls"] >= 1 and summary["fallen_robots"], summary["fallen_robots"]
    assert summary["outcome"].startswith("safe stop") and "fell" in summary["outcome"]
    assert summary["safety"]["safe_stop"] and summary["safety"]["final_state"] == "DONE"
    assert not summary["reached_goal"] and summary["duration_s"] < 4.0
    # the same run without the push: no fall, no stop (the check is of the push)
    calm = _run(_short("two_go2", 4.0))
    assert calm["falls"] == 0 and calm["safety"]["safe_stop"] is None
