"""The house rules, checked on the tree: module sizes, package sizes, who imports whom."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("core", "drivers", "deploy")
MAX_MODULE_LINES = 400
MAX_PACKAGE_MODULES = 16
# What core/ may not import: other layers, the simulator, hardware SDKs, files, sockets.
CORE_FORBIDDEN = {"drivers", "deploy", "mujoco", "cyclonedds", "can", "socket", "mcap",
                  "rerun", "yaml", "os", "pathlib", "subprocess", "multiprocessing"}


def _modules() -> list[Path]:
    return sorted(p for package in PACKAGES for p in (ROOT / package).rglob("*.py")
                  if "_pb2" not in p.name)


def _imported(path: Path) -> set[str]:
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.add(node.module)
    return names


def test_no_module_over_400_lines() -> None:
    long = {str(p.relative_to(ROOT)): n for p in _modules()
            if (n := len(p.read_text().splitlines())) > MAX_MODULE_LINES}
    assert not long


def test_no_subpackage_over_about_15_modules() -> None:
    packages = {p.parent for p in _modules()}
    crowded = {str(d.relative_to(ROOT)): n for d in packages
               if (n := len([p for p in d.glob("*.py") if p.name != "__init__.py"]))
               > MAX_PACKAGE_MODULES}
    assert not crowded


@pytest.mark.parametrize("package", ["core", "drivers", "deploy"])
def test_every_package_says_what_it_is_and_exports_with_all(package: str) -> None:
    for init in (ROOT / package).rglob("__init__.py"):
        if "messages" in init.parts or "tests" in init.parts:
            continue
        tree = ast.parse(init.read_text())
        assert ast.get_docstring(tree), init
        top = init.parent in {ROOT / p for p in PACKAGES}
        targets = [t for n in tree.body if isinstance(n, ast.Assign) for t in n.targets]
        targets += [n.target for n in tree.body if isinstance(n, ast.AnnAssign)]
        has_all = any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets)
        assert top or has_all, f"{init}: no __all__"


def test_core_imports_no_io_and_drivers_import_no_deploy() -> None:
    offending = []
    for path in _modules():
        layer = path.relative_to(ROOT).parts[0]
        for name in _imported(path):
            top = name.split(".")[0]
            if layer == "core" and top in CORE_FORBIDDEN:
                offending.append(f"{path.relative_to(ROOT)} imports {name}")
            if layer == "drivers" and top == "deploy":
                offending.append(f"{path.relative_to(ROOT)} imports {name}")
    assert not offending


def test_the_robot_drivers_load_without_mujoco() -> None:
    """``drivers.unitree`` (Go2 DDS, A1 UDP, their conventions and fakes), ``drivers.natnet``
    and ``drivers.can`` with mujoco made unimportable."""
    code = """
import importlib, pkgutil, sys
sys.modules["mujoco"] = None  # any import of mujoco now raises ImportError
import drivers.interfaces, drivers.link_errors
for package in ("drivers.unitree", "drivers.natnet", "drivers.can"):
    module = importlib.import_module(package)
    for info in pkgutil.iter_modules(module.__path__, package + "."):
        importlib.import_module(info.name)
    for name in module.__all__:
        getattr(module, name)
assert "mujoco" not in sys.modules or sys.modules["mujoco"] is None
print("ok")
"""
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "ok"


def test_mujoco_really_is_blocked_by_the_check() -> None:
    """The check above can fail: the MuJoCo drivers do not load without mujoco."""
    code = ('import sys; sys.modules["mujoco"] = None\n'
            'import drivers.mujoco.simulation')
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                            text=True, timeout=120)
    assert result.returncode != 0 and "import of mujoco halted" in result.stderr
