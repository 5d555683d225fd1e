"""MuJoCo backend of the driver interface: a team scene stepped in lockstep, no real-time pacing.

``TeamSimulation`` owns one ``mujoco.MjData`` started at ``TeamScene.initial_qpos``. Each robot
is reached through a ``RobotDriver`` (``robot_driver(name)``), the motion-capture system
through a ``MocapSource`` (``mocap()``), both in ``drivers.mujoco.sim_links``. Joint commands
are applied like Unitree motor firmware: the law of ``JointCommand`` is re-evaluated from the
current (q, dq) at every physics step and clipped to the actuator ctrlrange (the URDF effort
limit).

Ground truth for tests and logs (world frame, SI units): ``payload_pose``,
``payload_velocity``, ``coupling_wrench``. Scripted disturbances: ``apply_push``.

Deterministic: the same scene, seed, call sequence and commands give identical trajectories
(MuJoCo is deterministic on one thread; mocap noise comes from ``numpy.random.default_rng``).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from core.model.conventions import FOOT_COUNT, PAYLOAD_NAME
from core.model.rotations import cross3
from drivers.interfaces import (
    JointCommand,
    MocapFrame,
    Pose,
    RobotMeasurement,
)
from drivers.mujoco.scene import RobotIndices, TeamScene
from drivers.mujoco.sim_links import SimMocap, SimRobotDriver, SimWrenchSensors

_PYRAMIDAL_CONE = int(mujoco.mjtCone.mjCONE_PYRAMIDAL)
# as a plain int: an array compared with the binding's enum object compares element by element
# in Python (~150 us for ~200 constraint rows, against ~1 us)
_EQUALITY_CONSTRAINT = int(mujoco.mjtConstraint.mjCNSTR_EQUALITY)
# constraint type -> whether its rows add up to the contact normal force under a pyramidal cone
_PYRAMID_NORMAL_ROW = np.zeros(len(mujoco.mjtConstraint.__members__), dtype=bool)
_PYRAMID_NORMAL_ROW[[int(mujoco.mjtConstraint.mjCNSTR_CONTACT_FRICTIONLESS),
                     int(mujoco.mjtConstraint.mjCNSTR_CONTACT_PYRAMIDAL)]] = True


@dataclass
class _Push:
    body_id: int
    force_in_world_n: np.ndarray
    end_time_s: float


class TeamSimulation:
    """A team scene in MuJoCo, with per-robot drivers, a noisy mocap and ground truth.

    ``mocap_position_noise_m`` is the standard deviation of the Gaussian noise added to each
    position coordinate; ``mocap_angle_noise_rad`` that of each component of a rotation vector
    (world frame) applied to each mocap orientation. Both are drawn from ``seed``.
    """

    def __init__(self, scene: TeamScene, seed: int = 0, mocap_position_noise_m: float = 0.0,
                 mocap_angle_noise_rad: float = 0.0) -> None:
        self.scene = scene
        self.model = scene.model
        self.data = mujoco.MjData(self.model)
        self.data.qpos[:] = scene.initial_qpos
        mujoco.mj_forward(self.model, self.data)
        self.mocap_position_noise_m = mocap_position_noise_m
        self.mocap_angle_noise_rad = mocap_angle_noise_rad
        self._rng = np.random.default_rng(seed)
        self._commands = {robot.name: JointCommand() for robot in scene.robots}
        self._pushes: list[_Push] = []
        self._pushed = False  # xfrc_applied holds pushes of the last step
        # the moving obstacles' t = 0 [s of simulated time]; before it they stand at their
        # starts (the sim backend's world lays the robots down first, then sets it)
        self.obstacle_origin_s = 0.0
        self._qpos_addresses = np.concatenate([r.leg_qpos_addresses for r in scene.robots])
        self._qvel_addresses = np.concatenate([r.leg_qvel_addresses for r in scene.robots])
        self._actuator_ids = np.concatenate([r.actuator_ids for r in scene.robots])
        ctrlrange = self.model.actuator_ctrlrange[self._actuator_ids]
        self._ctrl_low, self._ctrl_high = ctrlrange[:, 0], ctrlrange[:, 1]
        self._stacked_command: np.ndarray | None = np.zeros((5, len(self._actuator_ids)))
        self._coupling_ids = {r.name: self.model.equality(f"{r.name}/coupling").id
                              for r in scene.robots}
        # geom id -> 1 + 4 x its robot's index + its foot index (LEG_NAMES order), 0 for any
        # other geom and, through the extra last entry, for the geom id -1 of flex contacts:
        # every robot's feet in one pass over the contacts, once per physics step
        self._foot_bin_of_geom = np.zeros(self.model.ngeom + 1, dtype=np.intp)
        self._foot_bins: dict[str, slice] = {}
        for index, robot in enumerate(scene.robots):
            first = 1 + FOOT_COUNT * index
            self._foot_bin_of_geom[robot.foot_geom_ids] = np.arange(first, first + FOOT_COUNT)
            self._foot_bins[robot.name] = slice(first, first + FOOT_COUNT)
        self._physics_steps = 0
        self._foot_forces_n: tuple[int, np.ndarray] | None = None  # (at step, every bin)
        # per robot, one gather from qpos / qvel: base free joint (7 / 6 entries), then legs
        self._state_addresses = {
            r.name: (np.concatenate([np.arange(r.base_qpos_address, r.base_qpos_address + 7),
                                     r.leg_qpos_addresses]),
                     np.concatenate([np.arange(r.base_qvel_address, r.base_qvel_address + 6),
                                     r.leg_qvel_addresses]))
            for r in scene.robots}

    @property
    def time_s(self) -> float:
        """Simulated time [s] since the start."""
        return float(self.data.time)

    @property
    def timestep_s(self) -> float:
        """Physics step [s]."""
        return float(self.model.opt.timestep)

    # --- drivers -------------------------------------------------------------------------
    def robot_driver(self, name: str) -> SimRobotDriver:
        """The ``RobotDriver`` of robot ``name`` (a team agent name)."""
        return SimRobotDriver(self, self.scene.robot(name))

    def mocap(self, rate_hz: float | None = None) -> SimMocap:
        """The ``MocapSource``: every robot base (by robot name) and ``"payload"``; a new
        frame at ``rate_hz`` of simulated time (None: a fresh frame at every call)."""
        return SimMocap(self, rate_hz)

    def wrench_sensors(self) -> SimWrenchSensors:
        """The ``WrenchSensors``: each coupling's transmitted wrench, exact."""
        return SimWrenchSensors(self)

    def set_command(self, name: str, command: JointCommand) -> None:
        """Store robot ``name``'s joint command; applied from the next physics step on."""
        self._commands[self.scene.robot(name).name] = command
        self._stacked_command = None  # stacked by the next step, once for all robots

    # --- stepping ------------------------------------------------------------------------
    def step(self, count: int = 1) -> None:
        """Advance ``count`` physics steps, re-evaluating the motor law before each."""
        data = self.data
        if self._stacked_command is None:
            self._stacked_command = np.array([
                np.concatenate([getattr(self._commands[r.name], field) for r in self.scene.robots])
                for field in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd")])
        torque, position, velocity, kp, kd = self._stacked_command
        scene = self.scene
        moving = scene.obstacles_move
        for _ in range(count):
            if moving:  # kinematic obstacles on their paths at this step's start time
                data.mocap_pos[list(scene.obstacle_mocap_ids), 0:2] = (
                    scene.obstacle_start_m[:, 0:2] + scene.obstacle_velocity_m_s
                    * max(data.time - self.obstacle_origin_s, 0.0))
            self._apply_pushes()
            q = data.qpos[self._qpos_addresses]
            dq = data.qvel[self._qvel_addresses]
            tau = torque + kp * (position - q) + kd * (velocity - dq)
            data.ctrl[self._actuator_ids] = np.clip(tau, self._ctrl_low, self._ctrl_high)
            mujoco.mj_step(self.model, data)
            self._physics_steps += 1

    def forward(self) -> None:
        """Recompute the derived quantities (contacts, constraint forces, sensors) after a
        direct change to ``data`` (tests, a reset); reads then see the changed state."""
        mujoco.mj_forward(self.model, self.data)
        self._foot_forces_n = None

    def obstacle_pose(self, index: int) -> tuple[np.ndarray, np.ndarray]:
        """Obstacle ``index``'s pose now: centre position [m] and quaternion (w, x, y, z),
        world frame (on its constant-velocity path)."""
        scene = self.scene
        position = scene.obstacle_start_m[index].copy()
        position[0:2] += (scene.obstacle_velocity_m_s[index]
                          * max(self.time_s - self.obstacle_origin_s, 0.0))
        return position, np.array([1.0, 0.0, 0.0, 0.0])

    def apply_push(self, body: str, force_world_n: np.ndarray, duration_s: float) -> None:
        """Push ``body`` (a robot name for its trunk, ``"payload"``, or any model body name)
        with ``force_world_n`` [N] at its centre of mass for ``duration_s`` [s] from now."""
        if body == PAYLOAD_NAME:
            body_id = self.scene.payload_body_id
        elif body in self._commands:
            body_id = self.scene.robot(body).base_body_id
        else:
            body_id = self.model.body(body).id
        self._pushes.append(_Push(body_id, np.asarray(force_world_n, dtype=float),
                                  self.time_s + duration_s))

    def _apply_pushes(self) -> None:
        if self._pushes or self._pushed:  # else nothing applied, nothing to clear
            self.data.xfrc_applied[:] = 0.0
            self._pushes = [p for p in self._pushes if self.time_s < p.end_time_s - 1e-12]
            for push in self._pushes:
                self.data.xfrc_applied[push.body_id, 0:3] += push.force_in_world_n
            self._pushed = bool(self._pushes)

    # --- ground truth --------------------------------------------------------------------
    def payload_pose(self) -> Pose:
        """Payload body origin [m] and quaternion wxyz, world frame."""
        a = self.scene.payload_qpos_address
        return self.data.qpos[a:a + 3].copy(), self.data.qpos[a + 3:a + 7].copy()

    def base_pose(self, name: str) -> Pose:
        """Robot ``name``'s base (URDF root link) origin [m] and quaternion wxyz, world frame."""
        a = self.scene.robot(name).base_qpos_address
        return self.data.qpos[a:a + 3].copy(), self.data.qpos[a + 3:a + 7].copy()

    def coupling_error_m(self, name: str) -> float:
        """Distance [m] between robot ``name``'s coupling point on its trunk and the payload's
        coupling point (the weld's translational violation), from the last step."""
        robot = self.scene.robot(name)
        gap = self.data.site_xpos[robot.coupling_site_id] - self.data.site_xpos[
            robot.coupler_site_id]
        return float(np.linalg.norm(gap))

    def payload_velocity(self) -> tuple[np.ndarray, np.ndarray]:
        """Payload origin linear velocity [m/s] and angular velocity [rad/s], both in world."""
        a = self.scene.payload_qvel_address
        return self.data.qvel[a:a + 3].copy(), _rotation(self.data.qpos[a + 3:a + 7]) @ \
            self.data.qvel[a + 3:a + 6]

    def coupling_wrench(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Force [N] and torque [N m] robot ``name``'s coupling applies to the payload (with its
        couplers), world frame, torque about the payload coupling point; from the last step.

        Computed as J^T f over the weld's constraint rows (``efc_type`` equality, ``efc_id``
        the weld), read on the payload's free-joint DoFs: linear = force in world, angular =
        torque about the payload origin in the payload frame. This sidesteps the frame in
        which MuJoCo expresses a weld's rotational rows.
        """
        data, model = self.data, self.model
        rows = ((data.efc_type == _EQUALITY_CONSTRAINT)
                & (data.efc_id == self._coupling_ids[self.scene.robot(name).name]))
        force = np.where(rows, data.efc_force, 0.0)
        generalized = np.zeros(model.nv)
        mujoco.mj_mulJacTVec(model, data, generalized, force)
        a = self.scene.payload_qvel_address
        force_n = generalized[a:a + 3].copy()
        payload = self.scene.payload_body_id
        torque_about_origin = data.xmat[payload].reshape(3, 3) @ generalized[a + 3:a + 6]
        lever = data.site_xpos[self.scene.robot(name).coupler_site_id] - data.xpos[payload]
        return force_n, torque_about_origin - cross3(lever, force_n)

    # --- sensors -------------------------------------------------------------------------
    def _measure(self, robot: RobotIndices) -> RobotMeasurement:
        data = self.data
        qpos_addresses, qvel_addresses = self._state_addresses[robot.name]
        qpos = data.qpos[qpos_addresses]  # fancy indexing: fresh arrays, sliced into views
        qvel = data.qvel[qvel_addresses]
        normal_force = self._foot_normal_forces(robot)
        return RobotMeasurement(
            time_s=float(data.time),
            position_rad=qpos[7:],
            velocity_rad_s=qvel[6:],
            torque_nm=data.actuator_force[robot.actuator_ids],
            position_in_world_m=qpos[0:3],
            quaternion_wxyz=qpos[3:7],
            linear_velocity_in_world_m_s=qvel[0:3],
            angular_velocity_in_body_rad_s=qvel[3:6],
            foot_contact=normal_force > 0.0,
            foot_normal_force_n=normal_force,
        )

    def _foot_normal_forces(self, robot: RobotIndices) -> np.ndarray:
        """Ground normal force [N] on each of ``robot``'s feet, (4,) in ``LEG_NAMES`` order: over
        the contacts involving the foot's geom (``foot_geom_ids``), the sum of the normal
        component of ``mj_contactForce``.

        Vectorised, with no call per contact. A contact's normal force is read from
        ``efc_force``: with a pyramidal cone, the sum of all its rows (the 2 (dim - 1) pyramid
        edges, MuJoCo's ``mju_decodePyramid``; the one row of a frictionless contact), summed
        by ``bincount`` over the rows tagged with the contact's id (``efc_id``) in row order;
        with an elliptic cone, its first row (``efc_address``). A contact without rows
        (``efc_address`` -1) has none. Feet then sum their contacts in contact order: the
        same additions in the same order as the per-contact loop, hence the same values.
        Computed for every robot at once and kept until the next physics step.
        """
        computed = self._foot_forces_n
        if computed is None or computed[0] != self._physics_steps:
            computed = self._foot_forces_n = (self._physics_steps, self._every_foot_force_n())
        return computed[1][self._foot_bins[robot.name]].copy()

    def _every_foot_force_n(self) -> np.ndarray:
        """Every robot's feet's normal forces [N] by bin (``_foot_bin_of_geom``), bin 0 the
        other geoms'."""
        data = self.data
        contact = data.contact
        if self.model.opt.cone == _PYRAMIDAL_CONE:
            rows = _PYRAMID_NORMAL_ROW[data.efc_type]
            normals = np.bincount(data.efc_id[rows], weights=data.efc_force[rows],
                                  minlength=data.ncon)
        else:
            addresses = contact.efc_address
            active = addresses >= 0
            normals = np.zeros(data.ncon)
            normals[active] = data.efc_force[addresses[active]]
        # each contact counts on both its sides
        feet = self._foot_bin_of_geom[contact.geom].ravel()
        return np.bincount(feet, weights=normals.repeat(2),
                           minlength=1 + FOOT_COUNT * len(self._foot_bins))

    def _mocap_frame(self) -> MocapFrame:
        poses: dict[str, Pose] = {}
        sources = [(r.name, r.base_qpos_address) for r in self.scene.robots]
        sources.append((PAYLOAD_NAME, self.scene.payload_qpos_address))
        for name, a in sources:
            position = self.data.qpos[a:a + 3] + self._rng.normal(
                0.0, self.mocap_position_noise_m, 3)
            rotation_vector = self._rng.normal(0.0, self.mocap_angle_noise_rad, 3)
            noise = np.zeros(4)
            mujoco.mju_axisAngle2Quat(noise, _unit(rotation_vector),
                                      float(np.linalg.norm(rotation_vector)))
            quaternion = np.zeros(4)
            mujoco.mju_mulQuat(quaternion, noise, self.data.qpos[a + 3:a + 7])
            poses[name] = (position, quaternion)
        return MocapFrame(time_s=self.time_s, poses=poses)


def _rotation(quaternion_wxyz: np.ndarray) -> np.ndarray:
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.asarray(quaternion_wxyz, dtype=float))
    return matrix.reshape(3, 3)


def _unit(vector: np.ndarray) -> np.ndarray:
    norm = float(np.linalg.norm(vector))
    return vector / norm if norm > 0.0 else np.array([0.0, 0.0, 1.0])
