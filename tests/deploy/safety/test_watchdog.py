"""The watchdog outside the control process, against Go2 fakes on real DDS: after kill -9 of
the loop's process, or a loop that stops beating, every robot gets damping-only commands soon
after its timeout; a clean end sends nothing; its watch at the loop's real-time priority.

These run on the wall clock beside whatever else the machine does, so their bounds hold on a
loaded 2-core machine: the shipped 25 ms timeout and a bound of TAKEOVER_S after the loss (the
shipped "damped within 50 ms" is the drill's verdict, in simulated time). The tests whose loop
beats from this process take a 0.1 s timeout, so that a late beat is not a takeover."""

from __future__ import annotations

import multiprocessing as mp
import os
import signal
import time

import numpy as np
import pytest

from core.plant.standard_scenarios import ring_team_settings
from deploy.compute import realtime
from deploy.config.deploy_config import DeployConfig, Go2Link, load_deploy_config
from deploy.safety.watchdog import Watchdog, WatchdogSpec
from drivers.interfaces import JointCommand
from drivers.link_errors import DriverError
from drivers.mujoco.scene import build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.robot_descriptions import srb_parameters
from drivers.unitree.go2_driver import Go2Driver
from drivers.unitree.go2_fake import FakeGo2

DOMAIN_ID = 64
HOLD_TORQUE_NM = 1.5  # what the "loop" keeps commanding: the torque that must not stay on
TAKEOVER_S = 0.1  # loss to the first damping command, wall clock (the timeout is 25 ms)
SLOW_TIMEOUT_S = 0.1  # the timeout where this process beats (a 2 ms sleep may take 30 ms)


def _slow(config: DeployConfig) -> DeployConfig:
    return config.model_copy(update={"watchdog": config.watchdog.model_copy(
        update={"timeout_s": SLOW_TIMEOUT_S})})


def _config(prefix: str) -> DeployConfig:
    config, _ = load_deploy_config("two_go2")
    robots = {name: Go2Link(driver="go2", domain_id=DOMAIN_ID, topic_prefix=f"{prefix}_{name}")
              for name in config.robots}
    return config.model_copy(update={"robots": robots})


@pytest.fixture
def team() -> tuple[DeployConfig, dict[str, FakeGo2]]:
    """Two Go2 fakes (on one simulation) on topics of their own, and the config naming them."""
    prefix = f"wd{os.getpid()}_{time.monotonic_ns() % 100000}"
    config = _config(prefix)
    scene = build_team_scene(ring_team_settings(["go2", "go2"], srb_parameters))
    simulation = TeamSimulation(scene)
    fakes = {name: FakeGo2(simulation.robot_driver(robot.name), DOMAIN_ID,
                           topic_prefix=f"{prefix}_{name}")
             for name, robot in zip(config.robots, scene.robots, strict=True)}
    yield config, fakes
    for fake in fakes.values():
        fake.close()


def _is_damping(command: JointCommand) -> bool:
    return (not command.kp.any() and not command.torque_nm.any()
            and bool(np.all(command.kd > 0.0)))


def _observe(fakes: dict[str, FakeGo2], seconds: float) -> list[tuple[float, str, JointCommand]]:
    """Every newest command the fakes apply in the next ``seconds`` (polled every ~0.5 ms)."""
    seen = []
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        for name, fake in fakes.items():
            if fake.poll_commands():
                assert fake.last_command is not None
                seen.append((time.monotonic(), name, fake.last_command))
        time.sleep(0.0005)
    return seen


def _a_loop(config: DeployConfig, ready: mp.Event) -> None:  # type: ignore[valid-type]
    """The control loop's stand-in (a process of its own): the watchdog, a heartbeat and a
    torque command to every robot every 2 ms, until killed."""
    watchdog = Watchdog(WatchdogSpec.of(config))
    drivers = [Go2Driver(name, link.domain_id, None, link.topic_prefix)
               for name, link in config.robots.items()]
    command = JointCommand(torque_nm=np.full(12, HOLD_TORQUE_NM))
    ready.set()
    while True:
        watchdog.beat()
        for driver in drivers:
            driver.send(command)
        time.sleep(0.002)


