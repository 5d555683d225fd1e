"""The flight-recorder log format: topics, version, and conversions to and from messages.

One MCAP file per run, protobuf encoding. Foxglove's well-known schemas where one fits
(``/tf`` FrameTransforms of the ground truth, ``/mocap/<body>`` PoseInFrame, ``/obstacles``
SceneUpdate), porter's own messages (``deploy/messages/porter_log.proto``) for the rest.
Run time is the run's clock: simulated time in simulation, time since the start of the run
on robots; porter's messages carry it (``time_s``). The file's log times are on the wall clock
(the run's start + run time, ``CLOCK_METADATA``; ``deploy.recording.flight_recorder``), and
so are the Foxglove messages' timestamps (``on_log_clock``). Quaternions are (w, x, y, z) in
porter messages and (x, y, z, w) in Foxglove ones: converted here, once.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from foxglove_schemas_protobuf.CubePrimitive_pb2 import CubePrimitive
from foxglove_schemas_protobuf.CylinderPrimitive_pb2 import CylinderPrimitive
from foxglove_schemas_protobuf.FrameTransform_pb2 import FrameTransform
from foxglove_schemas_protobuf.FrameTransforms_pb2 import FrameTransforms
from foxglove_schemas_protobuf.Log_pb2 import Log
from foxglove_schemas_protobuf.PoseInFrame_pb2 import PoseInFrame
from foxglove_schemas_protobuf.SceneEntity_pb2 import SceneEntity
from foxglove_schemas_protobuf.SceneUpdate_pb2 import SceneUpdate
from google.protobuf.timestamp_pb2 import Timestamp

from core.model.conventions import PAYLOAD_NAME
from core.model.obstacles import Obstacle
from deploy.recording.messages import porter_log_pb2 as pb
from drivers.interfaces import JointCommand, MocapFrame, RobotMeasurement

LOG_FORMAT_VERSION = 2  # bump when a message or topic changes meaning
# 1: log times were run times (no clock record); still read, with time origin 0
READABLE_LOG_FORMAT_VERSIONS = ("1", "2")
PROFILE = "porter"
WORLD_FRAME = "world"

# metadata records
RUN_METADATA = "porter"  # format version, versions, machine, scenario
SUMMARY_METADATA = "summary"  # the run's summary metrics (JSON under key "json")
CLOCK_METADATA = "clock"  # time_origin_ns: Unix time [ns] of run time 0 (log time - run time)

# attachments
SCENARIO_ATTACHMENT = "scenario.yaml"
MPC_SETTINGS_ATTACHMENT = "mpc_settings.yaml"
WBC_SETTINGS_ATTACHMENT = "wbc_settings.yaml"
DEPLOY_CONFIG_ATTACHMENT = "deploy_config.yaml"  # porter deploy: the config as run

# topics
TF = "/tf"
OBSTACLES = "/obstacles"
NMPC_INPUTS = "/nmpc/inputs"
NMPC_WARM_START = "/nmpc/warm_start"
NMPC_UPDATE = "/nmpc/update"
ADMM = "/nmpc/admm"
CBF = "/safety/cbf"
PAYLOAD_ESTIMATE = "/payload/estimate"
GROUND_TRUTH = "/sim/ground_truth"
LOOP_TIMING = "/loop/timing"
EVENTS = "/events"
FOXGLOVE_LOG = "/log"  # every event again as foxglove.Log, for Foxglove's Log panel

# porter's Event levels -> foxglove.Log levels (INFO 2, WARNING 3, ERROR 4)
_FOXGLOVE_LEVEL = {pb.Event.INFO: Log.INFO, pb.Event.WARNING: Log.WARNING,
                   pb.Event.ERROR: Log.ERROR}


def foxglove_log(event: pb.Event) -> Log:
    """``event`` as a ``foxglove.Log`` (name: its source)."""
    return Log(timestamp=timestamp(event.time_s), level=_FOXGLOVE_LEVEL.get(event.level, Log.UNKNOWN),
               message=event.text, name=event.source)


def robot_topic(robot: str, kind: str) -> str:
    """``/robot/<robot>/<kind>``, kind in state, command, wbc, wrench."""
    return f"/robot/{robot}/{kind}"


def mocap_topic(body: str) -> str:
    return f"/mocap/{body}"


def to_nanoseconds(time_s: float) -> int:
    return max(int(round(time_s * 1e9)), 0)


def on_log_clock(message: Any, time_origin_ns: int) -> Any:
    """A Foxglove ``message`` with its timestamps moved from run time to the log's clock (+
    ``time_origin_ns``), as a copy; porter's own messages as they are (they keep run time)."""
    if time_origin_ns == 0 or not message.DESCRIPTOR.full_name.startswith("foxglove."):
        return message
    original, message = message, type(message)()
    message.CopyFrom(original)
    fields = message.DESCRIPTOR.fields_by_name
    stamps = [message.timestamp] if "timestamp" in fields else []
    for name in ("transforms", "entities", "deletions"):
        if name in fields:
            stamps += [item.timestamp for item in getattr(message, name)]
    for stamp in stamps:
        stamp.seconds, stamp.nanos = divmod(
            stamp.seconds * 1_000_000_000 + stamp.nanos + time_origin_ns, 1_000_000_000)
    return message


