"""The Rerun layout of a porter run: entity paths and timelines, and the default blueprint.

``deploy.viewing.rerun_view`` logs under these paths; the blueprint arranges them: the 3D team view
beside a grid of time-series views (ADMM residuals, NMPC times, NLP iterations, CBF values,
tracking errors, forces per robot, deadline misses, loop timing), with the events log and the
run's metadata below the 3D view. Units are in the entity names (``_m``, ``_s``, ``_n``).
"""

from __future__ import annotations

from collections.abc import Sequence

import rerun.blueprint as rrb

APPLICATION_ID = "porter"
SIM_TIME = "sim_time"  # duration timeline: the log time (simulated time in simulation)
ADMM_ITERATION = "admm_iteration"  # sequence timeline: one step per logged ADMM iteration

# 3D, world frame [m]
WORLD = "world"
PAYLOAD = "world/payload"  # Transform3D world -> payload; the box below it
PAYLOAD_BOX = "world/payload/box"
PAYLOAD_REFERENCE = "world/payload_reference"
COUPLINGS = "world/couplings"
OBSTACLES = "world/obstacles"  # <id> cylinders, <id>/safety_circle line strips
MOCAP = "world/mocap"  # <body> points
PAYLOAD_PLAN = "world/nmpc/payload_plan"
ROBOT_PLANS = "world/nmpc/robot_plans"
CONSENSUS_PLAN = "world/nmpc/consensus_payload_plan"


def robot_entity(robot: str, part: str = "") -> str:
    """``world/robots/<robot>[/<part>]``: parts body (Transform3D + box), foot_targets,
    contact_forces, coupling_force (measured and predicted arrows)."""
    return f"{WORLD}/robots/{robot}" + (f"/{part}" if part else "")


# time series
ADMM = "admm"  # primal_payload_rms, primal_wrench_rms (one series per agent), dual_norm
NMPC_TIMES = "nmpc/time_s"  # update, deadline, max_solve, agent_solve (per agent)
NMPC_ITERATIONS = "nmpc/iterations"  # total, per_agent
SAFETY = "safety"  # h_m (per pair), min_h_m, predicted_min_h_m, true_min_h_m
TRACKING = "tracking"  # payload_position_error_m, payload_yaw_error_rad, coupling_error_m, ...
FORCES = "forces"  # <robot>/wbc_grf_sum_n, planned_grf_sum_n, coupling_force_n
LOOP_COUNTS = "loop/counts"  # deadline_missed, deadline_misses_total, recorder_dropped
LOOP_TIMES = "loop/time_s"  # wbc_tick_max, wbc_tick_mean, wbc/<robot>
EVENTS = "events"
RUN_INFO = "run"


def blueprint(robot_names: Sequence[str] = ()) -> rrb.Blueprint:
    """3D view and events on the left, time series in a two-column grid on the right.

    With ``robot_names`` the forces get one tab per robot; without (live view, names not yet
    known) one view shows every robot's.
    """
    if robot_names:
        forces: rrb.Container | rrb.View = rrb.Tabs(
            *[rrb.TimeSeriesView(origin=f"{FORCES}/{name}", name=f"Forces {name} [N]")
              for name in robot_names], name="GRFs & wrenches")
    else:
        forces = rrb.TimeSeriesView(origin=FORCES, name="GRFs & wrenches [N]")
    series = rrb.Grid(
        rrb.TimeSeriesView(origin=ADMM, name="ADMM residuals"),
        rrb.TimeSeriesView(origin=NMPC_TIMES, name="NMPC times [s]"),
        rrb.TimeSeriesView(origin=NMPC_ITERATIONS, name="NLP iterations"),
        rrb.TimeSeriesView(origin=SAFETY, name="CBF h [m]"),
        rrb.TimeSeriesView(origin=TRACKING, name="Tracking errors [m, rad]"),
        forces,
        rrb.TimeSeriesView(origin=LOOP_COUNTS, name="Deadline misses"),
        rrb.TimeSeriesView(origin=LOOP_TIMES, name="Loop timing [s]"),
        grid_columns=2, name="Time series")
    left = rrb.Vertical(
        # origin "/": the robots' URDF models live beside "world" (one top-level entity each,
        # deploy.viewing.robot_models), placed in it through their frames
        rrb.Spatial3DView(origin="/", name="Team (world)"),
        rrb.Tabs(rrb.TextLogView(origin=EVENTS, name="Events"),
                 rrb.TextDocumentView(origin=RUN_INFO, name="Run")),
        row_shares=[3, 1])
    return rrb.Blueprint(rrb.Horizontal(left, series, column_shares=[1, 1]),
                         rrb.TimePanel(timeline=SIM_TIME), collapse_panels=False)
