# mypy: disable-error-code="type-arg, valid-type, arg-type, attr-defined, misc"
"""Unitree Go2 DDS message types, field for field as Unitree's IDL (``unitree_go.msg.dds_``).

A real robot only understands these if type names, field order and field types match
Unitree's exactly: ``@annotate.final``, ``@annotate.autoid("sequential")``, fixed-size arrays,
IDL order (see ``shared/reference/HARDWARE.md``). The motion-switcher request / response
types (``unitree_api.msg.dds_``) follow ``unitree_sdk2``'s generic API client.

Conversion to and from the robot-neutral wire values of ``drivers.unitree.conventions``
(``WireState``, ``WireCommand``: 20 motor slots in Unitree order, SI units) happens here;
``low_cmd_crc`` packs a ``LowCmd_`` as the firmware does (812 bytes) and runs Unitree's
CRC-32 over its first 202 u32 words; ``low_state_crc`` does the same for a ``LowState_`` (1180
bytes, 294 words), as unitree_sdk2_python's ``utils/crc.py`` packs it.

No ``from __future__ import annotations`` here: cyclonedds resolves the field annotations at
run time and cannot parse them back from strings. Without cyclonedds' mypy plugin
(``cyclonedds.idl.mypy_plugin``, which reads ``types.array[T, n]`` as ``Sequence[T]``) mypy
rejects these annotations, hence the error codes disabled above for this file only; every
construction of and access to these types lives in this module for that reason.
"""

import struct
from dataclasses import dataclass

import cyclonedds.idl.annotations as annotate
import cyclonedds.idl.types as types
import numpy as np
from cyclonedds.idl import IdlStruct

from drivers.unitree.conventions import MOTOR_SLOT_COUNT, WireCommand, WireState, unitree_crc32

HEAD = (0xFE, 0xEF)
LEVEL_FLAG_LOW = 0xFF
MOTOR_MODE_SERVO = 0x01
LOW_CMD_CRC_FORMAT = "<4B4IH2x" + "B3x5f3I" * 20 + "4B" + "55Bx2I"
LOW_CMD_CRC_WORDS = 202
assert struct.calcsize(LOW_CMD_CRC_FORMAT) == 812 == 4 * (LOW_CMD_CRC_WORDS + 1)
# The LowState_ as unitree_sdk2_python's utils/crc.py packs it for its CRC (1180 bytes, the
# in-memory layout); the same CRC-32 over all words but the crc field.
LOW_STATE_CRC_FORMAT = ("<4B4IH2x" + "13fb3x" + "B3x7fb3x3I" * 20 + "4BiH4b15H"
                        + "8hI41B3xf2b2x2f4h2I")
LOW_STATE_CRC_WORDS = 294
assert struct.calcsize(LOW_STATE_CRC_FORMAT) == 1180 == 4 * (LOW_STATE_CRC_WORDS + 1)


@dataclass
@annotate.final
@annotate.autoid("sequential")
class MotorCmd_(IdlStruct, typename="unitree_go.msg.dds_.MotorCmd_"):  # noqa: N801
    mode: types.uint8
    q: types.float32
    dq: types.float32
    tau: types.float32
    kp: types.float32
    kd: types.float32
    reserve: types.array[types.uint32, 3]


@dataclass
@annotate.final
@annotate.autoid("sequential")
class MotorState_(IdlStruct, typename="unitree_go.msg.dds_.MotorState_"):  # noqa: N801
    mode: types.uint8
    q: types.float32
    dq: types.float32
    ddq: types.float32
    tau_est: types.float32
    q_raw: types.float32
    dq_raw: types.float32
    ddq_raw: types.float32
    temperature: types.uint8
    lost: types.uint32
    reserve: types.array[types.uint32, 2]


@dataclass
@annotate.final
@annotate.autoid("sequential")
class IMUState_(IdlStruct, typename="unitree_go.msg.dds_.IMUState_"):  # noqa: N801
    quaternion: types.array[types.float32, 4]  # w, x, y, z; body -> world
    gyroscope: types.array[types.float32, 3]  # rad/s, body
    accelerometer: types.array[types.float32, 3]  # m/s^2, body
    rpy: types.array[types.float32, 3]  # rad
    temperature: types.uint8


