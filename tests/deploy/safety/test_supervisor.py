"""Fault injection into the deployment safety supervisor: each fault trips the safe stop with a
cause that names it, the stop is latched, and afterwards nothing but joint damping reaches the
motors, whatever the inputs and the controller's commands. Healthy teams never trip; illegal
requests raise; a real MuJoCo team ends damped and at rest. The budgets (solver, WBC, stale state,
loop and deadline overruns) are in ``test_supervisor_budgets``."""

from __future__ import annotations

import dataclasses
import itertools
import time

import can
import numpy as np
import pytest
from pydantic import ValidationError

from core.model.conventions import LEG_JOINT_NAMES
from deploy.safety.checks import tilt_rad
from deploy.safety.supervisor import (
    RobotLimits,
    SafetyError,
    SafetyInputs,
    SafetyState,
    SafetySupervisor,
    SupervisorSettings,
    Transition,
    robot_limits,
)
from drivers.can.bus import EstopMonitor
from drivers.can.fake import FakeCanNode
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.link_errors import LinkLostError, LinkMonitor
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import UnknownRobotError

TICK_S = 0.002  # WBC period (500 Hz)
PHYSICS_STEPS_PER_TICK = 2  # scene timestep 1 ms
HOLD_KP, HOLD_KD = 100.0, 5.0  # joint PD that holds the standing pose in the sim
SETTINGS = SupervisorSettings()
S = SafetyState
_channels = itertools.count()


def _inputs(time_s: float, measurements: dict[str, RobotMeasurement], **changes) -> SafetyInputs:
    healthy = SafetyInputs(time_s=time_s, run_allowed=True, estop_reason="run allowed",
                           mocap_age_s=0.004, measurements=dict(measurements), link_errors={})
    return dataclasses.replace(healthy, **changes)


def _supervisor_in(state: SafetyState, limits, measurements, settings=SETTINGS,
                   log: list[Transition] | None = None) -> tuple[SafetySupervisor, float]:
    """A supervisor driven with healthy inputs along the planned sequence up to ``state``;
    returns it and the time [s] of its last tick."""
    supervisor = SafetySupervisor(settings, limits, None if log is None else log.append)
    path = [("begin_stand_up", S.STANDING_UP), ("arm", S.ARMED), ("begin_run", S.RUNNING),
            ("begin_sit_down", S.SITTING_DOWN)]
    time_s = 0.0
    for request, target in path:
        if supervisor.state == state:
            break
        getattr(supervisor, request)(time_s)
        for _ in range(5):
            time_s += TICK_S
            assert supervisor.check(_inputs(time_s, measurements)) == target
    assert supervisor.state == state
    return supervisor, time_s


def _wild_commands(supervisor: SafetySupervisor) -> dict[str, JointCommand]:
    """What a broken controller might send: huge torques, stiff gains, fast targets."""
    return {name: JointCommand(torque_nm=np.full(12, 500.0), position_rad=np.full(12, 3.0),
                               velocity_rad_s=np.full(12, 20.0), kp=np.full(12, 300.0),
                               kd=np.full(12, 40.0))
            for name in supervisor.limits}


def _assert_damping_only(commands: dict[str, JointCommand], supervisor: SafetySupervisor) -> None:
    assert set(commands) == set(supervisor.limits)
    for command in commands.values():
        assert np.all(command.torque_nm == 0.0)
        assert np.all(command.kp == 0.0)
        assert np.all(command.kd == supervisor.settings.damping_kd)
        assert np.all(command.velocity_rad_s == 0.0)


def _assert_latched_damping(supervisor: SafetySupervisor, time_s: float, measurements) -> None:
    """For the next ticks, with the fault gone and wild commands coming in: still SAFE_STOP,
    one safe-stop transition, damping only."""
    fault = supervisor.fault
    for _ in range(20):
        time_s += TICK_S
        assert supervisor.check(_inputs(time_s, measurements)) == S.SAFE_STOP
        filtered = supervisor.filter_commands(time_s, _wild_commands(supervisor), measurements)
        _assert_damping_only(filtered, supervisor)
    assert supervisor.fault == fault
    assert [t.target for t in supervisor.transitions].count(S.SAFE_STOP) == 1


