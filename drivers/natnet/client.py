"""OptiTrack NatNet client: the real-MoCap backend of ``MocapSource``.

A background thread receives FRAMEOFDATA over UDP and keeps the most recent one as a
``MocapFrame``: rigid-body name -> (position [m], quaternion (w, x, y, z)), world frame being
Motive's streaming frame (configure Motive for metres and z up). NatNet's (qx, qy, qz, qw) is
reordered here, and only here. ``MocapFrame.time_s`` is the server's frame timestamp [s];
``age_s`` measures on the local ``clock`` how long ago the last frame arrived, so that the
caller detects MoCap loss (``is_stale``, ``check``).

Modes (``NatNetClientConfig.multicast``):
- unicast: the client sends CONNECT to the server's command port and a KEEPALIVE every
  ``keepalive_period_s`` from one socket, and the frames arrive on that socket: Motive sends
  them to the address its requests came from (as OptiTrack's sample client expects: its
  unicast data socket is bound to an ephemeral port it never announces). ``data_port`` is
  not used; the data socket is bound to an ephemeral port and still read.
- multicast: the data socket is bound to (group, ``data_port``) and joins the group on the
  interface ``local_address``; commands still go unicast to the command port.
Sockets bind to ``local_address`` only (loopback by default), never to all interfaces.

Bodies are named through MODELDEF (requested after SERVERINFO, and again when a frame says
the tracked models changed) unless ``body_ids`` maps names to streaming ids. Bodies whose
tracking-valid bit is clear, with an unknown id, or with non-finite values are dropped and
counted; undecodable packets are counted and ignored, and so are packets from any host but
``server_address`` (another MoCap system, a spoof) and frames whose timestamp goes backwards
while the frame number advances (no fresh measurement: the stream goes stale).
"""

from __future__ import annotations

import math
import select
import socket
import threading
import time
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass, field

import numpy as np

from drivers.interfaces import MocapFrame, Pose
from drivers.natnet.protocol import (
    COMMAND_PORT,
    DATA_PORT,
    MULTICAST_GROUP,
    FrameOfData,
    MessageId,
    NatNetProtocolError,
    ServerInfo,
    pack_connect,
    pack_message,
    unpack_frame_of_data,
    unpack_message,
    unpack_model_definitions,
    unpack_server_info,
)

_RECEIVE_BYTES = 0x10000 + 16
_KNOWN_MESSAGE_IDS = frozenset(int(m) for m in MessageId)
_POLL_S = 0.01
_FRAME_NUMBER_RESTART_GAP = 1000  # a frame number this far back means the server restarted


class NatNetError(RuntimeError):
    """The NatNet client cannot do what was asked."""


class MocapLostError(NatNetError):
    """No MoCap frame arrived within the staleness timeout."""


@dataclass(frozen=True)
class NatNetClientConfig:
    """Where the server is and how to listen. Ports are UDP ports; periods in seconds."""

    server_address: str = "127.0.0.1"
    command_port: int = COMMAND_PORT
    data_port: int = DATA_PORT  # multicast only (unicast frames come to the command socket)
    multicast: bool = False
    multicast_group: str = MULTICAST_GROUP
    local_address: str = "127.0.0.1"  # interface to bind (and join the group) on
    body_ids: Mapping[str, int] | None = None  # name -> streaming id; None: from MODELDEF
    keepalive_period_s: float = 1.0
    request_retry_s: float = 0.25  # resend CONNECT / REQUEST_MODELDEF until answered
    stale_timeout_s: float = 0.1


@dataclass
class NatNetCounters:
    """What the client saw since it started."""

    frames_received: int = 0
    frames_missed: int = 0  # gaps in the frame numbers (dropped on the way)
    frames_out_of_order: int = 0  # older than the latest one, ignored
    packets_rejected: int = 0  # malformed, unknown id, foreign sender, timestamp backwards
    bodies_untracked: int = 0  # tracking-valid bit clear
    bodies_unknown: int = 0  # id without a name
    bodies_invalid: int = 0  # non-finite position or zero quaternion
    keepalives_sent: int = 0
    rejection_reasons: dict[str, int] = field(default_factory=dict)


