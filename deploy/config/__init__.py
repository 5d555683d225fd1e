"""Typed scenario and deploy configs, their YAML loading and the shipped files.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.config.deploy_config": ["Go2Link", "A1Link", "MocapConfig", "CanConfig",
        "PostureConfig", "RatesConfig", "PreflightConfig", "SimConfig", "DeployConfig",
        "config_path", "load_deploy_config"],
    "deploy.config.sim_faults": ["SimFault"],
    "deploy.config.files": ["ConfigError", "load_settings", "validate_settings"],
    "deploy.config.scenario": ["ObstacleSpec", "PushSpec", "DisturbanceSettings", "ReferenceSpec",
        "PayloadSpec", "ControllerSpec", "GaitSpec", "Scenario", "shipped_scenarios",
        "scenario_path", "load_scenario"],
}
__all__ = ["A1Link", "CanConfig", "ConfigError", "ControllerSpec", "DeployConfig",
           "DisturbanceSettings", "GaitSpec", "Go2Link", "MocapConfig", "ObstacleSpec",
           "PayloadSpec", "PostureConfig", "PreflightConfig", "PushSpec", "RatesConfig",
           "ReferenceSpec", "Scenario", "SimConfig", "SimFault", "config_path",
           "load_deploy_config", "load_scenario", "load_settings", "scenario_path",
           "shipped_scenarios", "validate_settings"]
__getattr__ = lazy_exports(__name__, _SOURCES)
