"""The base of every settings model: unknown fields are errors, values are frozen."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

__all__ = ["StrictModel"]


class StrictModel(BaseModel):
    """Base: unknown fields are errors, so a typo in YAML names the bad field."""

    model_config = ConfigDict(extra="forbid", frozen=True)
