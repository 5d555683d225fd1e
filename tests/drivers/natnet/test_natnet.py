"""NatNet client against the fake Motive over real UDP sockets on 127.0.0.1: wire round trip
and quaternion order, MODELDEF naming, untracked bodies, malformed packets, staleness and
recovery, dropout, latency, multicast on loopback, and a MuJoCo TeamSimulation as the source."""

from __future__ import annotations

import contextlib
import socket
import struct
import time

import numpy as np
import pytest

from core.plant.standard_scenarios import ring_team_settings
from drivers.interfaces import JointCommand, MocapSource
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.natnet.client import MocapLostError, NatNetClient, NatNetClientConfig, NatNetError
from drivers.natnet.fake import FakeNatNetServer, simulation_pose_source
from drivers.natnet.protocol import (
    COMMAND_PORT,
    FrameOfData,
    MessageId,
    NatNetProtocolError,
    RigidBodyDescription,
    RigidBodySample,
    ServerInfo,
    pack_frame_of_data,
    pack_message,
    pack_model_definitions,
    pack_server_info,
    unpack_frame_of_data,
    unpack_message,
    unpack_model_definitions,
    unpack_server_info,
)
from drivers.robot_descriptions import srb_parameters

# a non-symmetric rotation: swapping (w, x, y, z) <-> (x, y, z, w) gives a different one
QUATERNION_WXYZ = np.array([0.9, 0.1, -0.3, 0.2]) / np.linalg.norm([0.9, 0.1, -0.3, 0.2])
POSES = {"robot": (np.array([1.0, -2.0, 0.3]), QUATERNION_WXYZ),
         "payload": (np.array([0.5, 0.25, 0.45]), np.array([1.0, 0.0, 0.0, 0.0]))}
WAIT_S = 2.0


def _free_udp_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def _wait_until(condition, timeout_s: float = WAIT_S) -> bool:
    deadline_s = time.monotonic() + timeout_s
    while not condition():
        if time.monotonic() > deadline_s:
            return False
        time.sleep(0.002)
    return True


@contextlib.contextmanager
def _connected(source=lambda: POSES, client_options=None, **server_options):
    """(server, client) on free loopback ports, connected (names known, client registered)."""
    data_port = _free_udp_port()
    with FakeNatNetServer(source, command_port=0, data_port=data_port,
                          **server_options) as server, \
            NatNetClient(NatNetClientConfig(command_port=server.command_port,
                                            data_port=data_port,
                                            **(client_options or {}))) as client:
        assert _wait_until(lambda: client.is_ready() and bool(server.clients))
        yield server, client


@pytest.fixture
def link(request):
    """``_connected`` with options from an indirect parameter."""
    options = dict(getattr(request, "param", {}))
    with _connected(client_options=options.pop("client", None), **options) as pair:
        yield pair


def _publish_and_wait(server: FakeNatNetServer, client: NatNetClient):
    previous = client.latest()
    assert server.publish_frame()
    frame = client.wait_for_frame(WAIT_S, newer_than=previous)
    assert frame is not None
    return frame


# --- protocol -------------------------------------------------------------------------------
def _frame() -> FrameOfData:
    bodies = (RigidBodySample(3, (1.0, 2.0, 3.0), (0.1, 0.2, 0.3, 0.9), 0.001, True),
              RigidBodySample(-4, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0), 0.0, False))
    return FrameOfData(17, bodies, 12.5, 1, 2, 3, 4, 5, 6, 7, params=2)


