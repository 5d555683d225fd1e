"""The WBC's QP assembled by one CasADi function: the same torques and forces as the QP built
over the stance feet only (the formulation it replaced, kept here as the reference), and the
SO(3) log it uses against Pinocchio's."""

from __future__ import annotations

from pathlib import Path

import casadi as ca
import daqp
import numpy as np
import pinocchio as pin
import pytest

from core.locomotion.wbc_qp import so3_log
from core.locomotion.whole_body_control import (
    FloatingBaseState,
    WbcTarget,
    WholeBodyController,
    structural_patterns,
)
from core.model.rotations import rotation_from_euler
from deploy.compute.codegen_cache import CompiledCodeCache
from drivers.robot_descriptions import FOOT_RADIUS_M, load_pinocchio_model, standing_configuration

_INF = 1e30


def _reference(wbc: WholeBodyController, state: FloatingBaseState, target: WbcTarget
               ) -> tuple[np.ndarray, np.ndarray]:
    """(torques, (4, 3) forces) of the variable-size QP over the stance feet, in NumPy."""
    s, model = wbc.settings, wbc.model
    data = model.createData()
    rotation = state.rotation()
    q, v = wbc.pinocchio_state(state)
    pin.computeAllTerms(model, data, q, v)
    pin.updateFramePlacements(model, data)
    mass = np.triu(data.M) + np.triu(data.M, 1).T
    bias = np.array(data.nle)
    pin.forwardKinematics(model, data, q, v, np.zeros(model.nv))
    world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    jacobians = [pin.getFrameJacobian(model, data, i, world)[0:3] for i in wbc.foot_frame_ids]
    drifts = [pin.getFrameClassicalAcceleration(model, data, i, world).linear
              for i in wbc.foot_frame_ids]
    stance = np.flatnonzero(target.stance)
    nf, nv = 3 * len(stance), model.nv
    n = nf + nv
    # base target: PD on the planned trunk (spatial acceleration in the base frame)
    rotation_desired = rotation_from_euler(target.euler_rad)
    offset = rotation_desired @ wbc.com_offset_in_base_m
    omega = rotation @ state.angular_velocity_in_body_rad_s
    linear = (target.com_acceleration_m_s2
              + np.array(s.base_position_gain) * (target.com_position_m - offset
                                                  - state.position_base_in_world_m)
              + np.array(s.base_velocity_gain) * (
                  target.com_velocity_m_s - np.cross(target.angular_velocity_rad_s, offset)
                  - state.linear_velocity_in_world_m_s))
    angular = (target.angular_acceleration_rad_s2
               + np.array(s.base_orientation_gain) * pin.log3(rotation_desired @ rotation.T)
               + np.array(s.base_angular_velocity_gain) * (target.angular_velocity_rad_s - omega))
    base = np.concatenate([rotation.T @ linear - np.cross(v[3:6], v[0:3]), rotation.T @ angular])
    hessian = s.regularization * np.eye(n)
    hessian[range(nf, nf + 6), range(nf, nf + 6)] += s.base_weight
    hessian[range(nf), range(nf)] += s.force_weight
    gradient = np.zeros(n)
    gradient[nf:nf + 6] -= s.base_weight * base
    for leg in sorted(set(range(4)) - set(stance)):
        jacobian = jacobians[leg]
        foot = data.oMf[wbc.foot_frame_ids[leg]].translation
        desired = (target.foot_acceleration_m_s2[leg]
                   + s.swing_position_gain * (target.foot_position_m[leg]
                                              + (0, 0, wbc.foot_radius_m) - foot)
                   + s.swing_velocity_gain * (target.foot_velocity_m_s[leg] - jacobian @ v))
        hessian[nf:, nf:] += s.swing_weight * jacobian.T @ jacobian
        gradient[nf:] -= s.swing_weight * jacobian.T @ (desired - drifts[leg])
    gradient[0:nf] -= s.force_weight * target.planned_grf_n[stance].reshape(-1)
    contact = np.vstack([jacobians[leg] for leg in stance]) if nf else np.zeros((0, nv))
    mu = s.friction_coefficient
    pyramid = np.array([[1, 0, -mu], [-1, 0, -mu], [0, 1, -mu], [0, -1, -mu]])
    friction = np.zeros((4 * len(stance), n))
    for k in range(len(stance)):
        friction[4 * k:4 * k + 4, 3 * k:3 * k + 3] = pyramid
    dynamics = np.hstack([-contact[:, 0:6].T, mass[0:6]])
    stance_rows = np.hstack([np.zeros((nf, nf)), contact])
    torque_rows = np.hstack([-contact[:, 6:].T, mass[6:]])
    force, moment = target.wrench_on_robot[0:3], target.wrench_on_robot[3:6]
    lever = rotation @ wbc.coupling_in_base_m
    base_force = np.concatenate([rotation.T @ force, rotation.T @ (moment + np.cross(lever, force))])
    stance_rhs = (-np.concatenate([drifts[leg] for leg in stance] or [np.zeros(0)])
                  - s.stance_velocity_damping * (contact @ v))
    constraint = np.vstack([friction, dynamics, stance_rows, torque_rows])
    upper = np.concatenate([np.tile([_INF, _INF, s.max_normal_force_n], len(stance)),
                            np.zeros(len(friction)), base_force - bias[0:6], stance_rhs,
                            wbc.torque_limit_nm - bias[6:]])
    lower = np.concatenate([np.tile([-_INF, -_INF, s.min_normal_force_n], len(stance)),
                            -_INF * np.ones(len(friction)), base_force - bias[0:6], stance_rhs,
                            -wbc.torque_limit_nm - bias[6:]])
    sense = np.zeros(len(upper), dtype=np.int32)
    sense[nf + len(friction):nf + len(friction) + 6 + nf] = 5
    x, _, status, _ = daqp.solve(hessian, gradient, constraint, upper, lower, sense)
    assert status >= 1
    torque = mass[6:] @ x[nf:] + bias[6:] - contact[:, 6:].T @ x[0:nf]
    forces = np.zeros((4, 3))
    forces[stance] = x[0:nf].reshape(-1, 3)
    return np.clip(torque, -wbc.torque_limit_nm, wbc.torque_limit_nm), forces


