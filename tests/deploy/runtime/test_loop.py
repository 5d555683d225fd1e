"""The one control loop on both clocks, against the in-process MuJoCo drivers: the standing
sequence of ``porter sim`` (lockstep) with its safe stop, and the deploy sequence (paced, on an
injected clock whose sleep steps the simulation)."""

from __future__ import annotations

import gc
from dataclasses import replace

import numpy as np
import pytest

from core.nmpc.settings import BrakingSettings, MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.deploy_config import PostureConfig, RatesConfig
from deploy.config.scenario import Scenario, load_scenario
from deploy.nmpc_runtime.nmpc_lockstep import LockstepNmpc
from deploy.nmpc_runtime.nmpc_schedule import NmpcSchedule
from deploy.runtime.clock import PacedClock
from deploy.runtime.loop import ControlLoop, LoopSettings
from deploy.runtime.sim_run import SimRun
from deploy.safety.preflight import PreflightCheck, PreflightReport
from deploy.safety.settings import SupervisorSettings
from drivers.interfaces import JointCommand, RobotDriver, RobotMeasurement


def _scenario(duration_s: float) -> Scenario:
    scenario = load_scenario("two_go2")
    return scenario.model_copy(update={"duration_s": duration_s, "controller": (
        scenario.controller.model_copy(update={"executor": "serial"}))})


class Tapped:
    """A ``RobotDriver`` that records what is sent and can turn its joint angles to NaN."""

    def __init__(self, driver: RobotDriver, nan_after_s: float | None = None) -> None:
        self.driver, self.nan_after_s = driver, nan_after_s
        self.sent: list[tuple[float, JointCommand]] = []
        self.reads = 0
        self.name = driver.name
        self._time_s = 0.0

    def read(self) -> RobotMeasurement:
        self.reads += 1
        measurement = self.driver.read()
        self._time_s = measurement.time_s
        if self.nan_after_s is not None and measurement.time_s >= self.nan_after_s:
            q = measurement.position_rad.copy()
            q[4] = np.nan
            return replace(measurement, position_rad=q)
        return measurement

    def send(self, command: JointCommand) -> None:
        self.sent.append((self._time_s, command))
        self.driver.send(command)

    def send_damping(self, kd: float) -> None:
        self.driver.send_damping(kd)

    def close(self) -> None:
        self.driver.close()


def test_lockstep_starts_standing_and_ends_standing_at_the_duration() -> None:
    run = SimRun(_scenario(0.2), CompiledCodeCache())
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
    safety = summary["safety"]
    assert safety["transitions"] == ["0.000 s PREFLIGHT -> RUNNING: requested: start_standing",
                                     "0.200 s RUNNING -> DONE: requested: end_standing"]
    assert safety["safe_stop"] is None and safety["result"] == "ran 0.2 s"
    assert summary["nmpc_updates"] == 12 == summary["nmpc_plans_applied"]
    assert summary["duration_s"] == pytest.approx(0.2)


def test_lockstep_a_nan_ends_in_a_safe_stop_with_only_damping_reaching_the_motors() -> None:
    run = SimRun(_scenario(1.0), CompiledCodeCache())
    tapped = Tapped(run.links.drivers["go2_0"], nan_after_s=0.2)
    run.links.drivers["go2_0"] = tapped
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
    safety = summary["safety"]
    assert safety["final_state"] == "DONE"
    assert "non-finite measurement: go2_0 position_rad[4]" in safety["safe_stop"]
    trip_s = float(safety["transitions"][1].split(" s ")[0])
    assert 0.2 <= trip_s < 0.21
    after = [command for t, command in tapped.sent if t >= trip_s]
    assert after, "the safe stop commands damping"
    damping = run.loop_settings.safety.damping_kd
    for command in after:
        assert not command.kp.any() and not command.torque_nm.any()
        assert np.all(command.kd == damping)
    # the run ended after the damping time, not at the scenario's end
    posture = run.loop_settings.posture
    assert summary["duration_s"] == pytest.approx(trip_s + 2 * posture.final_damping_s, abs=0.01)


