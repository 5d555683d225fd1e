"""The ``--backend sim`` world, run in its own process: MuJoCo physics paced to real time and the
fakes that speak the hardware's wire protocols on loopback.

Per robot a ``FakeGo2`` (CycloneDDS) or ``FakeA1`` (UDP), a ``FakeNatNetServer`` streaming the
robots' and the payload's poses (Motive names, the scenario's MoCap noise, frame timestamps =
simulated time), and a ``FakeCanNode`` (e-stop heartbeat, F/T samples of the simulated
coupling wrenches). python-can's ``virtual`` bus exists only inside one process, so the CAN
node writes to a ``PipeBus``: its frames cross a pipe and the parent puts them on a virtual
bus (``deploy.sim_backend.backend``), where porter's ``EstopMonitor`` and ``ForceTorqueSensors`` read
them like frames from a CAN adapter.

Start: the robots are laid down before real time starts, as an operator leaves them: from the
scene's standing pose they sit (trunk lowered ``start_lowering_m`` by joint PD), then sink in
joint damping onto their bellies (simulated, unpaced). From then on every command comes from
the deploy loop through the drivers.

The loop (one thread, which alone touches the ``MjData``): every 1 / ``state_rate_hz`` s it
takes the newest valid command of each fake, advances physics to the (scaled, see
``ScaledClock``) wall clock at 1 kHz
(at most ``MAX_CATCH_UP_STEPS`` per cycle; beyond that simulated time slips behind wall time
and ``lag_s`` says by how much), publishes each robot's state, and a MoCap frame / F/T sample
when due. A cycle that runs late steps the physics several steps at once on the commands it
last read, with no state published in between: the simulated robots "hold" for that long,
which real motors never do; ``holds`` reports it (the longest, and how many were longer than
``HOLD_REPORT_S``, 4 ms: two Go2 state periods), so that a run on a loaded machine says that it
measured the machine, not porter.
The control pipe answers ``"ground_truth"`` and ends the world on ``"stop"``.

Faults (``sim.faults``) are injected at their simulated time after the loop starts; from the
first one on, every command a fake applies is counted, and those with stiffness or
feed-forward torque (anything but damping) are reported in the ground truth with the last
time one arrived, so a test sees what reached the motors after the safety stop.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json
import math
import os
import signal
import sys
import threading
import time
from dataclasses import dataclass
from multiprocessing.connection import Connection
from typing import Any

import can
import numpy as np

from core.model.conventions import JOINT_COUNT, PAYLOAD_NAME
from deploy.compute.gc_pauses import freeze_startup_objects
from deploy.compute.process_names import name_this_process
from deploy.compute.realtime import set_process_cpus, set_process_priority
from deploy.config.deploy_config import DeployConfig, Go2Link
from deploy.config.scenario import Scenario
from deploy.safety.checks import tilt_rad
from deploy.safety.posture import sitting_posture
from deploy.sim_backend.world_faults import inject_due_faults, network_faults
from drivers.can.fake import FakeCanNode
from drivers.interfaces import JointCommand, Pose
from drivers.mujoco.scene import PHYSICS_TIMESTEP_S, build_team_scene
from drivers.mujoco.simulation import TeamSimulation
from drivers.natnet.fake import FakeNatNetServer
from drivers.unitree.a1_fake import FakeA1
from drivers.unitree.go2_fake import FakeGo2

MAX_CATCH_UP_STEPS = 20
HOLD_REPORT_S = 0.004  # a world hold longer than this is reported (two 500 Hz state periods)
ORPHAN_RUN_S = 0.5  # simulated seconds the world runs on without porter (drills)
SETTLE_SIT_S = 1.0  # PD to the sitting posture
SETTLE_DAMPED_S = 2.0  # then joint damping: onto the belly
SETTLE_KP, SETTLE_KD, SETTLE_DAMPING_KD = 60.0, 3.0, 2.0


class ScaledClock:
    """``time_scale`` x ``time.monotonic()`` [s]: simulated seconds, the same in every process
    (the monotonic clock is system-wide); ``sleep`` waits simulated seconds."""

    def __init__(self, time_scale: float = 1.0) -> None:
        self.time_scale = time_scale

    def __call__(self) -> float:
        return self.time_scale * time.monotonic()

    def sleep(self, duration_s: float) -> None:
        time.sleep(duration_s / self.time_scale)


@dataclass
class CommandsAfterFault:
    """Commands a fake applied since the first injected fault [count]; the last one that was
    not damping, in simulated seconds after that fault."""

    commands: int = 0
    non_damping: int = 0
    last_non_damping_s: float | None = None
    first_damping_s: float | None = None  # the first damping-only command (kd > 0)
    non_damping_after_damping: int = 0  # the drill's "not damping after detection"


@dataclass(frozen=True)
class WorldSpec:
    """What the world process builds: the scenario's scene and the fakes of ``config`` (whose
    links are already the sim's loopback ones), NatNet frames sent to ``natnet_data_port``."""

    scenario: Scenario
    config: DeployConfig
    natnet_data_port: int


