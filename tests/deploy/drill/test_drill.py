"""``porter drill``: the catalogue covers the fault families, the verdict is strict, and a few
faults run end to end (the full suite is ``porter drill``, its table in README)."""

from __future__ import annotations

from pathlib import Path

import pytest

from deploy.config.deploy_config import SimFault
from deploy.drill.catalogue import DrillFault, catalogue
from deploy.drill.runner import _judge, _merge, format_table, run_fault


def test_the_catalogue_has_every_family_and_at_least_thirty_faults() -> None:
    faults = catalogue()
    assert len(faults) >= 30
    assert len({f.name for f in faults}) == len(faults)
    assert {f.expect for f in faults} == {"safe stop", "sit down", "ignored", "refused",
                                          "not started"}
    for fault in faults:
        for injected in fault.config.get("sim", {}).get("faults", []):
            SimFault.model_validate(injected)  # every injected fault is a valid one
        if fault.expect in ("safe stop", "refused", "not started"):
            assert fault.cause, fault.name


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


def test_a_refused_config_must_exit_2_and_name_the_field(tmp_path: Path) -> None:
    fault = DrillFault("bad", "refused", "safety.damping_kd")
    err = "porter: deploy.yaml: safety.damping_kd: Input should be greater than 0\n"
    assert _judge(fault, 2, None, err, tmp_path / "x.mcap", tmp_path).passed
    assert not _judge(fault, 1, None, err, tmp_path / "x.mcap", tmp_path).passed
    assert not _judge(fault, 2, None, "porter: other error\n", tmp_path / "x.mcap",
                      tmp_path).passed


@pytest.mark.slow
@pytest.mark.parametrize("name", ["e-stop pressed", "NatNet malformed packets",
                                  "config: damping_kd 0", "NMPC solver failure streak",
                                  "NMPC process killed"])
def test_drill_faults_end_to_end(tmp_path: Path, name: str) -> None:
    (fault,) = [f for f in catalogue() if f.name == name]
    row = run_fault(fault, tmp_path / "run")
    assert row.passed, (row, (tmp_path / "run" / "stderr.txt").read_text()[-2000:])
    if fault.expect == "safe stop" and fault.action == "none":  # the world timed the fault
        assert row.non_damping_after_detection == 0 and row.log == "yes"
        assert row.detected_after_ms is not None and row.detected_after_ms < 300
