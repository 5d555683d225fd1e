from google.protobuf.internal import containers as _containers
from google.protobuf import descriptor as _descriptor
from google.protobuf import message as _message
from collections.abc import Iterable as _Iterable, Mapping as _Mapping
from typing import ClassVar as _ClassVar, Optional as _Optional, Union as _Union

DESCRIPTOR: _descriptor.FileDescriptor

class Hello(_message.Message):
    __slots__ = ("wire_version", "team", "agent", "problem_digest", "host", "pid", "solved")
    WIRE_VERSION_FIELD_NUMBER: _ClassVar[int]
    TEAM_FIELD_NUMBER: _ClassVar[int]
    AGENT_FIELD_NUMBER: _ClassVar[int]
    PROBLEM_DIGEST_FIELD_NUMBER: _ClassVar[int]
    HOST_FIELD_NUMBER: _ClassVar[int]
    PID_FIELD_NUMBER: _ClassVar[int]
    SOLVED_FIELD_NUMBER: _ClassVar[int]
    wire_version: int
    team: str
    agent: int
    problem_digest: str
    host: str
    pid: int
    solved: int
    def __init__(self, wire_version: _Optional[int] = ..., team: _Optional[str] = ..., agent: _Optional[int] = ..., problem_digest: _Optional[str] = ..., host: _Optional[str] = ..., pid: _Optional[int] = ..., solved: _Optional[int] = ...) -> None: ...

class SolveRequest(_message.Message):
    __slots__ = ("wire_version", "team", "agent", "sequence", "update", "iteration", "problem_digest", "initial_guess", "parameters", "lower_bounds", "upper_bounds", "has_multipliers", "constraint_multipliers", "bound_multipliers", "warm_start", "stop", "admm_iterations", "consensus", "duals")
    WIRE_VERSION_FIELD_NUMBER: _ClassVar[int]
    TEAM_FIELD_NUMBER: _ClassVar[int]
    AGENT_FIELD_NUMBER: _ClassVar[int]
    SEQUENCE_FIELD_NUMBER: _ClassVar[int]
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    ITERATION_FIELD_NUMBER: _ClassVar[int]
    PROBLEM_DIGEST_FIELD_NUMBER: _ClassVar[int]
    INITIAL_GUESS_FIELD_NUMBER: _ClassVar[int]
    PARAMETERS_FIELD_NUMBER: _ClassVar[int]
    LOWER_BOUNDS_FIELD_NUMBER: _ClassVar[int]
    UPPER_BOUNDS_FIELD_NUMBER: _ClassVar[int]
    HAS_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    CONSTRAINT_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    BOUND_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    WARM_START_FIELD_NUMBER: _ClassVar[int]
    STOP_FIELD_NUMBER: _ClassVar[int]
    ADMM_ITERATIONS_FIELD_NUMBER: _ClassVar[int]
    CONSENSUS_FIELD_NUMBER: _ClassVar[int]
    DUALS_FIELD_NUMBER: _ClassVar[int]
    wire_version: int
    team: str
    agent: int
    sequence: int
    update: int
    iteration: int
    problem_digest: str
    initial_guess: bytes
    parameters: bytes
    lower_bounds: bytes
    upper_bounds: bytes
    has_multipliers: bool
    constraint_multipliers: bytes
    bound_multipliers: bytes
    warm_start: bool
    stop: bool
    admm_iterations: int
    consensus: bytes
    duals: bytes
    def __init__(self, wire_version: _Optional[int] = ..., team: _Optional[str] = ..., agent: _Optional[int] = ..., sequence: _Optional[int] = ..., update: _Optional[int] = ..., iteration: _Optional[int] = ..., problem_digest: _Optional[str] = ..., initial_guess: _Optional[bytes] = ..., parameters: _Optional[bytes] = ..., lower_bounds: _Optional[bytes] = ..., upper_bounds: _Optional[bytes] = ..., has_multipliers: _Optional[bool] = ..., constraint_multipliers: _Optional[bytes] = ..., bound_multipliers: _Optional[bytes] = ..., warm_start: _Optional[bool] = ..., stop: _Optional[bool] = ..., admm_iterations: _Optional[int] = ..., consensus: _Optional[bytes] = ..., duals: _Optional[bytes] = ...) -> None: ...

