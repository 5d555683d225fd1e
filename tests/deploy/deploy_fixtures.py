"""Deploy configs for tests that run ``porter deploy --backend sim``: the shipped ones in slow
motion, so that a run's outcome does not depend on how fast or busy the test machine is."""

from __future__ import annotations

from pathlib import Path

import yaml

from deploy.config.deploy_config import CONFIG_DIR

# The shipped configs run the sim backend at 1.0 (two Go2) and 0.5 (the mixed team) on the
# 2-core development machine, measured alone; CI machines differ 2x in speed and the test
# suite's own process hosts the loop, so end-to-end tests run at 0.2 (every rate, timeout and
# budget stays in simulated seconds: the same run, with time to spare).
TEST_TIME_SCALE = 0.2


def shipped_config_data(name: str, time_scale: float = TEST_TIME_SCALE) -> dict:
    """The shipped deploy config ``name`` as YAML data, its sim backend at ``time_scale``."""
    data = yaml.safe_load((CONFIG_DIR / f"{name}.yaml").read_text())
    data["sim"] = {**data.get("sim", {}), "time_scale": time_scale}
    return data


def write_config(data: dict, path: Path) -> Path:
    """``data`` written as a deploy config at ``path`` (its scenario is a shipped name)."""
    path.write_text(yaml.safe_dump(data))
    return path
