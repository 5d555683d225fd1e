"""One CLI convention (``deploy.cli.conventions``): help everywhere, ``--json FILE`` and
``--quiet`` on every command that reports, errors as one line on stderr, shared exit codes."""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

import pytest

from deploy.cli.conventions import OK, USAGE
from deploy.cli.porter import build_parser, main
from deploy.cli.sim_command import sim_verdict

ROOT = Path(__file__).resolve().parents[3]
LOG = ROOT / "logs" / "two_go2.mcap"
# every command that reports something (agent serves: it has --quiet only)
REPORTING = [("drill",), ("sim",), ("deploy",), ("replay",), ("log", "info"), ("log", "recover"),
             ("log", "timeline"), ("regress",), ("paper",), ("bench", "agents"),
             ("bench", "nmpc"), ("bench", "sim"), ("bench", "obstacles"), ("bench", "recorder"),
             ("bench", "drivers"), ("bench", "deploy"), ("bench", "wbc")]


def _commands(parser: argparse.ArgumentParser, path: tuple[str, ...] = ()
              ) -> dict[tuple[str, ...], argparse.ArgumentParser]:
    """Every (sub)command's parser by its words."""
    found = {path: parser}
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, child in action.choices.items():
                found.update(_commands(child, (*path, name)))
    return found


def test_every_command_and_option_has_help() -> None:
    commands = _commands(build_parser())
    missing = []
    for path, parser in commands.items():
        if path and not parser.description:
            missing.append(" ".join(path) + ": no description")
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                missing += [f"{' '.join(path)} {c.dest}: no help" for c in action._choices_actions
                            if not c.help]
            elif action.help is None:
                missing.append(f"{' '.join(path)} {action.dest}: no help")
    assert not missing


@pytest.mark.parametrize("words", REPORTING, ids=" ".join)
def test_every_reporting_command_takes_json_and_quiet(words: tuple[str, ...]) -> None:
    options = {o for a in _commands(build_parser())[words]._actions for o in a.option_strings}
    assert {"--json", "--quiet"} <= options
    assert "--quiet" in {o for a in _commands(build_parser())[("agent",)]._actions
                         for o in a.option_strings}


def test_json_to_stdout_is_the_document_alone(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["log", "info", str(LOG), "--json", "-"]) == OK
    out = capsys.readouterr().out
    assert json.loads(out)["messages"] > 1000  # nothing but the document