def test_paced_clock_runs_the_deploy_sequence_on_the_simulation() -> None:
    run = SimRun(_scenario(0.2), CompiledCodeCache())
    sim = run.simulation
    clock_s = [0.0]

    def sleep(seconds: float) -> None:  # the paced clock's sleep lets the world run
        steps = int(round(seconds / sim.timestep_s))
        sim.step(steps)
        clock_s[0] += steps * sim.timestep_s

    def clock() -> float:
        return clock_s[0]

    control = run.control
    nmpc = NmpcSchedule(control, LockstepNmpc(control, clock, True, 0.02), 60.0, clock, None,
                        run.links.force_torque, has_deadline=True, decide_after_send=True)
    # each decision's build: how many of this robot's ticks had read and sent by then
    progress: list[tuple[int, int]] = []
    build = control.nmpc_inputs

    def nmpc_inputs(*args, **kwargs):  # type: ignore[no-untyped-def]
        progress.append((tapped.reads, len(tapped.sent)))
        return build(*args, **kwargs)

    control.nmpc_inputs = nmpc_inputs  # type: ignore[method-assign]
    settings = LoopSettings(RatesConfig(), SupervisorSettings(), PostureConfig(
        stand_up_s=0.3, settle_s=0.1, sit_down_s=0.3, final_damping_s=0.05))
    ok = PreflightReport([PreflightCheck("simulation", True, "in process")])
    tapped = Tapped(run.links.drivers["go2_1"])
    run.links.drivers["go2_1"] = tapped
    loop = ControlLoop(control, run.links, settings, PacedClock(0.002, clock, sleep), nmpc, None,
                       lambda: False, 0.2, "deploy", confirm=lambda: True,
                       preflight=lambda measurements, errors: ok, verbose=False)
    try:
        loop.run("start: test")
    finally:
        run.close()
    outcome = loop.outcome()
    steps = [t.split(": ")[0].split(" s ")[1] for t in outcome["transitions"]]
    assert steps == ["PREFLIGHT -> STANDING_UP", "STANDING_UP -> ARMED", "ARMED -> RUNNING",
                     "RUNNING -> SITTING_DOWN", "SITTING_DOWN -> DONE"], outcome["transitions"]
    assert outcome["safe_stop"] is None and outcome["result"] == "ran 0.2 s"
    # the collector ran during the loop with start-up frozen, and was handed back after it
    assert set(loop.gc_pauses.summary()) == {"gen0", "gen1", "gen2"}
    assert gc.get_freeze_count() == 0
    # plans every other 60 Hz instant (20 ms each), each planned 20-22 ms ahead
    assert 5 <= outcome["nmpc_updates"] <= 8 and outcome["nmpc_deadline_misses"] >= 5
    # decided after the tick's commands went out (deploy's async runners), not before them
    assert len(progress) == outcome["nmpc_updates"]
    assert all(sent == reads for reads, sent in progress), progress
    # (the tick a transition happens in still sends the old state's command)
    running = [c for t, c in tapped.sent if loop.sequence.since[loop.supervisor.state.RUNNING] < t
               < loop.sequence.since[loop.supervisor.state.SITTING_DOWN]]
    # the WBC's hybrid command: its torque, with the firmware PD at the WBC's small gains
    stiffness = control.robots[1].wbc.settings.joint_stiffness_nm_rad
    assert 0 < stiffness < settings.posture.kp
    assert running and all(np.all(c.kp == stiffness) and c.torque_nm.any() for c in running)
    sitting = [c for t, c in tapped.sent if t > loop.sequence.since[loop.supervisor.state.SITTING_DOWN]]
    assert sitting and all(c.kp.any() for c in sitting[:100])  # the posture PD


