"""The team's joint commands for the state's command source (``deploy.safety.run_sequence``):
posture moves, or each robot's WBC on the active plan, held where its state is stale and
clipped where just past a torque limit.

**The stale-state rule** (``StaleStateHold``): a robot whose state stopped advancing is held on its
last fresh command, not driven by torques computed on old data.

A robot's state is fresh when its measurement time (``RobotMeasurement.time_s``, the driver's
receive time) moved since the previous tick. From the ``hold_after_ticks``-th tick in a row
without a new state on, the robot gets the command the WBC computed on its last fresh state
again: the hybrid command's PD (``deploy.runtime.controller.hybrid_command``) holds the joint
targets it integrated, and that is also the command the motors keep if the state comes late
because the robot's side stalled (the simulated world catching up, a firmware hiccup). A stall
longer than ``safety.stale_state_budget_s`` (50 ms) is a fault of its own (``robot state
stale``: the loop hands the supervisor each robot's stale time), and a silence longer than the
robot's link budget (``link_timeout_s``) is a lost link.

Measured in lockstep (``porter sim two_go2``, every second one 18 ms window in which the
motors keep the last command while the controller sees the old state): the fastest calf
reached 26.2 rad/s with a torque-plus-damping command (kp 0) and 15.7 rad/s with the
hybrid command at kp 10 (13.5 rad/s without the windows); deploy/README.md, "Commands
that fail soft".
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import replace

from deploy.runtime.controller import WbcStep
from deploy.safety.checks import RobotLimits, clip_torque
from deploy.safety.posture import PostureMove
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.link_errors import LinkMonitor

__all__ = ["SATURATION_MARGIN", "StaleStateHold", "TeamCommands", "link_notes"]

SATURATION_MARGIN = 0.25  # commands up to 25 % past a torque limit are clipped to it


class TeamCommands:
    """Commands for the robots ``names`` (``limits`` per robot; commanded torques are held to
    ``torque_limit_fraction`` of them); ``saturations`` counts each robot's clipped ticks."""

    def __init__(self, names: list[str], limits: dict[str, RobotLimits],
                 torque_limit_fraction: float, stale: StaleStateHold) -> None:
        self.names, self.limits, self.stale = names, limits, stale
        self.torque_limit_fraction = torque_limit_fraction
        self.saturations = dict.fromkeys(names, 0)

    def posture(self, t: float, moves: dict[str, PostureMove],
                measurements: dict[str, RobotMeasurement]) -> dict[str, JointCommand]:
        """Each move's joint PD command at ``t`` [s]."""
        return {name: self._saturate(name, move.command(t), measurements.get(name))
                for name, move in moves.items()}

    def planned(self, steps: list[WbcStep], measurements: dict[str, RobotMeasurement]
                ) -> tuple[dict[str, JointCommand], list[WbcStep]]:
        """The WBC steps' commands (one step per robot, in ``names`` order), held and clipped;
        the steps carry the commands sent."""
        names = self.names
        # a new step only where held or clipped: dataclasses.replace costs ~10 us a robot
        held = [self.stale.command(n, measurements[n], s.command)
                for n, s in zip(names, steps, strict=True)]
        steps = [step if (command := self._saturate(name, c, measurements[name])) is step.command
                 else replace(step, command=command)
                 for name, step, c in zip(names, steps, held, strict=True)]
        return {n: step.command for n, step in zip(names, steps, strict=True)}, steps

    def _saturate(self, name: str, command: JointCommand, measurement: RobotMeasurement | None
                  ) -> JointCommand:
        """``clip_torque`` at robot ``name``'s limit, counting the clipped ticks."""
        if measurement is None:
            return command
        limit = self.limits[name].torque_nm * self.torque_limit_fraction
        clipped = clip_torque(command, measurement, limit, SATURATION_MARGIN)
        self.saturations[name] += int(clipped is not command)
        return clipped


def link_notes(drivers: Mapping[str, object], names: Iterable[str]) -> dict[str, str]:
    """Per robot of ``names`` whose driver has a ``LinkMonitor`` (``link``) that rejected
    messages since its last valid one: what it rejected, so that a stale state is named by
    its cause (a frozen tick, a bad CRC), not only by its age."""
    notes = {}
    for name in names:
        # Not part of RobotDriver: the simulated robots of the lockstep have no wire link
        link = getattr(drivers.get(name), "link", None)
        if isinstance(link, LinkMonitor) and (note := link.since_valid_note()):
            notes[name] = note
    return notes


class StaleStateHold:
    """Per robot: ticks since its state last advanced, and its last fresh command.

    ``held_ticks`` counts, per robot, the ticks it was held; ``longest_stale_ticks`` the longest
    run of ticks without a new state (held or not)."""

    def __init__(self, names: Iterable[str], hold_after_ticks: int, tick_s: float) -> None:
        if hold_after_ticks < 1:
            raise ValueError(f"hold_after_ticks must be >= 1, got {hold_after_ticks}")
        self.hold_after_ticks = hold_after_ticks
        self.tick_s = tick_s  # the loop's period [s]
        self._time_s: dict[str, float | None] = dict.fromkeys(names)
        self._stale: dict[str, int] = dict.fromkeys(self._time_s, 0)
        self._fresh: dict[str, JointCommand] = {}
        self.held_ticks: dict[str, int] = dict.fromkeys(self._time_s, 0)
        self.longest_stale_ticks: dict[str, int] = dict.fromkeys(self._time_s, 0)

    def command(self, name: str, measurement: RobotMeasurement, computed: JointCommand
                ) -> JointCommand:
        """The command to send robot ``name`` this tick: ``computed`` (the WBC's, on
        ``measurement``) while its state is fresh, else its last fresh command once the state
        has not advanced for ``hold_after_ticks`` ticks."""
        time_s = measurement.time_s
        if time_s != self._time_s[name] or name not in self._fresh:
            self._time_s[name], self._stale[name] = time_s, 0
            self._fresh[name] = computed
            return computed
        stale = self._stale[name] = self._stale[name] + 1
        self.longest_stale_ticks[name] = max(self.longest_stale_ticks[name], stale)
        if stale < self.hold_after_ticks:
            return computed
        self.held_ticks[name] += 1
        return self._fresh[name]

    def stale_s(self) -> dict[str, float]:
        """Per robot whose state did not advance at its last ``command``: for how long [s]
        (stale ticks x ``tick_s``)."""
        return {name: ticks * self.tick_s for name, ticks in self._stale.items() if ticks}

    def holding(self, name: str) -> bool:
        """Whether robot ``name`` got its last fresh command this tick."""
        return self._stale[name] >= self.hold_after_ticks
