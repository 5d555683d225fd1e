"""A run's identity in its log: metadata (versions, revision, machine) and attachments (scenario,
effective settings, robot description files), and the recorder opened with them."""

from __future__ import annotations

import datetime
import importlib.metadata
import itertools
import os
import platform
import re
import socket
import subprocess
from pathlib import Path

import yaml

from core.locomotion.settings import WbcSettings
from core.nmpc.settings import MpcSettings
from deploy.config.scenario import Scenario
from deploy.recording.flight_recorder import FlightRecorder, RecorderSettings, Sink
from deploy.recording.log_format import (
    LOG_FORMAT_VERSION,
    MPC_SETTINGS_ATTACHMENT,
    RUN_METADATA,
    SCENARIO_ATTACHMENT,
    WBC_SETTINGS_ATTACHMENT,
)
from deploy.recording.robot_scene import ROBOT_SCENE, LinkTransforms, robot_scene
from drivers.robot_descriptions import robot_description

PACKAGES = ("casadi", "pin", "mujoco", "numpy", "daqp", "mcap", "protobuf", "rerun-sdk",
            "example-robot-data")
REPOSITORY = Path(__file__).resolve().parents[2]


def git_revision() -> str:
    """The checkout's commit (with ``-dirty`` when files differ), or ``unknown``."""
    try:
        revision = subprocess.run(["git", "describe", "--always", "--dirty"], cwd=REPOSITORY,
                                  capture_output=True, text=True, timeout=5, check=True)
        return revision.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def _version(package: str) -> str:
    try:
        return importlib.metadata.version(package)
    except importlib.metadata.PackageNotFoundError:
        return "absent"


def run_metadata(scenario: Scenario, backend: str, blas_kernels: str) -> dict[str, str]:
    """The run's identity; ``blas_kernels``: the BLASFEO target its solvers ran on (a replay
    agrees bit for bit only on the same kernels, see ``porter regress``)."""
    return {
        "log_format_version": str(LOG_FORMAT_VERSION),
        "porter_version": _version("porter"),
        "git_revision": git_revision(),
        "scenario": scenario.name,
        "seed": str(scenario.seed),
        "backend": backend,
        "blas_kernels": blas_kernels,
        "controller_mode": scenario.controller.mode,
        "robots": ",".join(agent.name for agent in scenario.team),
        "started_utc": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
        "python": platform.python_version(),
        "machine": f"{platform.system()} {platform.machine()}, {os.cpu_count()} CPUs, "
                   f"{socket.gethostname()}",
        **{f"package.{name}": _version(name) for name in PACKAGES},
    }


def run_attachments(scenario: Scenario, mpc_settings: MpcSettings,
                    wbc_settings: WbcSettings) -> dict[str, bytes]:
    """Scenario, effective NMPC and WBC settings as YAML, and each robot type's URDF."""
    def dump(model: object) -> bytes:
        return yaml.safe_dump(model.model_dump(mode="json"), sort_keys=False).encode()  # type: ignore[attr-defined]

    attachments = {SCENARIO_ATTACHMENT: dump(scenario),
                   MPC_SETTINGS_ATTACHMENT: dump(mpc_settings),
                   WBC_SETTINGS_ATTACHMENT: dump(wbc_settings)}
    for robot_type in sorted({agent.robot_type for agent in scenario.team}):
        path = robot_description(robot_type).urdf_path
        attachments[f"robots/{path.name}"] = path.read_bytes()
    return attachments


def open_run_recorder(path: Path | str, scenario: Scenario, mpc_settings: MpcSettings,
                      wbc_settings: WbcSettings, backend: str,
                      settings: RecorderSettings | None = None,
                      sinks: list[Sink] | None = None,
                      extra_attachments: dict[str, bytes] | None = None, *,
                      blas_kernels: str) -> FlightRecorder:
    """A flight recorder on ``path`` with the run's metadata and attachments (plus
    ``extra_attachments``, e.g. the deploy config); ``blas_kernels`` as in ``run_metadata``."""
    attachments = {**run_attachments(scenario, mpc_settings, wbc_settings),
                   **(extra_attachments or {})}
    robot_types = {agent.name: agent.robot_type for agent in scenario.team}
    recorder = FlightRecorder(path, settings,
                              {RUN_METADATA: run_metadata(scenario, backend, blas_kernels)},
                              attachments, sinks or [], [LinkTransforms(robot_types)])
    # the robots' shapes once, at run time 0, for Foxglove (deploy.recording.robot_scene)
    recorder.log(ROBOT_SCENE, robot_scene(robot_types), 0.0)
    return recorder


def safe_file_stem(name: str) -> str:
    """``name`` as a file-name stem that stays in its folder: letters, digits, ``.``, ``_``
    and ``-`` only (anything else, path separators included, becomes ``_``), no leading dot."""
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", name).lstrip(".")
    return stem or "run"


def default_log_path(scenario: Scenario, directory: Path | str = "runs",
                     prefix: str = "") -> Path:
    """A new log file ``<directory>/<prefix><scenario>-<date>-<time>[-n].mcap``, created
    empty here so that no other run (in this process or another) gets the same name: two runs
    in the same second get ``-2``, ``-3``, ... and nothing is ever overwritten. The scenario
    name is sanitized (``safe_file_stem``): it cannot leave ``directory``."""
    folder = Path(directory)
    folder.mkdir(parents=True, exist_ok=True)
    stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
    stem = f"{prefix}{safe_file_stem(scenario.name)}-{stamp}"
    for attempt in itertools.count(1):
        path = folder / (f"{stem}.mcap" if attempt == 1 else f"{stem}-{attempt}.mcap")
        try:
            os.close(os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644))
        except FileExistsError:
            continue
        return path
    raise AssertionError("unreachable")
