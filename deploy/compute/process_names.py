"""Names of porter's processes as the operating system shows them (``ps``, ``top``, psutil).

A spawned process is called ``python3.11`` by the system whatever name multiprocessing gave
it, and only its parent knows that name. ``name_this_process`` sets the Linux thread name of
the calling process's main thread (``/proc/<pid>/comm``, 15 characters), so that every porter
process is recognisable by its role, grandchildren included (the ADMM workers of the NMPC
process); ``deploy.compute.cpu_meter`` reads it back. Elsewhere it does nothing.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import sys

__all__ = ["COMM_LENGTH", "name_this_process"]

COMM_LENGTH = 15  # the kernel keeps this many characters of a task name
_PR_SET_NAME = 15


def name_this_process(name: str) -> None:
    """Set this process's system name to ``name`` (at most ``COMM_LENGTH`` characters)."""
    if len(name) > COMM_LENGTH:
        raise ValueError(f"process name {name!r} is longer than {COMM_LENGTH} characters")
    if not sys.platform.startswith("linux"):
        return
    with contextlib.suppress(OSError, AttributeError):
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        libc.prctl(_PR_SET_NAME, ctypes.c_char_p(name.encode()), 0, 0, 0)
