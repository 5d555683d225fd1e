"""The robots in Foxglove from the log alone: every link's pose and the links' shapes.

- ``LinkTransforms`` turns logged robot states (``/robot/<name>/state``: base pose and the 12
  joint angles) into ``foxglove.FrameTransforms`` on ``/tf/links``: world -> ``<robot>/<link>``
  for every link of the robot's URDF, through its Pinocchio model. It runs in the recorder's
  writer thread (a deriver, off the loop) at ``rate_hz`` per robot (50 Hz by default: the
  robots' states arrive at 500 Hz; a tenth is smooth in a viewer and costs ~2 % of a core).
- ``robot_scene`` is one ``foxglove.SceneUpdate`` on ``/robots/scene``, written once at the
  start: per robot and link an entity locked to the frame ``<robot>/<link>`` carrying the
  URDF's collision geometry — meshes embedded as STL bytes (``ModelPrimitive``, media type
  ``model/stl``), boxes, cylinders and spheres as Foxglove primitives. Collision geometry, not
  the visual meshes: the Go2's are convex STL hulls (0.25 MB for a robot; its visual COLLADA
  meshes are 5 MB, the A1's 9.4 MB), and the A1's are primitives. Embedded, they open in
  Foxglove without porter, without ROS package paths and without network access (the URDF
  attachments name ``package://`` meshes, which no viewer resolves from an MCAP file).

Frames: world as in ``deploy.recording.log_format``; each link's pose is that of the robot
model's body frame for the logged state (the measured base pose on robots, the simulator's
on the sim backend) — what porter believed, not the ground truth of ``/tf``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from collections.abc import Iterator
from typing import Any

import numpy as np
import pinocchio as pin
from foxglove_schemas_protobuf.FrameTransform_pb2 import FrameTransform
from foxglove_schemas_protobuf.FrameTransforms_pb2 import FrameTransforms
from foxglove_schemas_protobuf.SceneEntity_pb2 import SceneEntity
from foxglove_schemas_protobuf.SceneUpdate_pb2 import SceneUpdate

from core.model.robot_parameters import leg_joint_indices
from deploy.recording.log_format import WORLD_FRAME, robot_topic, timestamp
from drivers.robot_descriptions import load_pinocchio_model, robot_description, robots_directory

__all__ = ["LINK_TF", "ROBOT_SCENE", "LinkTransforms", "link_frame", "robot_scene"]

LINK_TF = "/tf/links"
ROBOT_SCENE = "/robots/scene"
PACKAGE_PREFIX = "package://example-robot-data/robots/"
_COLOR = (0.85, 0.85, 0.8, 1.0)


def link_frame(robot: str, link: str) -> str:
    """The frame id of ``robot``'s ``link``: ``<robot>/<link>``."""
    return f"{robot}/{link}"


class _RobotModel:
    """One robot type's Pinocchio model, its body frames and where its leg joints sit in q."""

    def __init__(self, robot_type: str) -> None:
        self.model = load_pinocchio_model(robot_type)
        self.data = self.model.createData()
        self.q_index, _ = leg_joint_indices(self.model)
        self.links = [(i, frame.name) for i, frame in enumerate(self.model.frames)
                      if frame.type == pin.FrameType.BODY]

    def link_poses(self, position_m: np.ndarray, quaternion_wxyz: np.ndarray,
                   joints_rad: np.ndarray) -> Iterator[tuple[str, pin.SE3]]:
        q = pin.neutral(self.model)
        q[0:3] = position_m
        w, x, y, z = quaternion_wxyz / np.linalg.norm(quaternion_wxyz)
        q[3:7] = (x, y, z, w)  # Pinocchio's free flyer: quaternion x, y, z, w
        q[self.q_index] = joints_rad
        pin.framesForwardKinematics(self.model, self.data, q)
        for index, name in self.links:
            yield name, self.data.oMf[index]


class LinkTransforms:
    """A recorder deriver: from ``/robot/<name>/state`` messages, world -> link transforms on
    ``LINK_TF`` at ``rate_hz`` per robot (the first state and then one per period)."""

    def __init__(self, robot_types: dict[str, str], rate_hz: float = 50.0) -> None:
        models = {t: _RobotModel(t) for t in sorted(set(robot_types.values()))}
        self._robots = {robot_topic(name, "state"): (name, models[t])
                        for name, t in robot_types.items()}
        self.period_ns = int(round(1e9 / rate_hz))
        self._next_ns = dict.fromkeys(self._robots, 0)

    def __call__(self, topic: str, message: Any, log_time_ns: int
                 ) -> list[tuple[str, FrameTransforms]]:
        robot = self._robots.get(topic)
        if robot is None or log_time_ns < self._next_ns[topic]:
            return []
        self._next_ns[topic] = log_time_ns + self.period_ns
        name, model = robot
        base = np.asarray(message.position_in_world_m, dtype=float)
        quaternion = np.asarray(message.quaternion_wxyz, dtype=float)
        joints = np.asarray(message.joint_position_rad, dtype=float)
        if not (np.isfinite(base).all() and np.isfinite(quaternion).all()
                and np.isfinite(joints).all() and np.linalg.norm(quaternion) > 0.0):
            return []  # nothing drawable in a non-finite state (the log keeps the state)
        stamp = timestamp(log_time_ns * 1e-9)
        transforms = FrameTransforms()
        for link, pose in model.link_poses(base, quaternion, joints):
            transform = FrameTransform(timestamp=stamp, parent_frame_id=WORLD_FRAME,
                                       child_frame_id=link_frame(name, link))
            _set_vector(transform.translation, pose.translation)
            _set_quaternion(transform.rotation, pose.rotation)
            transforms.transforms.append(transform)
        return [(LINK_TF, transforms)]


