"""Errors of the robot links (DDS, UDP) and the bookkeeping every link shares.

``LinkMonitor`` counts received and rejected messages (by reason), remembers when the last
valid one arrived on the driver's clock [s] and turns "nothing valid for ``timeout_s``" into
``LinkLostError``; a valid message after a loss counts as a reconnection. The drivers own the
transport; this module owns no socket and does no I/O.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field


class DriverError(RuntimeError):
    """A robot driver cannot do what was asked (bad configuration, transport failure)."""


class LinkLostError(DriverError):
    """No valid state arrived within the link timeout: the robot is not (or no longer) heard."""


@dataclass
class LinkMonitor:
    """Health of one incoming stream: counters, time of the last valid message, link loss.

    ``clock`` returns seconds on a monotonic clock (injected so that tests and replay can step
    it); ``timeout_s`` is the longest silence tolerated before ``check`` raises.
    ``description`` names the stream in error messages (e.g. ``"go2 rt/lowstate on domain 0"``).
    """

    description: str
    timeout_s: float
    clock: Callable[[], float]
    received: int = 0
    rejected: Counter[str] = field(default_factory=Counter)
    rejected_since_valid: Counter[str] = field(default_factory=Counter)  # since the last accept
    reconnections: int = 0
    last_receive_time_s: float | None = None
    # reason -> what to tell the operator when nothing valid ever arrived and messages were
    # rejected for that reason (e.g. a CRC the firmware may not fill in)
    never_valid_hints: dict[str, str] = field(default_factory=dict)
    _lost: bool = False

    def __post_init__(self) -> None:
        if self.timeout_s <= 0.0:
            raise DriverError(f"link timeout must be positive, got {self.timeout_s} s")

    @property
    def rejected_total(self) -> int:
        """Messages rejected for any reason."""
        return sum(self.rejected.values())

    def accept(self) -> float:
        """Count one valid message; returns its receive time [s] on ``clock``."""
        now_s = self.clock()
        self.received += 1
        self.last_receive_time_s = now_s
        if self.rejected_since_valid:
            self.rejected_since_valid.clear()
        if self._lost:
            self._lost = False
            self.reconnections += 1
        return now_s

    def reject(self, reason: str) -> None:
        """Count one message rejected for ``reason`` (a short tag, e.g. ``"crc"``)."""
        self.rejected[reason] += 1
        self.rejected_since_valid[reason] += 1

    def since_valid_note(self) -> str:
        """What arrived since the last valid message and was rejected, for a fault's text
        ("" when nothing was)."""
        rejected = self.rejected_since_valid
        return f"rejected since its last valid state: {dict(rejected)}" if rejected else ""

    def check(self) -> None:
        """Raise ``LinkLostError`` when no valid message arrived yet, or none within the last
        ``timeout_s``."""
        last_s = self.last_receive_time_s
        silent_s = None if last_s is None else self.clock() - last_s
        if silent_s is not None and silent_s <= self.timeout_s:
            return
        self._lost = silent_s is not None  # the first message ever is no reconnection
        heard = ("no valid state received yet" if silent_s is None
                 else f"last valid state {silent_s:.3f} s ago")
        hints = [hint for reason, hint in self.never_valid_hints.items()
                 if silent_s is None and self.rejected[reason]]
        raise LinkLostError(
            f"{self.description}: {heard} (timeout {self.timeout_s} s; received {self.received},"
            f" rejected {dict(self.rejected) or 0})" + "".join(f"; {h}" for h in hints))
