"""Unitree Go2 low-level driver over CycloneDDS: ``RobotDriver`` on ``rt/lowcmd``/``rt/lowstate``.

Frames and units as ``drivers.interfaces``; Unitree's motor order, foot order and sentinels
are converted in ``drivers.unitree.conventions``, once. The Go2 measures no world position or
linear velocity: they read zero (porter's estimator pipeline, ``deploy.runtime.state_pipeline``,
fills them in).

Network: the DDS domain is created with an explicit CycloneDDS configuration bound to one
network interface: loopback (``lo``) unless ``network_interface`` names another (e.g. the
robot's ``eth0``/``enp3s0``), so nothing is sent beyond this machine by default. CycloneDDS
allows one configuration per domain id and process: every driver and fake of one domain in
a process must name the same interface (``open_participant`` keeps the domains). Caveat
(CycloneDDS 11, measured with ``ss -uanp``): the interface choice governs what is advertised
and where packets are sent, but CycloneDDS still binds its well-known discovery / data receive
ports to 0.0.0.0 (only the transmit socket is bound to 127.0.0.1); we found no option to bind
them to one address. Firewall those ports (7400 + 250 x domain id, ...) if that matters.

Round trip (for ``porter bench drivers``): ``t = driver.clock(); driver.send(command);
driver.wait_for_state(after_s=t, timeout_s=...)`` returns once a state received after ``t``
is in, so ``driver.clock() - t`` is command out + peer reaction + state back. Measured by
``porter bench drivers`` with ``FakeGo2`` in another process: 1.3 ms median, of which 0.9 ms
is cyclonedds' pure-Python (de)serialization of the two messages at both ends (the same
exchange with pre-built messages): a 500 Hz loop spends ~25 % of a core on it.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Callable
from xml.sax.saxutils import quoteattr

from cyclonedds._clayer import ddspy_take, ddspy_write
from cyclonedds.core import (
    DDSException,
    InstanceState,
    ReadCondition,
    SampleState,
    ViewState,
    WaitSet,
)
from cyclonedds.domain import Domain, DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.qos import Policy, Qos
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic
from cyclonedds.util import duration

from drivers.link_errors import DriverError, LinkMonitor
from drivers.unitree.conventions import (
    WireCommand,
    WireState,
    state_problem,
)
from drivers.unitree.go2_cdr import LowCmdCodec, LowStateCodec
from drivers.unitree.go2_dds_types import (
    MOTOR_MODE_SERVO,
    LowCmd_,
    LowState_,
    Request_,
    Response_,
    api_request,
)
from drivers.unitree.peer import UnitreeLowLevelDriver

LOGGER = logging.getLogger(__name__)
LOOPBACK_INTERFACE = "lo"
MOTION_SWITCHER_SERVICE = "motion_switcher"
API_ID_RELEASE_MODE = 1003
# states between two polls are all checked and counted (the newest valid one is kept)
STATE_QUEUE = Qos(Policy.Reliability.BestEffort, Policy.History.KeepLast(16))
RELEASE_RETRY_S = 0.25  # ReleaseMode asked again after this long without an answer [s]
REQUEST_QOS = Qos(Policy.Reliability.Reliable(duration(milliseconds=100)),
                  Policy.History.KeepLast(8))

_DOMAINS: dict[int, tuple[Domain, str]] = {}  # process-wide: CycloneDDS allows one per id


def cyclonedds_config(network_interface: str) -> str:
    """CycloneDDS XML configuration using only ``network_interface`` (XML-escaped: the name
    is data, never markup)."""
    return ("<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
            f"<NetworkInterface name={quoteattr(network_interface)}/>"
            "</Interfaces></General></Domain></CycloneDDS>")


def open_participant(domain_id: int, network_interface: str | None) -> DomainParticipant:
    """A participant in DDS domain ``domain_id`` bound to ``network_interface`` (loopback when
    None). Creates the domain once per process; a second interface for it is an error."""
    interface = network_interface or LOOPBACK_INTERFACE
    if domain_id not in _DOMAINS:
        try:
            _DOMAINS[domain_id] = (Domain(domain_id, cyclonedds_config(interface)), interface)
        except DDSException as error:
            raise DriverError(f"cannot create DDS domain {domain_id} on interface {interface!r}"
                              f" (was it already created outside drivers.unitree.go2_driver?): {error}"
                              ) from error
    elif _DOMAINS[domain_id][1] != interface:
        raise DriverError(f"DDS domain {domain_id} already runs on interface "
                          f"{_DOMAINS[domain_id][1]!r} in this process; cannot add {interface!r}")
    return DomainParticipant(domain_id)


def write_raw(writer: DataWriter, data: bytes) -> None:
    """Publish already-serialized CDR ``data`` (``drivers.unitree.go2_cdr``) on ``writer``:
    the C layer's write, as ``DataWriter.write`` calls it after serializing."""
    code = ddspy_write(writer._ref, data)
    if code < 0:
        raise DDSException(code, f"writing {len(data)} bytes on {writer.topic.name}")


