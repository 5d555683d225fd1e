"""The estimator pipeline's stages, in order, on a simulated team read the way the Unitree
drivers read it (no world position, no linear velocity), with a MoCap tracker beside it."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from core.estimation.base_velocity import BaseVelocityEstimator
from core.plant.standard_scenarios import ring_team_settings
from deploy.runtime.links import MocapTracker
from deploy.runtime.state_pipeline import StatePipeline, mocap_state, wbc_state
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement
from drivers.link_errors import LinkLostError
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import load_pinocchio_model, srb_parameters
from tests.deploy.runtime.fakes import FakeClock
from tests.deploy.runtime.test_links import FakeMocap


class UnitreeLikeDriver:
    """A simulated robot read as a Unitree driver reads it: world position and linear velocity
    zero; ``lost`` makes ``read`` raise as a timed-out link does."""

    def __init__(self, simulation: TeamSimulation, name: str) -> None:
        self.inner, self.name, self.lost = simulation.robot_driver(name), name, False

    def read(self) -> RobotMeasurement:
        if self.lost:
            raise LinkLostError(f"{self.name}: no state for 0.2 s")
        return replace(self.inner.read(), position_in_world_m=np.zeros(3),
                       linear_velocity_in_world_m_s=np.zeros(3))

    def send(self, command: JointCommand) -> None:
        self.inner.send(command)


@pytest.fixture
def team():
    simulation = TeamSimulation(build_team_scene(ring_team_settings(["go2", "go2"],
                                                                    srb_parameters)))
    clock = FakeClock(1.0)
    source = FakeMocap(clock)
    tracker = MocapTracker(source, {"go2_0": "A", "go2_1": "B"}, 0.08, clock)
    drivers = {name: UnitreeLikeDriver(simulation, name) for name in ("go2_0", "go2_1")}
    estimators = {name: BaseVelocityEstimator(load_pinocchio_model("go2")) for name in drivers}
    return simulation, source, tracker, drivers, StatePipeline(drivers, tracker, estimators)


def test_the_stages_fill_the_base_state_from_the_mocap_and_the_legs(team) -> None:
    simulation, source, tracker, drivers, pipeline = team
    marks: list[str] = []
    truth = {name: simulation.base_pose(name) for name in drivers}
    source.push(MocapFrame(1.0, {"A": truth["go2_0"], "B": truth["go2_1"]}))
    reading = pipeline.update(1.0, marks.append)
    assert marks == ["read", "estimate"] and reading.link_errors == {}
    assert reading.frame is not None and set(reading.frame.poses) == {"go2_0", "go2_1"}
    for name, measurement in reading.measurements.items():
        # stage 3 placed the base where the MoCap (polled in stage 2 of this tick) saw it
        np.testing.assert_allclose(measurement.position_in_world_m, truth[name][0])
        # stage 4: the team stands still, so legs and MoCap agree on ~zero velocity
        np.testing.assert_allclose(measurement.linear_velocity_in_world_m_s, 0.0, atol=0.05)
        state = wbc_state(measurement)
        np.testing.assert_allclose(state.position_base_in_world_m, truth[name][0])
        nmpc = mocap_state(measurement, reading.frame, name)
        np.testing.assert_allclose(nmpc.quaternion_wxyz, truth[name][1])


def test_a_lost_link_is_reported_and_the_others_still_estimated(team) -> None:
    simulation, source, tracker, drivers, pipeline = team
    drivers["go2_1"].lost = True
    source.push(MocapFrame(1.0, {"A": simulation.base_pose("go2_0")}))
    reading = pipeline.update(1.0)
    assert set(reading.measurements) == {"go2_0"}
    assert reading.link_errors == {"go2_1": "go2_1: no state for 0.2 s"}


def test_the_fused_velocity_follows_the_mocap_mean_over_the_correction_time() -> None:
    """Legs at rest, MoCap at 0.1 m/s along x: the correction starts at the difference and
    then low-passes it with ``correction_time_s``."""
    simulation = TeamSimulation(build_team_scene(ring_team_settings(["go2", "go2"],
                                                                    srb_parameters)))
    measurement = simulation.robot_driver("go2_0").read()
    estimator = BaseVelocityEstimator(load_pinocchio_model("go2"), correction_time_s=0.2)
    legs = estimator.leg_odometry(measurement)
    assert legs is not None
    first = estimator.update(0.0, measurement, np.array([0.1, 0.0, 0.0]))
    np.testing.assert_allclose(first, [0.1, 0.0, 0.0], atol=1e-12)
    # the MoCap drops to zero: after one correction time the estimate has moved all the way
    later = estimator.update(0.2, measurement, np.zeros(3))
    np.testing.assert_allclose(later, legs + (np.zeros(3) - legs), atol=1e-12)
    half = BaseVelocityEstimator(load_pinocchio_model("go2"), correction_time_s=0.2)
    half.update(0.0, measurement, np.array([0.1, 0.0, 0.0]))
    midway = half.update(0.1, measurement, np.zeros(3))  # half a correction time
    np.testing.assert_allclose(midway - legs, 0.5 * (np.array([0.1, 0.0, 0.0]) - legs),
                               atol=1e-12)
