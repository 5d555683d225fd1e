"""What the one control loop (``deploy.runtime.loop``) is given: its settings, the watchdog's
heartbeat and a simulation's hooks."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from deploy.config.deploy_config import PostureConfig, RatesConfig
from deploy.runtime.controller import WbcStep
from deploy.safety.settings import SupervisorSettings

__all__ = ["Heartbeat", "LoopHooks", "LoopSettings"]


@dataclass(frozen=True)
class LoopSettings:
    """The loop's rates, fault thresholds and postures (``porter deploy``: from its config)."""

    rates: RatesConfig
    safety: SupervisorSettings
    posture: PostureConfig
    preflight_timeout_s: float = 5.0


class Heartbeat(Protocol):
    """The watchdog outside this process (``deploy.safety.watchdog``)."""

    def beat(self) -> None: ...
    @property
    def tripped(self) -> bool: ...
    def disarm(self) -> None: ...


class LoopHooks(Protocol):
    """What a simulation measures in the loop (``deploy.runtime.sim_run``)."""

    def before_tick(self, t: float) -> None: ...
    def wbc_stepped(self, steps: list[WbcStep]) -> None: ...
