"""The one controller protocol every team NMPC keeps: centralized
(``core.nmpc.centralized_mpc``), ADMM coordinated here (``core.admm.admm_mpc``) and ADMM run by
the agents (``core.admm.admm_peer_mpc``). Callers hold a ``TeamMpc`` and never ask which."""

from __future__ import annotations

from typing import Protocol

from core.model.team import TeamModel
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.mpc_plan import MpcPlan
from core.nmpc.settings import MpcSettings
from core.nmpc.warm_start import ControllerMemory

__all__ = ["TeamMpc"]


class TeamMpc(Protocol):
    """A receding-horizon team NMPC: ``update`` is one MPC step from ``inputs``."""

    team: TeamModel
    settings: MpcSettings

    def update(self, inputs: MpcInputs) -> MpcPlan: ...

    def reset(self) -> None:
        """Forget the warm start (the next update starts cold)."""

    def memory(self) -> ControllerMemory:
        """The warm start the next update will use."""
        ...

    def restore(self, memory: ControllerMemory) -> None:
        """Continue from ``memory`` (e.g. a logged keyframe)."""

    def close(self) -> None:
        """Release worker processes or agents (nothing for an in-process solver)."""
