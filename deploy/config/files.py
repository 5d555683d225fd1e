"""Settings from YAML: parse, merge over the typed defaults, validate, and report bad fields.

The typed models (``core.nmpc.settings``) carry the defaults; a YAML file overrides any subset.
Errors name the file and the dotted path of each bad field.
"""

from __future__ import annotations

from pathlib import Path
from typing import TypeVar

import yaml
from pydantic import BaseModel, ValidationError

Model = TypeVar("Model", bound=BaseModel)


class ConfigError(ValueError):
    """A configuration file cannot be read or does not validate."""


def load_settings(path: Path | str, model: type[Model]) -> Model:
    """Validate the YAML mapping in ``path`` as ``model`` (missing fields keep their defaults)."""
    path = Path(path)
    try:
        data = yaml.safe_load(path.read_text()) or {}
    except OSError as error:
        raise ConfigError(f"{path}: cannot read ({error.strerror})") from None
    except yaml.YAMLError as error:
        raise ConfigError(f"{path}: not valid YAML ({error})") from None
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: expected a mapping at the top level, got {type(data).__name__}")
    return validate_settings(data, model, source=str(path))


def validate_settings(data: dict, model: type[Model], source: str = "settings") -> Model:
    try:
        return model.model_validate(data)
    except ValidationError as error:
        problems = "; ".join(
            f"{'.'.join(str(part) for part in item['loc']) or '<root>'}: {item['msg']}"
            for item in error.errors()
        )
        raise ConfigError(f"{source}: {problems}") from None