class SharedTrajectory(_message.Message):
    __slots__ = ("wire_version", "team", "agent", "sequence", "update", "iteration", "shared")
    WIRE_VERSION_FIELD_NUMBER: _ClassVar[int]
    TEAM_FIELD_NUMBER: _ClassVar[int]
    AGENT_FIELD_NUMBER: _ClassVar[int]
    SEQUENCE_FIELD_NUMBER: _ClassVar[int]
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    ITERATION_FIELD_NUMBER: _ClassVar[int]
    SHARED_FIELD_NUMBER: _ClassVar[int]
    wire_version: int
    team: str
    agent: int
    sequence: int
    update: int
    iteration: int
    shared: bytes
    def __init__(self, wire_version: _Optional[int] = ..., team: _Optional[str] = ..., agent: _Optional[int] = ..., sequence: _Optional[int] = ..., update: _Optional[int] = ..., iteration: _Optional[int] = ..., shared: _Optional[bytes] = ...) -> None: ...

class IterationResult(_message.Message):
    __slots__ = ("stats", "shared", "consensus")
    STATS_FIELD_NUMBER: _ClassVar[int]
    SHARED_FIELD_NUMBER: _ClassVar[int]
    CONSENSUS_FIELD_NUMBER: _ClassVar[int]
    stats: SolveStats
    shared: bytes
    consensus: bytes
    def __init__(self, stats: _Optional[_Union[SolveStats, _Mapping]] = ..., shared: _Optional[bytes] = ..., consensus: _Optional[bytes] = ...) -> None: ...

class SolveStats(_message.Message):
    __slots__ = ("status", "success", "iterations", "wall_time_s", "objective", "constraint_violation", "cpu_time_s")
    STATUS_FIELD_NUMBER: _ClassVar[int]
    SUCCESS_FIELD_NUMBER: _ClassVar[int]
    ITERATIONS_FIELD_NUMBER: _ClassVar[int]
    WALL_TIME_S_FIELD_NUMBER: _ClassVar[int]
    OBJECTIVE_FIELD_NUMBER: _ClassVar[int]
    CONSTRAINT_VIOLATION_FIELD_NUMBER: _ClassVar[int]
    CPU_TIME_S_FIELD_NUMBER: _ClassVar[int]
    status: str
    success: bool
    iterations: int
    wall_time_s: float
    objective: float
    constraint_violation: float
    cpu_time_s: float
    def __init__(self, status: _Optional[str] = ..., success: _Optional[bool] = ..., iterations: _Optional[int] = ..., wall_time_s: _Optional[float] = ..., objective: _Optional[float] = ..., constraint_violation: _Optional[float] = ..., cpu_time_s: _Optional[float] = ...) -> None: ...

class SolveReply(_message.Message):
    __slots__ = ("wire_version", "team", "agent", "sequence", "update", "iteration", "decision", "constraint_multipliers", "bound_multipliers", "stats", "admm", "duals", "admm_failure")
    WIRE_VERSION_FIELD_NUMBER: _ClassVar[int]
    TEAM_FIELD_NUMBER: _ClassVar[int]
    AGENT_FIELD_NUMBER: _ClassVar[int]
    SEQUENCE_FIELD_NUMBER: _ClassVar[int]
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    ITERATION_FIELD_NUMBER: _ClassVar[int]
    DECISION_FIELD_NUMBER: _ClassVar[int]
    CONSTRAINT_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    BOUND_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    STATS_FIELD_NUMBER: _ClassVar[int]
    ADMM_FIELD_NUMBER: _ClassVar[int]
    DUALS_FIELD_NUMBER: _ClassVar[int]
    ADMM_FAILURE_FIELD_NUMBER: _ClassVar[int]
    wire_version: int
    team: str
    agent: int
    sequence: int
    update: int
    iteration: int
    decision: bytes
    constraint_multipliers: bytes
    bound_multipliers: bytes
    stats: SolveStats
    admm: _containers.RepeatedCompositeFieldContainer[IterationResult]
    duals: bytes
    admm_failure: str
    def __init__(self, wire_version: _Optional[int] = ..., team: _Optional[str] = ..., agent: _Optional[int] = ..., sequence: _Optional[int] = ..., update: _Optional[int] = ..., iteration: _Optional[int] = ..., decision: _Optional[bytes] = ..., constraint_multipliers: _Optional[bytes] = ..., bound_multipliers: _Optional[bytes] = ..., stats: _Optional[_Union[SolveStats, _Mapping]] = ..., admm: _Optional[_Iterable[_Union[IterationResult, _Mapping]]] = ..., duals: _Optional[bytes] = ..., admm_failure: _Optional[str] = ...) -> None: ...