def test_protocol_round_trips():
    message_id, payload = unpack_message(pack_frame_of_data(_frame()))
    assert message_id == MessageId.FRAMEOFDATA
    decoded = unpack_frame_of_data(payload)
    assert decoded.frame_number == 17 and decoded.timestamp_s == 12.5
    assert decoded.tracked_models_changed
    assert [b.id for b in decoded.rigid_bodies] == [3, -4]
    assert [b.tracking_valid for b in decoded.rigid_bodies] == [True, False]
    np.testing.assert_allclose(decoded.rigid_bodies[0].quaternion_xyzw, (0.1, 0.2, 0.3, 0.9),
                               rtol=1e-6)
    descriptions = [RigidBodyDescription("go2_0", 1), RigidBodyDescription("payload", 9, 1)]
    assert unpack_model_definitions(
        unpack_message(pack_model_definitions(descriptions))[1]) == descriptions
    info = ServerInfo("Motive", data_port=4321, is_multicast=True)
    assert unpack_server_info(unpack_message(pack_server_info(info))[1]) == info


def test_truncated_and_corrupted_packets_raise_protocol_errors_only():
    packets = [pack_frame_of_data(_frame()),
               pack_model_definitions([RigidBodyDescription("go2_0", 1)]),
               pack_server_info(ServerInfo())]
    decoders = {MessageId.FRAMEOFDATA: unpack_frame_of_data,
                MessageId.MODELDEF: unpack_model_definitions,
                MessageId.SERVERINFO: unpack_server_info}
    for packet in packets:
        for length in range(len(packet)):  # header size field no longer matches
            with pytest.raises(NatNetProtocolError):
                unpack_message(packet[:length])
        message_id, payload = unpack_message(packet)
        # consistent header, truncated content (SERVERINFO may stop after the NatNet version)
        shortest = 264 if message_id == MessageId.SERVERINFO else len(payload)
        for length in range(shortest):
            with pytest.raises(NatNetProtocolError):
                decoders[message_id](payload[:length])
    rng = np.random.default_rng(0)
    frame_payload = unpack_message(packets[0])[1]
    for _ in range(300):
        corrupted = bytearray(frame_payload)
        corrupted[rng.integers(len(corrupted))] = rng.integers(256)
        with contextlib.suppress(NatNetProtocolError):  # anything else fails the test
            unpack_frame_of_data(bytes(corrupted))
    bad_section = bytearray(frame_payload)
    struct.pack_into("<i", bad_section, 4 + 2 * 8, 1)  # rigid body count 1, size for 2
    with pytest.raises(NatNetProtocolError, match="rigid bodies"):
        unpack_frame_of_data(bytes(bad_section))


# --- client against the fake ----------------------------------------------------------------
def test_pose_round_trip_names_from_modeldef_and_quaternion_order(link):
    server, client = link
    assert isinstance(client, MocapSource)
    assert client.body_ids == server.body_ids == {"robot": 1, "payload": 2}
    assert client.server_info is not None and client.server_info.data_port == server.data_port
    # unicast: frames come back to the socket that sent CONNECT, not to a data port
    assert client.receive_port != client.data_port
    assert server.connects == 1 and server.keepalives_received >= 1
    frame = _publish_and_wait(server, client)
    assert set(frame.poses) == {"robot", "payload"}
    position_m, quaternion_wxyz = frame.poses["robot"]
    np.testing.assert_allclose(position_m, POSES["robot"][0], atol=1e-6)
    np.testing.assert_allclose(quaternion_wxyz, QUATERNION_WXYZ, atol=1e-6)
    assert client.counters.frames_received == 1 and client.counters.packets_rejected == 0


@pytest.mark.parametrize("link", [{"body_ids": {"robot": 7, "payload": 8},
                                   "client": {"body_ids": {"robot": 7}}}], indirect=True)
def test_configured_ids_name_bodies_and_others_are_unknown(link):
    server, client = link
    assert server.model_requests == 0  # names configured: no MODELDEF needed
    frame = _publish_and_wait(server, client)
    assert set(frame.poses) == {"robot"}
    np.testing.assert_allclose(frame.poses["robot"][1], QUATERNION_WXYZ, atol=1e-6)
    assert client.counters.bodies_unknown == 1


