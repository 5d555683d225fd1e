"""porter's one set of conventions: leg and joint order, array sizes, the payload's name.

Every per-joint array in porter has ``JOINT_COUNT`` entries in ``LEG_JOINT_NAMES`` order
(FL, FR, RL, RR x hip, thigh, calf); every per-foot array ``FOOT_COUNT`` entries in
``LEG_NAMES`` order. Drivers convert their hardware's order to these, once, at their boundary
(``drivers.unitree.conventions`` for Unitree's FR, FL, RR, RL). Quaternions are (w, x, y, z);
the world frame is z up; units are SI.
"""

from __future__ import annotations

__all__ = ["FOOT_COUNT", "JOINT_COUNT", "LEG_JOINT_KINDS", "LEG_JOINT_NAMES", "LEG_NAMES",
           "PAYLOAD_NAME"]

LEG_NAMES = ("FL", "FR", "RL", "RR")
FOOT_COUNT = len(LEG_NAMES)
LEG_JOINT_KINDS = ("hip", "thigh", "calf")
# Leg joints in the fixed order FL, FR, RL, RR x (hip, thigh, calf): the URDF joint names.
LEG_JOINT_NAMES = tuple(f"{leg}_{kind}_joint" for leg in LEG_NAMES for kind in LEG_JOINT_KINDS)
JOINT_COUNT = len(LEG_JOINT_NAMES)
# The payload's name everywhere a body is named: MuJoCo body, MoCap rigid body, log frame,
# push target, obstacle pair.
PAYLOAD_NAME = "payload"
