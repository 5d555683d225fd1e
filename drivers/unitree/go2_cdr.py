"""Precompiled CDR codecs of the Go2's fixed-size ``LowCmd_`` and ``LowState_``.

cyclonedds-python serializes an ``IdlStruct`` field by field in Python (~0.3 ms to decode a
LowState, ~0.45 ms to encode a LowCmd, measured); these messages are fixed-size, so every
field has a fixed byte offset. ``MessageLayout`` computes the offsets once from the IDL types
of ``drivers.unitree.go2_dds_types`` (no second copy of the message definitions), in both
layouts that matter:

- ``cdr``: the wire (XCDR1 little endian, encapsulation header ``00 01 00 00``; each primitive
  aligned to its size from the start of the payload; structs add no padding of their own).
  The bytes are identical to cyclonedds' own ``serialize()`` (tested on random messages, both
  directions).
- ``c``: the firmware's in-memory struct (members aligned, structs padded to their alignment):
  what Unitree's CRC-32 runs over (``LOW_CMD_CRC_FORMAT``, ``LOW_STATE_CRC_FORMAT``).

Fields are then read and written as NumPy views with the field's stride (or a gather where
the stride is irregular), so a message costs a few array copies instead of hundreds of Python
calls. The codecs speak porter's ``WireCommand`` / ``WireState`` (Unitree motor order, 20
slots); the conversion to porter's joint order stays in ``drivers.unitree.conventions``.
"""

from __future__ import annotations

import dataclasses
import typing
from collections.abc import Mapping

import numpy as np
from cyclonedds.idl import IdlStruct
from cyclonedds.idl.types import array

from drivers.unitree.conventions import WireCommand, WireState, unitree_crc32
from drivers.unitree.go2_dds_types import (
    HEAD,
    LEVEL_FLAG_LOW,
    LOW_CMD_CRC_WORDS,
    LOW_STATE_CRC_WORDS,
    MOTOR_MODE_SERVO,
    LowCmd_,
    LowState_,
)

__all__ = ["CDR_HEADER", "LowCmdCodec", "LowStateCodec", "MessageLayout", "idl_fields"]

CDR_HEADER = b"\x00\x01\x00\x00"  # XCDR1, little endian
# Accepted on receipt: XCDR1 and XCDR2 little endian (identical bytes for these final structs:
# they hold no 8-byte member, the only case where the two alignments differ).
_LITTLE_ENDIAN_CDR = (b"\x00\x01", b"\x00\x07")
_PRIMITIVES = {"uint8": "<u1", "int8": "<i1", "uint16": "<u2", "int16": "<i2", "uint32": "<u4",
               "int32": "<i4", "float32": "<f4", "uint64": "<u8", "int64": "<i8",
               "float64": "<f8"}


@dataclasses.dataclass(frozen=True)
class _Leaf:
    dtype: np.dtype
    offsets: np.ndarray  # byte offset of each element (several for arrays)
    stride: int | None  # bytes between elements when evenly spaced, else None
    byte_index: np.ndarray  # the bytes of every element, in order (for irregular fields)

    @classmethod
    def of(cls, dtype: np.dtype, offsets: list[int]) -> _Leaf:
        steps = np.diff(offsets)
        stride = (dtype.itemsize if len(offsets) == 1 else int(steps[0])
                  if np.all(steps == steps[0]) else None)
        index = (np.array(offsets)[:, None] + np.arange(dtype.itemsize)).reshape(-1)
        return cls(dtype, np.array(offsets), stride, index)


def idl_fields(struct: type) -> list[tuple[str, str | type, int]]:
    """(name, primitive name or nested struct type, count) of an IdlStruct's fields."""
    out: list[tuple[str, str | type, int]] = []
    for name, hint in typing.get_type_hints(struct, include_extras=True).items():
        if name not in {f.name for f in dataclasses.fields(struct)}:
            continue
        count, element = 1, hint
        args = typing.get_args(hint)
        if len(args) == 2 and isinstance(args[1], array):
            count, element = args[1].length, args[1].subtype
        if isinstance(element, type) and issubclass(element, IdlStruct):
            out.append((name, element, count))
        else:
            out.append((name, typing.get_args(element)[1], count))
    return out


