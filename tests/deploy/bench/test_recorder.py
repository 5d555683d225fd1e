"""``porter bench recorder`` prints its tables (figures are measured, not asserted)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from deploy.cli.porter import main


def test_bench_recorder_prints_tables(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out_json = tmp_path / "bench.json"
    assert main(["bench", "recorder", "--duration", "0.3", "--repeats", "1", "--executor",
                 "serial", "--memory-minutes", "1", "--json", str(out_json)]) == 0
    out = capsys.readouterr().out
    assert "ratio on/off" in out and "memory: 1 simulated minutes" in out
    figures = json.loads(out_json.read_text())
    off, on = figures["rows"]
    assert (off["recorder"], on["recorder"]) == ("off", "on")
    # every 2 ms tick logs 3 messages per robot: at least 3000 per simulated second
    assert on["messages_per_sim_s"] > 3000 and on["dropped"] == 0
    memory = figures["memory"]
    assert memory["messages"] > 0.9 * 60 * on["messages_per_sim_s"] and memory["dropped"] == 0
    assert len(memory["rss_mb"]) == 2  # at the start and after the simulated minute