def _controller() -> WholeBodyController:
    model = load_pinocchio_model("go2")
    return WholeBodyController(model, standing_configuration("go2", model),
                               np.array([0.05, -0.02, 0.1]), FOOT_RADIUS_M["go2"])


def _random_tick(wbc: WholeBodyController, rng: np.random.Generator, stance: np.ndarray
                 ) -> tuple[FloatingBaseState, WbcTarget]:
    q = standing_configuration("go2", wbc.model)
    quaternion = np.array([3.0, 0.0, 0.0, 0.0]) + rng.normal(size=4) * [1, 0.05, 0.05, 0.3]
    state = FloatingBaseState(np.array([0.1, -0.2, 0.3]) + rng.normal(size=3) * 0.02,
                              quaternion / np.linalg.norm(quaternion), rng.normal(size=3) * 0.3,
                              rng.normal(size=3) * 0.3, q[7:] + rng.normal(size=12) * 0.05,
                              rng.normal(size=12) * 0.5)
    srb = wbc.srb_state(state)
    feet = wbc.foot_positions(state)

    def small(*shape: int) -> np.ndarray:
        return rng.normal(size=shape) * 0.1

    target = WbcTarget(srb[0:3] + small(3), srb[3:6] + small(3), small(3) * 10,
                       srb[6:9] + small(3), srb[9:12] + small(3), small(3) * 10, stance,
                       np.abs(rng.normal(size=(4, 3)) * 5) + [0.0, 0.0, 40.0],
                       feet + small(4, 3), small(4, 3), small(4, 3) * 10,
                       rng.normal(size=6) * 5)
    return state, target


@pytest.mark.parametrize("pattern", range(16))
def test_fixed_size_qp_gives_the_stance_only_qps_torques(pattern: int) -> None:
    """Every stance pattern, random states and targets: torques and forces of the fixed-size
    QP (swing forces pinned to zero) equal the variable-size QP's to solver round-off."""
    wbc = _controller()
    rng = np.random.default_rng(pattern)
    stance = np.array([bool(pattern >> leg & 1) for leg in range(4)])
    for _ in range(4):
        state, target = _random_tick(wbc, rng, stance)
        output = wbc.compute(state, target)
        torque, forces = _reference(wbc, state, target)
        assert output.success
        np.testing.assert_allclose(output.torque_nm, torque, rtol=0, atol=1e-6)
        np.testing.assert_allclose(output.contact_force_n, forces, rtol=0, atol=1e-6)
        assert np.all(output.contact_force_n[~stance] == 0.0)


