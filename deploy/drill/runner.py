"""Run one drill fault as its own ``porter deploy --backend sim`` and judge it from outside.

Each fault gets a copy of a shipped deploy config (``two_go2`` unless the case names
another) with a short stand-up
(``STAND_UP``), in slow motion (``SLOW_MOTION``), the fault's changes merged in, and a run of
``DURATION_S``. The verdict reads:
the exit code; the summary (stdout JSON); the simulator's truth in it (per robot: the first
damping-only command after the fault, and every command that was not damping after that);
the flight log read back (``LogFile``; a log without its summary is recovered chunk by chunk).
"""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from deploy.config.deploy_config import CONFIG_DIR
from deploy.drill.catalogue import AT_S, DAMPED_WITHIN_S, DrillFault
from deploy.recording.log_reader import LogError, LogFile, recover
from deploy.reports.table import Column, render_table

__all__ = ["CONTROL", "DURATION_S", "DrillRow", "RunOutput", "format_table", "judge",
           "run_case", "run_fault", "with_control"]

DURATION_S = 2.0  # RUNNING seconds
ORPHAN_REPORT = "world_after_porter.json"  # kill -9: the world's ground truth after porter
STAND_UP = {"posture": {"stand_up_s": 1.0, "settle_s": 0.2}}
# The drill judges porter's reactions in simulated time; in slow motion the simulated world
# keeps its time on a 2-core machine (at the shipped 1.0 it holds the robots' states up to
# 20 ms now and then), so the verdicts and detection times are porter's, not the machine's.
SLOW_MOTION = {"sim": {"time_scale": 0.2}}
_RUNNING = re.compile(r"-> RUNNING")


@dataclass
class DrillRow:
    fault: str
    expect: str
    passed: bool
    detected_after_ms: float | None
    final_state: str
    non_damping_after_detection: int | None
    log: str
    exit_code: int
    detail: str
    within_ms: float | None = None  # the case's bound on its detection time
    control_fails: bool | None = None  # the same check on the control run failed (as it must)


@dataclass
class RunOutput:
    """What one ``porter deploy`` of a case left: its exit code, summary, stderr, flight log
    and (kill -9 of porter) the world's report after porter was gone."""

    code: int
    summary: dict[str, Any] | None
    stderr: str
    log_path: Path
    folder: Path
    orphan_report: dict[str, Any] | None = None


# The control run: the drill's deploy with no fault. Every case's check is also applied to it
# and must fail there, or the check could not tell the fault from its absence.
CONTROL = DrillFault("control run (no fault)", "ignored", "")


def _merge(base: dict[str, Any], changes: dict[str, Any]) -> dict[str, Any]:
    merged = dict(base)
    for key, value in changes.items():
        merged[key] = (_merge(merged[key], value) if isinstance(value, dict)
                       and isinstance(merged.get(key), dict) else value)
    return merged


def _config(fault: DrillFault, folder: Path) -> Path:
    data = yaml.safe_load((CONFIG_DIR / f"{fault.deployment}.yaml").read_text())
    data = _merge(_merge(_merge(data, STAND_UP), SLOW_MOTION), fault.config)
    if fault.action == "kill_porter":  # the world outlives porter and reports what it saw
        data = _merge(data, {"sim": {"orphan_report": str(folder / ORPHAN_REPORT)}})
    path = folder / "deploy.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def _children_named(pid: int, comm: str) -> list[int]:
    """Descendants of ``pid`` whose process name is ``comm`` (from /proc)."""
    parents: dict[int, int] = {}
    names: dict[int, str] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            name = stat[stat.index("(") + 1: stat.rindex(")")]
            parents[int(entry.name)] = int(stat[stat.rindex(")") + 2:].split()[1])
            names[int(entry.name)] = name
    found = []
    for child, name in names.items():
        ancestor = parents.get(child)
        while ancestor is not None and ancestor not in (0, 1, pid):
            ancestor = parents.get(ancestor)
        if ancestor == pid and name == comm:
            found.append(child)
    return found


def _act(process: subprocess.Popen, fault: DrillFault, running: threading.Event,
         time_scale: float) -> None:
    """Once RUNNING is announced, wait until about ``AT_S`` and do the fault's action."""
    if not running.wait(120.0):
        return
    time.sleep(max(AT_S - 1.5, 0.2) / time_scale)
    if fault.action == "sigterm":
        process.send_signal(signal.SIGTERM)
    elif fault.action == "sigint":
        process.send_signal(signal.SIGINT)
    elif fault.action == "kill_nmpc":
        for pid in _children_named(process.pid, "porter-nmpc"):
            os.kill(pid, signal.SIGKILL)
    elif fault.action == "kill_porter":
        process.kill()  # SIGKILL: no handler, no finally, no flush