def test_armed_without_a_first_plan_for_too_long_is_a_safe_stop() -> None:
    """The NMPC never delivers a plan (every update raises): the team may not stand armed
    forever; ``rates.max_armed_s`` after arming the supervisor stops it."""
    run = SimRun(_scenario(0.2), CompiledCodeCache())
    sim = run.simulation
    clock_s = [0.0]

    def sleep(seconds: float) -> None:
        steps = int(round(seconds / sim.timestep_s))
        sim.step(steps)
        clock_s[0] += steps * sim.timestep_s

    def clock() -> float:
        return clock_s[0]

    def no_plan(decision: object) -> None:
        raise RuntimeError("the solver never converges")

    control = run.control
    control.update = no_plan  # type: ignore[method-assign]
    nmpc = NmpcSchedule(control, LockstepNmpc(control, clock, True, 0.02), 60.0, clock, None,
                        run.links.force_torque, has_deadline=True)
    settings = LoopSettings(RatesConfig(max_armed_s=0.1),
                            SupervisorSettings(max_consecutive_solver_failures=30),
                            PostureConfig(stand_up_s=0.2, settle_s=0.05, sit_down_s=0.3,
                                          final_damping_s=0.05))
    ok = PreflightReport([PreflightCheck("simulation", True, "in process")])
    loop = ControlLoop(control, run.links, settings, PacedClock(0.002, clock, sleep), nmpc, None,
                       lambda: False, 0.2, "deploy", confirm=lambda: True,
                       preflight=lambda measurements, errors: ok, verbose=False)
    try:
        loop.run("start: test")
    finally:
        run.close()
    outcome = loop.outcome()
    assert "no NMPC plan" in outcome["safe_stop"] and "(max 0.1 s)" in outcome["safe_stop"]
    armed_s = loop.sequence.since[loop.supervisor.state.ARMED]
    stopped_s = loop.sequence.since[loop.supervisor.state.SAFE_STOP]
    assert 0.1 < stopped_s - armed_s <= 0.1 + 0.004
    assert outcome["nmpc_failed_updates"] >= 2 and loop.nmpc.plan is None


class _InfeasibleAfter(LockstepNmpc):
    """The lockstep NMPC, whose plans from ``after_s`` on report relaxed safety constraints (as
    a plan whose soft barriers used 5 cm of slack does)."""

    after_s = 0.4

    def take(self):  # type: ignore[no-untyped-def]
        result = super().take()
        if result is not None and result.plan is not None \
                and result.decision.time_s >= self.after_s:
            result.plan.barrier_slack_m = 0.05
            result.plan.relaxed = True
        return result


def test_persistent_infeasible_plans_brake_then_sit_down_in_a_controlled_stop(
        monkeypatch: pytest.MonkeyPatch) -> None:
    import deploy.runtime.sim_run as sim_run_module

    monkeypatch.setattr(sim_run_module, "LockstepNmpc", _InfeasibleAfter)
    braking = BrakingSettings(after_flagged_updates=3, controlled_stop_s=0.5)
    run = SimRun(_scenario(4.0), CompiledCodeCache(),
                 base_settings=MpcSettings(braking=braking))
    tapped = {name: Tapped(driver) for name, driver in run.links.drivers.items()}
    run.links.drivers.update(tapped)
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
    safety = summary["safety"]
    assert safety["safe_stop"] is None and safety["final_state"] == "DONE"
    assert safety["controlled_stop"] is True
    # three relaxed plans at the 60 Hz instants from 0.4 s: braking on the third
    braking_s = safety["braking_since_s"]
    assert 0.4 + 2 / 60 - 1e-6 <= braking_s <= 0.4 + 3 / 60 + 0.003
    sit = safety["transitions"][1]
    assert "RUNNING -> SITTING_DOWN: controlled stop: braking since" in sit
    sit_s = float(sit.split(" s ")[0])
    assert sit_s == pytest.approx(braking_s + 0.5, abs=0.003)
    assert safety["transitions"][2].split(" s ")[1].startswith("SITTING_DOWN -> DONE")
    assert safety["result"].startswith("controlled stop")
    # a controlled stop is no fall, and every command until DONE is the WBC's or the sit-down
    # posture's (joint PD), never damping
    assert summary["falls"] == 0
    done_s = float(safety["transitions"][2].split(" s ")[0])
    for driver in tapped.values():
        during = [command for t, command in driver.sent if sit_s + 0.01 < t < done_s]
        assert during and all(command.kp.any() for command in during)
    assert summary["nmpc_plans_applied"] > 0


class Stalled(Tapped):
    """A ``Tapped`` driver whose state stops advancing between ``from_s`` and ``until_s``
    (simulated time): it repeats its last state there, as a late world or firmware would."""

    def __init__(self, driver: RobotDriver, from_s: float, until_s: float) -> None:
        super().__init__(driver)
        self.from_s, self.until_s = from_s, until_s
        self.last: RobotMeasurement | None = None

    def read(self) -> RobotMeasurement:
        measurement = self.driver.read()
        if self.last is None or not self.from_s <= measurement.time_s < self.until_s:
            self.last = measurement
        self.reads += 1
        self._time_s = measurement.time_s
        return self.last


