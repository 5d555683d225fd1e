"""The robots' URDF models in Rerun: meshes logged once, joints moved by the logged states.

Each robot's URDF (example-robot-data's, its ``package://`` mesh paths resolved to the
installed files) goes into the recording once through the rerun SDK's URDF support
(``rr.urdf.UrdfTree``: visual and collision meshes, static joint transforms) under the entity
``model_<robot>`` with frame ids ``<robot>/<link>``. Per robot state (at most ``rate_hz`` per
robot) the root link is placed in the world (the state's base pose) and the 12 leg joints
are set to their logged angles (``UrdfJoint.compute_transform``), as Rerun's animated-URDF
example does. Joint angles in porter's ``LEG_JOINT_NAMES`` order, radians; base pose in world.
"""

from __future__ import annotations

import tempfile
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import rerun as rr

from core.model.conventions import LEG_JOINT_NAMES
from drivers.robot_descriptions import robot_description, robots_directory

__all__ = ["PACKAGE_PREFIX", "RobotModels", "model_entity"]

PACKAGE_PREFIX = "package://example-robot-data/robots/"
WORLD_FRAME = "tf#/world"  # the implicit frame of the ``world`` entity (the 3D scene's)


def model_entity(robot: str) -> str:
    """The top-level entity holding ``robot``'s URDF model (the SDK takes one path part)."""
    return f"model_{robot}"


class RobotModels:
    """URDF models of the robots in ``robot_types`` (name -> type), logged to ``recording``
    on a robot's first state; ``joint_transforms`` then moves them."""

    def __init__(self, recording: rr.RecordingStream, robot_types: Mapping[str, str],
                 rate_hz: float = 50.0) -> None:
        self.recording = recording
        self.robot_types = dict(robot_types)
        self.period_ns = int(round(1e9 / rate_hz))
        self._trees: dict[str, Any] = {}
        self._joints: dict[str, list] = {}
        self._next_ns: dict[str, int] = {}
        self._folder = tempfile.TemporaryDirectory(prefix="porter-urdf-")

    def has(self, robot: str) -> bool:
        return robot in self.robot_types

    def _load(self, robot: str) -> None:
        text = robot_description(self.robot_types[robot]).urdf_path.read_text()
        # package:// is a ROS convention Rerun resolves only through ROS_PACKAGE_PATH: name the
        # installed files instead (a copy of the URDF; the process environment stays as it is)
        path = Path(self._folder.name) / f"{robot}.urdf"
        path.write_text(text.replace(PACKAGE_PREFIX, f"{robots_directory()}/"))
        tree = rr.urdf.UrdfTree.from_file_path(
            path, model_entity(robot), frame_prefix=f"{robot}/",
            static_transform_entity_path=f"{model_entity(robot)}_tf_static")
        tree.log_urdf_to_recording(self.recording)
        joints = [tree.get_joint_by_name(name) for name in LEG_JOINT_NAMES]
        missing = [n for n, j in zip(LEG_JOINT_NAMES, joints, strict=True) if j is None]
        if missing:
            raise ValueError(f"{robot}: the URDF has no joint {', '.join(missing)}")
        self._trees[robot], self._joints[robot] = tree, joints
        self._next_ns[robot] = 0

    def state(self, robot: str, time_ns: int, position_m: Any, quaternion_wxyz: Any,
              joints_rad: Any) -> bool:
        """Place ``robot``'s model for a state at ``time_ns``; False when skipped (not due,
        not finite, or an unknown robot)."""
        if robot not in self.robot_types:
            return False
        if robot not in self._trees:
            self._load(robot)
        if time_ns < self._next_ns[robot]:
            return False
        position = np.asarray(position_m, dtype=float)
        w, x, y, z = (float(v) for v in quaternion_wxyz)
        angles = np.asarray(joints_rad, dtype=float)
        if not (np.isfinite(position).all() and np.isfinite([w, x, y, z]).all()
                and np.isfinite(angles).all()):
            return False
        self._next_ns[robot] = time_ns + self.period_ns
        root = self._trees[robot].root_link().name
        self.recording.log(f"{model_entity(robot)}_pose", rr.Transform3D(
            translation=position, quaternion=rr.Quaternion(xyzw=[x, y, z, w]),
            parent_frame=WORLD_FRAME, child_frame=f"{robot}/{root}"))
        for joint, angle in zip(self._joints[robot], angles, strict=True):
            self.recording.log(f"{model_entity(robot)}_joints/{joint.name}",
                               joint.compute_transform(float(angle), clamp=False))
        return True
