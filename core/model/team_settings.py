"""Typed team settings: the payload, the robots and where each is coupled to it (SI units)."""

from __future__ import annotations

from pydantic import Field, field_validator

from core.model.strict_model import StrictModel

__all__ = ["ROBOT_TYPES", "AgentSettings", "PayloadSettings", "TeamSettings"]


class PayloadSettings(StrictModel):
    """Modelled payload: a box of uniform density unless an inertia is given."""

    mass_kg: float = Field(5.0, gt=0)
    size_m: tuple[float, float, float] = (1.0, 0.5, 0.05)
    inertia_kg_m2: tuple[float, float, float] | None = None

    def principal_inertia_kg_m2(self) -> tuple[float, float, float]:
        if self.inertia_kg_m2 is not None:
            return self.inertia_kg_m2
        a, b, c = self.size_m
        m = self.mass_kg
        return (m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12)


ROBOT_TYPES = ("go2", "a1")


class AgentSettings(StrictModel):
    """One robot of the team and where it is coupled to the payload."""

    name: str
    robot_type: str = "go2"
    coupling_point_in_payload_m: tuple[float, float, float]
    coupling_point_in_robot_m: tuple[float, float, float] = (0.0, 0.0, 0.1)

    @field_validator("robot_type")
    @classmethod
    def _known_robot(cls, value: str) -> str:
        if value not in ROBOT_TYPES:
            raise ValueError(f"unknown robot type {value!r}; available: {', '.join(ROBOT_TYPES)}")
        return value


class TeamSettings(StrictModel):
    agents: list[AgentSettings] = Field(min_length=1)
    payload: PayloadSettings = PayloadSettings()

    @field_validator("agents")
    @classmethod
    def _unique_names(cls, agents: list[AgentSettings]) -> list[AgentSettings]:
        names = [a.name for a in agents]
        if len(set(names)) != len(names):
            raise ValueError(f"agent names must be unique, got {names}")
        return agents
