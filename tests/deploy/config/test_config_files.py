"""YAML settings: overrides merge over defaults; bad input names the file and the field."""

from __future__ import annotations

from pathlib import Path

import pytest

from core.model.team_settings import TeamSettings
from core.nmpc.settings import MpcSettings
from deploy.config.files import ConfigError, load_settings


def test_overrides_merge_over_defaults(tmp_path: Path) -> None:
    path = tmp_path / "mpc.yaml"
    path.write_text("horizon_steps: 10\nadmm:\n  iterations: 3\n  rho_state: 0.0\n")
    settings = load_settings(path, MpcSettings)
    assert settings.horizon_steps == 10
    assert settings.admm.iterations == 3 and settings.admm.rho_state == 0.0
    assert settings.admm.rho_wrench == MpcSettings().admm.rho_wrench
    assert settings.cost == MpcSettings().cost


@pytest.mark.parametrize(
    ("text", "field"),
    [
        ("admm:\n  iterations: 0\n", "admm.iterations"),
        ("safety:\n  alpha_one: 0.4\n", "safety.alpha_one"),
        ("solver:\n  name: snopt\n", "solver.name"),
        ("horizon_steps: many\n", "horizon_steps"),
    ],
)
def test_invalid_field_is_named(tmp_path: Path, text: str, field: str) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(ConfigError, match=f"bad.yaml: {field}"):
        load_settings(path, MpcSettings)


def test_unknown_robot_type_in_team_file(tmp_path: Path) -> None:
    path = tmp_path / "team.yaml"
    path.write_text("agents:\n  - name: a\n    robot_type: spot\n"
                    "    coupling_point_in_payload_m: [0.5, 0, 0]\n")
    with pytest.raises(ConfigError, match=r"agents\.0\.robot_type.*go2, a1"):
        load_settings(path, TeamSettings)


def test_unreadable_and_malformed_files(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="cannot read"):
        load_settings(tmp_path / "missing.yaml", MpcSettings)
    broken = tmp_path / "broken.yaml"
    broken.write_text("admm: [1, 2\n")
    with pytest.raises(ConfigError, match="not valid YAML"):
        load_settings(broken, MpcSettings)
    listing = tmp_path / "list.yaml"
    listing.write_text("- 1\n- 2\n")
    with pytest.raises(ConfigError, match="expected a mapping"):
        load_settings(listing, MpcSettings)