def test_json_to_a_file_beside_the_text_and_quiet_leaves_only_the_file(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "info.json"
    assert main(["log", "info", str(LOG), "--json", str(target)]) == OK
    shown = capsys.readouterr()
    assert not shown.out.lstrip().startswith("{") and "messages on" in shown.out
    assert json.loads(target.read_text())["path"] == str(LOG)
    target.unlink()
    assert main(["log", "info", str(LOG), "--json", str(target), "--quiet"]) == OK
    shown = capsys.readouterr()
    assert shown.out == "" and shown.err == "" and target.exists()


@pytest.mark.parametrize(("words", "expected"), [
    (["log", "recover", "/nonexistent/run.mcap"], "give the path of the log the run left"),
    (["log", "info", "/nonexistent/run.mcap"], "give the path of a flight log"),
    (["regress", "/nonexistent/run.mcap"], "give the path of a flight log"),
    (["drill", "no such fault"], "name a part of one of"),
    (["deploy", "--config", "no_such_config", "--backend", "sim", "--yes"],
     "shipped configs: four_go2, two_go2, two_go2_a1")])
def test_errors_are_one_line_on_stderr_that_says_what_to_do(
        words: list[str], expected: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(words) == USAGE
    shown = capsys.readouterr()
    assert shown.out == ""
    lines = shown.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("porter: ") and expected in lines[0]
    assert "Errno" not in lines[0] and "Traceback" not in lines[0]


def _summary(outcome: str, expected: str = "goal", falls: int = 0) -> dict:
    return {"reached_goal": outcome == "goal", "outcome": outcome, "expected_outcome": expected,
            "falls": falls, "min_h_m": 0.1, "safety": {"controlled_stop": False}}


@pytest.mark.parametrize(("summary", "duration_s", "as_expected"), [
    (_summary("goal"), None, True),
    (_summary("time out"), None, False),
    (_summary("time out"), 2.0, True),  # --duration shortened it
    (_summary("goal", falls=1), None, False),
    (_summary("controlled stop"), None, False),
    (_summary("controlled stop", "controlled stop"), None, True),
    (_summary("goal", "controlled stop"), None, False)])
def test_sim_is_as_expected_only_at_its_scenario_s_outcome_without_a_fall(
        summary: dict, duration_s: float | None, as_expected: bool) -> None:
    verdict, verdict_as_expected = sim_verdict(summary, duration_s)
    assert verdict_as_expected is as_expected
    assert f"outcome {summary['outcome']!r}" in verdict


def test_sim_exits_as_expected_on_a_real_short_run() -> None:
    done = subprocess.run([sys.executable, "-m", "deploy.cli", "sim", "--duration", "0.2",
                           "--serial", "--no-record", "--json", "-"], cwd=ROOT,
                          capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == OK, done.stderr
    assert json.loads(done.stdout)["outcome"] == "time out"  # stdout: the document alone


@pytest.mark.parametrize("command", [
    ["sim", "two_go2", "--duration", "0.1"],
    ["deploy", "--config", "two_go2", "--backend", "sim", "--yes", "--duration", "0.1"],
])
def test_an_existing_flight_log_is_never_overwritten_without_force(
        tmp_path: Path, command: list[str], capsys: pytest.CaptureFixture[str]) -> None:
    from deploy.cli.conventions import existing_record

    log = tmp_path / "earlier.mcap"
    log.write_bytes(b"an earlier run")
    assert main([*command, "--record", str(log)]) == USAGE
    assert "the file exists" in capsys.readouterr().err and "--force" in str(
        existing_record(argparse.Namespace(record=str(log), force=False)))
    assert log.read_bytes() == b"an earlier run"  # nothing was run, nothing written
    assert existing_record(argparse.Namespace(record=str(log), force=True)) is None
    assert existing_record(argparse.Namespace(record=str(tmp_path / "new.mcap"),
                                              force=False)) is None


@pytest.mark.parametrize(("command", "option"), [
    (["agent", "--scenario", "two_go2", "--key-prefix", "porter/x/1", "--index", "0"],
     "--peer-timeout"),
    (["agent", "--scenario", "two_go2", "--key-prefix", "porter/x/1"], "--index"),
    (["bench", "agents"], "--duration"),
    (["bench", "agents"], "--messages"),
    (["bench", "agents"], "--repeats"),
    (["bench", "recorder"], "--memory-minutes"),
    (["bench", "drivers"], "--domain"),
    (["log", "timeline", "logs/two_go2.mcap", "--around-fault"], "--window-ms"),
    (["sim"], "--seed"),
    (["sim"], "--channel-delay-rounds"),
    (["sim"], "--channel-drop"),
    (["sim"], "--delay-s"),
])
@pytest.mark.parametrize("value", ["inf", "nan", "-1"])
def test_every_numeric_option_is_finite_and_in_range(
        command: list[str], option: str, value: str,
        capsys: pytest.CaptureFixture[str]) -> None:
    # (refused while parsing: nothing runs)
    with pytest.raises(SystemExit) as exit_info:
        main([*command, option, value])
    assert exit_info.value.code == USAGE
    assert f"argument {option}" in capsys.readouterr().err
    if command[0] in ("agent", "sim") or option in ("--domain", "--memory-minutes"):
        with pytest.raises(SystemExit):  # and above its range
            main([*command, option, "1e9"])
