"""``porter bench drivers``: latency and jitter of each driver shim against its fake, on
loopback, with the same transport stripped of porter (raw) measured in the same run.

Rows (times in ms on ``time.monotonic``):

- ``go2``: ``Go2Driver.send`` (``JointCommand`` -> ``LowCmd_`` with CRC, CycloneDDS) ->
  ``FakeGo2`` in another process applies it to MuJoCo and answers one ``LowState_`` ->
  ``Go2Driver.wait_for_state`` + ``read`` (a ``RobotMeasurement``). Raw: the same DDS
  types and QoS, messages built once, no conversion, CRC or simulation.
- ``a1``: the same over UDP with ``A1Driver`` / ``FakeA1`` (LowCmd 730 B, LowState 891 B).
  Raw: datagrams of those sizes echoed undecoded.
- ``natnet``: one way, ``FakeNatNetServer`` stamps a frame and sends it -> the
  ``NatNetClient`` thread has decoded it (``latest()`` holds it). 120 Hz. Raw: frame-sized
  datagrams with the stamp, received by a blocking socket.
- ``can heartbeat`` / ``can F/T``: one way, ``FakeCanNode`` sends an e-stop heartbeat / one
  F/T sample per robot (two robots, four frames) -> ``EstopMonitor`` /
  ``ForceTorqueSensors`` have it. python-can's virtual bus (in-process: no CAN adapter
  here). Raw: the same frames between two plain virtual buses.

Round trips are paced at the link's rate (500 Hz for the Unitree links), as the deploy loop
sends. jitter = standard deviation. ``ratio`` = median / raw median.
"""

from __future__ import annotations

import multiprocessing
import os
import select
import socket
import statistics
import time
from collections.abc import Callable
from typing import Any

import can
import numpy as np
from cyclonedds.core import ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from deploy.bench.driver_peers import A1, GO2, STAMP, PeerSpec, serve
from deploy.reports.table import Column, render_table
from deploy.sim_backend.backend import free_udp_port
from drivers.can.bus import EstopMonitor, ForceTorqueSensors
from drivers.can.fake import FakeCanNode
from drivers.can.protocol import encode_estop_heartbeat, encode_wrench
from drivers.interfaces import JointCommand
from drivers.natnet.client import NatNetClient, NatNetClientConfig
from drivers.unitree.a1_driver import A1Driver
from drivers.unitree.a1_udp_layout import MOTOR_MODE_SERVO as A1_SERVO
from drivers.unitree.a1_udp_layout import encode_low_cmd
from drivers.unitree.conventions import wire_command_from_joint_command
from drivers.unitree.go2_dds_types import MOTOR_MODE_SERVO as GO2_SERVO
from drivers.unitree.go2_dds_types import LowCmd_, LowState_, low_cmd_from_wire
from drivers.unitree.go2_driver import STATE_QUEUE, Go2Driver, topic_name

UNITREE_RATE_HZ = 500.0
NATNET_RATE_HZ = 120.0
CAN_RATE_HZ = 100.0
REPLY_TIMEOUT_S = 0.2
START_TIMEOUT_S = 120.0  # the child imports MuJoCo and builds the scene
WARM_UP = 20  # first round trips (DDS discovery, caches) are not counted

Send = Callable[[int], object]
Wait = Callable[[float], float | None]  # after send at t0 [s]: arrival time [s] or None


def command(index: int) -> JointCommand:
    """A distinct, valid servo command per index (the fake's last one is checked)."""
    position = 0.01 * (index % 100) + np.linspace(-0.5, 0.5, 12)
    return JointCommand(position_rad=position, kp=np.full(12, 20.0), kd=np.full(12, 0.5))


def _paced(send: Send, wait: Wait, count: int, rate_hz: float) -> tuple[list[float], int]:
    """Latencies [s] of ``count`` exchanges after ``WARM_UP`` ones, and how many got none."""
    latencies, lost = [], 0
    next_s = time.monotonic()
    for index in range(WARM_UP + count):
        next_s += 1.0 / rate_hz
        time.sleep(max(0.0, next_s - time.monotonic()))
        start_s = time.monotonic()
        send(index)
        arrival_s = wait(start_s)
        if index < WARM_UP:
            continue
        if arrival_s is None:
            lost += 1
        else:
            latencies.append(arrival_s - start_s)
    return latencies, lost


def _until_answered(send: Send, wait: Wait, timeout_s: float, what: str) -> None:
    """Send until the first answer (discovery, peers' start-up) or raise."""
    deadline_s = time.monotonic() + timeout_s
    while time.monotonic() < deadline_s:
        start_s = time.monotonic()
        send(0)
        if wait(start_s) is not None:
            return
    raise RuntimeError(f"porter bench drivers: no answer on the {what} link within "
                       f"{timeout_s} s")


def _poll(condition: Callable[[], float | None], timeout_s: float) -> float | None:
    deadline_s = time.monotonic() + timeout_s
    while (value := condition()) is None:
        if time.monotonic() > deadline_s:
            return None
        time.sleep(0.0001)
    return value