class MessageLayout:
    """Byte offsets of every primitive of a fixed-size IdlStruct, by dotted path
    (``motor_cmd.q`` holds 20 offsets), in the ``cdr`` or ``c`` layout."""

    def __init__(self, struct: type, kind: typing.Literal["cdr", "c"]) -> None:
        self.kind = kind
        self.leaves: dict[str, _Leaf] = {}
        offsets: dict[str, list[int]] = {}
        dtypes: dict[str, np.dtype] = {}
        self.size = self._place(struct, "", 0, offsets, dtypes)
        self.leaves = {path: _Leaf.of(dtypes[path], o) for path, o in offsets.items()}

    def _alignment(self, element: str | type) -> int:
        if isinstance(element, str):
            return np.dtype(_PRIMITIVES[element]).itemsize
        return max(self._alignment(e) for _, e, _ in idl_fields(element))

    def _place(self, struct: type, prefix: str, offset: int, offsets: dict[str, list[int]],
               dtypes: dict[str, np.dtype]) -> int:
        start = offset
        for name, element, count in idl_fields(struct):
            path = f"{prefix}{name}"
            for _ in range(count):
                if isinstance(element, str):
                    dtype = np.dtype(_PRIMITIVES[element])
                    offset += -offset % dtype.itemsize
                    offsets.setdefault(path, []).append(offset)
                    dtypes[path] = dtype
                    offset += dtype.itemsize
                else:
                    if self.kind == "c":
                        offset += -offset % self._alignment(element)
                    offset = self._place(element, f"{path}.", offset, offsets, dtypes)
        if self.kind == "c":  # a C struct is padded to its alignment
            offset += -(offset - start) % self._alignment(struct)
        return offset

    def view(self, buffer: bytearray | bytes | memoryview, path: str, base: int = 0
             ) -> np.ndarray:
        """The field at ``path`` inside ``buffer`` (payload starting at ``base``): a view when
        its elements are evenly spaced (writable on a bytearray), else a gathered copy."""
        leaf = self.leaves[path]
        if leaf.stride is not None:
            return np.ndarray((leaf.offsets.size,), leaf.dtype, buffer,
                              base + int(leaf.offsets[0]), (leaf.stride,))
        raw = np.frombuffer(buffer, np.uint8, count=leaf.byte_index[-1] + 1, offset=base)
        return raw[leaf.byte_index].view(leaf.dtype)

    def write(self, buffer: bytearray, path: str, values: np.ndarray | float, base: int = 0
              ) -> None:
        """Store ``values`` (cast to the field's type) at ``path``."""
        leaf = self.leaves[path]
        if leaf.stride is not None:
            self.view(buffer, path, base)[:] = values
            return
        raw = np.frombuffer(buffer, np.uint8, count=leaf.byte_index[-1] + 1, offset=base)
        encoded = np.empty(leaf.offsets.size, leaf.dtype)
        encoded[:] = values
        raw[leaf.byte_index] = encoded.view(np.uint8)

    def encode(self, values: Mapping[str, np.ndarray | float], header: bytes = b"") -> bytes:
        """A whole message from every field's value (missing fields are zero)."""
        buffer = bytearray(len(header) + self.size)
        buffer[:len(header)] = header
        for path, value in values.items():
            self.write(buffer, path, value, len(header))
        return bytes(buffer)

    def decode(self, data: bytes, header_size: int = 0) -> dict[str, np.ndarray]:
        """Every field of a message, as arrays (copies)."""
        return {path: np.array(self.view(data, path, header_size)) for path in self.leaves}


def _check(data: bytes, layout: MessageLayout, what: str) -> None:
    if len(data) < len(CDR_HEADER) + layout.size:
        raise ValueError(f"{what} of {len(data)} bytes, expected {len(CDR_HEADER) + layout.size}")
    if bytes(data[0:2]) not in _LITTLE_ENDIAN_CDR:
        raise ValueError(f"{what} in encoding {bytes(data[0:2]).hex()}, expected little-endian "
                         "CDR (0001 or 0007)")


