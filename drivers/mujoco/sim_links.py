"""The ``TeamSimulation``'s ends of the driver interfaces (``drivers.interfaces``): each robot's
``RobotDriver``, the ``MocapSource``, the coupling ``WrenchSensors`` and an ``EstopSource``.
They read and write the simulation; ``TeamSimulation.robot_driver``, ``mocap`` and
``wrench_sensors`` hand them out.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from core.model.conventions import JOINT_COUNT
from drivers.interfaces import (
    EstopStatus,
    JointCommand,
    MocapFrame,
    RobotMeasurement,
    WrenchReading,
)
from drivers.mujoco.scene import RobotIndices

if TYPE_CHECKING:
    from drivers.mujoco.simulation import TeamSimulation

__all__ = ["SimMocap", "SimRobotDriver", "SimWrenchSensors", "SimulatedEstop"]


class SimRobotDriver:
    """``RobotDriver`` of one simulated robot (reads and writes its ``TeamSimulation``)."""

    def __init__(self, simulation: TeamSimulation, robot: RobotIndices) -> None:
        self._simulation = simulation
        self._robot = robot

    @property
    def name(self) -> str:
        return self._robot.name

    def read(self) -> RobotMeasurement:
        return self._simulation._measure(self._robot)

    def send(self, command: JointCommand) -> None:
        self._simulation.set_command(self._robot.name, command)

    def send_damping(self, kd: float) -> None:
        self.send(JointCommand(kd=np.full(JOINT_COUNT, kd)))

    def close(self) -> None:
        """Nothing to release: the simulation is the link."""


class SimMocap:
    """``MocapSource`` of a ``TeamSimulation``: noisy frames of the current state, a new one
    at every instant of a ``rate_hz`` grid of simulated time (the first call makes the first),
    or at every call when ``rate_hz`` is None. Each frame draws its noise once."""

    def __init__(self, simulation: TeamSimulation, rate_hz: float | None = None) -> None:
        self._simulation = simulation
        self._period_s = None if rate_hz is None else 1.0 / rate_hz
        self._frame: MocapFrame | None = None
        self._next = 0  # index of the next frame instant on the grid

    def latest(self) -> MocapFrame | None:
        t = self._simulation.time_s
        if self._period_s is None:
            return self._simulation._mocap_frame()
        if self._frame is None or t >= self._next * self._period_s - 1e-9:
            self._frame = self._simulation._mocap_frame()
            self._next = int(np.floor(t / self._period_s + 1e-6)) + 1
        return self._frame

    def age_s(self) -> float:
        if self._period_s is None:
            return 0.0
        return math.inf if self._frame is None else self._simulation.time_s - self._frame.time_s


class SimWrenchSensors:
    """``WrenchSensors`` of a ``TeamSimulation``: the wrench each coupling transmits now."""

    def __init__(self, simulation: TeamSimulation) -> None:
        self._simulation = simulation
        self._count = 0

    def latest(self) -> dict[str, WrenchReading]:
        self._count += 1
        sim = self._simulation
        readings = {}
        for robot in sim.scene.robots:
            force_n, torque_nm = sim.coupling_wrench(robot.name)
            readings[robot.name] = WrenchReading(force_n, torque_nm, self._count, False,
                                                 sim.time_s)
        return readings


class SimulatedEstop:
    """``EstopSource`` of a simulation: no e-stop hardware, so run is allowed until ``press``."""

    def __init__(self) -> None:
        self._reason = ""

    def press(self, reason: str = "pressed") -> None:
        self._reason = reason

    def status(self) -> EstopStatus:
        return EstopStatus(not self._reason, self._reason or "run")
