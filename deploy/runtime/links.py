"""The team's links for ``porter deploy``: robot drivers, MoCap, e-stop and F/T on CAN, opened
from a ``DeployConfig`` the same way for hardware and for ``--backend sim``.

The Go2 and A1 measure no world position or linear velocity; their drivers take them from the
MoCap (``MocapTracker.base_state``): position = the newest pose of the robot's rigid body,
velocity = least-squares slope of its positions over the last ``velocity_window_s`` of MoCap
frame timestamps (at 120 Hz and 2 mm noise a 0.08 s window gives ~2.5 cm/s noise for ~40 ms of
lag; a finite difference of two frames would give ~0.3 m/s). The payload estimator is not used
here: it needs the robot states first.

Opening a link never raises for a link that is absent (no CAN adapter, a Go2 that does not
answer): the failure is kept in ``problems`` for the pre-flight report.
"""

from __future__ import annotations

import collections
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import can
import numpy as np

from core.estimation.base_velocity import BaseVelocityEstimator
from core.model.conventions import PAYLOAD_NAME
from deploy.config.deploy_config import DeployConfig, Go2Link
from drivers.can.bus import EstopMonitor, ForceTorqueSensors
from drivers.interfaces import (
    EstopSource,
    JointCommand,
    MocapFrame,
    MocapSource,
    RobotDriver,
    WrenchSensors,
)
from drivers.link_errors import DriverError
from drivers.natnet.client import NatNetClient, NatNetClientConfig, NatNetError
from drivers.robot_descriptions import load_pinocchio_model
from drivers.unitree.a1_driver import A1Driver
from drivers.unitree.go2_driver import Go2Driver

Clock = Callable[[], float]


