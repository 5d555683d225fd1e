"""Expectations on a log's summary metrics, stored next to it as ``LOG.expect.json``.

Each entry names a summary key (dotted for nested ones, e.g. ``payload_estimate_error.
position_rms_m``) and a check: ``{"equals": v}``, ``{"min": a}``, ``{"max": b}`` or both.
``draft_expectations`` proposes them from a log's summary (exact for counts and flags, a band
around measured values, ±10 % and at least 1e-3); a human edits and commits them deliberately
(see logs/README.md). ``porter regress`` checks them against a re-simulation of the logged
run (``deploy.recording.resimulation``), not against the summary stored in the log.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

# Wall-clock figures differ between machines: never expected.
TIMING_KEYS = {"nmpc_update_ms", "deadline_misses", "wbc_tick_ms", "real_time_factor",
               "nlp_solve_ms_median", "wall_s", "nmpc_wall_s", "wbc_wall_s",
               "loop_tick_ms"}


def expectations_path(log_path: Path) -> Path:
    return log_path.with_suffix(".expect.json")


def flatten_summary(summary: dict, prefix: str = "") -> dict[str, Any]:
    flat: dict[str, Any] = {}
    for key, value in summary.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            flat.update(flatten_summary(value, name + "."))
        else:
            flat[name] = value
    return flat


def check_expectations(summary: dict | None, path: Path) -> list[str]:
    """Failures (empty when every expectation holds)."""
    try:
        expectations = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as error:
        return [f"{path}: cannot read expectations ({error})"]
    if summary is None:
        return [f"{path}: the log has no summary metrics to check"]
    flat = flatten_summary(summary)
    failures = []
    for key, check in expectations.items():
        if key not in flat:
            failures.append(f"{key}: not in the log's summary")
            continue
        value = flat[key]
        if "equals" in check and value != check["equals"]:
            failures.append(f"{key} = {value!r}, expected {check['equals']!r}")
        if "min" in check and (value is None or value < check["min"]):
            failures.append(f"{key} = {value!r}, expected >= {check['min']}")
        if "max" in check and (value is None or value > check["max"]):
            failures.append(f"{key} = {value!r}, expected <= {check['max']}")
    return failures


def expectation_margins(summary: dict | None, path: Path) -> dict[str, float]:
    """Per banded expectation (``min`` and ``max``), where the value sits: 1 at the band's
    centre, 0 on an edge, negative outside (distance to the nearer edge / half the band)."""
    try:
        expectations = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError):
        return {}
    flat = flatten_summary(summary or {})
    margins = {}
    for key, check in expectations.items():
        value = flat.get(key)
        if "min" in check and "max" in check and isinstance(value, int | float):
            half = (check["max"] - check["min"]) / 2
            if value == check["min"] == 0:
                continue  # a physical floor (a norm at 0), not a tolerance's edge
            if half > 0:
                margins[key] = min(value - check["min"], check["max"] - value) / half
    return margins


def _signed(key: str) -> bool:
    """Summary metrics that may be negative: the safety values h (inside the margin)."""
    return key.split(".")[0] in ("min_h_m", "min_h_by_pair_m")


def draft_expectations(summary: dict, relative_band: float = 0.1) -> dict[str, dict]:
    """Exact checks for flags, counts and names; ``value +- relative_band |value|`` (at least
    1e-3) for measured floats; nothing for wall-clock figures."""
    drafted: dict[str, dict] = {}
    for key, value in flatten_summary(summary).items():
        if key.split(".")[0] in TIMING_KEYS or value is None:
            continue
        if isinstance(value, bool | int | str):
            drafted[key] = {"equals": value}
        elif isinstance(value, float):
            band = max(relative_band * abs(value), 1e-3)
            low = value - band
            if value >= 0 and not _signed(key):
                low = max(low, 0.0)  # norms, errors, residuals, distances, times: never < 0
            drafted[key] = {"min": round(low, 6), "max": round(value + band, 6)}
    return drafted