def _replace(measurement: RobotMeasurement, field: str, index: int | None, value) -> \
        RobotMeasurement:
    array = np.array(getattr(measurement, field), dtype=float)
    if index is None:
        array[:] = value
    else:
        array[index] = value
    return dataclasses.replace(measurement, **{field: array})  # type: ignore[arg-type]


# --- limits and settings ---------------------------------------------------------------------
@pytest.mark.parametrize(("robot_type", "calf_torque_nm"), [("go2", 45.43), ("a1", 33.5)])
def test_robot_limits_come_from_the_urdf(scene, standing, robot_type, calf_torque_nm):
    robot = next(r for r in scene.robots if r.robot_type == robot_type)
    limits = robot_limits(robot_type, robot.name)
    assert limits.name == robot.name
    assert limits.torque_nm[LEG_JOINT_NAMES.index("RR_calf_joint")] == calf_torque_nm
    np.testing.assert_allclose(limits.torque_nm, scene.model.actuator_ctrlrange[
        robot.actuator_ids, 1])  # the scene's motors use the same URDF efforts
    for i, joint in enumerate(LEG_JOINT_NAMES):
        mj_range = scene.model.joint(f"{robot.name}/{joint}").range
        np.testing.assert_allclose([limits.lower_position_rad[i], limits.upper_position_rad[i]],
                                   mj_range, atol=1e-6)
    q = standing[robot.name].position_rad
    assert np.all((limits.lower_position_rad < q) & (q < limits.upper_position_rad))
    # nominal height: the base height of the standing scene, with the feet on the ground
    assert limits.nominal_height_m == pytest.approx(
        standing[robot.name].position_in_world_m[2], abs=2e-3)


def test_unknown_robot_type_and_bad_limits_are_rejected():
    with pytest.raises(UnknownRobotError, match="go2"):
        robot_limits("spot", "s")
    with pytest.raises(ValueError, match="12 finite"):
        RobotLimits("r", np.zeros(3), np.ones(12), np.ones(12), 0.3)
    with pytest.raises(ValueError, match="lower"):
        RobotLimits("r", np.ones(12), np.zeros(12), np.ones(12), 0.3)


def test_settings_forbid_unknown_keys_and_bad_values(limits):
    assert SupervisorSettings.model_validate({"mocap_timeout_s": 0.05}).mocap_timeout_s == 0.05
    with pytest.raises(ValidationError, match="mocap_timout_s"):
        SupervisorSettings.model_validate({"mocap_timout_s": 0.05})
    with pytest.raises(ValidationError):
        SupervisorSettings(torque_limit_fraction=1.5)
    with pytest.raises(ValueError, match="distinct"):
        SafetySupervisor(SETTINGS, [limits[0], limits[0]])


# --- transitions -----------------------------------------------------------------------------
def test_planned_sequence_is_logged_with_causes(limits, standing):
    log: list[Transition] = []
    supervisor, time_s = _supervisor_in(S.SITTING_DOWN, limits, standing, log=log)
    supervisor.finish(time_s)
    assert supervisor.state == S.DONE and supervisor.fault == ""
    assert log == supervisor.transitions
    assert [(t.source, t.target) for t in log] == [
        (S.PREFLIGHT, S.STANDING_UP), (S.STANDING_UP, S.ARMED), (S.ARMED, S.RUNNING),
        (S.RUNNING, S.SITTING_DOWN), (S.SITTING_DOWN, S.DONE)]
    assert log[2].text == "ARMED -> RUNNING: requested: begin_run"
    assert [t.time_s for t in log] == sorted(t.time_s for t in log)


@pytest.mark.parametrize(("state", "request_name"), [
    (S.PREFLIGHT, "arm"), (S.PREFLIGHT, "begin_run"), (S.PREFLIGHT, "begin_sit_down"),
    (S.STANDING_UP, "begin_run"), (S.STANDING_UP, "begin_stand_up"), (S.STANDING_UP, "finish"),
    (S.ARMED, "arm"), (S.RUNNING, "begin_stand_up"), (S.RUNNING, "finish"),
    (S.SITTING_DOWN, "begin_run"), (S.SITTING_DOWN, "begin_sit_down")])
