"""Pre-flight checks of ``porter deploy``: is everything there before a robot moves?

One ``PreflightCheck`` per item, each saying what was expected and what was found:
- every link opened (drivers, MoCap sockets, CAN bus) and each Go2's sport mode released;
- every robot heard: a valid state within its link timeout;
- joint states sane: finite, within the URDF limits (+ ``safety.joint_limit_margin_rad``),
  at rest (|dq| below ``preflight.max_joint_velocity_rad_s``), base not tipped over;
- the MoCap server answered and streams every rigid body (robots, payload, obstacles named in
  the config) tracked and fresh;
- the payload where the scenario starts (planar distance to (0, 0) below
  ``preflight.start_tolerance_m``): the reference begins there;
- the e-stop heartbeat present and released; an F/T sample from every robot's sensor.

``evaluate`` is pure (the deploy loop calls it each tick while it waits for the links).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from core.model.conventions import LEG_JOINT_NAMES, PAYLOAD_NAME
from deploy.config.deploy_config import DeployConfig
from deploy.runtime.links import TeamLinks
from deploy.safety.checks import (
    RobotLimits,
    joint_position_fault,
    non_finite_fault,
    orientation_fault,
)
from drivers.interfaces import RobotMeasurement


@dataclass(frozen=True)
class PreflightCheck:
    item: str
    ok: bool
    detail: str


@dataclass(frozen=True)
class PreflightReport:
    checks: list[PreflightCheck]

    @property
    def ok(self) -> bool:
        return all(check.ok for check in self.checks)

    @property
    def failed(self) -> list[PreflightCheck]:
        return [check for check in self.checks if not check.ok]

    def text(self) -> str:
        """One line per check, failures marked ``MISSING``."""
        lines = [f"  [{'ok' if check.ok else 'MISSING'}] {check.item}: {check.detail}"
                 for check in self.checks]
        verdict = "all checks passed" if self.ok else (
            f"{len(self.failed)} of {len(self.checks)} checks failed")
        return "\n".join([f"pre-flight: {verdict}", *lines])


def evaluate(config: DeployConfig, links: TeamLinks, limits: dict[str, RobotLimits],
             measurements: dict[str, RobotMeasurement], link_errors: dict[str, str],
             sport_mode: dict[str, str]) -> PreflightReport:
    """The report for the links' current readings (see the module docstring)."""
    checks = [PreflightCheck("link", False, problem) for problem in links.problems]
    for name, status in sport_mode.items():
        checks.append(PreflightCheck(f"robot {name} sport mode", status == "released", status))
    for name in config.robots:
        if name not in links.drivers:
            continue
        if name in link_errors:
            checks.append(PreflightCheck(f"robot {name} link", False, link_errors[name]))
            continue
        measurement = measurements[name]
        checks.append(PreflightCheck(f"robot {name} link", True,
                                     f"a state received at {measurement.time_s:.3f} s"))
        checks.append(_joint_check(name, measurement, limits[name], config))
    checks += _mocap_checks(config, links)
    checks += _can_checks(config, links)
    return PreflightReport(checks)


def _joint_check(name: str, measurement: RobotMeasurement, limits: RobotLimits,
                 config: DeployConfig) -> PreflightCheck:
    item = f"robot {name} joint states"
    fault = (non_finite_fault(name, measurement)
             or joint_position_fault(limits, measurement, config.safety)
             or orientation_fault(name, measurement, config.safety))
    if fault is not None:
        return PreflightCheck(item, False, fault)
    speeds = np.abs(measurement.velocity_rad_s)
    worst = int(np.argmax(speeds))
    if speeds[worst] > config.preflight.max_joint_velocity_rad_s:
        return PreflightCheck(item, False, f"not at rest: {LEG_JOINT_NAMES[worst]} moves at "
                              f"{speeds[worst]:.2f} rad/s (max "
                              f"{config.preflight.max_joint_velocity_rad_s} rad/s)")
    return PreflightCheck(item, True, "finite, within joint limits, at rest")


def _mocap_checks(config: DeployConfig, links: TeamLinks) -> list[PreflightCheck]:
    client, tracker = links.mocap, links.tracker
    if client is None or tracker is None:
        return []
    mocap = config.mocap
    server = f"{mocap.server_address}:{mocap.command_port}"
    if client.server_info is None:
        return [PreflightCheck("MoCap server", False, f"no answer from NatNet server {server}")]
    checks = [PreflightCheck("MoCap server", True,
                             f"{client.server_info.application_name} at {server}")]
    frame = client.latest()
    if frame is None:
        return [*checks, PreflightCheck("MoCap frames", False, f"no frame on port "
                                        f"{client.receive_port} ({client.counters.packets_rejected}"
                                        " packets rejected)")]
    wanted = tracker.bodies
    missing = [f"{name} (rigid body {body!r})" for name, body in wanted.items()
               if body not in frame.poses]
    seen = sorted(frame.poses)
    checks.append(PreflightCheck(
        "MoCap rigid bodies", not missing,
        f"every one of {len(wanted)} tracked" if not missing else
        f"not tracked: {', '.join(missing)}; tracked: {seen or 'none'}"))
    age_s = client.age_s()
    checks.append(PreflightCheck("MoCap stream", age_s <= mocap.stale_timeout_s,
                                 f"last frame {age_s:.3f} s ago (timeout "
                                 f"{mocap.stale_timeout_s} s), "
                                 f"{client.counters.frames_received} frames"))
    payload = frame.poses.get(config.body_name(PAYLOAD_NAME))
    if payload is not None:
        distance = math.hypot(payload[0][0], payload[0][1])
        tolerance = config.preflight.start_tolerance_m
        checks.append(PreflightCheck(
            "payload at the start", distance <= tolerance,
            f"{distance:.3f} m from the scenario's start (0, 0) (tolerance {tolerance} m)"))
    return checks


def _can_checks(config: DeployConfig, links: TeamLinks) -> list[PreflightCheck]:
    if links.estop is None:
        return []
    where = f"{config.can.interface} channel {config.can.channel!r}"
    status = links.estop.status()
    checks = [PreflightCheck("e-stop heartbeat", status.run_allowed,
                             f"{status.reason} ({where})")]
    if links.force_torque is not None:
        readings = links.force_torque.latest()
        missing = [name for name in config.robots if name not in readings]
        checks.append(PreflightCheck(
            "coupling F/T sensors", not missing,
            f"a sample from each of {len(config.robots)}" if not missing
            else f"no sample from {', '.join(missing)} ({where})"))
    return checks
