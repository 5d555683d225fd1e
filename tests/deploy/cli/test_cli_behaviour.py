"""The command line behaves: a version, JSON for scripts, quiet exits on closed pipes."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest

from deploy.cli.porter import main

ROOT = Path(__file__).resolve().parents[3]
LOG = ROOT / "logs" / "two_go2.mcap"


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as done:
        main(["--version"])
    assert done.value.code == 0
    assert capsys.readouterr().out.strip() == f"porter {version('porter')}"


def test_log_info_json_is_one_document_of_the_log(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["log", "info", str(LOG), "--json", "-"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["path"] == str(LOG) and record["messages"] > 1000
    assert record["topics"]["/nmpc/update"]["messages"] == 90
    assert record["metadata"]["porter"]["scenario"] == "two_go2"
    assert record["summary"]["falls"] == 0 and "mpc_settings.yaml" in record["attachments"]


def test_a_closed_pipe_ends_porter_quietly() -> None:
    read_end, write_end = os.pipe()
    os.close(read_end)  # the reader is gone before porter writes, as `| head` after its lines
    try:
        done = subprocess.run([sys.executable, "-m", "deploy.cli", "log", "info", str(LOG),
                               "--json", "-"], cwd=ROOT, stdout=write_end, stderr=subprocess.PIPE,
                              text=True, timeout=120, check=False)
    finally:
        os.close(write_end)
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr and "BrokenPipeError" not in done.stderr


def test_no_progress_bar_when_stderr_is_not_a_terminal(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", "--duration", "0.2", "--serial", "--no-record"]) == 0
    err = capsys.readouterr().err
    assert "RUNNING -> DONE" in err  # the transitions still reach the log
    assert "\r" not in err and "━" not in err and "\x1b[" not in err


def test_a_terminal_gets_the_progress_bar() -> None:
    import pty
    import threading

    controller, terminal = pty.openpty()
    chunks: list[bytes] = []

    def drain() -> None:  # read while porter writes: a full terminal buffer would block it
        while True:
            try:
                chunk = os.read(controller, 65536)
            except OSError:  # EIO: the other end is closed and drained
                return
            if not chunk:
                return
            chunks.append(chunk)

    reader = threading.Thread(target=drain, daemon=True)
    reader.start()
    try:
        done = subprocess.run([sys.executable, "-m", "deploy.cli", "sim", "--duration", "0.2",
                               "--serial", "--no-record"], cwd=ROOT, stdout=subprocess.DEVNULL,
                              stderr=terminal, timeout=300, check=False)
    finally:
        os.close(terminal)
        reader.join(timeout=10)
        os.close(controller)
    err = b"".join(chunks).decode(errors="replace")
    assert done.returncode == 0, err
    assert "s simulated" in err and "RTF" in err