def test_illegal_requests_raise_and_change_nothing(limits, standing, state, request_name):
    supervisor, time_s = _supervisor_in(state, limits, standing)
    count = len(supervisor.transitions)
    with pytest.raises(SafetyError, match=f"cannot {request_name} in state {state.name}"):
        getattr(supervisor, request_name)(time_s)
    assert isinstance(SafetyError(), ValueError)
    assert supervisor.state == state and len(supervisor.transitions) == count


def test_preflight_is_limp_and_reports_faults_without_moving(limits, standing):
    supervisor = SafetySupervisor(SETTINGS, limits)
    inputs = _inputs(0.0, standing, run_allowed=False, estop_reason="e-stop pressed (heartbeat 3)")
    assert supervisor.check(inputs) == S.PREFLIGHT
    assert supervisor.active_faults == ["e-stop: run not allowed (e-stop pressed (heartbeat 3))"]
    filtered = supervisor.filter_commands(0.0, _wild_commands(supervisor), standing)
    assert set(filtered) == set(supervisor.limits)
    for command in filtered.values():
        for name in ("torque_nm", "position_rad", "velocity_rad_s", "kp", "kd"):
            assert np.all(getattr(command, name) == 0.0)
    supervisor.trigger_safe_stop(0.0, "operator abort")  # nothing to stop yet
    assert supervisor.state == S.PREFLIGHT and supervisor.transitions == []
    supervisor.finish(0.1)  # aborted before standing up
    assert supervisor.state == S.DONE


def test_the_latch_holds_until_finish(limits, standing):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    supervisor.trigger_safe_stop(time_s, "operator abort: Ctrl-C")
    assert supervisor.state == S.SAFE_STOP and supervisor.fault == "operator abort: Ctrl-C"
    supervisor.check(_inputs(time_s, standing, mocap_age_s=5.0))  # another fault: no new stop
    _assert_latched_damping(supervisor, time_s, standing)
    for request in ("begin_stand_up", "arm", "begin_run", "begin_sit_down"):
        with pytest.raises(SafetyError, match="operator abort"):
            getattr(supervisor, request)(time_s)
    supervisor.finish(time_s + 1.0)
    assert supervisor.state == S.DONE and supervisor.fault == "operator abort: Ctrl-C"
    supervisor.trigger_safe_stop(time_s + 1.1, "late fault")
    assert supervisor.check(_inputs(time_s + 1.2, standing, run_allowed=False)) == S.DONE
    _assert_damping_only(supervisor.filter_commands(time_s + 1.2, _wild_commands(supervisor),
                                                    standing), supervisor)
    assert [t.target for t in supervisor.transitions][-2:] == [S.SAFE_STOP, S.DONE]
    with pytest.raises(SafetyError, match="DONE"):
        supervisor.finish(time_s + 2.0)


# --- healthy ---------------------------------------------------------------------------------
def test_healthy_team_never_trips_in_1000_ticks(scene, limits):
    """A real MuJoCo team held standing, with occasional (within budget) NMPC trouble."""
    simulation = TeamSimulation(scene)
    drivers = {robot.name: simulation.robot_driver(robot.name) for robot in scene.robots}
    hold = {robot.name: JointCommand.hold(scene.initial_qpos[robot.leg_qpos_addresses],
                                          HOLD_KP, HOLD_KD) for robot in scene.robots}
    supervisor = SafetySupervisor(SETTINGS, limits)
    for tick in range(1000):
        time_s = tick * TICK_S
        if tick == 0:
            supervisor.begin_stand_up(time_s)
        elif tick == 50:
            supervisor.arm(time_s)
        elif tick == 100:
            supervisor.begin_run(time_s)
        measurements = {name: driver.read() for name, driver in drivers.items()}
        update = tick % 10 == 0  # NMPC at 50 Hz: every 30th fails, every 7th is late
        inputs = _inputs(time_s, measurements, mocap_age_s=0.008 * (tick % 3),
                         solver_failed=(tick % 300 == 0) if update else None,
                         deadline_missed=(tick % 70 == 0) if update else None)
        assert supervisor.check(inputs) != S.SAFE_STOP, supervisor.active_faults
        filtered = supervisor.filter_commands(time_s, hold, measurements)
        assert supervisor.state != S.SAFE_STOP, supervisor.fault
        assert all(filtered[name] is hold[name] for name in hold)
        for name, driver in drivers.items():
            driver.send(filtered[name])
        simulation.step(PHYSICS_STEPS_PER_TICK)
    assert supervisor.state == S.RUNNING and supervisor.active_faults == []
    assert len(supervisor.transitions) == 3


