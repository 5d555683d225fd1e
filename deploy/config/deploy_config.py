"""``porter deploy`` configuration: which scenario, which robots on which links, MoCap, CAN,
safety thresholds, posture timing, loop rates, recorder, and the ``--backend sim`` world.

One YAML file per team (``deploy/config/deployments/``), validated here; unknown fields are errors and
every error names the file and the dotted path of the bad field (``deploy.config.files``).
The scenario (a shipped name or a YAML path, relative paths from the config's directory)
supplies the team, payload, obstacles, reference, gait and controller; ``robots`` must name
exactly the scenario's team.

Network: nothing binds beyond loopback unless ``network_interface`` names an interface
(e.g. ``enp3s0``): with it None, DDS runs on ``lo`` and every local IP address (A1 UDP,
NatNet) must be a loopback address (127.0.0.0/8). Units: SI, rates in Hz, times in seconds.
"""

from __future__ import annotations

import ipaddress
import socket
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, ValidationError, field_validator, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from core.model.conventions import PAYLOAD_NAME
from core.model.strict_model import StrictModel
from deploy.config.files import ConfigError, load_settings
from deploy.config.scenario import Scenario, load_scenario, scenario_path, shipped_scenarios
from deploy.config.sim_faults import GO2_FAULTS, SimFault
from deploy.recording.flight_recorder import RecorderSettings
from deploy.safety.settings import SupervisorSettings, WatchdogSettings

CONFIG_DIR = Path(__file__).parent / "deployments"


class Go2Link(StrictModel):
    """A Go2 over CycloneDDS (``drivers.unitree.go2_driver``): ``<topic_prefix>/rt/lowstate`` etc."""

    driver: Literal["go2"]
    domain_id: int = Field(0, ge=0, le=232)
    topic_prefix: str = ""  # "" = the robot's own rt/lowcmd, rt/lowstate
    release_sport_mode: bool = True  # ask the motion switcher before low-level control
    link_timeout_s: float = Field(0.1, gt=0, le=1.0)
    contact_threshold_n: float = Field(20.0, ge=0, le=500.0)
    foot_force_n_per_count: float = Field(1.0, gt=0, le=100.0)  # UNVERIFIED scale of the counts
    # refuse states whose CRC-32 does not match (as unitree_sdk2_python computes it); off only
    # for a firmware that leaves LowState_.crc unfilled (UNVERIFIED which ones do)
    check_state_crc: bool = True


class A1Link(StrictModel):
    """An A1 over UDP (``drivers.unitree.a1_driver``, unitree_legged_sdk 3.3 low level)."""

    driver: Literal["a1"]
    robot_address: tuple[str, int] = ("192.168.123.10", 8007)
    local_address: str = "127.0.0.1"  # must be on the robot's network to reach it
    local_port: int = Field(8080, ge=0, le=65535)  # 0: any free port
    link_timeout_s: float = Field(0.1, gt=0, le=1.0)
    contact_threshold_n: float = Field(20.0, ge=0, le=500.0)
    foot_force_n_per_count: float = Field(1.0, gt=0, le=100.0)


RobotLink = Annotated[Go2Link | A1Link, Field(discriminator="driver")]


class MocapConfig(StrictModel):
    """OptiTrack NatNet (``drivers.natnet.client``). ``bodies`` maps porter's names (robot
    names, ``payload``) to Motive rigid-body names (default: the same name); ``body_ids`` maps
    Motive names to streaming ids (None: learnt from MODELDEF). The rigid body's pivot must be
    the trunk origin (URDF root link) of each robot and the payload box centre."""

    server_address: str = "127.0.0.1"
    local_address: str = "127.0.0.1"  # interface to bind / join the multicast group on
    # NatNet's well-known ports and group (drivers.natnet.protocol; a test holds them equal)
    command_port: int = Field(1510, ge=0, le=65535)
    data_port: int = Field(1511, ge=0, le=65535)  # multicast only (unicast frames come
    # back to the socket that sent CONNECT, as from Motive)
    multicast: bool = False
    multicast_group: str = "239.255.42.99"
    bodies: dict[str, str] = {}
    body_ids: dict[str, int] | None = None
    obstacle_bodies: list[str | None] = []  # per scenario obstacle: a body whose position is used
    stale_timeout_s: float = Field(0.1, gt=0, le=1.0)
    velocity_window_s: float = Field(0.08, gt=0, le=1.0)  # least-squares velocity from poses this old
    # a body whose pose repeats exactly in more new frames than this is frozen (unseen): a
    # tracked pose always jitters; 12 frames = 0.1 s at 120 Hz
    max_repeated_frames: int = Field(12, ge=1, le=1000)


