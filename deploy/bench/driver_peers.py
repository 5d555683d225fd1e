"""The robots' side of ``porter bench drivers``: one child process (a robot is another
machine; here another process with its own interpreter lock) hosting, on loopback,

- a ``FakeGo2`` and a ``FakeA1`` backed by one MuJoCo ``TeamSimulation``, each in *answer*
  mode: it blocks until a command arrives, applies it (``poll_commands``) and publishes one
  state at once, so a round trip measures both ends' transport and codecs without the
  robot's publishing phase (a Go2 publishes at 500 Hz on its own clock; an A1 answers each
  command, as here);
- raw echoes of the same transports that skip porter entirely: a DDS peer that answers a
  pre-built ``LowCmd_`` with a pre-built ``LowState_`` on the same types and QoS, a UDP peer
  that answers a 730-byte datagram with a 891-byte one;
- a ``FakeNatNetServer`` streaming the simulation's poses with ``time.monotonic`` as frame
  timestamp (one clock for both processes on Linux, so one-way latency is measurable), and a
  raw stream of frame-sized datagrams carrying the same stamp.

The parent controls it over a pipe: ``("stream", "natnet"|"raw", rate_hz)``, ``("quiet",)``
and ``("stop",)``, which answers with the peers' counters.
"""

from __future__ import annotations

import socket
import struct
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from multiprocessing.connection import Connection

import numpy as np
from cyclonedds.core import ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from core.plant.standard_scenarios import ring_team_settings
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.natnet.fake import FakeNatNetServer, simulation_pose_source
from drivers.natnet.protocol import FrameOfData, RigidBodySample, pack_frame_of_data
from drivers.robot_descriptions import srb_parameters
from drivers.unitree.a1_fake import FakeA1
from drivers.unitree.a1_udp_layout import encode_low_state
from drivers.unitree.conventions import wire_state_from_measurement
from drivers.unitree.go2_dds_types import LowCmd_, LowState_, low_state_from_wire
from drivers.unitree.go2_driver import topic_name
from drivers.unitree.go2_fake import COMMAND_QUEUE, FakeGo2
from drivers.unitree.peer import PeriodicThread

GO2, A1 = "go2_0", "a1_1"
STAMP = struct.Struct("<d")  # raw stream: time.monotonic() of the send [s]
_WAIT_S = 0.05


@dataclass(frozen=True)
class PeerSpec:
    """Where the peers listen / send. Topic prefixes keep concurrent runs apart."""

    domain_id: int
    go2_topic_prefix: str
    raw_topic_prefix: str
    natnet_data_port: int  # the parent's NatNet client data port
    raw_stream_port: int  # the parent's raw stream socket


def _answer(wait: Callable[[float], bool], answer: Callable[[], object],
            stop: threading.Event) -> threading.Thread:
    def loop() -> None:
        while not stop.is_set():
            if wait(_WAIT_S):
                answer()
    thread = threading.Thread(target=loop, daemon=True)
    thread.start()
    return thread


def _frame_sized_packet(bodies: int) -> int:
    frame = FrameOfData(1, tuple(RigidBodySample(i + 1, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
                                 for i in range(bodies)))
    return len(pack_frame_of_data(frame))


def serve(spec: PeerSpec, control: Connection) -> None:
    """Child process entry: start every peer, report their endpoints, obey ``control``."""
    simulation = TeamSimulation(build_team_scene(ring_team_settings(["go2", "a1"],
                                                                    srb_parameters)))
    sim_lock = threading.Lock()  # the two fakes share the MuJoCo data
    stop = threading.Event()

    go2 = FakeGo2(simulation.robot_driver(GO2), spec.domain_id,
                  topic_prefix=spec.go2_topic_prefix)
    a1 = FakeA1(simulation.robot_driver(A1))

    def answer_with(fake: FakeGo2 | FakeA1) -> Callable[[], None]:
        def answer() -> None:
            with sim_lock:
                if fake.poll_commands():
                    fake.publish_state()
        return answer

    # raw DDS echo: same types and QoS as the Go2 link, messages built once
    participant = go2.participant
    raw_commands = DataReader(participant, Topic(
        participant, topic_name(spec.raw_topic_prefix, "lowcmd"), LowCmd_), qos=COMMAND_QUEUE)
    raw_states = DataWriter(participant, Topic(
        participant, topic_name(spec.raw_topic_prefix, "lowstate"), LowState_))
    waitset = WaitSet(participant)
    waitset.attach(ReadCondition(raw_commands, SampleState.NotRead | ViewState.Any))
    wire_state = wire_state_from_measurement(simulation.robot_driver(GO2).read(), 1.0, tick_ms=0)
    prebuilt_state = low_state_from_wire(wire_state)

    def raw_dds_answer() -> None:
        if any(isinstance(sample, LowCmd_) for sample in raw_commands.take(N=16)):
            raw_states.write(prebuilt_state)

    # raw UDP echo: A1-sized datagrams, nothing decoded
    raw_udp = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    raw_udp.bind(("127.0.0.1", 0))
    raw_udp.settimeout(_WAIT_S)
    a1_state_bytes = encode_low_state(wire_state_from_measurement(
        simulation.robot_driver(A1).read(), 1.0, tick_ms=0))

    def raw_udp_loop() -> None:
        while not stop.is_set():
            try:
                _, source = raw_udp.recvfrom(4096)
            except TimeoutError:
                continue
            raw_udp.sendto(a1_state_bytes, source)
    raw_udp_thread = threading.Thread(target=raw_udp_loop, daemon=True)
    raw_udp_thread.start()

    poses = simulation_pose_source(simulation, include_obstacles=False)
    natnet = FakeNatNetServer(poses, command_port=0, data_port=spec.natnet_data_port,
                              timestamp_source=time.monotonic)
    raw_stream = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    raw_padding = bytes(_frame_sized_packet(len(poses())) - STAMP.size)

    threads = [_answer(go2.wait_for_command, answer_with(go2), stop),
               _answer(a1.wait_for_command, answer_with(a1), stop),
               _answer(lambda t: bool(waitset.wait(duration(seconds=t))), raw_dds_answer, stop)]
    control.send({"a1": a1.local_endpoint, "raw_udp": raw_udp.getsockname(),
                  "natnet_command_port": natnet.command_port})
    streamer = PeriodicThread("porter-bench-raw-stream")
    try:
        while True:
            request = control.recv()
            streamer.stop()
            natnet.stop_streaming()
            if request[0] == "stop":
                break
            if request[0] == "stream" and request[1] == "natnet":
                natnet.start_streaming(request[2])
            elif request[0] == "stream" and request[1] == "raw":
                streamer.start(request[2], [lambda: raw_stream.sendto(
                    STAMP.pack(time.monotonic()) + raw_padding,
                    ("127.0.0.1", spec.raw_stream_port))])
            control.send("ok")
    finally:
        stop.set()
        for thread in [*threads, raw_udp_thread]:
            thread.join(timeout=1.0)
        control.send({name: {"commands_received": fake.commands_received,
                             "commands_rejected": fake.commands_rejected_total,
                             "states_published": fake.states_published,
                             "last_position_rad": None if fake.last_command is None
                             else np.asarray(fake.last_command.position_rad).tolist()}
                      for name, fake in (("go2", go2), ("a1", a1))}
                     | {"natnet": {"frames_published": natnet.frames_published}})
        natnet.close()
        a1.close()
        raw_udp.close()
        raw_stream.close()
