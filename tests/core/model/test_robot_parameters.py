"""SRB parameters of the shipped quadrupeds, computed from their URDFs with Pinocchio."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from core.model.conventions import LEG_NAMES
from core.model.robot_parameters import srb_parameters_from_model
from core.model.team_settings import ROBOT_TYPES
from drivers.robot_descriptions import (
    UnknownRobotError,
    load_pinocchio_model,
    srb_parameters,
    standing_configuration,
)

# Total masses of the example-robot-data descriptions [kg] (independent cross-check).
EXPECTED_MASS_KG = {"go2": 16.085, "a1": 13.741}


def _level_standing(robot_type: str, model: pin.Model) -> np.ndarray:
    q = standing_configuration(robot_type, model).copy()
    q[3:7] = (0.0, 0.0, 0.0, 1.0)
    return q


def _composite_inertia_about_com(model: pin.Model, q: np.ndarray) -> tuple[float, np.ndarray,
                                                                           np.ndarray]:
    """Mass, CoM and inertia about the CoM by summing every body (parallel-axis theorem)."""
    data = model.createData()
    pin.forwardKinematics(model, data, q)
    masses, coms, inertias = [], [], []
    for joint in range(1, model.njoints):
        body = model.inertias[joint]
        placement = data.oMi[joint]
        masses.append(body.mass)
        coms.append(placement.act(body.lever))
        rotation = placement.rotation
        inertias.append(rotation @ body.inertia @ rotation.T)
    mass = float(sum(masses))
    com = sum(m * c for m, c in zip(masses, coms, strict=True)) / mass
    total = np.zeros((3, 3))
    for m, c, i in zip(masses, coms, inertias, strict=True):
        r = c - com
        total += i + m * (r @ r * np.eye(3) - np.outer(r, r))
    return mass, com, total


@pytest.mark.parametrize("robot_type", ROBOT_TYPES)
def test_mass_is_the_models_total_mass(robot_type: str) -> None:
    params = srb_parameters(robot_type)
    model = load_pinocchio_model(robot_type)
    assert params.name == robot_type
    assert params.mass_kg == pytest.approx(pin.computeTotalMass(model), abs=1e-9)
    assert params.mass_kg == pytest.approx(EXPECTED_MASS_KG[robot_type], abs=1e-6)


@pytest.mark.parametrize("robot_type", ROBOT_TYPES)
def test_inertia_is_the_composite_inertia_at_standing(robot_type: str) -> None:
    params = srb_parameters(robot_type)
    inertia = params.inertia_in_body_kg_m2
    assert inertia.shape == (3, 3)
    np.testing.assert_allclose(inertia, inertia.T, atol=0)
    eigenvalues = np.linalg.eigvalsh(inertia)
    assert np.all(eigenvalues > 0)
    # Principal moments of a rigid body satisfy the triangle inequality.
    assert eigenvalues[0] + eigenvalues[1] >= eigenvalues[2]
    model = load_pinocchio_model(robot_type)
    mass, _, reference = _composite_inertia_about_com(model, _level_standing(robot_type, model))
    assert mass == pytest.approx(params.mass_kg, abs=1e-9)
    np.testing.assert_allclose(inertia, reference, atol=1e-9)
    # The legs contribute: the composite inertia exceeds the trunk's alone (about the CoM).
    trunk = model.inertias[1].inertia
    assert np.trace(inertia) > np.trace(trunk)


@pytest.mark.parametrize("robot_type", ROBOT_TYPES)
def test_hips_are_left_right_symmetric(robot_type: str) -> None:
    hips = dict(zip(LEG_NAMES, srb_parameters(robot_type).hip_positions_in_body_m, strict=True))
    assert hips["FL"][1] > 0 and hips["RL"][1] > 0
    assert hips["FR"][1] < 0 and hips["RR"][1] < 0
    assert hips["FL"][0] > 0 and hips["FR"][0] > 0
    assert hips["RL"][0] < 0 and hips["RR"][0] < 0
    for left, right in (("FL", "FR"), ("RL", "RR")):
        # Same x and z; y mirrored about the trunk midline (which the CoM may be off by mm).
        assert hips[left][0] == pytest.approx(hips[right][0], abs=1e-9)
        assert hips[left][2] == pytest.approx(hips[right][2], abs=1e-9)
        assert hips[left][1] + hips[right][1] == pytest.approx(
            hips["FL"][1] + hips["FR"][1], abs=1e-9)
        assert abs(hips[left][1] + hips[right][1]) < 0.01
    # Hip-to-hip offsets do not depend on the CoM: compare with the URDF joint placements.
    model = load_pinocchio_model(robot_type)
    placement = {leg: model.jointPlacements[model.getJointId(f"{leg}_hip_joint")].translation
                 for leg in LEG_NAMES}
    for leg in LEG_NAMES:
        np.testing.assert_allclose(hips[leg] - hips["FL"], placement[leg] - placement["FL"],
                                   atol=1e-12)


@pytest.mark.parametrize("robot_type", ROBOT_TYPES)
def test_hips_are_relative_to_the_com(robot_type: str) -> None:
    model = load_pinocchio_model(robot_type)
    q = _level_standing(robot_type, model)
    _, com, _ = _composite_inertia_about_com(model, q)
    data = model.createData()
    pin.forwardKinematics(model, data, q)
    params = srb_parameters(robot_type)
    for leg, hip in zip(LEG_NAMES, params.hip_positions_in_body_m, strict=True):
        np.testing.assert_allclose(hip, data.oMi[model.getJointId(f"{leg}_hip_joint")].translation
                                   - com, atol=1e-9)


@pytest.mark.parametrize("robot_type", ROBOT_TYPES)
def test_nominal_height_is_plausible(robot_type: str) -> None:
    params = srb_parameters(robot_type)
    assert 0.2 < params.nominal_height_m < 0.4
    # The hips sit near the CoM height (the legs hang below them).
    assert np.all(np.abs(params.hip_positions_in_body_m[:, 2]) < 0.1)


def test_go2_stands_taller_and_is_heavier_than_a1() -> None:
    go2, a1 = srb_parameters("go2"), srb_parameters("a1")
    assert go2.mass_kg > a1.mass_kg
    assert go2.nominal_height_m > a1.nominal_height_m


def test_foot_radius_lowers_the_ground() -> None:
    model = load_pinocchio_model("go2")
    q = standing_configuration("go2", model)
    without = srb_parameters_from_model("go2", model, q, foot_radius_m=0.0)
    with_radius = srb_parameters_from_model("go2", model, q, foot_radius_m=0.02)
    assert with_radius.nominal_height_m - without.nominal_height_m == pytest.approx(0.02, abs=1e-12)


def test_base_orientation_in_configuration_is_ignored() -> None:
    """Parameters are taken with a level trunk whatever base quaternion q carries."""
    model = load_pinocchio_model("a1")
    q = standing_configuration("a1", model)
    tilted = q.copy()
    tilted[3:7] = pin.Quaternion(pin.rpy.rpyToMatrix(0.3, -0.2, 1.0)).coeffs()
    a = srb_parameters_from_model("a1", model, q)
    b = srb_parameters_from_model("a1", model, tilted)
    np.testing.assert_allclose(a.inertia_in_body_kg_m2, b.inertia_in_body_kg_m2, atol=1e-12)
    np.testing.assert_allclose(a.hip_positions_in_body_m, b.hip_positions_in_body_m, atol=1e-12)
    assert a.nominal_height_m == pytest.approx(b.nominal_height_m, abs=1e-12)


def test_unknown_robot_type_names_the_available_ones() -> None:
    with pytest.raises(UnknownRobotError) as error:
        srb_parameters("spot")
    message = str(error.value)
    assert "spot" in message
    for robot_type in ROBOT_TYPES:
        assert robot_type in message
    assert isinstance(error.value, ValueError)


def test_the_pinocchio_model_is_parsed_once_per_robot_type() -> None:
    assert load_pinocchio_model("go2") is load_pinocchio_model("go2")
    assert load_pinocchio_model("go2") is not load_pinocchio_model("a1")
