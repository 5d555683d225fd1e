"""Deploy-config defaults that mirror facts held elsewhere."""

from __future__ import annotations

from deploy.config.deploy_config import MocapConfig
from drivers.natnet import protocol


def test_mocap_defaults_are_natnets_well_known_ports() -> None:
    """The config spells NatNet's defaults itself (configuration imports no driver)."""
    mocap = MocapConfig()
    assert (mocap.command_port, mocap.data_port, mocap.multicast_group) == (
        protocol.COMMAND_PORT, protocol.DATA_PORT, protocol.MULTICAST_GROUP)
