"""The base of every settings model: unknown fields are errors, values are frozen."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

__all__ = ["StrictModel"]


class StrictModel(BaseModel):
    """Base: unknown fields are errors, so a typo in YAML names the bad field; NaN and
    infinity are refused in every float (``.inf`` would silently switch a timeout or a bound
    off)."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)