class NatNetClient:
    """``MocapSource`` fed by a NatNet server; starts receiving on construction."""

    def __init__(self, config: NatNetClientConfig | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.config = config = config or NatNetClientConfig()
        self._clock = clock
        self.counters = NatNetCounters()
        self.server_info: ServerInfo | None = None
        self._names_from_model = config.body_ids is None
        self._id_to_name = {} if config.body_ids is None else {
            body_id: name for name, body_id in config.body_ids.items()}
        self._model_received = not self._names_from_model
        self._latest: MocapFrame | None = None
        self._latest_frame_number: int | None = None
        self._latest_receive_s: float | None = None
        self._next_keepalive_s = self._next_request_s = -math.inf
        self._changed = threading.Condition()
        self._server = (config.server_address, config.command_port)
        try:  # packets are accepted from the server's address only
            self._server_ip = socket.gethostbyname(config.server_address)
        except OSError as error:
            raise NatNetError(f"server_address {config.server_address!r} does not resolve: "
                              f"{error}") from error
        self._latest_timestamp_s: float | None = None
        self._command_socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._data_socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            self._command_socket.bind((config.local_address, 0))
            self._bind_data_socket()
        except OSError as error:
            self._close_sockets()
            raise NatNetError(f"cannot open NatNet sockets on {config.local_address} (data port "
                              f"{config.data_port}): {error}") from error
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="natnet-client", daemon=True)
        self._thread.start()

    def _bind_data_socket(self) -> None:
        config, data = self.config, self._data_socket
        if not config.multicast:
            data.bind((config.local_address, 0))
            return
        data.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        data.bind((config.multicast_group, config.data_port))
        data.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP,
                        socket.inet_aton(config.multicast_group)
                        + socket.inet_aton(config.local_address))

    # --- MocapSource and health -------------------------------------------------------------
    def latest(self) -> MocapFrame | None:
        """The most recent frame (tracked bodies with a name), or None before the first."""
        with self._changed:
            return self._latest

    @property
    def data_port(self) -> int:
        """The UDP port the data socket is bound to (multicast: ``config.data_port`` unless
        that was 0; unicast: an ephemeral one)."""
        return int(self._data_socket.getsockname()[1])

    @property
    def receive_port(self) -> int:
        """The UDP port frames arrive on: the command socket's in unicast (where the server
        sends them), the data socket's in multicast."""
        sock = self._data_socket if self.config.multicast else self._command_socket
        return int(sock.getsockname()[1])

    @property
    def body_ids(self) -> dict[str, int]:
        """Current name -> streaming id map (from the config or the last MODELDEF)."""
        with self._changed:
            return {name: body_id for body_id, name in self._id_to_name.items()}

    def is_ready(self) -> bool:
        """Whether the server answered CONNECT and the body names are known."""
        return self.server_info is not None and self._model_received

    def age_s(self) -> float:
        """Seconds on ``clock`` since the last frame arrived; infinite before the first."""
        with self._changed:
            last_s = self._latest_receive_s
        return math.inf if last_s is None else self._clock() - last_s

    def is_stale(self) -> bool:
        """Whether no frame arrived within ``config.stale_timeout_s``."""
        return self.age_s() > self.config.stale_timeout_s

    def check(self) -> None:
        """Raise ``MocapLostError`` when the stream is stale."""
        age_s = self.age_s()
        if age_s > self.config.stale_timeout_s:
            raise MocapLostError(
                f"no NatNet frame from {self._server[0]} for {age_s:.3f} s (timeout "
                f"{self.config.stale_timeout_s} s; received {self.counters.frames_received}, "
                f"rejected {self.counters.packets_rejected})")

    def wait_for_frame(self, timeout_s: float, names: Collection[str] = (),
                       newer_than: MocapFrame | None = None) -> MocapFrame | None:
        """Block up to ``timeout_s`` (wall time) for a frame holding all ``names`` (and other
        than ``newer_than``); returns it, or None on timeout."""
        def ready() -> bool:
            frame = self._latest
            return (frame is not None and frame is not newer_than
                    and all(name in frame.poses for name in names))
        with self._changed:
            return self._latest if self._changed.wait_for(ready, timeout_s) else None

    def close(self) -> None:
        """Stop the receive thread, say DISCONNECT (unicast) and close the sockets."""
        if self._stop.is_set():
            return
        self._stop.set()
        self._thread.join(timeout=1.0)
        if not self.config.multicast:
            self._send(pack_message(MessageId.DISCONNECT))
        self._close_sockets()

    def __enter__(self) -> NatNetClient:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    # --- receive thread ---------------------------------------------------------------------
    def _run(self) -> None:
        sockets = [self._command_socket, self._data_socket]
        while not self._stop.is_set():
            self._send_due_requests()
            try:
                readable, _, _ = select.select(sockets, [], [], _POLL_S)
                for sock in readable:
                    packet, (sender, _) = sock.recvfrom(_RECEIVE_BYTES)
                    if sender != self._server_ip:  # another host's stream, or a spoof
                        self._reject("foreign sender")
                        continue
                    self._handle(packet)
            except OSError:
                if self._stop.is_set():
                    return
                time.sleep(_POLL_S)  # e.g. ICMP port unreachable before the server is up

    def _send_due_requests(self) -> None:
        now_s = self._clock()
        if now_s >= self._next_request_s and (self.server_info is None
                                              or not self._model_received):
            self._next_request_s = now_s + self.config.request_retry_s
            self._send(pack_connect() if self.server_info is None
                       else pack_message(MessageId.REQUEST_MODELDEF))
        if not self.config.multicast and now_s >= self._next_keepalive_s:
            self._next_keepalive_s = now_s + self.config.keepalive_period_s
            if self._send(pack_message(MessageId.KEEPALIVE)):
                self.counters.keepalives_sent += 1

    def _send(self, packet: bytes) -> bool:
        try:
            self._command_socket.sendto(packet, self._server)
            return True
        except OSError:
            return False

    def _handle(self, packet: bytes) -> None:
        try:
            message_id, payload = unpack_message(packet)
            if message_id == MessageId.FRAMEOFDATA:
                self._on_frame(unpack_frame_of_data(payload))
            elif message_id == MessageId.SERVERINFO:
                self.server_info = unpack_server_info(payload)
                self._next_request_s = -math.inf  # MODELDEF next, without waiting
            elif message_id == MessageId.MODELDEF:
                descriptions = unpack_model_definitions(payload)
                if self._names_from_model:
                    with self._changed:
                        self._id_to_name = {d.id: d.name for d in descriptions}
                    self._model_received = True
            elif message_id not in _KNOWN_MESSAGE_IDS:
                raise NatNetProtocolError(f"unknown message id {message_id}", "unknown message")
        except NatNetProtocolError as error:
            self._reject(error.reason)

    def _reject(self, reason: str) -> None:
        self.counters.packets_rejected += 1
        reasons = self.counters.rejection_reasons
        reasons[reason] = reasons.get(reason, 0) + 1

    def _on_frame(self, frame: FrameOfData) -> None:
        counters = self.counters
        last = self._latest_frame_number
        if (last is not None and frame.frame_number <= last
                and last - frame.frame_number < _FRAME_NUMBER_RESTART_GAP):
            counters.frames_out_of_order += 1
            return
        if (self._latest_timestamp_s is not None and frame.frame_number > (last or 0)
                and frame.timestamp_s < self._latest_timestamp_s):
            # a newer frame from an older time: the server's clock jumped back (a restarted
            # or misbehaving Motive); it is no fresh measurement, so the stream goes stale
            self._reject("timestamp backwards")
            return
        if last is not None and frame.frame_number > last + 1:
            counters.frames_missed += frame.frame_number - last - 1
        if frame.tracked_models_changed and self._names_from_model:
            self._model_received = False  # ask for MODELDEF again
            self._next_request_s = -math.inf
        poses: dict[str, Pose] = {}
        for body in frame.rigid_bodies:
            if not body.tracking_valid:
                counters.bodies_untracked += 1
                continue
            name = self._id_to_name.get(body.id)
            if name is None:
                counters.bodies_unknown += 1
                continue
            position_m = np.array(body.position_m, dtype=float)
            qx, qy, qz, qw = body.quaternion_xyzw
            quaternion_wxyz = np.array([qw, qx, qy, qz], dtype=float)
            norm = float(np.linalg.norm(quaternion_wxyz))
            if not (np.isfinite(position_m).all() and math.isfinite(norm) and norm > 0.5):
                counters.bodies_invalid += 1
                continue
            poses[name] = (position_m, quaternion_wxyz / norm)
        counters.frames_received += 1
        with self._changed:
            self._latest = MocapFrame(time_s=frame.timestamp_s, poses=poses)
            self._latest_frame_number = frame.frame_number
            self._latest_timestamp_s = frame.timestamp_s
            self._latest_receive_s = self._clock()
            self._changed.notify_all()

    def _close_sockets(self) -> None:
        self._command_socket.close()
        self._data_socket.close()