class CanConfig(StrictModel):
    """python-can bus of the e-stop heartbeat and the coupling F/T sensors."""

    interface: str = "socketcan"
    channel: str = "can0"
    force_torque: bool = True  # F/T sensors present: robot i of ``robots:`` is sensor i


class PostureConfig(StrictModel):
    """Stand up / sit down: joint PD targets interpolated (smoothstep) between the measured
    posture and the SRDF standing posture, or the sitting posture (base lowered by
    ``sit_lowering_m`` with the feet in place)."""

    stand_up_s: float = Field(2.5, gt=0, le=30.0)
    sit_down_s: float = Field(2.0, gt=0, le=30.0)
    settle_s: float = Field(0.5, ge=0, le=10.0)  # hold standing before arming
    sit_lowering_m: float = Field(0.1, ge=0.0, le=0.2)
    kp: float = Field(60.0, gt=0, le=200.0)  # [N m/rad]
    kd: float = Field(3.0, gt=0, le=20.0)  # [N m s/rad]
    final_damping_s: float = Field(0.5, ge=0, le=10.0)  # damping after sitting down


class RatesConfig(StrictModel):
    wbc_hz: float = Field(500.0, ge=100.0, le=2000.0)  # the motors' firmware wants >= 100 Hz
    nmpc_hz: float = Field(60.0, ge=10.0, le=200.0)
    max_plan_age_s: float = Field(0.25, gt=0, le=1.0)  # older active plan while running: stop
    max_armed_s: float = Field(2.0, gt=0, le=30.0)  # ARMED this long with no first plan: stop
    # SCHED_FIFO priority of the loop's thread while it runs (deploy.compute.realtime); null:
    # normal scheduling. On robots a priority that cannot be set is an error; in simulation
    # the loop then runs at normal priority with a warning.
    loop_priority: int | None = Field(None, ge=1, le=99)
    # the CPU the loop's process (its thread and helper threads) runs on while the loop runs
    # (deploy.compute.realtime); null: any.
    # A CPU this process may not use is an error on robots, a warning in simulation.
    loop_cpu: int | None = Field(None, ge=0, le=1023)


def _distinct_cpus(cls: type, cpus: list[int] | None) -> list[int] | None:
    """A list of CPUs names each at most once (``nmpc.cpus``, ``sim.world_cpus``)."""
    if cpus is not None and len(set(cpus)) != len(cpus):
        raise ValueError(f"names a CPU twice: {cpus}")
    return cpus


class NmpcRunConfig(StrictModel):
    """Where the NMPC runs. ``runner``: ``process``, a process of its own (off the loop's
    interpreter lock), or ``thread``, a thread of the loop's process. ``executor``: the ADMM
    local solves ``serial`` in the NMPC's process, one ``process`` per agent, or ``zenoh``:
    ``porter agent`` processes over Zenoh (the scenario's ``controller.network``); None keeps
    the scenario's ``controller.executor`` (a different explicit value there is an error).
    ``admm_iterations``: ADMM iterations per NMPC update on this computer; None keeps the
    scenario's ``controller.admm_iterations`` (the paper's 2; a different explicit value there
    is an error)."""

    runner: Literal["process", "thread"] = "process"
    executor: Literal["serial", "process", "zenoh"] | None = None
    admm_iterations: int | None = Field(None, ge=1, le=20)
    # nice value of the NMPC's process (runner: process; deploy.compute.realtime): below 0 it
    # gets the CPU before normal-priority processes. A value it cannot take is an error on
    # robots, a warning (and 0) in simulation.
    nice: int = Field(0, ge=-20, le=19)
    # the CPUs of the NMPC's process and its ADMM workers (runner: process); null: any.
    # Apart from rates.loop_cpu; unavailable ones as for rates.loop_cpu.
    cpus: list[Annotated[int, Field(ge=0, le=1023)]] | None = Field(None, min_length=1)

    _distinct = field_validator("cpus")(_distinct_cpus)


