"""The NMPC in a process of its own: the same interface as
``deploy.nmpc_runtime.nmpc_thread.NmpcThread`` (``busy``, ``submit``, ``take``, ``close``), so no
NMPC work runs on the loop's interpreter.

In a thread, the NMPC's Python (guesses, parameters, consensus and dual updates, decoding,
~4 ms per 2-agent update) takes the interpreter lock from the 500 Hz loop for whole switch
intervals; in a process it competes for a core only. The process builds the scenario's NMPC
(``deploy.runtime.controller.build_team_mpc``; its ADMM workers, if any, are its children),
answers ``ready``, then takes one ``(update, inputs, with_memory)`` at a time over a pipe and
answers ``(update, plan or None, error, done_monotonic_s, memory)``: plain arrays and
dataclasses, no shared state. ``memory`` is the warm start the update started from, for the
log's keyframes: only with ``with_memory`` (``NmpcProcess.memory_every``), else None (43 kB of
arrays for three agents, pickled, piped and unpickled on the loop's core for nothing).

The loop only polls the pipe (``take`` never blocks). A process that dies, or a pipe that
breaks, yields an error result for the running update (the supervisor counts it as a failed
update) and raises on the next ``submit``: the loop's exception handler then safe-stops.
"""

from __future__ import annotations

import contextlib
import multiprocessing as mp
import signal
import time
from collections.abc import Callable
from multiprocessing.connection import Connection

from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.settings import MpcSettings
from deploy.compute import realtime
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.compute.gc_pauses import freeze_startup_objects
from deploy.compute.process_names import name_this_process
from deploy.config.scenario import Scenario
from deploy.nmpc_runtime.nmpc_thread import NmpcResult
from deploy.runtime.controller import NmpcDecision, build_team_mpc

__all__ = ["NmpcProcess", "NmpcProcessError"]


class NmpcProcessError(RuntimeError):
    """The NMPC process is gone (died, or never started)."""


def _serve(scenario: Scenario, settings: MpcSettings, cache: CompiledCodeCache,
           connection: Connection, nice: int = 0, cpus: list[int] | None = None) -> None:
    # Ctrl-C at the terminal reaches the whole process group: the loop sits the team down,
    # and the NMPC (its ADMM workers inherit the ignored signal) lives until it is told.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    name_this_process("porter-nmpc")
    if nice != 0:  # before the ADMM workers start: they inherit it
        realtime.set_nice(nice)
    realtime.pin(cpus)  # the same
    controller = build_team_mpc(scenario, settings, cache)
    freeze_startup_objects()  # no full collection of the NMPC's objects during updates
    connection.send("ready")
    try:
        while True:
            try:
                message = connection.recv()
            except (EOFError, OSError):  # the loop's process is gone
                return
            if message is None:
                return
            update, inputs, with_memory = message
            memory = controller.memory() if with_memory else None
            plan, error = None, ""
            try:
                plan = controller.update(inputs)
            except Exception as exception:  # the loop's safety decides what a failure means
                error = f"{type(exception).__name__}: {exception}"
            connection.send((update, plan, error, time.monotonic(), memory))
    finally:
        if hasattr(controller, "close"):
            controller.close()


