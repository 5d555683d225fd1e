"""CompiledCodeCache: compile once, hit afterwards, flags in the key, clean failure on bad C."""

from __future__ import annotations

import shutil
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from deploy.compute.codegen_cache import CompilationError, CompiledCodeCache, default_cache_directory

pytestmark = pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")

NAME = "rosenbrock"
OPTIONS = {"print_time": False, "ipopt.print_level": 0, "ipopt.sb": "yes"}


def rosenbrock() -> dict[str, ca.SX]:
    x = ca.SX.sym("x", 2)
    a = ca.SX.sym("a")
    return {"x": x, "p": a, "f": (a - x[0]) ** 2 + 100 * (x[1] - x[0] ** 2) ** 2}


class Counting:
    """Wraps a C generator and counts its calls."""

    def __init__(self, generate: Callable[[str], None]) -> None:
        self.generate = generate
        self.calls = 0

    def __call__(self, path: str) -> None:
        self.calls += 1
        self.generate(path)


def generator() -> Counting:
    return Counting(ca.nlpsol(f"{NAME}_gen", "ipopt", rosenbrock(), OPTIONS).generate_dependencies)


def test_miss_compiles_then_hit_reuses_and_library_solves(tmp_path: Path) -> None:
    cache = CompiledCodeCache(tmp_path, flags=("-O0",))
    first = generator()
    path = cache.library_for(NAME, "k1", first)
    assert first.calls == 1
    assert Path(path).is_file() and Path(path).parent == tmp_path
    assert Path(path).name.startswith(f"{NAME}_k1_") and path.endswith(".so")
    assert not list(tmp_path.glob(".build_*")), "scratch directory left behind"

    second = generator()
    assert cache.library_for(NAME, "k1", second) == path
    assert second.calls == 0

    solver = ca.nlpsol(NAME, "ipopt", path, OPTIONS)
    result = solver(x0=[-1.0, 1.0], p=2.0)
    np.testing.assert_allclose(np.asarray(result["x"]).ravel(), [2.0, 4.0], atol=1e-6)


def test_flags_and_compiler_are_part_of_the_file_name(tmp_path: Path) -> None:
    o0 = CompiledCodeCache(tmp_path, flags=("-O0",))
    o1 = CompiledCodeCache(tmp_path, flags=("-O1",))
    assert o0.library_path(NAME, "k") != o1.library_path(NAME, "k")
    assert o0.library_path(NAME, "k") == CompiledCodeCache(tmp_path, flags=("-O0",)).library_path(
        NAME, "k")
    assert (CompiledCodeCache(tmp_path, compiler="clang", flags=("-O0",)).library_path(NAME, "k")
            != o0.library_path(NAME, "k"))
    path = o0.library_for(NAME, "k", generator())
    other = generator()
    assert o1.library_for(NAME, "k", other) != path
    assert other.calls == 1
    assert len(list(tmp_path.glob("*.so"))) == 2


def test_invalid_c_raises_with_compiler_output_and_caches_nothing(tmp_path: Path) -> None:
    def broken(path: str) -> None:
        Path(path).write_text("int broken( { this is not C\n")

    cache = CompiledCodeCache(tmp_path, flags=("-O0",))
    with pytest.raises(CompilationError, match="error"):
        cache.library_for(NAME, "bad", broken)
    assert not list(tmp_path.glob("*.so"))
    assert not list(tmp_path.glob(".build_*"))


def test_generator_that_writes_nothing_raises(tmp_path: Path) -> None:
    with pytest.raises(CompilationError, match="wrote no"):
        CompiledCodeCache(tmp_path).library_for(NAME, "empty", lambda path: None)


def test_default_directory_honours_environment(monkeypatch: pytest.MonkeyPatch,
                                               tmp_path: Path) -> None:
    monkeypatch.setenv("PORTER_CACHE_DIR", str(tmp_path / "custom"))
    assert CompiledCodeCache().directory == tmp_path / "custom"
    monkeypatch.delenv("PORTER_CACHE_DIR")
    assert default_cache_directory() == Path(__file__).resolve().parents[3] / ".porter_cache"


def test_concurrent_misses_compile_once(tmp_path: Path) -> None:
    def slow_valid_c(path: str) -> None:
        time.sleep(0.3)  # keep the first builder inside the lock while the second arrives
        Path(path).write_text("double twice(double x) { return 2 * x; }\n")

    counting = Counting(slow_valid_c)
    cache = CompiledCodeCache(tmp_path, flags=("-O0",))
    with ThreadPoolExecutor(max_workers=2) as pool:
        paths = list(pool.map(lambda _: cache.library_for(NAME, "same", counting), range(2)))
    assert paths[0] == paths[1] and Path(paths[0]).is_file()
    assert counting.calls == 1
