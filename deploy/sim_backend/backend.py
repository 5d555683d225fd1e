"""``porter deploy --backend sim``: the simulated world the deploy loop talks to through the very
drivers it uses on hardware.

``SimBackend(config, scenario)`` starts ``deploy.sim_backend.world`` in a process of its own (its own
interpreter lock: the fakes' DDS encoding and the physics do not compete with the 500 Hz loop
for it) and rewrites the config's links to the fakes on loopback, unique to this run so that
parallel runs and tests do not cross:

- Go2: same DDS domain, topic prefix ``porter_sim_<pid>_<n>/<robot>``, interface ``lo``;
- A1: the fake's UDP endpoint (127.0.0.1, a free port), local port 0 (any free one);
- NatNet: unicast to the fake's command port (a free one), data to a free local port;
- CAN: python-can ``virtual`` channel ``porter_sim_<pid>_<n>``; a bridge thread moves the
  world's frames from its pipe onto that channel (see ``deploy.sim_backend.world``);
- ``safety``: with ``sim.safety_overrides`` applied.

``clock`` is the world's (``ScaledClock``: wall time x ``sim.time_scale``): the deploy loop and
the drivers run on it, so that a slow-motion world (time scale below 1) is slow motion for the
controller too. ``ground_truth()`` asks the world for simulator truth (summary only: the
deploy loop never uses it to control); ``close()`` stops the world.
"""

from __future__ import annotations

import contextlib
import itertools
import multiprocessing as mp
import os
import socket
import threading
from typing import Any

import can

from deploy.config.deploy_config import A1Link, CanConfig, DeployConfig, Go2Link, MocapConfig
from deploy.config.scenario import Scenario
from deploy.sim_backend.world import ScaledClock, WorldSpec, serve
from drivers.link_errors import DriverError

START_TIMEOUT_S = 120.0
_runs = itertools.count()


def free_udp_port() -> int:
    """A UDP port on 127.0.0.1 free right now (the OS picks it)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def loopback_config(config: DeployConfig, tag: str, natnet_data_port: int) -> DeployConfig:
    """``config`` with every link on loopback and namespaced by ``tag`` (A1 and NatNet
    endpoints of the fakes are filled in once they are known)."""
    robots: dict[str, Go2Link | A1Link] = {}
    for name, link in config.robots.items():
        if isinstance(link, Go2Link):
            robots[name] = link.model_copy(update={"topic_prefix": f"{tag}/{name}"})
        else:
            robots[name] = link.model_copy(update={"local_address": "127.0.0.1",
                                                   "local_port": 0})
    mocap = config.mocap.model_copy(update={
        "server_address": "127.0.0.1", "local_address": "127.0.0.1", "multicast": False,
        "data_port": natnet_data_port})
    return config.model_copy(update={
        "network_interface": None, "robots": robots, "mocap": mocap,
        "safety": config.sim_safety(),
        "can": CanConfig(interface="virtual", channel=tag,
                         force_torque=config.can.force_torque)})


class SimBackend:
    """The world process and the CAN bridge; ``config`` holds the links to use."""

    def __init__(self, config: DeployConfig, scenario: Scenario) -> None:
        tag = f"porter_sim_{os.getpid()}_{next(_runs)}"
        data_port = free_udp_port()
        world_config = loopback_config(config, tag, data_port)
        context = mp.get_context("spawn")
        self._control, child_control = context.Pipe()
        can_out, can_in = context.Pipe(duplex=False)
        self._process = context.Process(
            target=serve, args=(WorldSpec(scenario, world_config, data_port), child_control,
                                can_in),
            name="porter-sim-world", daemon=True)
        self._process.start()
        child_control.close()
        can_in.close()
        if not self._control.poll(START_TIMEOUT_S):
            self.close()
            raise DriverError(f"the simulated world did not start within {START_TIMEOUT_S} s")
        status, payload = self._control.recv()
        if status != "ready":
            self.close()
            raise DriverError(f"the simulated world failed to start: {payload}")
        self.config = self._with_endpoints(world_config, payload)
        self.clock = ScaledClock(config.sim.time_scale)
        # The world's time zero on ``clock``: its faults are due from here, and porter's own
        # (``PorterFaults``) must count from the same instant, not from porter's later start-up.
        self.start_s = config.sim.time_scale * float(payload["start_monotonic_s"])
        self.can_bus = can.Bus(interface="virtual", channel=tag)
        self._can_in = can_out
        self._bridge = threading.Thread(target=self._forward_can, name="porter-sim-can-bridge",
                                        daemon=True)
        self._bridge.start()

    @staticmethod
    def _with_endpoints(config: DeployConfig, endpoints: dict[str, Any]) -> DeployConfig:
        robots: dict[str, Go2Link | A1Link] = dict(config.robots)
        for name, endpoint in endpoints["a1"].items():
            robots[name] = robots[name].model_copy(update={"robot_address": tuple(endpoint)})
        mocap: MocapConfig = config.mocap.model_copy(
            update={"command_port": endpoints["natnet_command_port"]})
        return config.model_copy(update={"robots": robots, "mocap": mocap})

    def _forward_can(self) -> None:
        while True:
            try:
                message = self._can_in.recv()
            except (EOFError, OSError):
                return
            try:
                self.can_bus.send(message)
            except can.CanError:
                return  # bus shut down

    @property
    def pid(self) -> int | None:
        """The world process's id."""
        return self._process.pid

    def ground_truth(self, timeout_s: float = 5.0) -> dict[str, Any] | None:
        """Simulator truth (``SimWorld.ground_truth``), or None when the world is gone."""
        try:
            self._control.send("ground_truth")
            if self._control.poll(timeout_s):
                result: dict[str, Any] = self._control.recv()
                return result
        except (EOFError, OSError):
            pass
        return None

    def close(self) -> None:
        """Stop the world process and the bridge; idempotent."""
        with contextlib.suppress(OSError, ValueError):
            self._control.send("stop")
        self._process.join(timeout=5.0)
        if self._process.is_alive():
            self._process.terminate()
            self._process.join(timeout=2.0)
        self._control.close()
        if hasattr(self, "_can_in"):
            self._can_in.close()
            self._bridge.join(timeout=2.0)
            self.can_bus.shutdown()
