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


def test_package_faces_list_their_modules_and_re_export_nothing() -> None:
    """Every ``__init__`` below the top level lists exactly its modules and subpackages in
    ``__all__`` and imports nothing (no lazy ``__getattr__``)."""
    wrong = []
    for package in PACKAGES:
        for init in sorted((ROOT / package).rglob("__init__.py")):
            if init.parent == ROOT / package or "messages" in init.parts:
                continue
            tree = ast.parse(init.read_text())
            names = [ast.literal_eval(n.value) for n in tree.body if isinstance(n, ast.Assign)
                     and any(isinstance(t, ast.Name) and t.id == "__all__" for t in n.targets)]
            present = {p.stem for p in init.parent.glob("*.py") if not p.name.startswith("__")
                       and "_pb2" not in p.name}
            present |= {d.name for d in init.parent.iterdir() if (d / "__init__.py").exists()}
            imports = [n for n in tree.body
                       if isinstance(n, ast.Import | ast.ImportFrom | ast.FunctionDef)]
            if not names or set(names[0]) != present or imports:
                wrong.append(str(init.relative_to(ROOT)))
    assert not wrong


_ROBOT_PATH = ("deploy.cli.porter", "deploy.cli.deploy_command", "deploy.runtime.loop",
               "deploy.runtime.links", "deploy.safety.watchdog", "deploy.nmpc_runtime.nmpc_process")
_CONFIGURATION = ("deploy.config.deploy_config", "deploy.config.scenario",
                  "deploy.config.sim_faults", "deploy.config.files")
# driver implementations (the interfaces module is the contract every layer shares)
_DRIVER_IMPLEMENTATIONS = ("drivers.unitree", "drivers.natnet", "drivers.can", "drivers.mujoco",
                           "drivers.robot_descriptions", "mujoco", "cyclonedds", "can")


def _loaded_after(modules: tuple[str, ...], watched: tuple[str, ...]) -> list[str]:
    code = (f"import importlib, sys\nfor m in {modules!r}: importlib.import_module(m)\n"
            f"print(sorted(m for m in sys.modules if m.split('.')[0] in {watched!r} or "
            f"any(m == w or m.startswith(w + '.') for w in {watched!r})))")
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                            text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    return list(ast.literal_eval(result.stdout.strip()))


def test_the_robot_path_imports_no_mujoco() -> None:
    """``porter deploy`` on robots (its command, loop, links, watchdog, NMPC process) loads no
    MuJoCo: the sim backend loads when ``--backend sim`` asks for it."""
    assert _loaded_after(_ROBOT_PATH, ("mujoco", "drivers.mujoco")) == []
    assert _loaded_after(("deploy.sim_backend.world",), ("mujoco",)) != []  # the check can fail


def test_configuration_imports_no_driver() -> None:
    """Loading and validating configs loads no driver, no DDS and no simulator."""
    assert _loaded_after(_CONFIGURATION, _DRIVER_IMPLEMENTATIONS) == []
    assert _loaded_after(("deploy.safety.watchdog",), _DRIVER_IMPLEMENTATIONS) != []