def test_untracked_body_is_dropped_and_counted(link):
    server, client = link
    server.set_tracked("payload", False)
    assert set(_publish_and_wait(server, client).poses) == {"robot"}
    assert client.counters.bodies_untracked == 1
    server.set_tracked("payload", True)
    assert set(_publish_and_wait(server, client).poses) == {"robot", "payload"}


def test_malformed_packets_are_counted_and_ignored(link):
    server, client = link
    good = pack_frame_of_data(FrameOfData(1, (RigidBodySample(1, (0, 0, 0), (0, 0, 0, 1)),)))
    message_id, payload = unpack_message(good)
    server.send_packet(b"\x07")  # shorter than a header
    server.send_packet(good[:-5])  # truncated: header size no longer matches
    server.send_packet(pack_message(message_id, payload[:30]))  # consistent header, cut frame
    server.send_packet(pack_message(55, b""))  # unknown message id
    assert _wait_until(lambda: client.counters.packets_rejected == 4)
    assert client.latest() is None
    frame = _publish_and_wait(server, client)
    assert set(frame.poses) == {"robot", "payload"}
    assert client.counters.frames_received == 1


# 0.5 s: a margin that holds on a loaded 2-core machine (the behaviour, not the figure)
@pytest.mark.parametrize("link", [{"client": {"stale_timeout_s": 0.5}}], indirect=True)
def test_staleness_detected_and_recovery_after_the_stream_resumes(link):
    server, client = link
    assert client.latest() is None and client.is_stale()
    with pytest.raises(MocapLostError, match="no NatNet frame"):
        client.check()
    _publish_and_wait(server, client)
    assert not client.is_stale() and client.age_s() < 0.5
    client.check()
    time.sleep(0.6)
    assert client.is_stale()
    with pytest.raises(MocapLostError):
        client.check()
    server.start_streaming(rate_hz=200.0)
    assert _wait_until(lambda: not client.is_stale())
    server.stop_streaming()
    assert client.counters.frames_received > 1


@pytest.mark.parametrize("link", [{"dropout_probability": 0.5, "seed": 3}], indirect=True)
def test_dropout_loses_frames_and_the_client_counts_the_gaps(link):
    server, client = link
    for _ in range(40):
        server.publish_frame()
    assert 5 < server.frames_dropped < 35
    assert _wait_until(lambda: client.counters.frames_received == server.frames_published)
    assert client.counters.frames_missed > 0
    assert client.counters.frames_missed <= server.frames_dropped


@pytest.mark.parametrize("link", [{"latency_s": 0.05}], indirect=True)
def test_latency_delays_delivery(link):
    server, client = link
    start_s = time.monotonic()
    server.publish_frame()
    assert client.latest() is None
    assert client.wait_for_frame(WAIT_S) is not None
    assert time.monotonic() - start_s >= 0.045


@pytest.mark.parametrize("link", [{"position_noise_m": 0.01, "angle_noise_rad": 0.02}],
                         indirect=True)
def test_noise_has_the_configured_spread(link):
    server, client = link
    errors_m, angles_rad = [], []
    for _ in range(60):
        position_m, quaternion_wxyz = _publish_and_wait(server, client).poses["robot"]
        errors_m.append(position_m - POSES["robot"][0])
        angles_rad.append(2 * np.arccos(min(1.0, abs(quaternion_wxyz @ QUATERNION_WXYZ))))
    assert np.std(errors_m) == pytest.approx(0.01, rel=0.3)
    # the angle of a 3-D Gaussian rotation vector is Maxwell distributed: mean 2 sqrt(2/pi) s
    assert np.mean(angles_rad) == pytest.approx(0.02 * 2 * np.sqrt(2 / np.pi), rel=0.3)


