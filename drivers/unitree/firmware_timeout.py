"""The motor firmware's reaction when low-level commands stop arriving, as the fakes model it.

A Go2 keeps applying its last ``LowCmd`` when the commands stop (the unsafe case, and the
default here: ``timeout_s`` None). With ``timeout_s`` [s of the fake's clock] set, a robot
whose last command is older than that applies joint damping (torque 0, kp 0, kd ``damping_kd``)
until a new command arrives, as a firmware with a command watchdog would.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from core.model.conventions import JOINT_COUNT
from drivers.interfaces import JointCommand

__all__ = ["CommandTimeout"]


class CommandTimeout:
    """When commands stop: hold the last one (``timeout_s`` None) or damp after ``timeout_s``."""

    def __init__(self, timeout_s: float | None = None, damping_kd: float = 2.0) -> None:
        if timeout_s is not None and not timeout_s > 0.0:
            raise ValueError(f"command timeout must be positive or None, got {timeout_s}")
        self.timeout_s = timeout_s
        self.damping_kd = damping_kd
        self.timeouts = 0  # how often the firmware fell back to damping
        self._last_s: float | None = None
        self._damping = False

    def received(self, time_s: float) -> None:
        """A valid command arrived at ``time_s``: it applies, any damping ends."""
        self._last_s, self._damping = time_s, False

    def check(self, time_s: float) -> JointCommand | None:
        """The damping command to apply now, once, when the last command just became older
        than the timeout; None otherwise (hold whatever applies)."""
        if self.timeout_s is None or self._last_s is None or self._damping:
            return None
        if time_s - self._last_s <= self.timeout_s:
            return None
        self._damping = True
        self.timeouts += 1
        return JointCommand(kd=np.full(JOINT_COUNT, self.damping_kd))

    def update(self, newest: JointCommand | None, now_s: Callable[[], float]
               ) -> JointCommand | None:
        """One poll of a fake: ``newest`` (None: no valid command arrived) at ``now_s()``
        (read only when a timeout is modelled). Returns the damping to apply now, if any."""
        if self.timeout_s is None:
            return None
        if newest is not None:
            self.received(now_s())
            return None
        return self.check(now_s())