# --- faults of one tick's inputs -------------------------------------------------------------
GO2, A1 = "go2_0", "a1_1"


def _measurement_fault(robot: str, field: str, index: int | None, value):
    def inject(inputs: SafetyInputs) -> SafetyInputs:
        measurements = dict(inputs.measurements)
        measurements[robot] = _replace(measurements[robot], field, index, value)
        return dataclasses.replace(inputs, measurements=measurements)
    return inject


def _tilted(robot: str, angle_rad: float):
    quaternion = [np.cos(angle_rad / 2), np.sin(angle_rad / 2), 0.0, 0.0]  # about world x
    return _measurement_fault(robot, "quaternion_wxyz", None, quaternion)


def _link_lost(inputs: SafetyInputs) -> SafetyInputs:
    clock_s = [0.0]
    monitor = LinkMonitor("a1 UDP 192.168.123.10:8007", 0.02, lambda: clock_s[0])
    monitor.accept()
    clock_s[0] = 0.05
    with pytest.raises(LinkLostError) as error:
        monitor.check()
    measurements = {GO2: inputs.measurements[GO2]}  # no state read from the lost robot
    return dataclasses.replace(inputs, measurements=measurements,
                               link_errors={A1: str(error.value)})


FAULTS = {  # name -> (inject into healthy inputs, text the cause must contain)
    "e-stop pressed": (lambda i: dataclasses.replace(
        i, run_allowed=False, estop_reason="e-stop pressed (heartbeat 7)"),
        "e-stop: run not allowed (e-stop pressed (heartbeat 7))"),
    "heartbeat lost": (lambda i: dataclasses.replace(
        i, run_allowed=False,
        estop_reason="e-stop heartbeat lost: last valid one 0.153 s ago (timeout 0.1 s)"),
        "e-stop heartbeat lost: last valid one 0.153 s ago"),
    "mocap stale": (lambda i: dataclasses.replace(i, mocap_age_s=0.153),
                    "MoCap lost: no frame for 0.153 s (timeout 0.1 s)"),
    "mocap never received": (lambda i: dataclasses.replace(i, mocap_age_s=None),
                             "MoCap lost: no frame received yet"),
    "nan joint position": (_measurement_fault(GO2, "position_rad", 4, np.nan),
                           "non-finite measurement: go2_0 position_rad[4] = nan"),
    "inf quaternion": (_measurement_fault(A1, "quaternion_wxyz", 0, np.inf),
                       "non-finite measurement: a1_1 quaternion_wxyz[0] = inf"),
    "nan base velocity": (_measurement_fault(A1, "linear_velocity_in_world_m_s", 2, np.nan),
                          "non-finite measurement: a1_1 linear_velocity_in_world_m_s[2]"),
    "nan foot force": (_measurement_fault(GO2, "foot_normal_force_n", 1, -np.inf),
                       "non-finite measurement: go2_0 foot_normal_force_n[1] = -inf"),
    "tilt": (_tilted(GO2, 0.8), "tilt: go2_0 trunk tilted 0.800 rad (max 0.7 rad)"),
    "upside down": (_tilted(A1, np.pi), "tilt: a1_1 trunk tilted 3.142 rad"),
    "not a quaternion": (_measurement_fault(GO2, "quaternion_wxyz", None, 0.0),
                         "implausible base quaternion: go2_0 norm 0.000"),
    "base too low": (_measurement_fault(A1, "position_in_world_m", 2, 0.1),
                     "base height: a1_1 base at 0.100 m, below 0.133 m (0.5 of nominal 0.266 m)"),
    "joint velocity": (_measurement_fault(GO2, "velocity_rad_s", 4, -35.0),
                       "joint velocity: go2_0 FR_thigh_joint at -35.00 rad/s (max 30.0 rad/s)"),
    "joint above limit": (_measurement_fault(A1, "position_rad", 2, -0.80),
                          "joint position limit: a1_1 FL_calf_joint at -0.800 rad, outside "
                          "[-2.697, -0.916] rad (margin 0.1 rad)"),
    "joint below limit": (_measurement_fault(GO2, "position_rad", 9, -1.2),
                          "joint position limit: go2_0 RR_hip_joint at -1.200 rad"),
    "link lost": (_link_lost, "robot link lost: a1_1: a1 UDP 192.168.123.10:8007: last valid "
                              "state 0.050 s ago (timeout 0.02 s"),
    "measurement missing": (lambda i: dataclasses.replace(
        i, measurements={A1: i.measurements[A1]}), "no measurement of robot go2_0"),
}