@dataclass
@annotate.final
@annotate.autoid("sequential")
class BmsCmd_(IdlStruct, typename="unitree_go.msg.dds_.BmsCmd_"):  # noqa: N801
    off: types.uint8
    reserve: types.array[types.uint8, 3]


@dataclass
@annotate.final
@annotate.autoid("sequential")
class BmsState_(IdlStruct, typename="unitree_go.msg.dds_.BmsState_"):  # noqa: N801
    version_high: types.uint8
    version_low: types.uint8
    status: types.uint8
    soc: types.uint8
    current: types.int32
    cycle: types.uint16
    bq_ntc: types.array[types.uint8, 2]
    mcu_ntc: types.array[types.uint8, 2]
    cell_vol: types.array[types.uint16, 15]


@dataclass
@annotate.final
@annotate.autoid("sequential")
class LowCmd_(IdlStruct, typename="unitree_go.msg.dds_.LowCmd_"):  # noqa: N801
    head: types.array[types.uint8, 2]
    level_flag: types.uint8
    frame_reserve: types.uint8
    sn: types.array[types.uint32, 2]
    version: types.array[types.uint32, 2]
    bandwidth: types.uint16
    motor_cmd: types.array[MotorCmd_, 20]
    bms_cmd: BmsCmd_
    wireless_remote: types.array[types.uint8, 40]
    led: types.array[types.uint8, 12]
    fan: types.array[types.uint8, 2]
    gpio: types.uint8
    reserve: types.uint32
    crc: types.uint32


@dataclass
@annotate.final
@annotate.autoid("sequential")
class LowState_(IdlStruct, typename="unitree_go.msg.dds_.LowState_"):  # noqa: N801
    head: types.array[types.uint8, 2]
    level_flag: types.uint8
    frame_reserve: types.uint8
    sn: types.array[types.uint32, 2]
    version: types.array[types.uint32, 2]
    bandwidth: types.uint16
    imu_state: IMUState_
    motor_state: types.array[MotorState_, 20]
    bms_state: BmsState_
    foot_force: types.array[types.int16, 4]  # raw sensor counts
    foot_force_est: types.array[types.int16, 4]
    tick: types.uint32  # ms
    wireless_remote: types.array[types.uint8, 40]
    bit_flag: types.uint8
    adc_reel: types.float32
    temperature_ntc1: types.uint8
    temperature_ntc2: types.uint8
    power_v: types.float32
    power_a: types.float32
    fan_frequency: types.array[types.uint16, 4]
    reserve: types.uint32
    crc: types.uint32


# --- motion switcher (unitree_api generic request / response) ------------------------------
@dataclass
@annotate.final
@annotate.autoid("sequential")
class RequestIdentity_(IdlStruct, typename="unitree_api.msg.dds_.RequestIdentity_"):  # noqa: N801
    id: types.int64
    api_id: types.int64


@dataclass
@annotate.final
@annotate.autoid("sequential")
class RequestLease_(IdlStruct, typename="unitree_api.msg.dds_.RequestLease_"):  # noqa: N801
    id: types.int64


@dataclass
@annotate.final
@annotate.autoid("sequential")
class RequestPolicy_(IdlStruct, typename="unitree_api.msg.dds_.RequestPolicy_"):  # noqa: N801
    priority: types.int32
    noreply: bool


@dataclass
@annotate.final
@annotate.autoid("sequential")
class RequestHeader_(IdlStruct, typename="unitree_api.msg.dds_.RequestHeader_"):  # noqa: N801
    identity: RequestIdentity_
    lease: RequestLease_
    policy: RequestPolicy_


@dataclass
@annotate.final
@annotate.autoid("sequential")
class Request_(IdlStruct, typename="unitree_api.msg.dds_.Request_"):  # noqa: N801
    header: RequestHeader_
    parameter: str
    binary: types.sequence[types.uint8]


@dataclass
@annotate.final
@annotate.autoid("sequential")
class ResponseStatus_(IdlStruct, typename="unitree_api.msg.dds_.ResponseStatus_"):  # noqa: N801
    code: types.int32


@dataclass
@annotate.final
@annotate.autoid("sequential")
class ResponseHeader_(IdlStruct, typename="unitree_api.msg.dds_.ResponseHeader_"):  # noqa: N801
    identity: RequestIdentity_
    status: ResponseStatus_


