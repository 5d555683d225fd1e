"""``porter drill``: the catalogue covers the fault families, the verdict is strict, and a few
faults run end to end (the full suite is ``porter drill``, its table in README)."""

from __future__ import annotations

from pathlib import Path

import pytest

from deploy.config.deploy_config import SimFault
from deploy.drill.catalogue import DrillFault, catalogue
from deploy.drill.runner import (
    CONTROL,
    _judge,
    _judge_kill,
    _merge,
    format_table,
    judge,
    run_case,
    run_fault,
    with_control,
)
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.log_format import LOG_FORMAT_VERSION, RUN_METADATA


def test_the_catalogue_has_every_family_and_at_least_thirty_faults() -> None:
    faults = catalogue()
    assert len(faults) >= 30
    assert len({f.name for f in faults}) == len(faults)
    assert {f.expect for f in faults} == {"safe stop", "sit down", "ignored", "refused",
                                          "not started", "damped", "rides through"}
    for fault in faults:
        for injected in fault.config.get("sim", {}).get("faults", []):
            SimFault.model_validate(injected)  # every injected fault is a valid one
        if fault.expect in ("safe stop", "refused", "not started"):
            assert fault.cause, fault.name
        if fault.expect == "rides through":
            assert fault.evidence, fault.name


def test_config_changes_merge_into_nested_sections() -> None:
    base = {"robots": {"go2_0": {"driver": "go2", "link_timeout_s": 0.1}, "go2_1": {}},
            "safety": {"damping_kd": 2.0}}
    merged = _merge(base, {"robots": {"go2_0": {"link_timeout_s": 0.5}}})
    assert merged["robots"]["go2_0"] == {"driver": "go2", "link_timeout_s": 0.5}
    assert merged["robots"]["go2_1"] == {} and merged["safety"] == {"damping_kd": 2.0}
    assert base["robots"]["go2_0"]["link_timeout_s"] == 0.1  # the base is not changed


def _summary(cause: str, non_damping: int, first_damping_s: float | None = 0.1) -> dict:
    after = {"first_damping_s": first_damping_s, "non_damping_after_damping": non_damping}
    return {"final_state": "DONE", "safe_stop": cause, "result": "safe stop",
            "sim_ground_truth": {"faults_applied": [{"kind": "estop_press"}],
                                 "robots": {"go2_0": {"after_fault": after},
                                            "go2_1": {"after_fault": after}}}}


def test_a_safe_stop_passes_only_with_its_cause_and_damping_only_after_detection(
        tmp_path: Path) -> None:
    fault = DrillFault("e-stop", "safe stop", "e-stop")
    log = tmp_path / "absent.mcap"
    good = _judge(fault, 3, _summary("e-stop: pressed", 0), "", log, tmp_path)
    assert good.passed and good.detected_after_ms == pytest.approx(100.0)
    assert good.non_damping_after_detection == 0 and good.log == "none"
    assert not _judge(fault, 3, _summary("e-stop: pressed", 2), "", log, tmp_path).passed
    assert not _judge(fault, 3, _summary("MoCap lost", 0), "", log, tmp_path).passed
    assert not _judge(fault, 0, _summary("e-stop: pressed", 0), "", log, tmp_path).passed
    assert not _judge(fault, 3, None, "Traceback", log, tmp_path).passed
    table = format_table([good])
    assert "1 of 1 faults handled as expected" in table and "e-stop" in table


def test_a_killed_porter_passes_only_if_every_robot_was_damped_in_time(tmp_path: Path) -> None:
    """kill -9 of porter: the verdict comes from the world's report alone."""
    fault = DrillFault("kill", "damped", "", action="kill_porter")
    log = tmp_path / "absent.mcap"

    def report(*firsts: float | None, non_damping: int = 0) -> dict:
        return {"faults_applied": [{"kind": "porter_lost", "time_s": 5.0}],
                "robots": {f"go2_{i}": {"after_fault": {
                    "first_damping_s": first, "non_damping_after_damping": non_damping}}
                    for i, first in enumerate(firsts)}}

    row = _judge_kill(fault, -9, report(0.004, 0.006), log, tmp_path)
    assert row.detected_after_ms == pytest.approx(6.0) and row.log == "none"
    assert not row.passed  # no log to read back
    written = tmp_path / "run.mcap"
    FlightRecorder(written, metadata={RUN_METADATA: {"log_format_version": str(
        LOG_FORMAT_VERSION)}}).close(summary={})
    good = _judge_kill(fault, -9, report(0.004, 0.006), written, tmp_path)
    assert good.passed and good.log == "yes"
    assert not _judge_kill(fault, 0, report(0.004, 0.006), written, tmp_path).passed
    assert not _judge_kill(fault, -9, report(0.004, None), log, tmp_path).passed
    assert not _judge_kill(fault, -9, report(0.004, 0.080), log, tmp_path).passed
    assert not _judge_kill(fault, -9, report(0.004, 0.006, non_damping=1), log, tmp_path).passed
    assert not _judge_kill(fault, -9, None, log, tmp_path).passed


