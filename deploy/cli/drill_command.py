"""``porter drill``: run the fault suite (``deploy.drill``) and print its table."""

from __future__ import annotations

import argparse
import json
import tempfile
from dataclasses import asdict
from pathlib import Path

from deploy.drill.catalogue import catalogue
from deploy.drill.runner import format_table, run_fault

__all__ = ["run_drill"]


def run_drill(args: argparse.Namespace) -> int:
    """``porter drill``: exit 0 when every fault was handled as expected, else 1."""
    faults = [fault for fault in catalogue() if not args.faults
              or any(name.lower() in fault.name.lower() for name in args.faults)]
    if not faults:
        print(f"porter drill: no fault matches {args.faults}; faults: "
              f"{[fault.name for fault in catalogue()]}")
        return 2
    folder = Path(args.keep) if args.keep else Path(tempfile.mkdtemp(prefix="porter-drill-"))
    print(f"porter drill: {len(faults)} faults, one porter deploy --backend sim each "
          f"(runs in {folder})", flush=True)
    rows = []
    for index, fault in enumerate(faults):
        rows.append(run_fault(fault, folder / f"{index:02d}"))
        row = rows[-1]
        print(f"  {fault.name}: {'ok' if row.passed else 'NOT AS EXPECTED'} "
              f"(exit {row.exit_code}; {row.detail[:70]})", flush=True)
    print(format_table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({"rows": [asdict(r) for r in rows]}, indent=2))
        print(f"wrote {args.json}")
    return 0 if all(row.passed for row in rows) else 1
