"""MuJoCo scene of a team: robots from their URDFs, a free box payload, yaw-free couplings.

Built in code with ``mujoco.MjSpec`` from the same robot descriptions the controller uses
(``drivers.robot_descriptions``). World frame, SI units. MuJoCo quaternions are (w, x, y, z);
Pinocchio's (x, y, z, w) appear only inside ``_standing_pose_in_base``.

Scene contents:
- ground plane; per robot a free joint on the URDF root link (the Pinocchio base frame) and
  torque actuators on the 12 leg joints, ctrlrange = +-URDF effort limit [N m];
- feet: contact priority 1 and sliding friction ``foot_friction`` (so the foot's value, not
  MuJoCo's max-combination with the ground's, governs foot contacts);
- payload: free uniform box, total mass (box + couplers) = the configured or true mass;
- coupling (the real mechanism): a small coupler body hinged to the payload about the payload
  z-axis at the payload's coupling point, welded (site weld, 6 DoF) to the robot trunk at the
  robot's coupling point, so relative yaw is free and relative roll/pitch/translation are not;
- obstacles: cylinders standing on the ground, each a MuJoCo mocap body (kinematic: it moves
  on its own constant-velocity path, ``TeamSimulation`` sets its position before every step,
  and nothing pushes it) that collides with the robots and the payload, so a collision is one
  in physics too.

``build_team_scene`` places robots in the SRDF ``standing`` pose where
``core.nmpc.reference.robot_state_from_payload`` puts them for a level payload at the origin;
``TeamScene.initial_qpos`` is that configuration (``model.qpos0`` has zero leg angles).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np
import pinocchio as pin

from core.model.conventions import LEG_JOINT_NAMES, LEG_NAMES, PAYLOAD_NAME
from core.model.robot_parameters import leg_joint_indices
from core.model.team import TeamModel
from core.model.team_settings import TeamSettings
from core.nmpc.reference import robot_state_from_payload
from drivers.robot_descriptions import (
    load_pinocchio_model,
    robot_description,
    srb_parameters,
    standing_configuration,
)

DEFAULT_FOOT_FRICTION = 0.8
PHYSICS_TIMESTEP_S = 0.001  # MuJoCo step: physics at 1 kHz
COUPLER_MASS_KG = 0.01  # counted in the payload's total mass
_COUPLER_RADIUS_M = 0.02
# Coupling weld stiffness: MuJoCo's default (0.02 s, solimp 0.9..0.95) lets the coupling points
# drift ~13 mm apart under a standing team's load; these keep them < 0.3 mm (measured).
COUPLING_SOLIMP = (0.99, 0.999, 0.001)
# Collision bits: robots 1, payload 2 (payload touches the ground only, not the robots).
_ROBOT_BIT, _PAYLOAD_BIT = 1, 2


def robot_urdf_text(robot_type: str) -> str:
    """The robot's URDF with ``<visual>`` removed and ``package://`` URIs made absolute."""
    description = robot_description(robot_type)
    text = re.sub(r"<visual\b.*?</visual>", "", description.urdf_path.read_text(), flags=re.S)
    directory = description.package_directory.as_posix()
    return re.sub(r"package://[^\"']*?([A-Za-z0-9_]+_description/)",
                  lambda m: f"{directory}/{m.group(1)}", text)


def urdf_effort_limits_nm(robot_type: str) -> dict[str, float]:
    """Effort limit [N m] of each revolute joint, from the URDF ``<limit effort=...>``."""
    root = ET.fromstring(robot_description(robot_type).urdf_path.read_text())
    return {joint.attrib["name"]: float(joint.find("limit").attrib["effort"])  # type: ignore[union-attr]
            for joint in root.iter("joint")
            if joint.attrib.get("type") == "revolute" and joint.find("limit") is not None}


