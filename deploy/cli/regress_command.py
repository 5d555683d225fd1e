"""``porter regress LOG...``: replay each log's NMPC decisions, re-simulate its run and check
its expectations (``deploy.recording.regression``); or draft the expectations afresh."""

from __future__ import annotations

import argparse
import json
from dataclasses import asdict
from pathlib import Path

from core.locomotion.settings import WbcSettings
from core.nmpc.settings import MpcSettings
from deploy.cli.conventions import DIFFERS, OK, USAGE, Output, error
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.files import ConfigError, load_settings
from deploy.recording.expectations import draft_expectations, expectations_path
from deploy.recording.log_reader import LogError, LogFile
from deploy.recording.regression import (
    format_report,
    recorded_kernels,
    regress_log,
    replay_blas_target,
)

__all__ = ["run_regress"]


def run_regress(args: argparse.Namespace) -> int:
    """Exit 0 when every log passes, 1 when one differs, 2 when one cannot be read."""
    out = Output(args)
    if args.refresh_expectations:
        return refresh_expectations(args.logs, out)
    settings = load_settings(args.settings, MpcSettings) if args.settings else None
    wbc = load_settings(args.wbc_settings, WbcSettings) if args.wbc_settings else None
    cache: CompiledCodeCache | None = None  # one per process: kernels load once
    reports = []
    for path in args.logs:
        try:
            cache = cache or CompiledCodeCache(blas_target=replay_blas_target(
                recorded_kernels(LogFile(path))))
            report = regress_log(path, cache, settings, args.max_decisions,
                                 not args.no_resimulate, wbc)
        except (LogError, ConfigError) as failure:
            return error(f"{failure}; give the path of a flight log porter wrote")
        out.report(format_report(report))
        reports.append(report)
    out.write_json([asdict(r) | {"passed": r.passed} for r in reports])
    failed = [r for r in reports if not r.passed]
    out.report(f"porter regress: {len(reports) - len(failed)} of {len(reports)} logs pass")
    return DIFFERS if failed else OK


def refresh_expectations(paths: list[str], out: Output) -> int:
    """Write LOG.expect.json beside each log from its summary (to review and commit)."""
    for path in paths:
        try:
            summary = LogFile(path).summary()
        except LogError as failure:
            return error(f"{failure}; give the path of a flight log porter wrote")
        if summary is None:
            return error(f"{path}: no summary metrics to draft expectations from; record a "
                         "run that ends normally (its summary is written on close)", USAGE)
        target = expectations_path(Path(path))
        target.write_text(json.dumps(draft_expectations(summary), indent=2) + "\n")
        out.report(f"wrote {target}: review the bands, then commit it")
    return OK
