"""The stale-state rule of the RUNNING loop: a robot whose state stopped advancing is held on its
last fresh command, not driven by torques computed on old data.

A robot's state is fresh when its measurement time (``RobotMeasurement.time_s``, the driver's
receive time) moved since the previous tick. From the ``hold_after_ticks``-th tick in a row
without a new state on, the robot gets the command the WBC computed on its last fresh state
again: the hybrid command's PD (``deploy.runtime.controller.hybrid_command``) holds the joint
targets it integrated, and that is also the command the motors keep if the state comes late
because the robot's side stalled (the simulated world catching up, a firmware hiccup). A stall
longer than ``safety.stale_state_budget_s`` (50 ms) is a fault of its own (``robot state
stale``: the loop hands the supervisor each robot's stale time), and a silence longer than the
robot's link budget (``link_timeout_s``) is a lost link as before.

Measured in lockstep (``porter sim two_go2``, every second one 18 ms window in which the
motors keep the last command while the controller sees the old state): the fastest calf
reached 26.2 rad/s with the former torque-plus-damping command (kp 0) and 15.7 rad/s with the
hybrid command at kp 10 (13.5 rad/s without the windows). README, "Commands that fail soft".
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.link_errors import LinkMonitor

__all__ = ["StaleStateHold", "link_notes"]


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
