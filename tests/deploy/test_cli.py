"""The ``porter`` command line: the bench runs end to end and writes its JSON."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from deploy.cli import main


def test_bench_nmpc_writes_table_and_json(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    out = tmp_path / "bench.json"
    code = main(["bench", "nmpc", "--agents", "2", "--duration", "0.1", "--serial",
                 "--interpreted", "--json", str(out)])
    assert code == 0
    printed = capsys.readouterr().out
    assert "dist/cent" in printed and "ipopt-reference" in printed
    figures = json.loads(out.read_text())
    rows = figures["rows"]
    (check,) = figures["accuracy"]
    assert check["agents"] == 2 and check["samples"] >= 1
    assert 0 <= check["max_grf_difference_n"] < 50
    keys = {(r["mode"], r["agents"], r["solver"]) for r in rows}
    assert keys == {("centralized", 2, "fatrop"), ("distributed", 2, "fatrop"),
                    ("distributed", 2, "ipopt-reference")}
    for row in rows:
        assert row["variables"] == (612 if row["mode"] == "centralized" else 408)
        assert set(row["update_ms"]) == {"mean", "std", "median", "p95"}
        assert row["update_ms"]["median"] > 0
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
