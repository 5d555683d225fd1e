"""NlpSolver: compiled and interpreted derivatives give the same solution; the compiled library
is built once and reused; every solve reports its figures."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

from core.nmpc.nlp_solver import NlpSolver
from core.nmpc.settings import MpcSettings, SafetySettings, SolverSettings
from core.nmpc.transport_problem import build_transport_problem
from core.nmpc.warm_start import initial_guess
from deploy.runtime.codegen_cache import CompiledCodeCache
from tests.core.controller_fixtures import inputs_at_start, team


class CountingCache(CompiledCodeCache):
    def __init__(self, directory: Path) -> None:
        super().__init__(directory)
        self.generated = 0

    def library_for(self, name, key, generate_c):  # type: ignore[no-untyped-def]
        def counted(path: str) -> None:
            self.generated += 1
            generate_c(path)

        return super().library_for(name, key, counted)


@pytest.mark.parametrize("solver", ["fatrop", "ipopt"])
def test_compiled_matches_interpreted_and_is_cached(tmp_path: Path, solver: str) -> None:
    mpc = MpcSettings(horizon_steps=2, safety=SafetySettings(max_obstacles=0),
                      solver=SolverSettings(name=solver, tolerance=1e-8))  # type: ignore[arg-type]
    model = team(("go2",))
    problem = build_transport_problem(mpc, agent_count=1)
    inputs = inputs_at_start(model, mpc)
    args = (initial_guess(problem, model, inputs, None, agent=None),
            problem.parameter_vector(model, inputs), *problem.decision_bounds(inputs.contacts))
    cache = CountingCache(tmp_path)
    start = time.perf_counter()
    compiled = NlpSolver(problem.nlp, mpc.solver, cache)
    first_build_s = time.perf_counter() - start
    assert compiled.compiled and cache.generated == 1
    interpreted = NlpSolver(problem.nlp, mpc.solver.model_copy(update={"compiled": False}))
    a, b = compiled.solve(*args), interpreted.solve(*args)
    assert a.stats.success and b.stats.success
    assert a.stats.iterations > 0 and a.stats.wall_time_s > 0
    assert a.stats.constraint_violation < 1e-6
    np.testing.assert_allclose(a.decision, b.decision, atol=1e-5)
    start = time.perf_counter()
    again = NlpSolver(problem.nlp, mpc.solver, cache)
    assert cache.generated == 1  # second start reuses the library
    assert time.perf_counter() - start < first_build_s
    np.testing.assert_allclose(again.solve(*args).decision, a.decision, atol=1e-9)


def test_reference_configuration_is_never_compiled(tmp_path: Path) -> None:
    mpc = MpcSettings(horizon_steps=2, safety=SafetySettings(max_obstacles=0),
                      solver=SolverSettings(name="ipopt-reference"))
    problem = build_transport_problem(mpc, agent_count=1)
    cache = CountingCache(tmp_path)
    assert not NlpSolver(problem.nlp, mpc.solver, cache).compiled
    assert cache.generated == 0
