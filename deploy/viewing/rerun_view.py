"""Porter log messages as Rerun data: the 3D team scene, time series and events.

``RerunLogView.handle(topic, message, log_time_ns)`` takes the decoded messages of a flight
log (``deploy.recording.log_format``) in log-time order, from ``porter replay`` or live from the flight
recorder's writer thread (``live_sink``, ``porter sim --rerun``), and logs them to its own
``rr.RecordingStream`` on the ``sim_time`` timeline (ADMM iterations also on
``admm_iteration``). Entity paths and the layout are in ``deploy.viewing.layout``. Poses come
from the ground truth (``/tf``) where the log has it, otherwise from the robots' own state and
the MoCap payload pose (hardware). Robots whose type is known (``robot_types``) are drawn as
their URDF models, legs moved by the logged joint angles (``deploy.viewing.robot_models``),
others as SRB boxes. Topics without a view (commands, NMPC inputs, warm starts) are skipped.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
import rerun as rr

from core.model.conventions import PAYLOAD_NAME
from core.model.rotations import rotation_from_quaternion_wxyz
from deploy.recording import log_format as fmt
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.viewing import layout as paths
from deploy.viewing.robot_models import RobotModels
from deploy.viewing.series import SeriesLogger

PAYLOAD_BOX_TOPIC = "/payload/box"
GO2_TRUNK_SIZE_M = (0.38, 0.09, 0.11)
A1_TRUNK_SIZE_M = (0.27, 0.19, 0.11)
ROBOT_COLORS = [(230, 120, 40), (60, 170, 90), (150, 90, 200), (220, 60, 110), (40, 160, 200)]
PLAN_COLOR, CONSENSUS_COLOR = (250, 200, 40), (240, 240, 240)
MEASURED_COLOR, PREDICTED_COLOR = (240, 80, 60), (60, 140, 250)

Pose = tuple[np.ndarray, np.ndarray]  # position in world [m], rotation matrix world <- body


class RerunLogView:
    """Logs porter messages to ``recording``.

    ``robot_names``: the team in agent order (learned from the topics when not given);
    ``coupling_points_m``: per robot (point in payload frame, point in robot frame) [m], for
    the coupling segments and wrench arrows (payload centre and robot base without);
    ``force_scale_m_per_n``: arrow length per newton; ``robot_types``: robot -> type
    (``go2``, ``a1``) for the URDF models.
    """

    def __init__(self, recording: rr.RecordingStream, robot_names: Sequence[str] = (),
                 coupling_points_m: Mapping[str, tuple[Sequence[float], Sequence[float]]]
                 | None = None, force_scale_m_per_n: float = 0.005,
                 robot_types: Mapping[str, str] | None = None) -> None:
        self.recording = recording
        self.models = RobotModels(recording, robot_types or {})
        self.robot_names = list(robot_names)
        self.coupling_points_m = {name: (np.asarray(p, float), np.asarray(r, float))
                                  for name, (p, r) in (coupling_points_m or {}).items()}
        self.force_scale_m_per_n = force_scale_m_per_n
        self.series = SeriesLogger(recording, self._agent_names)
        self._poses: dict[str, Pose] = {}
        self._tf_frames: set[str] = set()
        self._bodies_logged: set[str] = set()
        self._time_ns: int | None = None
        self._handlers: dict[str, Callable[[Any], None] | None] = {}

    def handle(self, topic: str, message: Any, log_time_ns: int) -> None:
        """Log one message at its log time (skipped when its topic has no view)."""
        if topic not in self._handlers:
            self._handlers[topic] = self._handler(topic)
        handler = self._handlers[topic]
        if handler is None:
            return
        if log_time_ns != self._time_ns:
            self.recording.set_time(paths.SIM_TIME, duration=np.timedelta64(log_time_ns, "ns"))
            self._time_ns = log_time_ns
        handler(message)

    def _handler(self, topic: str) -> Callable[[Any], None] | None:
        series = self.series
        fixed: dict[str, Callable[[Any], None]] = {
            fmt.TF: self._tf, fmt.OBSTACLES: self._obstacles, PAYLOAD_BOX_TOPIC: self._payload_box,
            fmt.NMPC_UPDATE: self._nmpc_update, fmt.ADMM: series.admm, fmt.CBF: series.cbf,
            fmt.GROUND_TRUTH: self._ground_truth, fmt.PAYLOAD_ESTIMATE: series.payload_estimate,
            fmt.LOOP_TIMING: series.loop_timing, fmt.EVENTS: self._event}
        if topic in fixed:
            return fixed[topic]
        parts = topic.strip("/").split("/")
        if len(parts) == 2 and parts[0] == "mocap":
            return lambda message: self._mocap(parts[1], message)
        if len(parts) == 3 and parts[0] == "robot":
            robot, kind = parts[1], parts[2]
            self._learn(robot)
            kinds = {"state": self._robot_state, "wbc": self._wbc, "wrench": self._wrench}
            if kind in kinds:
                return lambda message: kinds[kind](robot, message)
        return None

    # --- robot names ------------------------------------------------------------------------
    def _learn(self, robot: str) -> None:
        if robot not in self.robot_names:
            self.robot_names.append(robot)

    def _agent_names(self, count: int) -> list[str]:
        return [self.robot_names[k] if k < len(self.robot_names) else f"agent_{k}"
                for k in range(count)]

    def _color(self, robot: str) -> tuple[int, int, int]:
        index = self.robot_names.index(robot) if robot in self.robot_names else 0
        return ROBOT_COLORS[index % len(ROBOT_COLORS)]

    # --- poses and the 3D scene -------------------------------------------------------------
    def _set_pose(self, frame: str, position_m: Sequence[float],
                  quaternion_wxyz: Sequence[float]) -> None:
        position = np.asarray(position_m, dtype=float)
        w, x, y, z = (float(v) for v in quaternion_wxyz)
        self._poses[frame] = (position, rotation_from_quaternion_wxyz(np.array([w, x, y, z])))
        if frame == PAYLOAD_NAME:
            entity = paths.PAYLOAD
        else:
            entity = paths.robot_entity(frame, "body")
            if frame not in self._bodies_logged and not self.models.has(frame):
                self._bodies_logged.add(frame)
                size = A1_TRUNK_SIZE_M if frame.lower().startswith("a1") else GO2_TRUNK_SIZE_M
                self.recording.log(entity, rr.Boxes3D(sizes=[size], colors=[self._color(frame)],
                                                      labels=[frame]), static=True)
        self.recording.log(entity, rr.Transform3D(translation=position,
                                                  quaternion=rr.Quaternion(xyzw=[x, y, z, w])))

    def _tf(self, message: Any) -> None:
        for transform in message.transforms:
            t, q = transform.translation, transform.rotation
            self._tf_frames.add(transform.child_frame_id)
            self._set_pose(transform.child_frame_id, (t.x, t.y, t.z), (q.w, q.x, q.y, q.z))
        self._log_couplings()

    def _mocap(self, body: str, message: Any) -> None:
        p, q = message.pose.position, message.pose.orientation
        self.recording.log(f"{paths.MOCAP}/{body}", rr.Points3D([(p.x, p.y, p.z)], radii=0.015))
        if body == PAYLOAD_NAME and body not in self._tf_frames:  # no ground truth: hardware
            self._set_pose(body, (p.x, p.y, p.z), (q.w, q.x, q.y, q.z))
            self._log_couplings()

    def _robot_state(self, robot: str, message: pb.RobotState) -> None:
        if robot not in self._tf_frames:
            self._set_pose(robot, message.position_in_world_m, message.quaternion_wxyz)
        self.models.state(robot, self._time_ns or 0, message.position_in_world_m,
                          message.quaternion_wxyz, message.joint_position_rad)

    def _coupling_point(self, robot: str, on_payload: bool) -> np.ndarray | None:
        frame = PAYLOAD_NAME if on_payload else robot
        if frame not in self._poses:
            return None
        position, rotation = self._poses[frame]
        points = self.coupling_points_m.get(robot)
        return position if points is None else position + rotation @ points[0 if on_payload
                                                                                else 1]

    def _log_couplings(self) -> None:
        segments, colors = [], []
        for robot in self.robot_names:
            on_robot = self._coupling_point(robot, False)
            on_payload = self._coupling_point(robot, True)
            if on_robot is not None and on_payload is not None:
                segments.append(np.stack([on_robot, on_payload]))
                colors.append(self._color(robot))
        if segments:
            self.recording.log(paths.COUPLINGS, rr.LineStrips3D(segments, colors=colors,
                                                                radii=0.01))

    def _wbc(self, robot: str, message: pb.WbcTick) -> None:
        targets = np.asarray(message.foot_target_in_world_m, dtype=float).reshape(-1, 3)
        forces = np.asarray(message.contact_force_in_world_n, dtype=float).reshape(-1, 3)
        stance = np.asarray(message.stance, dtype=float) > 0.5
        self.recording.log(paths.robot_entity(robot, "foot_targets"), rr.Points3D(
            targets, radii=0.02, colors=[self._color(robot) if s else (120, 120, 120)
                                         for s in stance]))
        self.recording.log(paths.robot_entity(robot, "contact_forces"), rr.Arrows3D(
            origins=targets[stance], vectors=forces[stance] * self.force_scale_m_per_n,
            colors=self._color(robot)))
        self.series.wbc(robot, message, float(np.linalg.norm(forces[stance].sum(axis=0))))

    def _wrench(self, robot: str, message: pb.InteractionWrench) -> None:
        origin = self._coupling_point(robot, False)
        if origin is not None:
            vectors = np.array([message.measured_force_n, message.predicted_force_n])
            self.recording.log(paths.robot_entity(robot, "coupling_force"), rr.Arrows3D(
                origins=[origin, origin], vectors=vectors * self.force_scale_m_per_n,
                colors=[MEASURED_COLOR, PREDICTED_COLOR], labels=["measured", "predicted"]))
        self.series.wrench(robot, message)

    def _nmpc_update(self, message: pb.NmpcUpdate) -> None:
        log = self.recording.log
        payload = _array(message.payload_trajectory)
        robots = _array(message.robot_trajectories)
        if payload is not None and payload.ndim == 2:
            log(paths.PAYLOAD_PLAN, rr.LineStrips3D([payload[:, 0:3]], colors=PLAN_COLOR,
                                                    radii=0.008))
            consensus = self._consensus_payload_m(message, payload)
            if consensus is not None:
                log(paths.CONSENSUS_PLAN, rr.LineStrips3D([consensus], colors=CONSENSUS_COLOR,
                                                          radii=0.004))
        if robots is not None and robots.ndim == 3:
            names = self._agent_names(robots.shape[0])
            log(paths.ROBOT_PLANS, rr.LineStrips3D(
                list(robots[:, :, 0:3]), labels=names, radii=0.006,
                colors=[self._color(name) for name in names]))
        self.series.nmpc_update(message, _array(message.grf))

    @staticmethod
    def _consensus_payload_m(message: pb.NmpcUpdate, payload: np.ndarray) -> np.ndarray | None:
        """The ADMM consensus payload positions, stages 1..N (None when centralized).

        Logs of this format leave ``consensus_trajectory`` empty: with ADMM the payload plan's
        stages 1..N are the consensus. Earlier ones hold the consensus vector (payload states
        k = 1..N, then the wrenches)."""
        stages = payload.shape[0] - 1
        consensus = _array(message.consensus_trajectory)
        if consensus is not None and stages > 0 and consensus.size >= 12 * stages:
            return consensus[:12 * stages].reshape(stages, 12)[:, 0:3]
        if any(solve.agent > 0 for solve in message.solves):  # local solves per agent: ADMM
            return payload[1:, 0:3]
        return None

    def _ground_truth(self, message: pb.GroundTruth) -> None:
        if message.robot_names:
            for robot in message.robot_names:
                self._learn(robot)
        if message.desired_payload_position_in_world_m:
            self.recording.log(paths.PAYLOAD_REFERENCE, rr.Points3D(
                [message.desired_payload_position_in_world_m], radii=0.03,
                colors=PLAN_COLOR, labels=["reference"]))
        self.series.ground_truth(message)

    # --- scenes (Foxglove SceneUpdate) ------------------------------------------------------
    def _obstacles(self, message: Any) -> None:
        for entity in message.entities:
            path = f"{paths.OBSTACLES}/{entity.id}"
            solid = [c for c in entity.cylinders if c.color.a >= 0.99]
            circles = [c for c in entity.cylinders if c.color.a < 0.99]
            if solid:
                self.recording.log(path, rr.Cylinders3D(
                    lengths=[c.size.z for c in solid], radii=[c.size.x / 2 for c in solid],
                    centers=[_xyz(c.pose.position) for c in solid],
                    colors=[_rgba(c.color) for c in solid]))
            if circles:
                self.recording.log(f"{path}/safety_circle", rr.LineStrips3D(
                    [_circle(c.pose.position, c.size.x / 2) for c in circles],
                    colors=[_rgba(c.color, alpha=1.0) for c in circles], radii=0.006))

    def _payload_box(self, message: Any) -> None:
        cubes = [cube for entity in message.entities for cube in entity.cubes]
        if cubes:
            self.recording.log(paths.PAYLOAD_BOX, rr.Boxes3D(
                centers=[_xyz(c.pose.position) for c in cubes],
                sizes=[_xyz(c.size) for c in cubes], colors=[_rgba(c.color) for c in cubes],
                fill_mode=rr.components.FillMode.Solid))

    def _event(self, message: pb.Event) -> None:
        level = {pb.Event.WARNING: rr.TextLogLevel.WARN,
                 pb.Event.ERROR: rr.TextLogLevel.ERROR}.get(message.level, rr.TextLogLevel.INFO)
        self.recording.log(paths.EVENTS, rr.TextLog(f"[{message.source}] {message.text}",
                                                    level=level))


def _array(message: pb.Array) -> np.ndarray | None:
    return fmt.from_array(message) if message.values else None


def _xyz(vector: Any) -> tuple[float, float, float]:
    return (vector.x, vector.y, vector.z)


def _rgba(color: Any, alpha: float | None = None) -> tuple[int, int, int, int]:
    a = color.a if alpha is None else alpha
    return tuple(int(round(255 * v)) for v in (color.r, color.g, color.b, a))  # type: ignore[return-value]


def _circle(center: Any, radius_m: float, segments: int = 64) -> np.ndarray:
    angle = np.linspace(0.0, 2 * np.pi, segments + 1)
    return np.column_stack([center.x + radius_m * np.cos(angle),
                            center.y + radius_m * np.sin(angle),
                            np.full_like(angle, center.z)])


def open_recording(target: str, recording_name: str, robot_names: Sequence[str] = ()
                   ) -> rr.RecordingStream:
    """A new recording stream (not the global one) sending to ``target``, blueprint first.

    ``target``: ``spawn`` (start a viewer), ``connect`` (the local viewer's default URL), a
    ``rerun+http://`` URL, or a path ending in ``.rrd`` (saved to that file).
    """
    recording = rr.RecordingStream(paths.APPLICATION_ID)
    recording.set_log_time_enabled(False)  # the log's own clock is the timeline (sim_time)
    recording.set_log_tick_enabled(False)
    if target.endswith(".rrd"):
        recording.save(target)
    elif target == "spawn":
        recording.spawn()
    elif target == "connect":
        recording.connect_grpc()
    elif "://" in target:
        recording.connect_grpc(target)
    else:
        raise ValueError(f"Rerun target {target!r}: expected 'spawn', 'connect', a "
                         "rerun+http:// URL or a FILE.rrd")
    recording.send_blueprint(paths.blueprint(robot_names))  # active and default
    recording.send_recording_name(recording_name)
    return recording


class LiveSink:
    """A flight-recorder sink (``(topic, message, log_time_ns)``) feeding a ``RerunLogView``;
    called from the recorder's writer thread only. ``close`` flushes the stream."""

    def __init__(self, recording: rr.RecordingStream,
                 robot_types: Mapping[str, str] | None = None) -> None:
        self.recording = recording
        self.view = RerunLogView(recording, robot_types=robot_types)

    def __call__(self, topic: str, message: Any, log_time_ns: int) -> None:
        self.view.handle(topic, message, log_time_ns)

    def close(self) -> None:
        self.recording.flush()
        self.recording.disconnect()


def live_sink(target: str, recording_name: str,
              robot_types: Mapping[str, str] | None = None) -> LiveSink:
    """``porter sim --rerun TARGET``: stream the run to Rerun while it is recorded."""
    return LiveSink(open_recording(target, recording_name), robot_types)
