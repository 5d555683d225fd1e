"""The precompiled Go2 CDR codecs against cyclonedds' own serializer: byte-identical on random
messages in both directions, CRC and header checks, malformed input rejected."""

from __future__ import annotations

import struct

import numpy as np
import pytest

from drivers.unitree.conventions import WireCommand, WireState
from drivers.unitree.go2_cdr import CDR_HEADER, LowCmdCodec, LowStateCodec, MessageLayout, idl_fields
from drivers.unitree.go2_dds_types import (
    LOW_CMD_CRC_FORMAT,
    LOW_STATE_CRC_FORMAT,
    LowCmd_,
    LowState_,
    low_cmd_crc,
    low_cmd_from_wire,
    low_state_crc,
    low_state_from_wire,
    wire_from_low_cmd,
    wire_from_low_state,
)

_RANGES = {"uint8": (0, 2**8), "int8": (-2**7, 2**7), "uint16": (0, 2**16),
           "int16": (-2**15, 2**15), "uint32": (0, 2**32), "int32": (-2**31, 2**31)}


def _random(message: type, rng: np.random.Generator) -> tuple[object, dict[str, list]]:
    """A random instance of ``struct`` and its values by dotted path."""
    values: dict[str, list] = {}
    kwargs = {}
    for name, element, count in idl_fields(message):
        items = []
        for _ in range(count):
            if isinstance(element, str):
                if element.startswith("float"):
                    item = float(np.float32(rng.normal(0.0, 100.0)))
                else:
                    low, high = _RANGES[element]
                    item = int(rng.integers(low, high))
                values.setdefault(name, []).append(item)
            else:
                item, inner = _random(element, rng)
                for path, v in inner.items():
                    values.setdefault(f"{name}.{path}", []).extend(v)
            items.append(item)
        kwargs[name] = items if count > 1 or name in ("sn", "version") else items[0]
    return message(**kwargs), values


@pytest.mark.parametrize("message", [LowCmd_, LowState_])
def test_random_messages_are_byte_identical_both_ways(message: type) -> None:
    rng = np.random.default_rng(7)
    layout = MessageLayout(message, "cdr")
    for _ in range(25):
        sample, values = _random(message, rng)
        reference = sample.serialize()
        ours = layout.encode({p: np.array(v) for p, v in values.items()}, CDR_HEADER)
        padded = ours + b"\0" * (-len(ours) % 4)
        assert padded == reference
        decoded = layout.decode(reference, len(CDR_HEADER))
        for path, value in values.items():
            np.testing.assert_array_equal(decoded[path], np.array(value, decoded[path].dtype))
        # cyclonedds reads our bytes back into the same message (uint8 arrays come back as bytes)
        assert message.deserialize(padded).serialize() == reference


def test_c_layout_is_the_firmware_struct_the_crc_covers() -> None:
    memory = MessageLayout(LowCmd_, "c")
    assert memory.size == struct.calcsize(LOW_CMD_CRC_FORMAT) == 812
    assert memory.leaves["motor_cmd.q"].offsets[0] == 28  # MotorCmd_ aligned to 4 at 24
    assert MessageLayout(LowCmd_, "cdr").leaves["motor_cmd.q"].offsets[0] == 24


def test_state_crc_covers_the_sdk_packing_and_every_field() -> None:
    """On random ``LowState_`` (every field random, as a robot could fill it), the codec's CRC
    check agrees with the CRC of unitree_sdk2_python's packing (``LOW_STATE_CRC_FORMAT``), and
    one flipped bit in any field's bytes fails it."""
    assert MessageLayout(LowState_, "c").size == struct.calcsize(LOW_STATE_CRC_FORMAT) == 1180
    rng = np.random.default_rng(11)
    codec = LowStateCodec()
    wire = MessageLayout(LowState_, "cdr")
    covered = 4 + np.concatenate([leaf.byte_index for path, leaf in wire.leaves.items()
                                  if path != "crc"])  # field bytes, not CDR padding
    for _ in range(10):
        sample, _ = _random(LowState_, rng)
        sample.crc = low_state_crc(sample)
        data = bytearray(sample.serialize())
        assert codec.crc_ok(bytes(data))
        position = int(rng.choice(covered))
        data[position] ^= 1 << int(rng.integers(0, 8))
        assert not codec.crc_ok(bytes(data))
    assert not codec.crc_ok(low_state_from_wire(WireState()).serialize()[:-4] + bytes(4))


