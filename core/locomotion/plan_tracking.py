"""From an NMPC plan (60 Hz) to WBC targets (500 Hz) for one robot: plan interpolation, gait
phase, lift-off and touchdown bookkeeping and swing-foot trajectories. World frame, SI units.

The plan's stage k holds at time t_plan + k Ts. Between stages the trunk set-point is linearly
interpolated, its feed-forward accelerations are the stage's finite differences (exact for the
semi-implicit Euler model: v_{k+1} = v_k + Ts a_k), and GRFs and wrenches are held (zero-order).

**Swing set-points** (``SwingTargets``): one robot's swing-foot set-points at one WBC tick as
one CasADi function: the gait's phase, Raibert's touchdown targets from the measured trunk
(``FootholdPlanner.swing_targets``) and the swing trajectory (``swing_point``) of every swing
leg, stance legs holding their footholds.

The same arithmetic as those NumPy functions (tested against them), written once as an
expression so that the 500 Hz tick makes one call instead of ~40 small NumPy operations per
robot (~43 µs back to back, ~100 µs at real-time pace, measured).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from core.locomotion.buffered_function import BufferedFunction, ParameterVector
from core.locomotion.gait import TROT_OFFSETS, FootholdPlanner, TrotGait
from core.locomotion.swing_trajectory import POLYNOMIALS
from core.locomotion.whole_body_control import WbcTarget
from core.model.srb_model import SrbParameters, rotation_body_to_world
from core.nmpc.mpc_plan import MpcPlan

if TYPE_CHECKING:  # a protocol only; the NMPC package need not load
    from core.nmpc.nlp_solver import NlpCompiler

__all__ = ["LegCoordinator", "SwingTargets", "plan_set_point", "wbc_target"]

_FEET = 4


@dataclass
class LegCoordinator:
    """Gait bookkeeping of one robot: stance flags, lift-off points, footholds, swing targets.

    Lift-off points are the measured feet when a leg leaves the ground; a landing leg's stored
    foothold becomes its measured touchdown point (on the ground), so the NMPC's lever arms are
    the real ones.
    """

    robot: SrbParameters
    gait: TrotGait
    swing_height_m: float = 0.08
    ground_height_m: float = 0.0
    planner: FootholdPlanner = field(init=False)
    liftoff_m: np.ndarray = field(default_factory=lambda: np.zeros((4, 3)))
    stance: np.ndarray = field(default_factory=lambda: np.ones(4))
    compiler: NlpCompiler | None = None  # the swing set-points as compiled C (else CasADi SX)
    _set_points: SwingTargets = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.planner = FootholdPlanner(self.robot, self.gait, ground_height_m=self.ground_height_m)
        # built (and its library loaded) here, not at the first swing: that is a tick of the
        # real-time loop, and ~10-20 ms there let the watchdog take over (measured)
        self._set_points = SwingTargets(self.planner, self.swing_height_m, self.compiler)

    def reset(self, robot_state: np.ndarray, measured_feet_m: np.ndarray) -> None:
        """Standing start: all legs in stance at their measured positions."""
        self.planner.reset(robot_state)
        self._set_feet(measured_feet_m, np.ones(4, dtype=bool))
        self.liftoff_m = np.array(measured_feet_m, dtype=float)
        self.stance = np.ones(4)

    def _set_feet(self, measured_feet_m: np.ndarray, mask: np.ndarray) -> None:
        feet = np.array(measured_feet_m, dtype=float)
        feet[:, 2] = self.ground_height_m
        self.planner.set_feet(feet, mask)

    def advance(self, time_s: float, robot_state: np.ndarray, reference_state: np.ndarray,
                measured_feet_m: np.ndarray) -> np.ndarray:
        """Move to ``time_s``; returns the (4,) stance flags now."""
        stance = self.gait.contacts(time_s)
        if np.array_equal(stance, self.stance):  # most ticks: no leg lifts or lands
            self.planner.update(time_s, robot_state, reference_state, stance)
            return stance
        lifting = (stance == 0.0) & (self.stance == 1.0)
        landing = (stance == 1.0) & (self.stance == 0.0)
        self.liftoff_m[lifting] = np.asarray(measured_feet_m)[lifting]
        self.planner.update(time_s, robot_state, reference_state, stance)
        if np.any(landing):
            self._set_feet(measured_feet_m, landing)
        self.stance = stance
        return stance

    def swing_targets(self, time_s: float, robot_state: np.ndarray,
                      velocity_reference_m_s: np.ndarray
                      ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Swing-foot contact-point position, velocity, acceleration (4, 3) each; stance legs
        hold their footholds with zero velocity. One call of ``SwingTargets`` (the arithmetic of
        ``FootholdPlanner.swing_targets`` and ``swing_point``, tested against them)."""
        return self._set_points(time_s, robot_state, velocity_reference_m_s, self.liftoff_m,
                                self.planner.feet_in_world_m, self.stance)


