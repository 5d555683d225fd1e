"""The ``porter`` command line: the bench runs end to end and writes its JSON."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from deploy.cli.porter import main


def test_bench_nmpc_writes_table_and_json(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    out = tmp_path / "bench.json"
    code = main(["bench", "nmpc", "--agents", "2", "--duration", "0.1", "--serial",
                 "--interpreted", "--json", str(out)])
    assert code == 0
    printed = capsys.readouterr().out
    assert "dist/cent" in printed and "ipopt-reference" in printed and "cpu med" in printed
    figures = json.loads(out.read_text())
    rows = figures["rows"]
    assert [c["solver"] for c in figures["accuracy"]] == ["fatrop", "rti"]
    for check in figures["accuracy"]:
        assert check["agents"] == 2 and check["samples"] >= 1
        assert 0 <= check["max_grf_difference_n"] < 50
    (fidelity,) = figures["rti_fidelity"]
    assert fidelity["solves"] >= 1 and 0 <= fidelity["median_n"] <= fidelity["max_n"]
    keys = {(r["mode"], r["agents"], r["solver"]) for r in rows}
    assert keys == {("centralized", 2, "fatrop"), ("distributed", 2, "fatrop"),
                    ("centralized", 2, "rti"), ("distributed", 2, "rti"),
                    ("distributed", 2, "ipopt-reference")}
    for row in rows:
        # the paper's counts (Table I) plus one barrier slack per stage (soft barriers)
        assert row["variables"] == (612 if row["mode"] == "centralized" else 408) + 8
        assert set(row["update_ms"]) == {"mean", "std", "median", "p95"}
        assert row["update_ms"]["median"] > 0
        # serial: the CPU of an update is this process's, at most its wall time per core
        cores = os.cpu_count() or 1
        assert 0 < row["cpu_ms"]["median"] <= cores * row["update_ms"]["median"] + 0.5
        assert ("local_ms" in row) == (row["mode"] == "distributed")
        assert row["iterations_mean"] > 0


def test_unknown_command_is_rejected(capsys: pytest.CaptureFixture) -> None:
    with pytest.raises(SystemExit) as error:
        main(["fly"])
    assert error.value.code == 2
    assert "invalid choice" in capsys.readouterr().err


def test_bad_config_file_is_a_clear_error(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    config = tmp_path / "mpc.yaml"
    config.write_text("admm:\n  iterations: -1\n")
    code = main(["bench", "nmpc", "--agents", "2", "--duration", "0.1", "--interpreted",
                 "--config", str(config)])
    assert code == 2
    assert "admm.iterations" in capsys.readouterr().err


SUMMARY_KEYS = {"scenario", "duration_s", "falls", "reached_goal", "min_h_m",
                "rms_payload_position_error_m", "rms_payload_yaw_error_rad",
                "max_coupling_error_m", "admm_residual_rms", "nmpc_update_ms",
                "deadline_misses", "wbc_tick_ms", "real_time_factor"}


def test_sim_runs_the_default_scenario_on_mujoco(tmp_path: Path,
                                                 capsys: pytest.CaptureFixture) -> None:
    out = tmp_path / "summary.json"
    code = main(["sim", "--duration", "0.5", "--serial", "--json", str(out)])
    assert code == 0
    captured = capsys.readouterr()
    summary = json.loads(out.read_text())
    assert set(summary) >= SUMMARY_KEYS
    assert summary["scenario"] == "two_go2" and summary["backend"] == "mujoco"
    assert summary["duration_s"] == pytest.approx(0.5)
    assert summary["falls"] == 0
    for aggregate in ("admm_residual_rms", "admm_residual_mean"):  # over updates, two ways
        assert set(summary[aggregate]) == {"payload_state", "wrench", "payload_position_m",
                                           "force_n"}
    assert set(summary["nmpc_update_ms"]) == {"median", "p95", "max"}
    assert set(summary["wbc_tick_ms"]) == {"median", "p95"}
    assert summary["nmpc_update_ms"]["median"] > 0 and summary["wbc_tick_ms"]["median"] > 0
    assert json.loads(captured.out) == summary
    # a shortened run is no broken expectation
    assert summary["outcome"] == "time out" and summary["expected_outcome"] == "goal"
    assert "(--duration 0.5 s: the scenario's own length expects 'goal')" in captured.err


def test_sim_rejects_a_bad_scenario_file_naming_the_field(
        tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    scenario = tmp_path / "bad.yaml"
    from deploy.config.scenario import scenario_path

    scenario.write_text(scenario_path("two_go2").read_text().replace(
        "mass_kg: 5.0", "mass_kg: -5.0"))
    assert main(["sim", str(scenario)]) == 2
    assert "payload.mass_kg" in capsys.readouterr().err


def test_sim_rejects_an_unknown_scenario_listing_the_shipped_ones(
        capsys: pytest.CaptureFixture) -> None:
    assert main(["sim", "no_such_scenario"]) == 2
    assert "two_go2" in capsys.readouterr().err


def test_bench_sim_prints_the_table_and_json(tmp_path: Path,
                                             capsys: pytest.CaptureFixture) -> None:
    out = tmp_path / "bench_sim.json"
    code = main(["bench", "sim", "two_go2", "--duration", "0.3", "--executor", "serial",
                 "--json", str(out)])
    assert code == 0
    printed = capsys.readouterr().out
    assert "RTF" in printed and "two_go2" in printed
    (row,) = json.loads(out.read_text())["rows"]
    assert row["real_time_factor"] > 0 and row["nmpc_wall_s"] > 0 and row["wbc_wall_s"] > 0
    assert row["nmpc_wall_s"] + row["wbc_wall_s"] < row["wall_s"]
    assert row["executor"] == "serial"


def test_overlap_without_a_fixed_delay_is_refused_naming_the_fields(
        capsys: pytest.CaptureFixture) -> None:
    assert main(["sim", "--overlap", "--duration", "0.2", "--no-record"]) == 2
    assert "overlap_computation needs" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exit_info:  # refused while parsing, with its range
        main(["bench", "sim", "two_go2", "--duration", "0.2", "--delay-s", "-1"])
    assert exit_info.value.code == 2
    assert "argument --delay-s: must be a finite number in [0, 0.5]" in capsys.readouterr().err


def test_bench_sim_overlapped_reports_its_delay(tmp_path: Path,
                                               capsys: pytest.CaptureFixture) -> None:
    """Overlapped without ``--executor``: the scenario's default for it, serial."""
    out = tmp_path / "bench_sim.json"
    code = main(["bench", "sim", "two_go2", "--duration", "0.3", "--delay-s", "0.012",
                 "--overlap", "--json", str(out)])
    assert code == 0
    shown = capsys.readouterr()
    assert "computation_delay_s 0.012, overlap_computation True" in shown.err  # progress
    assert "two_go2" in shown.out and "RTF" in shown.out  # the table
    (row,) = json.loads(out.read_text())["rows"]
    assert row["executor"] == "serial"