class PipeBus(can.BusABC):
    """A send-only CAN bus whose frames go down ``connection`` (to the parent's bridge)."""

    def __init__(self, connection: Connection) -> None:
        self._connection = connection
        self._lock = threading.Lock()
        self.channel_info = "pipe to the parent process"
        super().__init__(channel="pipe")

    def send(self, msg: can.Message, timeout: float | None = None) -> None:
        with self._lock, contextlib.suppress(OSError):  # OSError: the parent is gone
            self._connection.send(msg)

    def _recv_internal(self, timeout: float | None) -> tuple[can.Message | None, bool]:
        return None, False


def lay_down(simulation: TeamSimulation, robot_types: dict[str, str], lowering_m: float) -> None:
    """Sit (PD to the sitting posture) then sink in joint damping, unpaced (see module)."""
    for name, robot_type in robot_types.items():
        simulation.set_command(name, JointCommand.hold(sitting_posture(robot_type, lowering_m),
                                                       SETTLE_KP, SETTLE_KD))
    simulation.step(round(SETTLE_SIT_S / simulation.timestep_s))
    for name in robot_types:
        simulation.set_command(name, JointCommand(kd=np.full(JOINT_COUNT, SETTLE_DAMPING_KD)))
    simulation.step(round(SETTLE_DAMPED_S / simulation.timestep_s))


