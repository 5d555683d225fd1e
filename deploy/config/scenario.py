"""Scenario files: the team, payload, obstacles, reference, controller, gait and disturbances of
one closed-loop run, as a typed and validated YAML document.

``load_scenario`` takes a path to a YAML file or the bare name of a shipped scenario (a file
stem in ``deploy/config/scenarios/``). Errors are ``ConfigError``s naming the file and the dotted path
of each bad field, including the cross-field checks (push targets, obstacle count, obstacles
inside their safety margin at the start, a duration too short for the reference).

World frame, SI units. The payload starts level at ``(0, 0, reference.payload_height_m)`` with
yaw ``reference.payload_yaw_rad``; each robot starts with its coupling point on the payload's.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, Field, ValidationError, field_validator, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from core.model.conventions import PAYLOAD_NAME
from core.model.obstacles import Obstacle
from core.model.strict_model import StrictModel
from core.model.team_settings import AgentSettings, PayloadSettings, TeamSettings
from core.nmpc.reference import WaypointReference
from core.nmpc.settings import AdmmSettings, ChannelSettings, MpcSettings, SafetySettings
from deploy.agents.zenoh_session import AgentNetwork
from deploy.config.files import ConfigError, load_settings

SCENARIO_DIR = Path(__file__).parent / "scenarios"
DEFAULT_SCENARIO = "two_go2"

Vector2 = tuple[float, float]
Vector3 = tuple[float, float, float]


class ObstacleSpec(StrictModel):
    """A vertical cylinder; ``position_m`` at t = 0, moving at constant ``velocity_m_s``."""

    position_m: Vector2
    radius_m: float = Field(gt=0)
    velocity_m_s: Vector2 = (0.0, 0.0)
    height_m: float = Field(0.6, gt=0)  # drawing only: the CBFs are planar

    def to_obstacle(self) -> Obstacle:
        return Obstacle(position_m=self.position_m, velocity_m_s=self.velocity_m_s,
                        radius_m=self.radius_m)


class PushSpec(StrictModel):
    """A constant world-frame force on a robot's trunk or on the payload for ``duration_s``."""

    time_s: float = Field(ge=0)
    duration_s: float = Field(gt=0)
    target: str  # a robot name or "payload"
    force_n: Vector3


class DisturbanceSettings(StrictModel):
    pushes: list[PushSpec] = []
    mocap_position_noise_m: float = Field(0.002, ge=0)  # std per coordinate
    mocap_angle_noise_rad: float = Field(0.005, ge=0)  # std per rotation-vector component


class ReferenceSpec(StrictModel):
    """The payload follows ``waypoints_m`` at ``speed_m_s`` at a constant height and yaw."""

    waypoints_m: list[Vector2] = Field(min_length=2)
    speed_m_s: float = Field(gt=0, le=1.0)
    payload_yaw_rad: float = 0.0
    payload_height_m: float = Field(0.45, gt=0)
    # Reference governor: while the payload lags the reference by more than this [m], the
    # reference waits (its clock stops) instead of running away from a blocked team; None: off.
    max_lag_m: float | None = Field(0.25, gt=0.05, le=5.0)

    @field_validator("waypoints_m")
    @classmethod
    def _starts_at_origin(cls, points: list[Vector2]) -> list[Vector2]:
        if points[0] != (0.0, 0.0):
            raise ValueError(f"the first waypoint must be (0, 0), where the team starts; "
                             f"got {points[0]}")
        for i in range(1, len(points)):
            if points[i] == points[i - 1]:
                raise ValueError(f"waypoint {i} repeats waypoint {i - 1} {points[i]}")
        return points

    @property
    def path_length_m(self) -> float:
        return float(sum(math.dist(a, b) for a, b in zip(self.waypoints_m[:-1],
                                                          self.waypoints_m[1:], strict=True)))

    def to_reference(self) -> WaypointReference:
        return WaypointReference(np.array(self.waypoints_m, dtype=float), self.speed_m_s,
                                 self.payload_height_m, self.payload_yaw_rad)


class PayloadSpec(StrictModel):
    """``mass_kg`` is what the controller models; ``true_mass_kg`` what is simulated."""

    mass_kg: float = Field(5.0, gt=0)
    true_mass_kg: float | None = Field(None, gt=0)  # None: the modelled mass
    size_m: Vector3 = (1.0, 0.5, 0.05)

    @field_validator("size_m")
    @classmethod
    def _positive_size(cls, size: Vector3) -> Vector3:
        if min(size) <= 0:
            raise ValueError(f"every side must be positive, got {size}")
        return size


