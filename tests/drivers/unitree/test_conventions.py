"""Unitree conventions: motor and foot order by name, CRC-32 against MPEG-2 and Unitree's
bitwise recipe, loop-off sentinels, IMU angles, state plausibility."""

from __future__ import annotations

import numpy as np
import pytest

from core.model.conventions import LEG_JOINT_NAMES, LEG_NAMES
from core.model.rotations import euler_from_rotation, rotation_from_quaternion_wxyz
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.unitree.conventions import (
    POS_STOP_F,
    UNITREE_JOINT_NAMES,
    UNITREE_LEG_ORDER,
    VEL_STOP_F,
    WIRE_FOOT_OF_FOOT,
    WIRE_SLOT_OF_JOINT,
    WireState,
    crc32_mpeg2,
    damping_wire_command,
    joint_command_from_wire_command,
    measurement_from_wire_state,
    rpy_from_quaternion_wxyz,
    state_problem,
    unitree_crc32,
    wire_command_from_joint_command,
    wire_state_from_measurement,
)


def unitree_sdk_crc32(words: list[int]) -> int:
    """Bit-by-bit transcription of unitree_sdk2's ``crc32_core`` (the reference recipe)."""
    crc = 0xFFFFFFFF
    for word in words:
        bit = 1 << 31
        for _ in range(32):
            crc = ((crc << 1) & 0xFFFFFFFF) ^ (0x04C11DB7 if crc & 0x80000000 else 0)
            if word & bit:
                crc ^= 0x04C11DB7
            bit >>= 1
    return crc


def test_motor_order_maps_by_name():
    assert UNITREE_JOINT_NAMES[:3] == ("FR_hip_joint", "FR_thigh_joint", "FR_calf_joint")
    assert UNITREE_JOINT_NAMES[9:] == ("RL_hip_joint", "RL_thigh_joint", "RL_calf_joint")
    for joint, slot in enumerate(WIRE_SLOT_OF_JOINT):
        assert UNITREE_JOINT_NAMES[slot] == LEG_JOINT_NAMES[joint]
    for foot, wire_foot in enumerate(WIRE_FOOT_OF_FOOT):
        assert UNITREE_LEG_ORDER[wire_foot] == LEG_NAMES[foot]
    assert sorted(WIRE_SLOT_OF_JOINT) == list(range(12))


def test_crc32_is_mpeg2_and_matches_unitree_recipe():
    assert crc32_mpeg2(b"123456789") == 0x0376E6E7  # CRC-32/MPEG-2 check value
    words = np.random.default_rng(0).integers(0, 2**32, size=202, dtype=np.uint64)
    words_list = [int(w) for w in words]
    expected = unitree_sdk_crc32(words_list)
    assert unitree_crc32(words_list) == expected
    big_endian = b"".join(w.to_bytes(4, "big") for w in words_list)
    assert crc32_mpeg2(big_endian) == expected
    # no final XOR: appending the CRC leaves a zero remainder
    assert unitree_crc32([*words_list, expected]) == 0
    assert unitree_crc32([0x31323334]) == crc32_mpeg2(b"1234")


def test_wire_state_round_trip_and_conventions():
    quaternion = np.array([0.9, 0.1, -0.2, 0.3]) / np.linalg.norm([0.9, 0.1, -0.2, 0.3])
    measurement = RobotMeasurement(
        time_s=1.25, position_rad=np.arange(12) * 0.1, velocity_rad_s=-np.arange(12) * 0.5,
        torque_nm=np.arange(12) + 0.5, position_in_world_m=np.ones(3),
        quaternion_wxyz=quaternion, linear_velocity_in_world_m_s=np.ones(3),
        angular_velocity_in_body_rad_s=np.array([0.3, -0.2, 0.1]),
        foot_contact=np.array([True, True, False, True]),
        foot_normal_force_n=np.array([40.0, 50.0, 0.0, 70.0]))
    wire = wire_state_from_measurement(measurement, foot_force_n_per_count=0.5, tick_ms=1250)
    fr_calf = LEG_JOINT_NAMES.index("FR_calf_joint")
    assert wire.q_rad[2] == pytest.approx(measurement.position_rad[fr_calf])
    assert list(wire.foot_force) == [100, 80, 140, 0]  # FR, FL, RR, RL counts
    np.testing.assert_allclose(wire.accelerometer_m_s2,
                               rotation_from_quaternion_wxyz(quaternion).T @ [0, 0, 9.80665])
    back = measurement_from_wire_state(wire, 2.0, 0.5,
                                       contact_threshold_n=10.0)
    np.testing.assert_allclose(back.position_rad, measurement.position_rad)
    np.testing.assert_allclose(back.torque_nm, measurement.torque_nm)
    np.testing.assert_allclose(back.quaternion_wxyz, quaternion)
    np.testing.assert_allclose(back.foot_normal_force_n, measurement.foot_normal_force_n)
    assert list(back.foot_contact) == [True, True, False, True]
    assert back.time_s == 2.0
    # measured by neither robot: zero until the estimator pipeline fills them in
    np.testing.assert_array_equal(back.position_in_world_m, np.zeros(3))
    np.testing.assert_array_equal(back.linear_velocity_in_world_m_s, np.zeros(3))