class SimWorld:
    """The simulated team behind its fakes (built inside the world process)."""

    def __init__(self, spec: WorldSpec, can_link: Connection) -> None:
        scenario, config = spec.scenario, spec.config
        self.config = config
        scene = build_team_scene(
            scenario.team_settings(), payload_true_mass_kg=scenario.true_payload_mass_kg,
            obstacles=[(*o.position_m, o.radius_m, o.height_m, *o.velocity_m_s)
                       for o in scenario.obstacles],
            timestep_s=PHYSICS_TIMESTEP_S, payload_height_m=scenario.reference.payload_height_m)
        self.simulation = sim = TeamSimulation(scene, seed=scenario.seed)
        self.robot_types = {agent.name: agent.robot_type for agent in scenario.team}
        sim.obstacle_origin_s = math.inf  # obstacles wait while the robots are laid down
        lay_down(sim, self.robot_types, config.sim.start_lowering_m)
        # Moving obstacles start on their paths when the world starts running, not when the
        # team is armed: porter sees where they are through the MoCap (mocap.obstacle_bodies).
        sim.obstacle_origin_s = sim.time_s
        self.fakes: dict[str, FakeGo2 | FakeA1] = {}
        self.a1_endpoints: dict[str, tuple[str, int]] = {}
        for name, link in config.robots.items():
            driver = sim.robot_driver(name)
            if isinstance(link, Go2Link):
                self.fakes[name] = FakeGo2(driver, link.domain_id, None, link.topic_prefix,
                                           link.foot_force_n_per_count,
                                           config.sim.firmware_command_timeout_s)
            else:
                a1 = FakeA1(driver, "127.0.0.1", 0,
                            foot_force_n_per_count=link.foot_force_n_per_count,
                            command_timeout_s=config.sim.firmware_command_timeout_s)
                self.fakes[name] = a1
                self.a1_endpoints[name] = a1.local_endpoint
        self.obstacle_bodies = {  # Motive body -> obstacle index
            body: index for index, body in enumerate(config.mocap.obstacle_bodies)
            if body is not None}
        noise = scenario.disturbances
        mocap = config.mocap
        self.natnet = FakeNatNetServer(
            self._poses, body_ids=mocap.body_ids, host="127.0.0.1", command_port=0,
            data_port=spec.natnet_data_port, position_noise_m=noise.mocap_position_noise_m,
            angle_noise_rad=noise.mocap_angle_noise_rad, latency_s=config.sim.mocap_latency_s,
            dropout_probability=config.sim.mocap_dropout_probability, seed=scenario.seed,
            timestamp_source=lambda: sim.time_s, clock=ScaledClock(config.sim.time_scale))
        for body in config.sim.untracked_bodies:
            self.natnet.set_tracked(config.body_name(body), False)
        self.can_node = FakeCanNode(PipeBus(can_link), robot_names=list(config.robots),
                                    wrench_source=sim.coupling_wrench) \
            if config.sim.can_node else None
        self.payload_start_m = sim.payload_pose()[0]
        self.min_height_m = {name: math.inf for name in self.robot_types}
        self.max_tilt_rad = dict.fromkeys(self.robot_types, 0.0)
        self.lag_s = 0.0
        self.steps = 0
        self.longest_hold_s = 0.0  # the most simulated time stepped at once (after the first)
        self.long_holds = 0  # cycles stepping more than HOLD_REPORT_S at once
        self.silent = set(config.sim.silent_robots)
        self.stalled_until: dict[str, float] = {}  # robot_stall: silent until (elapsed s)
        self.mocap_stopped = False
        self.network_faults: set[str] = set()  # sent beside every MoCap frame
        self.pending_faults = sorted(config.sim.faults, key=lambda fault: fault.at_s)
        self.faults_applied: list[dict[str, Any]] = []
        self.after_fault = {name: CommandsAfterFault() for name in self.robot_types}

    def _received(self, name: str, command: JointCommand | None) -> None:
        """Once a fault is in: count what reaches the motors; damping = no stiffness, no
        feed-forward torque."""
        if not self.faults_applied or command is None:
            return
        counts = self.after_fault[name]
        counts.commands += 1
        since_s = self.simulation.time_s - self.faults_applied[0]["time_s"]
        if np.any(command.kp != 0.0) or np.any(command.torque_nm != 0.0):
            counts.non_damping += 1
            counts.last_non_damping_s = since_s
            counts.non_damping_after_damping += int(counts.first_damping_s is not None)
        elif counts.first_damping_s is None and np.any(command.kd > 0.0):
            counts.first_damping_s = since_s

    def endpoints(self, start_monotonic_s: float) -> dict[str, Any]:
        """Where the fakes listen: NatNet command port, each A1's UDP (address, port); and the
        instant the world's time starts (``time.monotonic()``, system-wide), from which its
        ``sim.faults`` are due."""
        return {"natnet_command_port": self.natnet.command_port,
                "a1": dict(self.a1_endpoints), "start_monotonic_s": start_monotonic_s}

    def _poses(self) -> dict[str, Pose]:
        sim = self.simulation
        poses = {self.config.body_name(name): sim.base_pose(name) for name in self.robot_types}
        poses[self.config.body_name(PAYLOAD_NAME)] = sim.payload_pose()
        for body, index in self.obstacle_bodies.items():
            poses[body] = sim.obstacle_pose(index)
        return poses

    def ground_truth(self) -> dict[str, Any]:
        """Simulator truth for the run summary (world frame, SI units)."""
        sim = self.simulation
        robots = {}
        for name in self.robot_types:
            fake = self.fakes[name]
            robots[name] = {"position_m": sim.base_pose(name)[0].tolist(),
                            "min_height_m": self.min_height_m[name],
                            "max_tilt_rad": self.max_tilt_rad[name],
                            "commands_received": fake.commands_received,
                            "commands_rejected": fake.commands_rejected_total,
                            "states_published": fake.states_published,
                            "firmware_timeouts": fake.command_timeout.timeouts,
                            "after_fault": dataclasses.asdict(self.after_fault[name])}
        return {"time_s": sim.time_s, "payload_start_m": self.payload_start_m.tolist(),
                "payload_position_m": sim.payload_pose()[0].tolist(), "robots": robots,
                "lag_s": self.lag_s, "physics_steps": self.steps,
                "holds": {"longest_s": self.longest_hold_s,
                          "over_4_ms": self.long_holds},
                "mocap_frames": self.natnet.frames_published,
                "cpus": sorted(os.sched_getaffinity(0)),
                "faults_applied": self.faults_applied}

    def _track(self) -> None:
        for name in self.robot_types:
            position, quaternion = self.simulation.base_pose(name)
            self.min_height_m[name] = min(self.min_height_m[name], float(position[2]))
            self.max_tilt_rad[name] = max(self.max_tilt_rad[name], tilt_rad(quaternion))

    def run(self, control: Connection, start_monotonic_s: float | None = None) -> None:
        """Real-time loop from ``start_monotonic_s`` (``time.monotonic()``; now if None) until
        ``"stop"`` arrives or the parent's end of ``control`` closes (then, with
        ``sim.orphan_report``, ``ORPHAN_RUN_S`` more and the report)."""
        sim, settings = self.simulation, self.config.sim
        dt = sim.timestep_s
        scale = settings.time_scale
        cycle_steps = max(1, round(1.0 / (settings.state_rate_hz * dt)))
        mocap_period_s, ft_period_s = 1.0 / settings.mocap_rate_hz, 1.0 / settings.force_torque_rate_hz
        start = time.monotonic() if start_monotonic_s is None else start_monotonic_s
        start_sim_s = next_mocap_s = next_ft_s = sim.time_s
        orphan_since_s: float | None = None
        while True:
            if orphan_since_s is None:
                try:
                    if control.poll():
                        request = control.recv()
                        if request == "stop":
                            return
                        control.send(self.ground_truth())
                except (EOFError, OSError):  # porter's process is gone (kill -9, a crash)
                    if settings.orphan_report is None:
                        return
                    orphan_since_s = sim.time_s
                    self.faults_applied.append({"kind": "porter_lost", "robot": None,
                                                "time_s": orphan_since_s})
            elif sim.time_s - orphan_since_s >= ORPHAN_RUN_S:
                assert settings.orphan_report is not None
                with open(settings.orphan_report, "w") as report:
                    json.dump(self.ground_truth(), report)
                return
            inject_due_faults(self, sim.time_s - start_sim_s)
            for name, fake in self.fakes.items():
                if fake.poll_commands():
                    self._received(name, fake.last_command)
            due = int(scale * (time.monotonic() - start) / dt) - self.steps
            if due > MAX_CATCH_UP_STEPS:  # cannot keep up: simulated time slips
                start += (due - MAX_CATCH_UP_STEPS) * dt / scale
                self.lag_s += (due - MAX_CATCH_UP_STEPS) * dt
                due = MAX_CATCH_UP_STEPS
            if due > 0:
                if self.steps > 0:  # the first cycle steps from the world's start
                    self.longest_hold_s = max(self.longest_hold_s, due * dt)
                    self.long_holds += due * dt > HOLD_REPORT_S + 1e-9
                sim.step(due)
                self.steps += due
                self._track()
            for name, fake in self.fakes.items():
                if name not in self.silent:
                    fake.publish_state()
            if sim.time_s >= next_mocap_s:
                if not self.mocap_stopped:
                    self.natnet.publish_frame()
                    network_faults(self)
                next_mocap_s += mocap_period_s * max(1, math.ceil((sim.time_s - next_mocap_s)
                                                                  / mocap_period_s))
            if self.can_node is not None and sim.time_s >= next_ft_s:
                self.can_node.publish_wrenches()
                next_ft_s += ft_period_s * max(1, math.ceil((sim.time_s - next_ft_s)
                                                            / ft_period_s))
            wake_s = start + (self.steps + cycle_steps) * dt / scale
            time.sleep(max(0.0, wake_s - time.monotonic()))

    def close(self) -> None:
        if self.can_node is not None:
            self.can_node.close()
            self.can_node.bus.shutdown()
        self.natnet.close()
        for fake in self.fakes.values():
            fake.close()


