"""Unitree wire conventions (Go2 over DDS, A1 over UDP) and their one conversion to ours.

Unitree motor order: FR, FL, RR, RL x (hip, thigh, calf) in the first 12 of 20 motor slots;
per-foot arrays (``foot_force``) in the same leg order. Ours (``drivers.interfaces``): FL, FR,
RL, RR. Both maps are built by joint / leg name. The Unitree IMU quaternion is (w, x, y, z),
body -> world, like ours and MuJoCo's: no reordering. Gyroscope [rad/s] and accelerometer
[m/s^2] are in the body frame. Foot forces are raw int16 sensor counts; the scale to newtons
is a parameter (UNVERIFIED per robot: calibrate before trusting contact forces).

``WireState`` / ``WireCommand`` hold one message in wire conventions (20 motor slots, SI
units); the Go2 DDS types and the A1 packed structs only pack and unpack them. The CRC is
Unitree's CRC-32: polynomial 0x04C11DB7, initial 0xFFFFFFFF, no final XOR, each u32 word fed
MSB first, i.e. CRC-32/MPEG-2 over the big-endian bytes of each word.
"""

from __future__ import annotations

import math
import zlib
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from core.model.conventions import FOOT_COUNT, JOINT_COUNT, LEG_JOINT_KINDS, LEG_JOINT_NAMES, LEG_NAMES
from drivers.interfaces import JointCommand, RobotMeasurement

MOTOR_SLOT_COUNT = 20
UNITREE_LEG_ORDER = ("FR", "FL", "RR", "RL")
UNITREE_JOINT_NAMES = tuple(f"{leg}_{kind}_joint" for leg in UNITREE_LEG_ORDER
                            for kind in LEG_JOINT_KINDS)
# ours[j] = wire[WIRE_SLOT_OF_JOINT[j]]; ours[f] = wire_feet[WIRE_FOOT_OF_FOOT[f]]
WIRE_SLOT_OF_JOINT = np.array([UNITREE_JOINT_NAMES.index(n) for n in LEG_JOINT_NAMES])
WIRE_FOOT_OF_FOOT = np.array([UNITREE_LEG_ORDER.index(leg) for leg in LEG_NAMES])
# Unitree's "loop off" sentinels: a target q of PosStopF disables the position loop, a target dq
# of VelStopF the velocity loop.
POS_STOP_F = 2.146e9
VEL_STOP_F = 16000.0
# Plausibility bounds of a received leg state (far outside any Go2/A1 motion).
MAX_JOINT_ANGLE_RAD = 10.0
MAX_JOINT_SPEED_RAD_S = 200.0
MAX_JOINT_TORQUE_NM = 500.0
MAX_BODY_RATE_RAD_S = 100.0
QUATERNION_NORM_TOLERANCE = 0.05
STANDARD_GRAVITY_M_S2 = 9.80665


_INT16_MIN, _INT16_MAX = int(np.iinfo(np.int16).min), int(np.iinfo(np.int16).max)


def _slots(values: np.ndarray | None = None) -> np.ndarray:
    """Our (12,) per-joint values in a (20,) wire-slot array (zero in unused slots)."""
    wire = np.zeros(MOTOR_SLOT_COUNT)
    if values is not None:
        wire[WIRE_SLOT_OF_JOINT] = values
    return wire


@dataclass
class WireState:
    """One Unitree low-level state in wire conventions. Per-slot arrays (20,) in Unitree motor
    order: joint angle [rad], speed [rad/s], estimated torque [N m]; IMU quaternion wxyz (body ->
    world), gyroscope [rad/s] and accelerometer [m/s^2] in body, rpy [rad]; raw foot force
    counts (4,) in FR, FL, RR, RL order; robot tick [ms]."""

    q_rad: np.ndarray = field(default_factory=_slots)
    dq_rad_s: np.ndarray = field(default_factory=_slots)
    tau_est_nm: np.ndarray = field(default_factory=_slots)
    quaternion_wxyz: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0, 0.0]))
    gyroscope_rad_s: np.ndarray = field(default_factory=lambda: np.zeros(3))
    accelerometer_m_s2: np.ndarray = field(default_factory=lambda: np.zeros(3))
    rpy_rad: np.ndarray = field(default_factory=lambda: np.zeros(3))
    foot_force: np.ndarray = field(default_factory=lambda: np.zeros(FOOT_COUNT, dtype=np.int16))
    tick_ms: int = 0


