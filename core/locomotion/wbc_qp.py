"""The WBC's QP of one robot assembled by one CasADi function: all four feet, the swing feet's
forces pinned to zero, so its size never changes with the gait.

``core.locomotion.whole_body_control`` documents the QP. Built as NumPy operations per tick it
cost ~70 small operations per robot, a few µs each (~0.15 ms per robot back to back, 2-3x that
in the loop's cold ticks); here the whole assembly (base PD target with its SO(3) log, swing
tasks, friction, dynamics, stance and torque rows, bounds) is one SX function evaluated
through CasADi's buffer interface into preallocated arrays: the inputs are views into one
parameter vector that the caller fills, the outputs land in arrays DAQP takes as they are.

Fixed size: x = (f of the 4 feet [N], qdd [18]). A swing foot's force is bounded to [0, 0] as
an equality, its friction and stance rows are left unbounded, its planned force is ignored: the
QP's unique minimizer is the one of the QP over the stance feet only (the pinned forces enter
no other row with a non-zero value), so the torques are those of the variable-size QP up to
the solver's round-off (tested against it).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import casadi as ca
import numpy as np

from core.locomotion.buffered_function import BufferedFunction, ParameterVector
from core.locomotion.settings import WbcSettings
from core.model.srb_model import rotation_body_to_world

if TYPE_CHECKING:  # a protocol only; the NMPC package need not load
    from core.nmpc.nlp_solver import NlpCompiler

__all__ = ["WbcQpArrays", "WbcQpAssembly", "so3_log"]

_INF = 1e30  # DAQP's "no bound"
_EQUALITY = 5  # DAQP constraint sense: equality
FEET = 4
FORCES = 3 * FEET
VELOCITIES = 18  # free flyer (6) + 12 joints
JOINTS = VELOCITIES - 6
FRICTION_ROWS = 4 * FEET
CONSTRAINT_ROWS = FRICTION_ROWS + 6 + FORCES + JOINTS  # friction, dynamics, stance, torque
TORQUE_ROWS = slice(CONSTRAINT_ROWS - JOINTS, CONSTRAINT_ROWS)
VARIABLES = FORCES + VELOCITIES


def so3_log(rotation: ca.SX) -> ca.SX:
    """log(R) as a rotation vector [rad] (Pinocchio's ``log3`` for angles below pi - 1e-3; at
    pi itself the axis is ill-defined from the skew part and this returns a shorter vector:
    the WBC never sees a 180 degree trunk error, the supervisor stops far earlier)."""
    skew = 0.5 * ca.vertcat(rotation[2, 1] - rotation[1, 2], rotation[0, 2] - rotation[2, 0],
                            rotation[1, 0] - rotation[0, 1])  # sin(angle) * axis
    cosine = 0.5 * (rotation[0, 0] + rotation[1, 1] + rotation[2, 2] - 1.0)
    sine = ca.norm_2(skew)
    angle = ca.atan2(sine, cosine)
    scale = ca.if_else(sine < 1e-9, 1.0 + angle * angle / 6.0, angle / ca.fmax(sine, 1e-300))
    return scale * skew


@dataclass(frozen=True)
class WbcQpArrays:
    """The QP DAQP solves, as preallocated arrays the assembly writes into: ``hessian``
    (30, 30), ``gradient`` (30,), ``constraint`` (46, 30) C-ordered, ``upper`` / ``lower``
    (58,): the 12 force bounds, then the constraint rows. Torques = ``constraint[TORQUE_ROWS] @
    x + bias[6:]``."""

    hessian: np.ndarray
    gradient: np.ndarray
    constraint: np.ndarray
    upper: np.ndarray
    lower: np.ndarray


class WbcQpAssembly:
    """One robot's QP assembly. Fill the input ``views`` (``mass`` ... ``wrench_on_robot``), call
    ``assemble()``, read ``arrays``; ``sense(stance)`` gives DAQP's constraint senses.

    Inputs (world frame unless said): ``mass`` (18, 18) Pinocchio's M (upper triangle used),
    ``bias`` (18,) its nonlinear effects, ``contact_jacobian`` (12, 18) the feet's linear
    LOCAL_WORLD_ALIGNED Jacobian rows, ``foot_drift`` (12,) their classical accelerations at
    qdd = 0, ``foot_frame`` (12,) the foot frames' positions, ``velocity`` (18,) Pinocchio's v,
    ``rotation`` (3, 3) base to world, ``base_position``, ``base_velocity`` (world),
    ``angular_velocity_in_body``, and the target's ``com_position`` ... ``wrench_on_robot``
    (as ``WbcTarget``, feet flattened leg-major; ``stance`` 1.0 / 0.0).
    """

    def __init__(self, settings: WbcSettings, com_offset_in_base_m: np.ndarray,
                 coupling_in_base_m: np.ndarray, foot_radius_m: float,
                 torque_limit_nm: np.ndarray, compiler: NlpCompiler | None = None,
                 jacobian_pattern: np.ndarray | None = None,
                 mass_pattern: np.ndarray | None = None) -> None:
        """``compiler``: evaluate the assembly as compiled C from this cache; None: the SX
        function (same outputs bit for bit, tested). ``jacobian_pattern`` (12, 18) and
        ``mass_pattern`` (18, 18): where the feet's Jacobian rows and the mass matrix can be
        non-zero (the kinematic tree's structure; ``structural_patterns``); the assembly
        reads only those entries, which halves its operations (a foot's Jacobian touches 9
        of the 18 velocities). None: dense."""
        parameters = ParameterVector([
            ("mass", VELOCITIES, VELOCITIES), ("bias", VELOCITIES, 1),
            ("contact_jacobian", FORCES, VELOCITIES), ("foot_drift", FORCES, 1),
            ("foot_frame", FORCES, 1), ("velocity", VELOCITIES, 1), ("rotation", 3, 3),
            ("base_position", 3, 1), ("base_velocity", 3, 1), ("angular_velocity_in_body", 3, 1),
            ("com_position", 3, 1), ("com_velocity", 3, 1), ("com_acceleration", 3, 1),
            ("euler", 3, 1), ("angular_velocity", 3, 1), ("angular_acceleration", 3, 1),
            ("stance", FEET, 1), ("planned_grf", FORCES, 1), ("foot_position", FORCES, 1),
            ("foot_velocity", FORCES, 1), ("foot_acceleration", FORCES, 1),
            ("wrench_on_robot", 6, 1)])
        self.views = parameters.views
        inputs = dict(parameters.symbols)
        for name, pattern in (("contact_jacobian", jacobian_pattern), ("mass", mass_pattern)):
            if pattern is not None:
                nonzero_rows, nonzero_cols = np.nonzero(pattern)
                inputs[name] = ca.project(inputs[name], ca.Sparsity.triplet(
                    int(pattern.shape[0]), int(pattern.shape[1]), nonzero_rows.tolist(),
                    nonzero_cols.tolist()))
        outputs = _qp_expressions(inputs, settings, com_offset_in_base_m, coupling_in_base_m,
                                  foot_radius_m, np.asarray(torque_limit_nm, dtype=float))
        self.arrays = WbcQpArrays(np.zeros((VARIABLES, VARIABLES)), np.zeros(VARIABLES),
                                  np.zeros((CONSTRAINT_ROWS, VARIABLES)),
                                  np.zeros(FORCES + CONSTRAINT_ROWS),
                                  np.zeros(FORCES + CONSTRAINT_ROWS))
        # the constraint output is A^T column-major, i.e. A row-major (C order), as DAQP reads
        self._function = BufferedFunction(
            "wbc_qp", parameters, list(outputs),
            [self.arrays.hessian, self.arrays.gradient, self.arrays.constraint,
             self.arrays.upper, self.arrays.lower], compiler)
        self._senses = [_sense(pattern) for pattern in range(1 << FEET)]

    @property
    def compiled(self) -> bool:
        """Whether the assembly runs as compiled C (else in CasADi's SX virtual machine)."""
        return self._function.compiled

    def assemble(self) -> WbcQpArrays:
        """Evaluate the QP for the inputs as filled now (no allocation)."""
        self._function.evaluate()
        return self.arrays

    def sense(self, stance: np.ndarray) -> np.ndarray:
        """DAQP's senses for the stance flags (FL, FR, RL, RR): swing forces pinned (equality
        bounds), dynamics and stance rows of stance feet equalities."""
        pattern = sum(1 << leg for leg in range(FEET) if stance[leg])
        return self._senses[pattern]


def _sense(pattern: int) -> np.ndarray:
    sense = np.zeros(FORCES + CONSTRAINT_ROWS, dtype=np.int32)
    dynamics = FORCES + FRICTION_ROWS
    sense[dynamics:dynamics + 6] = _EQUALITY
    for leg in range(FEET):
        in_stance = bool(pattern >> leg & 1)
        if not in_stance:
            sense[3 * leg:3 * leg + 3] = _EQUALITY  # force pinned at zero
        else:
            row = dynamics + 6 + 3 * leg
            sense[row:row + 3] = _EQUALITY  # the stance foot stays still
    return sense


def _qp_expressions(p: dict[str, ca.SX], s: WbcSettings, com_offset_in_base_m: np.ndarray,
                    coupling_in_base_m: np.ndarray, foot_radius_m: float,
                    torque_limit_nm: np.ndarray) -> tuple[ca.SX, ...]:
    upper_part = ca.triu(p["mass"])
    mass = upper_part + ca.triu(p["mass"], False).T  # Pinocchio fills the upper triangle
    bias, jacobian, velocity = p["bias"], p["contact_jacobian"], p["velocity"]
    rotation, stance = p["rotation"], p["stance"]
    swing = 1.0 - stance

    # Base task: PD on the planned trunk plus its feed-forward (free-flyer acceleration in the
    # base frame, Pinocchio's spatial convention).
    rotation_desired = rotation_body_to_world(p["euler"])
    offset_desired = rotation_desired @ com_offset_in_base_m
    position_desired = p["com_position"] - offset_desired
    velocity_desired = p["com_velocity"] - ca.cross(p["angular_velocity"], offset_desired)
    omega = rotation @ p["angular_velocity_in_body"]
    linear = (p["com_acceleration"]
              + np.asarray(s.base_position_gain) * (position_desired - p["base_position"])
              + np.asarray(s.base_velocity_gain) * (velocity_desired - p["base_velocity"]))
    angular = (p["angular_acceleration"]
               + np.asarray(s.base_orientation_gain) * so3_log(rotation_desired @ rotation.T)
               + np.asarray(s.base_angular_velocity_gain) * (p["angular_velocity"] - omega))
    # classical -> spatial linear acceleration in the base frame: a_s = a_c - w x v
    linear_local = rotation.T @ linear - ca.cross(velocity[3:6], velocity[0:3])
    base_acceleration = ca.vertcat(linear_local, rotation.T @ angular)

    # Cost 0.5 x'Hx + g'x; x = (f, qdd).
    hessian_forces = (s.regularization + s.force_weight) * ca.SX.eye(FORCES)
    hessian_motion = s.regularization * ca.SX.eye(VELOCITIES)
    hessian_motion[0:6, 0:6] += s.base_weight * ca.SX.eye(6)
    gradient_motion = ca.vertcat(-s.base_weight * base_acceleration, ca.SX.zeros(JOINTS))
    for leg in range(FEET):
        rows = slice(3 * leg, 3 * leg + 3)
        leg_jacobian = jacobian[rows, :]
        foot_velocity = leg_jacobian @ velocity
        lift = np.array([0.0, 0.0, foot_radius_m])
        desired = (p["foot_acceleration"][rows]
                   + s.swing_position_gain * (p["foot_position"][rows] + lift
                                              - p["foot_frame"][rows])
                   + s.swing_velocity_gain * (p["foot_velocity"][rows] - foot_velocity))
        weighted = (s.swing_weight * swing[leg]) * leg_jacobian.T
        hessian_motion += weighted @ leg_jacobian
        gradient_motion -= weighted @ (desired - p["foot_drift"][rows])
    stance_per_force = ca.repmat(stance.T, 3, 1).reshape((FORCES, 1))
    gradient_forces = -s.force_weight * stance_per_force * p["planned_grf"]
    hessian = ca.blockcat([[hessian_forces, ca.SX.zeros(FORCES, VELOCITIES)],
                           [ca.SX.zeros(VELOCITIES, FORCES), hessian_motion]])
    gradient = ca.vertcat(gradient_forces, gradient_motion)

    # Constraint rows: friction (4 per foot), floating-base dynamics, stance feet, torques.
    mu = s.friction_coefficient
    pyramid = np.array([[1.0, 0.0, -mu], [-1.0, 0.0, -mu], [0.0, 1.0, -mu], [0.0, -1.0, -mu]])
    friction = ca.SX.zeros(FRICTION_ROWS, VARIABLES)
    for leg in range(FEET):
        friction[4 * leg:4 * leg + 4, 3 * leg:3 * leg + 3] = pyramid
    dynamics = ca.horzcat(-jacobian[:, 0:6].T, mass[0:6, :])
    stance_rows = ca.horzcat(ca.SX.zeros(FORCES, FORCES), jacobian)
    torque_rows = ca.horzcat(-jacobian[:, 6:].T, mass[6:, :])
    constraint = ca.vertcat(friction, dynamics, stance_rows, torque_rows)

    wrench = p["wrench_on_robot"]
    lever = rotation @ coupling_in_base_m
    base_force = ca.vertcat(rotation.T @ wrench[0:3],
                            rotation.T @ (wrench[3:6] + ca.cross(lever, wrench[0:3])))
    drift_rhs = -p["foot_drift"] - s.stance_velocity_damping * (jacobian @ velocity)
    force_upper = ca.vertcat(*[ca.vertcat(_INF, _INF, s.max_normal_force_n) * stance[leg]
                               for leg in range(FEET)])
    force_lower = ca.vertcat(*[ca.vertcat(-_INF, -_INF, s.min_normal_force_n) * stance[leg]
                               for leg in range(FEET)])
    friction_upper = ca.vertcat(*[ca.if_else(stance[leg], 0.0, _INF) * ca.SX.ones(4)
                                  for leg in range(FEET)])
    unbounded = _INF * ca.SX.ones(FORCES)
    stance_upper = ca.if_else(stance_per_force, drift_rhs, unbounded)
    stance_lower = ca.if_else(stance_per_force, drift_rhs, -unbounded)
    upper = ca.vertcat(force_upper, friction_upper, base_force - bias[0:6], stance_upper,
                       torque_limit_nm - bias[6:])
    lower = ca.vertcat(force_lower, -_INF * ca.SX.ones(FRICTION_ROWS), base_force - bias[0:6],
                       stance_lower, -torque_limit_nm - bias[6:])
    return hessian, gradient, constraint.T, upper, lower