def _standing_pose_in_base(robot_type: str) -> tuple[np.ndarray, dict[str, float]]:
    """CoM in the base frame [m] and leg joint angles [rad] of the SRDF ``standing`` pose,
    with a level trunk (as the SRB parameters are computed)."""
    model = load_pinocchio_model(robot_type)
    q = standing_configuration(robot_type, model)
    q[0:7] = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # base at the origin; quaternion xyzw
    com_in_base_m = np.array(pin.centerOfMass(model, model.createData(), q))
    q_indices, _ = leg_joint_indices(model)
    angles_rad = {name: float(q[i]) for name, i in zip(LEG_JOINT_NAMES, q_indices, strict=True)}
    return com_in_base_m, angles_rad


def robot_spec(robot_type: str, foot_friction: float = DEFAULT_FOOT_FRICTION) -> mujoco.MjSpec:
    """One robot: free joint on the root link, 12 leg motors (+-effort), foot geoms and sites.

    Names are the URDF's; feet carry sites ``<leg>_foot`` at the foot link origin.
    """
    spec = mujoco.MjSpec.from_string(robot_urdf_text(robot_type))
    spec.compiler.fusestatic = False  # keep foot links as bodies
    spec.compiler.discardvisual = True
    base = spec.worldbody.first_body()
    base.add_freejoint(name="root")
    efforts = urdf_effort_limits_nm(robot_type)
    for joint in LEG_JOINT_NAMES:
        actuator = spec.add_actuator(name=joint.removesuffix("_joint"), target=joint,
                                     trntype=mujoco.mjtTrn.mjTRN_JOINT)
        actuator.set_to_motor()
        actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        actuator.ctrlrange = [-efforts[joint], efforts[joint]]
    for leg in LEG_NAMES:
        foot = spec.body(f"{leg}_foot")
        foot.add_site(name=f"{leg}_foot")
        for geom in foot.geoms:
            geom.priority = 1
            geom.friction = [foot_friction, geom.friction[1], geom.friction[2]]
    for geom in spec.geoms:
        geom.contype, geom.conaffinity = _ROBOT_BIT, _ROBOT_BIT
    for leg in LEG_NAMES:  # the shipped thigh meshes overlap the trunk at the hip
        spec.add_exclude(bodyname1=spec.body(f"{leg}_hip").parent.name,
                         bodyname2=f"{leg}_thigh")
    return spec


@dataclass(frozen=True)
class RobotIndices:
    """Where one robot lives in the compiled model. Leg arrays are in ``LEG_JOINT_NAMES`` order,
    foot arrays in ``LEG_NAMES`` order."""

    name: str
    robot_type: str
    base_body_id: int
    base_qpos_address: int  # free joint: position (3), quaternion wxyz (4)
    base_qvel_address: int  # free joint: linear velocity (world, 3), angular (body, 3)
    leg_qpos_addresses: np.ndarray  # (12,)
    leg_qvel_addresses: np.ndarray  # (12,)
    actuator_ids: np.ndarray  # (12,)
    foot_geom_ids: np.ndarray  # (4,)
    foot_site_ids: np.ndarray  # (4,)
    coupling_site_id: int  # on the robot base, at the robot's coupling point
    coupler_body_id: int
    coupler_hinge_qpos_address: int  # relative yaw payload -> coupler [rad]
    coupler_site_id: int  # on the coupler, at the payload's coupling point


@dataclass(frozen=True)
class TeamScene:
    """A compiled team scene and its name/index maps (robots in team order)."""

    model: mujoco.MjModel
    robots: tuple[RobotIndices, ...]
    payload_body_id: int
    payload_qpos_address: int
    payload_qvel_address: int
    obstacle_geom_ids: tuple[int, ...]
    initial_qpos: np.ndarray  # robots standing, payload level at the configured height
    obstacle_mocap_ids: tuple[int, ...] = ()  # each obstacle body's row in data.mocap_pos
    obstacle_start_m: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))  # (k, 3)
    obstacle_velocity_m_s: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))

    @property
    def obstacles_move(self) -> bool:
        return bool(np.any(self.obstacle_velocity_m_s != 0.0))

    def robot(self, name: str) -> RobotIndices:
        for robot in self.robots:
            if robot.name == name:
                return robot
        raise KeyError(f"no robot {name!r}; team is {[r.name for r in self.robots]}")