def _row(link: str, measured: str, latencies_s: list[float], lost: int,
         raw_latencies_s: list[float]) -> dict[str, Any]:
    ms = np.array(latencies_s) * 1e3
    raw_ms = np.array(raw_latencies_s) * 1e3
    if len(ms) == 0 or len(raw_ms) == 0:
        raise RuntimeError(f"porter bench drivers: {link}: no sample arrived")
    median, raw_median = float(np.median(ms)), float(np.median(raw_ms))
    return {"link": link, "measured": measured, "samples": len(ms), "lost": lost,
            "median_ms": median, "p95_ms": float(np.percentile(ms, 95)),
            "p99_ms": float(np.percentile(ms, 99)), "max_ms": float(ms.max()),
            "jitter_ms": float(statistics.pstdev(ms)), "raw_median_ms": raw_median,
            "raw_p95_ms": float(np.percentile(raw_ms, 95)), "ratio": median / raw_median}


def _unitree_row(link: str, driver: Go2Driver | A1Driver, raw_send: Send, raw_wait: Wait,
                 count: int) -> dict[str, Any]:
    def send(index: int) -> None:
        driver.send(command(index))

    def wait(start_s: float) -> float | None:
        if not driver.wait_for_state(after_s=start_s, timeout_s=REPLY_TIMEOUT_S):
            return None
        driver.read()  # into porter's types: part of what the controller waits for
        return time.monotonic()

    _until_answered(send, wait, 20.0, link)
    latencies, lost = _paced(send, wait, count, UNITREE_RATE_HZ)
    _until_answered(raw_send, raw_wait, 20.0, f"raw {link}")
    raw, _ = _paced(raw_send, raw_wait, count, UNITREE_RATE_HZ)
    row = _row(link, "command -> state round trip", latencies, lost, raw)
    row["last_sent_position_rad"] = command(WARM_UP + count - 1).position_rad.tolist()
    return row


def _go2_row(spec: PeerSpec, count: int) -> dict[str, Any]:
    driver = Go2Driver(GO2, spec.domain_id, topic_prefix=spec.go2_topic_prefix,
                       link_timeout_s=1.0)
    p = driver.participant
    writer = DataWriter(p, Topic(p, topic_name(spec.raw_topic_prefix, "lowcmd"), LowCmd_))
    reader = DataReader(p, Topic(p, topic_name(spec.raw_topic_prefix, "lowstate"), LowState_),
                        qos=STATE_QUEUE)
    waitset = WaitSet(p)
    waitset.attach(ReadCondition(reader, SampleState.NotRead | ViewState.Any))
    prebuilt = low_cmd_from_wire(wire_command_from_joint_command(command(0), GO2_SERVO))

    def raw_wait(start_s: float) -> float | None:
        deadline_s = start_s + REPLY_TIMEOUT_S
        while time.monotonic() < deadline_s:
            if any(isinstance(s, LowState_) for s in reader.take(N=16)):
                return time.monotonic()
            waitset.wait(duration(seconds=max(0.0, deadline_s - time.monotonic())))
        return None

    return _unitree_row("go2 (DDS)", driver, lambda _: writer.write(prebuilt), raw_wait, count)


def _a1_row(endpoints: dict, count: int) -> dict[str, Any]:
    raw = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    raw.bind(("127.0.0.1", 0))
    raw.connect(tuple(endpoints["raw_udp"]))
    prebuilt = encode_low_cmd(wire_command_from_joint_command(command(0), A1_SERVO))

    def raw_wait(start_s: float) -> float | None:
        readable, _, _ = select.select([raw], [], [], REPLY_TIMEOUT_S)
        if not readable:
            return None
        raw.recv(4096)
        return time.monotonic()

    with A1Driver(A1, robot_address=tuple(endpoints["a1"]), local_port=0,
                  link_timeout_s=1.0) as driver, raw:
        return _unitree_row("a1 (UDP)", driver, lambda _: raw.send(prebuilt), raw_wait, count)


def _natnet_row(spec: PeerSpec, endpoints: dict, control: Any, raw_stream: socket.socket,
                count: int) -> dict[str, Any]:
    config = NatNetClientConfig(command_port=endpoints["natnet_command_port"],
                                data_port=spec.natnet_data_port)
    latencies: list[float] = []
    with NatNetClient(config) as client:
        if _poll(lambda: 1.0 if client.is_ready() else None, 10.0) is None:
            raise RuntimeError("porter bench drivers: the NatNet client never connected")
        control.send(("stream", "natnet", NATNET_RATE_HZ))
        control.recv()
        frame = client.wait_for_frame(2.0)
        missed_before = client.counters.frames_missed
        while frame is not None and len(latencies) < count:
            frame = client.wait_for_frame(1.0, newer_than=frame)
            if frame is not None and client.latest() is frame:
                latencies.append(time.monotonic() - client.age_s() - frame.time_s)
        lost = client.counters.frames_missed - missed_before
    raw: list[float] = []
    control.send(("stream", "raw", NATNET_RATE_HZ))
    control.recv()
    raw_stream.settimeout(1.0)
    while len(raw) < count:
        data = raw_stream.recv(4096)
        raw.append(time.monotonic() - STAMP.unpack_from(data)[0])
    control.send(("quiet",))
    control.recv()
    return _row("natnet (UDP)", "frame, server -> client, one way", latencies, lost, raw)


