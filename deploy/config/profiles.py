"""Controller profiles: shipped ``MpcSettings`` files, ``paper`` (the paper's NLP exactly,
solved to convergence) and ``porter`` (porter's defaults), found by name or by path."""

from __future__ import annotations

from pathlib import Path

from core.nmpc.settings import MpcSettings
from deploy.config.files import ConfigError, load_settings

PROFILE_DIR = Path(__file__).resolve().parent / "profiles"
# The profiles every ``porter paper`` claim runs unless told otherwise: porter's, the paper's.
DEFAULT_PROFILES = ("porter", "paper")


def shipped_profiles() -> list[str]:
    """Names (file stems) of the profiles in ``deploy/config/profiles/``, sorted."""
    return sorted(path.stem for path in PROFILE_DIR.glob("*.yaml"))


def profile_path(name_or_path: Path | str) -> Path:
    """The file of a shipped profile's name, or ``name_or_path`` itself if it is a path."""
    text = str(name_or_path)
    if isinstance(name_or_path, Path) or text.endswith((".yaml", ".yml")) or "/" in text \
            or Path(text).is_file():
        return Path(name_or_path)
    if text not in shipped_profiles():
        raise ConfigError(f"unknown profile {text!r}; shipped profiles: "
                          f"{', '.join(shipped_profiles())} (or give the path of a YAML file)")
    return PROFILE_DIR / f"{text}.yaml"


def load_profile(name_or_path: Path | str) -> tuple[str, MpcSettings]:
    """(label, settings): a shipped profile's name is its label, a file's stem is."""
    path = profile_path(name_or_path)
    return path.stem, load_settings(path, MpcSettings)
