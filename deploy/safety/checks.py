"""The safety supervisor's fault predicates: settings, per-robot limits and pure checks.

Each ``*_fault`` function looks at one kind of input and returns ``None`` when it is fine or a
cause text naming the fault, the robot (and joint), the value and the limit, e.g.
``"MoCap lost: no frame for 0.153 s (timeout 0.1 s)"``. They do no I/O and keep no state, except
the two small counters of NMPC health (``SolverFailureCounter``, ``DeadlineOverrunWindow``).
``deploy.safety.supervisor`` decides which checks apply in which state and what a fault does.

Units: SI; joint arrays in ``core.model.conventions.LEG_JOINT_NAMES`` order; quaternions wxyz
(``drivers.interfaces``).
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, fields, replace
from functools import cache

import numpy as np
import pinocchio as pin

from core.model.conventions import JOINT_COUNT, LEG_JOINT_NAMES, LEG_NAMES
from core.model.robot_parameters import leg_joint_indices
from deploy.safety.settings import SupervisorSettings
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.robot_descriptions import (
    FOOT_RADIUS_M,
    load_pinocchio_model,
    standing_configuration,
)

_QUATERNION_NORM_TOLERANCE = 0.1  # |norm - 1| beyond this is no rotation a sensor would report
_TORQUE_TOLERANCE_NM = 1e-9  # a command exactly at the limit is allowed
_MEASUREMENT_FIELDS = tuple(field.name for field in fields(RobotMeasurement))


@dataclass
class RobotLimits:
    """One robot's limits, arrays (12,) in ``LEG_JOINT_NAMES`` order. ``nominal_height_m`` is
    the standing height of the base origin (URDF root link, what ``RobotMeasurement``
    reports) above the ground [m]."""

    name: str
    lower_position_rad: np.ndarray
    upper_position_rad: np.ndarray
    torque_nm: np.ndarray
    nominal_height_m: float

    def __post_init__(self) -> None:
        for name in ("lower_position_rad", "upper_position_rad", "torque_nm"):
            value = np.asarray(getattr(self, name), dtype=float)
            if value.shape != (JOINT_COUNT,) or not np.isfinite(value).all():
                raise ValueError(f"{self.name}: {name} must be {JOINT_COUNT} finite values, "
                                 f"got {value}")
            setattr(self, name, value.copy())
        if np.any(self.lower_position_rad >= self.upper_position_rad):
            raise ValueError(f"{self.name}: lower joint limits must be below the upper ones")
        if np.any(self.torque_nm <= 0.0) or not self.nominal_height_m > 0.0:
            raise ValueError(f"{self.name}: torque limits and nominal height must be positive")


@cache
def _urdf_limits(robot_type: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    model = load_pinocchio_model(robot_type)  # raises UnknownRobotError for unknown types
    q_indices, v_indices = leg_joint_indices(model)
    q = standing_configuration(robot_type, model)
    q[0:7] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # base at the origin, level (xyzw)
    data = model.createData()
    pin.framesForwardKinematics(model, data, q)
    lowest_foot_m = min(data.oMf[model.getFrameId(f"{leg}_foot")].translation[2]
                        for leg in LEG_NAMES) - FOOT_RADIUS_M[robot_type]
    return (model.lowerPositionLimit[q_indices].copy(), model.upperPositionLimit[q_indices].copy(),
            model.effortLimit[v_indices].copy(), float(-lowest_foot_m))


def robot_limits(robot_type: str, name: str) -> RobotLimits:
    """Limits of robot ``name`` of type ``robot_type`` from its URDF (Pinocchio): joint position
    and effort limits, and the base height above the ground in the SRDF standing pose."""
    lower, upper, torque, height_m = _urdf_limits(robot_type)
    return RobotLimits(name, lower, upper, torque, height_m)


# --- faults of one robot's measurement ----------------------------------------------------
def non_finite_fault(name: str, measurement: RobotMeasurement) -> str | None:
    """The first NaN/inf entry of any field of ``measurement``."""
    # axis None flattens every field (scalars too) in one call: no ravel per field
    everything = np.concatenate([getattr(measurement, name) for name in _MEASUREMENT_FIELDS],
                                axis=None, dtype=float)
    if np.isfinite(everything).all():  # the common case: one check
        return None
    for field in fields(measurement):
        value = np.asarray(getattr(measurement, field.name), dtype=float)
        bad = ~np.isfinite(value)
        if bad.any():
            index = int(np.flatnonzero(bad)[0])
            where = f"[{index}]" if value.ndim else ""
            return (f"non-finite measurement: {name} {field.name}{where} = "
                    f"{value.ravel()[index]}")
    return None


def _norm(quaternion_wxyz: np.ndarray) -> float:
    # in Python floats: np.linalg.norm costs ~5 µs a call on the 500 Hz path (~1 µs this)
    w, x, y, z = np.asarray(quaternion_wxyz, dtype=float).tolist()
    return math.sqrt(w * w + x * x + y * y + z * z)


def tilt_rad(quaternion_wxyz: np.ndarray, norm: float | None = None) -> float:
    """Angle [rad] between the base z-axis and the world z-axis (quaternion base -> world);
    ``norm``: the quaternion's norm when already at hand."""
    norm = _norm(quaternion_wxyz) if norm is None else norm
    _, x, y, _ = np.asarray(quaternion_wxyz, dtype=float).tolist()
    x, y = x / norm, y / norm
    return math.acos(min(1.0, max(-1.0, 1.0 - 2.0 * (x * x + y * y))))


