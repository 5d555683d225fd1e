"""NlpSolver: compiled and interpreted derivatives give the same solution; the compiled library
is built once and reused; every solve reports its figures."""

from __future__ import annotations

import time
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from core.model.obstacles import Obstacle
from core.nmpc.nlp_solver import InPlaceCall, NlpSolver
from core.nmpc.settings import MpcSettings, SafetySettings, SolverSettings
from core.nmpc.transport_problem import build_transport_problem
from core.nmpc.warm_start import initial_guess
from deploy.compute.codegen_cache import CompiledCodeCache
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


@pytest.mark.parametrize("solver", ["fatrop", "rti", "ipopt"])
def test_compiled_matches_interpreted_and_is_cached(tmp_path: Path, solver: str) -> None:
    mpc = MpcSettings(horizon_steps=2, safety=SafetySettings(max_obstacles=0),
                      solver=SolverSettings(name=solver, tolerance=1e-8,  # type: ignore[arg-type]
                                                sqp_steps=20))
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


def _local_problem_near_an_obstacle():  # type: ignore[no-untyped-def]
    """Agent 0's local problem (4 stages) with an obstacle 5 cm outside the front robot's
    margin: the problem, the solve arguments from a cold guess, and that guess."""
    model = team(("go2", "go2"))
    # Hard barriers: fatrop relaxes every bound by ~1e-8, which a soft barrier's exact penalty
    # (1e5 per m, scaled) turns into a 1e-3 N difference between the two solvers' optima.
    base = MpcSettings(horizon_steps=4, safety=SafetySettings(max_obstacles=1, obstacle_slots=1,
                                                              soft_barriers=False))
    problem = build_transport_problem(base, agent_count=2, local=True)
    obstacle = Obstacle((1.3, 0.05), (0.0, 0.0), 0.1)
    inputs = inputs_at_start(model, base, [obstacle])
    assert 0 < np.min(inputs.safety_values()) < 0.1
    guess = initial_guess(problem, model, inputs, None, agent=0)
    args = (guess, problem.parameter_vector(
        model, inputs, agent=0, consensus_target=problem.shared_trajectory(guess)),
        *problem.decision_bounds(inputs.contacts, agent=0))
    return problem, args, guess


def test_rti_iterated_converges_to_the_interior_point_solution() -> None:
    """The real-time-iteration path (SQP steps on HPIPM's stage-wise QP) on one fixed local
    problem with an obstacle near a robot: from a cold start it iterates to fatrop's optimum;
    warm, it takes one step, which already moves most of the way there."""
    problem, args, guess = _local_problem_near_an_obstacle()

    def solver(name: str, tolerance: float = 1e-8) -> NlpSolver:
        return NlpSolver(problem.nlp, SolverSettings(  # type: ignore[arg-type]
            name=name, compiled=False, tolerance=tolerance))

    exact = solver("fatrop", tolerance=1e-6).solve(*args, warm_start=False)
    rti = solver("rti")
    converged = rti.solve(*args, warm_start=False)
    one_step = rti.solve(*args)
    assert exact.stats.success and converged.stats.success and one_step.stats.success
    # Converged: by its tolerance, or by a step too small to move (kernel-dependent).
    assert converged.stats.status in ("Solve_Succeeded", "Search_Direction_Becomes_Too_Small")
    assert 1 < converged.stats.iterations < 50
    assert one_step.stats.iterations == 1
    assert converged.stats.constraint_violation < 1e-6
    np.testing.assert_allclose(converged.decision, exact.decision, atol=1e-3)
    assert converged.stats.objective == pytest.approx(exact.stats.objective, rel=1e-5)
    distance = np.linalg.norm(one_step.decision - exact.decision)
    assert distance < 0.05 * np.linalg.norm(guess - exact.decision)


def test_rti_warm_steps_take_their_qp_settings() -> None:
    """``qp_tolerance`` and ``qp_initial_barrier`` reach HPIPM on warm steps: a step whose QP
    stops at a loose tolerance lands measurably farther from the SQP's own converged point
    than one at the default; the cold start (to convergence) does not use them."""
    problem, args, _ = _local_problem_near_an_obstacle()

    def rti(**qp: float) -> NlpSolver:
        return NlpSolver(problem.nlp, SolverSettings(compiled=False, tolerance=1e-8, **qp))

    default, loose = rti(), rti(qp_tolerance=0.5, qp_initial_barrier=100.0)
    converged = default.solve(*args, warm_start=False)
    np.testing.assert_array_equal(loose.solve(*args, warm_start=False).decision,
                                  converged.decision)
    near = default.solve(*args)
    far = loose.solve(*args)
    assert near.stats.success and far.stats.success
    assert (np.linalg.norm(far.decision - converged.decision)
            > 2 * np.linalg.norm(near.decision - converged.decision))
    with pytest.raises(ValueError, match="qp_tolerance"):
        SolverSettings(qp_tolerance=2.0)


def test_in_place_call_equals_a_normal_call_and_keeps_no_state() -> None:
    """``InPlaceCall`` (the solver's buffered evaluation) returns what CasADi's normal call
    returns for the same inputs, bit for bit, over a sequence of different solves (nothing of
    one call leaks into the next); an omitted input is zeros, as in a normal call; solutions
    do not alias the buffer the next solve overwrites."""
    problem, (guess, parameters, lower, upper), _ = _local_problem_near_an_obstacle()
    solver = NlpSolver(problem.nlp, SolverSettings(compiled=False))
    plugin, options = solver._options()
    plain = ca.nlpsol("plain", plugin, problem.nlp.casadi_dict(), options)  # type: ignore[call-overload]
    in_place = InPlaceCall(plain)
    rng = np.random.default_rng(3)
    for trial in range(4):
        values = {"x0": guess + 0.01 * trial * rng.standard_normal(guess.size), "p": parameters,
                  "lbx": lower, "ubx": upper, "lbg": problem.nlp.lower_constraints,
                  "ubg": problem.nlp.upper_constraints}
        if trial % 2:
            values["lam_g0"] = rng.standard_normal(problem.nlp.lower_constraints.size)
        if trial == 3:
            del values["x0"]  # a start at zero
        expected = plain(**values)
        got = in_place(values)
        for name in ("x", "f", "g", "lam_x", "lam_g"):
            np.testing.assert_array_equal(got[name], np.asarray(expected[name]).ravel(),
                                          err_msg=f"trial {trial}: {name}")
        assert in_place.stats()["iter_count"] == plain.stats()["iter_count"] == 1
    first = solver.solve(guess, parameters, lower, upper)
    kept = first.decision.copy()
    solver.solve(guess + 0.05, parameters, lower, upper)
    np.testing.assert_array_equal(first.decision, kept)


def test_a_nan_parameter_fails_the_solve_without_raising_and_poisons_nothing() -> None:
    """A NaN in the parameters is a failed solve (reported, not raised); the solve after it,
    on good inputs through the same in-place buffers, equals a fresh solver's."""
    problem, (guess, parameters, lower, upper), _ = _local_problem_near_an_obstacle()
    solver = NlpSolver(problem.nlp, SolverSettings(compiled=False))
    bad = parameters.copy()
    bad[0] = np.nan
    failed = solver.solve(guess, bad, lower, upper)
    assert not failed.stats.success
    after = solver.solve(guess, parameters, lower, upper)
    fresh = NlpSolver(problem.nlp, SolverSettings(compiled=False)).solve(
        guess, parameters, lower, upper)
    assert after.stats.success
    np.testing.assert_array_equal(after.decision, fresh.decision)
    np.testing.assert_array_equal(after.constraint_multipliers, fresh.constraint_multipliers)
