"""The faults the simulated world injects into itself (``sim.faults``, the kinds of
``deploy.config.sim_faults`` that are not ``PORTER_FAULTS``), due on its own time line.
Functions of the ``SimWorld`` (``deploy.sim_backend.world``), which alone touches its state."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from deploy.config.sim_faults import PORTER_FAULTS
from drivers.unitree.go2_fake import FakeGo2

if TYPE_CHECKING:
    from deploy.sim_backend.world import SimWorld

__all__ = ["inject_due_faults", "network_faults"]


def inject_due_faults(world: SimWorld, elapsed_s: float) -> None:
    """Inject the world's faults due by ``elapsed_s`` (simulated s since its loop started) and
    end the ``robot_stall`` windows that are over; count each in ``faults_applied``."""
    for name, until_s in list(world.stalled_until.items()):  # robot_stall: publishing again
        if elapsed_s >= until_s:
            del world.stalled_until[name]
            world.silent.discard(name)
    while world.pending_faults and world.pending_faults[0].at_s <= elapsed_s:
        fault = world.pending_faults.pop(0)
        if fault.kind == "robot_stall" and fault.robot is not None:
            assert fault.duration_s is not None  # SimFault requires it
            world.silent.add(fault.robot)
            world.stalled_until[fault.robot] = fault.at_s + fault.duration_s
        if fault.kind == "estop_press" and world.can_node is not None:
            world.can_node.press_estop()
        elif fault.kind == "heartbeat_loss" and world.can_node is not None:
            world.can_node.stop_heartbeat()
        elif fault.kind == "mocap_loss":
            world.mocap_stopped = True
        elif fault.kind == "mocap_frozen":
            world.natnet.frozen = True
        elif fault.kind == "robot_silent" and fault.robot is not None:
            world.silent.add(fault.robot)
        elif fault.kind == "mocap_backwards":
            world.natnet.rewind = True
        elif fault.kind in ("mocap_foreign", "natnet_malformed"):
            world.network_faults.add(fault.kind)
        elif fault.kind == "robot_push" and fault.robot is not None:
            world.simulation.apply_push(fault.robot, np.array([0.0, 300.0, 0.0]), 0.4)
        elif fault.kind == "robot_frozen" and fault.robot is not None:
            world.fakes[fault.robot].frozen = True  # either fake: both resend their last state
        elif fault.kind in ("robot_garbage", "robot_nan", "robot_bad_crc") \
                and fault.robot is not None:
            fake = world.fakes[fault.robot]
            if isinstance(fake, FakeGo2):  # load_deploy_config allows no other
                fake.corrupt = fault.kind.removeprefix("robot_")
        elif fault.kind == "external":
            pass  # done from outside (the drill); from now on the world counts the commands
        elif fault.kind in PORTER_FAULTS:
            pass  # porter injects it itself (deploy.sim_backend.porter_faults); counted
        world.faults_applied.append({"kind": fault.kind, "robot": fault.robot,
                                    "time_s": world.simulation.time_s})

def network_faults(world: SimWorld) -> None:
    """Beside a frame: the same frame from another host, and a packet that is no NatNet
    message (a truncated frame header)."""
    if "mocap_foreign" in world.network_faults and world.natnet.last_packet is not None:
        world.natnet.send_foreign(world.natnet.last_packet)
    if "natnet_malformed" in world.network_faults:
        world.natnet.send_packet(b"\x07\x00\xff\x7f" + bytes(9))