def _admm_field(name: str) -> Any:
    """``core.nmpc.settings.AdmmSettings``'s field ``name``: its default and bounds."""
    return AdmmSettings.model_fields[name]


class ControllerSpec(StrictModel):
    mode: Literal["distributed", "centralized", "wrench-only"] = "distributed"
    # ADMM: the penalties and their bounds are declared once, in core.nmpc.settings
    admm_iterations: int = _admm_field("iterations")
    rho_state: float = _admm_field("rho_state")
    rho_wrench: float = _admm_field("rho_wrench")
    # ADMM local solves: worker processes of this machine (pipes), serially in this process,
    # or ``porter agent`` processes over Zenoh (``network``: where they meet).
    executor: Literal["process", "serial", "zenoh"] = "process"
    network: AgentNetwork = AgentNetwork()
    # ADMM messages through a lossy network (``admm.channel``; default: a perfect one)
    channel: ChannelSettings = ChannelSettings()
    # Simulation only: a plan takes effect when its computation would have finished: after
    # its measured update time, or after ``computation_delay_s`` when set (deterministic).
    model_computation_delay: bool = False
    computation_delay_s: float | None = Field(None, ge=0.0, le=0.5)
    # Simulation only, with a fixed computation_delay_s: the NMPC computes in a process of its
    # own while the world steps (the same results; two cores do both at once). Its executor
    # defaults to serial then (README, porter bench sim: an ADMM worker beside the NMPC's
    # process and the world is a third busy process for two cores); a set executor wins.
    overlap_computation: bool = False
    # Plan from the state predicted to the instant the plan takes effect
    # (core.nmpc.delay_compensation): "measured" uses the median of the last updates' delays
    # (0 in lockstep without model_computation_delay), a number fixes it [s], 0 turns it off.
    delay_compensation_s: Literal["measured"] | float = Field("measured")

    @field_validator("delay_compensation_s")
    @classmethod
    def _finite_delay(cls, value: str | float) -> str | float:
        if not isinstance(value, str) and not 0.0 <= value <= 0.5:
            raise ValueError(f"must be 'measured' or a delay in [0, 0.5] s, got {value}")
        return value

    @model_validator(mode="before")
    @classmethod
    def _overlap_defaults_to_serial(cls, data: Any) -> Any:
        if isinstance(data, dict) and data.get("overlap_computation") is True \
                and "executor" not in data:
            return {**data, "executor": "serial"}
        return data

    @model_validator(mode="after")
    def _overlap_needs_fixed_delay(self) -> ControllerSpec:
        if self.overlap_computation and (not self.model_computation_delay
                                         or self.computation_delay_s is None):
            raise ValueError(
                "overlap_computation needs model_computation_delay: true and a fixed "
                "computation_delay_s in [0, 0.5] s (a plan computed meanwhile must take effect "
                "at a time known in advance)")
        return self


class GaitSpec(StrictModel):
    period_s: float = Field(0.3, gt=0)
    duty_factor: float = Field(0.5, gt=0, lt=1)
    swing_height_m: float = Field(0.08, gt=0)