def orientation_fault(name: str, measurement: RobotMeasurement,
                      settings: SupervisorSettings) -> str | None:
    """Not a rotation, or the trunk tilted beyond ``max_tilt_rad``."""
    norm = _norm(measurement.quaternion_wxyz)
    if not abs(norm - 1.0) <= _QUATERNION_NORM_TOLERANCE:  # NaN too (caught before, anyway)
        return f"implausible base quaternion: {name} norm {norm:.3f} (expected 1)"
    tilt = tilt_rad(measurement.quaternion_wxyz, norm)
    if tilt > settings.max_tilt_rad:
        return f"tilt: {name} trunk tilted {tilt:.3f} rad (max {settings.max_tilt_rad} rad)"
    return None


def base_height_fault(limits: RobotLimits, measurement: RobotMeasurement,
                      settings: SupervisorSettings) -> str | None:
    """Base lower than ``min_base_height_fraction`` of the nominal standing height."""
    height_m = float(measurement.position_in_world_m[2])
    lowest_m = settings.min_base_height_fraction * limits.nominal_height_m
    if height_m < lowest_m:
        return (f"base height: {limits.name} base at {height_m:.3f} m, below {lowest_m:.3f} m "
                f"({settings.min_base_height_fraction} of nominal {limits.nominal_height_m:.3f} m)")
    return None


def joint_velocity_fault(name: str, measurement: RobotMeasurement,
                         settings: SupervisorSettings) -> str | None:
    """Fastest joint beyond ``max_joint_velocity_rad_s``."""
    speeds = np.abs(measurement.velocity_rad_s)
    worst = int(np.argmax(speeds))
    if speeds[worst] > settings.max_joint_velocity_rad_s:
        return (f"joint velocity: {name} {LEG_JOINT_NAMES[worst]} at "
                f"{measurement.velocity_rad_s[worst]:.2f} rad/s "
                f"(max {settings.max_joint_velocity_rad_s} rad/s)")
    return None


def joint_position_fault(limits: RobotLimits, measurement: RobotMeasurement,
                         settings: SupervisorSettings) -> str | None:
    """First joint outside [lower - margin, upper + margin]."""
    margin = settings.joint_limit_margin_rad
    q = measurement.position_rad
    outside = (q < limits.lower_position_rad - margin) | (q > limits.upper_position_rad + margin)
    if not outside.any():
        return None
    i = int(np.flatnonzero(outside)[0])
    return (f"joint position limit: {limits.name} {LEG_JOINT_NAMES[i]} at {q[i]:.3f} rad, "
            f"outside [{limits.lower_position_rad[i]:.3f}, {limits.upper_position_rad[i]:.3f}]"
            f" rad (margin {margin} rad)")


def torque_fault(limits: RobotLimits, command: JointCommand, measurement: RobotMeasurement,
                 settings: SupervisorSettings) -> str | None:
    """Commanded torque (feed-forward + PD at the measured state) beyond the allowed fraction
    of the effort limit, or not finite."""
    tau = command.torque_for(measurement.position_rad, measurement.velocity_rad_s)
    allowed = settings.torque_limit_fraction * limits.torque_nm
    bad = ~np.isfinite(tau) | (np.abs(tau) > allowed + _TORQUE_TOLERANCE_NM)
    if not bad.any():
        return None
    i = int(np.flatnonzero(bad)[0])
    return (f"commanded torque: {limits.name} {LEG_JOINT_NAMES[i]} {tau[i]:.2f} N m beyond "
            f"{allowed[i]:.2f} N m ({settings.torque_limit_fraction} of limit "
            f"{limits.torque_nm[i]} N m)")


