"""Unitree A1 low-level UDP messages (unitree_legged_sdk 3.3.x): packed LowCmd / LowState.

``#pragma pack(1)`` structs, little-endian, laid out with ``struct`` (sizes asserted below):

- LowCmd (730 bytes): levelFlag u8, commVersion u16, robotID u16, SN u32, bandWidth u8,
  motorCmd[20] {mode u8, q, dq, tau, Kp, Kd f32, reserve[3] u32}, led[4] {r, g, b u8},
  wirelessRemote[40] u8, reserve u32, crc u32.
- LowState (891 bytes): levelFlag, commVersion, robotID, SN, bandWidth, imu {quaternion[4]
  (w, x, y, z), gyroscope[3] [rad/s], accelerometer[3] [m/s^2], rpy[3] [rad] f32,
  temperature i8}, motorState[20] {mode u8, q, dq, ddq, tauEst, q_raw, dq_raw, ddq_raw f32,
  temperature i8, reserve[2] u32}, footForce[4] i16, footForceEst[4] i16, tick u32,
  wirelessRemote[40] u8, reserve u32, crc u32.

Values are carried as ``drivers.unitree.conventions`` ``WireCommand`` / ``WireState`` (20
motor slots in Unitree order, SI units). The CRC is a replaceable ``crc`` argument (bytes ->
u32). UNVERIFIED default: the A1's CRC lives in a closed library; we assume it is the Go2's
CRC-32 over all u32 words but the last (``len // 4 - 1`` words from the start), stored in
the final 4 bytes.
"""

from __future__ import annotations

import struct
from collections.abc import Callable

import numpy as np

from drivers.unitree.conventions import (
    MOTOR_SLOT_COUNT,
    WireCommand,
    WireState,
    unitree_crc32_of_packed,
)

LEVEL_FLAG_LOW = 0xFF
MOTOR_MODE_SERVO = 0x0A
MOTOR_MODE_BRAKE = 0x00
_HEADER = "BHHIB"
_MOTOR_CMD = "B5f3I"
_MOTOR_STATE = "B7fb2I"
_IMU = "4f3f3f3fb"
LOW_CMD = struct.Struct("<" + _HEADER + _MOTOR_CMD * 20 + "12B" + "40B" + "II")
LOW_STATE = struct.Struct("<" + _HEADER + _IMU + _MOTOR_STATE * 20 + "4h4h" + "I" + "40B" + "II")
LOW_CMD_SIZE = 730
LOW_STATE_SIZE = 891
assert LOW_CMD.size == LOW_CMD_SIZE, LOW_CMD.size
assert LOW_STATE.size == LOW_STATE_SIZE, LOW_STATE.size

Crc = Callable[[bytes], int]
default_crc: Crc = unitree_crc32_of_packed


class LayoutError(ValueError):
    """A datagram is not a well-formed A1 message (size or CRC)."""


def _with_crc(packed: bytes, crc: Crc) -> bytes:
    return packed[:-4] + struct.pack("<I", crc(packed))


def _check(data: bytes, size: int, crc: Crc, what: str) -> None:
    if len(data) != size:
        raise LayoutError(f"{what}: expected {size} bytes, got {len(data)}")
    expected = crc(data)
    received = struct.unpack_from("<I", data, size - 4)[0]
    if received != expected:
        raise LayoutError(f"{what}: crc 0x{received:08x}, expected 0x{expected:08x}")


def encode_low_cmd(wire: WireCommand, crc: Crc = default_crc) -> bytes:
    """The 730-byte LowCmd datagram of ``wire`` (levelFlag 0xFF, CRC filled in)."""
    values: list[int | float] = [LEVEL_FLAG_LOW, 0, 0, 0, 0]
    for i in range(MOTOR_SLOT_COUNT):
        values += [int(wire.mode[i]), float(wire.q_rad[i]), float(wire.dq_rad_s[i]),
                   float(wire.tau_nm[i]), float(wire.kp[i]), float(wire.kd[i]), 0, 0, 0]
    values += [0] * 12 + [0] * 40 + [0, 0]
    return _with_crc(LOW_CMD.pack(*values), crc)


def decode_low_cmd(data: bytes, crc: Crc = default_crc) -> tuple[int, WireCommand]:
    """(levelFlag, command) of a LowCmd datagram; ``LayoutError`` on a bad size or CRC."""
    _check(data, LOW_CMD_SIZE, crc, "A1 LowCmd")
    values = LOW_CMD.unpack(data)
    motors = np.array(values[5:5 + 9 * MOTOR_SLOT_COUNT], dtype=float).reshape(-1, 9)
    return int(values[0]), WireCommand(
        mode=motors[:, 0].astype(np.uint8), q_rad=motors[:, 1], dq_rad_s=motors[:, 2],
        tau_nm=motors[:, 3], kp=motors[:, 4], kd=motors[:, 5])


def encode_low_state(state: WireState, motor_mode: int = MOTOR_MODE_SERVO,
                     crc: Crc = default_crc) -> bytes:
    """The 891-byte LowState datagram of ``state`` (what the robot answers with)."""
    values: list[int | float] = [LEVEL_FLAG_LOW, 0, 0, 0, 0]
    values += [float(v) for v in (*state.quaternion_wxyz, *state.gyroscope_rad_s,
                                  *state.accelerometer_m_s2, *state.rpy_rad)]
    values.append(0)  # IMU temperature
    for i in range(MOTOR_SLOT_COUNT):
        values += [motor_mode, float(state.q_rad[i]), float(state.dq_rad_s[i]), 0.0,
                   float(state.tau_est_nm[i]), 0.0, 0.0, 0.0, 0, 0, 0]
    foot_force = [int(v) for v in state.foot_force]
    values += foot_force + foot_force + [int(state.tick_ms) & 0xFFFFFFFF] + [0] * 40 + [0, 0]
    return _with_crc(LOW_STATE.pack(*values), crc)


def decode_low_state(data: bytes, crc: Crc = default_crc) -> tuple[int, WireState]:
    """(levelFlag, state) of a LowState datagram; ``LayoutError`` on a bad size or CRC."""
    _check(data, LOW_STATE_SIZE, crc, "A1 LowState")
    values = LOW_STATE.unpack(data)
    imu = np.array(values[5:18], dtype=float)
    start = 19
    motors = np.array(values[start:start + 11 * MOTOR_SLOT_COUNT], dtype=float).reshape(-1, 11)
    rest = values[start + 11 * MOTOR_SLOT_COUNT:]
    return int(values[0]), WireState(
        q_rad=motors[:, 1], dq_rad_s=motors[:, 2], tau_est_nm=motors[:, 4],
        quaternion_wxyz=imu[0:4], gyroscope_rad_s=imu[4:7], accelerometer_m_s2=imu[7:10],
        rpy_rad=imu[10:13], foot_force=np.array(rest[0:4], dtype=np.int16),
        tick_ms=int(rest[8]))
