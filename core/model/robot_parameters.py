"""SRB parameters of a quadruped computed from its kinematic/inertial description (Pinocchio).

Pure math on an already-built ``pinocchio.Model``: locating and parsing the URDF is the
caller's job (``drivers.robot_descriptions``). Mass and inertia are the whole robot's
(trunk plus legs) composite rigid-body values at the standing configuration, which is what
the SRB model approximates.
"""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from core.model.conventions import LEG_JOINT_NAMES, LEG_NAMES
from core.model.srb_model import SrbParameters


def leg_joint_indices(model: pin.Model) -> tuple[np.ndarray, np.ndarray]:
    """Where the 12 leg joints (``LEG_JOINT_NAMES`` order) sit in Pinocchio's q and v vectors."""
    joints = [model.joints[model.getJointId(name)] for name in LEG_JOINT_NAMES]
    return np.array([j.idx_q for j in joints]), np.array([j.idx_v for j in joints])


def srb_parameters_from_model(
    name: str, model: pin.Model, standing_configuration: np.ndarray, foot_radius_m: float = 0.0
) -> SrbParameters:
    """Composite SRB parameters at ``standing_configuration`` (Pinocchio q, base quaternion xyzw).

    The SRB body frame has its origin at the CoM and the trunk's orientation. Hip positions are
    the hip joints' origins relative to the CoM; the nominal height is the CoM height above
    the lowest foot contact point (foot frame minus ``foot_radius_m``).
    """
    q = np.array(standing_configuration, dtype=float)
    q[3:7] = (0.0, 0.0, 0.0, 1.0)  # level trunk: world axes equal body axes
    data = model.createData()
    pin.forwardKinematics(model, data, q)
    pin.updateFramePlacements(model, data)
    com = np.array(pin.centerOfMass(model, data, q))
    pin.ccrba(model, data, q, np.zeros(model.nv))
    inertia = np.array(data.Ig.inertia)
    hips = np.array([data.oMi[model.getJointId(f"{leg}_hip_joint")].translation - com
                     for leg in LEG_NAMES])
    feet = np.array([data.oMf[model.getFrameId(f"{leg}_foot")].translation - com
                     for leg in LEG_NAMES])
    feet[:, 2] -= foot_radius_m
    nominal_height = float(-feet[:, 2].min())
    return SrbParameters(
        name=name,
        mass_kg=float(pin.computeTotalMass(model)),
        inertia_in_body_kg_m2=0.5 * (inertia + inertia.T),
        hip_positions_in_body_m=hips,
        nominal_height_m=nominal_height,
        nominal_feet_in_body_m=feet,
    )