def _cdr_size(layout: MessageLayout) -> int:
    """What cyclonedds sends: header + payload padded to a multiple of 4."""
    size = len(CDR_HEADER) + layout.size
    return size + (-size % 4)


class _WireCrc:
    """Unitree's CRC-32 of a message's wire bytes: each field's bytes re-laid from where they
    sit on the wire (after the CDR header) to where they sit in the C struct, in one gather;
    the C struct's padding stays zero; the CRC runs over its first ``words`` u32 words."""

    def __init__(self, wire: MessageLayout, memory: MessageLayout, words: int) -> None:
        leaves = list(wire.leaves)
        self._to_memory = np.concatenate([memory.leaves[p].byte_index for p in leaves])
        self._from_wire = np.concatenate([wire.leaves[p].byte_index for p in leaves]) + 4
        self._memory = np.zeros(memory.size, np.uint8)
        self._words = self._memory[:4 * words].view("<u4")
        self._wire = wire

    def of(self, data: bytes | bytearray) -> int:
        """The CRC ``data`` (a whole sample, header included) should carry."""
        self._memory[self._to_memory] = np.frombuffer(data, np.uint8)[self._from_wire]
        return unitree_crc32(self._words)

    def carried(self, data: bytes | bytearray) -> int:
        """The CRC ``data`` carries."""
        return int(self._wire.view(data, "crc", 4)[0])


class LowCmdCodec:
    """``LowCmd_`` bytes <-> ``WireCommand`` (head 0xFE 0xEF, level flag 0xFF, CRC)."""

    def __init__(self) -> None:
        self.wire = MessageLayout(LowCmd_, "cdr")
        self.memory = MessageLayout(LowCmd_, "c")
        self.size = _cdr_size(self.wire)
        self._buffer = bytearray(self.size)
        self._buffer[:4] = CDR_HEADER
        self._memory = bytearray(self.memory.size)
        for layout, buffer, base in ((self.wire, self._buffer, 4), (self.memory, self._memory, 0)):
            layout.write(buffer, "head", np.array(HEAD), base)
            layout.write(buffer, "level_flag", LEVEL_FLAG_LOW, base)
        self._views = [(self.wire.view(self._buffer, f"motor_cmd.{f}", 4),
                        self.memory.view(self._memory, f"motor_cmd.{f}"), f)
                       for f in ("q", "dq", "tau", "kp", "kd")]
        self._crc = self.wire.view(self._buffer, "crc", 4)
        self._words = np.frombuffer(self._memory, "<u4", count=LOW_CMD_CRC_WORDS)
        self._received_crc = _WireCrc(self.wire, self.memory, LOW_CMD_CRC_WORDS)

    def encode(self, command: WireCommand) -> bytes:
        """The wire bytes of ``command`` with its CRC filled in."""
        values = {"q": command.q_rad, "dq": command.dq_rad_s, "tau": command.tau_nm,
                  "kp": command.kp, "kd": command.kd}
        for wire_view, memory_view, name in self._views:
            wire_view[:] = values[name]
            memory_view[:] = values[name]
        self.wire.write(self._buffer, "motor_cmd.mode", command.mode, 4)
        self.memory.write(self._memory, "motor_cmd.mode", command.mode)
        self._crc[0] = unitree_crc32(self._words)
        return bytes(self._buffer)

    def decode(self, data: bytes) -> tuple[WireCommand, bool, bool]:
        """(command, header ok, CRC ok) of received bytes; ``ValueError`` for a wrong size
        or encoding."""
        _check(data, self.wire, "LowCmd_")
        fields = {f: np.array(self.wire.view(data, f"motor_cmd.{f}", 4), dtype=float)
                  for f in ("q", "dq", "tau", "kp", "kd")}
        mode = np.array(self.wire.view(data, "motor_cmd.mode", 4), dtype=np.uint8)
        command = WireCommand(mode=mode, q_rad=fields["q"], dq_rad_s=fields["dq"],
                              tau_nm=fields["tau"], kp=fields["kp"], kd=fields["kd"])
        head = tuple(int(v) for v in self.wire.view(data, "head", 4))
        header_ok = head == HEAD and int(self.wire.view(data, "level_flag", 4)[0]) == \
            LEVEL_FLAG_LOW
        crc_ok = self._received_crc.of(data) == self._received_crc.carried(data)
        return command, header_ok, crc_ok


