"""``porter paper``: each claim's variants run under both profiles (porter's and the paper's
NLP), porter's figures stand beside the paper's, and the JSON and the PNG are written (the
figures themselves are README's, from full runs)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from deploy.cli.porter import main
from deploy.paper.claims import CLAIMS


def test_every_claim_names_the_papers_figures_and_differs_only_in_its_subject() -> None:
    assert set(CLAIMS) == {"delay", "iterations", "consensus"}
    for claim in CLAIMS.values():
        assert len(claim.variants) >= 3 and claim.metrics and claim.series
        assert any(v.paper for v in claim.variants)
        for variant in claim.variants:
            assert set(variant.paper) <= set(claim.metrics)
    iterations = [v.controller["admm_iterations"] for v in CLAIMS["iterations"].variants]
    assert iterations == [1, 2, 3, 6]


def test_porter_paper_delay_runs_its_variants_and_writes_json_and_png(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "delay", "--duration", "0.5", "--out", str(tmp_path)]) == 0
    printed = capsys.readouterr().out
    assert "6.97e-05" in printed and "5.93" in printed  # the paper's figures beside
    result = json.loads((tmp_path / "delay.json").read_text())
    assert set(result["profiles"]) == {"porter", "paper"}
    assert result["profiles"]["paper"]["solver"]["name"] == "ipopt-reference"
    labels = [v.label for v in CLAIMS["delay"].variants]
    assert [(r["profile"], r["variant"]) for r in result["rows"]] == [
        (profile, label) for profile in ("porter", "paper") for label in labels]
    for row in result["rows"]:
        assert row["falls"] == 0 and row["failed_updates"] == 0
        assert all(math.isfinite(value) and value >= 0 for value in row["metrics"].values())
        # the paper's time average of each update's RMS, never above the RMS over updates
        metrics = row["metrics"]
        assert 0 < metrics["admm_residual_mean.force_n"] <= metrics["admm_residual_rms.force_n"]
    # the delayed runs disagree more than the nominal one, from the first half second on
    rows = {row["variant"]: row for row in result["rows"] if row["profile"] == "porter"}
    nominal = rows["nominal"]["metrics"]["admm_residual_rms.force_n"]
    assert rows["delayed, fresh <= 2 rounds (porter)"]["metrics"][
        "admm_residual_rms.force_n"] > nominal
    # the same channel on messages that crossed Zenoh (agent processes)
    assert rows["delayed, fresh <= 2, over Zenoh agents"]["metrics"][
        "admm_residual_rms.force_n"] > nominal
    paper = {row["variant"]: row for row in result["rows"] if row["profile"] == "paper"}
    assert paper["delayed, hold-last (paper)"]["metrics"]["admm_residual_rms.force_n"] > \
        paper["nominal"]["metrics"]["admm_residual_rms.force_n"]
    assert len(result["series"]["porter: nominal"]["force_residual_n"]) >= 25  # 60 Hz, 0.5 s
    png = (tmp_path / "delay.png").read_bytes()
    assert png.startswith(b"\x89PNG") and len(png) > 10_000


def test_a_bad_duration_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "delay", "--duration", "-1"]) == 2
    assert "must be positive" in capsys.readouterr().err


def test_an_unknown_profile_is_refused_before_anything_runs(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "delay", "--profile", "nowhere"]) == 2
    assert "unknown profile 'nowhere'" in capsys.readouterr().err
    assert main(["paper", "delay", "--profile", "paper", "paper"]) == 2
    assert "each profile once" in capsys.readouterr().err


def test_porter_paper_table1_puts_both_modes_and_the_paper_side_by_side(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "table1", "--agents", "2", "--duration", "0.2", "--out",
                 str(tmp_path)]) == 0
    printed = capsys.readouterr().out
    assert "9.28 / 7.62" in printed  # the paper's 2-agent row beside porter's
    rows = json.loads((tmp_path / "table1.json").read_text())["rows"]
    assert [(r["agents"], r["profile"], r["solver"]) for r in rows] == [
        (2, "porter", "rti"), (2, "paper", "ipopt-reference")]
    porter, reference = rows
    # the paper's NLP has exactly the paper's decision variables; porter's local problem adds
    # the barrier slack (one per stage, and one per stage of the centralized problem)
    assert tuple(reference["variables"]) == (408, 612)
    assert tuple(porter["variables"]) == (416, 620)
    for row in rows:
        distributed, centralized = row["distributed_ms"][0], row["centralized_ms"][0]
        assert distributed > 0 and centralized > 0
        assert row["reduction"] == pytest.approx(1 - distributed / centralized)
        update_distributed, update_centralized = row["update_ms"]
        assert row["update_ratio"] == pytest.approx(update_distributed / update_centralized)
        assert update_distributed >= distributed  # an update holds at least one local solve
    assert reference["paper"]["reduction"] == pytest.approx(1 - 9.28 / 7.62)


def test_table1_refuses_impossible_team_sizes(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "table1", "--agents", "1"]) == 2
    assert "--agents must be in [2, 8]" in capsys.readouterr().err


def test_porter_paper_experiments_draws_the_paths_among_the_safe_sets(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "experiments", "--scenarios", "moving_obstacle", "--duration", "0.4",
                 "--out", str(tmp_path)]) == 0
    assert "a moving obstacle: avoided" in capsys.readouterr().out
    rows = json.loads((tmp_path / "experiments.json").read_text())["rows"]
    assert [r["profile"] for r in rows] == ["porter", "paper"]
    row = rows[0]
    assert row["scenario"] == "moving_obstacle" and row["robots"] == ["go2_0", "go2_1"]
    paths = row["paths_m"]
    assert len(paths) > 100 and len(paths[0]) == 3  # payload and two robots per sample
    moving = [o for o in row["obstacles"] if o["start_m"] != o["end_m"]]
    assert moving and all(o["safe_radius_m"] > o["radius_m"] for o in row["obstacles"])
    assert (tmp_path / "experiments.png").read_bytes().startswith(b"\x89PNG")
    # the experiment figures' time series: h, planned GRFs, ADMM residuals
    series = row["series"]
    assert len(series["min_h_m"]) == len(series["sample_time_s"]) > 100
    assert min(series["min_h_m"]) == pytest.approx(row["min_h_m"], abs=1e-9)
    updates = len(series["update_time_s"])
    assert updates >= 20 and len(series["force_residual_n"]) == updates
    assert len(series["dual_residual"]) == updates and len(series["grf_z_sum_n"][0]) == 2
    # the robots carry their own weight and the payload's: ~ (2 x 15 + 5) kg x g in all
    assert 250 < sum(series["grf_z_sum_n"][-1]) < 450
    assert (tmp_path / "experiments_series.png").read_bytes().startswith(b"\x89PNG")


def test_porter_paper_experiments_include_the_four_agent_team(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "experiments", "--scenarios", "four_go2", "--duration", "0.3",
                 "--profile", "porter", "--out", str(tmp_path)]) == 0
    assert "four Go2" in capsys.readouterr().out
    row = json.loads((tmp_path / "experiments.json").read_text())["rows"][0]
    assert row["scenario"] == "four_go2" and len(row["robots"]) == 4
    assert len(row["paths_m"][0]) == 5  # payload and four robots per sample


def test_experiments_refuse_unknown_scenarios(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "experiments", "--scenarios", "nowhere"]) == 2
    assert "unknown scenarios ['nowhere']" in capsys.readouterr().err


def test_porter_paper_iterations_prints_the_papers_aggregate_beside_the_rms(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "iterations", "--duration", "0.3", "--out", str(tmp_path)]) == 0
    printed = capsys.readouterr().out
    assert "avg force_n porter" in printed and "rms force_n porter" in printed
    rows = json.loads((tmp_path / "iterations.json").read_text())["rows"]
    labels = ["1 iteration", "2 iterations", "3 iterations", "6 iterations"]
    assert [(r["profile"], r["variant"]) for r in rows] == [
        (profile, label) for profile in ("porter", "paper") for label in labels]
    for row in rows:
        metrics = row["metrics"]
        assert 0 < metrics["admm_residual_mean.force_n"] <= metrics["admm_residual_rms.force_n"]
        assert "admm_residual_mean.force_n" in row["paper"]  # the paper's figure is the mean


def test_porter_paper_consensus_runs_the_wrench_only_ablation(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "consensus", "--duration", "0.3", "--out", str(tmp_path)]) == 0
    rows = json.loads((tmp_path / "consensus.json").read_text())["rows"]
    assert len(rows) == 6 and all(r["falls"] == 0 for r in rows)
    assert [r["profile"] for r in rows] == ["porter"] * 3 + ["paper"] * 3
    for row in rows:
        assert math.isfinite(row["metrics"]["rms_payload_yaw_error_rad"])
    assert (tmp_path / "consensus.png").read_bytes().startswith(b"\x89PNG")


def test_porter_paper_closed_loop_compares_distributed_and_centralized(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "closed-loop", "--scenarios", "two_go2", "--duration", "0.3",
                 "--out", str(tmp_path)]) == 0
    assert "distributed vs centralized" in capsys.readouterr().out
    document = json.loads((tmp_path / "closed-loop.json").read_text())
    assert set(document["profiles"]) == {"porter", "paper"}
    rows = document["rows"]
    assert [(r["profile"], r["mode"]) for r in rows] == [
        ("porter", "distributed"), ("porter", "centralized"),
        ("paper", "distributed"), ("paper", "centralized")]
    for row in rows:
        assert row["falls"] == 0 and row["failed_updates"] == 0 and row["shortened"]
        assert row["rms_payload_position_error_m"] > 0 and row["grf_change_rms_n"] > 0
    for ratio, profile in zip(document["ratios"], ("porter", "paper"), strict=True):
        assert ratio["profile"] == profile
        distributed, centralized = (r for r in rows if r["profile"] == profile)
        assert ratio["rms_payload_position_error_m_ratio"] == pytest.approx(
            distributed["rms_payload_position_error_m"]
            / centralized["rms_payload_position_error_m"])


def test_closed_loop_refuses_unknown_scenarios(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["paper", "closed-loop", "--scenarios", "nowhere"]) == 2
    assert "unknown scenarios ['nowhere']" in capsys.readouterr().err