def test_new_body_triggers_a_new_modeldef():
    poses = dict(POSES)
    with _connected(lambda: poses) as (server, client):
        poses["obstacle_0"] = (np.zeros(3), np.array([1.0, 0.0, 0.0, 0.0]))  # new in Motive
        server.publish_frame()
        assert _wait_until(lambda: "obstacle_0" in client.body_ids)
        assert client.body_ids == server.body_ids
        assert set(_publish_and_wait(server, client).poses) == set(poses)


@pytest.mark.parametrize("link", [{"multicast": True, "client": {"multicast": True}}],
                         indirect=True)
def test_multicast_on_loopback(link):
    server, client = link
    assert client.server_info is not None and client.server_info.is_multicast
    assert client.counters.keepalives_sent == 0
    frame = _publish_and_wait(server, client)
    np.testing.assert_allclose(frame.poses["robot"][1], QUATERNION_WXYZ, atol=1e-6)


def test_team_simulation_poses_through_the_wire():
    team = ring_team_settings(["go2", "go2"], srb_parameters)
    scene = build_team_scene(team, obstacles=[(1.5, 0.5, 0.2, 0.5)])
    simulation = TeamSimulation(scene)
    for robot in scene.robots:
        simulation.robot_driver(robot.name).send(
            JointCommand.hold(scene.initial_qpos[robot.leg_qpos_addresses], 100.0, 5.0))
    simulation.apply_push("payload", np.array([0.0, 0.0, 30.0]), 0.05)  # tilt things a bit
    simulation.step(50)
    with _connected(simulation_pose_source(simulation),
                    timestamp_source=lambda: simulation.time_s) as (server, client):
        frame = _publish_and_wait(server, client)
        assert frame.time_s == pytest.approx(simulation.time_s)
        assert set(frame.poses) == {"go2_0", "go2_1", "payload", "obstacle_0"}
        for name in ("go2_0", "go2_1"):
            position_m, quaternion_wxyz = simulation.base_pose(name)
            np.testing.assert_allclose(frame.poses[name][0], position_m, atol=1e-6)
            np.testing.assert_allclose(frame.poses[name][1], quaternion_wxyz, atol=1e-6)
        np.testing.assert_allclose(frame.poses["payload"][1], simulation.payload_pose()[1],
                                   atol=1e-6)
        np.testing.assert_allclose(frame.poses["obstacle_0"][0], [1.5, 0.5, 0.25], atol=1e-6)
        client.close()
        assert _wait_until(lambda: not server.clients)  # the client said DISCONNECT


def test_packets_from_another_host_are_rejected(link):
    """127.0.0.2 is loopback too, but not the configured server (127.0.0.1)."""
    server, client = link
    frame = pack_frame_of_data(FrameOfData(1, (RigidBodySample(1, (0, 0, 0), (0, 0, 0, 1)),)))
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as stranger:
        stranger.bind(("127.0.0.2", 0))
        for _ in range(3):
            stranger.sendto(frame, ("127.0.0.1", client.data_port))
    assert _wait_until(lambda: client.counters.rejection_reasons.get("foreign sender") == 3)
    assert client.latest() is None and client.counters.frames_received == 0
    assert set(_publish_and_wait(server, client).poses) == {"robot", "payload"}


def test_a_frame_from_an_older_time_is_no_fresh_frame(link):
    server, client = link
    body = (RigidBodySample(1, (0.5, 0.0, 0.0), (0, 0, 0, 1)),)
    server.send_packet(pack_frame_of_data(FrameOfData(5000, body, timestamp_s=12.5)))
    assert _wait_until(lambda: client.counters.frames_received == 1)
    server.send_packet(pack_frame_of_data(FrameOfData(5001, body, timestamp_s=12.0)))
    assert _wait_until(lambda: client.counters.rejection_reasons.get("timestamp backwards") == 1)
    assert client.latest().time_s == 12.5 and client.counters.frames_received == 1
    server.send_packet(pack_frame_of_data(FrameOfData(5002, body, timestamp_s=12.6)))
    assert _wait_until(lambda: client.counters.frames_received == 2)
    # a restarted server (frame numbers, far back, and clock from zero) is followed
    server.send_packet(pack_frame_of_data(FrameOfData(1, body, timestamp_s=0.01)))
    assert _wait_until(lambda: client.counters.frames_received == 3)


