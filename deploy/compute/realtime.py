"""Real-time scheduling of the control loop's thread: Linux ``SCHED_FIFO`` while it runs.

Under the default (``SCHED_OTHER``) policy the 500 Hz loop shares its core with whatever else
is runnable (the NMPC's process, the sim backend's world, the recorder): measured on a 2-core
machine at time scale 1.0, the loop kept 0.82-0.90 of its rate with a wake-up jitter p99 of
3.3-4.8 ms; with the loop's thread at ``SCHED_FIFO`` it kept 0.99 with 1.2-1.7 ms (README).
A ``SCHED_FIFO`` thread runs as soon as it is runnable and until it blocks; the loop sleeps
every period, and the kernel's real-time throttling (``sched_rt_runtime_us``) leaves the rest
of the machine a share even if it did not.

Only the loop's own thread: Linux schedules threads, and a thread or process started by a
``SCHED_FIFO`` thread inherits its policy (the NMPC and world processes, the recorder's
thread are started before the loop runs, and stay at the normal policy). ``check`` probes the
permission before any of them exists; ``applied`` sets the priority for the loop and restores
the thread's previous policy after it (the caller, e.g. a test process, goes on as before).

Setting it needs ``CAP_SYS_NICE`` (root) or an ``RLIMIT_RTPRIO`` at least the priority
(``ulimit -r``, ``rtprio`` in ``/etc/security/limits.conf``).

The NMPC's process gets a nice value instead (``nmpc.nice``): a share of the CPU before the
normal-priority processes (the sim's world), not the loop's first claim. At ``SCHED_FIFO`` it
took the world's time (the simulated robots fell behind: safe stops); at nice -10 it kept
45-57 Hz against 40-51 Hz at nice 0 in alternating runs at time scale 1.0 (README). A nice
value below the current one needs ``CAP_SYS_NICE`` or ``RLIMIT_NICE`` (``nice`` in
limits.conf).

CPU affinity (``rates.loop_cpu``, ``nmpc.cpus``): the loop's process on one core while it
runs, the NMPC's process (and its ADMM workers) on others, the sim's world on ``sim.world_cpus``
(or where the kernel puts it). At time scale 1.0 on two cores the NMPC kept 53-54 Hz with 27-35 late
updates in 10 s against 50-51 Hz and 56-65 unpinned (update p99 17-18 against 23 ms): it no
longer migrates after the loop's wake-ups (README). Every thread of the loop's process goes
to the loop's core, not only the loop's: a helper thread (MoCap client, CAN, the recorder)
that holds the interpreter lock on the NMPC's core waits there behind the NMPC's nice -10
process, and the loop waits for the lock meanwhile (a watchdog take-over, 25 ms without a
tick, was seen once so). On the loop's core a lock holder runs as soon as the loop blocks:
WBC jitter p99 0.95-1.08 -> 0.24-0.26 ms, tick p99 1.96-2.34 -> 1.63-1.67 ms (README).
Pinning to CPUs this process may use needs no privilege.

The watchdog's process (``deploy.safety.watchdog``) runs at the loop's priority: its 2 ms
watch must not wait behind the NMPC's process (nice -10) or the world, and at equal priority
Linux places it on a core that is not running the loop (the same priority needs no further
permission than the loop's).
"""

from __future__ import annotations

import contextlib
import os
import threading
from collections.abc import Iterable, Iterator

__all__ = ["RealtimePriorityError", "applied", "check", "check_cpus", "check_nice", "pin", "pinned",
           "set_nice", "set_priority", "set_process_cpus", "set_process_priority"]

SETTING = "rates.loop_priority"
NICE_SETTING = "nmpc.nice"


class RealtimePriorityError(RuntimeError):
    """The loop's real-time priority was asked for and cannot be set."""


def _why_not(priority: int, error: OSError | AttributeError) -> str:
    reason = error.strerror if isinstance(error, OSError) else "no SCHED_FIFO on this system"
    return (f"{SETTING}: cannot run the loop at SCHED_FIFO priority {priority} ({reason}); "
            "allow it (root, CAP_SYS_NICE on the interpreter, or `ulimit -r` / limits.conf "
            f"rtprio >= {priority}) or set {SETTING}: null for normal scheduling")


def _current() -> tuple[int, int]:
    return os.sched_getscheduler(0), os.sched_getparam(0).sched_priority


def _set(policy: int, priority: int) -> None:
    os.sched_setscheduler(0, policy, os.sched_param(priority))


def check(priority: int | None) -> str | None:
    """Whether this thread may run at ``SCHED_FIFO`` ``priority`` (set and restored at once):
    None if it may (or ``priority`` is None), else why not (the message names the setting)."""
    try:
        previous = set_priority(priority)
    except RealtimePriorityError as error:
        return str(error)
    if previous is not None:
        _set(*previous)
    return None


def set_priority(priority: int | None) -> tuple[int, int] | None:
    """The calling thread at ``SCHED_FIFO`` ``priority`` from now on (nothing if None); its
    previous (policy, priority), or None if nothing changed; ``RealtimePriorityError`` if it
    cannot be set."""
    if priority is None:
        return None
    try:
        previous = _current()
        _set(os.SCHED_FIFO, priority)
    except (OSError, AttributeError) as error:
        raise RealtimePriorityError(_why_not(priority, error)) from error
    return previous