def serve(spec: WorldSpec, control: Connection, can_link: Connection) -> None:
    """World-process entry point: build, report ``("ready", endpoints)``, run, clean up.
    Ctrl-C at the terminal reaches the whole process group: the world ignores it and lives
    until the parent, which sits the robots down first, says ``"stop"``."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    name_this_process("porter-world")
    try:
        world = SimWorld(spec, can_link)
    except Exception as error:  # reported to the parent, which raises it
        control.send(("error", f"{type(error).__name__}: {error}"))
        return
    priority = spec.config.sim.world_priority
    problem = None if priority is None else set_process_priority(priority, "sim.world_priority")
    if problem is not None:
        print(f"porter-world: {problem} (normal scheduling instead)", file=sys.stderr)
    cpus = spec.config.sim.world_cpus
    problem = None if cpus is None else set_process_cpus(cpus, "sim.world_cpus")
    if problem is not None:
        print(f"porter-world: {problem} (any CPU instead)", file=sys.stderr)
    freeze_startup_objects()  # no full collection of the scene's objects while it runs
    try:
        start_monotonic_s = time.monotonic()
        control.send(("ready", world.endpoints(start_monotonic_s)))
        world.run(control, start_monotonic_s)
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass  # the parent is gone or interrupted
    finally:
        world.close()