def test_kill_9_of_the_loop_leaves_only_damping_soon_after(team) -> None:
    config, fakes = team
    context = mp.get_context("spawn")
    ready = context.Event()
    # not a daemon: daemonic processes may not start the watchdog's process
    loop = context.Process(target=_a_loop, args=(config, ready))
    loop.start()
    try:
        deadline = time.monotonic() + 60.0
        while not ready.wait(0.1):
            assert loop.is_alive() and time.monotonic() < deadline, \
                "the loop's stand-in did not start"
        before = _observe(fakes, 0.3)
        assert {name for _, name, _ in before} == set(fakes)  # the loop's torques arrive
        assert all(c.torque_nm[0] == pytest.approx(HOLD_TORQUE_NM) for _, _, c in before)
        os.kill(loop.pid, signal.SIGKILL)
        killed_s = time.monotonic()
        after = _observe(fakes, 0.3)
    finally:
        loop.kill()
        loop.join(5.0)
    for name in fakes:
        applied = [(t, c) for t, n, c in after if n == name]
        first_damping = next(t for t, c in applied if _is_damping(c))
        assert first_damping - killed_s <= TAKEOVER_S, (name, first_damping - killed_s)
        # nothing but damping once the first damping command arrived (the loop's last
        # torques may still be in flight before it)
        assert all(_is_damping(c) for t, c in applied if t >= first_damping), name
        assert len([t for t, c in applied if t >= first_damping]) > 50  # it keeps damping


def test_a_loop_that_stops_beating_is_taken_over_and_a_clean_end_sends_nothing(team) -> None:
    config, fakes = team
    config = _slow(config)
    watchdog = Watchdog(WatchdogSpec.of(config))
    try:
        for _ in range(50):  # 0.1 s of a healthy loop: nothing from the watchdog
            watchdog.beat()
            time.sleep(0.002)
        assert not watchdog.tripped
        assert _observe(fakes, 0.01) == []
        stopped_s = time.monotonic()  # the loop hangs: no more beats
        after = _observe(fakes, 0.3)
        assert watchdog.tripped and watchdog.alive
        for name in fakes:
            damping = [t for t, n, c in after if n == name and _is_damping(c)]
            assert damping and damping[0] - stopped_s <= SLOW_TIMEOUT_S + TAKEOVER_S
            assert len(damping) == len([1 for _, n, _ in after if n == name])
    finally:
        watchdog.disarm()
    assert not watchdog.alive
    _observe(fakes, 0.05)  # drain what was in flight
    assert _observe(fakes, 0.1) == []  # disarmed: the damping stream stopped
    quiet = Watchdog(WatchdogSpec.of(config))  # (the slow timeout: 20 beats 2 ms apart)
    for _ in range(20):
        quiet.beat()
        time.sleep(0.002)
    quiet.disarm()
    assert not quiet.tripped and _observe(fakes, 0.1) == []


def _policy(thread: int) -> tuple[int, int]:
    """(policy, priority) of one thread (Linux takes a thread id where a pid goes)."""
    return os.sched_getscheduler(thread), os.sched_getparam(thread).sched_priority


def test_the_watch_runs_at_the_loops_priority_and_still_takes_over(team) -> None:
    config, fakes = team
    priority = 20 if realtime.check(20) is None else None  # where this process may
    watchdog = Watchdog(WatchdogSpec.of(config, priority=priority))
    try:
        pid = watchdog.pid
        assert pid is not None
        threads = [int(t) for t in os.listdir(f"/proc/{pid}/task")]
        assert len(threads) > 1  # DDS's threads beside the watch
        others = {_policy(t) for t in threads if t != pid}
        assert others == {(os.SCHED_OTHER, 0)}  # started before the priority: normal
        if priority is None:
            assert _policy(pid) == (os.SCHED_OTHER, 0)
        else:
            assert _policy(pid) == (os.SCHED_FIFO, priority)
        watchdog.beat()
        stopped_s = time.monotonic()
        after = _observe(fakes, 0.3)
        assert watchdog.tripped
        for name in fakes:
            damping = [t for t, n, c in after if n == name and _is_damping(c)]
            assert damping and damping[0] - stopped_s <= TAKEOVER_S
    finally:
        watchdog.disarm()


def test_a_priority_it_cannot_take_stops_its_start_with_the_reason(team) -> None:
    config, _ = team
    with pytest.raises(DriverError, match=r"watchdog did not start: .*rates\.loop_priority"):
        Watchdog(WatchdogSpec.of(config, priority=100))  # beyond SCHED_FIFO's 1-99