def build_team_scene(team: TeamSettings, payload_true_mass_kg: float | None = None,
                     obstacles: Sequence[tuple[float, ...]] = (),
                     timestep_s: float = PHYSICS_TIMESTEP_S,
                     foot_friction: float = DEFAULT_FOOT_FRICTION,
                     payload_height_m: float = 0.45,
                     coupling_time_constant_s: float = 0.005) -> TeamScene:
    """Compile the team's scene with the payload level at (0, 0, ``payload_height_m``), yaw 0.

    ``payload_true_mass_kg`` overrides ``team.payload.mass_kg`` (model mismatch on purpose).
    ``obstacles`` are (x [m], y [m], radius [m], height [m]) cylinders standing on the ground
    at t = 0, optionally followed by their constant velocity (vx, vy) [m/s].
    ``coupling_time_constant_s`` is the weld's solref time constant (>= 2 timesteps, MuJoCo's
    stability rule).
    """
    if coupling_time_constant_s < 2 * timestep_s:
        raise ValueError(f"coupling time constant {coupling_time_constant_s} s is below two "
                         f"timesteps ({timestep_s} s)")
    team_model = TeamModel.from_settings(team, srb_parameters)
    spec = mujoco.MjSpec()
    spec.option.timestep = timestep_s
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[0, 0, 0.05],
                            contype=_ROBOT_BIT | _PAYLOAD_BIT, conaffinity=_ROBOT_BIT | _PAYLOAD_BIT)
    starts, velocities = [], []
    for i, obstacle in enumerate(obstacles):
        if len(obstacle) not in (4, 6):
            raise ValueError(f"obstacle {i}: (x, y, radius, height[, vx, vy]), got {obstacle}")
        x, y, radius, height = obstacle[0:4]
        starts.append((x, y, height / 2))
        velocities.append(tuple(obstacle[4:6]) if len(obstacle) == 6 else (0.0, 0.0))
        body = spec.worldbody.add_body(name=f"obstacle_{i}", pos=[x, y, height / 2], mocap=True)
        body.add_geom(name=f"obstacle_{i}", type=mujoco.mjtGeom.mjGEOM_CYLINDER,
                      size=[radius, height / 2, 0], contype=_ROBOT_BIT | _PAYLOAD_BIT,
                      conaffinity=_ROBOT_BIT | _PAYLOAD_BIT, rgba=[0.8, 0.3, 0.3, 0.6])

    mass_kg = team.payload.mass_kg if payload_true_mass_kg is None else payload_true_mass_kg
    box_mass_kg = mass_kg - COUPLER_MASS_KG * len(team.agents)
    if box_mass_kg <= 0:
        raise ValueError(f"payload mass {mass_kg} kg does not exceed the couplers' mass")
    a, b, c = team.payload.size_m
    payload = spec.worldbody.add_body(name=PAYLOAD_NAME, pos=[0, 0, payload_height_m])
    payload.add_freejoint(name="payload_root")
    payload.add_geom(name="payload_box", type=mujoco.mjtGeom.mjGEOM_BOX, size=[a / 2, b / 2, c / 2],
                     contype=_PAYLOAD_BIT, conaffinity=0, mass=box_mass_kg,
                     rgba=[0.6, 0.5, 0.3, 1])
    payload.mass = box_mass_kg
    payload.inertia = [box_mass_kg * (b * b + c * c) / 12, box_mass_kg * (a * a + c * c) / 12,
                       box_mass_kg * (a * a + b * b) / 12]
    payload.explicitinertial = True

    payload_state = np.zeros(12)
    payload_state[2] = payload_height_m
    standing_angles: dict[str, dict[str, float]] = {}
    for i, agent in enumerate(team.agents):
        com_in_base_m, standing_angles[agent.name] = _standing_pose_in_base(agent.robot_type)
        robot_state = robot_state_from_payload(team_model, i, payload_state)
        yaw = robot_state[8]
        child = robot_spec(agent.robot_type, foot_friction)
        coupling_in_base_m = com_in_base_m + np.asarray(agent.coupling_point_in_robot_m)
        child.worldbody.first_body().add_site(name="coupling", pos=coupling_in_base_m)
        frame = spec.worldbody.add_frame(
            pos=robot_state[0:3] - com_in_base_m,  # level trunk, yaw 0: base = CoM - offset
            quat=[np.cos(yaw / 2), 0, 0, np.sin(yaw / 2)])
        spec.attach(child, prefix=f"{agent.name}/", frame=frame)

        coupler = payload.add_body(name=f"{agent.name}/coupler",
                                   pos=list(agent.coupling_point_in_payload_m),
                                   mass=COUPLER_MASS_KG, explicitinertial=True,
                                   inertia=[0.4 * COUPLER_MASS_KG * _COUPLER_RADIUS_M**2] * 3)
        coupler.add_joint(name=f"{agent.name}/coupler_yaw", type=mujoco.mjtJoint.mjJNT_HINGE,
                          axis=[0, 0, 1])
        coupler.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[_COUPLER_RADIUS_M, 0, 0],
                         contype=0, conaffinity=0, mass=0, rgba=[0.2, 0.2, 0.9, 1])
        coupler.add_site(name=f"{agent.name}/coupler")
        spec.add_equality(name=f"{agent.name}/coupling", type=mujoco.mjtEq.mjEQ_WELD,
                          objtype=mujoco.mjtObj.mjOBJ_SITE, name1=f"{agent.name}/coupler",
                          name2=f"{agent.name}/coupling",
                          solref=[coupling_time_constant_s, 1.0], solimp=[*COUPLING_SOLIMP, 0.5, 2])

    model = spec.compile()
    robots = tuple(_robot_indices(model, agent.name, agent.robot_type) for agent in team.agents)
    initial_qpos = model.qpos0.copy()
    for robot in robots:
        angles = standing_angles[robot.name]
        initial_qpos[robot.leg_qpos_addresses] = [angles[j] for j in LEG_JOINT_NAMES]
    payload_joint = model.joint("payload_root")
    return TeamScene(
        model=model, robots=robots, payload_body_id=model.body(PAYLOAD_NAME).id,
        payload_qpos_address=int(payload_joint.qposadr[0]),
        payload_qvel_address=int(payload_joint.dofadr[0]),
        obstacle_geom_ids=tuple(model.geom(f"obstacle_{i}").id for i in range(len(obstacles))),
        initial_qpos=initial_qpos,
        obstacle_mocap_ids=tuple(int(model.body_mocapid[model.body(f"obstacle_{i}").id])
                                 for i in range(len(obstacles))),
        obstacle_start_m=np.array(starts, dtype=float).reshape(-1, 3),
        obstacle_velocity_m_s=np.array(velocities, dtype=float).reshape(-1, 2),
    )