def test_imu_fields_match_the_rotation_matrix_for_any_quaternion_norm():
    """The scalar IMU formulas against the rotation matrix, on quaternions a little off unit
    length (as a simulator's are): R^T (0, 0, g) and the Z-Y-X angles of R."""
    rng = np.random.default_rng(3)
    for _ in range(200):
        quaternion = rng.normal(size=4)
        quaternion *= (1.0 + 1e-3 * rng.normal()) / np.linalg.norm(quaternion)
        measurement = RobotMeasurement(
            time_s=0.0, position_rad=np.zeros(12), velocity_rad_s=np.zeros(12),
            torque_nm=np.zeros(12), position_in_world_m=np.zeros(3), quaternion_wxyz=quaternion,
            linear_velocity_in_world_m_s=np.zeros(3),
            angular_velocity_in_body_rad_s=np.zeros(3), foot_contact=np.zeros(4, dtype=bool),
            foot_normal_force_n=np.zeros(4))
        wire = wire_state_from_measurement(measurement, foot_force_n_per_count=1.0)
        rotation = rotation_from_quaternion_wxyz(quaternion)
        np.testing.assert_allclose(wire.accelerometer_m_s2, rotation.T @ [0, 0, 9.80665],
                                   atol=1e-12)
        np.testing.assert_allclose(wire.rpy_rad, euler_from_rotation(rotation), atol=1e-9)
        np.testing.assert_array_equal(wire.quaternion_wxyz, quaternion)


def test_rpy_of_known_rotations():
    half = np.sqrt(0.5)
    np.testing.assert_allclose(rpy_from_quaternion_wxyz([half, 0, 0, half]), [0, 0, np.pi / 2],
                               atol=1e-12)
    np.testing.assert_allclose(rpy_from_quaternion_wxyz([half, half, 0, 0]), [np.pi / 2, 0, 0],
                               atol=1e-12)


def test_command_mapping_and_loop_off_sentinels():
    command = JointCommand(torque_nm=np.arange(12.0), position_rad=np.arange(12) * 0.1,
                           velocity_rad_s=np.arange(12) * 0.2, kp=np.arange(12) + 10.0,
                           kd=np.arange(12) + 1.0)
    wire = wire_command_from_joint_command(command, servo_mode=0x01)
    assert list(wire.mode) == [1] * 12 + [0] * 8
    assert wire.tau_nm[0] == command.torque_nm[LEG_JOINT_NAMES.index("FR_hip_joint")]
    back = joint_command_from_wire_command(wire)
    for name in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd"):
        np.testing.assert_array_equal(getattr(back, name), getattr(command, name))
    damping = damping_wire_command(kd=3.0, servo_mode=0x0A)
    assert (damping.q_rad[:12] == POS_STOP_F).all()
    damped = joint_command_from_wire_command(damping)
    assert (damped.kp == 0).all() and (damped.kd == 3.0).all() and (damped.position_rad == 0).all()
    wire.dq_rad_s[:] = VEL_STOP_F
    wire.mode[0] = 0  # FR hip braked: no torque at all
    velocity_off = joint_command_from_wire_command(wire)
    assert (velocity_off.kd == 0).all()
    fr_hip = LEG_JOINT_NAMES.index("FR_hip_joint")
    assert velocity_off.kp[fr_hip] == 0 and velocity_off.torque_nm[fr_hip] == 0


def test_state_plausibility():
    assert state_problem(WireState()) is None
    nan_state = WireState()
    nan_state.q_rad[3] = np.nan
    assert state_problem(nan_state) == "non-finite"
    unused_slot_nan = WireState()
    unused_slot_nan.q_rad[15] = np.nan  # slots 12..19 carry no leg motor
    assert state_problem(unused_slot_nan) is None
    assert state_problem(WireState(quaternion_wxyz=np.zeros(4))) == "implausible"
    fast = WireState()
    fast.dq_rad_s[0] = 1e4
    assert state_problem(fast) == "implausible"
    # every limit, at its last leg slot, just inside and just outside
    for field_name, limit in (("q_rad", 10.0), ("dq_rad_s", 200.0), ("tau_est_nm", 500.0),
                              ("gyroscope_rad_s", 100.0)):
        for sign in (1.0, -1.0):
            state = WireState()
            getattr(state, field_name)[WIRE_SLOT_OF_JOINT[-1] if field_name != "gyroscope_rad_s"
                                       else 2] = sign * limit
            assert state_problem(state) is None, field_name
            getattr(state, field_name)[WIRE_SLOT_OF_JOINT[-1] if field_name != "gyroscope_rad_s"
                                       else 2] = sign * limit * 1.001
            assert state_problem(state) == "implausible", field_name
    assert state_problem(WireState(quaternion_wxyz=np.array([1.049, 0.0, 0.0, 0.0]))) is None
    assert state_problem(WireState(quaternion_wxyz=np.array([0.949, 0.0, 0.0, 0.0]))) == \
        "implausible"
    assert state_problem(WireState(gyroscope_rad_s=np.array([0.0, np.inf, 0.0]))) == \
        "non-finite"