@pytest.mark.parametrize("fault", FAULTS)
def test_fault_trips_a_running_team_into_a_latched_damping_stop(limits, standing, fault):
    inject, cause = FAULTS[fault]
    log: list[Transition] = []
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing, log=log)
    time_s += TICK_S
    assert supervisor.check(inject(_inputs(time_s, standing))) == S.SAFE_STOP
    assert cause in supervisor.fault
    assert log[-1] == Transition(time_s, S.RUNNING, S.SAFE_STOP, supervisor.fault)
    assert supervisor.fault in log[-1].text
    _assert_damping_only(supervisor.filter_commands(time_s, _wild_commands(supervisor), standing),
                         supervisor)
    _assert_latched_damping(supervisor, time_s, standing)


def test_the_cause_lists_every_simultaneous_fault(limits, standing):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    inputs = FAULTS["tilt"][0](FAULTS["mocap stale"][0](_inputs(time_s + TICK_S, standing)))
    supervisor.check(inputs)
    assert "MoCap lost" in supervisor.fault and "tilt: go2_0" in supervisor.fault
    assert len(supervisor.active_faults) == 2


@pytest.mark.parametrize("state", [S.STANDING_UP, S.ARMED, S.RUNNING, S.SITTING_DOWN])
@pytest.mark.parametrize("fault", ["e-stop pressed", "joint velocity", "link lost"])
def test_faults_trip_in_every_active_state(limits, standing, state, fault):
    inject, cause = FAULTS[fault]
    supervisor, time_s = _supervisor_in(state, limits, standing)
    assert supervisor.check(inject(_inputs(time_s + TICK_S, standing))) == S.SAFE_STOP
    assert supervisor.transitions[-1].source == state and cause in supervisor.fault
    _assert_latched_damping(supervisor, time_s + TICK_S, standing)


def test_lying_robots_and_no_mocap_are_fine_until_armed(limits, standing):
    """Standing up starts (and sitting down ends) with the trunks on the ground, and the
    MoCap may start late; once ARMED, both are faults."""
    lying = {name: _replace(m, "position_in_world_m", 2, 0.08) for name, m in standing.items()}
    supervisor = SafetySupervisor(SETTINGS, limits)
    supervisor.begin_stand_up(0.0)
    for tick in range(1, 20):
        assert supervisor.check(_inputs(tick * TICK_S, lying, mocap_age_s=None)) == S.STANDING_UP
    supervisor.arm(0.04)
    assert supervisor.check(_inputs(0.042, lying, mocap_age_s=None)) == S.SAFE_STOP
    assert "MoCap lost: no frame received yet" in supervisor.fault
    assert "base height: go2_0" in supervisor.fault and "base height: a1_1" in supervisor.fault

    supervisor, time_s = _supervisor_in(S.SITTING_DOWN, limits, standing)
    assert supervisor.check(_inputs(time_s + TICK_S, lying)) == S.SITTING_DOWN
    assert supervisor.check(_inputs(time_s + 2 * TICK_S, lying, mocap_age_s=0.2)) == S.SAFE_STOP


