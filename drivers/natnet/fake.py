"""A fake OptiTrack Motive: a NatNet 4.1 server on loopback, fed by a pose callable.

``FakeNatNetServer`` speaks the same wire protocol as Motive (``drivers.natnet.protocol``):
it answers CONNECT with SERVERINFO and REQUEST_MODELDEF with MODELDEF, tracks KEEPALIVE and
DISCONNECT per client, and streams FRAMEOFDATA either unicast to each connected client — to
the address and port its CONNECT and keep-alives came from, as Motive does (OptiTrack's sample
client binds its unicast data socket to an ephemeral port it never announces and receives the
frames on the socket that sent CONNECT) — or to the multicast group on ``data_port`` (sent on
the ``host`` interface).

Poses come from ``pose_source() -> {name: (position [m] (3,), quaternion wxyz (4,))}``, world
frame, e.g. ``simulation_pose_source(TeamSimulation)``: robot bases by robot name, the
payload and the obstacles. Optional imperfections, all seeded: Gaussian position noise
[m] per coordinate, Gaussian rotation-vector noise [rad] per component (world frame, applied
on the left, as ``TeamSimulation`` does), a constant delivery latency [s], and a dropout
probability per frame (a dropped frame still uses up its frame number, as a lost datagram
would). ``set_tracked(name, False)`` streams that body with its tracking-valid bit clear.

Stepping: ``publish_frame()`` samples and sends one frame now (deterministic, from the
caller's thread); ``start_streaming(rate_hz)`` does so from a thread at a real-time rate,
in which case ``pose_source`` is called from that thread and must be safe to call there.
"""

from __future__ import annotations

import collections
import contextlib
import select
import socket
import threading
import time
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING

import numpy as np

from core.model.conventions import PAYLOAD_NAME
from core.model.rotations import cross3
from drivers.interfaces import Pose
from drivers.natnet.protocol import (
    COMMAND_PORT,
    DATA_PORT,
    MULTICAST_GROUP,
    FrameOfData,
    MessageId,
    NatNetProtocolError,
    RigidBodyDescription,
    RigidBodySample,
    ServerInfo,
    pack_frame_of_data,
    pack_model_definitions,
    pack_server_info,
    unpack_message,
)

if TYPE_CHECKING:
    from drivers.mujoco.simulation import TeamSimulation

PoseSource = Callable[[], Mapping[str, Pose]]
_POLL_S = 0.01
_TICKS_PER_S = 1_000_000_000