def plan_set_point(plan: MpcPlan, agent: int, elapsed_s: float, sample_period_s: float
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Robot ``agent``'s planned state (12,) interpolated ``elapsed_s`` after the plan's start,
    its acceleration (linear, angular) (6,), and the held GRFs (4, 3) and wrench on the payload
    (6,) of the current stage."""
    trajectory = plan.robot_trajectories[agent]
    steps = plan.grf_trajectories.shape[1]
    position = max(elapsed_s, 0.0) / sample_period_s
    k = min(int(position), steps - 1)
    fraction = min(position - k, 1.0)
    state = (1.0 - fraction) * trajectory[k] + fraction * trajectory[k + 1]
    derivative = (trajectory[k + 1] - trajectory[k]) / sample_period_s
    acceleration = np.concatenate([derivative[3:6], derivative[9:12]])
    grf = plan.grf_trajectories[agent, k].reshape(4, 3)
    wrench = plan.wrench_trajectories[agent, k]
    return state, acceleration, grf, wrench


def wbc_target(plan: MpcPlan, agent: int, elapsed_s: float, sample_period_s: float,
               stance: np.ndarray, feet: tuple[np.ndarray, np.ndarray, np.ndarray]) -> WbcTarget:
    """The WBC target of robot ``agent``: its interpolated plan, the gait's ``stance`` flags and
    the swing-foot ``feet`` (position, velocity, acceleration)."""
    state, acceleration, grf, wrench = plan_set_point(plan, agent, elapsed_s, sample_period_s)
    return WbcTarget(
        com_position_m=state[0:3], com_velocity_m_s=state[3:6],
        com_acceleration_m_s2=acceleration[0:3], euler_rad=state[6:9],
        angular_velocity_rad_s=state[9:12], angular_acceleration_rad_s2=acceleration[3:6],
        stance=np.asarray(stance, dtype=bool), planned_grf_n=grf,
        foot_position_m=feet[0], foot_velocity_m_s=feet[1], foot_acceleration_m_s2=feet[2],
        wrench_on_robot=-np.asarray(wrench),
    )


class SwingTargets:
    """One robot's swing-foot set-points. ``__call__(time_s, robot_state, velocity_reference,
    liftoff, footholds, stance)`` -> (position, velocity, acceleration), (4, 3) each.

    ``planner``: the robot's Raibert planner (its gait, neutral feet, gain and ground height
    are built in); ``swing_height_m``: apex above the lift-off / touchdown line [m]."""

    def __init__(self, planner: FootholdPlanner, swing_height_m: float,
                 compiler: NlpCompiler | None = None) -> None:
        parameters = ParameterVector([
            ("time", 1, 1), ("robot_state", 12, 1), ("velocity_reference", 3, 1),
            ("liftoff", _FEET, 3), ("footholds", _FEET, 3), ("stance", _FEET, 1)])
        self._views = parameters.views
        outputs = _set_point_expressions(parameters.symbols, planner, swing_height_m)
        # each output (3, 4), a column per leg, column-major: a leg's x, y, z after another,
        # i.e. a (4, 3) array row-major
        self._results = [np.zeros((_FEET, 3)) for _ in range(3)]
        self._function = BufferedFunction("swing_targets", parameters, outputs,
                                          self._results, compiler)

    @property
    def compiled(self) -> bool:
        """Whether the set-points run as compiled C (else in CasADi's SX virtual machine)."""
        return self._function.compiled

    def __call__(self, time_s: float, robot_state: np.ndarray, velocity_reference: np.ndarray,
                 liftoff_m: np.ndarray, footholds_m: np.ndarray, stance: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        views = self._views
        views["time"][0] = time_s
        views["robot_state"][:] = robot_state
        views["velocity_reference"][:] = velocity_reference
        views["liftoff"][:] = liftoff_m
        views["footholds"][:] = footholds_m
        views["stance"][:] = stance
        self._function.evaluate()
        position, velocity, acceleration = (result.copy() for result in self._results)
        return position, velocity, acceleration


def _set_point_expressions(p: dict[str, ca.SX], planner: FootholdPlanner,
                           swing_height_m: float) -> list[ca.SX]:
    gait = planner.gait
    state, reference = p["robot_state"], p["velocity_reference"]
    velocity = state[3:6]
    neutral = planner.robot.nominal_feet_in_body_m
    if neutral is None:
        neutral = planner.robot.hip_positions_in_body_m
    rotation = rotation_body_to_world(ca.vertcat(0.0, 0.0, state[8]))  # Rz(yaw), as yaw_rotation
    raibert = reference * gait.stance_duration_s / 2 + planner.velocity_gain * (velocity
                                                                               - reference)
    scale = np.array([1.0, 1.0 / gait.swing_duration_s, gait.swing_duration_s**-2.0] * 2)
    rows: list[list[ca.SX]] = [[], [], []]
    for leg in range(_FEET):
        phase = ca.fmod(p["time"] / gait.period_s + TROT_OFFSETS[leg], 1.0)
        swinging = phase >= gait.duty_factor
        lead = ca.if_else(swinging, (1.0 - phase) * gait.period_s, 0.0)
        progress = ca.if_else(swinging, (phase - gait.duty_factor) / (1.0 - gait.duty_factor),
                              0.0)
        target = (state[0:3] + lead * velocity) + rotation @ ca.DM(neutral[leg]) + raibert
        target[2] = planner.ground_height_m
        s = ca.fmin(ca.fmax(progress, 0.0), 1.0)
        powers = ca.vertcat(*[s**k for k in range(POLYNOMIALS.shape[0])])
        values = (ca.DM(POLYNOMIALS.T) @ powers) * ca.DM(scale)  # m, dm, ddm, b, db, ddb
        start = p["liftoff"][leg, :].T
        delta = target - start
        lift = ca.vertcat(0.0, 0.0, swing_height_m)
        in_stance = p["stance"][leg]
        motion = [start + delta * values[0] + lift * values[3], delta * values[1]
                  + lift * values[4], delta * values[2] + lift * values[5]]
        held = [p["footholds"][leg, :].T, ca.SX.zeros(3), ca.SX.zeros(3)]
        for order in range(3):
            rows[order].append(ca.if_else(in_stance, held[order], motion[order]))
    return [ca.horzcat(*row) for row in rows]  # (3, 4): column = leg
