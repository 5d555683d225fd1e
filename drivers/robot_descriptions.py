"""Robot description files shipped by ``example-robot-data``: where they are and how to load them.

This is the only place that knows file locations; the controller receives built models and
SRB parameters.
"""

from __future__ import annotations

import re
import sysconfig
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import pinocchio as pin

from core.model.robot_parameters import srb_parameters_from_model
from core.model.srb_model import SrbParameters
from core.model.team_settings import ROBOT_TYPES

# Foot collision sphere radii [m] of the shipped descriptions (go2 foot sphere, a1 foot sphere).
FOOT_RADIUS_M = {"go2": 0.022, "a1": 0.02}


class UnknownRobotError(ValueError):
    """Raised for a robot type that has no shipped description."""


def robots_directory() -> Path:
    """Folder holding ``<robot>_description`` directories of example-robot-data."""
    prefix = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix"
    path = prefix / "share" / "example-robot-data" / "robots"
    if not path.is_dir():
        raise FileNotFoundError(f"example-robot-data robots not found at {path}")
    return path


@dataclass(frozen=True)
class RobotDescription:
    robot_type: str
    urdf_path: Path
    srdf_path: Path
    package_directory: Path


def robot_description(robot_type: str) -> RobotDescription:
    if robot_type not in ROBOT_TYPES:
        raise UnknownRobotError(
            f"unknown robot type {robot_type!r}; available: {', '.join(ROBOT_TYPES)}"
        )
    base = robots_directory() / f"{robot_type}_description"
    return RobotDescription(
        robot_type=robot_type,
        urdf_path=base / "urdf" / f"{robot_type}.urdf",
        srdf_path=base / "srdf" / f"{robot_type}.srdf",
        package_directory=robots_directory(),
    )


@cache
def load_pinocchio_model(robot_type: str) -> pin.Model:
    """Free-flyer Pinocchio model of the robot (base quaternion xyzw in q[3:7]); parsed once per
    process and shared: read it, never change it (each user makes its own ``pin.Data``)."""
    description = robot_description(robot_type)
    return pin.buildModelFromUrdf(str(description.urdf_path), pin.JointModelFreeFlyer())


def standing_configuration(robot_type: str, model: pin.Model) -> np.ndarray:
    """The SRDF's ``standing`` group state as a Pinocchio configuration vector."""
    text = robot_description(robot_type).srdf_path.read_text()
    block = re.search(r'<group_state name="standing".*?</group_state>', text, re.S)
    if block is None:
        raise ValueError(f"{robot_type}: SRDF has no 'standing' group state")
    q = pin.neutral(model)
    for joint, value in re.findall(r'<joint name="([^"]+)" value="([^"]+)"', block.group(0)):
        values = [float(v) for v in value.split()]
        joint_id = model.getJointId(joint)
        index = model.joints[joint_id].idx_q
        q[index : index + len(values)] = values
    return q


@cache
def srb_parameters(robot_type: str) -> SrbParameters:
    """SRB parameters of ``robot_type`` computed from its URDF (cached per process)."""
    model = load_pinocchio_model(robot_type)
    q = standing_configuration(robot_type, model)
    return srb_parameters_from_model(robot_type, model, q, FOOT_RADIUS_M[robot_type])
