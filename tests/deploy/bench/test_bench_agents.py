"""``porter bench agents`` measures both transports and both executors in one run (figures
come from the bench; this checks that it measures what it says)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from deploy.cli.porter import main


def test_bench_agents_measures_both_transports_and_executors(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "agents.json"
    assert main(["bench", "agents", "--messages", "10", "--duration", "0.3", "--repeats", "1",
                 "--json", str(out)]) == 0
    printed = capsys.readouterr().out
    for row in ("round trip, pipe", "round trip, Zenoh", "ADMM update, pipe executor",
                "ADMM update, Zenoh agents"):
        assert row in printed
    figures = json.loads(out.read_text())
    for transport in ("pipe", "zenoh"):
        trip = figures["round_trip_ms"][transport]
        assert trip["count"] == 10 and 0 < trip["median"] <= trip["p99"]
    assert figures["request_bytes"] > 8 * 1000  # the real local NLP's vectors, not a toy
    for executor in ("process", "zenoh"):
        assert figures["admm_update_ms"][executor][0]["median"] > 0