class PreflightConfig(StrictModel):
    timeout_s: float = Field(5.0, gt=0, le=120.0)  # wait this long for every link, then report
    max_joint_velocity_rad_s: float = Field(1.0, gt=0, le=5.0)  # robots must be at rest
    start_tolerance_m: float = Field(0.3, gt=0, le=2.0)  # payload this near the scenario's start


class SimConfig(StrictModel):
    """``--backend sim`` only: the MuJoCo world behind the fakes (``deploy.sim_backend.backend``)."""

    # simulated seconds per wall-clock second, for the world and for the loop's clock (which
    # the sim backend scales alike): 1 = real time; below 1 a slow-motion run for machines too
    # slow for real time (every rate, timeout and budget is then in simulated seconds)
    time_scale: float = Field(1.0, gt=0, le=1.0)
    mocap_rate_hz: float = Field(120.0, gt=0)
    mocap_latency_s: float = Field(0.0, ge=0)
    mocap_dropout_probability: float = Field(0.0, ge=0, le=1)
    force_torque_rate_hz: float = Field(100.0, gt=0)
    state_rate_hz: float = Field(500.0, gt=0)  # LowState per robot (Go2: 500 Hz)
    start_lowering_m: float = Field(0.1, ge=0.0, le=0.2)  # robots start crouched this much
    # The robots' firmware when commands stop: None holds the last command forever (the unsafe
    # case, as a Go2 does); a value [s]: joint damping once no command came for that long.
    firmware_command_timeout_s: float | None = Field(None, gt=0, le=1.0)
    # SCHED_FIFO priority of the world's process (every thread: physics and the fakes' DDS),
    # below rates.loop_priority: the physics never waits behind the NMPC or porter's helper
    # threads; null: normal scheduling. One that cannot be set: a warning, normal scheduling.
    world_priority: int | None = Field(None, ge=1, le=98)
    # the CPUs of the world's process (every thread), apart from rates.loop_cpu; null: any.
    # Beside an NMPC at a positive nice on the same core, the world gets that core first
    # without any privilege. Unavailable ones: a warning, any CPU.
    world_cpus: list[Annotated[int, Field(ge=0, le=1023)]] | None = Field(None, min_length=1)
    # ``safety`` fields replaced for this backend only (e.g. budgets this machine cannot meet)
    safety_overrides: dict[str, float | int] = {}
    # faults for tests: what the fake world leaves out
    can_node: bool = True  # False: no e-stop heartbeat, no F/T
    untracked_bodies: list[str] = []  # streamed with tracking invalid (Motive lost them)
    silent_robots: list[str] = []  # their fakes never publish a state
    faults: list[SimFault] = []  # injected while running (see SimFault)
    # drills of kill -9: when porter's process is gone, the world runs on for ORPHAN_RUN_S
    # simulated seconds (what reaches the motors now comes from the watchdog alone), then
    # writes its ground truth as JSON to this file; None: the world ends with porter
    orphan_report: str | None = None

    _distinct = field_validator("world_cpus")(_distinct_cpus)