def robot_scene(robot_types: dict[str, str]) -> SceneUpdate:
    """Every robot's links as scene entities (frame ``<robot>/<link>``, frame locked, no
    lifetime) carrying the URDF's collision geometry; STL meshes embedded."""
    update = SceneUpdate()
    geometry = {t: _collision_geometry(t) for t in sorted(set(robot_types.values()))}
    for name, robot_type in robot_types.items():
        for link, shapes in geometry[robot_type].items():
            entity = SceneEntity(timestamp=timestamp(0.0), frame_id=link_frame(name, link),
                                 id=link_frame(name, link), frame_locked=True)
            for kind, pose, shape in shapes:
                primitive = {"mesh": entity.models, "box": entity.cubes,
                             "cylinder": entity.cylinders, "sphere": entity.spheres}[kind].add()
                _set_vector(primitive.pose.position, pose.translation)
                _set_quaternion(primitive.pose.orientation, pose.rotation)
                primitive.color.r, primitive.color.g, primitive.color.b, primitive.color.a = _COLOR
                _fill(primitive, kind, shape)
            update.entities.append(entity)
    return update


def _fill(primitive: Any, kind: str, shape: dict[str, Any]) -> None:
    if kind == "mesh":
        primitive.data, primitive.media_type = shape["data"], "model/stl"
        primitive.scale.x, primitive.scale.y, primitive.scale.z = shape["scale"]
        primitive.override_color = True
    elif kind == "box":
        primitive.size.x, primitive.size.y, primitive.size.z = shape["size"]
    elif kind == "cylinder":  # URDF and Foxglove cylinders both lie along their local z
        primitive.size.x = primitive.size.y = 2.0 * shape["radius"]
        primitive.size.z = shape["length"]
        primitive.bottom_scale = primitive.top_scale = 1.0
    else:
        primitive.size.x = primitive.size.y = primitive.size.z = 2.0 * shape["radius"]


def _collision_geometry(robot_type: str) -> dict[str, list[tuple[str, pin.SE3, dict]]]:
    """Per link: (kind, pose in the link frame, shape) of each URDF ``<collision>``."""
    root = ElementTree.parse(robot_description(robot_type).urdf_path).getroot()
    links: dict[str, list[tuple[str, pin.SE3, dict]]] = {}
    for link in root.iter("link"):
        for collision in link.iter("collision"):
            origin = collision.find("origin")
            xyz = _floats(origin, "xyz", 3) if origin is not None else np.zeros(3)
            rpy = _floats(origin, "rpy", 3) if origin is not None else np.zeros(3)
            pose = pin.SE3(pin.rpy.rpyToMatrix(*rpy), xyz)
            geometry = collision.find("geometry")
            for element in list(geometry) if geometry is not None else []:
                shape = _shape(element)
                if shape is not None:
                    links.setdefault(link.get("name", ""), []).append((element.tag, pose, shape))
    return links


def _shape(element: ElementTree.Element) -> dict[str, Any] | None:
    if element.tag == "mesh":
        filename = element.get("filename", "")
        if not filename.startswith(PACKAGE_PREFIX) or not filename.lower().endswith(".stl"):
            return None  # only example-robot-data's STL meshes are embedded
        path = robots_directory() / filename.removeprefix(PACKAGE_PREFIX)
        scale = _floats(element, "scale", 3) if element.get("scale") else np.ones(3)
        return {"data": path.read_bytes(), "scale": tuple(float(v) for v in scale)}
    if element.tag == "box":
        return {"size": tuple(float(v) for v in _floats(element, "size", 3))}
    if element.tag == "cylinder":
        return {"radius": float(element.get("radius", 0)), "length": float(element.get("length", 0))}
    if element.tag == "sphere":
        return {"radius": float(element.get("radius", 0))}
    return None


def _floats(element: ElementTree.Element, attribute: str, count: int) -> np.ndarray:
    values = np.array([float(v) for v in element.get(attribute, "").split()])
    return values if values.size == count else np.zeros(count)


def _set_vector(target: Any, values: np.ndarray) -> None:
    target.x, target.y, target.z = (float(v) for v in values)


def _set_quaternion(target: Any, rotation: np.ndarray) -> None:
    x, y, z, w = pin.Quaternion(rotation).coeffs()
    target.x, target.y, target.z, target.w = float(x), float(y), float(z), float(w)