def test_an_unresolvable_server_address_is_a_clear_error():
    with pytest.raises(NatNetError, match="server_address 'no-such-mocap.invalid'"):
        NatNetClient(NatNetClientConfig(server_address="no-such-mocap.invalid"))


# --- interoperability with OptiTrack's own behaviour (unicast) -------------------------------
def test_the_fake_serves_a_client_written_like_optitracks_sample():
    """OptiTrack's NatNet SDK sample client (NatNetClient.py), unicast: its data socket is bound
    to an ephemeral port it never announces; it sends CONNECT ("Ping") and keep-alives from
    its command socket and reads frames there. Built from raw bytes here, not porter's code."""
    poses = {"robot": POSES["robot"]}
    with FakeNatNetServer(lambda: poses, command_port=0, data_port=_free_udp_port()) as server, \
            socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as command, \
            socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as data:
        command.bind(("127.0.0.1", 0))
        data.bind(("127.0.0.1", 0))  # the sample's unicast data socket: never used
        command.settimeout(WAIT_S)
        target = ("127.0.0.1", server.command_port)
        command.sendto(struct.pack("<HH", 0, 5) + b"Ping\0", target)  # NAT_CONNECT
        message_id, _ = struct.unpack_from("<HH", command.recv(0x10000))
        assert message_id == 1  # NAT_SERVERINFO, to the command socket
        command.sendto(struct.pack("<HH", 10, 0) + b"\0", target)  # NAT_KEEPALIVE
        assert _wait_until(lambda: server.keepalives_received == 1)
        received = []
        for _ in range(3):
            server.publish_frame()
            packet = command.recv(0x10000)
            assert struct.unpack_from("<H", packet)[0] == 7  # NAT_FRAMEOFDATA
            received.append(unpack_frame_of_data(unpack_message(packet)[1]))
        assert [f.frame_number for f in received] == [1, 2, 3]
        (body,) = received[0].rigid_bodies
        np.testing.assert_allclose(body.position_m, POSES["robot"][0], atol=1e-6)
        data.setblocking(False)
        with pytest.raises(BlockingIOError):  # nothing was sent to a data port
            data.recv(0x10000)


def test_the_client_receives_from_a_motive_style_unicast_server():
    """A server that behaves as Motive does in unicast: it answers on its command port and
    sends frames, from another socket, to the address the client's requests came from (it
    knows no data port of the client's)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as server, \
            socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as server_data:
        server.bind(("127.0.0.1", 0))
        server_data.bind(("127.0.0.1", 0))
        server.settimeout(WAIT_S)
        config = NatNetClientConfig(command_port=server.getsockname()[1], data_port=COMMAND_PORT)
        with NatNetClient(config) as client:
            requester = None
            while not client.is_ready():
                packet, requester = server.recvfrom(0x10000)
                message_id, _ = unpack_message(packet)
                if message_id == MessageId.CONNECT:
                    server.sendto(pack_server_info(ServerInfo("Motive")), requester)
                elif message_id == MessageId.REQUEST_MODELDEF:
                    server.sendto(pack_model_definitions([RigidBodyDescription("robot", 3)]),
                                  requester)
            assert requester is not None and requester[1] == client.receive_port
            position, (w, x, y, z) = POSES["robot"]
            frame = FrameOfData(1, (RigidBodySample(3, tuple(position), (x, y, z, w)),))
            server_data.sendto(pack_frame_of_data(frame), requester)
            assert client.wait_for_frame(WAIT_S, ["robot"])
            np.testing.assert_allclose(client.latest().poses["robot"][1], QUATERNION_WXYZ,
                                       atol=1e-6)