class Scenario(StrictModel):
    """One closed-loop run. Cross-field errors name the dotted path of the bad field."""

    name: str = Field(min_length=1)
    description: str = ""
    team: list[AgentSettings] = Field(min_length=2)
    payload: PayloadSpec
    obstacles: list[ObstacleSpec] = []
    reference: ReferenceSpec
    safety_distance_m: float = Field(0.6, gt=0)
    controller: ControllerSpec = ControllerSpec()
    gait: GaitSpec = GaitSpec()
    disturbances: DisturbanceSettings = DisturbanceSettings()
    duration_s: float = Field(gt=0)
    seed: int = Field(0, ge=0)
    goal_tolerance_m: float = Field(0.15, gt=0)
    # How a correct run of this scenario ends (the tests hold every shipped scenario to it; the
    # summary reports it beside the outcome): at the goal, or in a controlled stop (the team
    # brakes and sits down short of the goal: no fault, no fall, the margins kept).
    expected_outcome: Literal["goal", "controlled stop"] = "goal"

    @field_validator("team")
    @classmethod
    def _unique_names(cls, team: list[AgentSettings]) -> list[AgentSettings]:
        names = [agent.name for agent in team]
        if len(set(names)) != len(names):
            raise ValueError(f"robot names must be unique, got {names}")
        if PAYLOAD_NAME in names:
            raise ValueError(f"{PAYLOAD_NAME!r} is reserved for the payload (push targets)")
        return team

    @model_validator(mode="after")
    def _consistent(self) -> Scenario:
        problems: list[tuple[tuple[str | int, ...], str, Any]] = []
        names = [agent.name for agent in self.team]
        for i, push in enumerate(self.disturbances.pushes):
            if push.target != PAYLOAD_NAME and push.target not in names:
                problems.append((("disturbances", "pushes", i, "target"),
                                 f"unknown robot {push.target!r}; team is {names} "
                                 f"(or {PAYLOAD_NAME!r})", push.target))
            if push.time_s >= self.duration_s:
                problems.append((("disturbances", "pushes", i, "time_s"),
                                 f"{push.time_s} s is not before the end of the scenario "
                                 f"(duration_s {self.duration_s} s)", push.time_s))
        limit = SafetySettings().max_obstacles
        if len(self.obstacles) > limit:
            problems.append((("obstacles",), f"{len(self.obstacles)} obstacles, at most {limit} "
                             "(safety.max_obstacles)", len(self.obstacles)))
        for i, obstacle in enumerate(self.obstacles):
            margin = self.safety_distance_m + obstacle.radius_m
            for body, xy in self.initial_positions_m().items():
                distance = math.dist(obstacle.position_m, xy)
                if distance <= margin:
                    problems.append((("obstacles", i),
                                     f"starts inside its safety margin: {distance:.3f} m from "
                                     f"the {body} at t = 0, needs > {margin:.3f} m "
                                     f"(safety_distance_m {self.safety_distance_m} + radius_m "
                                     f"{obstacle.radius_m})", obstacle.position_m))
                    break
        needed = self.reference.path_length_m / self.reference.speed_m_s
        if needed > self.duration_s:
            problems.append((("duration_s",),
                             f"{self.duration_s} s is too short: the reference needs "
                             f"{needed:.2f} s to reach its goal ({self.reference.path_length_m:.2f} "
                             f"m at {self.reference.speed_m_s} m/s)", self.duration_s))
        if problems:
            raise ValidationError.from_exception_data(type(self).__name__, [
                InitErrorDetails(type=PydanticCustomError("scenario", message), loc=loc,
                                 input=value)
                for loc, message, value in problems])
        return self

    def initial_positions_m(self) -> dict[str, Vector2]:
        """Planar positions at t = 0: the payload centre (origin) and each robot's CoM."""
        yaw = self.reference.payload_yaw_rad
        c, s = math.cos(yaw), math.sin(yaw)
        positions: dict[str, Vector2] = {"payload centre": (0.0, 0.0)}
        for agent in self.team:
            dx = agent.coupling_point_in_payload_m[0] - agent.coupling_point_in_robot_m[0]
            dy = agent.coupling_point_in_payload_m[1] - agent.coupling_point_in_robot_m[1]
            positions[f"robot {agent.name!r}"] = (c * dx - s * dy, s * dx + c * dy)
        return positions

    @property
    def true_payload_mass_kg(self) -> float:
        if self.payload.true_mass_kg is None:
            return self.payload.mass_kg
        return self.payload.true_mass_kg

    def with_controller(self, **update: Any) -> Scenario:
        """This scenario with ``controller`` fields replaced, validated as a whole (a conflict
        is a ConfigError naming the field)."""
        current = self.controller
        try:
            controller = ControllerSpec.model_validate(
                {**current.model_dump(include=current.model_fields_set), **update})
        except ValidationError as error:
            detail = error.errors()[0]
            where = ".".join(str(part) for part in ("controller", *detail["loc"]))
            raise ConfigError(f"{where}: {detail['msg']}") from None
        return self.model_copy(update={"controller": controller})

    def team_settings(self) -> TeamSettings:
        """The controller's team model (modelled payload mass)."""
        return TeamSettings(agents=list(self.team), payload=PayloadSettings(
            mass_kg=self.payload.mass_kg, size_m=self.payload.size_m))

    def core_obstacles(self) -> list[Obstacle]:
        return [obstacle.to_obstacle() for obstacle in self.obstacles]

    def mpc_settings(self, base: MpcSettings | None = None, base_source: str = "--config"
                     ) -> MpcSettings:
        """``base`` (default: the paper's) with this scenario's safety distance and ADMM
        parameters; the wrench-only mode also drops the coupling constraints and sets
        ``admm.rho_state`` to 0 (the paper's ablation, see ``core.admm.admm_mpc``).

        Precedence, field by field: a value set explicitly in one place (``base``'s YAML,
        named ``base_source`` in errors, or this scenario's file) wins over the other's
        default; set explicitly in both to different values is a ``ConfigError`` naming both.
        """
        base = base or MpcSettings()
        control = self.controller
        admm = {
            field: _one_value(f"admm.{field}", base.admm, field, base_source,
                              f"controller.{spec}", control, spec, self.name)
            for field, spec in (("iterations", "admm_iterations"), ("rho_state", "rho_state"),
                                ("rho_wrench", "rho_wrench"), ("channel", "channel"))
        }
        distance = _one_value("safety.safety_distance_m", base.safety, "safety_distance_m",
                              base_source, "safety_distance_m", self, "safety_distance_m",
                              self.name)
        coupling = base.coupling
        if control.mode == "wrench-only":
            # The scenario's own rho_state is meant for its distributed mode (``--mode``
            # switches modes); an explicit non-zero one in ``base`` is a contradiction.
            explicit_rho = _explicit(base.admm, "rho_state") and base.admm.rho_state != 0.0
            explicit_coupling = _explicit(base.coupling, "enabled") and base.coupling.enabled
            if explicit_rho or explicit_coupling:
                what = ("coupling.enabled: true" if explicit_coupling
                        else f"admm.rho_state = {base.admm.rho_state}")
                raise ConfigError(f"{what} in {base_source} conflicts with controller.mode: "
                                  f"wrench-only of scenario {self.name!r}, which sets "
                                  "rho_state 0 and no coupling")
            admm["rho_state"] = 0.0
            coupling = coupling.model_copy(update={"enabled": False})
        return base.model_copy(update={
            "safety": base.safety.model_copy(update={"safety_distance_m": distance}),
            "admm": base.admm.model_copy(update=admm),
            "coupling": coupling,
        })


