"""``porter paper closed-loop``: the paper's "comparable closed-loop transportation
performance" of the distributed NMPC against the centralized one, on shipped scenarios under
each controller profile, in MuJoCo: payload tracking (RMS position and yaw error), safety
(min h, falls, goal) and the plan's smoothness (RMS change of the planned first-stage GRFs
between updates)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from deploy.cli.conventions import DIFFERS, OK, Output
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.paper.reproduce import Profile, profile_documents, shortened_scenario, write_document
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun

# Table I's team sizes: 2, 3 (the mixed team) and 4 agents
DEFAULT_SCENARIOS = ("two_go2", "mixed_three", "four_go2")
MODES = ("distributed", "centralized")


def run_mode(name: str, mode: str, duration_s: float | None, profile: Profile,
             cache: CompiledCodeCache) -> dict:
    scenario = shortened_scenario(name, duration_s)
    shortened = scenario.duration_s < shortened_scenario(name, None).duration_s
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"mode": mode, "executor": "serial"})})
    run = SimRun(scenario, cache, profile[1])
    try:
        summary = run.run()
    finally:
        run.close()
    metrics = run.metrics
    return {"scenario": name, "profile": profile[0], "mode": mode,
            "rms_payload_position_error_m": summary["rms_payload_position_error_m"],
            "rms_payload_yaw_error_rad": summary["rms_payload_yaw_error_rad"],
            "min_h_m": summary["min_h_m"], "falls": summary["falls"],
            "reached_goal": summary["reached_goal"], "outcome": summary["outcome"],
            "expected_outcome": summary["expected_outcome"], "shortened": shortened,
            "failed_updates": summary["safety"]["nmpc_failed_updates"],
            "grf_change_rms_n": float(np.sqrt(np.mean(np.square(metrics.grf_change_n[1:]))))
            if len(metrics.grf_change_n) > 1 else 0.0,
            "nmpc_update_ms_median": summary["nmpc_update_ms"]["median"],
            "duration_s": summary["duration_s"]}


def compare(rows: list[dict]) -> list[dict]:
    """Per scenario and profile: distributed over centralized for each tracking metric."""
    out = []
    keys = ("rms_payload_position_error_m", "rms_payload_yaw_error_rad", "grf_change_rms_n")
    for d in (r for r in rows if r["mode"] == "distributed"):
        c = next(r for r in rows if r["mode"] == "centralized"
                 and (r["scenario"], r["profile"]) == (d["scenario"], d["profile"]))
        out.append({"scenario": d["scenario"], "profile": d["profile"],
                    **{f"{key}_ratio": d[key] / c[key] if c[key] else float("nan")
                       for key in keys}})
    return out


def format_closed_loop(rows: list[dict], ratios: list[dict]) -> str:
    cells = []
    for r in rows:
        ratio = next((q for q in ratios if (q["scenario"], q["profile"])
                      == (r["scenario"], r["profile"])), None) if r["mode"] == "distributed" \
            else None
        cells.append([
            r["scenario"], r["profile"], r["mode"], f"{r['rms_payload_position_error_m']:.3f}",
            f"{r['rms_payload_yaw_error_rad']:.3f}", f"{r['grf_change_rms_n']:.2f}",
            f"{r['min_h_m']:.3f}", str(r["falls"]), "yes" if r["reached_goal"] else "no",
            str(r["failed_updates"]),
            "" if ratio is None else (f"{ratio['rms_payload_position_error_m_ratio']:.2f} / "
                                      f"{ratio['rms_payload_yaw_error_rad_ratio']:.2f} / "
                                      f"{ratio['grf_change_rms_n_ratio']:.2f}")])
    columns: list[Column | str] = ["scenario", "profile", "mode", *(
        Column(name, "right") for name in ("rms pos m", "rms yaw rad", "dGRF rms N",
                                           "min h m", "falls")), "goal",
        Column("failed", "right"), "dist/cent pos / yaw / dGRF"]
    return ("porter paper closed-loop: distributed vs centralized NMPC in closed loop "
            "(the paper: comparable performance)\n" + render_table(columns, cells, [
                "dGRF rms = RMS change of the planned first-stage GRFs between updates, "
                "feet in stance in both (smoothness); failed = updates with a failed solve"]))


def reproduce_closed_loop(names: list[str], duration_s: float | None, out: Path,
                          output: Output, profiles: list[Profile]) -> int:
    """Exit ``OK`` when every run of both modes ended without a fall as its scenario expects
    (a shortened run need not arrive), else ``DIFFERS``."""
    cache = CompiledCodeCache()
    rows = [run_mode(name, mode, duration_s, profile, cache)
            for profile in profiles for name in names for mode in MODES]
    ratios = compare(rows)
    output.report(format_closed_loop(rows, ratios))
    document = {"claim": "closed-loop", "profiles": profile_documents(profiles),
                "rows": rows, "ratios": ratios}
    write_document(out, "closed-loop", document)
    output.progress(f"wrote {out / 'closed-loop.json'}")
    output.write_json(document)
    as_expected = all(r["falls"] == 0 and (r["outcome"] == r["expected_outcome"] or (
        r["shortened"] and r["outcome"] == "time out")) for r in rows)
    return OK if as_expected else DIFFERS
