"""The small driver interface the control loop talks to, in simulation and on robots alike.

World frame (z up), SI units. Quaternions are (w, x, y, z) and rotate body vectors into the
world frame. Per-joint arrays have 12 entries in ``core.model.conventions.LEG_JOINT_NAMES``
order, FL, FR, RL, RR x (hip, thigh, calf); per-foot arrays have 4 entries in
``core.model.conventions.LEG_NAMES`` order. Backends map their own orders (e.g. Unitree's
FR, FL, RR, RL motor order) to these by name, once, inside the driver.

The control loop (``deploy.runtime.loop``) sees only these protocols: ``RobotDriver`` per robot,
a ``MocapSource``, an ``EstopSource`` and optionally ``WrenchSensors``; the real links
(``drivers.unitree``, ``drivers.natnet``, ``drivers.can``) and the in-process simulation
(``drivers.mujoco``) implement them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np

from core.model.conventions import JOINT_COUNT

_COMMAND_FIELDS = ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd")
_JOINT_SHAPE = (JOINT_COUNT,)


def _zeros_12() -> np.ndarray:
    return np.zeros(JOINT_COUNT)


@dataclass
class JointCommand:
    """Per-joint motor command, applied by the motor firmware law at its own (high) rate:

        tau = torque_nm + kp (position_rad - q) + kd (velocity_rad_s - dq)

    clipped to the motor's torque limit. kp [N m/rad], kd [N m s/rad]. The default (all zero)
    is a limp robot.
    """

    torque_nm: np.ndarray = field(default_factory=_zeros_12)
    position_rad: np.ndarray = field(default_factory=_zeros_12)
    velocity_rad_s: np.ndarray = field(default_factory=_zeros_12)
    kp: np.ndarray = field(default_factory=_zeros_12)
    kd: np.ndarray = field(default_factory=_zeros_12)

    def __post_init__(self) -> None:
        for name in _COMMAND_FIELDS:
            value = getattr(self, name)
            # Fast path (every tick builds several): already a float (12,) array, copied so
            # the command owns its data.
            if type(value) is np.ndarray and value.shape == _JOINT_SHAPE and value.dtype == float:
                setattr(self, name, value.copy())
            else:
                setattr(self, name, np.broadcast_to(np.asarray(value, dtype=float),
                                                    _JOINT_SHAPE).copy())

    @classmethod
    def hold(cls, position_rad: np.ndarray, kp: float, kd: float) -> JointCommand:
        """Joint PD holding ``position_rad`` at zero velocity with no feed-forward torque."""
        return cls(position_rad=position_rad, kp=np.full(JOINT_COUNT, kp),
                   kd=np.full(JOINT_COUNT, kd))

    def torque_for(self, position_rad: np.ndarray, velocity_rad_s: np.ndarray) -> np.ndarray:
        """Firmware law at joint state (q [rad], dq [rad/s]) -> motor torque [N m], unclipped."""
        return (self.torque_nm + self.kp * (self.position_rad - position_rad)
                + self.kd * (self.velocity_rad_s - velocity_rad_s))


@dataclass(frozen=True)
class RobotMeasurement:
    """One robot's state as its onboard sensors (joint encoders, IMU, state estimate) give it.

    The base is the URDF root link (the trunk). ``linear_velocity_in_world_m_s`` is the base
    origin's velocity in the world frame; ``angular_velocity_in_body_rad_s`` is in the base
    frame (what an IMU gyroscope measures). Foot contact: ``foot_normal_force_n`` is the
    ground's normal force on each foot [N], ``foot_contact`` whether it is positive.
    """

    time_s: float
    position_rad: np.ndarray  # (12,)
    velocity_rad_s: np.ndarray  # (12,)
    torque_nm: np.ndarray  # (12,) motor torque applied in the last control period
    position_in_world_m: np.ndarray  # (3,)
    quaternion_wxyz: np.ndarray  # (4,) base -> world
    linear_velocity_in_world_m_s: np.ndarray  # (3,)
    angular_velocity_in_body_rad_s: np.ndarray  # (3,)
    foot_contact: np.ndarray  # (4,) bool
    foot_normal_force_n: np.ndarray  # (4,)


Pose = tuple[np.ndarray, np.ndarray]  # (position_m (3,), quaternion_wxyz (4,)) in world


@dataclass(frozen=True)
class MocapFrame:
    """Motion-capture poses of rigid bodies at ``time_s``: name -> (position [m], quaternion
    wxyz), world frame."""

    time_s: float
    poses: dict[str, Pose]


@dataclass(frozen=True)
class EstopStatus:
    """Whether the e-stop allows running, and why not."""

    run_allowed: bool
    reason: str


@dataclass(frozen=True)
class WrenchReading:
    """One robot's measured coupling wrench: force [N] and torque about the coupling point
    [N m] its coupling applies to the payload, sensor frame (world-aligned for now)."""

    force_n: np.ndarray
    torque_nm: np.ndarray
    sample_counter: int
    saturated: bool
    receive_time_s: float


@runtime_checkable
class RobotDriver(Protocol):
    """One robot: read its sensors, send its joint command (kept until the next one)."""

    @property
    def name(self) -> str: ...

    def read(self) -> RobotMeasurement:
        """The newest state; raises ``drivers.link_errors.LinkLostError`` when it is stale."""
        ...

    def send(self, command: JointCommand) -> None: ...

    def send_damping(self, kd: float) -> None:
        """The stop command: position loops off, tau = kd [N m s/rad] (0 - dq)."""
        ...

    def close(self) -> None:
        """Release the link (sockets, DDS entities); the robot keeps its firmware's timeout."""
        ...


@runtime_checkable
class MocapSource(Protocol):
    """A motion-capture system: the most recent frame (None before the first one) and how
    long ago it arrived [s]."""

    def latest(self) -> MocapFrame | None: ...

    def age_s(self) -> float:
        """Seconds since the newest frame arrived (inf before the first one)."""
        ...


@runtime_checkable
class EstopSource(Protocol):
    """The e-stop: run is allowed only while it says so."""

    def status(self) -> EstopStatus: ...


@runtime_checkable
class WrenchSensors(Protocol):
    """Coupling force/torque sensors: the newest complete sample per robot name."""

    def latest(self) -> dict[str, WrenchReading]: ...