class NmpcProcess:
    """Runs the scenario's NMPC (on ``settings``: ``TeamController.settings``) in a child
    process, one decision at a time.

    ``clock`` is the loop's clock (simulated seconds under a time scale); an update's
    ``wall_s`` is converted to it from the system's monotonic clock, which both processes
    share. Construction blocks until the NMPC is built (``start_timeout_s``: a cold cache
    compiles for minutes). ``nice``: the process's nice value, ``cpus``: the CPUs it (and its
    ADMM workers) may run on, None: any (``deploy.compute.realtime``).
    """

    def __init__(self, scenario: Scenario, settings: MpcSettings, cache: CompiledCodeCache,
                 clock: Callable[[], float] = time.monotonic,
                 start_timeout_s: float = 900.0, nice: int = 0,
                 cpus: list[int] | None = None) -> None:
        self.clock = clock
        context = mp.get_context("spawn")
        self._connection, child = context.Pipe()
        # Not a daemon: daemonic processes may not start the ADMM workers. It ends when told,
        # or when its pipe closes (this process gone).
        self._process = context.Process(
            target=_serve, args=(scenario, settings, cache, child, nice, cpus), name="porter-nmpc")
        self._process.start()
        child.close()
        self._pending: tuple[NmpcDecision, int, float, float] | None = None
        # the updates whose warm start comes back (every memory_every-th: the recording's
        # keyframes, ``RecorderSettings.warm_start_every``; default: every); None: none
        self.memory_every: int | None = 1
        self._closed = False
        try:
            ready = self._connection.poll(start_timeout_s) and self._connection.recv() == "ready"
        except (EOFError, OSError):
            ready = False
        if not ready:
            self.close()
            raise NmpcProcessError("the NMPC process did not start (see its error above)")

    @property
    def busy(self) -> bool:
        """An update is submitted and its result not yet taken."""
        return self._pending is not None

    @property
    def pid(self) -> int | None:
        """The NMPC process's id."""
        return self._process.pid

    @property
    def alive(self) -> bool:
        return self._process.is_alive()

    def submit(self, decision: NmpcDecision, update: int) -> None:
        if self._pending is not None:
            raise RuntimeError("NMPC update submitted while one is running")
        inputs: MpcInputs = decision.inputs
        try:
            every = self.memory_every
            self._connection.send((update, inputs, every is not None and update % every == 0))
        except (BrokenPipeError, OSError) as error:
            raise NmpcProcessError(f"the NMPC process is gone ({error})") from error
        self._pending = (decision, update, self.clock(), time.monotonic())

    def take(self) -> NmpcResult | None:
        """The finished update's result, if any (never blocks)."""
        if self._pending is None:
            return None
        decision, update, submitted, submitted_monotonic = self._pending
        try:
            if not self._connection.poll(0.0):
                if self._process.is_alive():
                    return None
                raise EOFError(f"exit code {self._process.exitcode}")
            answer_update, plan, error, done_monotonic, memory = self._connection.recv()
        except (EOFError, OSError) as failure:
            self._pending = None
            return NmpcResult(decision, update, None, self.clock() - submitted,
                              f"NmpcProcessError: the NMPC process died ({failure})")
        if answer_update != update:  # cannot happen with one update at a time
            raise NmpcProcessError(f"NMPC answered update {answer_update}, expected {update}")
        self._pending = None
        return NmpcResult(decision, update, plan,
                          self._on_clock(submitted, submitted_monotonic, done_monotonic),
                          error, memory)

    def wait(self, timeout_s: float) -> NmpcResult:
        """The submitted update's result, waiting up to ``timeout_s`` for it (the lockstep sim,
        whose simulated time stands still meanwhile); NmpcProcessError if none comes."""
        if self._pending is None:
            raise RuntimeError("no NMPC update submitted")
        with contextlib.suppress(EOFError, OSError):  # a broken pipe: take reports it
            self._connection.poll(timeout_s)
        result = self.take()
        if result is None:
            raise NmpcProcessError(f"the NMPC process did not answer within {timeout_s:.0f} s")
        return result

    def _on_clock(self, submitted: float, submitted_monotonic: float,
                  done_monotonic: float) -> float:
        """Submit-to-done on the loop's clock: the loop clock runs at a constant rate against
        the monotonic clock, so the rate measured since the submit converts the child's time."""
        now, now_monotonic = self.clock(), time.monotonic()
        elapsed_monotonic = now_monotonic - submitted_monotonic
        if elapsed_monotonic <= 0.0:
            return now - submitted
        rate = (now - submitted) / elapsed_monotonic
        return max(done_monotonic - submitted_monotonic, 0.0) * rate

    def close(self, timeout_s: float = 10.0) -> None:
        """Stop the process after the running update (if any) finishes; kill it if it does
        not stop within ``timeout_s``."""
        if self._closed:
            return
        self._closed = True
        with contextlib.suppress(BrokenPipeError, OSError):
            self._connection.send(None)
        self._process.join(timeout_s)
        if self._process.is_alive():
            self._process.kill()
            self._process.join(1.0)
        self._connection.close()

    def kill(self) -> None:
        """Kill the process at once (tests: a dead NMPC)."""
        self._process.kill()
        self._process.join(5.0)

    def __del__(self) -> None:
        with contextlib.suppress(Exception):
            self.close(timeout_s=1.0)