class FakeNatNetServer:
    """NatNet server on ``host`` (loopback by default); starts its command thread at once.

    ``body_ids`` maps names to streaming ids; by default the names of the first
    ``pose_source()`` call get ids 1, 2, ... in order, and later names get the next ids.
    ``timestamp_source`` gives the frame timestamp [s] (default: seconds since start on
    ``clock``). Clients silent for ``client_timeout_s`` stop receiving unicast frames;
    ``data_port`` is the multicast port (and what SERVERINFO announces).
    """

    def __init__(self, pose_source: PoseSource, *, body_ids: Mapping[str, int] | None = None,
                 host: str = "127.0.0.1", command_port: int = COMMAND_PORT,
                 data_port: int = DATA_PORT, multicast: bool = False,
                 multicast_group: str = MULTICAST_GROUP, position_noise_m: float = 0.0,
                 angle_noise_rad: float = 0.0, latency_s: float = 0.0,
                 dropout_probability: float = 0.0, seed: int = 0,
                 timestamp_source: Callable[[], float] | None = None,
                 client_timeout_s: float = 5.0,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if not 0.0 <= dropout_probability <= 1.0:
            raise ValueError(f"dropout probability {dropout_probability} is not in [0, 1]")
        self._pose_source = pose_source
        self.host, self.data_port, self.multicast = host, data_port, multicast
        self.multicast_group = multicast_group
        self.position_noise_m, self.angle_noise_rad = position_noise_m, angle_noise_rad
        self.latency_s, self.dropout_probability = latency_s, dropout_probability
        self.client_timeout_s = client_timeout_s
        self._clock = clock
        self._start_s = clock()
        self._timestamp_source = timestamp_source or (lambda: self._clock() - self._start_s)
        self._rng = np.random.default_rng(seed)
        self._body_ids = dict(body_ids) if body_ids is not None else {
            name: index + 1 for index, name in enumerate(pose_source())}
        self._models_changed = False
        self._untracked: set[str] = set()
        self._lock = threading.Lock()
        self.clients: dict[tuple[str, int], float] = {}  # command address -> last heard [s]
        self.connects = self.keepalives_received = self.model_requests = 0
        self.frames_published = self.frames_dropped = 0
        self._frame_number = 0
        # fault injection: frames keep coming (numbers, timestamps rising) with the last poses;
        # ``rewind``: each frame's timestamp 1 ms before the previous one
        self.frozen = False
        self.rewind = False
        self.last_packet: bytes | None = None  # the newest frame packet
        self._last_timestamp_s = 0.0
        self._last_bodies: list[RigidBodySample] = []
        self._command_socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._command_socket.bind((host, command_port))
        self._data_socket = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self._data_socket.bind((host, 0))
        if multicast:
            self._data_socket.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_IF,
                                         socket.inet_aton(host))
            self._data_socket.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
            self._data_socket.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, 1)
        self._stop = threading.Event()
        self._streaming: threading.Thread | None = None
        self._stop_streaming = threading.Event()
        self._pending: collections.deque[tuple[float, bytes]] = collections.deque()
        self._pending_ready = threading.Condition(self._lock)
        self._threads = [threading.Thread(target=self._serve_commands, daemon=True,
                                          name="natnet-fake-commands")]
        if latency_s > 0.0:
            self._threads.append(threading.Thread(target=self._deliver_late, daemon=True,
                                                  name="natnet-fake-latency"))
        for thread in self._threads:
            thread.start()

    @property
    def command_port(self) -> int:
        return int(self._command_socket.getsockname()[1])

    @property
    def body_ids(self) -> dict[str, int]:
        with self._lock:
            return dict(self._body_ids)

    def set_tracked(self, name: str, tracked: bool) -> None:
        """Stream body ``name`` with its tracking-valid bit set (True) or clear (False)."""
        with self._lock:
            (self._untracked.discard if tracked else self._untracked.add)(name)

    # --- streaming ----------------------------------------------------------------------------
    def publish_frame(self) -> bool:
        """Sample ``pose_source`` and send one frame (after ``latency_s``); False if dropped."""
        self._frame_number += 1
        if self._rng.random() < self.dropout_probability:
            self.frames_dropped += 1
            return False
        timestamp_s = float(self._timestamp_source())
        if self.rewind:
            timestamp_s = self._last_timestamp_s - 0.001
        self._last_timestamp_s = timestamp_s
        ticks = int(self._clock() * _TICKS_PER_S)
        bodies = []
        with self._lock:
            for name, (position_m, quaternion_wxyz) in (
                    {} if self.frozen and self._last_bodies else self._pose_source()).items():
                if name not in self._body_ids:
                    self._body_ids[name] = max(self._body_ids.values(), default=0) + 1
                    self._models_changed = True
                position_m, quaternion_wxyz = self._add_noise(position_m, quaternion_wxyz)
                w, x, y, z = quaternion_wxyz
                bodies.append(RigidBodySample(
                    self._body_ids[name], tuple(position_m), (x, y, z, w),
                    tracking_valid=name not in self._untracked))
            if self.frozen and self._last_bodies:
                bodies = list(self._last_bodies)
            self._last_bodies = bodies
            params = 0x02 if self._models_changed else 0
            self._models_changed = False
        packet = pack_frame_of_data(FrameOfData(
            self._frame_number, tuple(bodies), timestamp_s, camera_mid_exposure_ticks=ticks,
            data_received_ticks=ticks, transmit_ticks=ticks, params=params))
        self.frames_published += 1
        self.last_packet = packet
        if self.latency_s > 0.0:
            with self._pending_ready:
                self._pending.append((self._clock() + self.latency_s, packet))
                self._pending_ready.notify()
        else:
            self.send_packet(packet)
        return True

    def send_foreign(self, packet: bytes, source_host: str = "127.0.0.2") -> None:
        """Send ``packet`` to the data destinations from another host (fault injection: a
        second NatNet server or a spoofer on the network; on loopback any 127.x address)."""
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as foreign:
            foreign.bind((source_host, 0))
            for destination in self._destinations():
                foreign.sendto(packet, destination)

    def send_packet(self, packet: bytes) -> None:
        """Send raw bytes to the data destinations now (fault injection: malformed packets)."""
        for destination in self._destinations():
            with contextlib.suppress(OSError):  # nobody listening: dropped, as on the wire
                self._data_socket.sendto(packet, destination)

    def start_streaming(self, rate_hz: float) -> None:
        """Call ``publish_frame`` from a thread every 1 / ``rate_hz`` seconds (real time)."""
        self.stop_streaming()
        self._stop_streaming.clear()
        self._streaming = threading.Thread(target=self._stream, args=(1.0 / rate_hz,),
                                           daemon=True, name="natnet-fake-stream")
        self._streaming.start()

    def stop_streaming(self) -> None:
        if self._streaming is not None:
            self._stop_streaming.set()
            self._streaming.join(timeout=1.0)
            self._streaming = None

    def close(self) -> None:
        self.stop_streaming()
        self._stop.set()
        with self._pending_ready:
            self._pending_ready.notify()
        for thread in self._threads:
            thread.join(timeout=1.0)
        self._command_socket.close()
        self._data_socket.close()

    def __enter__(self) -> FakeNatNetServer:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def _stream(self, period_s: float) -> None:
        next_s = time.monotonic()
        while not self._stop_streaming.is_set():
            self.publish_frame()
            next_s += period_s
            self._stop_streaming.wait(max(0.0, next_s - time.monotonic()))

    def _destinations(self) -> list[tuple[str, int]]:
        if self.multicast:
            return [(self.multicast_group, self.data_port)]
        now_s = self._clock()
        with self._lock:
            return [address for address, heard_s in self.clients.items()
                    if now_s - heard_s <= self.client_timeout_s]

    def _deliver_late(self) -> None:
        while not self._stop.is_set():
            with self._pending_ready:
                if not self._pending:
                    self._pending_ready.wait(_POLL_S)
                    continue
                due_s, packet = self._pending[0]
                if self._clock() < due_s:
                    self._pending_ready.wait(min(_POLL_S, due_s - self._clock()))
                    continue
                self._pending.popleft()
            self.send_packet(packet)

    # --- commands -------------------------------------------------------------------------
    def _serve_commands(self) -> None:
        while not self._stop.is_set():
            try:
                readable, _, _ = select.select([self._command_socket], [], [], _POLL_S)
                if readable:
                    packet, address = self._command_socket.recvfrom(0x10000)
                    self._answer(packet, address)
            except (OSError, ValueError):
                if self._stop.is_set():
                    return

    def _answer(self, packet: bytes, address: tuple[str, int]) -> None:
        try:
            message_id, _ = unpack_message(packet)
        except NatNetProtocolError:
            return
        with self._lock:
            if message_id in (MessageId.CONNECT, MessageId.KEEPALIVE):
                self.clients[address] = self._clock()
            elif message_id == MessageId.DISCONNECT:
                self.clients.pop(address, None)
            descriptions = [RigidBodyDescription(name, body_id)
                            for name, body_id in self._body_ids.items()]
        if message_id == MessageId.CONNECT:
            self.connects += 1
            self._command_socket.sendto(pack_server_info(ServerInfo(
                application_name="porter FakeNatNetServer", high_resolution_clock_hz=_TICKS_PER_S,
                data_port=self.data_port, is_multicast=self.multicast,
                multicast_group=self.multicast_group)), address)
        elif message_id == MessageId.KEEPALIVE:
            self.keepalives_received += 1
        elif message_id == MessageId.REQUEST_MODELDEF:
            self.model_requests += 1
            self._command_socket.sendto(pack_model_definitions(descriptions), address)

    def _add_noise(self, position_m: np.ndarray, quaternion_wxyz: np.ndarray) -> Pose:
        position_m = np.asarray(position_m, dtype=float)
        quaternion_wxyz = np.asarray(quaternion_wxyz, dtype=float)
        if self.position_noise_m > 0.0:
            position_m = position_m + self._rng.normal(0.0, self.position_noise_m, 3)
        if self.angle_noise_rad > 0.0:
            rotation_vector = self._rng.normal(0.0, self.angle_noise_rad, 3)
            quaternion_wxyz = _multiply(_quaternion_from_rotation_vector(rotation_vector),
                                        quaternion_wxyz)
        return position_m, quaternion_wxyz