def set_process_priority(priority: int, setting: str) -> str | None:
    """Every thread of this process at ``SCHED_FIFO`` ``priority`` (the sim's world: its
    physics thread and the DDS threads that carry its states); None once set, else why not
    (naming ``setting``). Threads started later inherit it from the thread that starts them."""
    try:
        for task in os.listdir("/proc/self/task"):
            with contextlib.suppress(ProcessLookupError):  # a thread that ended meanwhile
                os.sched_setscheduler(int(task), os.SCHED_FIFO, os.sched_param(priority))
    except (OSError, AttributeError) as error:
        reason = error.strerror if isinstance(error, OSError) else "no SCHED_FIFO here"
        return (f"{setting}: cannot run at SCHED_FIFO priority {priority} ({reason}); allow "
                f"it (root, CAP_SYS_NICE, `ulimit -r` >= {priority}) or set {setting}: null")
    return None


def set_process_cpus(cpus: Iterable[int], setting: str) -> str | None:
    """Every thread of this process on ``cpus`` only (the sim's world: its physics thread and
    the DDS threads that carry its states); None once set, else why not (naming ``setting``).
    Threads started later inherit it from the thread that starts them."""
    problem = check_cpus(cpus, setting)
    if problem is None:
        for tid in _threads():
            with contextlib.suppress(OSError):  # a thread that ended meanwhile
                os.sched_setaffinity(tid, set(cpus))
    return problem


@contextlib.contextmanager
def applied(priority: int | None) -> Iterator[None]:
    """The calling thread at ``SCHED_FIFO`` ``priority`` inside the block (nothing if None),
    its previous policy and priority after; ``RealtimePriorityError`` if it cannot be set."""
    previous = set_priority(priority)
    try:
        yield
    finally:
        if previous is not None:
            _set(*previous)


def _why_not_nice(nice: int, error: OSError) -> str:
    return (f"{NICE_SETTING}: cannot run the NMPC at nice {nice} ({error.strerror}); allow it "
            "(root, CAP_SYS_NICE on the interpreter, or limits.conf nice <= "
            f"{nice}) or set {NICE_SETTING}: 0")


def check_nice(nice: int) -> str | None:
    """Whether a process started from this one may take nice value ``nice`` (probed on this
    thread and restored): None if it may, else why not (the message names the setting)."""
    current = os.getpriority(os.PRIO_PROCESS, 0)
    if nice >= current:
        return None  # a higher nice value (less CPU) is always allowed
    try:
        os.setpriority(os.PRIO_PROCESS, 0, nice)
    except OSError as error:
        return _why_not_nice(nice, error)
    os.setpriority(os.PRIO_PROCESS, 0, current)  # raising it back is always allowed
    return None


def set_nice(nice: int) -> None:
    """This thread (and what it starts) at nice value ``nice``; ``RealtimePriorityError`` if
    not allowed."""
    try:
        os.setpriority(os.PRIO_PROCESS, 0, nice)
    except OSError as error:
        raise RealtimePriorityError(_why_not_nice(nice, error)) from error


def check_cpus(cpus: Iterable[int] | None, setting: str) -> str | None:
    """Whether this process may run on every CPU of ``cpus``: None if it may (or ``cpus`` is
    None), else why not (the message names ``setting`` and the CPUs it may use)."""
    if cpus is None:
        return None
    available = os.sched_getaffinity(0)
    missing = sorted(set(cpus) - available)
    if not missing:
        return None
    return (f"{setting}: CPU {', '.join(map(str, missing))} is not available to this process "
            f"(it may run on {', '.join(map(str, sorted(available)))}); name those or set "
            f"{setting}: null")


def pin(cpus: Iterable[int] | None) -> None:
    """The calling thread (and what it starts from now on) on ``cpus`` only (nothing if
    None); ``RealtimePriorityError`` if not allowed."""
    if cpus is None:
        return
    try:
        os.sched_setaffinity(0, set(cpus))
    except OSError as error:
        raise RealtimePriorityError(f"cannot run on CPUs {sorted(cpus)}: {error.strerror}"
                                    ) from error


def _threads() -> list[int]:
    """This process's thread ids (Linux: /proc/self/task; elsewhere none is listed)."""
    try:
        return [int(tid) for tid in os.listdir("/proc/self/task")]
    except OSError:
        return []


@contextlib.contextmanager
def pinned(cpus: Iterable[int] | None) -> Iterator[None]:
    """This process, every thread of it, on ``cpus`` inside the block (nothing if None): the
    calling thread (``RealtimePriorityError`` if not allowed) and the helper threads already
    running (MoCap client, CAN, DDS, recorder; a thread that ended meanwhile is skipped);
    threads started inside inherit it. After it each thread is back on the CPUs it had."""
    if cpus is None:
        yield
        return
    wanted = set(cpus)
    mine = os.sched_getaffinity(0)
    pin(wanted)
    me, moved = threading.get_native_id(), {}
    for tid in _threads():
        if tid == me:
            continue
        try:
            affinity = os.sched_getaffinity(tid)
            os.sched_setaffinity(tid, wanted)
        except OSError:  # it ended meanwhile
            continue
        moved[tid] = affinity
    try:
        yield
    finally:
        os.sched_setaffinity(0, mine)
        for tid, affinity in moved.items():
            with contextlib.suppress(OSError):
                os.sched_setaffinity(tid, affinity)