def test_a_late_state_rides_through_only_if_it_completes_and_was_seen(tmp_path: Path) -> None:
    fault = DrillFault("stall", "rides through", "", evidence="stale_state_held_ticks.go2_0")
    log = tmp_path / "absent.mcap"

    def summary(held: int, cause: str | None = None) -> dict:
        return {"final_state": "DONE", "safe_stop": cause, "result": "ran 2 s",
                "stale_state_held_ticks": {"go2_0": held, "go2_1": 0}}
    good = _judge(fault, 0, summary(9), "", log, tmp_path)
    assert good.passed and "stale_state_held_ticks.go2_0 9" in good.detail
    assert not _judge(fault, 0, summary(0), "", log, tmp_path).passed  # never seen
    assert not _judge(fault, 3, summary(9, "joint speed: go2_0"), "", log, tmp_path).passed
    other = DrillFault("stall", "rides through", "", evidence="stale_state_held_ticks.go2_9")
    assert not _judge(other, 0, summary(9), "", log, tmp_path).passed  # no such count


def test_timed_faults_need_a_duration_and_others_refuse_one() -> None:
    SimFault.model_validate({"at_s": 1.0, "kind": "robot_stall", "robot": "go2_0",
                             "duration_s": 0.02})
    with pytest.raises(ValueError, match="duration_s"):
        SimFault.model_validate({"at_s": 1.0, "kind": "robot_stall", "robot": "go2_0"})
    with pytest.raises(ValueError, match="duration_s"):
        SimFault.model_validate({"at_s": 1.0, "kind": "estop_press", "duration_s": 0.02})
    with pytest.raises(ValueError, match="duration_s"):
        SimFault.model_validate({"at_s": 1.0, "kind": "plan_late", "duration_s": -0.05})


def test_a_refused_config_must_exit_2_and_name_the_field(tmp_path: Path) -> None:
    fault = DrillFault("bad", "refused", "safety.damping_kd")
    err = "porter: deploy.yaml: safety.damping_kd: Input should be greater than 0\n"
    assert _judge(fault, 2, None, err, tmp_path / "x.mcap", tmp_path).passed
    assert not _judge(fault, 1, None, err, tmp_path / "x.mcap", tmp_path).passed
    assert not _judge(fault, 2, None, "porter: other error\n", tmp_path / "x.mcap",
                      tmp_path).passed


def test_a_detection_slower_than_its_bound_fails_the_case(tmp_path: Path) -> None:
    log = tmp_path / "absent.mcap"
    summary = _summary("e-stop: pressed", 0, first_damping_s=0.1)  # detected after 100 ms
    assert _judge(DrillFault("e-stop", "safe stop", "e-stop", within_ms=150), 3, summary, "",
                  log, tmp_path).passed
    late = _judge(DrillFault("e-stop", "safe stop", "e-stop", within_ms=50), 3, summary, "",
                  log, tmp_path)
    assert not late.passed and "detected after 100" in late.detail
    safe_stops = [f for f in catalogue() if f.expect == "safe stop" and f.action == "none"]
    assert all(f.within_ms is not None for f in safe_stops)  # every timed case has a bound


@pytest.mark.slow
def test_every_check_fails_on_the_control_run(tmp_path: Path) -> None:
    """The drill's own control: a run without any fault, judged by every case's check; each
    must fail (a check that passes without its fault cannot fail), and with_control marks a
    row that would pass there."""
    control = run_case(CONTROL, tmp_path / "control")
    assert control.code == 0 and control.summary is not None  # the plain run completes
    passing = [f.name for f in catalogue() if judge(f, control).passed]
    assert passing == []
    always = DrillFault("a check that cannot fail", "ignored", "", rejected="go2_0")
    row = with_control(judge(always, control), always, control)
    assert row.control_fails is True  # (no packets were refused in the control run)


@pytest.mark.slow
@pytest.mark.parametrize("name", ["e-stop pressed", "NatNet malformed packets",
                                  "config: damping_kd 0", "NMPC solver failure streak",
                                  "NMPC process killed",
                                  "kill -9 of porter (the loop's own process)",
                                  "robot go2_0 state stalls 20 ms",
                                  "robot go2_1 state stalls 60 ms (past its stale-state budget)",
                                  "NMPC plan 50 ms late",
                                  "robot a1_2 frozen (tick stops; the mixed team)"])
def test_drill_faults_end_to_end(tmp_path: Path, name: str) -> None:
    (fault,) = [f for f in catalogue() if f.name == name]
    row = run_fault(fault, tmp_path / "run")
    assert row.passed, (row, (tmp_path / "run" / "stderr.txt").read_text()[-2000:])
    if fault.expect == "safe stop" and fault.action == "none":  # the world timed the fault
        assert row.non_damping_after_detection == 0 and row.log == "yes"
        assert row.detected_after_ms is not None and row.detected_after_ms < 300
    if fault.expect == "damped":  # kill -9: the watchdog alone, the log recovered
        assert row.exit_code == -9 and row.non_damping_after_detection == 0
        assert row.detected_after_ms is not None and row.detected_after_ms <= 50
        assert row.log.startswith("recovered") or row.log == "yes"