@pytest.mark.parametrize("event", ["pressed", "heartbeat lost"])
def test_real_estop_monitor_reasons_trip(limits, standing, event):
    channel = f"porter-safety-test-{next(_channels)}"
    clock_s = [0.0]
    with EstopMonitor(channel=channel, timeout_s=0.1, clock=lambda: clock_s[0]) as monitor, \
            can.Bus(interface="virtual", channel=channel) as raw, \
            FakeCanNode(raw, heartbeat=False) as node:
        def heartbeat() -> None:
            received = monitor.counters.frames_received
            node.send_heartbeat()
            deadline_s = time.monotonic() + 2.0
            while monitor.counters.frames_received == received:
                assert time.monotonic() < deadline_s, "heartbeat not received"
                time.sleep(0.001)

        def inputs(time_s: float) -> SafetyInputs:
            status = monitor.status()
            return _inputs(time_s, standing, run_allowed=status.run_allowed,
                           estop_reason=status.reason)

        supervisor, time_s = _supervisor_in(S.ARMED, limits, standing)
        assert supervisor.check(inputs(time_s)) == S.SAFE_STOP  # no heartbeat yet
        assert "no e-stop heartbeat received yet" in supervisor.fault
        supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
        heartbeat()
        assert supervisor.check(inputs(time_s)) == S.RUNNING
        if event == "pressed":
            node.press_estop()
            heartbeat()
            expected = "e-stop: run not allowed (e-stop pressed (heartbeat 2))"
        else:
            clock_s[0] = 0.15
            expected = "e-stop heartbeat lost: last valid one 0.150 s ago (timeout 0.1 s)"
        assert supervisor.check(inputs(time_s + TICK_S)) == S.SAFE_STOP
        assert expected in supervisor.fault
        node.release_estop()
        heartbeat()  # run allowed again: the stop stays
        assert monitor.is_run_allowed()
        _assert_latched_damping(supervisor, time_s + TICK_S, standing)


# --- commanded torque --------------------------------------------------------------------------
def _torque_case(kind: str, standing) -> tuple[JointCommand, str, SupervisorSettings]:
    q = standing[GO2].position_rad
    calf, thigh, hip = (LEG_JOINT_NAMES.index(j) for j in
                        ("FL_calf_joint", "FR_thigh_joint", "RL_hip_joint"))
    if kind == "feed-forward":
        torque = np.zeros(12)
        torque[calf] = -50.0
        return (JointCommand(torque_nm=torque), "commanded torque: go2_0 FL_calf_joint -50.00 N m "
                "beyond 45.43 N m (1.0 of limit 45.43 N m)", SETTINGS)
    if kind == "pd at the state":  # no feed-forward: 100 N m/rad x 0.3 rad = 30 N m > 23.7
        target = q.copy()
        target[thigh] += 0.3
        return (JointCommand.hold(target, 100.0, 1.0), "go2_0 FR_thigh_joint 30.00 N m", SETTINGS)
    if kind == "fraction":
        torque = np.zeros(12)
        torque[hip] = 15.0
        return (JointCommand(torque_nm=torque), "go2_0 RL_hip_joint 15.00 N m beyond 11.85 N m "
                "(0.5 of limit 23.7 N m)", SupervisorSettings(torque_limit_fraction=0.5))
    torque = np.zeros(12)
    torque[hip] = np.nan
    return JointCommand(torque_nm=torque), "go2_0 RL_hip_joint nan N m", SETTINGS


@pytest.mark.parametrize("state", [S.STANDING_UP, S.RUNNING, S.SITTING_DOWN])
@pytest.mark.parametrize("kind", ["feed-forward", "pd at the state", "fraction", "nan"])
def test_commanded_torque_beyond_the_limit_trips(limits, standing, state, kind):
    command, cause, settings = _torque_case(kind, standing)
    supervisor, time_s = _supervisor_in(state, limits, standing, settings)
    commands = {A1: JointCommand(), GO2: command}
    filtered = supervisor.filter_commands(time_s, commands, standing)
    assert supervisor.state == S.SAFE_STOP and supervisor.transitions[-1].source == state
    assert cause in supervisor.fault
    _assert_damping_only(filtered, supervisor)
    _assert_latched_damping(supervisor, time_s, standing)