@dataclass
@annotate.final
@annotate.autoid("sequential")
class Response_(IdlStruct, typename="unitree_api.msg.dds_.Response_"):  # noqa: N801
    header: ResponseHeader_
    data: str
    binary: types.sequence[types.uint8]


# --- conversions ----------------------------------------------------------------------------
def low_cmd_from_wire(wire: WireCommand) -> LowCmd_:
    """A low-level ``LowCmd_`` (head 0xFE 0xEF, level_flag 0xFF) of ``wire``, CRC filled in."""
    motors = [MotorCmd_(mode=int(wire.mode[i]), q=float(wire.q_rad[i]),
                        dq=float(wire.dq_rad_s[i]), tau=float(wire.tau_nm[i]),
                        kp=float(wire.kp[i]), kd=float(wire.kd[i]), reserve=[0, 0, 0])
              for i in range(MOTOR_SLOT_COUNT)]
    cmd = LowCmd_(head=list(HEAD), level_flag=LEVEL_FLAG_LOW, frame_reserve=0, sn=[0, 0],
                  version=[0, 0], bandwidth=0, motor_cmd=motors,
                  bms_cmd=BmsCmd_(off=0, reserve=[0, 0, 0]), wireless_remote=[0] * 40,
                  led=[0] * 12, fan=[0, 0], gpio=0, reserve=0, crc=0)
    cmd.crc = low_cmd_crc(cmd)
    return cmd


def wire_from_low_cmd(cmd: LowCmd_) -> WireCommand:
    """The per-slot values of a received ``LowCmd_``."""
    motors = cmd.motor_cmd
    return WireCommand(mode=np.array([m.mode for m in motors], dtype=np.uint8),
                       q_rad=np.array([m.q for m in motors]),
                       dq_rad_s=np.array([m.dq for m in motors]),
                       tau_nm=np.array([m.tau for m in motors]),
                       kp=np.array([m.kp for m in motors]), kd=np.array([m.kd for m in motors]))


def low_state_from_wire(state: WireState, motor_mode: int = MOTOR_MODE_SERVO) -> LowState_:
    """A ``LowState_`` carrying ``state`` (what the robot publishes on ``rt/lowstate``)."""
    motors = [MotorState_(mode=motor_mode, q=float(state.q_rad[i]), dq=float(state.dq_rad_s[i]),
                          ddq=0.0, tau_est=float(state.tau_est_nm[i]), q_raw=0.0, dq_raw=0.0,
                          ddq_raw=0.0, temperature=0, lost=0, reserve=[0, 0])
              for i in range(MOTOR_SLOT_COUNT)]
    imu = IMUState_(quaternion=[float(v) for v in state.quaternion_wxyz],
                    gyroscope=[float(v) for v in state.gyroscope_rad_s],
                    accelerometer=[float(v) for v in state.accelerometer_m_s2],
                    rpy=[float(v) for v in state.rpy_rad], temperature=0)
    bms = BmsState_(version_high=0, version_low=0, status=0, soc=100, current=0, cycle=0,
                    bq_ntc=[0, 0], mcu_ntc=[0, 0], cell_vol=[0] * 15)
    foot_force = [int(v) for v in state.foot_force]
    message = LowState_(head=list(HEAD), level_flag=LEVEL_FLAG_LOW, frame_reserve=0, sn=[0, 0],
                        version=[0, 0], bandwidth=0, imu_state=imu, motor_state=motors,
                        bms_state=bms, foot_force=foot_force, foot_force_est=foot_force,
                        tick=int(state.tick_ms) & 0xFFFFFFFF, wireless_remote=[0] * 40,
                        bit_flag=0, adc_reel=0.0, temperature_ntc1=0, temperature_ntc2=0,
                        power_v=0.0, power_a=0.0, fan_frequency=[0] * 4, reserve=0, crc=0)
    message.crc = low_state_crc(message)
    return message