def timestamp(time_s: float) -> Timestamp:
    nanoseconds = to_nanoseconds(time_s)
    return Timestamp(seconds=nanoseconds // 1_000_000_000, nanos=nanoseconds % 1_000_000_000)


def array(values: np.ndarray | None) -> pb.Array:
    """A numpy array as a row-major ``Array`` (None gives an empty one)."""
    if values is None:
        return pb.Array()
    values = np.asarray(values, dtype=float)
    # lists convert into repeated fields several times faster than numpy arrays
    return pb.Array(shape=values.shape, values=values.reshape(-1).tolist())


def from_array(message: pb.Array) -> np.ndarray:
    """The numpy array of an ``Array`` message (shape restored)."""
    return np.asarray(message.values, dtype=float).reshape(tuple(message.shape))


def robot_state(robot: str, measurement: RobotMeasurement) -> pb.RobotState:
    m = measurement
    return pb.RobotState(
        time_s=m.time_s, robot=robot, position_in_world_m=as_list(m.position_in_world_m),
        quaternion_wxyz=as_list(m.quaternion_wxyz),
        linear_velocity_in_world_m_s=as_list(m.linear_velocity_in_world_m_s),
        angular_velocity_in_body_rad_s=as_list(m.angular_velocity_in_body_rad_s),
        joint_position_rad=as_list(m.position_rad), joint_velocity_rad_s=as_list(m.velocity_rad_s),
        joint_torque_nm=as_list(m.torque_nm), foot_normal_force_n=as_list(m.foot_normal_force_n),
        foot_contact=np.asarray(m.foot_contact, dtype=bool).tolist())


def joint_command(time_s: float, robot: str, command: JointCommand) -> pb.JointCommand:
    return pb.JointCommand(time_s=time_s, robot=robot, torque_nm=as_list(command.torque_nm),
                           position_rad=as_list(command.position_rad),
                           velocity_rad_s=as_list(command.velocity_rad_s),
                           kp=as_list(command.kp), kd=as_list(command.kd))


def as_list(values: np.ndarray) -> list[float]:
    return np.asarray(values, dtype=float).reshape(-1).tolist()


def pose_in_frame(time_s: float, position_m: np.ndarray, quaternion_wxyz: np.ndarray
                  ) -> PoseInFrame:
    message = PoseInFrame(timestamp=timestamp(time_s), frame_id=WORLD_FRAME)
    _set_pose(message.pose, position_m, quaternion_wxyz)
    return message


def frame_transforms(time_s: float, poses: dict[str, tuple[np.ndarray, np.ndarray]]
                     ) -> FrameTransforms:
    """World -> body transforms (ground truth) for every named body."""
    message = FrameTransforms()
    for name, (position, quaternion) in poses.items():
        transform = FrameTransform(timestamp=timestamp(time_s), parent_frame_id=WORLD_FRAME,
                                   child_frame_id=name)
        transform.translation.x, transform.translation.y, transform.translation.z = (
            float(v) for v in position)
        w, x, y, z = (float(v) for v in quaternion)
        transform.rotation.x, transform.rotation.y = x, y
        transform.rotation.z, transform.rotation.w = z, w
        message.transforms.append(transform)
    return message


def mocap_messages(frame: MocapFrame) -> dict[str, PoseInFrame]:
    """One PoseInFrame per MoCap rigid body, keyed by topic."""
    return {mocap_topic(name): pose_in_frame(frame.time_s, position, quaternion)
            for name, (position, quaternion) in frame.poses.items()}


def obstacle_scene(time_s: float, obstacles: list[Obstacle], safety_distance_m: float,
                   height_m: list[float]) -> SceneUpdate:
    """Obstacles as Foxglove cylinders, each with its safety circle (radius + d, translucent)."""
    update = SceneUpdate()
    for j, (obstacle, height) in enumerate(zip(obstacles, height_m, strict=True)):
        row = obstacle.row(time_s, safety_distance_m)
        entity = SceneEntity(timestamp=timestamp(time_s), frame_id=WORLD_FRAME,
                             id=f"obstacle_{j}", frame_locked=False)
        for radius, z_size, alpha in ((obstacle.radius_m, height, 1.0),
                                      (obstacle.radius_m + safety_distance_m, 0.01, 0.25)):
            cylinder = CylinderPrimitive(bottom_scale=1.0, top_scale=1.0)
            cylinder.pose.position.x, cylinder.pose.position.y = float(row[0]), float(row[1])
            cylinder.pose.position.z = z_size / 2
            cylinder.pose.orientation.w = 1.0
            cylinder.size.x = cylinder.size.y = 2 * radius
            cylinder.size.z = z_size
            cylinder.color.r, cylinder.color.g, cylinder.color.b, cylinder.color.a = (
                0.8, 0.3, 0.2, alpha)
            entity.cylinders.append(cylinder)
        update.entities.append(entity)
    return update


def payload_box(time_s: float, size_m: np.ndarray) -> SceneUpdate:
    """The payload as a Foxglove cube locked to its ``/tf`` frame."""
    entity = SceneEntity(timestamp=timestamp(time_s), frame_id=PAYLOAD_NAME, id=PAYLOAD_NAME,
                         frame_locked=True)
    cube = CubePrimitive()
    cube.pose.orientation.w = 1.0
    cube.size.x, cube.size.y, cube.size.z = (float(v) for v in size_m)
    cube.color.r, cube.color.g, cube.color.b, cube.color.a = 0.2, 0.5, 0.9, 0.8
    entity.cubes.append(cube)
    return SceneUpdate(entities=[entity])


def _set_pose(pose: Any, position_m: np.ndarray, quaternion_wxyz: np.ndarray) -> None:
    pose.position.x, pose.position.y, pose.position.z = (float(v) for v in position_m)
    w, x, y, z = (float(v) for v in quaternion_wxyz)
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = x, y, z, w