@dataclass
class WireCommand:
    """One Unitree low-level command in wire conventions, per slot (20,) in Unitree motor order:
    motor mode, target q [rad], target dq [rad/s], feed-forward tau [N m], kp [N m/rad],
    kd [N m s/rad]."""

    mode: np.ndarray = field(default_factory=lambda: np.zeros(MOTOR_SLOT_COUNT, dtype=np.uint8))
    q_rad: np.ndarray = field(default_factory=_slots)
    dq_rad_s: np.ndarray = field(default_factory=_slots)
    tau_nm: np.ndarray = field(default_factory=_slots)
    kp: np.ndarray = field(default_factory=_slots)
    kd: np.ndarray = field(default_factory=_slots)


# --- state ----------------------------------------------------------------------------------
def wire_state_from_measurement(measurement: RobotMeasurement, foot_force_n_per_count: float,
                                tick_ms: int = 0) -> WireState:
    """What a Unitree robot in ``measurement``'s state would send (fakes). The accelerometer
    reads the static specific force R^T (0, 0, g) (the measurement carries no acceleration)."""
    # scalar math, not NumPy: the world process runs this per robot at 500 Hz
    w, x, y, z = (float(v) for v in measurement.quaternion_wxyz)
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    # R^T (0, 0, g) is g times R's last row, (2(xz - wy), 2(yz + wx), 1 - 2(x^2 + y^2)) / |q|^2
    g = STANDARD_GRAVITY_M_S2 / (norm * norm)
    accelerometer = np.array([2.0 * (x * z - w * y) * g, 2.0 * (y * z + w * x) * g,
                              (w * w - x * x - y * y + z * z) * g])
    counts = np.zeros(FOOT_COUNT, dtype=np.int16)
    counts[WIRE_FOOT_OF_FOOT] = np.clip(
        np.rint(measurement.foot_normal_force_n / foot_force_n_per_count),
        _INT16_MIN, _INT16_MAX)
    return WireState(
        q_rad=_slots(measurement.position_rad), dq_rad_s=_slots(measurement.velocity_rad_s),
        tau_est_nm=_slots(measurement.torque_nm),
        quaternion_wxyz=np.array([w, x, y, z]),
        gyroscope_rad_s=np.array(measurement.angular_velocity_in_body_rad_s, dtype=float),
        accelerometer_m_s2=accelerometer, rpy_rad=np.array(_rpy(w / norm, x / norm, y / norm,
                                                                 z / norm)),
        foot_force=counts, tick_ms=tick_ms)


def measurement_from_wire_state(state: WireState, time_s: float,
                                foot_force_n_per_count: float,
                                contact_threshold_n: float) -> RobotMeasurement:
    """Our measurement from a received state. Unitree robots measure no world position nor
    linear velocity: both read zero. ``time_s`` is the receive time [s]."""
    position_m, velocity_m_s = np.zeros(3), np.zeros(3)
    force_n = np.asarray(state.foot_force, dtype=float)[WIRE_FOOT_OF_FOOT] * foot_force_n_per_count
    return RobotMeasurement(
        time_s=time_s, position_rad=state.q_rad[WIRE_SLOT_OF_JOINT].astype(float),
        velocity_rad_s=state.dq_rad_s[WIRE_SLOT_OF_JOINT].astype(float),
        torque_nm=state.tau_est_nm[WIRE_SLOT_OF_JOINT].astype(float),
        position_in_world_m=position_m, quaternion_wxyz=state.quaternion_wxyz.astype(float),
        linear_velocity_in_world_m_s=velocity_m_s,
        angular_velocity_in_body_rad_s=state.gyroscope_rad_s.astype(float),
        foot_contact=force_n > contact_threshold_n, foot_normal_force_n=force_n)


# |q|, |dq|, |tau_est| of the leg motors, |gyroscope|: what a plausible state stays within
_STATE_LIMITS = np.concatenate((np.full(JOINT_COUNT, MAX_JOINT_ANGLE_RAD),
                                np.full(JOINT_COUNT, MAX_JOINT_SPEED_RAD_S),
                                np.full(JOINT_COUNT, MAX_JOINT_TORQUE_NM),
                                np.full(3, MAX_BODY_RATE_RAD_S)))


def state_problem(state: WireState) -> str | None:
    """Why a received state must be rejected (a short reason tag), or None if plausible."""
    legs = WIRE_SLOT_OF_JOINT
    # one array of every checked value against one array of limits (a few NumPy calls per
    # state instead of ~15: this runs per robot at 500 Hz)
    values = np.concatenate((state.q_rad[legs], state.dq_rad_s[legs], state.tau_est_nm[legs],
                             state.gyroscope_rad_s, state.quaternion_wxyz))
    if not np.isfinite(values).all():
        return "non-finite"
    quaternion = values[-4:]
    if ((np.abs(values[:-4]) > _STATE_LIMITS).any()
            or abs(math.sqrt(float(quaternion @ quaternion)) - 1.0) > QUATERNION_NORM_TOLERANCE):
        return "implausible"
    return None