def run_fault(fault: DrillFault, folder: Path, timeout_s: float = 300.0) -> DrillRow:
    """Run ``fault`` in ``folder`` (its config, log and output land there) and judge it."""
    return judge(fault, run_case(fault, folder, timeout_s))


def judge(fault: DrillFault, output: RunOutput) -> DrillRow:
    """``fault``'s verdict on a run's ``output`` (its own, or the control run's)."""
    if fault.action == "kill_porter":
        return _judge_kill(fault, output.code, output.orphan_report, output.log_path,
                           output.folder)
    return _judge(fault, output.code, output.summary, output.stderr, output.log_path,
                  output.folder)


def with_control(row: DrillRow, fault: DrillFault, control: RunOutput) -> DrillRow:
    """``row`` with the control verdict: the case's check applied to the control run must
    fail; a check that passes there as well cannot fail, and the row does not pass."""
    fails = not judge(fault, control).passed
    row.control_fails = fails
    if not fails:
        row.passed = False
        row.detail = ("its check passes without the fault too; " + row.detail)[:110]
    return row


def run_case(fault: DrillFault, folder: Path, timeout_s: float = 300.0) -> RunOutput:
    """One ``porter deploy --backend sim`` of ``fault`` in ``folder``, its action done."""
    folder.mkdir(parents=True, exist_ok=True)
    config = _config(fault, folder)
    log_path = folder / "run.mcap"
    args = ["--duration", f"{DURATION_S:g}", *fault.args]
    command = [sys.executable, "-m", "deploy.cli", "deploy", "--config", str(config),
               "--backend", "sim", "--yes", "--record", str(log_path), *args]
    time_scale = float(yaml.safe_load(config.read_text())["sim"].get("time_scale", 1.0))
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
    running = threading.Event()
    errors: list[str] = []
    output: list[str] = []

    def read_stderr() -> None:
        assert process.stderr is not None
        for line in process.stderr:
            errors.append(line)
            if _RUNNING.search(line):
                running.set()

    def read_stdout() -> None:
        assert process.stdout is not None
        output.append(process.stdout.read())

    readers = [threading.Thread(target=read, daemon=True) for read in (read_stderr, read_stdout)]
    for reader in readers:
        reader.start()
    if fault.action != "none":
        threading.Thread(target=_act, args=(process, fault, running, time_scale),
                         daemon=True).start()
    try:
        process.wait(timeout=timeout_s)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
    for reader in readers:
        reader.join(10.0)
    running.set()  # release an actor still waiting
    stdout = "".join(output)
    (folder / "stderr.txt").write_text("".join(errors))
    orphan = (_orphan_report(folder / ORPHAN_REPORT) if fault.action == "kill_porter"
              else None)
    return RunOutput(process.returncode, _summary(stdout), "".join(errors), log_path, folder,
                     orphan)


