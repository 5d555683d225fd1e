"""OptiTrack NatNet 4.1 wire format: pack and unpack the messages porter uses.

Every packet is a little-endian header, int16 message id + uint16 payload size [bytes], then
the payload. Units on the wire are Motive's streaming units, metres by default; orientations
are quaternions in NatNet's order (qx, qy, qz, qw). This module keeps NatNet's order: the
conversion to porter's (w, x, y, z) happens once, in ``drivers.natnet.client``.

Layouts (NatNet 4.1, as in the public SDK clients):

- FRAMEOFDATA: frame number int32; then eight sections, each int32 count + int32 byte size
  (4.1+): marker sets, legacy (unlabeled) markers, rigid bodies, skeletons, assets, labeled
  markers, force plates, devices; then the suffix: timecode u32, timecode sub u32, timestamp
  f64 [s], camera mid-exposure / data received / transmit timestamps int64 [ticks], precision
  timestamp u32 seconds + u32 fraction, params int16 (bit 0 recording, bit 1 tracked models
  changed). Rigid body: id int32, position 3 x f32, orientation qx, qy, qz, qw f32, mean
  marker error f32 [m], params int16 (bit 0 tracking valid). Only the rigid-body section is
  decoded; the others are skipped by their byte size. Bytes after the suffix (older servers
  append an int32 end-of-data tag) are ignored.
- MODELDEF: int32 description count; each description is int32 type + int32 byte size (4.1+)
  + body. Rigid body (type 1): name (NUL-terminated), id int32, parent id int32, offset
  3 x f32 [m], marker count int32, marker offsets, active labels, names. Simplified: the
  packer writes no markers; the unpacker reads name, ids and offset and skips the rest (and
  every other description type) by the byte size.
- SERVERINFO (sSender_Server): application name char[256], server version u8[4], NatNet
  version u8[4], high-resolution clock [Hz] u64, data port u16, is-multicast u8, multicast
  group u8[4]. Older servers stop after the NatNet version; the tail is then left at defaults.
- CONNECT: a client sSender (name char[256], version u8[4], NatNet version u8[4]). Motive
  accepts a short "Ping" string too; servers here accept any payload.
- KEEPALIVE, REQUEST_MODELDEF, DISCONNECT: empty payloads.

Any truncated or inconsistent packet raises ``NatNetProtocolError`` (a ``ValueError``) that
says what was expected; ``struct.error`` and ``IndexError`` never leak out.
"""

from __future__ import annotations

import socket
import struct
from dataclasses import dataclass
from enum import IntEnum

NATNET_VERSION = (4, 1, 0, 0)
MULTICAST_GROUP = "239.255.42.99"
COMMAND_PORT = 1510
DATA_PORT = 1511
MAX_PAYLOAD_BYTES = 0xFFFF
HEADER = struct.Struct("<hH")
RIGID_BODY = struct.Struct("<i3f4ffh")  # 38 bytes
SUFFIX = struct.Struct("<IId3q2Ih")
SECTION_COUNT = 8  # marker sets, legacy markers, rigid bodies, skeletons, assets, labeled
RIGID_BODY_SECTION = 2  # markers, force plates, devices
RIGID_BODY_DESCRIPTION_TYPE = 1
TRACKING_VALID_BIT = 0x01
MODELS_CHANGED_BIT = 0x02
_NAME_BYTES = 256
_SERVER_INFO = struct.Struct("<256s4B4BQHB4B")
_SENDER = struct.Struct("<256s4B4B")
_INT32 = struct.Struct("<i")


class MessageId(IntEnum):
    CONNECT = 0
    SERVERINFO = 1
    REQUEST = 2
    RESPONSE = 3
    REQUEST_MODELDEF = 4
    MODELDEF = 5
    REQUEST_FRAMEOFDATA = 6
    FRAMEOFDATA = 7
    MESSAGESTRING = 8
    DISCONNECT = 9
    KEEPALIVE = 10
    UNRECOGNIZED_REQUEST = 100


class NatNetProtocolError(ValueError):
    """A packet that is truncated, inconsistent or not a NatNet message; ``reason`` is a short
    tag for counting ("truncated", "malformed", "unknown message")."""

    def __init__(self, message: str, reason: str = "malformed") -> None:
        super().__init__(message)
        self.reason = reason


@dataclass(frozen=True)
class RigidBodySample:
    """One rigid body of a frame, in NatNet's conventions: position [m] in the MoCap world
    frame, orientation quaternion (qx, qy, qz, qw) body -> world."""

    id: int
    position_m: tuple[float, float, float]
    quaternion_xyzw: tuple[float, float, float, float]
    mean_marker_error_m: float = 0.0
    tracking_valid: bool = True


