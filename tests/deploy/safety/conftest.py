"""The team the supervisor tests share: a Go2 and an A1 in a MuJoCo scene, their URDF limits
and their standing measurements."""

from __future__ import annotations

import pytest

from core.plant.standard_scenarios import ring_team_settings
from deploy.safety.supervisor import RobotLimits, robot_limits
from drivers.interfaces import RobotMeasurement
from drivers.mujoco.scene import TeamScene, build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters


@pytest.fixture(scope="module")
def scene() -> TeamScene:
    return build_team_scene(ring_team_settings(["go2", "a1"], srb_parameters))


@pytest.fixture(scope="module")
def limits(scene) -> list[RobotLimits]:
    return [robot_limits(robot.robot_type, robot.name) for robot in scene.robots]


@pytest.fixture(scope="module")
def standing(scene) -> dict[str, RobotMeasurement]:
    """Measurements of the team standing still (the scene's initial state)."""
    simulation = TeamSimulation(scene)
    return {robot.name: simulation.robot_driver(robot.name).read() for robot in scene.robots}