def _can_rows(count: int) -> list[dict[str, Any]]:
    names = ["robot_0", "robot_1"]
    channel = f"porter-bench-{os.getpid()}"
    rows = []
    with FakeCanNode(channel=channel, robot_names=names, heartbeat=False,
                     wrench_source=lambda name: (np.array([1.0, -2.0, 30.0]),
                                                 np.array([0.1, 0.2, -0.3]))) as node, \
            EstopMonitor(channel=channel, timeout_s=1.0) as monitor, \
            ForceTorqueSensors(names, channel=channel) as sensors, \
            can.Bus(interface="virtual", channel=f"{channel}-raw") as raw_tx, \
            can.Bus(interface="virtual", channel=f"{channel}-raw") as raw_rx:
        def heartbeat_wait(start_s: float) -> float | None:
            def arrived() -> float | None:
                last_s = monitor.last_receive_time_s
                return last_s if last_s is not None and last_s >= start_s else None
            return _poll(arrived, REPLY_TIMEOUT_S)

        def wrench_wait(start_s: float) -> float | None:
            def arrived() -> float | None:
                reading = sensors.reading(names[-1])
                return (reading.receive_time_s if reading is not None
                        and reading.receive_time_s >= start_s else None)
            return _poll(arrived, REPLY_TIMEOUT_S)

        def raw_exchange(frames: list[can.Message]) -> tuple[Send, Wait]:
            def raw_wait(start_s: float) -> float | None:
                for _ in frames:
                    if raw_rx.recv(REPLY_TIMEOUT_S) is None:
                        return None
                return time.monotonic()
            def raw_send(_: int) -> None:
                for frame in frames:
                    raw_tx.send(frame)
            return raw_send, raw_wait

        for link, send, wait, frames in (
                ("can heartbeat", lambda _: node.send_heartbeat(), heartbeat_wait,
                 [encode_estop_heartbeat(1, node.state)]),
                ("can F/T", lambda _: node.publish_wrenches(), wrench_wait,
                 [m for i in range(len(names))
                  for m in encode_wrench(i, np.ones(3), np.ones(3), 1)])):
            latencies, lost = _paced(send, wait, count, CAN_RATE_HZ)
            raw, _ = _paced(*raw_exchange(frames), count, CAN_RATE_HZ)
            rows.append(_row(link, f"{len(frames)} frame(s), one way, virtual bus", latencies,
                             lost, raw))
    return rows


def run_bench(unitree_samples: int = 2000, stream_samples: int = 600,
              domain_id: int = 0) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    """The rows (see the module doc) and the peers' counters (commands received / rejected
    and the last command applied by each fake)."""
    context = multiprocessing.get_context("spawn")
    control, child_control = context.Pipe()
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as raw_stream:
        raw_stream.bind(("127.0.0.1", 0))
        spec = PeerSpec(domain_id, f"bench_{os.getpid()}", f"bench_raw_{os.getpid()}",
                        free_udp_port(), int(raw_stream.getsockname()[1]))
        peers = context.Process(target=serve, args=(spec, child_control), daemon=True,
                                name="porter-bench-peers")
        peers.start()
        counters: dict[str, Any] = {}
        try:
            if not control.poll(START_TIMEOUT_S):
                raise RuntimeError("porter bench drivers: the peers process did not start")
            endpoints = control.recv()
            rows = [_go2_row(spec, unitree_samples), _a1_row(endpoints, unitree_samples),
                    _natnet_row(spec, endpoints, control, raw_stream, stream_samples),
                    *_can_rows(stream_samples)]
        finally:
            if peers.is_alive():
                control.send(("stop",))
                if control.poll(10.0):
                    counters = control.recv()
            peers.join(timeout=10.0)
            if peers.is_alive():
                peers.kill()
    return rows, counters


def format_table(rows: list[dict[str, Any]]) -> str:
    cells = [[row["link"], row["measured"], str(row["samples"]), str(row["lost"]),
              *(f"{row[key]:.3f}" for key in ("median_ms", "p95_ms", "p99_ms", "max_ms",
                                              "jitter_ms", "raw_median_ms", "raw_p95_ms")),
              f"{row['ratio']:.2f}"] for row in rows]
    numbers = [Column(name, "right") for name in (
        "n", "lost", "median", "p95", "p99", "max", "jitter", "raw med", "raw p95", "ratio")]
    return render_table(["link", "measured", *numbers], cells, [
        "ms on time.monotonic; jitter = standard deviation; raw = the same transport without "
        "porter (pre-built messages, nothing decoded); ratio = median / raw median"])