def test_commands_within_the_limits_pass_unchanged(limits, standing):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    at_limit = {name: JointCommand(torque_nm=-limit.torque_nm) for name, limit in
                supervisor.limits.items()}
    filtered = supervisor.filter_commands(time_s, at_limit, standing)
    assert supervisor.state == S.RUNNING
    assert all(filtered[name] is at_limit[name] for name in at_limit)
    unknown = {"go2_9": JointCommand()}
    _assert_damping_only(supervisor.filter_commands(time_s, unknown, standing), supervisor)
    assert "command for unknown robot 'go2_9'" in supervisor.fault


def test_a_command_without_a_measurement_trips(limits, standing):
    supervisor, time_s = _supervisor_in(S.RUNNING, limits, standing)
    supervisor.filter_commands(time_s, {A1: JointCommand()}, {GO2: standing[GO2]})
    assert supervisor.state == S.SAFE_STOP
    assert "a1_1 cannot be checked without a measurement" in supervisor.fault


# --- a real team -----------------------------------------------------------------------------
def test_safe_stop_leaves_a_real_team_damped_and_at_rest(scene, limits):
    """Hold a MuJoCo team standing, press the e-stop while the controller goes wild: only
    damping reaches the motors; the team sinks under the payload, slows down and comes to rest
    on the ground with finite states."""
    simulation = TeamSimulation(scene)
    drivers = {robot.name: simulation.robot_driver(robot.name) for robot in scene.robots}
    hold = {robot.name: JointCommand.hold(scene.initial_qpos[robot.leg_qpos_addresses],
                                          HOLD_KP, HOLD_KD) for robot in scene.robots}
    supervisor = SafetySupervisor(SETTINGS, limits)
    supervisor.begin_stand_up(0.0)
    supervisor.arm(0.0)
    supervisor.begin_run(0.0)
    fault_tick, ticks = 100, 100 + 500  # 0.2 s standing, then 1.0 s (0.5 s, twice) damped
    peak_rad_s, at_half_rad_s = 0.0, 0.0
    for tick in range(ticks):
        time_s = tick * TICK_S
        measurements = {name: driver.read() for name, driver in drivers.items()}
        faulty = tick >= fault_tick
        inputs = _inputs(time_s, measurements, run_allowed=not faulty,
                         estop_reason="e-stop pressed (heartbeat 9)" if faulty else "run allowed")
        supervisor.check(inputs)
        commands = _wild_commands(supervisor) if faulty else hold
        filtered = supervisor.filter_commands(time_s, commands, measurements)
        if faulty:
            _assert_damping_only(filtered, supervisor)
        for name, driver in drivers.items():
            driver.send(filtered[name])
        simulation.step(PHYSICS_STEPS_PER_TICK)
        speed_rad_s = max(float(np.abs(m.velocity_rad_s).max()) for m in measurements.values())
        peak_rad_s = max(peak_rad_s, speed_rad_s)
        if tick == fault_tick + 250:
            at_half_rad_s = speed_rad_s
        assert all(np.isfinite(simulation.data.qpos)) and all(np.isfinite(simulation.data.qvel))
    assert supervisor.state == S.SAFE_STOP
    assert supervisor.transitions[-1].time_s == pytest.approx(fault_tick * TICK_S)
    final = {name: driver.read() for name, driver in drivers.items()}
    final_rad_s = max(float(np.abs(m.velocity_rad_s).max()) for m in final.values())
    assert peak_rad_s > 1.0  # the damping let the team sink ...
    assert at_half_rad_s < 0.5 * peak_rad_s  # ... slowing down after 0.5 s ...
    assert final_rad_s < 0.3  # ... and at rest after 1 s
    for name, measurement in final.items():
        height_m = measurement.position_in_world_m[2]
        assert 0.03 < height_m < 0.5 * supervisor.limits[name].nominal_height_m
        assert tilt_rad(measurement.quaternion_wxyz) < SETTINGS.max_tilt_rad  # not toppled
        assert measurement.foot_contact.any()