class MocapTracker:
    """The newest MoCap frame under porter's names (robot names, ``payload``, ``obstacle_<i>``
    for the obstacles the config names a rigid body for), when each body
    was last seen [s on ``clock``], and each body's recent positions for its velocity.
    ``poll`` (once per loop tick, loop thread) takes in a new frame if there is one."""

    def __init__(self, client: MocapSource, bodies: dict[str, str], window_s: float,
                 clock: Clock, max_repeated_frames: int | None = None) -> None:
        self.client = client
        # A tracked pose always jitters (sensor noise): the same pose bit for bit in more than
        # this many new frames in a row is a frozen tracker, and the body counts as unseen
        # (so its age grows into the MoCap timeout). None: not checked.
        self.max_repeated_frames = max_repeated_frames
        self.repeated_frames: dict[str, int] = dict.fromkeys(bodies, 0)
        self.bodies = bodies  # porter name -> Motive name
        self.window_s = window_s
        self.clock = clock
        self.frame: MocapFrame | None = None
        self.last_seen_s: dict[str, float] = {}
        self._raw: MocapFrame | None = None
        self._history: dict[str, collections.deque[tuple[float, np.ndarray]]] = {
            name: collections.deque() for name in bodies}
        self._velocity: dict[str, np.ndarray] = {}  # the fit of each history as it is now

    def poll(self) -> MocapFrame | None:
        raw = self.client.latest()
        if raw is None or raw is self._raw:
            return self.frame
        self._raw = raw
        received_s = self.clock() - self.client.age_s()
        poses = {}
        for name, body in self.bodies.items():
            pose = raw.poses.get(body)
            if pose is None:
                continue
            poses[name] = pose
            if self._frozen(name, pose):
                continue
            self.last_seen_s[name] = received_s
            history = self._history[name]
            history.append((raw.time_s, pose[0]))
            while history and history[0][0] < raw.time_s - self.window_s:
                history.popleft()
            self._velocity.pop(name, None)  # the fit changes with the window
        self.frame = MocapFrame(raw.time_s, poses)
        return self.frame

    def _frozen(self, name: str, pose: tuple[np.ndarray, np.ndarray]) -> bool:
        """Count ``name``'s pose repeating its previous one exactly; True once frozen."""
        previous = self.frame.poses.get(name) if self.frame is not None else None
        same = previous is not None and np.array_equal(previous[0], pose[0]) \
            and np.array_equal(previous[1], pose[1])
        self.repeated_frames[name] = self.repeated_frames[name] + 1 if same else 0
        limit = self.max_repeated_frames
        return limit is not None and self.repeated_frames[name] > limit

    def age_s(self, names: list[str] | None = None) -> float | None:
        """Seconds since the stalest of ``names`` (default all bodies) was last seen; None
        while one was never seen."""
        now_s = self.clock()
        ages = [now_s - self.last_seen_s[name] if name in self.last_seen_s else None
                for name in (names or list(self.bodies))]
        return None if any(age is None for age in ages) else max(ages)  # type: ignore[type-var]

    def missing(self) -> list[str]:
        """Bodies not in the newest frame."""
        return [name for name in self.bodies if self.frame is None or name not in self.frame.poses]

    def velocity(self, name: str) -> np.ndarray:
        """Least-squares linear velocity [m/s] of body ``name`` over the window, world frame.
        Fitted once per MoCap frame (120 Hz), not per read of it (500 Hz per robot)."""
        velocity = self._velocity.get(name)
        if velocity is None:
            velocity = self._velocity[name] = self._fit_velocity(name)
        return velocity.copy()

    def _fit_velocity(self, name: str) -> np.ndarray:
        history = self._history[name]
        if len(history) < 2:
            return np.zeros(3)
        times = np.array([t for t, _ in history])
        positions = np.array([p for _, p in history])
        centred = times - times.mean()
        denominator = float(centred @ centred)
        return centred @ (positions - positions.mean(axis=0)) / denominator \
            if denominator > 0.0 else np.zeros(3)

    def body_motion(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Body ``name``'s (position [m], velocity [m/s]) in world, from the newest frame; the
        last position seen and zero velocity while it is missing; zeros before it was seen."""
        frame = self.frame
        if frame is None or name not in frame.poses:
            history = self._history[name]
            position = history[-1][1] if history else np.zeros(3)
            return np.array(position), np.zeros(3)
        return np.array(frame.poses[name][0]), self.velocity(name)


@dataclass
class TeamLinks:
    """Open links, as the loop sees them (``drivers.interfaces`` protocols); ``problems``
    names the ones that could not be opened. ``mocap`` is the NatNet client behind ``tracker``
    (None in the in-process simulation); ``base_velocity`` fuses the base velocity of the
    robots whose driver measures none; ``sport_mode`` how each Go2's motion switcher answered
    the release request; ``closers`` release what the links hold."""

    drivers: dict[str, RobotDriver]
    mocap: NatNetClient | None
    tracker: MocapTracker | None
    estop: EstopSource | None
    force_torque: WrenchSensors | None
    problems: list[str] = field(default_factory=list)
    base_velocity: dict[str, BaseVelocityEstimator] = field(default_factory=dict)
    sport_mode: dict[str, str] = field(default_factory=dict)
    closers: list[Callable[[], None]] = field(default_factory=list)

    def send(self, commands: dict[str, JointCommand]) -> str | None:
        """Send each robot its command; the first driver error's text (None: all sent). A
        failed send does not keep the other robots from theirs."""
        failure = None
        for name, command in commands.items():
            driver = self.drivers.get(name)
            if driver is not None:
                try:
                    driver.send(command)
                except DriverError as error:
                    failure = failure or str(error)
        return failure

    def close(self) -> None:
        for close in self.closers:
            close()
        for driver in self.drivers.values():
            driver.close()


def open_links(config: DeployConfig, clock: Clock = time.monotonic) -> TeamLinks:
    """Open every link of ``config`` (see the module docstring)."""
    problems: list[str] = []
    mocap_config = config.mocap
    bodies = {name: config.body_name(name) for name in [*config.robots, PAYLOAD_NAME]}
    bodies.update({f"obstacle_{i}": body for i, body in enumerate(mocap_config.obstacle_bodies)
                   if body is not None})
    mocap: NatNetClient | None = None
    tracker: MocapTracker | None = None
    try:
        mocap = NatNetClient(NatNetClientConfig(
            server_address=mocap_config.server_address, command_port=mocap_config.command_port,
            data_port=mocap_config.data_port, multicast=mocap_config.multicast,
            multicast_group=mocap_config.multicast_group,
            local_address=mocap_config.local_address, body_ids=mocap_config.body_ids,
            stale_timeout_s=mocap_config.stale_timeout_s), clock=clock)
        tracker = MocapTracker(mocap, bodies, mocap_config.velocity_window_s, clock,
                               mocap_config.max_repeated_frames)
    except NatNetError as error:
        problems.append(f"MoCap: {error}")
    drivers: dict[str, RobotDriver] = {}
    sport_mode: dict[str, str] = {}
    for name, link in config.robots.items():
        try:
            if isinstance(link, Go2Link):
                go2 = Go2Driver(
                    name, link.domain_id, config.network_interface, link.topic_prefix,
                    link.link_timeout_s, link.contact_threshold_n, link.foot_force_n_per_count,
                    clock=clock, check_state_crc=link.check_state_crc)
                drivers[name] = go2
                if link.release_sport_mode:
                    sport_mode[name] = _release_sport_mode(go2)
            else:
                drivers[name] = A1Driver(
                    name, link.robot_address, link.local_address, link.local_port,
                    link.link_timeout_s, link.contact_threshold_n, link.foot_force_n_per_count,
                    clock=clock)
        except DriverError as error:
            problems.append(f"robot {name}: {error}")
    estop: EstopMonitor | None = None
    force_torque: ForceTorqueSensors | None = None
    try:
        estop = EstopMonitor(interface=config.can.interface, channel=config.can.channel,
                             timeout_s=config.safety.heartbeat_timeout_s, clock=clock)
        if config.can.force_torque:
            force_torque = ForceTorqueSensors(list(config.robots), estop.bus, clock=clock)
    except (can.CanError, OSError, ValueError) as error:
        problems.append(f"CAN: cannot open {config.can.interface} channel "
                        f"{config.can.channel!r}: {error}")
    closers = [reader.close for reader in (force_torque, estop, mocap) if reader is not None]
    base_velocity = {name: BaseVelocityEstimator(load_pinocchio_model(
        config.robots[name].driver)) for name in drivers}
    return TeamLinks(drivers, mocap, tracker, estop, force_torque, problems, base_velocity,
                     sport_mode, closers)


def _release_sport_mode(driver: Go2Driver) -> str:
    """Ask the Go2's motion switcher to release the sport mode (low-level control needs it)."""
    try:
        code = driver.release_sport_mode()
    except DriverError as error:
        return str(error)
    return "released" if code == 0 else f"refused, code {code}"

