"""The deployment safety state machine: which state the team is in, and what it may command.

    PREFLIGHT -> STANDING_UP -> ARMED -> RUNNING -> SITTING_DOWN -> DONE
                      |            |         |            |
                      +------------+---------+------------+--> SAFE_STOP -> DONE

The loop requests the planned transitions (``begin_stand_up``, ``arm``, ``begin_run``,
``begin_sit_down`` from STANDING_UP, ARMED or RUNNING, ``finish`` from SITTING_DOWN, SAFE_STOP
or PREFLIGHT; in simulation, where the team starts standing, ``start_standing`` PREFLIGHT ->
RUNNING and ``end_standing`` RUNNING -> DONE); any other request raises ``SafetyError``. Every
WBC tick it calls ``check`` with ``SafetyInputs`` and passes its joint commands through
``filter_commands``. In STANDING_UP, ARMED, RUNNING and SITTING_DOWN any fault
(``deploy.safety.checks``) moves to SAFE_STOP, which is latched: only ``finish`` leaves it. From
then on ``filter_commands`` returns pure joint damping (torque 0, kp 0, kd ``damping_kd``,
velocity 0) whatever the controller asks.

Which checks apply: all of them in every active state, except the base height (ARMED and
RUNNING only: the robot lies down before standing up and after sitting down) and a MoCap that
never sent a frame (a fault once the team has been ARMED). In PREFLIGHT, DONE and SAFE_STOP
``check`` still evaluates the faults (``active_faults``) but changes nothing.

Every transition is kept in ``transitions`` and passed to ``on_transition`` (the deploy loop
forwards it to the flight recorder) after the state has changed, so a failing callback cannot
delay a safe stop.
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from core.model.conventions import JOINT_COUNT
from deploy.safety.checks import (
    DeadlineOverrunWindow,
    RobotLimits,
    SolverFailureCounter,
    WbcFailureCounter,
    base_height_fault,
    joint_position_fault,
    joint_velocity_fault,
    mocap_fault,
    non_finite_fault,
    orientation_fault,
    robot_limits,
    torque_fault,
)
from deploy.safety.settings import SupervisorSettings
from drivers.interfaces import JointCommand, RobotMeasurement

__all__ = ["RobotLimits", "SafetyError", "SafetyInputs", "SafetyState", "SafetySupervisor",
           "SupervisorSettings", "Transition", "robot_limits"]


class SafetyState(enum.Enum):
    PREFLIGHT = "preflight"
    STANDING_UP = "standing_up"
    ARMED = "armed"
    RUNNING = "running"
    SITTING_DOWN = "sitting_down"
    SAFE_STOP = "safe_stop"
    DONE = "done"


ACTIVE_STATES = frozenset({SafetyState.STANDING_UP, SafetyState.ARMED, SafetyState.RUNNING,
                           SafetyState.SITTING_DOWN})
_STANDING_STATES = frozenset({SafetyState.ARMED, SafetyState.RUNNING})
# request -> (states it may be made in, state it leads to)
_REQUESTS: dict[str, tuple[frozenset[SafetyState], SafetyState]] = {
    "begin_stand_up": (frozenset({SafetyState.PREFLIGHT}), SafetyState.STANDING_UP),
    "arm": (frozenset({SafetyState.STANDING_UP}), SafetyState.ARMED),
    "begin_run": (frozenset({SafetyState.ARMED}), SafetyState.RUNNING),
    "begin_sit_down": (ACTIVE_STATES - {SafetyState.SITTING_DOWN}, SafetyState.SITTING_DOWN),
    "finish": (frozenset({SafetyState.PREFLIGHT, SafetyState.SITTING_DOWN,
                          SafetyState.SAFE_STOP}), SafetyState.DONE),
    # simulation: the team starts standing and the run ends standing
    "start_standing": (frozenset({SafetyState.PREFLIGHT}), SafetyState.RUNNING),
    "end_standing": (frozenset({SafetyState.RUNNING}), SafetyState.DONE),
}


class SafetyError(ValueError):
    """A transition was requested that the current state does not allow."""


@dataclass(frozen=True)
class Transition:
    time_s: float
    source: SafetyState
    target: SafetyState
    cause: str

    @property
    def text(self) -> str:
        """One line for the flight recorder's events, e.g. ``RUNNING -> SAFE_STOP: ...``."""
        return f"{self.source.name} -> {self.target.name}: {self.cause}"