class DeployConfig(StrictModel):
    """One team's deployment. See the module docstring for the network rule."""

    scenario: str
    network_interface: str | None = None
    robots: dict[str, RobotLink]
    mocap: MocapConfig = MocapConfig()
    can: CanConfig = CanConfig()
    safety: SupervisorSettings = SupervisorSettings()
    posture: PostureConfig = PostureConfig()
    rates: RatesConfig = RatesConfig()
    nmpc: NmpcRunConfig = NmpcRunConfig()
    watchdog: WatchdogSettings = WatchdogSettings()
    preflight: PreflightConfig = PreflightConfig()
    recorder: RecorderSettings = RecorderSettings()
    sim: SimConfig = SimConfig()

    @field_validator("network_interface")
    @classmethod
    def _interface_on_this_host(cls, name: str | None) -> str | None:
        # Checked at load, so a typo is an error naming the field, not a DDS domain that
        # fails to start (or, pasted into CycloneDDS's XML, a different configuration).
        if name is None:
            return None
        available = sorted(interface for _, interface in socket.if_nameindex())
        if name not in available:
            raise ValueError(f"no network interface {name!r} on this host; it has "
                             f"{', '.join(available)}")
        return name

    @model_validator(mode="after")
    def _valid_sim_safety(self) -> DeployConfig:
        try:
            self.sim_safety()
        except ValidationError as error:
            raise ValidationError.from_exception_data(type(self).__name__, [
                InitErrorDetails(type=PydanticCustomError("safety", "{message}", {
                    "message": item["msg"]}), loc=("sim", "safety_overrides", *item["loc"]),
                    input=item["input"]) for item in error.errors()]) from None
        return self

    @model_validator(mode="after")
    def _world_below_loop(self) -> DeployConfig:
        world, loop = self.sim.world_priority, self.rates.loop_priority
        if world is not None and (loop is None or world >= loop):
            raise ValueError(f"sim.world_priority: {world} must be below rates.loop_priority "
                             f"({loop}): the loop's ticks come first; lower it or set it null")
        return self

    @model_validator(mode="after")
    def _cpus_apart(self) -> DeployConfig:
        loop_cpu = self.rates.loop_cpu
        for setting, cpus in (("nmpc.cpus", self.nmpc.cpus),
                              ("sim.world_cpus", self.sim.world_cpus)):
            if cpus is not None and loop_cpu in cpus:
                raise ValueError(f"{setting}: {cpus} includes rates.loop_cpu {loop_cpu}: the "
                                 "loop's core is its own; set them apart or one of them to null")
        return self

    @model_validator(mode="after")
    def _budgets_can_trip(self) -> DeployConfig:
        for where, safety in (("safety", self.safety), ("sim.safety_overrides", None)):
            settings = safety if safety is not None else self.sim_safety()
            # a budget trips when MORE than it are counted in the window: it must be below
            # the most that can be counted there
            for budget, rate, counted in (
                    ("deadline_overrun_budget", "nmpc_hz", "updates"),
                    ("loop_overrun_budget", "wbc_hz", "loop ticks")):
                most = getattr(self.rates, rate) * settings.deadline_window_s
                value = getattr(settings, budget)
                if value >= most:
                    raise ValueError(
                        f"{where}: {budget} {value} can never be used up: at most "
                        f"rates.{rate} x deadline_window_s = {most:g} {counted} fit in the "
                        f"window; set it below {most:g}")
        return self

    def sim_safety(self) -> SupervisorSettings:
        """``safety`` with ``sim.safety_overrides`` applied (``--backend sim``)."""
        return SupervisorSettings.model_validate({**self.safety.model_dump(),
                                                  **self.sim.safety_overrides})

    @model_validator(mode="after")
    def _loopback_unless_interface(self) -> DeployConfig:
        if self.network_interface is not None:
            return self
        problems: list[tuple[tuple[str, ...], str]] = []
        for name, link in self.robots.items():
            if isinstance(link, A1Link) and not _is_loopback(link.local_address):
                problems.append((("robots", name, "local_address"), link.local_address))
        if not _is_loopback(self.mocap.local_address):
            problems.append((("mocap", "local_address"), self.mocap.local_address))
        if problems:
            raise ValidationError.from_exception_data(type(self).__name__, [
                InitErrorDetails(type=PydanticCustomError(
                    "network", "{address} is not a loopback address: set network_interface "
                    "to bind beyond loopback", {"address": address}), loc=loc, input=address)
                for loc, address in problems])
        return self

    def body_name(self, name: str) -> str:
        """Motive's rigid-body name of porter's body ``name`` (a robot or ``payload``)."""
        return self.mocap.bodies.get(name, name)


def _is_loopback(address: str) -> bool:
    try:
        return ipaddress.ip_address(address).is_loopback
    except ValueError:
        return address == "localhost"


def config_path(path_or_name: Path | str) -> Path:
    """A shipped config's name (``two_go2``) or a path."""
    path = Path(path_or_name)
    if path.suffix in (".yaml", ".yml") or path.exists() or "/" in str(path_or_name):
        return path
    return CONFIG_DIR / f"{path_or_name}.yaml"


