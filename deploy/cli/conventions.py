"""The conventions every ``porter`` command keeps: exit codes, ``--json FILE`` (``-``: stdout),
``--quiet``, and errors as one line on stderr that names what to do.

Exit codes (the same for every command):

====  ==============  =======================================================================
code  name            meaning
====  ==============  =======================================================================
0     ``OK``          done, and as expected (a run reached its scenario's expected outcome;
                      every fault of a drill was handled; every log passed its regression)
1     ``DIFFERS``     done, but not as expected (another outcome, a fall, a fault not handled
                      as expected, a regression that differs, a claim's run that failed)
2     ``USAGE``       nothing was run: a bad argument, config or file (the message says which)
3     ``SAFE_STOP``   ``porter deploy``: the team ended in a safe stop
130   ``STOPPED``     stopped by the operator (Ctrl-C, SIGTERM) before the end
====  ==============  =======================================================================

``--json FILE`` writes the command's report as one JSON document; with ``-`` it goes to
stdout and the text report is left out, so that stdout is the document alone. ``--quiet``
leaves out the text report and the progress lines: errors (stderr), ``--json`` and the exit
code remain.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["DIFFERS", "OK", "SAFE_STOP", "STOPPED", "USAGE", "Output", "add_output_options",
           "add_record_options", "error", "existing_record", "number_in", "os_error",
           "whole_number_in"]

OK, DIFFERS, USAGE, SAFE_STOP, STOPPED = 0, 1, 2, 3, 130


def number_in(low: float, high: float, low_open: bool = False, high_open: bool = False
              ) -> Callable[[str], float]:
    """An argument type: a finite number within [low, high] (an open end excludes it; high
    ``math.inf``: no upper bound)."""
    left, right = "(" if low_open else "[", ")" if high_open else "]"
    where = (f"{'above' if low_open else 'at least'} {low:g}" if math.isinf(high)
             else f"in {left}{low:g}, {high:g}{right}")

    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
        inside = (math.isfinite(value) and (value > low if low_open else value >= low)
                  and (value < high if high_open else value <= high))
        if not inside:
            raise argparse.ArgumentTypeError(
                f"must be a finite number {where}, got {text}")
        return value

    return parse


def whole_number_in(low: int, high: int | None = None) -> Callable[[str], int]:
    """An argument type: a whole number within [low, high] (high None: no upper bound)."""
    where = f"at least {low}" if high is None else f"in [{low}, {high}]"

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
        if value < low or (high is not None and value > high):
            raise argparse.ArgumentTypeError(f"must be a whole number {where}, got {text}")
        return value

    return parse


def add_output_options(parser: argparse.ArgumentParser, report: str) -> None:
    """``--json FILE`` (the ``report``, e.g. "the summary") and ``--quiet`` on ``parser``."""
    parser.add_argument("--json", metavar="FILE",
                        help=f"also write {report} as JSON to FILE ('-': to stdout, instead of "
                             "the text)")
    parser.add_argument("--quiet", action="store_true",
                        help="print nothing but errors (the exit code and --json carry the "
                             "result)")


def add_record_options(parser: argparse.ArgumentParser, default: str) -> None:
    """``--record LOG.mcap`` (default ``default``), ``--no-record`` and ``--force``."""
    parser.add_argument("--record", metavar="LOG.mcap", help=f"flight log (default {default}); "
                        "an existing file is refused unless --force")
    parser.add_argument("--force", action="store_true",
                        help="overwrite an existing --record file")


def existing_record(args: argparse.Namespace) -> str | None:
    """Why ``--record`` must not be written (a file is there and no ``--force``), or None."""
    record = getattr(args, "record", None)
    if record and Path(record).exists() and not getattr(args, "force", False):
        return (f"--record {record}: the file exists; give another path, or --force to "
                "overwrite it")
    return None


class Output:
    """Where a command's report, progress and JSON go, by ``--json`` and ``--quiet``."""

    def __init__(self, args: argparse.Namespace) -> None:
        self.json_path: str | None = getattr(args, "json", None)
        self.quiet = bool(getattr(args, "quiet", False)) or self.json_path == "-"

    def report(self, text: str) -> None:
        """The text report (stdout)."""
        if not self.quiet:
            print(text, flush=True)

    def progress(self, text: str) -> None:
        """A line on how the command is getting on (stderr)."""
        if not self.quiet:
            print(text, file=sys.stderr, flush=True)

    def write_json(self, document: Any) -> None:
        """The report as JSON to ``--json``'s FILE, or to stdout for ``-``; nothing without."""
        if self.json_path is None:
            return
        text = json.dumps(document, indent=2, default=str) + "\n"
        if self.json_path == "-":
            sys.stdout.write(text)
            sys.stdout.flush()
            return
        Path(self.json_path).write_text(text)
        self.progress(f"wrote {self.json_path}")


def error(message: str, code: int = USAGE) -> int:
    """Print ``porter: message`` as one line on stderr; returns ``code``."""
    line = "; ".join(part.strip() for part in message.splitlines() if part.strip())
    print(f"porter: {line}", file=sys.stderr, flush=True)
    return code


def os_error(failure: OSError, what_to_do: str = "") -> str:
    """One line for a file error: ``PATH: cannot read (No such file or directory)``."""
    target = failure.filename if failure.filename is not None else "file"
    reason = failure.strerror or type(failure).__name__
    return f"{target}: {reason}" + (f"; {what_to_do}" if what_to_do else "")
