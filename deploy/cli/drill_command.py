"""``porter drill``: run the fault suite (``deploy.drill``) and print its table."""

from __future__ import annotations

import argparse
import tempfile
from dataclasses import asdict
from pathlib import Path

from deploy.cli.conventions import DIFFERS, OK, Output, error
from deploy.drill.catalogue import catalogue
from deploy.drill.runner import CONTROL, format_table, judge, run_case, with_control

__all__ = ["run_drill"]


def run_drill(args: argparse.Namespace) -> int:
    """``porter drill``: exit 0 when every fault was handled as expected, else 1 (2: no fault
    matches the names given)."""
    faults = [fault for fault in catalogue() if not args.faults
              or any(name.lower() in fault.name.lower() for name in args.faults)]
    if not faults:
        return error(f"drill: no fault matches {args.faults}; name a part of one of "
                     f"{[fault.name for fault in catalogue()]}")
    out = Output(args)
    folder = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="porter-drill-"))
    out.progress(f"porter drill: {len(faults)} faults, one porter deploy --backend sim each, "
                 f"and a control run without a fault (runs in {folder})")
    # every case's check must fail on the control run: a check that passes without its fault
    # cannot tell it from its absence
    control = run_case(CONTROL, folder / "control")
    rows = []
    for index, fault in enumerate(faults):
        rows.append(with_control(judge(fault, run_case(fault, folder / f"{index:02d}")),
                                 fault, control))
        row = rows[-1]
        out.progress(f"  {fault.name}: {'ok' if row.passed else 'NOT AS EXPECTED'} "
                     f"(exit {row.exit_code}; {row.detail[:70]})")
    out.report(format_table(rows))
    out.write_json({"rows": [asdict(r) for r in rows]})
    return OK if all(row.passed for row in rows) else DIFFERS