def _with_nmpc_overrides(path: Path, config: DeployConfig, scenario: Scenario) -> Scenario:
    """The scenario with ``nmpc.executor`` / ``nmpc.admm_iterations`` where the config sets
    them; ``ConfigError`` where the scenario sets a different value explicitly."""
    controller = scenario.controller
    for field in ("executor", "admm_iterations"):  # the same name in both models
        value = getattr(config.nmpc, field)
        if value is None or value == getattr(controller, field):
            continue
        if field in controller.model_fields_set:
            raise ConfigError(f"{path}: nmpc.{field}: {value!r}, but the scenario sets "
                              f"controller.{field}: {getattr(controller, field)!r}; set one "
                              "of them")
        controller = controller.model_copy(update={field: value})
    return scenario.model_copy(update={"controller": controller})


def load_deploy_config(path_or_name: Path | str) -> tuple[DeployConfig, Scenario]:
    """The config and its scenario, cross-checked (robots = the scenario's team, one MoCap
    obstacle entry at most per obstacle). Raises ``ConfigError`` naming the field."""
    path = config_path(path_or_name)
    if not path.exists():
        shipped = sorted(p.stem for p in CONFIG_DIR.glob("*.yaml"))
        raise ConfigError(f"no deploy config {str(path_or_name)!r} ({path} does not exist); "
                          f"shipped configs: {', '.join(shipped)} (or give the path of a "
                          "YAML file)")
    config = load_settings(path, DeployConfig)
    reference = Path(config.scenario)
    relative = path.parent / reference
    if reference.suffix in (".yaml", ".yml") and not reference.is_absolute() \
            and not reference.exists() and relative.exists():
        reference = relative
    try:
        scenario = load_scenario(reference if reference.suffix else config.scenario)
    except ConfigError as error:
        raise ConfigError(f"{path}: scenario: {error} (shipped: "
                          f"{', '.join(shipped_scenarios())})") from None
    scenario = _with_nmpc_overrides(path, config, scenario)
    if config.nmpc.runner == "thread":
        for field, value, unset in (("nice", config.nmpc.nice, 0), ("cpus", config.nmpc.cpus, None)):
            if value != unset:
                raise ConfigError(f"{path}: nmpc.{field}: {value} needs nmpc.runner: process "
                                  "(a thread runs in the loop's process); set one of them")
    team = [agent.name for agent in scenario.team]
    if sorted(config.robots) != sorted(team):
        missing = [name for name in team if name not in config.robots]
        extra = [name for name in config.robots if name not in team]
        raise ConfigError(f"{path}: robots: must name the scenario's team {team} "
                          f"(scenario {scenario_path(config.scenario)}); missing {missing}, "
                          f"unknown {extra}")
    for name, link in config.robots.items():
        robot_type = next(agent.robot_type for agent in scenario.team if agent.name == name)
        if link.driver != robot_type:
            raise ConfigError(f"{path}: robots.{name}.driver: {link.driver!r} but the "
                              f"scenario's {name} is a {robot_type!r}")
    if len(config.mocap.obstacle_bodies) > len(scenario.obstacles):
        raise ConfigError(f"{path}: mocap.obstacle_bodies: {len(config.mocap.obstacle_bodies)}"
                          f" entries for {len(scenario.obstacles)} scenario obstacles")
    for field_name, names in (("sim.untracked_bodies", config.sim.untracked_bodies),
                              ("sim.silent_robots", config.sim.silent_robots),
                              ("sim.faults.robot", [f.robot for f in config.sim.faults
                                                    if f.robot is not None])):
        known = [*team, PAYLOAD_NAME] if field_name == "sim.untracked_bodies" else team
        unknown = [name for name in names if name not in known]
        if unknown:
            raise ConfigError(f"{path}: {field_name}: unknown {unknown}; known {known}")
    for fault in config.sim.faults:
        if fault.kind in GO2_FAULTS and not isinstance(config.robots[str(fault.robot)],
                                                       Go2Link):
            raise ConfigError(f"{path}: sim.faults: {fault.kind} needs a Go2 (its fake), "
                              f"{fault.robot} is not one")
    return config, scenario