def _explicit(model: BaseModel, field: str) -> bool:
    return field in model.model_fields_set


def _one_value(base_name: str, base: BaseModel, base_field: str, base_source: str,
               scenario_name: str, scenario: BaseModel, scenario_field: str,
               scenario_label: str) -> Any:
    """The explicitly set one of two values (the scenario's when neither is); both explicit
    and different is an error naming both places."""
    base_value = getattr(base, base_field)
    scenario_value = getattr(scenario, scenario_field)
    in_base, in_scenario = _explicit(base, base_field), _explicit(scenario, scenario_field)
    if in_base and in_scenario and base_value != scenario_value:
        raise ConfigError(f"{base_name} = {base_value} in {base_source} conflicts with "
                          f"{scenario_name} = {scenario_value} in scenario {scenario_label!r}; "
                          "set it in one place")
    return base_value if in_base else scenario_value


def shipped_scenarios() -> list[str]:
    """Names (file stems) of the scenarios in ``deploy/config/scenarios/``, sorted."""
    return sorted(path.stem for path in SCENARIO_DIR.glob("*.yaml"))


def scenario_path(path_or_name: Path | str) -> Path:
    """The file of a shipped scenario's name, or ``path_or_name`` itself if it is a path."""
    path = Path(path_or_name)
    text = str(path_or_name)
    if (isinstance(path_or_name, Path) or path.is_file() or path.suffix in (".yaml", ".yml")
            or "/" in text or "\\" in text):
        return path
    if text not in shipped_scenarios():
        raise ConfigError(f"unknown scenario {text!r}; shipped scenarios: "
                          f"{', '.join(shipped_scenarios())} (or give the path of a YAML file)")
    return SCENARIO_DIR / f"{text}.yaml"


def load_scenario(path_or_name: Path | str = DEFAULT_SCENARIO) -> Scenario:
    """Load and validate a scenario file, or a shipped scenario by name."""
    return load_settings(scenario_path(path_or_name), Scenario)
