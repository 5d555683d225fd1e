"""On-disk cache of compiled CasADi-generated code (implements ``core.nmpc.nlp_solver.NlpCompiler``).

Compiling the derivatives of a transport NLP takes tens of seconds, so each library is built
once per (problem, solver options, CasADi version, compiler, flags) and reused by every later
process. A library is ``<directory>/{name}_{key}_{flags-hash}.so``: the flag hash makes a change
of compiler or flags build a new library instead of reusing one built differently.

Safe under concurrency: a per-library ``fcntl`` lock makes two processes that miss the same key
compile it once, and the library is compiled in a temporary directory inside the cache and
moved into place with ``os.replace``, so nobody ever loads a half-written file.

Default flags ``-O1``, measured on the 2-agent ADMM local problem (fatrop, gcc 12, 408
variables, 17 iterations; interpreted CasADi: 42 ms per solve):

    flags   compile [s]   median solve [ms]
    -O0         20             21.9
    -O1         53             12.6
    -O2        131             12.5
    -Os         81             13.2

``-O1`` gets the ``-O2`` solve time for 40 % of its compile time.

The cache also owns the BLAS kernels under the solvers: before its first library is handed
out in a process it loads BLASFEO built for this CPU (``deploy.compute.blas_kernels``), so the
fatrop and hpipm plugins CasADi loads afterwards use it instead of CasADi's generic build.
"""

from __future__ import annotations

import contextlib
import fcntl
import hashlib
import os
import subprocess
import tempfile
import threading
from collections.abc import Callable, Iterator
from pathlib import Path

from deploy.compute.blas_kernels import BlasKernels, load_blas_kernels

DEFAULT_FLAGS: tuple[str, ...] = ("-O1",)
CACHE_DIR_VARIABLE = "PORTER_CACHE_DIR"
_SOURCE_NAME = "generated.c"  # CasADi writes only bare C-identifier names into the cwd
_STDERR_TAIL = 3000
_cwd_lock = threading.Lock()  # chdir is process-wide: one generation at a time per process


class CompilationError(RuntimeError):
    """Generating or compiling the C code of a cached library failed."""


def default_cache_directory() -> Path:
    """``$PORTER_CACHE_DIR`` if set, else ``<repo root>/.porter_cache`` (git-ignored)."""
    configured = os.environ.get(CACHE_DIR_VARIABLE)
    if configured:
        return Path(configured).expanduser()
    return Path(__file__).resolve().parents[2] / ".porter_cache"


@contextlib.contextmanager
def _working_directory(path: Path) -> Iterator[None]:
    with _cwd_lock:
        previous = os.getcwd()
        os.chdir(path)
        try:
            yield
        finally:
            os.chdir(previous)


class CompiledCodeCache:
    """Builds shared libraries from generated C on a miss, returns the cached path on a hit."""

    def __init__(
        self,
        directory: Path | None = None,
        compiler: str = "gcc",
        flags: tuple[str, ...] = DEFAULT_FLAGS,
        blas_target: str = "auto",
        kernel_directory: Path | None = None,
    ) -> None:
        """``blas_target``: ``auto`` (this CPU's BLASFEO kernels), ``generic`` (CasADi's) or a
        BLASFEO target name; the kernels live in ``kernel_directory`` (default: the shared
        cache, so caches in scratch directories do not rebuild them)."""
        self.directory = Path(directory) if directory is not None else default_cache_directory()
        self.compiler = compiler
        self.flags = tuple(flags)
        self.blas_target = blas_target
        self.kernel_directory = (Path(kernel_directory) if kernel_directory is not None
                                 else default_cache_directory())
        self._kernels: tuple[int, BlasKernels] | None = None  # (process id, kernels)
        build = "\0".join((compiler, *self.flags)).encode()
        self._flags_hash = hashlib.sha256(build).hexdigest()[:8]

    def blas_kernels(self) -> BlasKernels:
        """The BLASFEO this process's solvers use, loaded on the first call in each process
        (a cache pickled into a worker process loads it there again)."""
        if self._kernels is None or self._kernels[0] != os.getpid():
            kernels = load_blas_kernels(self.kernel_directory, self.blas_target, self.compiler)
            self._kernels = (os.getpid(), kernels)
        return self._kernels[1]

    def library_path(self, name: str, key: str) -> Path:
        """Where the library for (``name``, ``key``) with this compiler and flags lives."""
        return self.directory / f"{name}_{key}_{self._flags_hash}.so"

    def library_for(self, name: str, key: str, generate_c: Callable[[str], None]) -> str:
        """Path of the compiled library for ``key``; generates and compiles it on a miss.

        ``generate_c`` is called with a bare file name and the working directory set to a fresh
        temporary directory, because ``Function.generate_dependencies`` (its usual value) only
        writes into the current directory and rejects paths.
        """
        self.blas_kernels()  # before any solver plugin (and its BLASFEO) is loaded
        library = self.library_path(name, key)
        if library.exists():
            return str(library)
        self.directory.mkdir(parents=True, exist_ok=True)
        lock_path = library.with_suffix(".lock")
        with open(lock_path, "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file is closed
            if not library.exists():  # another process may have built it while we waited
                self._build(library, generate_c)
        return str(library)

    def _build(self, library: Path, generate_c: Callable[[str], None]) -> None:
        with tempfile.TemporaryDirectory(prefix=".build_", dir=self.directory) as scratch:
            build = Path(scratch)
            try:
                with _working_directory(build):
                    generate_c(_SOURCE_NAME)
            except Exception as error:
                raise CompilationError(f"generating C for {library.name} failed: {error}") from error
            source = build / _SOURCE_NAME
            if not source.exists():
                raise CompilationError(f"the C generator for {library.name} wrote no {source.name}")
            output = build / "tmp.so"
            command = [self.compiler, "-fPIC", "-shared", *self.flags, str(source),
                       "-o", str(output), "-lm"]
            try:
                result = subprocess.run(command, capture_output=True, text=True, check=False)
            except OSError as error:
                raise CompilationError(f"cannot run compiler {self.compiler!r}: {error}") from error
            if result.returncode != 0 or not output.exists():
                raise CompilationError(
                    f"{' '.join(command)} failed with exit code {result.returncode} while "
                    f"building {library.name}:\n{result.stderr[-_STDERR_TAIL:]}"
                )
            os.replace(output, library)  # same filesystem: atomic
