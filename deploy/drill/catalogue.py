"""The drill's faults: what each injects and how the team must end.

Expected outcomes: ``safe stop`` (exit 3, SAFE_STOP with ``cause`` in its reason, and from the
first damping-only command on nothing but damping reaches any motor), ``sit down`` (a stop
request: exit 130, the team sits down, no safe stop), ``ignored`` (the run completes, exit 0,
and the link counted what it refused: ``rejected``), ``refused`` (a bad config or command
line: exit 2 naming ``cause`` before anything starts), ``not started`` (the pre-flight check
names ``cause`` and the robots never stand up: exit 1), ``damped`` (porter's own process is
killed: nothing of porter reports, so the world, running on, says whether every robot got
damping-only commands within ``DAMPED_WITHIN_S`` from the watchdog and nothing else after, and
the log must read back up to its last flushed chunk), ``rides through`` (a late state or plan
within the budget: the run completes, exit 0, no safe stop, and the summary's ``evidence``
count is above 0: the loop saw the fault and held the robot on its last fresh command, or
counted the late plan). Times are simulated seconds after the
world starts (the team is RUNNING from about 1.5 s with the drill's short stand-up).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

__all__ = ["AT_S", "DAMPED_WITHIN_S", "DrillFault", "catalogue"]

AT_S = 2.5  # simulated s after the world starts: RUNNING by then
DAMPED_WITHIN_S = 0.05  # kill -9 of porter: every robot damped this soon (simulated s)
Expect = Literal["safe stop", "sit down", "ignored", "refused", "not started", "damped",
                 "rides through"]
Action = Literal["none", "sigterm", "sigint", "kill_nmpc", "kill_porter"]


@dataclass(frozen=True)
class DrillFault:
    """One drill case: ``config`` is merged into the drill's deploy config (the shipped
    ``deployment``'s, section by section), ``args`` replace command-line options, ``action``
    is done from outside at ``AT_S``; ``cause`` must appear in the safe-stop reason (or,
    refused, in the error)."""

    name: str
    expect: Expect
    cause: str
    config: dict[str, Any] = field(default_factory=dict)
    args: tuple[str, ...] = ()
    action: Action = "none"
    rejected: str = ""  # ignored: the link that must have counted refusals ("mocap", a robot)
    evidence: str = ""  # rides through: a summary count (dotted key) that must be above...
    evidence_above: float = 0.0  # ...this
    deployment: str = "two_go2"  # the shipped deploy config the case starts from
    # safe stop: the most simulated ms from the fault to the first damping-only command (about
    # 1.5-2x what the drill measures, so that a slower detection fails the case)
    within_ms: float | None = None


def _sim(kind: str, robot: str | None = None, at_s: float = AT_S,
         duration_s: float | None = None) -> dict[str, Any]:
    fault: dict[str, Any] = {"at_s": at_s, "kind": kind}
    if robot is not None:
        fault["robot"] = robot
    if duration_s is not None:
        fault["duration_s"] = duration_s
    return {"sim": {"faults": [fault]}}


def catalogue() -> list[DrillFault]:
    """Every fault of the drill, in table order."""
    stop: Expect = "safe stop"
    return [
        DrillFault("e-stop pressed", stop, "e-stop: run not allowed", _sim("estop_press"),
                   within_ms=50),
        DrillFault("e-stop pressed while standing up", stop, "e-stop",
                   _sim("estop_press", at_s=0.6), within_ms=50),
        DrillFault("e-stop heartbeat lost", stop, "e-stop", _sim("heartbeat_loss"),
                   within_ms=150),
        DrillFault("MoCap lost", stop, "MoCap lost", _sim("mocap_loss"), within_ms=300),
        DrillFault("MoCap frozen (frames rise, poses repeat)", stop, "MoCap lost",
                   _sim("mocap_frozen"), within_ms=300),
        DrillFault("MoCap timestamps backwards", stop, "MoCap lost",
                   _sim("mocap_backwards"), within_ms=300),
        DrillFault("NatNet frames from a foreign host", "ignored", "", _sim("mocap_foreign"),
                   rejected="mocap"),
        DrillFault("NatNet malformed packets", "ignored", "", _sim("natnet_malformed"),
                   rejected="mocap"),
        DrillFault("robot go2_0 silent", stop, "robot state stale: go2_0",
                   _sim("robot_silent", "go2_0"), within_ms=100),
        DrillFault("robot go2_1 silent", stop, "robot state stale: go2_1",
                   _sim("robot_silent", "go2_1"), within_ms=100),
        DrillFault("robot go2_0 state stalls 20 ms", "rides through", "",
                   _sim("robot_stall", "go2_0", duration_s=0.02),
                   evidence="stale_state_held_ticks.go2_0"),
        DrillFault("robot go2_1 state stalls 60 ms (past its stale-state budget)", stop,
                   "robot state stale: go2_1", _sim("robot_stall", "go2_1", duration_s=0.06),
                   within_ms=100),
        DrillFault("robot go2_0 state stalls 150 ms", stop, "robot state stale: go2_0",
                   _sim("robot_stall", "go2_0", duration_s=0.15), within_ms=100),
        DrillFault("robot go2_0 frozen (tick stops)", stop, "frozen tick",
                   _sim("robot_frozen", "go2_0"), within_ms=100),
        DrillFault("robot go2_1 frozen (tick stops)", stop, "frozen tick",
                   _sim("robot_frozen", "go2_1"), within_ms=100),
        DrillFault("robot a1_2 frozen (tick stops; the mixed team)", stop,
                   "frozen tick", _sim("robot_frozen", "a1_2"),
                   deployment="two_go2_a1", within_ms=100),
        # (every byte after the CDR header 0xFF: the CRC is the first check it fails)
        DrillFault("robot go2_0 malformed LowState", stop, "'crc'",
                   _sim("robot_garbage", "go2_0"), within_ms=100),
        DrillFault("robot go2_1 LowState with a bad CRC", stop, "'crc'",
                   _sim("robot_bad_crc", "go2_1"), within_ms=100),
        DrillFault("robot go2_1 NaN joint angle", stop, "'non-finite'",
                   _sim("robot_nan", "go2_1"), within_ms=100),
        DrillFault("robot go2_0 pushed over (fall)", stop, "go2_0",
                   _sim("robot_push", "go2_0"), within_ms=300),
        DrillFault("NMPC solver failure streak", stop, "NMPC solver failed",
                   _sim("nmpc_failure"), within_ms=150),
        DrillFault("NMPC plan 50 ms late", "rides through", "",
                   _sim("plan_late", duration_s=0.05), evidence="nmpc_longest_delay_ms",
                   evidence_above=50.0),
        # (the marker starts the world's count shortly before the kill: from the first
        # damping-only command on, nothing else may reach a motor)
        DrillFault("NMPC process killed", stop, "NMPC process lost",
                   _sim("external", at_s=AT_S - 0.3), action="kill_nmpc"),
        DrillFault("kill -9 of porter (the loop's own process)", "damped", "",
                   action="kill_porter"),
        DrillFault("flight recorder: disk full", stop, "flight recorder failed",
                   _sim("recorder_failure"), within_ms=50),
        DrillFault("control loop stalls 0.3 s (watchdog)", stop, "watchdog took over",
                   _sim("loop_stall"), within_ms=100),
        DrillFault("SIGTERM", "sit down", "", action="sigterm"),
        DrillFault("SIGINT (Ctrl-C)", "sit down", "", action="sigint"),
        DrillFault("robot silent from the start (pre-flight)", "not started",
                   "[MISSING] robot go2_1 link",
                   {"sim": {"silent_robots": ["go2_1"]}}),
        DrillFault("config: NaN timeout", "refused", "mocap_timeout_s",
                   {"safety": {"mocap_timeout_s": float("nan")}}),
        DrillFault("config: infinite link timeout", "refused", "link_timeout_s",
                   {"robots": {"go2_0": {"link_timeout_s": float("inf")}}}),
        DrillFault("config: damping_kd 0", "refused", "damping_kd",
                   {"safety": {"damping_kd": 0.0}}),
        DrillFault("config: max_tilt_rad 100", "refused", "max_tilt_rad",
                   {"safety": {"max_tilt_rad": 100.0}}),
        DrillFault("config: 1e9 solver failures allowed", "refused",
                   "max_consecutive_solver_failures",
                   {"safety": {"max_consecutive_solver_failures": 1_000_000_000}}),
        DrillFault("config: port out of range", "refused", "command_port",
                   {"mocap": {"command_port": 70000}}),
        DrillFault("config: unknown network interface", "refused", "network_interface",
                   {"network_interface": "enp9s9-absent"}),
        DrillFault("config: unknown field", "refused", "Extra inputs are not permitted",
                   {"safety": {"max_tilt_deg": 40}}),
        DrillFault("command line: --duration -1", "refused", "argument --duration",
                   args=("--duration", "-1")),
    ]
