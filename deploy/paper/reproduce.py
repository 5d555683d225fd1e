"""``porter paper CLAIM``: run a claim's variants on the MuJoCo backend under each controller
profile (``deploy.config.profiles``: porter's and the paper's NLP) and print porter's figures
beside the paper's; write them as JSON and the paper's ablation plot as a PNG."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from core.nmpc.settings import MpcSettings
from deploy.cli.conventions import DIFFERS, OK, Output
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import Scenario, load_scenario
from deploy.paper.claims import CLAIMS, Claim, Variant
from deploy.recording.expectations import flatten_summary
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun

Profile = tuple[str, MpcSettings]  # (label, settings)


def variant_scenario(scenario: Scenario, variant: Variant, executor: str) -> Scenario:
    controller = scenario.controller.model_copy(update={
        **variant.controller, "executor": variant.executor or executor})
    return scenario.model_copy(update={"controller": controller})


def variant_settings(base: MpcSettings, variant: Variant) -> MpcSettings:
    if variant.coupling_enabled:
        return base
    return base.model_copy(update={"coupling": base.coupling.model_copy(
        update={"enabled": False})})


def shortened_scenario(name: str, duration_s: float | None) -> Scenario:
    scenario = load_scenario(name)
    if duration_s is None:
        return scenario
    return scenario.model_copy(update={"duration_s": min(duration_s, scenario.duration_s)})


def run_claim(claim: Claim, scenario_name: str, duration_s: float | None,
              profiles: list[Profile], executor: str = "serial",
              cache: CompiledCodeCache | None = None) -> list[dict]:
    """One row per profile and variant: its metrics, the paper's, the safety outcome, the
    NLP's health (failed solves, relaxed plans) and the series."""
    cache = cache or CompiledCodeCache()
    scenario = shortened_scenario(scenario_name, duration_s)
    rows = []
    for label, settings in profiles:
        for variant in claim.variants:
            run = SimRun(variant_scenario(scenario, variant, executor), cache,
                         variant_settings(settings, variant))
            try:
                summary = run.run()
            finally:
                run.close()
            flat = flatten_summary(summary)
            series = {name: list(map(float, getattr(run.metrics, name)))
                      for name in claim.series}
            rows.append({"profile": label, "variant": variant.label,
                         "metrics": {m: float(flat[m]) for m in claim.metrics},
                         "paper": dict(variant.paper), "falls": summary["falls"],
                         "reached_goal": summary["reached_goal"],
                         "min_h_m": summary["min_h_m"],
                         "failed_updates": int(flat["safety.nmpc_failed_updates"]),
                         "duration_s": summary["duration_s"], "series": series})
    return rows


def format_rows(claim: Claim, rows: list[dict]) -> str:
    prefix = {"admm_residual_mean": "avg ", "admm_residual_rms": "rms "}
    short = {m: prefix.get(m.split(".")[0], "") + m.split(".")[-1] for m in claim.metrics}
    columns: list[Column | str] = ["profile", "variant"]
    for m in claim.metrics:
        columns += [Column(f"{short[m]} porter", "right"), Column("paper", "right")]
    columns += [Column("falls", "right"), "goal", Column("min h m", "right"),
                Column("failed", "right")]
    cells = []
    for row in rows:
        values = []
        for m in claim.metrics:
            values += [f"{row['metrics'][m]:.3g}",
                       f"{row['paper'][m]:.3g}" if m in row["paper"] else "-"]
        cells.append([row["profile"], row["variant"], *values, str(row["falls"]),
                      "yes" if row["reached_goal"] else "no", f"{row['min_h_m']:.3f}",
                      str(row["failed_updates"])])
    return f"porter paper {claim.name}: {claim.statement}\n" + render_table(columns, cells, [
        "profile: porter = porter's NLP and rti, paper = the paper's NLP, IPOPT converged "
        "(deploy/config/profiles); failed = NMPC updates with a failed local solve"])


def plot(claim: Claim, rows: list[dict], path: Path) -> None:
    """The paper's ablation panels: each series over time, one line per profile and variant
    (solid porter's profile, dashed the paper's)."""
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(1, len(claim.series), figsize=(6 * len(claim.series), 3.6),
                                squeeze=False)
    profiles = list(dict.fromkeys(row["profile"] for row in rows))
    styles = ["-", "--", ":", "-."]
    for axis, name in zip(axes[0], claim.series, strict=True):
        for row in rows:
            values = np.asarray(row["series"][name])
            if name == "yaw_error_rad":
                values = np.abs(values)
            time_s = np.linspace(0.0, row["duration_s"], len(values))
            axis.plot(time_s, values, label=f"{row['profile']}: {row['variant']}",
                      linewidth=1.0,
                      linestyle=styles[profiles.index(row["profile"]) % len(styles)])
        axis.set_xlabel("time [s]")
        axis.set_ylabel(name.replace("_", " "))
        if name != "yaw_error_rad":
            axis.set_yscale("log")
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize=7)
    figure.suptitle(f"porter paper {claim.name}")
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)


def write_document(out: Path, name: str, document: dict) -> None:
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{name}.json").write_text(json.dumps(
        document, indent=2,
        default=lambda v: None if isinstance(v, float) and math.isnan(v) else v) + "\n")


def profile_documents(profiles: list[Profile]) -> dict:
    """Each profile's whole settings, so that a document says what ran."""
    return {label: settings.model_dump(mode="json") for label, settings in profiles}


def reproduce(name: str, scenario: str, duration_s: float | None, out: Path,
              output: Output, profiles: list[Profile], executor: str = "serial") -> int:
    """Exit ``OK`` when every variant of every profile ran safely to the goal (the paper's
    claim is of safe runs), else ``DIFFERS``."""
    claim = CLAIMS[name]
    rows = run_claim(claim, scenario, duration_s, profiles, executor)
    output.report(format_rows(claim, rows))
    out.mkdir(parents=True, exist_ok=True)
    plot(claim, rows, out / f"{name}.png")
    table = [{k: v for k, v in row.items() if k != "series"} for row in rows]
    document = {"claim": name, "statement": claim.statement, "scenario": scenario,
                "profiles": profile_documents(profiles), "rows": table,
                "series": {f"{row['profile']}: {row['variant']}": row["series"]
                           for row in rows}}
    write_document(out, name, document)
    output.progress(f"wrote {out / (name + '.json')} and {out / (name + '.png')}")
    output.write_json(document)
    shortened = duration_s is not None and duration_s < load_scenario(scenario).duration_s
    safe = all(row["falls"] == 0 and (row["reached_goal"] or shortened) for row in rows)
    return OK if safe else DIFFERS
