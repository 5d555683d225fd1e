"""The robots in Foxglove from the MCAP alone: read with the mcap library only, every link of
every robot has a transform to world at each sampled time, the transforms follow the logged
joint angles, and the embedded meshes decode as STL."""

from __future__ import annotations

import struct
import xml.etree.ElementTree as ElementTree
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest
from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

from core.model.conventions import LEG_JOINT_NAMES
from deploy.recording import log_format as fmt
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.recording.robot_scene import LINK_TF, ROBOT_SCENE, LinkTransforms, robot_scene

ROBOTS = ("go2_0", "go2_1")


def _read(path: Path) -> tuple[dict, dict[str, bytes], list]:
    with open(path, "rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        metadata = {m.name: dict(m.metadata) for m in reader.iter_metadata()}
        attachments = {a.name: bytes(a.data) for a in reader.iter_attachments()}
        messages = [(channel.topic, message.log_time, decoded) for _, channel, message, decoded
                    in reader.iter_decoded_messages(log_time_order=True)]
    return metadata, attachments, messages


def _rotation(quaternion) -> np.ndarray:
    x, y, z, w = quaternion.x, quaternion.y, quaternion.z, quaternion.w
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def _stl_triangles(data: bytes) -> int:
    """Triangles of a binary STL (80-byte header, count, 50 bytes each); asserts it is one."""
    (count,) = struct.unpack_from("<I", data, 80)
    assert len(data) == 84 + 50 * count and count > 0
    values = np.frombuffer(data[84:], dtype=np.dtype([("f", "<f4", 12), ("a", "<u2")]))
    assert np.isfinite(values["f"]).all()
    return count


def test_every_link_has_a_transform_to_world_that_follows_the_logged_joints(
        recorded_run: tuple[Path, list, dict]) -> None:
    metadata, attachments, messages = _read(recorded_run[0])
    origin_ns = int(metadata[fmt.CLOCK_METADATA]["time_origin_ns"])
    urdf = ElementTree.fromstring(attachments["robots/go2.urdf"])
    links = {link.get("name") for link in urdf.iter("link")}
    joints = {joint.get("name"): joint for joint in urdf.iter("joint")}
    states: dict[tuple[str, int], pb.RobotState] = {}
    samples: dict[str, list] = defaultdict(list)
    for topic, log_time, message in messages:
        if topic.endswith("/state") and topic.startswith("/robot/"):
            states[(message.robot, log_time)] = message
        elif topic == LINK_TF:
            samples[message.transforms[0].child_frame_id.split("/")[0]].append(
                (log_time, message))
    assert set(samples) == set(ROBOTS)
    for robot, robot_samples in samples.items():
        times_s = np.array([t for t, _ in robot_samples]) * 1e-9 - origin_ns * 1e-9
        assert times_s[0] == pytest.approx(0.0, abs=0.003)
        assert np.diff(times_s) == pytest.approx(0.02, abs=0.0025)  # 50 Hz of 500 Hz states
        for log_time, message in robot_samples:
            frames = {t.child_frame_id: t for t in message.transforms}
            # every URDF link, each directly under world (the chain to world is one step)
            assert set(frames) == {f"{robot}/{link}" for link in links}
            assert {t.parent_frame_id for t in message.transforms} == {fmt.WORLD_FRAME}
            assert all(t.timestamp.ToNanoseconds() == log_time for t in message.transforms)
            state = states[(robot, log_time)]
            base = frames[f"{robot}/base"]
            np.testing.assert_allclose([base.translation.x, base.translation.y,
                                        base.translation.z], state.position_in_world_m,
                                       atol=1e-9)
            # the knee: the calf's rotation relative to the thigh is the logged knee angle
            # about the joint's axis (y; its origin has no rotation in the Go2's URDF)
            for leg in ("FL", "RR"):
                joint = joints[f"{leg}_calf_joint"]
                assert joint.find("axis").get("xyz").split() == ["0", "1", "0"]
                relative = (_rotation(frames[f"{robot}/{leg}_thigh"].rotation).T
                            @ _rotation(frames[f"{robot}/{leg}_calf"].rotation))
                angle = np.arctan2(relative[0, 2], relative[0, 0])
                knee = state.joint_position_rad[LEG_JOINT_NAMES.index(f"{leg}_calf_joint")]
                assert angle == pytest.approx(knee, abs=1e-6)
                offset = np.array([float(v) for v in joint.find("origin").get("xyz").split()])
                thigh, calf = (frames[f"{robot}/{leg}_{part}"].translation
                               for part in ("thigh", "calf"))
                assert np.linalg.norm([calf.x - thigh.x, calf.y - thigh.y, calf.z - thigh.z]) \
                    == pytest.approx(np.linalg.norm(offset), abs=1e-9)


def test_the_robot_meshes_are_embedded_and_decode(recorded_run: tuple[Path, list, dict]
                                                  ) -> None:
    _, attachments, messages = _read(recorded_run[0])
    (scene,) = [m for topic, _, m in messages if topic == ROBOT_SCENE]
    frames = {t.child_frame_id for topic, _, m in messages if topic == LINK_TF
              for t in m.transforms}
    urdf = ElementTree.fromstring(attachments["robots/go2.urdf"])
    with_geometry = {link.get("name") for link in urdf.iter("link")
                     if link.find("collision") is not None}
    assert {e.id for e in scene.entities} == {f"{r}/{link}" for r in ROBOTS
                                              for link in with_geometry}
    triangles = 0
    for entity in scene.entities:
        assert entity.frame_locked and entity.frame_id in frames
        for model in entity.models:
            assert model.media_type == "model/stl" and not model.url
            triangles += _stl_triangles(model.data)
    assert triangles > 1000


def test_the_a1_is_drawn_from_primitives_and_bad_states_are_skipped() -> None:
    """The A1's URDF collision geometry is boxes, cylinders and spheres; a state that is not
    finite gives no transforms (the state itself stays in the log)."""
    scene = robot_scene({"a1_0": "a1"})
    shapes = {kind: sum(len(getattr(e, kind)) for e in scene.entities)
              for kind in ("cubes", "cylinders", "spheres", "models")}
    assert shapes["cubes"] >= 9 and shapes["cylinders"] == 8 and shapes["spheres"] == 4
    assert shapes["models"] == 0
    derive = LinkTransforms({"a1_0": "a1"}, rate_hz=10.0)
    state = pb.RobotState(robot="a1_0", position_in_world_m=[1.0, 2.0, 0.3],
                          quaternion_wxyz=[1.0, 0.0, 0.0, 0.0],
                          joint_position_rad=[0.0, 0.8, -1.5] * 4)
    topic = fmt.robot_topic("a1_0", "state")
    assert len(derive(topic, state, 0)[0][1].transforms) == 23  # the A1's body frames
    assert derive(topic, state, 50_000_000) == []  # within the 0.1 s period
    assert derive(fmt.robot_topic("other", "state"), state, 200_000_000) == []
    state.joint_position_rad[4] = float("nan")
    assert derive(topic, state, 200_000_000) == []