def simulation_pose_source(simulation: TeamSimulation,
                           include_obstacles: bool = True) -> PoseSource:
    """Ground-truth poses of a ``TeamSimulation``: each robot base (by robot name), the
    ``"payload"`` and, optionally, each obstacle geom (by geom name), world frame."""
    scene, model = simulation.scene, simulation.model
    obstacles = [(model.geom(geom).name, index)
                 for index, geom in enumerate(scene.obstacle_geom_ids)] if include_obstacles \
        else []

    def poses() -> dict[str, Pose]:
        current = {robot.name: simulation.base_pose(robot.name) for robot in scene.robots}
        current[PAYLOAD_NAME] = simulation.payload_pose()
        for name, index in obstacles:
            current[name] = simulation.obstacle_pose(index)
        return current
    return poses


def _quaternion_from_rotation_vector(rotation_vector_rad: np.ndarray) -> np.ndarray:
    angle_rad = float(np.linalg.norm(rotation_vector_rad))
    if angle_rad == 0.0:
        return np.array([1.0, 0.0, 0.0, 0.0])
    axis = rotation_vector_rad / angle_rad
    return np.concatenate([[np.cos(angle_rad / 2)], np.sin(angle_rad / 2) * axis])


def _multiply(a_wxyz: np.ndarray, b_wxyz: np.ndarray) -> np.ndarray:
    """Hamilton product a * b of quaternions (w, x, y, z)."""
    aw, av = a_wxyz[0], a_wxyz[1:]
    bw, bv = b_wxyz[0], b_wxyz[1:]
    return np.concatenate([[aw * bw - av @ bv], aw * bv + bw * av + cross3(av, bv)])
