"""BLASFEO for this CPU: target choice, build failures, and fatrop really running on it."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from deploy.compute.blas_kernels import (
    GENERIC,
    SONAME,
    build_blasfeo,
    cpu_target,
    host_cpu_flags,
    load_blas_kernels,
)

ROOT = Path(__file__).resolve().parents[3]


def test_targets_have_four_row_panels_and_match_the_cpu() -> None:
    assert cpu_target("x86_64", {"avx", "avx2", "fma", "avx512f"}) == "X64_INTEL_HASWELL"
    assert cpu_target("x86_64", {"avx", "sse3"}) == "X64_INTEL_SANDY_BRIDGE"
    assert cpu_target("x86_64", {"sse3"}) is None
    assert cpu_target("aarch64", {"fp", "asimd"}) == "ARMV8A_ARM_CORTEX_A57"
    assert cpu_target("riscv64", set()) is None


def test_cpu_flags_are_read_from_cpuinfo(tmp_path: Path) -> None:
    x86 = tmp_path / "x86"
    x86.write_text("processor\t: 0\nflags\t\t: fpu avx avx2 fma\n\nprocessor\t: 1\nflags\t: fpu\n")
    arm = tmp_path / "arm"
    arm.write_text("processor\t: 0\nFeatures\t: fp asimd evtstrm\n")
    assert host_cpu_flags(x86) == {"fpu", "avx", "avx2", "fma"}
    assert host_cpu_flags(arm) == {"fp", "asimd", "evtstrm"}
    assert host_cpu_flags(tmp_path / "missing") == set()


def test_generic_request_keeps_casadis_library(tmp_path: Path) -> None:
    kernels = load_blas_kernels(tmp_path, "generic")
    assert kernels.target == GENERIC and not kernels.optimized and kernels.reason


def test_failed_build_raises_with_its_output_and_leaves_no_library(tmp_path: Path) -> None:
    with pytest.raises(RuntimeError, match="BLASFEO"):
        build_blasfeo(tmp_path, "X64_INTEL_HASWELL", compiler="no-such-compiler-cc")
    assert not list(tmp_path.rglob(SONAME))
    assert not list(tmp_path.rglob(".build_*"))


_PROBE = """
import json, sys
import casadi as ca
import numpy as np
from deploy.compute.blas_kernels import loaded_blasfeo
from deploy.compute.codegen_cache import CompiledCodeCache
kernels = CompiledCodeCache(blas_target=sys.argv[1]).blas_kernels()
# A small optimal-control problem in fatrop's stage form: double integrator to the origin.
n, x, u, g, w = 10, [], [], [], []
for k in range(n + 1):
    x.append(ca.SX.sym(f"x{k}", 2)); w.append(x[-1])
    if k < n:
        u.append(ca.SX.sym(f"u{k}", 1)); w.append(u[-1])
f = 0
for k in range(n):
    g.append(x[k + 1] - ca.vertcat(x[k][0] + 0.1 * x[k][1], x[k][1] + 0.1 * u[k]))
    if k == 0:
        g.append(x[0] - ca.DM([1.0, 0.0]))
    g.append(u[k] - 0.2 * ca.sin(x[k][0]))  # a nonlinear path constraint, bounded below
    f += ca.sumsqr(x[k + 1]) + 0.1 * ca.sumsqr(u[k])
lbg, ubg, eq = [], [], []
for k in range(n):
    lbg += [0, 0] + ([0, 0] if k == 0 else []) + [-2.0]
    ubg += [0, 0] + ([0, 0] if k == 0 else []) + [np.inf]
    eq += [True, True] + ([True, True] if k == 0 else []) + [False]
solver = ca.nlpsol("s", "fatrop", {"x": ca.vertcat(*w), "f": f, "g": ca.vertcat(*g)},
                   {"structure_detection": "manual", "nx": [2] * (n + 1), "nu": [1] * n + [0],
                    "ng": [3] + [1] * (n - 1) + [0], "N": n, "equality": eq,
                    "fatrop.print_level": 0, "print_time": False})
result = solver(x0=0, lbg=lbg, ubg=ubg)
print(json.dumps({"target": kernels.target, "library": str(loaded_blasfeo()),
                  "success": bool(solver.stats()["success"]),
                  "x": np.asarray(result["x"]).ravel().tolist()}))
"""


def _probe(target: str) -> dict:
    done = subprocess.run([sys.executable, "-c", _PROBE, target], cwd=ROOT, capture_output=True,
                          text=True, check=True, timeout=600)
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.skipif(shutil.which("gcc") is None or shutil.which("make") is None,
                    reason="needs gcc and make")
def test_fatrop_runs_on_the_loaded_kernels_and_agrees_with_casadis() -> None:
    optimized, generic = _probe("auto"), _probe("generic")
    assert generic["target"] == GENERIC and "casadi" in generic["library"]
    assert optimized["success"] and generic["success"]
    if optimized["target"] == GENERIC:  # a CPU without a 4-row-panel target
        assert cpu_target(*_machine()) is None
    else:
        # fatrop's plugin was loaded after the kernels, and resolved to porter's build.
        assert optimized["library"].endswith(f"{optimized['target']}-gcc/{SONAME}")
    assert optimized["x"] == pytest.approx(generic["x"], abs=1e-7)


def _machine() -> tuple[str, set[str]]:
    import platform

    return platform.machine(), host_cpu_flags()
