"""The swing-foot set-points of one robot at one WBC tick as one CasADi function: the gait's
phase, Raibert's touchdown targets from the measured trunk (``FootholdPlanner.swing_targets``)
and the swing trajectory (``swing_point``) of every swing leg, stance legs holding their
footholds. World frame, SI units.

The same arithmetic as those NumPy functions (tested against them), written once as an
expression so that the 500 Hz tick makes one call instead of ~40 small NumPy operations per
robot (~43 µs back to back, ~100 µs at real-time pace, measured).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from core.locomotion.buffered_function import BufferedFunction, ParameterVector
from core.locomotion.gait import TROT_OFFSETS, FootholdPlanner
from core.locomotion.swing_trajectory import POLYNOMIALS
from core.model.srb_model import rotation_body_to_world

if TYPE_CHECKING:  # a protocol only; the NMPC package need not load
    from core.nmpc.nlp_solver import NlpCompiler

__all__ = ["SwingTargets"]

_FEET = 4


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
