"""Faults the sim backend injects (``sim.faults`` of a deploy config): the world's, and those
porter's own process injects into itself (``deploy.sim_backend.porter_faults``)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from core.model.strict_model import StrictModel

__all__ = ["GO2_FAULTS", "PORTER_FAULTS", "ROBOT_FAULTS", "TIMED_FAULTS", "SimFault"]

ROBOT_FAULTS = ("robot_silent", "robot_stall", "robot_frozen", "robot_garbage", "robot_nan",
                "robot_bad_crc", "robot_push")
TIMED_FAULTS = ("robot_stall", "plan_late")  # the faults with a duration_s (and only they)
# the Go2 fake's wire faults (robot_frozen: either fake)
GO2_FAULTS = ("robot_garbage", "robot_nan", "robot_bad_crc")
# Faults porter's own process injects into itself (``deploy.sim_backend.porter_faults``), at
# ``at_s`` on the loop's clock; the others are the world's.
PORTER_FAULTS = ("nmpc_failure", "recorder_failure", "loop_stall", "plan_late")


class SimFault(StrictModel):
    """A fault injected ``at_s`` simulated seconds after the world starts running (tests and
    drills of the safety stop). The world's: ``estop_press`` (the CAN node's heartbeats say
    "stopped"), ``heartbeat_loss`` (they stop), ``mocap_loss`` (NatNet frames stop),
    ``mocap_frozen`` (frames keep coming, frame numbers and timestamps rising, with the last
    poses repeated exactly), ``mocap_backwards`` (each frame's timestamp 1 ms before the
    last), ``mocap_foreign`` (every frame is also sent from another host), ``natnet_malformed``
    (a malformed packet beside every frame), ``robot_silent`` (``robot``'s fake stops
    publishing its state), ``robot_stall`` (it publishes no state for ``duration_s``, then
    goes on; physics and commands run on), ``robot_frozen`` (``robot``'s fake, Go2 or A1,
    keeps publishing its last state, tick included), ``robot_garbage`` (it publishes bytes that are
    no ``LowState_``), ``robot_nan`` (a joint angle of its state is NaN), ``robot_bad_crc`` (its
    states carry a wrong CRC: one bit flipped on the way), ``robot_push`` (a 300 N sideways push on
    ``robot``'s trunk for 0.4 s). Porter's own (``PORTER_FAULTS``): ``nmpc_failure`` (every NMPC
    plan from then on is a failed solve), ``recorder_failure`` (every log write fails with
    ENOSPC), ``loop_stall`` (the loop's thread hangs 0.3 s once), ``plan_late`` (the next NMPC
    plan reaches the loop ``duration_s`` later than it was ready, once). ``external`` changes
    nothing: it marks an action done from outside about then (the drill's), so that the world
    counts what reaches the motors from it on."""

    at_s: float = Field(ge=0)
    kind: Literal["external", "estop_press", "heartbeat_loss", "mocap_loss", "mocap_frozen",
                  "mocap_backwards", "mocap_foreign", "natnet_malformed",
                  "robot_silent", "robot_stall", "robot_frozen", "robot_garbage", "robot_nan",
                  "robot_bad_crc", "robot_push", "nmpc_failure", "recorder_failure", "loop_stall",
                  "plan_late"]
    robot: str | None = None
    duration_s: float | None = Field(None, gt=0, le=10.0)  # robot_stall, plan_late [simulated s]

    @model_validator(mode="after")
    def _robot_iff_robot_fault(self) -> SimFault:
        if (self.kind in ROBOT_FAULTS) != (self.robot is not None):
            raise ValueError(f"robot: name the robot for {', '.join(ROBOT_FAULTS)}, and only "
                             "for them")
        if (self.kind in TIMED_FAULTS) != (self.duration_s is not None):
            raise ValueError(f"duration_s: give it (> 0, <= 10 s) for {', '.join(TIMED_FAULTS)}, "
                             "and only for them")
        return self