def _command(rng: np.random.Generator) -> WireCommand:
    return WireCommand(mode=rng.integers(0, 256, 20).astype(np.uint8),
                       q_rad=rng.normal(size=20), dq_rad_s=rng.normal(size=20),
                       tau_nm=rng.normal(size=20), kp=rng.uniform(0, 50, 20),
                       kd=rng.uniform(0, 5, 20))


def test_command_codec_matches_cyclonedds_with_the_unitree_crc() -> None:
    rng = np.random.default_rng(1)
    codec = LowCmdCodec()
    for _ in range(20):
        command = _command(rng)
        reference = low_cmd_from_wire(command).serialize()
        assert codec.encode(command) == reference
        typed = LowCmd_.deserialize(reference)
        assert typed.crc == low_cmd_crc(typed)
        decoded, header_ok, crc_ok = codec.decode(reference)
        assert header_ok and crc_ok
        expected = wire_from_low_cmd(typed)
        for name in ("mode", "q_rad", "dq_rad_s", "tau_nm", "kp", "kd"):
            np.testing.assert_array_equal(getattr(decoded, name), getattr(expected, name))


def test_state_codec_matches_cyclonedds() -> None:
    rng = np.random.default_rng(2)
    codec = LowStateCodec()
    for _ in range(20):
        state = WireState(q_rad=rng.normal(size=20), dq_rad_s=rng.normal(size=20),
                          tau_est_nm=rng.normal(size=20), quaternion_wxyz=rng.normal(size=4),
                          gyroscope_rad_s=rng.normal(size=3),
                          accelerometer_m_s2=rng.normal(size=3), rpy_rad=rng.normal(size=3),
                          foot_force=rng.integers(-2**15, 2**15, 4).astype(np.int16),
                          tick_ms=int(rng.integers(0, 2**32)))
        reference = low_state_from_wire(state).serialize()
        assert codec.encode(state) == reference  # the CRC as the SDK computes it included
        assert codec.crc_ok(reference)
        decoded, expected = codec.decode(reference), wire_from_low_state(
            LowState_.deserialize(reference))
        for name in ("q_rad", "dq_rad_s", "tau_est_nm", "quaternion_wxyz", "gyroscope_rad_s",
                     "accelerometer_m_s2", "rpy_rad", "foot_force"):
            np.testing.assert_array_equal(getattr(decoded, name), getattr(expected, name))
        assert decoded.tick_ms == expected.tick_ms


def test_corruption_wrong_encoding_and_truncation_are_caught() -> None:
    codec = LowCmdCodec()
    data = bytearray(codec.encode(_command(np.random.default_rng(3))))
    data[100] ^= 0x40  # a bit of motor 2's command flips on the way
    _, header_ok, crc_ok = codec.decode(bytes(data))
    assert header_ok and not crc_ok
    data = bytearray(codec.encode(_command(np.random.default_rng(3))))
    data[4] = 0x00  # head 0x00 0xEF
    assert codec.decode(bytes(data))[1] is False
    with pytest.raises(ValueError, match="encoding 0000"):
        codec.decode(b"\x00\x00\x00\x00" + bytes(data[4:]))  # big-endian CDR
    with pytest.raises(ValueError, match="bytes"):
        LowStateCodec().decode(bytes(data[:300]))


def test_nan_passes_the_codec_so_the_layers_above_can_refuse_it() -> None:
    """The codec is bytes only: a NaN stays a NaN (the driver refuses non-finite commands
    before encoding, ``command_problem`` / ``state_problem`` reject them after decoding)."""
    codec = LowStateCodec()
    state = WireState(q_rad=np.full(20, np.nan))
    assert np.isnan(codec.decode(codec.encode(state)).q_rad).all()
