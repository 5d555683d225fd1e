"""Graceful stop on Ctrl-C and SIGTERM: the first signal asks the loop to stop at its next tick
(so logs are finished and robots reach a defined state); a second one interrupts at once.

Raising ``KeyboardInterrupt`` from a signal handler at an arbitrary point can leave a lock (e.g.
the recorder queue's) held by the interrupted frame, so the handler only sets a flag.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType


class StopRequest:
    """A flag set by SIGINT/SIGTERM (or ``request``); polled by the loop via ``__call__``."""

    def __init__(self) -> None:
        self.reason = ""
        self._event = threading.Event()

    def __call__(self) -> bool:
        return self._event.is_set()

    def request(self, reason: str) -> None:
        self.reason = self.reason or reason
        self._event.set()

    def _handle(self, signum: int, frame: FrameType | None) -> None:
        if self._event.is_set():  # the second signal: the user insists
            raise KeyboardInterrupt(signal.Signals(signum).name)
        self.request(signal.Signals(signum).name)

    @contextmanager
    def installed(self) -> Iterator[StopRequest]:
        """Handle SIGINT and SIGTERM with this request while the block runs (main thread)."""
        if threading.current_thread() is not threading.main_thread():
            yield self
            return
        previous = {s: signal.signal(s, self._handle) for s in (signal.SIGINT, signal.SIGTERM)}
        try:
            yield self
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)
