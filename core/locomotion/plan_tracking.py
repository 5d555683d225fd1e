"""From an NMPC plan (60 Hz) to WBC targets (500 Hz) for one robot: plan interpolation, gait
phase, lift-off and touchdown bookkeeping and swing-foot trajectories. World frame, SI units.

The plan's stage k holds at time t_plan + k Ts. Between stages the trunk set-point is linearly
interpolated, its feed-forward accelerations are the stage's finite differences (exact for the
semi-implicit Euler model: v_{k+1} = v_k + Ts a_k), and GRFs and wrenches are held (zero-order).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from core.locomotion.gait import FootholdPlanner, TrotGait
from core.locomotion.swing_targets import SwingTargets
from core.locomotion.whole_body_control import WbcTarget
from core.model.srb_model import SrbParameters
from core.nmpc.mpc_plan import MpcPlan

if TYPE_CHECKING:  # a protocol only
    from core.nmpc.nlp_solver import NlpCompiler


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