def take_raw(reader: DataReader, count: int) -> list[bytes]:
    """The serialized samples pending on ``reader`` (up to ``count``, oldest first), without
    cyclonedds' Python deserializer; instance-state notifications are skipped."""
    taken = ddspy_take(reader._ref, SampleState.Any | ViewState.Any | InstanceState.Any, count)
    if isinstance(taken, int):
        raise DDSException(taken, f"taking from {reader.topic.name}")
    return [data for data, info in taken if info.valid_data]


def topic_name(prefix: str, name: str) -> str:
    """``rt/<name>`` under an optional robot prefix: ("", "lowcmd") -> "rt/lowcmd",
    ("go2_left", "lowcmd") -> "go2_left/rt/lowcmd"."""
    return f"{prefix.rstrip('/')}/rt/{name}" if prefix else f"rt/{name}"


class Go2Driver(UnitreeLowLevelDriver):
    """One Go2 over DDS. ``read`` raises ``LinkLostError`` without a valid state in the last
    ``link_timeout_s`` [s] (on ``clock``, seconds) and recovers when states resume.

    Foot forces [N] = raw counts x ``foot_force_n_per_count`` (UNVERIFIED scale: the Go2's
    foot sensors are uncalibrated counts); contact where the force exceeds
    ``contact_threshold_n``. Measurement ``time_s`` is the receive time on ``clock``.

    Every state must carry Unitree's CRC-32 of its contents (``check_state_crc``, as
    unitree_sdk2_python computes it; UNVERIFIED that every Go2 firmware fills it in: a robot
    whose states all fail it never passes pre-flight, and the error names the setting).
    """

    def __init__(self, name: str = "go2", domain_id: int = 0,
                 network_interface: str | None = None, topic_prefix: str = "",
                 link_timeout_s: float = 0.1, contact_threshold_n: float = 20.0,
                 foot_force_n_per_count: float = 1.0,
                 clock: Callable[[], float] = time.monotonic,
                 check_state_crc: bool = True) -> None:
        self._name = name
        self.check_state_crc = check_state_crc
        self.motor_mode = MOTOR_MODE_SERVO
        self.clock = clock
        self.topic_prefix = topic_prefix
        self.contact_threshold_n = contact_threshold_n
        self.foot_force_n_per_count = foot_force_n_per_count
        self.participant = open_participant(domain_id, network_interface)
        state_topic = Topic(self.participant, topic_name(topic_prefix, "lowstate"), LowState_)
        self._reader = DataReader(self.participant, state_topic, qos=STATE_QUEUE)
        self._writer = DataWriter(self.participant,
                                  Topic(self.participant, topic_name(topic_prefix, "lowcmd"),
                                        LowCmd_))
        self._waitset = WaitSet(self.participant)
        self._waitset.attach(ReadCondition(self._reader, SampleState.NotRead | ViewState.Any))
        self.link = LinkMonitor(f"{name}: {state_topic.name} on DDS domain {domain_id}",
                                link_timeout_s, clock)
        self.link.never_valid_hints["crc"] = (
            "every state failed Unitree's CRC: if this robot's firmware leaves LowState_.crc "
            "unfilled, turn check_state_crc off for it")
        self.commands_sent = 0
        self.last_state: WireState | None = None
        self._states, self._commands = LowStateCodec(), LowCmdCodec()

    def poll(self) -> int:
        """Take every pending state; keep the newest valid one. Returns how many were valid."""
        valid = 0
        for data in take_raw(self._reader, 64):
            try:
                state = self._states.decode(data)
            except ValueError:
                self.link.reject("encoding")
                continue
            if self.check_state_crc and not self._states.crc_ok(data):
                # a bit flipped on the way (or a sender that is no Go2): nothing in it counts
                self.link.reject("crc")
                continue
            problem = state_problem(state)
            if problem is None and self.last_state is not None \
                    and state.tick_ms == self.last_state.tick_ms:
                # The robot's tick advances with every message: the same tick again is a
                # frozen state (its sensors or firmware loop stopped), not a fresh one, so a
                # robot that keeps repeating itself ends in a lost link after the timeout.
                problem = "frozen tick"
            if problem is not None:
                self.link.reject(problem)
                continue
            self.link.accept()
            self.last_state, valid = state, valid + 1
        return valid

    def _wait_readable(self, timeout_s: float) -> None:
        self._waitset.wait(duration(seconds=timeout_s))

    def send_wire(self, wire: WireCommand) -> None:
        """Publish a wire-convention command as a ``LowCmd_`` (head, level flag, CRC set)."""
        write_raw(self._writer, self._commands.encode(wire))
        self.commands_sent += 1

    def release_sport_mode(self, timeout_s: float = 2.0) -> int:
        """Ask the motion switcher to release sport mode (needed before low-level control).

        Request ``unitree_api.msg.dds_.Request_`` on ``rt/api/motion_switcher/request`` with api
        id 1003 (ReleaseMode) and parameter ``"{}"``, as ``unitree_sdk2``'s
        ``MotionSwitcherClient.ReleaseMode`` sends it; waits for the ``Response_`` of the same
        identity on ``.../response`` and returns its status code (0 = success). UNVERIFIED on a
        robot: the API types follow unitree_sdk2's IDL, and the SDK first calls CheckMode
        (api 1001) and repeats ReleaseMode until no mode is active; this asks again every
        ``RELEASE_RETRY_S`` until the first answer (to any of its requests).
        Raises ``DriverError`` when no service answers within ``timeout_s`` [s].
        """
        service = f"api/{MOTION_SWITCHER_SERVICE}"
        writer = DataWriter(self.participant, Topic(
            self.participant, topic_name(self.topic_prefix, f"{service}/request"), Request_),
            qos=REQUEST_QOS)
        reader = DataReader(self.participant, Topic(
            self.participant, topic_name(self.topic_prefix, f"{service}/response"), Response_),
            qos=REQUEST_QOS)
        deadline_s = time.monotonic() + timeout_s
        # Both directions matched before asking: the response topic is volatile, so an answer
        # published before our reader matched the service's writer would be lost (seen on a
        # loaded machine: the request matched, the answer never arrived).
        while (writer.get_publication_matched_status().current_count == 0
               or reader.get_subscription_matched_status().current_count == 0):
            if time.monotonic() > deadline_s:
                raise DriverError(f"{self._name}: no motion-switcher service on "
                                  f"{writer.topic.name} within {timeout_s} s")
            time.sleep(0.005)
        # Asked again every RELEASE_RETRY_S until answered: our reader matching the service's
        # writer does not mean its writer has matched our reader yet (discovery runs each way
        # on its own), and an answer written before that is lost; ReleaseMode is idempotent and
        # unitree_sdk2's own examples repeat it. An answer to any of our requests counts.
        asked: set[int] = set()
        next_ask_s = time.monotonic()
        while time.monotonic() < deadline_s:
            if time.monotonic() >= next_ask_s:
                request_id = time.time_ns()
                asked.add(request_id)
                writer.write(api_request(request_id, API_ID_RELEASE_MODE))
                next_ask_s += RELEASE_RETRY_S
            for response in reader.take(N=16):
                if (isinstance(response, Response_)
                        and response.header.identity.id in asked):
                    code = int(response.header.status.code)
                    LOGGER.info("%s: ReleaseMode answered with code %d (request %d of %d)",
                                self._name, code, sorted(asked).index(
                                    response.header.identity.id) + 1, len(asked))
                    return code
            time.sleep(0.002)
        raise DriverError(f"{self._name}: the motion switcher did not answer ReleaseMode "
                          f"within {timeout_s} s")