@dataclass
class SafetyInputs:
    """What the supervisor looks at in one WBC tick (500 Hz)."""

    time_s: float
    run_allowed: bool  # EstopMonitor.is_run_allowed()
    estop_reason: str  # EstopMonitor.reason()
    mocap_age_s: float | None  # None: no frame received yet
    measurements: dict[str, RobotMeasurement]
    link_errors: dict[str, str] = field(default_factory=dict)  # robot -> LinkLostError text
    solver_failed: bool | None = None  # on ticks where an NMPC update finished
    deadline_missed: bool | None = None  # on ticks where an NMPC update finished
    loop_overrun: bool = False  # this tick started more than a loop period late
    # robot -> time [s] its state has not advanced (``deploy.runtime.team_commands``; RUNNING)
    stale_state_s: dict[str, float] = field(default_factory=dict)
    link_notes: dict[str, str] = field(default_factory=dict)  # robot -> its rejected messages


class SafetySupervisor:
    """The state machine over a team whose robots have ``limits`` (one entry per robot)."""

    def __init__(self, settings: SupervisorSettings, limits: list[RobotLimits],
                 on_transition: Callable[[Transition], None] | None = None) -> None:
        names = [robot.name for robot in limits]
        if not names or len(set(names)) != len(names):
            raise ValueError(f"need limits of one or more distinct robots, got {names}")
        self.settings = settings
        self.limits = {robot.name: robot for robot in limits}
        self.on_transition = on_transition
        self.state = SafetyState.PREFLIGHT
        self.transitions: list[Transition] = []
        self.fault = ""  # cause of the safe stop
        self.active_faults: list[str] = []  # found by the latest check, in any state
        self._solver = SolverFailureCounter(settings.max_consecutive_solver_failures)
        self._deadlines = DeadlineOverrunWindow(settings.deadline_overrun_budget,
                                                settings.deadline_window_s)
        self._loop_overruns = DeadlineOverrunWindow(
            settings.loop_overrun_budget, settings.deadline_window_s, "control-loop overruns")
        self.wbc_failures = WbcFailureCounter(settings.max_consecutive_wbc_failures)
        self._has_been_armed = False
        self._started_standing = False

    # --- requested transitions ------------------------------------------------------------
    def begin_stand_up(self, time_s: float) -> None:
        self._request("begin_stand_up", time_s)

    def arm(self, time_s: float) -> None:
        self._request("arm", time_s)

    def begin_run(self, time_s: float) -> None:
        self._request("begin_run", time_s)

    def begin_sit_down(self, time_s: float, cause: str | None = None) -> None:
        """Sit down (a planned end, or with ``cause`` a controlled stop: the braking backup
        held the team and the plans stayed infeasible)."""
        self._request("begin_sit_down", time_s, cause)

    def finish(self, time_s: float) -> None:
        self._request("finish", time_s)

    def start_standing(self, time_s: float) -> None:
        """Simulation only: the team starts standing, so PREFLIGHT -> RUNNING directly."""
        self._request("start_standing", time_s)
        self._started_standing = True

    def end_standing(self, time_s: float) -> None:
        """Simulation only: a run started standing ends standing, RUNNING -> DONE."""
        if not self._started_standing:
            raise SafetyError("cannot end_standing: the run did not start standing (robots "
                              "sit down: begin_sit_down)")
        self._request("end_standing", time_s)

    def trigger_safe_stop(self, time_s: float, cause: str) -> None:
        """Safe stop for a reason found outside the supervisor (operator abort, exception);
        ignored unless in an active state."""
        if self.state in ACTIVE_STATES:
            self._trip(time_s, cause)

    def wbc_ticked(self, time_s: float, name: str, success: bool, status: int) -> None:
        """Robot ``name``'s WBC tick: more than ``max_consecutive_wbc_failures`` failed QPs in
        a row trip the safe stop at once, before the tick's commands are filtered."""
        cause = self.wbc_failures.update(name, success, status)
        if cause is not None:
            self.trigger_safe_stop(time_s, cause)

    def _request(self, request: str, time_s: float, cause: str | None = None) -> None:
        allowed, target = _REQUESTS[request]
        if self.state not in allowed:
            raise SafetyError(
                f"cannot {request} in state {self.state.name}: it is allowed only in "
                f"{', '.join(sorted(s.name for s in allowed))}"
                + (f" (safe stop: {self.fault})" if self.fault else ""))
        self._has_been_armed |= target in (SafetyState.ARMED, SafetyState.RUNNING)
        self._move(time_s, target, cause or f"requested: {request}")

    def _trip(self, time_s: float, cause: str) -> None:
        self.fault = cause
        self._move(time_s, SafetyState.SAFE_STOP, cause)

    def _move(self, time_s: float, target: SafetyState, cause: str) -> None:
        transition = Transition(time_s, self.state, target, cause)
        self.state = target
        self.transitions.append(transition)
        if self.on_transition is not None:
            self.on_transition(transition)

    # --- the per-tick checks --------------------------------------------------------------
    def check(self, inputs: SafetyInputs) -> SafetyState:
        """Evaluate every fault; in an active state, any fault trips the safe stop."""
        self.active_faults = self._faults(inputs)
        if self.active_faults and self.state in ACTIVE_STATES:
            self._trip(inputs.time_s, "; ".join(self.active_faults))
        return self.state

    def _faults(self, inputs: SafetyInputs) -> list[str]:
        settings = self.settings
        faults = []
        if not inputs.run_allowed:
            faults.append(f"e-stop: run not allowed ({inputs.estop_reason})")
        faults += [f"robot link lost: {name}: {message}"
                   for name, message in inputs.link_errors.items()]
        faults += [f"robot state stale: {name}: no new state for {stale_s * 1000:.0f} ms "
                   f"(budget {settings.stale_state_budget_s * 1000:.0f} ms)"
                   + (f"; {inputs.link_notes[name]}" if name in inputs.link_notes else "")
                   for name, stale_s in inputs.stale_state_s.items()
                   if stale_s > settings.stale_state_budget_s + 1e-9]
        mocap = mocap_fault(inputs.mocap_age_s, settings, require_frame=self._has_been_armed)
        if mocap is not None:
            faults.append(mocap)
        standing = self.state in _STANDING_STATES
        for name, limits in self.limits.items():
            measurement = inputs.measurements.get(name)
            if measurement is None:
                if name not in inputs.link_errors:
                    faults.append(f"no measurement of robot {name}")
                continue
            bad_value = non_finite_fault(name, measurement)
            if bad_value is not None:
                faults.append(bad_value)
                continue
            for fault in (orientation_fault(name, measurement, settings),
                          base_height_fault(limits, measurement, settings) if standing else None,
                          joint_velocity_fault(name, measurement, settings),
                          joint_position_fault(limits, measurement, settings)):
                if fault is not None:
                    faults.append(fault)
        for fault in (self._solver.update(inputs.solver_failed),
                      self._deadlines.update(inputs.time_s, inputs.deadline_missed),
                      self._loop_overruns.update(inputs.time_s, inputs.loop_overrun)):
            if fault is not None:
                faults.append(fault)
        return faults

    # --- the commands that may reach the motors -------------------------------------------
    def filter_commands(self, time_s: float, commands: dict[str, JointCommand],
                        measurements: dict[str, RobotMeasurement]) -> dict[str, JointCommand]:
        """The commands to send: in an active state ``commands`` themselves once their torques
        at the measured state are within the limits (else a safe stop); in SAFE_STOP and DONE
        damping for every robot; in PREFLIGHT limp (all-zero) commands for every robot."""
        if self.state in ACTIVE_STATES:
            for name, command in commands.items():
                cause = self._command_fault(name, command, measurements.get(name))
                if cause is not None:
                    self._trip(time_s, cause)
                    break
            else:
                return dict(commands)
        if self.state == SafetyState.PREFLIGHT:
            return {name: JointCommand() for name in self.limits}
        return self.damping_commands()

    def _command_fault(self, name: str, command: JointCommand,
                       measurement: RobotMeasurement | None) -> str | None:
        limits = self.limits.get(name)
        if limits is None:
            return f"command for unknown robot {name!r}; team is {list(self.limits)}"
        if measurement is None:
            return f"commanded torque: {name} cannot be checked without a measurement"
        return torque_fault(limits, command, measurement, self.settings)

    def damping_command(self) -> JointCommand:
        """Pure joint damping: torque 0, kp 0, kd ``damping_kd``, velocity 0."""
        return JointCommand(kd=np.full(JOINT_COUNT, self.settings.damping_kd))

    def damping_commands(self) -> dict[str, JointCommand]:
        """A fresh damping command for every robot of the team."""
        return {name: self.damping_command() for name in self.limits}