# --- command --------------------------------------------------------------------------------
def wire_command_from_joint_command(command: JointCommand, servo_mode: int) -> WireCommand:
    """The wire command of ``command``: leg slots in ``servo_mode``, unused slots mode 0."""
    mode = np.zeros(MOTOR_SLOT_COUNT, dtype=np.uint8)
    mode[WIRE_SLOT_OF_JOINT] = servo_mode
    return WireCommand(mode=mode, q_rad=_slots(command.position_rad),
                       dq_rad_s=_slots(command.velocity_rad_s), tau_nm=_slots(command.torque_nm),
                       kp=_slots(command.kp), kd=_slots(command.kd))


def damping_wire_command(kd: float, servo_mode: int) -> WireCommand:
    """Safe stop: every leg motor damps its speed to zero (tau = kd (0 - dq)), position loop off
    (q = PosStopF, kp = 0), no feed-forward torque."""
    wire = wire_command_from_joint_command(JointCommand(kd=np.full(JOINT_COUNT, kd)), servo_mode)
    wire.q_rad[WIRE_SLOT_OF_JOINT] = POS_STOP_F
    return wire


def joint_command_from_wire_command(wire: WireCommand) -> JointCommand:
    """Our command from a received wire command (fakes). Slots with the PosStopF / VelStopF
    sentinel (or a mode other than servo, i.e. 0) get that loop switched off, as the firmware
    does; the firmware law itself is applied by the simulation."""
    legs = WIRE_SLOT_OF_JOINT
    q, dq = wire.q_rad[legs].astype(float), wire.dq_rad_s[legs].astype(float)
    kp, kd = wire.kp[legs].astype(float), wire.kd[legs].astype(float)
    position_off = np.abs(q) >= POS_STOP_F / 2
    velocity_off = np.abs(dq) >= VEL_STOP_F / 2
    q[position_off], kp[position_off] = 0.0, 0.0
    dq[velocity_off], kd[velocity_off] = 0.0, 0.0
    active = wire.mode[legs] != 0
    return JointCommand(torque_nm=np.where(active, wire.tau_nm[legs], 0.0), position_rad=q,
                        velocity_rad_s=dq, kp=np.where(active, kp, 0.0),
                        kd=np.where(active, kd, 0.0))


def command_problem(wire: WireCommand) -> str | None:
    """Why a received command must be rejected (a short reason tag), or None."""
    legs = WIRE_SLOT_OF_JOINT
    arrays = (wire.q_rad[legs], wire.dq_rad_s[legs], wire.tau_nm[legs], wire.kp[legs],
              wire.kd[legs])
    return None if all(np.isfinite(a).all() for a in arrays) else "non-finite"


# --- IMU ------------------------------------------------------------------------------------
def rpy_from_quaternion_wxyz(quaternion_wxyz: np.ndarray) -> np.ndarray:
    """Roll, pitch, yaw [rad] (Z-Y-X intrinsic, as the Unitree IMU reports) of (w, x, y, z)."""
    w, x, y, z = (float(v) for v in quaternion_wxyz)
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    return np.array(_rpy(w / norm, x / norm, y / norm, z / norm))


def _rpy(w: float, x: float, y: float, z: float) -> tuple[float, float, float]:
    """Roll, pitch, yaw [rad] of the unit quaternion (w, x, y, z)."""
    return (math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y)),
            math.asin(min(1.0, max(-1.0, 2 * (w * y - z * x)))),
            math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


# --- CRC ------------------------------------------------------------------------------------
_BIT_REVERSED_BYTE = bytes(int(f"{i:08b}"[::-1], 2) for i in range(256))


def crc32_mpeg2(data: bytes) -> int:
    """CRC-32/MPEG-2 of ``data`` (poly 0x04C11DB7, init 0xFFFFFFFF, MSB first, no final XOR).

    Computed by zlib's reflected CRC-32 over bit-reversed bytes: the reflected register is the
    bit reversal of the MPEG-2 one, and zlib's final XOR is undone.
    """
    reflected = zlib.crc32(data.translate(_BIT_REVERSED_BYTE)) ^ 0xFFFFFFFF
    return int(f"{reflected:032b}"[::-1], 2)


def unitree_crc32(words: Sequence[int] | np.ndarray) -> int:
    """Unitree's CRC-32 of u32 ``words`` (each fed MSB first)."""
    return crc32_mpeg2(np.asarray(words, dtype=np.uint32).astype(">u4").tobytes())


def unitree_crc32_of_packed(packed: bytes) -> int:
    """Unitree's CRC-32 of a packed little-endian message: over its first len // 4 - 1 u32
    words (all but the last word; the CRC field itself is not covered)."""
    return unitree_crc32(np.frombuffer(packed, dtype="<u4", count=len(packed) // 4 - 1))