def test_so3_log_matches_pinocchio_below_pi() -> None:
    rotation = ca.SX.sym("R", 3, 3)
    log = ca.Function("log", [rotation], [so3_log(rotation)])
    rng = np.random.default_rng(3)
    angles = np.concatenate([[0.0, 1e-12, 1e-6, 1e-3], rng.uniform(0.0, 3.1, size=40)])
    for angle in angles:
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        matrix = pin.exp3(angle * axis)
        np.testing.assert_allclose(np.array(log(matrix)).ravel(), pin.log3(matrix),
                                   rtol=0, atol=1e-9)


def test_compiled_assembly_writes_the_same_arrays(tmp_path: Path) -> None:
    """The assembly as compiled C (the deploy loop's) fills the same QP arrays as the SX
    function, bit for bit, and a second controller loads the cached library."""
    model = load_pinocchio_model("go2")
    cache = CompiledCodeCache(tmp_path)
    interpreted = _controller()
    compiled = WholeBodyController(model, standing_configuration("go2", model),
                                   np.array([0.05, -0.02, 0.1]), FOOT_RADIUS_M["go2"],
                                   compiler=cache)
    assert compiled._qp.compiled and not interpreted._qp.compiled
    assert len(list(tmp_path.glob("wbc_qp_*.so"))) == 1
    rng = np.random.default_rng(7)
    for pattern in (15, 9, 6, 0):
        stance = np.array([bool(pattern >> leg & 1) for leg in range(4)])
        state, target = _random_tick(interpreted, rng, stance)
        outputs = [wbc.compute(state, target) for wbc in (interpreted, compiled)]
        for field in ("hessian", "gradient", "constraint", "upper", "lower"):
            np.testing.assert_array_equal(getattr(compiled._qp.arrays, field),
                                          getattr(interpreted._qp.arrays, field))
        np.testing.assert_array_equal(outputs[0].torque_nm, outputs[1].torque_nm)
    library_time = next(tmp_path.glob("wbc_qp_*.so")).stat().st_mtime_ns
    WholeBodyController(model, standing_configuration("go2", model),
                        np.array([0.05, -0.02, 0.1]), FOOT_RADIUS_M["go2"], compiler=cache)
    assert next(tmp_path.glob("wbc_qp_*.so")).stat().st_mtime_ns == library_time


@pytest.mark.parametrize("robot_type", ["go2", "a1"])
def test_structural_patterns_hold_every_non_zero(robot_type: str) -> None:
    """The assembly reads the Jacobian and the mass matrix only inside these patterns: on
    random configurations nothing outside them is non-zero, and a foot's rows are 9 columns
    (the base's 6, its leg's 3)."""
    model = load_pinocchio_model(robot_type)
    data = model.createData()
    feet = [model.getFrameId(f"{leg}_foot") for leg in ("FL", "FR", "RL", "RR")]
    jacobian_pattern, mass_pattern = structural_patterns(model, feet)
    assert jacobian_pattern.sum(axis=1).tolist() == [9] * 12
    assert (mass_pattern == mass_pattern.T).all()
    rng = np.random.default_rng(5)
    for _ in range(10):
        q = pin.randomConfiguration(model, -np.ones(model.nq), np.ones(model.nq))
        pin.computeAllTerms(model, data, q, rng.normal(size=model.nv))
        pin.updateFramePlacements(model, data)
        jacobian = np.vstack([pin.getFrameJacobian(model, data, i, pin.LOCAL_WORLD_ALIGNED)[0:3]
                              for i in feet])
        mass = np.triu(data.M) + np.triu(data.M, 1).T
        assert np.all(jacobian[~jacobian_pattern] == 0.0)
        assert np.all(mass[~mass_pattern] == 0.0)
        assert np.count_nonzero(jacobian[jacobian_pattern]) > 0.9 * jacobian_pattern.sum()
