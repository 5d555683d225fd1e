"""The stale-state rule and the hybrid joint command, on hand-made measurements and WBC outputs."""

from __future__ import annotations

import numpy as np
import pytest

from core.locomotion.whole_body_control import WbcOutput
from deploy.runtime.controller import hybrid_command
from deploy.runtime.team_commands import StaleStateHold, link_notes
from drivers.interfaces import JointCommand, RobotMeasurement
from drivers.link_errors import LinkMonitor


def measurement(time_s: float, position: float = 0.1, velocity: float = 0.0) -> RobotMeasurement:
    return RobotMeasurement(time_s, np.full(12, position), np.full(12, velocity), np.zeros(12),
                            np.array([0.0, 0.0, 0.3]), np.array([1.0, 0.0, 0.0, 0.0]),
                            np.zeros(3), np.zeros(3), np.ones(4, dtype=bool), np.full(4, 30.0))


def command(torque: float) -> JointCommand:
    return JointCommand(torque_nm=np.full(12, torque))


def test_fresh_states_pass_the_computed_command_through() -> None:
    hold = StaleStateHold(["a"], hold_after_ticks=2, tick_s=0.002)
    for k in range(5):
        computed = command(float(k))
        assert hold.command("a", measurement(0.002 * k), computed) is computed
        assert not hold.holding("a")
    assert hold.held_ticks == {"a": 0}
    assert hold.longest_stale_ticks == {"a": 0}


def test_a_stalled_state_gets_the_last_fresh_command_from_the_nth_tick() -> None:
    hold = StaleStateHold(["a", "b"], hold_after_ticks=2, tick_s=0.002)
    fresh = command(1.0)
    assert hold.command("a", measurement(0.0), fresh) is fresh
    hold.command("b", measurement(0.0), command(5.0))
    # one repeated state (a tick that ran before the robot's next state): still computed
    first_stale = command(2.0)
    assert hold.command("a", measurement(0.0), first_stale) is first_stale
    assert not hold.holding("a")
    # from the second repeat on: the command computed on the last fresh state
    for k in range(4):
        assert hold.command("a", measurement(0.0), command(3.0 + k)) is fresh
        assert hold.holding("a")
    assert hold.held_ticks == {"a": 4, "b": 0}
    assert hold.longest_stale_ticks == {"a": 5, "b": 0}
    # the state advances again: back to the WBC's command, the count of the stall kept
    recovered = command(9.0)
    assert hold.command("a", measurement(0.002), recovered) is recovered
    assert not hold.holding("a")
    assert hold.longest_stale_ticks["a"] == 5


def test_hold_after_ticks_must_be_positive() -> None:
    with pytest.raises(ValueError, match="hold_after_ticks"):
        StaleStateHold(["a"], hold_after_ticks=0, tick_s=0.002)


def test_the_stale_time_of_each_robot_is_its_repeated_ticks_times_the_period() -> None:
    hold = StaleStateHold(["a", "b"], hold_after_ticks=2, tick_s=0.002)
    hold.command("a", measurement(0.0), command(1.0))
    hold.command("b", measurement(0.0), command(1.0))
    assert hold.stale_s() == {}
    for k in range(1, 6):  # a repeats its state, b advances
        hold.command("a", measurement(0.0), command(1.0))
        hold.command("b", measurement(0.002 * k), command(1.0))
    assert hold.stale_s() == {"a": pytest.approx(0.010)}
    hold.command("a", measurement(0.02), command(1.0))
    assert hold.stale_s() == {}


def test_the_hybrid_command_integrates_the_qp_accelerations_one_tick_ahead() -> None:
    tick_s = 0.002
    acceleration = np.linspace(-50.0, 50.0, 12)
    output = WbcOutput(torque_nm=np.full(12, 3.0), joint_acceleration_rad_s2=acceleration,
                       contact_force_n=np.zeros((4, 3)), success=True, status=1,
                       solve_time_s=0.0)
    state = measurement(0.0, position=0.4, velocity=2.0)
    kp, kd = np.full(12, 10.0), np.full(12, 0.5)
    hybrid = hybrid_command(output, state, tick_s, kp, kd)
    np.testing.assert_allclose(hybrid.torque_nm, 3.0)
    np.testing.assert_allclose(hybrid.velocity_rad_s, 2.0 + acceleration * tick_s)
    np.testing.assert_allclose(hybrid.position_rad,
                               0.4 + 2.0 * tick_s + 0.5 * acceleration * tick_s**2)
    np.testing.assert_allclose(hybrid.kp, 10.0)
    np.testing.assert_allclose(hybrid.kd, 0.5)
    # Applied on time (state = target one tick later), the PD adds nothing to the torque; held
    # a further 18 ms with the joint drifting on at the planned velocity, it pulls back.
    late_q = hybrid.position_rad + hybrid.velocity_rad_s * 0.018
    pd = hybrid.kp * (hybrid.position_rad - late_q)
    assert np.all(np.sign(pd) == -np.sign(hybrid.velocity_rad_s))


def test_a_stale_robot_is_named_with_what_its_link_rejected_since_its_last_valid_state() -> None:
    now = [0.0]
    link = LinkMonitor("go2 rt/lowstate", 0.1, lambda: now[0])

    class Driver:  # a wire driver's link monitor; the lockstep's robots have none
        def __init__(self) -> None:
            self.link = link

    drivers = {"a": Driver(), "b": object()}
    link.accept()
    assert link_notes(drivers, ["a", "b"]) == {}  # nothing rejected since the valid state
    link.reject("frozen tick")
    link.reject("frozen tick")
    link.reject("crc")
    assert link_notes(drivers, ["a", "b"]) == {
        "a": "rejected since its last valid state: {'frozen tick': 2, 'crc': 1}"}
    assert link_notes(drivers, ["b"]) == {}
    link.accept()  # a valid state again: the note starts over, the totals stay
    assert link_notes(drivers, ["a"]) == {} and link.rejected_total == 3