# --- faults of the system ------------------------------------------------------------------
def mocap_fault(age_s: float | None, settings: SupervisorSettings,
                require_frame: bool) -> str | None:
    """Newest MoCap frame older than the timeout; no frame at all counts only with
    ``require_frame``."""
    if age_s is None:
        return "MoCap lost: no frame received yet" if require_frame else None
    if not age_s <= settings.mocap_timeout_s:  # also NaN
        return f"MoCap lost: no frame for {age_s:.3f} s (timeout {settings.mocap_timeout_s} s)"
    return None


class SolverFailureCounter:
    """Consecutive failed NMPC updates; a successful update resets the count."""

    def __init__(self, max_consecutive_failures: int) -> None:
        self.max_consecutive_failures = max_consecutive_failures
        self.consecutive_failures = 0

    def update(self, failed: bool | None) -> str | None:
        """Count one update (``None``: no update finished this tick)."""
        if failed is None:
            return None
        self.consecutive_failures = self.consecutive_failures + 1 if failed else 0
        if self.consecutive_failures > self.max_consecutive_failures:
            return (f"NMPC solver failed {self.consecutive_failures} consecutive updates "
                    f"(max {self.max_consecutive_failures})")
        return None


class WbcFailureCounter:
    """Consecutive failed WBC QPs per robot; a solved tick resets that robot's count."""

    def __init__(self, max_consecutive_failures: int) -> None:
        self.max_consecutive_failures = max_consecutive_failures
        self.consecutive: dict[str, int] = {}
        self.failed_ticks = 0  # every failed QP of the run, all robots

    def update(self, name: str, success: bool, status: int) -> str | None:
        """Count one WBC tick of robot ``name`` (``status``: the QP solver's exit flag)."""
        count = 0 if success else self.consecutive.get(name, 0) + 1
        self.consecutive[name] = count
        self.failed_ticks += int(not success)
        if count > self.max_consecutive_failures:
            return (f"WBC failed: {name}'s QP failed {count} consecutive ticks (status "
                    f"{status}; max {self.max_consecutive_failures})")
        return None


class DeadlineOverrunWindow:
    """Overruns (NMPC deadlines, or loop ticks with ``what``) in the last ``window_s``
    seconds, i.e. at times in (t - window_s, t]; more than ``budget`` of them is a fault."""

    def __init__(self, budget: int, window_s: float,
                 what: str = "NMPC deadline overruns") -> None:
        self.budget = budget
        self.window_s = window_s
        self.what = what
        self._overrun_times_s: deque[float] = deque()

    @property
    def count(self) -> int:
        """Overruns in the window as of the last update."""
        return len(self._overrun_times_s)

    def update(self, time_s: float, missed: bool | None) -> str | None:
        """Count one update (``None``: no update finished this tick) at ``time_s``."""
        times = self._overrun_times_s
        if missed:
            times.append(time_s)
        while times and times[0] <= time_s - self.window_s:
            times.popleft()
        if len(times) > self.budget:
            return (f"{self.what}: {len(times)} within {self.window_s} s "
                    f"(budget {self.budget})")
        return None


def clip_torque(command: JointCommand, measurement: RobotMeasurement, limit_nm: np.ndarray,
                margin: float) -> JointCommand:
    """``command`` with its feed-forward trimmed so that the firmware law's torque at the
    measured state stays within ``limit_nm`` (as the motor would clip it), when that torque is
    at most ``margin`` (a fraction) past the limit; else ``command`` itself (the same object):
    within the limit nothing changes, and further past it the supervisor's torque fault stops
    the team. The WBC's own torques respect the limits, but its damping term ``kd (qdd dt)``
    can push the sum just past them; a posture move's PD starting on a leg in mid-swing
    (sit-down) brakes it with kd (0 - dq)."""
    total = command.torque_for(measurement.position_rad, measurement.velocity_rad_s)
    clipped = np.clip(total, -limit_nm, limit_nm)
    if np.array_equal(clipped, total) or not np.all(np.abs(total) <= (1.0 + margin) * limit_nm):
        return command
    return replace(command, torque_nm=command.torque_nm + clipped - total)
