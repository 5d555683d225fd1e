"""A run's identity in its log: metadata (versions, revision, machine) and attachments (scenario,
effective settings, robot description files), and the recorder opened with them."""

from __future__ import annotations

import datetime
import importlib.metadata
import os
import platform
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


def run_metadata(scenario: Scenario, backend: str) -> dict[str, str]:
    return {
        "log_format_version": str(LOG_FORMAT_VERSION),
        "porter_version": _version("porter"),
        "git_revision": git_revision(),
        "scenario": scenario.name,
        "seed": str(scenario.seed),
        "backend": backend,
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
                      sinks: list[Sink] | None = None) -> FlightRecorder:
    return FlightRecorder(path, settings, {RUN_METADATA: run_metadata(scenario, backend)},
                          run_attachments(scenario, mpc_settings, wbc_settings), sinks or [])


def default_log_path(scenario: Scenario, directory: Path | str = "runs") -> Path:
    stamp = datetime.datetime.now().strftime("%Y%m%d-%H%M%S")
    return Path(directory) / f"{scenario.name}-{stamp}.mcap"
