"""Team links without hardware: the MoCap tracker on an injected clock and source, and the
pre-flight report over links built from fakes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from core.model.conventions import PAYLOAD_NAME
from deploy.config.deploy_config import load_deploy_config
from deploy.runtime.links import MocapTracker, TeamLinks
from deploy.safety.posture import standing_posture
from deploy.safety.preflight import evaluate
from deploy.safety.supervisor import robot_limits
from drivers.interfaces import EstopStatus, MocapFrame, RobotMeasurement
from tests.deploy.runtime.fakes import FakeClock

IDENTITY = np.array([1.0, 0.0, 0.0, 0.0])


class FakeMocap:
    """``MocapSource``: frames set by the test, arriving at the clock's time."""

    def __init__(self, clock: FakeClock) -> None:
        self.clock, self.frame, self.arrived_s = clock, None, -math.inf

    def push(self, frame: MocapFrame) -> None:
        self.frame, self.arrived_s = frame, self.clock()

    def latest(self) -> MocapFrame | None:
        return self.frame

    def age_s(self) -> float:
        return self.clock() - self.arrived_s


def test_tracker_renames_bodies_ages_them_and_fits_a_velocity() -> None:
    clock = FakeClock(10.0)
    source = FakeMocap(clock)
    tracker = MocapTracker(source, {"go2_0": "Robot A", PAYLOAD_NAME: "Box"}, 0.08, clock)
    assert tracker.poll() is None and tracker.age_s() is None
    for k in range(10):  # 120 Hz, the robot moving at 0.6 m/s along x
        t = k / 120.0
        source.push(MocapFrame(t, {"Robot A": (np.array([0.6 * t, 0.0, 0.3]), IDENTITY)}))
        frame = tracker.poll()
        clock.sleep(1.0 / 120.0)
    assert frame is not None and set(frame.poses) == {"go2_0"}
    assert tracker.missing() == [PAYLOAD_NAME]
    assert tracker.age_s(["go2_0"]) == pytest.approx(1.0 / 120.0)
    assert tracker.age_s() is None  # the payload was never seen
    np.testing.assert_allclose(tracker.velocity("go2_0"), [0.6, 0.0, 0.0], atol=1e-9)
    position, velocity = tracker.body_motion("go2_0")
    np.testing.assert_allclose(position, [0.6 * 9 / 120, 0.0, 0.3])
    np.testing.assert_allclose(velocity, [0.6, 0.0, 0.0], atol=1e-9)
    # the same frame again is not a new sample
    assert tracker.poll() is frame
    # the fit is kept per frame: a caller's change to it stays with the caller, and the next
    # frame (the robot stopped) changes it
    tracker.velocity("go2_0")[:] = 99.0
    np.testing.assert_allclose(tracker.velocity("go2_0"), [0.6, 0.0, 0.0], atol=1e-9)
    for k in range(10, 20):
        source.push(MocapFrame(k / 120.0, {"Robot A": (np.array([0.6 * 9 / 120, 0.0, 0.3]),
                                                       IDENTITY)}))
        tracker.poll()
        clock.sleep(1.0 / 120.0)
    np.testing.assert_allclose(tracker.velocity("go2_0"), 0.0, atol=1e-9)


def test_a_pose_repeated_bit_for_bit_freezes_the_body_while_jitter_does_not() -> None:
    clock = FakeClock(0.0)
    source = FakeMocap(clock)
    tracker = MocapTracker(source, {"go2_0": "A", "go2_1": "B"}, 0.08, clock,
                           max_repeated_frames=12)
    rng = np.random.default_rng(0)
    frozen_position = np.array([1.0, 2.0, 0.3])
    ages = []
    for k in range(60):  # 0.5 s at 120 Hz, frame numbers / timestamps rising
        t = k / 120.0
        jitter = np.array([0.5, 0.0, 0.3]) + rng.normal(0.0, 2e-4, 3)  # 0.2 mm sensor noise
        source.push(MocapFrame(t, {"A": (frozen_position.copy(), IDENTITY.copy()),
                                   "B": (jitter, IDENTITY.copy())}))
        tracker.poll()
        ages.append(tracker.age_s(["go2_0"]))
        clock.sleep(1.0 / 120.0)
        assert tracker.age_s(["go2_1"]) == pytest.approx(1.0 / 120.0)  # jitter: always fresh
    # go2_0: seen on its first frame and 12 repeats, then no more: its age grows from there
    assert ages[12] == pytest.approx(0.0) and tracker.repeated_frames["go2_0"] == 59
    assert ages[-1] == pytest.approx(47 / 120.0)
    assert tracker.age_s() == pytest.approx(48 / 120.0)  # the stalest body
    # a pose that moves again is fresh at once
    source.push(MocapFrame(0.5, {"A": (frozen_position + 1e-4, IDENTITY.copy()),
                                 "B": (frozen_position, IDENTITY.copy())}))
    tracker.poll()
    assert tracker.age_s(["go2_0"]) == pytest.approx(0.0)
    # without the check a frozen body stays fresh (the lockstep simulation's tracker)
    plain = MocapTracker(source, {"go2_0": "A"}, 0.08, clock)
    for k in range(30):
        source.push(MocapFrame(1.0 + k, {"A": (frozen_position.copy(), IDENTITY.copy())}))
        plain.poll()
    assert plain.age_s() == pytest.approx(0.0)


class FakeEstop:
    def __init__(self, allowed: bool) -> None:
        self.allowed = allowed

    def status(self) -> EstopStatus:
        return EstopStatus(self.allowed, "run" if self.allowed else "released")


def _resting(robot_type: str, moving: float = 0.0) -> RobotMeasurement:
    q = standing_posture(robot_type)
    return RobotMeasurement(0.5, q, np.full(12, moving), np.zeros(12), np.array([0, 0, 0.3]),
                            IDENTITY, np.zeros(3), np.zeros(3), np.ones(4, bool), np.full(4, 30.))


def test_preflight_passes_on_good_links_and_names_each_problem() -> None:
    config, _ = load_deploy_config("two_go2")
    names = list(config.robots)
    limits = {name: robot_limits("go2", name) for name in names}
    good = TeamLinks(dict.fromkeys(names), None, None, FakeEstop(True), None)  # type: ignore[arg-type]
    measurements = {name: _resting("go2") for name in names}
    report = evaluate(config.model_copy(update={"can": config.can.model_copy(
        update={"force_torque": False})}), good, limits, measurements, {}, {})
    assert report.ok, report.text()
    bad = TeamLinks(dict.fromkeys(names), None, None, FakeEstop(False), None,  # type: ignore[arg-type]
                    problems=["MoCap: no server"])
    report = evaluate(config, bad, limits,
                      {names[0]: _resting("go2", moving=2.0)}, {names[1]: "no state for 0.2 s"},
                      {names[0]: "refused, code 3102"})
    failed = {check.item: check.detail for check in report.failed}
    assert not report.ok
    assert failed["link"] == "MoCap: no server"
    assert "3102" in failed[f"robot {names[0]} sport mode"]
    assert "not at rest" in failed[f"robot {names[0]} joint states"]
    assert failed[f"robot {names[1]} link"] == "no state for 0.2 s"
    assert any("e-stop" in item.lower() or "estop" in item.lower() for item in failed)