@dataclass(frozen=True)
class FrameOfData:
    """A decoded FRAMEOFDATA: the rigid bodies and the suffix. ``timestamp_s`` is the server's
    clock [s]; the camera timestamps are in high-resolution clock ticks."""

    frame_number: int
    rigid_bodies: tuple[RigidBodySample, ...]
    timestamp_s: float = 0.0
    timecode: int = 0
    timecode_sub: int = 0
    camera_mid_exposure_ticks: int = 0
    data_received_ticks: int = 0
    transmit_ticks: int = 0
    precision_timestamp_s: int = 0
    precision_timestamp_fraction: int = 0
    params: int = 0

    @property
    def tracked_models_changed(self) -> bool:
        return bool(self.params & MODELS_CHANGED_BIT)


@dataclass(frozen=True)
class RigidBodyDescription:
    """A rigid body as MODELDEF describes it: streaming name and id, parent id, offset [m]."""

    name: str
    id: int
    parent_id: int = -1
    offset_m: tuple[float, float, float] = (0.0, 0.0, 0.0)


@dataclass(frozen=True)
class ServerInfo:
    """SERVERINFO: who is streaming, which NatNet version, and where the data goes."""

    application_name: str = "Motive"
    server_version: tuple[int, int, int, int] = (3, 1, 0, 0)
    natnet_version: tuple[int, int, int, int] = NATNET_VERSION
    high_resolution_clock_hz: int = 0
    data_port: int = DATA_PORT
    is_multicast: bool = False
    multicast_group: str = MULTICAST_GROUP


class _Reader:
    """Bounds-checked little-endian reader over one payload."""

    def __init__(self, data: bytes, what: str) -> None:
        self.data, self.offset, self.what = data, 0, what

    def take(self, count: int) -> bytes:
        if count < 0 or self.offset + count > len(self.data):
            raise NatNetProtocolError(
                f"{self.what}: truncated, needs {count} bytes at offset {self.offset}, "
                f"payload has {len(self.data)}", "truncated")
        chunk = self.data[self.offset:self.offset + count]
        self.offset += count
        return chunk

    def unpack(self, layout: struct.Struct) -> tuple:
        return layout.unpack(self.take(layout.size))

    def int32(self) -> int:
        return int(self.unpack(_INT32)[0])

    def string(self) -> str:
        end = self.data.find(b"\0", self.offset)
        if end < 0:
            raise NatNetProtocolError(f"{self.what}: string at offset {self.offset} has no NUL")
        return _decode_name(self.take(end + 1 - self.offset)[:-1], self.what)



def _decode_name(raw: bytes, what: str) -> str:
    try:
        return raw.split(b"\0", 1)[0].decode("utf-8")
    except UnicodeDecodeError as error:
        raise NatNetProtocolError(f"{what}: name is not UTF-8 ({error})") from None


def _encode_name(name: str) -> bytes:
    raw = name.encode("utf-8")
    if b"\0" in raw:
        raise ValueError(f"name {name!r} contains NUL")
    return raw


# --- header ---------------------------------------------------------------------------------
def pack_message(message_id: int, payload: bytes = b"") -> bytes:
    """Header + payload. Raises ValueError when the payload exceeds 65535 bytes."""
    if len(payload) > MAX_PAYLOAD_BYTES:
        raise ValueError(f"payload of {len(payload)} bytes exceeds {MAX_PAYLOAD_BYTES}")
    return HEADER.pack(int(message_id), len(payload)) + payload


def unpack_message(packet: bytes) -> tuple[int, bytes]:
    """(message id, payload) of one datagram; its size field must match the datagram, except
    for trailing NUL bytes after the payload (OptiTrack's sample client ends every request,
    a keep-alive of size 0 included, with a NUL it does not count)."""
    if len(packet) < HEADER.size:
        raise NatNetProtocolError(f"packet of {len(packet)} bytes is shorter than the header",
                                  "truncated")
    message_id, size = HEADER.unpack_from(packet)
    carried = len(packet) - HEADER.size
    if carried < size or packet[HEADER.size + size:].strip(b"\0"):
        raise NatNetProtocolError(f"message {message_id}: header says {size} payload bytes, "
                                  f"datagram carries {carried}", "truncated")
    return int(message_id), bytes(packet[HEADER.size:HEADER.size + size])


# --- commands and server info ----------------------------------------------------------------
def pack_connect(client_name: str = "porter") -> bytes:
    sender = _SENDER.pack(_encode_name(client_name)[:_NAME_BYTES - 1], *NATNET_VERSION,
                          *NATNET_VERSION)
    return pack_message(MessageId.CONNECT, sender)


def pack_server_info(info: ServerInfo) -> bytes:
    group = socket.inet_aton(info.multicast_group)
    payload = _SERVER_INFO.pack(_encode_name(info.application_name)[:_NAME_BYTES - 1],
                                *info.server_version, *info.natnet_version,
                                info.high_resolution_clock_hz, info.data_port,
                                int(info.is_multicast), *group)
    return pack_message(MessageId.SERVERINFO, payload)