def wire_from_low_state(msg: LowState_) -> WireState:
    """The per-slot values of a received ``LowState_``."""
    motors, imu = msg.motor_state, msg.imu_state
    return WireState(q_rad=np.array([m.q for m in motors]),
                     dq_rad_s=np.array([m.dq for m in motors]),
                     tau_est_nm=np.array([m.tau_est for m in motors]),
                     quaternion_wxyz=np.array(imu.quaternion, dtype=float),
                     gyroscope_rad_s=np.array(imu.gyroscope, dtype=float),
                     accelerometer_m_s2=np.array(imu.accelerometer, dtype=float),
                     rpy_rad=np.array(imu.rpy, dtype=float),
                     foot_force=np.array(msg.foot_force, dtype=np.int16), tick_ms=msg.tick)


def api_request(request_id: int, api_id: int, parameter: str = "{}") -> Request_:
    """A unitree_api request expecting a reply (lease 0, priority 0)."""
    return Request_(header=RequestHeader_(
        identity=RequestIdentity_(id=request_id, api_id=api_id), lease=RequestLease_(id=0),
        policy=RequestPolicy_(priority=0, noreply=False)), parameter=parameter, binary=[])


def api_response(request: Request_, code: int) -> Response_:
    """The reply to ``request`` with status ``code`` (0 = success) and no data."""
    return Response_(header=ResponseHeader_(identity=request.header.identity,
                                            status=ResponseStatus_(code=code)),
                     data="", binary=[])


def low_cmd_crc(cmd: LowCmd_) -> int:
    """Unitree's CRC-32 of ``cmd``: packed little-endian with ``LOW_CMD_CRC_FORMAT`` (812
    bytes, the firmware's in-memory layout), first 202 u32 words (the crc field excluded)."""
    values: list[int | float] = [*cmd.head, cmd.level_flag, cmd.frame_reserve, *cmd.sn,
                                 *cmd.version, cmd.bandwidth]
    for motor in cmd.motor_cmd:
        values += [motor.mode, motor.q, motor.dq, motor.tau, motor.kp, motor.kd, *motor.reserve]
    values += [cmd.bms_cmd.off, *cmd.bms_cmd.reserve, *cmd.wireless_remote, *cmd.led, *cmd.fan,
               cmd.gpio, cmd.reserve, cmd.crc]
    packed = struct.pack(LOW_CMD_CRC_FORMAT, *values)
    return unitree_crc32(np.frombuffer(packed, dtype="<u4", count=LOW_CMD_CRC_WORDS))


def low_state_crc(state: LowState_) -> int:
    """Unitree's CRC-32 of ``state``: packed little-endian with ``LOW_STATE_CRC_FORMAT`` (1180
    bytes, as unitree_sdk2_python packs it), first 294 u32 words (the crc field excluded).
    The SDK packs the temperatures as signed bytes ("b") and the fan frequencies as int16
    ("h") where the IDL has unsigned types: the same bytes, so they are reinterpreted here
    rather than refused above the signed range."""
    def signed(value: int, bits: int = 8) -> int:
        return value - (1 << bits) if value >= 1 << (bits - 1) else value

    imu, bms = state.imu_state, state.bms_state
    values: list[int | float] = [*state.head, state.level_flag, state.frame_reserve, *state.sn,
                                 *state.version, state.bandwidth, *imu.quaternion,
                                 *imu.gyroscope, *imu.accelerometer, *imu.rpy,
                                 signed(imu.temperature)]
    for motor in state.motor_state:
        values += [motor.mode, motor.q, motor.dq, motor.ddq, motor.tau_est, motor.q_raw,
                   motor.dq_raw, motor.ddq_raw, signed(motor.temperature), motor.lost,
                   *motor.reserve]
    values += [bms.version_high, bms.version_low, bms.status, bms.soc, bms.current, bms.cycle,
               *map(signed, bms.bq_ntc), *map(signed, bms.mcu_ntc), *bms.cell_vol,
               *state.foot_force, *state.foot_force_est, state.tick, *state.wireless_remote,
               state.bit_flag, state.adc_reel, signed(state.temperature_ntc1),
               signed(state.temperature_ntc2), state.power_v,
               state.power_a, *(signed(v, 16) for v in state.fan_frequency), state.reserve,
               state.crc]
    packed = struct.pack(LOW_STATE_CRC_FORMAT, *values)
    return unitree_crc32(np.frombuffer(packed, dtype="<u4", count=LOW_STATE_CRC_WORDS))