def test_lockstep_a_stalled_state_resends_the_last_fresh_command() -> None:
    run = SimRun(_scenario(0.5), CompiledCodeCache())
    stalled = Stalled(run.links.drivers["go2_0"], from_s=0.3, until_s=0.32)
    run.links.drivers["go2_0"] = stalled
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
    safety = summary["safety"]
    assert safety["safe_stop"] is None and safety["result"] == "ran 0.5 s"
    hold_after = run.loop_settings.safety.stale_state_hold_ticks
    # from 0.3 s on the driver repeats the state it read last before 0.3 s
    fresh = [command for t, command in stalled.sent if t < 0.3][-1]
    window = [command for t, command in stalled.sent if 0.3 <= t < 0.32 - 1e-9]
    assert safety["longest_stale_state_ticks"]["go2_0"] == len(window) >= 9
    assert safety["stale_state_held_ticks"] == {"go2_0": len(window) - hold_after + 1,
                                                 "go2_1": 0}
    for command in window[hold_after - 1:]:
        np.testing.assert_array_equal(command.torque_nm, fresh.torque_nm)
        np.testing.assert_array_equal(command.position_rad, fresh.position_rad)
        np.testing.assert_array_equal(command.velocity_rad_s, fresh.velocity_rad_s)
        assert command.kp.any() and command.kd.any()
    # before the hold, the WBC's command on the repeated state is its own
    assert hold_after == 1 or not np.array_equal(window[0].torque_nm, fresh.torque_nm)


# the simulated world and its scenario harness: on a robot, the drivers' own modules take their
# place; the loop's call path is everything else porter runs in a tick
WORLD_MODULES = ("drivers.mujoco.", "deploy.runtime.sim_run", "deploy.runtime.run_metrics")
MAX_TICK_MODULES = 17  # measured: 17 (22 with the world's); the design target is 12


def _modules_of_one_running_tick(monkeypatch: pytest.MonkeyPatch) -> set[str]:
    """The porter modules whose functions run during one RUNNING tick without an NMPC update
    (250 ticks in, 0.5 s: past the 0.3 s settling, the gait trots), by ``sys.setprofile``."""
    import sys

    from deploy.safety.supervisor import SafetyState
    seen: set[str] = set()
    original, ticks = ControlLoop._tick, [0]

    def traced(loop: ControlLoop) -> bool:
        ticks[0] += 1
        if loop.supervisor.state != SafetyState.RUNNING or ticks[0] < 250 or seen:
            return original(loop)
        modules: set[str] = set()

        def profile(frame: object, event: str, _: object) -> None:
            if event == "call":
                name = frame.f_globals.get("__name__", "")  # type: ignore[attr-defined]
                if name.startswith(("core.", "deploy.", "drivers.")):
                    modules.add(name)
        updates = loop.nmpc.updates
        sys.setprofile(profile)
        try:
            return original(loop)
        finally:
            sys.setprofile(None)
            if loop.nmpc.updates == updates:  # a plain tick; else try the next one
                seen.update(modules)
    monkeypatch.setattr(ControlLoop, "_tick", traced)
    run = SimRun(_scenario(0.6), CompiledCodeCache())
    try:
        run.run(verbose=False)
    finally:
        run.close()
    return seen


def test_a_running_tick_crosses_few_modules(monkeypatch: pytest.MonkeyPatch) -> None:
    modules = _modules_of_one_running_tick(monkeypatch)
    loop_path = sorted(m for m in modules if not m.startswith(WORLD_MODULES))
    # what the tick must run: the check can see it
    for needed in ("deploy.runtime.loop", "deploy.runtime.state_pipeline",
                   "deploy.safety.supervisor", "core.locomotion.whole_body_control",
                   "core.locomotion.gait"):
        assert needed in loop_path, needed
    assert any(m.startswith("drivers.mujoco.") for m in modules)  # the world was read
    assert len(loop_path) <= MAX_TICK_MODULES, loop_path
