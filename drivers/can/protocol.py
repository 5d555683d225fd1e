"""Porter's own CAN layout (DBC-like) for the e-stop heartbeat and the coupling F/T sensors.

The hardware is custom, so the layout is ours. Classic CAN 2.0A: 11-bit identifiers, no
remote frames, data little-endian, exact DLC required.

| frame | id | dlc | bytes |
|---|---|---|---|
| e-stop heartbeat | 0x010 | 2 | 0: counter u8 (+1 per frame, wraps); 1: state u8 (0 run, 1 stopped) |
| F/T force, sensor i | 0x200 + 2 i | 8 | 0-5: fx, fy, fz int16 [0.01 N]; 6: sample u8; 7: flags u8 |
| F/T torque, sensor i | 0x201 + 2 i | 8 | 0-5: tx, ty, tz int16 [0.001 N m]; 6: sample u8; 7: flags |

- F/T sensors i = 0 .. 15, one per robot (the order of the robot names given to the reader).
  One sample is two frames carrying the same sample counter; a reading is complete when both
  halves with one counter have arrived.
- Ranges: force +-327.67 N (0.01 N steps), torque +-32.767 N m (0.001 N m steps). Values
  beyond are saturated to +-32767 counts and flag bit 0 (saturated) is set; -32768 is never
  sent and is rejected as invalid. Other flag bits are reserved (sent 0, ignored).
- The wrench is the one robot i's coupling applies to the payload: force, and torque about the
  coupling point, in the sensor frame, which is taken as world-aligned for now (the fakes
  send ``TeamSimulation.coupling_wrench``, world frame); a body-fixed sensor will need the
  rotation applied in the reader.

Decoding raises ``CanFrameError`` (a ``ValueError``) naming what was expected.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass
from enum import IntEnum

import can
import numpy as np

ESTOP_HEARTBEAT_ID = 0x010
ESTOP_HEARTBEAT_DLC = 2
FORCE_TORQUE_BASE_ID = 0x200
FORCE_TORQUE_DLC = 8
MAX_SENSORS = 16
FORCE_RESOLUTION_N = 0.01
TORQUE_RESOLUTION_NM = 0.001
SATURATED_FLAG = 0x01
_COUNT_LIMIT = 32767
_INVALID_COUNT = -32768
_HALF = struct.Struct("<3hBB")


class EstopState(IntEnum):
    RUN = 0
    STOPPED = 1


class CanFrameError(ValueError):
    """A CAN frame that does not fit porter's layout; ``reason`` is a short tag for counting
    ("id", "frame type", "length", "state", "value", "counter", "sensor")."""

    def __init__(self, message: str, reason: str) -> None:
        super().__init__(message)
        self.reason = reason


@dataclass(frozen=True)
class EstopHeartbeat:
    counter: int
    state: EstopState


@dataclass(frozen=True)
class WrenchHalf:
    """One of the two frames of an F/T sample: ``is_force`` says which; ``values`` is force [N]
    or torque [N m] (3,), sensor frame."""

    sensor_index: int
    is_force: bool
    values: np.ndarray
    sample_counter: int
    saturated: bool


def _check_shape(message: can.Message, dlc: int, what: str) -> None:
    if message.is_extended_id or message.is_remote_frame or message.is_error_frame:
        raise CanFrameError(f"{what}: expected a standard data frame, got id "
                            f"0x{message.arbitration_id:x} extended={message.is_extended_id} "
                            f"remote={message.is_remote_frame} error={message.is_error_frame}",
                            "frame type")
    if message.dlc != dlc or len(message.data) != dlc:
        raise CanFrameError(f"{what}: expected {dlc} data bytes, got {len(message.data)}",
                            "length")


# --- e-stop -------------------------------------------------------------------------------
def encode_estop_heartbeat(counter: int, state: EstopState) -> can.Message:
    return can.Message(arbitration_id=ESTOP_HEARTBEAT_ID, is_extended_id=False,
                       data=bytes([counter & 0xFF, int(state)]))


def decode_estop_heartbeat(message: can.Message) -> EstopHeartbeat:
    if message.arbitration_id != ESTOP_HEARTBEAT_ID:
        raise CanFrameError(f"e-stop heartbeat: expected id 0x{ESTOP_HEARTBEAT_ID:03x}, got "
                            f"0x{message.arbitration_id:x}", "id")
    _check_shape(message, ESTOP_HEARTBEAT_DLC, "e-stop heartbeat")
    counter, state = message.data[0], message.data[1]
    if state not in (EstopState.RUN, EstopState.STOPPED):
        raise CanFrameError(f"e-stop heartbeat: state must be 0 (run) or 1 (stopped), got {state}",
                            "state")
    return EstopHeartbeat(counter, EstopState(state))


# --- force/torque ---------------------------------------------------------------------------
def is_force_torque_id(arbitration_id: int) -> bool:
    """Whether ``arbitration_id`` lies in the F/T block (0x200 .. 0x21f)."""
    return FORCE_TORQUE_BASE_ID <= arbitration_id < FORCE_TORQUE_BASE_ID + 2 * MAX_SENSORS


def encode_wrench(sensor_index: int, force_n: np.ndarray, torque_nm: np.ndarray,
                  sample_counter: int) -> tuple[can.Message, can.Message]:
    """The force and torque frames of one sample, saturated to the ranges above."""
    if not 0 <= sensor_index < MAX_SENSORS:
        raise ValueError(f"sensor index {sensor_index} outside 0 .. {MAX_SENSORS - 1}")
    messages = []
    for offset, values, resolution in ((0, force_n, FORCE_RESOLUTION_N),
                                       (1, torque_nm, TORQUE_RESOLUTION_NM)):
        counts = np.rint(np.asarray(values, dtype=float).reshape(3) / resolution)
        saturated = bool((np.abs(counts) > _COUNT_LIMIT).any() or not np.isfinite(counts).all())
        counts = np.clip(np.nan_to_num(counts), -_COUNT_LIMIT, _COUNT_LIMIT).astype(int)
        data = _HALF.pack(*counts, sample_counter & 0xFF, SATURATED_FLAG if saturated else 0)
        messages.append(can.Message(arbitration_id=FORCE_TORQUE_BASE_ID + 2 * sensor_index
                                    + offset, is_extended_id=False, data=data))
    return messages[0], messages[1]


def decode_wrench_half(message: can.Message) -> WrenchHalf:
    if not is_force_torque_id(message.arbitration_id):
        raise CanFrameError(f"F/T frame: id 0x{message.arbitration_id:x} outside "
                            f"0x{FORCE_TORQUE_BASE_ID:03x} .. "
                            f"0x{FORCE_TORQUE_BASE_ID + 2 * MAX_SENSORS - 1:03x}", "id")
    _check_shape(message, FORCE_TORQUE_DLC, "F/T frame")
    *counts, sample_counter, flags = _HALF.unpack(bytes(message.data))
    if _INVALID_COUNT in counts:
        raise CanFrameError(f"F/T frame 0x{message.arbitration_id:x}: invalid value -32768",
                            "value")
    offset = message.arbitration_id - FORCE_TORQUE_BASE_ID
    is_force = offset % 2 == 0
    resolution = FORCE_RESOLUTION_N if is_force else TORQUE_RESOLUTION_NM
    return WrenchHalf(offset // 2, is_force, np.array(counts, dtype=float) * resolution,
                      sample_counter, bool(flags & SATURATED_FLAG))
