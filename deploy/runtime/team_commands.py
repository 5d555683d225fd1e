"""The team's joint commands for the state's command source (``deploy.safety.run_sequence``):
posture moves, or each robot's WBC on the active plan, held where its state is stale
(``deploy.runtime.stale_state``) and clipped where just past a torque limit."""

from __future__ import annotations

from dataclasses import replace

from deploy.runtime.controller import WbcStep
from deploy.runtime.stale_state import StaleStateHold
from deploy.safety.checks import RobotLimits, clip_torque
from deploy.safety.posture import PostureMove
from drivers.interfaces import JointCommand, RobotMeasurement

__all__ = ["SATURATION_MARGIN", "TeamCommands"]

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
