"""``porter regress``: the shipped reference logs replay within tolerance; a changed controller
and violated expectations fail with a non-zero exit code."""

from __future__ import annotations

import json
import math
import platform
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from deploy.cli.porter import main
from deploy.compute.blas_kernels import GENERIC, cpu_target, host_cpu_flags
from deploy.recording.log_format import (
    MPC_SETTINGS_ATTACHMENT,
    RUN_METADATA,
    WBC_SETTINGS_ATTACHMENT,
)
from deploy.recording.log_reader import LogFile
from deploy.recording.regression import TOLERANCES, regress_log, replay_blas_target

ROOT = Path(__file__).resolve().parents[3]
LOGS = ROOT / "logs"
SHIPPED = sorted(LOGS.glob("*.mcap"))


def porter_regress(*args: str) -> subprocess.CompletedProcess[str]:
    """``porter regress`` in a fresh process, as users run it: a test earlier in this process
    may have loaded other BLASFEO kernels than the logs were recorded on."""
    return subprocess.run([sys.executable, "-m", "deploy.cli", "regress", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=900, check=False)


def test_reference_logs_are_shipped_with_expectations() -> None:
    assert {p.stem for p in SHIPPED} >= {"two_go2", "mixed_three"}
    for path in SHIPPED:
        assert path.stat().st_size < 3_000_000, path
        assert path.with_suffix(".expect.json").exists(), path


def test_shipped_logs_pass_on_their_kernels(tmp_path: Path) -> None:
    done = porter_regress(*map(str, SHIPPED), "--json", str(tmp_path / "reports.json"))
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.count("PASS") == len(SHIPPED)
    assert f"{len(SHIPPED)} of {len(SHIPPED)} logs pass" in done.stdout
    for report in json.loads((tmp_path / "reports.json").read_text()):
        # Same kernels, same compiled code: the replay is within the solver's last bits.
        assert report["kernels_recorded"] == report["kernels_replayed"] != "unknown", report
        assert report["status_mismatches"] == 0 and report["decisions"] == 90
        assert all(report["max_deviation"][k] <= TOLERANCES[k] for k in TOLERANCES), report
        # the expectations held on a re-simulation of the run, not on the stored summary
        assert report["resimulated"] and report["expectation_failures"] == []
        assert len(report["expectation_margins"]) > 20
        assert min(report["expectation_margins"].values()) >= 0


_OTHER_KERNELS_FIRST = """
import json, sys
from deploy.recording.regression import format_report, regress_log
from deploy.compute.codegen_cache import CompiledCodeCache
cache = CompiledCodeCache(blas_target=sys.argv[1])
cache.blas_kernels()  # as a test or a notebook that built a solver before the replay
report = regress_log(sys.argv[2], cache, max_decisions=3)
print(json.dumps({"report": format_report(report), "mismatch": report.kernel_mismatch,
                  "passed": report.passed, "replayed": report.kernels_replayed}))
"""


def test_a_replay_on_other_kernels_says_so() -> None:
    log = LogFile(LOGS / "two_go2.mcap")
    recorded = log.metadata()[RUN_METADATA]["blas_kernels"]
    other = "auto" if recorded == GENERIC else "generic"
    done = subprocess.run([sys.executable, "-c", _OTHER_KERNELS_FIRST, other,
                           str(LOGS / "two_go2.mcap")], cwd=ROOT, capture_output=True,
                          text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout.splitlines()[-1])
    assert result["replayed"] != recorded and result["mismatch"]
    assert f"recorded on {recorded}" in result["report"]
    if not result["passed"]:
        assert "other BLAS kernels than the recording" in result["report"]


def test_replay_targets_the_recorded_kernels_only_where_the_cpu_runs_them() -> None:
    assert replay_blas_target(GENERIC) == "generic"
    assert replay_blas_target("unknown") == "auto"
    assert replay_blas_target("NOT_A_TARGET_OF_THIS_CPU") == "auto"
    here = cpu_target(platform.machine(), host_cpu_flags())
    if here is not None:
        assert replay_blas_target(here) == here


def test_a_changed_cost_weight_fails(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    settings = yaml.safe_load(LogFile(LOGS / "two_go2.mcap").attachment_text(
        MPC_SETTINGS_ATTACHMENT))
    settings["cost"]["ground_reaction_force"] *= 2.0
    settings["solver"]["compiled"] = False  # no compile for a one-off problem
    changed = tmp_path / "changed.yaml"
    changed.write_text(yaml.safe_dump(settings))
    code = main(["regress", str(LOGS / "two_go2.mcap"), "--settings", str(changed),
                 "--max-decisions", "3", "--no-resimulate", "--json",
                 str(tmp_path / "report.json")])
    assert code == 1
    assert "FAIL" in capsys.readouterr().out
    report = json.loads((tmp_path / "report.json").read_text())[0]
    assert not report["passed"]
    assert report["max_deviation"]["grf_n"] > 10 * TOLERANCES["grf_n"]


def test_violated_expectations_fail(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    log = tmp_path / "run.mcap"
    shutil.copy(LOGS / "two_go2.mcap", log)
    expectations = json.loads((LOGS / "two_go2.expect.json").read_text())
    expectations["falls"] = {"equals": 1}
    log.with_suffix(".expect.json").write_text(json.dumps(expectations))
    assert main(["regress", str(log), "--max-decisions", "2"]) == 1
    assert "expectation: falls = 0, expected 1" in capsys.readouterr().out


def test_refresh_writes_expectations_that_hold(tmp_path: Path) -> None:
    log = tmp_path / "run.mcap"
    shutil.copy(LOGS / "mixed_three.mcap", log)
    assert main(["regress", str(log), "--refresh-expectations"]) == 0
    drafted = json.loads(log.with_suffix(".expect.json").read_text())
    assert drafted["falls"] == {"equals": 0} and "wall_s" not in drafted
    assert regress_log(log, max_decisions=1, resimulate=False).expectation_failures == []


def test_a_bad_log_is_a_usage_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.mcap"
    bad.write_bytes(b"\x00" * 100)
    assert main(["regress", str(bad)]) == 2
    assert "not an MCAP file" in capsys.readouterr().err


def test_a_changed_wbc_gain_passes_the_replay_and_fails_the_resimulation(tmp_path: Path) -> None:
    """The decision replay cannot see a change outside the NMPC; the re-simulated metrics
    can: a fifth of the swing-foot gain changes the run's margin flags (an exact expectation)."""
    settings = yaml.safe_load(LogFile(LOGS / "two_go2.mcap").attachment_text(
        WBC_SETTINGS_ATTACHMENT))
    settings["swing_position_gain"] *= 0.2
    changed = tmp_path / "wbc.yaml"
    changed.write_text(yaml.safe_dump(settings))
    report_path = tmp_path / "report.json"
    done = porter_regress(str(LOGS / "two_go2.mcap"), "--wbc-settings", str(changed),
                          "--json", str(report_path))
    assert done.returncode == 1, done.stdout + done.stderr
    report = json.loads(report_path.read_text())[0]
    assert all(report["max_deviation"][k] <= TOLERANCES[k] for k in TOLERANCES)
    assert report["status_mismatches"] == 0
    assert report["resimulated"]
    assert any("nmpc_margin_flags" in failure for failure in report["expectation_failures"])


@pytest.mark.parametrize(("ours", "theirs", "expected"), [
    ([1.0, 2.0], [1.0, 2.5], 0.5),
    ([1.0, math.nan], [5.0, math.nan], 4.0),  # NaN matches NaN, the rest is compared
    ([math.nan, 1.0], [math.nan, 1.0], 0.0),
    ([math.nan, 1.0], [1.0, math.nan], math.inf),  # NaN in another place
    ([1.0, 2.0], [1.0, math.nan], math.inf),
    ([math.inf, 1.0], [-math.inf, 1.0], math.inf),  # infinities are values
    ([math.inf, 1.0], [math.inf, 3.0], 2.0),
    ([math.inf], [1e308], math.inf),
    ([1.0, 2.0], [1.0, 2.0, 3.0], math.inf),  # another shape
])
def test_deviation_compares_nan_only_to_nan_and_infinities_as_values(
        ours: list[float], theirs: list[float], expected: float) -> None:
    from deploy.recording.regression import array_deviation

    assert array_deviation(np.array(ours), np.array(theirs)) == expected