def _robot_indices(model: mujoco.MjModel, name: str, robot_type: str) -> RobotIndices:
    root = model.joint(f"{name}/root")
    legs = [model.joint(f"{name}/{joint}") for joint in LEG_JOINT_NAMES]
    feet = [model.body(f"{name}/{leg}_foot") for leg in LEG_NAMES]
    hinge = model.joint(f"{name}/coupler_yaw")
    return RobotIndices(
        name=name, robot_type=robot_type,
        base_body_id=int(root.bodyid[0]),
        base_qpos_address=int(root.qposadr[0]), base_qvel_address=int(root.dofadr[0]),
        leg_qpos_addresses=np.array([int(j.qposadr[0]) for j in legs]),
        leg_qvel_addresses=np.array([int(j.dofadr[0]) for j in legs]),
        actuator_ids=np.array([model.actuator(f"{name}/{joint.removesuffix('_joint')}").id
                               for joint in LEG_JOINT_NAMES]),
        foot_geom_ids=np.array([int(foot.geomadr[0]) for foot in feet]),
        foot_site_ids=np.array([model.site(f"{name}/{leg}_foot").id for leg in LEG_NAMES]),
        coupling_site_id=model.site(f"{name}/coupling").id,
        coupler_body_id=model.body(f"{name}/coupler").id,
        coupler_hinge_qpos_address=int(hinge.qposadr[0]),
        coupler_site_id=model.site(f"{name}/coupler").id,
    )
