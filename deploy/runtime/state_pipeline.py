"""The one estimator pipeline: the drivers' readings in, the robots' states out, once per tick.

Its stages run in this order each tick, in the lockstep and the paced clock alike (in the spirit
of upkie's ``ObserverPipeline``: one stage, one input):

1. **joints and IMU**: every robot's driver (``RobotDriver.read``); a lost link is reported in
   ``link_errors``, not raised;
2. **MoCap**: the tracker's newest frame (``MocapTracker.poll``, porter's body names);
3. **base pose**: robots whose driver measures no world position (``mocap_posed``: the Unitree
   robots) get their MoCap body's position, and its velocity (least squares over the
   tracker's window) as the MoCap velocity;
4. **base velocity**: for the same robots, leg odometry fused with that MoCap velocity
   (``core.estimation.base_velocity``), which is the measurement's base velocity from then on.

The floating-base states the controllers use are assembled here and nowhere else:
``wbc_state`` (the WBC, 500 Hz: the measurement as it stands) and ``nmpc_state`` (the NMPC's
robot states: pose from the MoCap frame, twist and joints from the robot, as on hardware). The
payload's state follows from the robots' NMPC states (``core.estimation.payload_estimator``,
at NMPC instants in ``TeamController.nmpc_inputs``). World frame, SI units.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from core.estimation.base_velocity import BaseVelocityEstimator
from core.locomotion.whole_body_control import FloatingBaseState
from drivers.interfaces import MocapFrame, RobotDriver, RobotMeasurement
from drivers.link_errors import LinkLostError

if TYPE_CHECKING:  # the tracker lives with the links (deploy.runtime.links)
    from deploy.runtime.links import MocapTracker

__all__ = ["StatePipeline", "TeamReading", "mocap_state", "wbc_state"]


@dataclass
class TeamReading:
    """One tick's estimate: each robot's measurement (base state complete), the robots whose
    link was lost (name -> why) and the newest MoCap frame (None: none yet, or no MoCap)."""

    measurements: dict[str, RobotMeasurement]
    link_errors: dict[str, str]
    frame: MocapFrame | None


class StatePipeline:
    """The stages above over ``drivers``, ``tracker`` (None: no MoCap) and the base velocity
    estimators of the robots whose base pose comes from the MoCap (``mocap_posed``)."""

    def __init__(self, drivers: dict[str, RobotDriver], tracker: MocapTracker | None,
                 mocap_posed: dict[str, BaseVelocityEstimator]) -> None:
        self.drivers, self.tracker, self.mocap_posed = drivers, tracker, mocap_posed

    def update(self, time_s: float, mark: Callable[[str], None] | None = None) -> TeamReading:
        """Run every stage for the tick at ``time_s`` [s, loop time]; ``mark`` (the loop's
        stage timer) is called with "read" after stage 2 and "estimate" after stage 4."""
        measurements, errors = {}, {}
        for name, driver in self.drivers.items():  # 1. joints and IMU
            try:
                measurements[name] = driver.read()
            except LinkLostError as error:
                errors[name] = str(error)
        tracker = self.tracker
        frame = tracker.poll() if tracker is not None else None  # 2. MoCap
        if mark is not None:
            mark("read")
        for name, estimator in self.mocap_posed.items():
            measurement = measurements.get(name)
            if measurement is None:
                continue
            if tracker is not None:  # 3. base pose
                position_m, mocap_velocity_m_s = tracker.body_motion(name)
            else:
                position_m, mocap_velocity_m_s = np.zeros(3), np.zeros(3)
            measurements[name] = replace(  # 4. base velocity
                measurement, position_in_world_m=position_m,
                linear_velocity_in_world_m_s=estimator.update(time_s, measurement,
                                                              mocap_velocity_m_s))
        if mark is not None:
            mark("estimate")
        return TeamReading(measurements, errors, frame)


def wbc_state(measurement: RobotMeasurement) -> FloatingBaseState:
    """The WBC's floating-base state: the robot's measurement as the pipeline left it."""
    return FloatingBaseState(
        measurement.position_in_world_m, measurement.quaternion_wxyz,
        measurement.linear_velocity_in_world_m_s, measurement.angular_velocity_in_body_rad_s,
        measurement.position_rad, measurement.velocity_rad_s)


def mocap_state(measurement: RobotMeasurement, frame: MocapFrame, name: str) -> FloatingBaseState:
    """The NMPC's robot state: pose from the MoCap frame, twist and joints from the robot."""
    position, quaternion = frame.poses[name]
    return FloatingBaseState(position, quaternion, measurement.linear_velocity_in_world_m_s,
                             measurement.angular_velocity_in_body_rad_s,
                             measurement.position_rad, measurement.velocity_rad_s)