def _orphan_report(path: Path, timeout_s: float = 60.0) -> dict[str, Any] | None:
    """The world's report once it has run on without porter (it writes it at the end)."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if path.exists():
            try:
                return json.loads(path.read_text())
            except json.JSONDecodeError:
                pass  # still being written
        time.sleep(0.2)
    return None


def _judge_kill(fault: DrillFault, code: int, truth: dict[str, Any] | None, log_path: Path,
                folder: Path) -> DrillRow:
    """kill -9 of porter: from the moment the world lost porter, every robot must get
    damping-only commands within ``DAMPED_WITHIN_S`` (the watchdog) and nothing else."""
    log = _log_state(log_path, folder)
    if truth is None or not truth.get("faults_applied"):
        return DrillRow(fault.name, fault.expect, False, None, "killed", None, log, code,
                        "the world wrote no report after porter was gone")
    after = [robot.get("after_fault", {}) for robot in truth.get("robots", {}).values()]
    firsts = [a.get("first_damping_s") for a in after]
    non_damping = sum(a.get("non_damping_after_damping", 0) for a in after)
    damped = bool(after) and all(first is not None for first in firsts)
    detected_ms = 1e3 * max(firsts) if damped else None  # the last robot to be damped
    passed = (code == -signal.SIGKILL and damped and non_damping == 0
              and detected_ms is not None and detected_ms <= 1e3 * DAMPED_WITHIN_S
              and (log == "yes" or log.startswith("recovered")))
    detail = (f"every robot damped by the watchdog within {detected_ms:.0f} ms of the loss"
              if damped else "a robot got no damping command")
    return DrillRow(fault.name, fault.expect, passed, detected_ms, "killed", non_damping, log,
                    code, detail, 1e3 * DAMPED_WITHIN_S)


def _summary(stdout: str) -> dict[str, Any] | None:
    start = stdout.find("{")
    try:
        return json.loads(stdout[start:]) if start >= 0 else None
    except json.JSONDecodeError:
        return None


def _log_state(path: Path, folder: Path) -> str:
    if not path.exists():
        return "none"
    try:
        if LogFile(path).summary() is not None:
            return "yes"
    except LogError:
        pass
    try:
        recovered = recover(path, folder / "recovered.mcap")
    except LogError as error:
        return f"no ({error})"
    return f"recovered ({recovered.messages} msgs)"


def _judge(fault: DrillFault, code: int, summary: dict[str, Any] | None, stderr: str,
           log_path: Path, folder: Path) -> DrillRow:
    log = _log_state(log_path, folder)
    if fault.expect in ("refused", "not started"):
        wanted = 2 if fault.expect == "refused" else 1
        text = stderr if summary is None else stderr + json.dumps(summary)
        passed = code == wanted and fault.cause in text
        # the last line naming the cause: the error or the pre-flight report, not a banner
        detail = next((line.strip() for line in reversed(stderr.splitlines())
                       if fault.cause in line),
                      stderr.strip().splitlines()[-1] if stderr.strip() else "")
        return DrillRow(fault.name, fault.expect, passed, None, "-" if summary is None
                        else summary.get("final_state", "-"), None, log, code, detail[:110])
    if summary is None:
        return DrillRow(fault.name, fault.expect, False, None, "?", None, log, code,
                        "no summary: " + stderr.strip()[-100:])
    truth = summary.get("sim_ground_truth") or {}
    robots = truth.get("robots") or {}
    after = [robot.get("after_fault", {}) for robot in robots.values()]
    firsts = [a.get("first_damping_s") for a in after if a.get("first_damping_s") is not None]
    detected_ms = (1e3 * min(firsts) if firsts and truth.get("faults_applied")
                   and fault.expect == "safe stop" else None)
    non_damping = (sum(a.get("non_damping_after_damping", 0) for a in after)
                   if truth.get("faults_applied") else None)
    final, cause = summary.get("final_state", "?"), summary.get("safe_stop") or ""
    if fault.expect == "safe stop":
        in_time = fault.within_ms is None or (detected_ms is not None
                                              and detected_ms <= fault.within_ms)
        # (every safe-stop case has the world counting: a fault applied, or a marker)
        passed = (code == 3 and final == "DONE" and fault.cause in cause
                  and non_damping == 0 and in_time)
        detail = cause if in_time else f"detected after {detected_ms} ms; {cause}"
    elif fault.expect == "sit down":
        passed = code == 130 and final == "DONE" and not cause
        detail = summary.get("result", "")
    elif fault.expect == "rides through":
        count = _dotted(summary, fault.evidence)
        passed = (code == 0 and final == "DONE" and not cause
                  and (count or 0) > fault.evidence_above)
        detail = f"{fault.evidence} {count}; {summary.get('result', '')}"
    else:  # ignored
        rejected = sum(summary.get("rejected", {}).get(fault.rejected, {}).values())
        passed = code == 0 and final == "DONE" and not cause and rejected > 0
        detail = f"{rejected} {fault.rejected} packets refused; {summary.get('result', '')}"
    return DrillRow(fault.name, fault.expect, passed, detected_ms, final, non_damping, log,
                    code, detail[:110], fault.within_ms)


def _dotted(summary: dict[str, Any], key: str) -> Any:
    value: Any = summary
    for part in key.split("."):
        value = value.get(part) if isinstance(value, dict) else None
    return value


def format_table(rows: list[DrillRow]) -> str:
    columns: list[Column | str] = [
        "fault", "expected", "ok", Column("detected [ms]", "right"),
        Column("bound [ms]", "right"), "control", "final",
        Column("non-damping", "right"), "log", Column("exit", "right"), "detail"]
    cells = [[row.fault, row.expect, "yes" if row.passed else "NO",
              "-" if row.detected_after_ms is None else f"{row.detected_after_ms:.0f}",
              "-" if row.within_ms is None else f"{row.within_ms:.0f}",
              {None: "-", True: "fails", False: "PASSES"}[row.control_fails],
              row.final_state,
              "-" if row.non_damping_after_detection is None
              else str(row.non_damping_after_detection),
              row.log[:10], str(row.exit_code), row.detail] for row in rows]
    passed = sum(row.passed for row in rows)
    return render_table(columns, cells, [
        f"{passed} of {len(rows)} faults handled as expected; detected: simulated ms from the "
        "fault to the first damping-only command a robot received (bound: the most the case "
        "allows); control: the case's check on a run without any fault (it must fail); "
        "non-damping: commands that were not damping after that (must be 0)"])
