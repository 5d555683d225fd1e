"""BLASFEO built for this CPU under CasADi's structure-exploiting solvers (fatrop, hpipm).

CasADi's wheel ships BLASFEO built for its GENERIC target (plain C, one 4x4 kernel). fatrop and
hpipm link it dynamically by its soname ``libblasfeo.so.0``. porter builds the same library,
BLASFEO 0.1.4.2 (vendored in ``deploy/native/blasfeo``, BSD-2), for this CPU once into the
cache, and loads it with ``RTLD_GLOBAL`` before the first solver plugin is loaded: the dynamic
linker then resolves the plugins' ``libblasfeo.so.0`` to the loaded library (a ``DT_NEEDED``
entry matches an object already loaded under that soname) and CasADi's copy is never opened.

Measured on the 2-agent ADMM local NLP (fatrop, same iterates): 15.8 -> 7.6 ms median per
local solve on an AVX2 machine. Only targets with BLASFEO's 4-row panels are chosen: the
panel height is compiled into fatrop's element accessors, so a target with another panel
height (AVX-512) would silently corrupt its matrices.

A failed build or an unsupported CPU is not an error: the solvers keep CasADi's generic
kernels, and ``BlasKernels.reason`` says why (porter's benches print it).
"""

from __future__ import annotations

import contextlib
import ctypes
import fcntl
import logging
import os
import platform
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

BLASFEO_VERSION = "0.1.4.2"
SONAME = "libblasfeo.so.0"
SOURCE_DIRECTORY = Path(__file__).resolve().parents[1] / "native" / "blasfeo"
GENERIC = "GENERIC"
LOADED_FIRST = "another BLASFEO was loaded first"
_LOG = logging.getLogger(__name__)
_STDERR_TAIL = 2000


@dataclass(frozen=True)
class BlasKernels:
    """Which BLASFEO the solvers of this process use."""

    target: str  # a BLASFEO target name, or GENERIC (CasADi's own library)
    library: Path | None  # porter's build, None for CasADi's
    reason: str = ""  # why GENERIC, when it is

    @property
    def optimized(self) -> bool:
        return self.library is not None

    @property
    def preempted(self) -> bool:
        """Generic only because CasADi's BLASFEO was loaded into this process before porter's
        build: a fresh process would get the optimized one."""
        return self.reason.startswith(LOADED_FIRST)


def cpu_target(machine: str, cpu_flags: set[str]) -> str | None:
    """The BLASFEO target for a CPU (``platform.machine()``, its feature flags), or None.

    Only 4-row-panel targets (see the module docstring): AVX2+FMA -> Haswell kernels, AVX ->
    Sandy Bridge kernels, 64-bit ARM with NEON -> Cortex-A57 kernels (Jetson-class boards)."""
    if machine in ("x86_64", "AMD64"):
        if {"avx2", "fma"} <= cpu_flags:
            return "X64_INTEL_HASWELL"
        if "avx" in cpu_flags:
            return "X64_INTEL_SANDY_BRIDGE"
        return None
    if machine in ("aarch64", "arm64") and ({"asimd", "neon"} & cpu_flags):
        return "ARMV8A_ARM_CORTEX_A57"
    return None


def host_cpu_flags(cpuinfo: Path = Path("/proc/cpuinfo")) -> set[str]:
    """Feature flags of this machine's first CPU (x86 ``flags``, ARM ``Features``)."""
    try:
        text = cpuinfo.read_text()
    except OSError:
        return set()
    for line in text.splitlines():
        key, _, value = line.partition(":")
        if key.strip() in ("flags", "Features"):
            return set(value.split())
    return set()


def loaded_blasfeo() -> Path | None:
    """Path of the ``libblasfeo`` mapped into this process, if any (Linux)."""
    with contextlib.suppress(OSError), open("/proc/self/maps") as maps:
        for line in maps:
            path = line.split()[-1]
            if "/libblasfeo.so" in path:
                return Path(path)
    return None


def library_path(directory: Path, target: str, compiler: str) -> Path:
    return directory / f"blasfeo-{BLASFEO_VERSION}-{target}-{Path(compiler).name}" / SONAME


def build_blasfeo(directory: Path, target: str, compiler: str = "gcc",
                  source: Path = SOURCE_DIRECTORY) -> Path:
    """Build ``libblasfeo.so.0`` for ``target`` into ``directory`` once (locked, atomic move);
    return its path. Raises ``RuntimeError`` with the build's error output on failure."""
    library = library_path(directory, target, compiler)
    if library.exists():
        return library
    library.parent.mkdir(parents=True, exist_ok=True)
    with open(library.parent / "build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # two processes missing it build it once
        if library.exists():
            return library
        with tempfile.TemporaryDirectory(prefix=".build_", dir=library.parent) as scratch:
            tree = Path(scratch) / "blasfeo"
            shutil.copytree(source, tree)
            # git keeps no empty folders: the Makefile moves its output into lib/.
            (tree / "lib").mkdir(exist_ok=True)
            jobs = str(max(1, os.cpu_count() or 1))
            command = ["make", "-s", f"-j{jobs}", "shared_library", f"TARGET={target}",
                       f"CC={compiler}"]
            try:
                result = subprocess.run(command, cwd=tree, capture_output=True, text=True,
                                        check=False)
            except OSError as error:
                raise RuntimeError(f"cannot run make for BLASFEO: {error}") from error
            built = tree / "lib" / "libblasfeo.so"
            if result.returncode != 0 or not built.exists():
                raise RuntimeError(f"building BLASFEO {target} failed (exit "
                                   f"{result.returncode}):\n{result.stderr[-_STDERR_TAIL:]}")
            os.replace(built, library)
    return library


def load_blas_kernels(directory: Path, target: str = "auto", compiler: str = "gcc"
                      ) -> BlasKernels:
    """Make this process's solvers use BLASFEO built for ``target`` (``auto``: this CPU's,
    ``generic``: CasADi's own). Call before the first fatrop/hpipm solver is created."""
    if target == "generic":
        return BlasKernels(GENERIC, None, "generic kernels requested")
    chosen = target if target != "auto" else cpu_target(platform.machine(), host_cpu_flags())
    if chosen is None:
        return BlasKernels(GENERIC, None, f"no optimized BLASFEO target for this CPU "
                                          f"({platform.machine()})")
    library = library_path(directory, chosen, compiler)
    present = loaded_blasfeo()
    if present is not None and present.resolve() != library.resolve():
        return BlasKernels(GENERIC, None, f"{LOADED_FIRST} ({present})")
    try:
        library = build_blasfeo(directory, chosen, compiler)
        ctypes.CDLL(str(library), mode=os.RTLD_NOW | os.RTLD_GLOBAL)
    except (RuntimeError, OSError) as error:
        _LOG.warning("using CasADi's generic BLASFEO: %s", error)
        return BlasKernels(GENERIC, None, str(error).splitlines()[0])
    mapped = loaded_blasfeo()
    if mapped is None or mapped.resolve() != library.resolve():
        return BlasKernels(GENERIC, None, f"loaded BLASFEO is {mapped}, not {library}")
    return BlasKernels(chosen, library)
