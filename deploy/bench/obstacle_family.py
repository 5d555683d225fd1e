"""``porter bench obstacles``: the team against obstacles it cannot simply pass, in MuJoCo.

A family of scenarios built here (not shipped as files): an obstacle **crossing** the path at
0.1-0.3 m/s so that it reaches the path where the front robot will be; an obstacle coming
**head-on** down the path (0.1 m off the line); a static obstacle **exactly on** the reference
line (the symmetric case). Teams of 2-4 Go2 on a ring, payloads of 5-12 kg. Each case runs to
its end (or its stop) and reports how it ended: the outcome (goal, ran out of time, controlled
stop, safe stop), falls, the minimum h of any body, how many plans relaxed their safety
constraints and by how much, and when braking began.

``baseline=True`` runs the same cases with the behaviour before infeasibility handling: hard
barriers, no braking backup, no reference governor.
"""

from __future__ import annotations

import math

from core.nmpc.settings import BrakingSettings, MpcSettings, SafetySettings
from deploy.cli.conventions import Output, error
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import Scenario
from deploy.reports.table import Column, render_table
from deploy.runtime.sim_run import SimRun

__all__ = ["family", "format_table", "run_bench", "run_case"]

_COUPLING_IN_ROBOT_M = [0.0, 0.0, 0.1343]  # Go2
_RINGS = {
    2: [(0.55, 0.0), (-0.55, 0.0)],
    3: [(0.55, 0.0), (-0.275, 0.4763), (-0.275, -0.4763)],
    4: [(0.55, 0.0), (0.0, 0.55), (-0.55, 0.0), (0.0, -0.55)],
}
FRONT_M = 0.55  # the front robot's coupling point ahead of the payload centre


def _scenario(name: str, robots: int, mass_kg: float, speed_m_s: float,
              obstacle: dict, length_m: float) -> Scenario:
    team = [{"name": f"go2_{i}", "robot_type": "go2", "coupling_point_in_payload_m": [x, y, 0.0],
             "coupling_point_in_robot_m": _COUPLING_IN_ROBOT_M}
            for i, (x, y) in enumerate(_RINGS[robots])]
    return Scenario.model_validate({
        "name": name, "description": f"porter bench obstacles: {name}", "team": team,
        "payload": {"mass_kg": mass_kg},
        "reference": {"waypoints_m": [[0.0, 0.0], [length_m, 0.0]], "speed_m_s": speed_m_s},
        "obstacles": [obstacle], "safety_distance_m": 0.6,
        "duration_s": math.ceil(length_m / speed_m_s) + 2.0})


def crossing(robots: int, mass_kg: float, obstacle_speed_m_s: float,
             team_speed_m_s: float = 0.2, start_y_m: float = 1.6) -> Scenario:
    """An obstacle (radius 0.15 m) crossing the path from the right; it reaches the path where
    the front robot will be at that time on the reference (at most 2.4 m out)."""
    x = min(FRONT_M + team_speed_m_s * start_y_m / obstacle_speed_m_s, 2.4)
    return _scenario(f"cross_{robots}r_{mass_kg:g}kg_{obstacle_speed_m_s:g}", robots, mass_kg,
                     team_speed_m_s, {"position_m": [round(x, 3), -start_y_m],
                                      "radius_m": 0.15,
                                      "velocity_m_s": [0.0, obstacle_speed_m_s]}, 2.6)


def head_on(robots: int, mass_kg: float, obstacle_speed_m_s: float,
            team_speed_m_s: float = 0.2) -> Scenario:
    """An obstacle (radius 0.15 m) coming down the path from 3.6 m, 0.1 m off the line."""
    return _scenario(f"headon_{robots}r_{mass_kg:g}kg_{obstacle_speed_m_s:g}", robots, mass_kg,
                     team_speed_m_s, {"position_m": [3.6, 0.1], "radius_m": 0.15,
                                      "velocity_m_s": [-obstacle_speed_m_s, 0.0]}, 2.6)


def symmetric(robots: int, mass_kg: float) -> Scenario:
    """A static obstacle (radius 0.15 m) exactly on the reference line at 1.8 m."""
    return _scenario(f"symmetric_{robots}r_{mass_kg:g}kg", robots, mass_kg, 0.3,
                     {"position_m": [1.8, 0.0], "radius_m": 0.15}, 3.6)


def family() -> list[Scenario]:
    """The cases, in table order."""
    return [
        crossing(2, 5.0, 0.1, team_speed_m_s=0.3), crossing(2, 12.0, 0.3),
        crossing(3, 8.0, 0.2), crossing(3, 12.0, 0.3), crossing(4, 8.0, 0.2),
        head_on(2, 5.0, 0.2, team_speed_m_s=0.3), head_on(3, 8.0, 0.3), head_on(4, 12.0, 0.1),
        symmetric(2, 5.0), symmetric(3, 8.0),
    ]


def baseline_settings() -> MpcSettings:
    """MpcSettings of the behaviour before: hard barriers and no braking (the governor is the
    scenario's, switched off in ``run_case``)."""
    return MpcSettings(safety=SafetySettings(soft_barriers=False),
                       braking=BrakingSettings(enabled=False))


def run_case(scenario: Scenario, cache: CompiledCodeCache, baseline: bool = False) -> dict:
    """Run one case with the serial ADMM executor; its summary plus ``robots`` and
    ``outcome``."""
    base: MpcSettings | None = None
    if baseline:
        base = baseline_settings()
        scenario = scenario.model_copy(update={"reference": scenario.reference.model_copy(
            update={"max_lag_m": None})})
    scenario = scenario.model_copy(update={"controller": scenario.controller.model_copy(
        update={"executor": "serial"})})
    run = SimRun(scenario, cache, base)
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
    summary["robots"] = len(scenario.team)
    return summary


def format_table(rows: list[dict]) -> str:
    cells = []
    for row in rows:
        safety = row["safety"]
        braking = safety.get("braking_since_s")
        cells.append([row["scenario"], str(row["robots"]), f"{row['duration_s']:.1f}",
                      row["outcome"], f"{row['min_h_m']:.3f}", str(row.get("relaxed_plans", 0)),
                      f"{row.get('max_barrier_slack_m', 0.0):.4f}",
                      "-" if braking is None else f"{braking:.2f}",
                      (safety["safe_stop"] or "")[:70]])
    return render_table(
        ["case", Column("n", "right"), Column("sim s", "right"), "outcome",
         *(Column(name, "right") for name in ("min h [m]", "relaxed", "max slack [m]",
                                              "braking [s]")), "stop cause"], cells,
        ["min h: ground truth, every body against every obstacle (< 0: inside the margin); "
         "relaxed: plans whose soft barriers used slack"])



def run_bench(names: list[str], baseline: bool, out: Output) -> int:
    """``porter bench obstacles``: run the cases named (default all), print the table."""
    cases = [case for case in family() if not names or case.name in names]
    unknown = set(names) - {case.name for case in family()}
    if unknown:
        return error(f"bench obstacles: unknown cases {sorted(unknown)}; choose from "
                     f"{[case.name for case in family()]}")
    out.progress(f"porter bench obstacles: {len(cases)} cases" + (
        " with the baseline (hard barriers, no braking, no governor)" if baseline else ""))
    cache = CompiledCodeCache()
    rows = []
    for case in cases:
        rows.append(run_case(case, cache, baseline=baseline))
        out.progress(f"  {case.name}: {rows[-1]['outcome']}")
    out.report(format_table(rows))
    out.write_json({"rows": rows})
    return 0
