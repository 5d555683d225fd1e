"""``porter paper experiments``: the paper's experiments as scenarios (2- and 3-agent
transport, an unknown 12 kg payload with pushes, three agents with pushes, a moving obstacle,
a narrow passage, and the 4-agent team of its Table I), run on
the MuJoCo backend under each controller profile and drawn as the paper's trajectory figures:
xy paths of the payload and the robots among the obstacles and their safe sets."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from core.nmpc.settings import MpcSettings
from deploy.cli.conventions import DIFFERS, OK, Output
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.paper.reproduce import Profile, profile_documents, shortened_scenario
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun

# scenario -> what the paper shows for it (it reports safety and completion, no numbers)
EXPERIMENTS = {
    "two_go2": "two Go2, 5 kg payload, 7 obstacles: safe transport (h >= 0)",
    "mixed_three": "two Go2 + one A1, 5 kg payload: safe transport",
    "heavy_payload_pushes": "unknown 12 kg payload and pushes: safe and robust",
    "mixed_three_pushes": "three agents, 5 kg payload, pushes: brief violations, rapid recovery",
    "moving_obstacle": "a moving obstacle: avoided",
    "narrow_passage": "a narrow passage: passed safely",
    "four_go2": "four Go2 (Table I's 4-agent team, simulated only in the paper): safe transport",
}


def run_experiment(name: str, duration_s: float | None, cache: CompiledCodeCache,
                   profile: Profile | None = None) -> dict:
    profile = profile or ("porter", MpcSettings())
    scenario = shortened_scenario(name, duration_s)
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, cache, profile[1])
    try:
        summary = run.run()
    finally:
        run.close()
    paths = np.array(run.metrics.body_xy_m)  # (samples, 1 + robots, 2)
    safety = run.settings.safety.safety_distance_m
    obstacles = [{"start_m": o.row(0.0, 0.0)[0:2].tolist(),
                  "end_m": o.row(summary["duration_s"], 0.0)[0:2].tolist(),
                  "radius_m": o.radius_m, "safe_radius_m": o.radius_m + safety}
                 for o in run.obstacles]
    shortened = duration_s is not None and duration_s < load_scenario(name).duration_s
    as_expected = summary["falls"] == 0 and (summary["outcome"] == summary["expected_outcome"]
                                             or (shortened and summary["outcome"] == "time out"))
    return {"scenario": name, "profile": profile[0], "paper": EXPERIMENTS[name],
            "falls": summary["falls"],
            "outcome": summary["outcome"], "as_expected": as_expected,
            "reached_goal": summary["reached_goal"], "min_h_m": summary["min_h_m"],
            "rms_payload_position_error_m": summary["rms_payload_position_error_m"],
            "duration_s": summary["duration_s"], "robots": [r.name for r in run.control.robots],
            "goal_m": run.metrics.goal_m[0:2].tolist(), "obstacles": obstacles,
            "paths_m": paths[:: max(1, len(paths) // 2000)].tolist(),
            "series": series(run)}


def series(run: SimRun) -> dict:
    """The paper's experiment panels over time: min h [m] (ground truth), each robot's
    planned vertical GRF sum [N] and the ADMM residuals of each update's last iteration."""
    m = run.metrics
    step = max(1, len(m.min_h_m) // 2000)
    grf_z = (np.array([grf.reshape(len(grf), 4, 3)[:, :, 2].sum(axis=1) for grf in m.grf_n])
             if m.grf_n else np.zeros((0, 0)))
    return {"sample_time_s": np.linspace(0.0, m.duration_s, len(m.min_h_m))[::step].tolist(),
            "min_h_m": m.min_h_m[::step],
            "update_time_s": np.linspace(0.0, m.duration_s, len(m.grf_n)).tolist(),
            "grf_z_sum_n": grf_z.tolist(), "force_residual_n": list(m.force_residual_n),
            "position_residual_m": list(m.position_residual_m),
            "dual_residual": list(m.dual_residual)}


def plot_series(rows: list[dict], path: Path) -> None:
    """One row of panels per experiment: min h, planned GRF sums, ADMM residuals."""
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(len(rows), 3, figsize=(15, 2.6 * len(rows)), squeeze=False)
    for (h_axis, grf_axis, residual_axis), row in zip(axes, rows, strict=True):
        s = row["series"]
        title = f"{row['scenario']} ({row['profile']})"
        h_axis.plot(s["sample_time_s"], s["min_h_m"], linewidth=1.0)
        h_axis.axhline(0.0, color="tab:red", linewidth=0.8, linestyle="--")
        h_axis.set_ylabel("min h [m]")
        grf = np.asarray(s["grf_z_sum_n"])
        for i, robot in enumerate(row["robots"]):
            if grf.size:
                grf_axis.plot(s["update_time_s"], grf[:, i], linewidth=0.8, label=robot)
        grf_axis.set_ylabel("planned GRF z sum [N]")
        grf_axis.legend(fontsize=7)
        updates = np.asarray(s["update_time_s"])
        for name, label in (("force_residual_n", "force [N]"),
                            ("position_residual_m", "position [m]"), ("dual_residual", "dual")):
            values = np.asarray(s[name])
            if values.size:
                residual_axis.semilogy(updates[-len(values):], np.maximum(values, 1e-12),
                                       linewidth=0.8, label=label)
        residual_axis.set_ylabel("ADMM residual (RMS)")
        residual_axis.legend(fontsize=7)
        for axis in (h_axis, grf_axis, residual_axis):
            axis.set_title(title, fontsize=9)
            axis.set_xlabel("time [s]")
            axis.grid(True, alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, dpi=80)
    plt.close(figure)


def plot_experiments(rows: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    profiles = list(dict.fromkeys(row["profile"] for row in rows))
    columns = len(rows) // len(profiles)
    figure, axes = plt.subplots(len(profiles), columns, figsize=(5 * columns,
                                                                 4.5 * len(profiles)),
                                squeeze=False)
    for axis, row in zip(axes.reshape(-1), rows, strict=True):
        paths = np.asarray(row["paths_m"])
        for o in row["obstacles"]:
            start, end = np.asarray(o["start_m"]), np.asarray(o["end_m"])
            for centre, alpha in ((start, 0.6), (end, 0.25)) if not np.allclose(
                    start, end) else ((start, 0.6),):
                xy = (float(centre[0]), float(centre[1]))
                axis.add_patch(plt.Circle(xy, o["radius_m"], color="0.3", alpha=alpha))
                axis.add_patch(plt.Circle(xy, o["safe_radius_m"], fill=False,
                                          linestyle="--", color="tab:red", alpha=alpha))
            if not np.allclose(start, end):
                axis.annotate("", end, start, arrowprops={"arrowstyle": "->", "color": "0.3"})
        axis.plot(paths[:, 0, 0], paths[:, 0, 1], color="k", linewidth=2, label="payload")
        for i, robot in enumerate(row["robots"], start=1):
            axis.plot(paths[:, i, 0], paths[:, i, 1], linewidth=1, label=robot)
        axis.plot(*row["goal_m"], marker="*", markersize=12, color="tab:green", label="goal")
        axis.set_aspect("equal")
        axis.set_title(f"{row['scenario']} ({row['profile']}): min h {row['min_h_m']:.3f} m, "
                       f"falls {row['falls']}", fontsize=9)
        axis.set_xlabel("x [m]")
        axis.set_ylabel("y [m]")
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize=7, loc="best")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def format_experiments(rows: list[dict]) -> str:
    cells = [[r["scenario"], r["profile"], "yes" if r["reached_goal"] else "no",
              str(r["falls"]),
              f"{r['min_h_m']:.3f}", f"{r['rms_payload_position_error_m']:.3f}", r["paper"]]
             for r in rows]
    table = render_table(["scenario", "profile", "goal", Column("falls", "right"),
                          Column("min h m", "right"), Column("rms pos m", "right"),
                          "the paper shows"], cells)
    return "porter paper experiments: the paper's experiments as MuJoCo scenarios\n" + table



def reproduce_experiments(names: list[str], duration_s: float | None, out: Path,
                          output: Output, profiles: list[Profile]) -> int:
    """Exit ``OK`` when every experiment ran without a fall to its scenario's expected
    outcome (a shortened run need not arrive) under every profile, else ``DIFFERS``."""
    cache = CompiledCodeCache()
    rows = [run_experiment(name, duration_s, cache, profile)
            for profile in profiles for name in names]
    output.report(format_experiments(rows))
    out.mkdir(parents=True, exist_ok=True)
    plot_experiments(rows, out / "experiments.png")
    plot_series(rows, out / "experiments_series.png")
    document = {"claim": "experiments", "profiles": profile_documents(profiles), "rows": rows}
    (out / "experiments.json").write_text(json.dumps(document) + "\n")
    output.progress(f"wrote {out / 'experiments.json'}, {out / 'experiments.png'} and "
                    f"{out / 'experiments_series.png'}")
    output.write_json(document)
    return OK if all(row["as_expected"] for row in rows) else DIFFERS