class LowStateCodec:
    """``LowState_`` bytes <-> ``WireState`` (what porter reads of it and a robot fills in,
    CRC included)."""

    _FIELDS = (("q_rad", "motor_state.q"), ("dq_rad_s", "motor_state.dq"),
               ("tau_est_nm", "motor_state.tau_est"),
               ("quaternion_wxyz", "imu_state.quaternion"),
               ("gyroscope_rad_s", "imu_state.gyroscope"),
               ("accelerometer_m_s2", "imu_state.accelerometer"), ("rpy_rad", "imu_state.rpy"))

    def __init__(self) -> None:
        self.wire = MessageLayout(LowState_, "cdr")
        self.size = _cdr_size(self.wire)
        self._buffer = bytearray(self.size)
        self._buffer[:4] = CDR_HEADER
        self.wire.write(self._buffer, "head", np.array(HEAD), 4)
        self.wire.write(self._buffer, "level_flag", LEVEL_FLAG_LOW, 4)
        self.wire.write(self._buffer, "bms_state.soc", 100, 4)
        self._views = {name: self.wire.view(self._buffer, path, 4) for name, path in self._FIELDS}
        self._foot = [self.wire.view(self._buffer, p, 4) for p in ("foot_force", "foot_force_est")]
        self._tick = self.wire.view(self._buffer, "tick", 4)
        self._crc_view = self.wire.view(self._buffer, "crc", 4)
        self._crc = _WireCrc(self.wire, MessageLayout(LowState_, "c"), LOW_STATE_CRC_WORDS)
        # decode: the float fields porter reads, gathered in one indexing from the wire bytes
        # (after the CDR header) and widened to float64 once (exact), then split into slices
        leaves = [self.wire.leaves[path] for _, path in self._FIELDS]
        if any(leaf.dtype != np.dtype("<f4") for leaf in leaves):
            raise TypeError("LowState_: every decoded field must be float32")
        self._gather = np.concatenate([leaf.byte_index for leaf in leaves]) + 4
        ends = np.cumsum([leaf.offsets.size for leaf in leaves])
        self._slices = {name: slice(int(end - leaf.offsets.size), int(end))
                        for (name, _), leaf, end in zip(self._FIELDS, leaves, ends, strict=True)}

    def encode_header(self) -> bytes:
        """The 4-byte CDR encapsulation header every sample starts with."""
        return bytes(self._buffer[:4])

    def encode(self, state: WireState, motor_mode: int = MOTOR_MODE_SERVO) -> bytes:
        """The wire bytes of a robot's ``state``, its CRC filled in as the robot's."""
        for name, view in self._views.items():
            view[:] = getattr(state, name)
        for view in self._foot:
            view[:] = state.foot_force
        self._tick[0] = int(state.tick_ms) & 0xFFFFFFFF
        self.wire.write(self._buffer, "motor_state.mode", motor_mode, 4)
        self._crc_view[0] = self._crc.of(self._buffer)
        return bytes(self._buffer)

    def crc_ok(self, data: bytes) -> bool:
        """Whether received ``data`` (size and encoding checked by ``decode``) carries the
        CRC of its contents."""
        return self._crc.of(data) == self._crc.carried(data)

    def decode(self, data: bytes) -> WireState:
        """The state in received bytes; ``ValueError`` for a wrong size or encoding."""
        _check(data, self.wire, "LowState_")
        values = np.frombuffer(data, np.uint8)[self._gather].view("<f4").astype(float)
        arrays = {name: values[rows] for name, rows in self._slices.items()}
        return WireState(**arrays,
                         foot_force=np.array(self.wire.view(data, "foot_force", 4), np.int16),
                         tick_ms=int(self.wire.view(data, "tick", 4)[0]))