def unpack_server_info(payload: bytes) -> ServerInfo:
    if len(payload) < _SENDER.size:
        raise NatNetProtocolError(f"SERVERINFO: {len(payload)} bytes, expected at least "
                                  f"{_SENDER.size}", "truncated")
    if len(payload) < _SERVER_INFO.size:
        fields = _SENDER.unpack_from(payload)
        return ServerInfo(_decode_name(fields[0], "SERVERINFO"), fields[1:5], fields[5:9],
                          0, DATA_PORT, False, MULTICAST_GROUP)
    fields = _SERVER_INFO.unpack_from(payload)
    return ServerInfo(_decode_name(fields[0], "SERVERINFO"), fields[1:5], fields[5:9],
                      fields[9], fields[10], bool(fields[11]),
                      socket.inet_ntoa(bytes(fields[12:16])))


# --- model definitions ----------------------------------------------------------------------
def pack_model_definitions(descriptions: list[RigidBodyDescription]) -> bytes:
    parts = [_INT32.pack(len(descriptions))]
    for description in descriptions:
        body = (_encode_name(description.name) + b"\0"
                + struct.pack("<ii3fi", description.id, description.parent_id,
                              *description.offset_m, 0))
        parts.append(struct.pack("<ii", RIGID_BODY_DESCRIPTION_TYPE, len(body)) + body)
    return pack_message(MessageId.MODELDEF, b"".join(parts))


def unpack_model_definitions(payload: bytes) -> list[RigidBodyDescription]:
    """The rigid-body descriptions of a MODELDEF payload (other types skipped by size)."""
    reader = _Reader(payload, "MODELDEF")
    count = reader.int32()
    if count < 0:
        raise NatNetProtocolError(f"MODELDEF: negative description count {count}")
    descriptions = []
    for index in range(count):
        kind, size = reader.int32(), reader.int32()
        body = _Reader(reader.take(size), f"MODELDEF description {index} (type {kind})")
        if kind == RIGID_BODY_DESCRIPTION_TYPE:
            name = body.string()
            body_id, parent_id, *offset = body.unpack(struct.Struct("<ii3f"))
            descriptions.append(RigidBodyDescription(name, body_id, parent_id, tuple(offset)))
    return descriptions


# --- frame of data --------------------------------------------------------------------------
def pack_frame_of_data(frame: FrameOfData) -> bytes:
    """FRAMEOFDATA with only the rigid-body section filled (the others empty)."""
    bodies = b"".join(
        RIGID_BODY.pack(body.id, *body.position_m, *body.quaternion_xyzw,
                        body.mean_marker_error_m, TRACKING_VALID_BIT if body.tracking_valid else 0)
        for body in frame.rigid_bodies)
    sections = [struct.pack("<ii", 0, 0)] * SECTION_COUNT
    sections[RIGID_BODY_SECTION] = struct.pack("<ii", len(frame.rigid_bodies), len(bodies)) + bodies
    suffix = SUFFIX.pack(frame.timecode, frame.timecode_sub, frame.timestamp_s,
                         frame.camera_mid_exposure_ticks, frame.data_received_ticks,
                         frame.transmit_ticks, frame.precision_timestamp_s,
                         frame.precision_timestamp_fraction, frame.params)
    return pack_message(MessageId.FRAMEOFDATA,
                        _INT32.pack(frame.frame_number) + b"".join(sections) + suffix)


def unpack_frame_of_data(payload: bytes) -> FrameOfData:
    reader = _Reader(payload, "FRAMEOFDATA")
    frame_number = reader.int32()
    bodies: tuple[RigidBodySample, ...] = ()
    for section in range(SECTION_COUNT):
        count, size = reader.int32(), reader.int32()
        if count < 0 or size < 0:
            raise NatNetProtocolError(f"FRAMEOFDATA section {section}: negative count {count} "
                                      f"or size {size}")
        data = reader.take(size)
        if section == RIGID_BODY_SECTION:
            if size != count * RIGID_BODY.size:
                raise NatNetProtocolError(
                    f"FRAMEOFDATA rigid bodies: {count} bodies need {count * RIGID_BODY.size} "
                    f"bytes, section size says {size}")
            bodies = tuple(_rigid_body(fields) for fields in RIGID_BODY.iter_unpack(data))
    (timecode, timecode_sub, timestamp_s, mid_exposure, received, transmit, precision_s,
     precision_fraction, params) = reader.unpack(SUFFIX)
    return FrameOfData(frame_number, bodies, timestamp_s, timecode, timecode_sub, mid_exposure,
                       received, transmit, precision_s, precision_fraction, params)


def _rigid_body(fields: tuple) -> RigidBodySample:
    body_id, x, y, z, qx, qy, qz, qw, error_m, params = fields
    return RigidBodySample(body_id, (x, y, z), (qx, qy, qz, qw), error_m,
                           bool(params & TRACKING_VALID_BIT))
