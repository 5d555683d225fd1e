from google.protobuf.internal import containers as _containers
from google.protobuf.internal import enum_type_wrapper as _enum_type_wrapper
from google.protobuf import descriptor as _descriptor
from google.protobuf import message as _message
from collections.abc import Iterable as _Iterable, Mapping as _Mapping
from typing import ClassVar as _ClassVar, Optional as _Optional, Union as _Union

DESCRIPTOR: _descriptor.FileDescriptor

class Array(_message.Message):
    __slots__ = ("shape", "values")
    SHAPE_FIELD_NUMBER: _ClassVar[int]
    VALUES_FIELD_NUMBER: _ClassVar[int]
    shape: _containers.RepeatedScalarFieldContainer[int]
    values: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, shape: _Optional[_Iterable[int]] = ..., values: _Optional[_Iterable[float]] = ...) -> None: ...

class RobotState(_message.Message):
    __slots__ = ("time_s", "robot", "position_in_world_m", "quaternion_wxyz", "linear_velocity_in_world_m_s", "angular_velocity_in_body_rad_s", "joint_position_rad", "joint_velocity_rad_s", "joint_torque_nm", "foot_normal_force_n", "foot_contact")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ROBOT_FIELD_NUMBER: _ClassVar[int]
    POSITION_IN_WORLD_M_FIELD_NUMBER: _ClassVar[int]
    QUATERNION_WXYZ_FIELD_NUMBER: _ClassVar[int]
    LINEAR_VELOCITY_IN_WORLD_M_S_FIELD_NUMBER: _ClassVar[int]
    ANGULAR_VELOCITY_IN_BODY_RAD_S_FIELD_NUMBER: _ClassVar[int]
    JOINT_POSITION_RAD_FIELD_NUMBER: _ClassVar[int]
    JOINT_VELOCITY_RAD_S_FIELD_NUMBER: _ClassVar[int]
    JOINT_TORQUE_NM_FIELD_NUMBER: _ClassVar[int]
    FOOT_NORMAL_FORCE_N_FIELD_NUMBER: _ClassVar[int]
    FOOT_CONTACT_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    robot: str
    position_in_world_m: _containers.RepeatedScalarFieldContainer[float]
    quaternion_wxyz: _containers.RepeatedScalarFieldContainer[float]
    linear_velocity_in_world_m_s: _containers.RepeatedScalarFieldContainer[float]
    angular_velocity_in_body_rad_s: _containers.RepeatedScalarFieldContainer[float]
    joint_position_rad: _containers.RepeatedScalarFieldContainer[float]
    joint_velocity_rad_s: _containers.RepeatedScalarFieldContainer[float]
    joint_torque_nm: _containers.RepeatedScalarFieldContainer[float]
    foot_normal_force_n: _containers.RepeatedScalarFieldContainer[float]
    foot_contact: _containers.RepeatedScalarFieldContainer[bool]
    def __init__(self, time_s: _Optional[float] = ..., robot: _Optional[str] = ..., position_in_world_m: _Optional[_Iterable[float]] = ..., quaternion_wxyz: _Optional[_Iterable[float]] = ..., linear_velocity_in_world_m_s: _Optional[_Iterable[float]] = ..., angular_velocity_in_body_rad_s: _Optional[_Iterable[float]] = ..., joint_position_rad: _Optional[_Iterable[float]] = ..., joint_velocity_rad_s: _Optional[_Iterable[float]] = ..., joint_torque_nm: _Optional[_Iterable[float]] = ..., foot_normal_force_n: _Optional[_Iterable[float]] = ..., foot_contact: _Optional[_Iterable[bool]] = ...) -> None: ...

class JointCommand(_message.Message):
    __slots__ = ("time_s", "robot", "torque_nm", "position_rad", "velocity_rad_s", "kp", "kd")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ROBOT_FIELD_NUMBER: _ClassVar[int]
    TORQUE_NM_FIELD_NUMBER: _ClassVar[int]
    POSITION_RAD_FIELD_NUMBER: _ClassVar[int]
    VELOCITY_RAD_S_FIELD_NUMBER: _ClassVar[int]
    KP_FIELD_NUMBER: _ClassVar[int]
    KD_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    robot: str
    torque_nm: _containers.RepeatedScalarFieldContainer[float]
    position_rad: _containers.RepeatedScalarFieldContainer[float]
    velocity_rad_s: _containers.RepeatedScalarFieldContainer[float]
    kp: _containers.RepeatedScalarFieldContainer[float]
    kd: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, time_s: _Optional[float] = ..., robot: _Optional[str] = ..., torque_nm: _Optional[_Iterable[float]] = ..., position_rad: _Optional[_Iterable[float]] = ..., velocity_rad_s: _Optional[_Iterable[float]] = ..., kp: _Optional[_Iterable[float]] = ..., kd: _Optional[_Iterable[float]] = ...) -> None: ...

class WbcTick(_message.Message):
    __slots__ = ("time_s", "robot", "success", "status", "solve_time_s", "stance", "contact_force_in_world_n", "foot_target_in_world_m")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ROBOT_FIELD_NUMBER: _ClassVar[int]
    SUCCESS_FIELD_NUMBER: _ClassVar[int]
    STATUS_FIELD_NUMBER: _ClassVar[int]
    SOLVE_TIME_S_FIELD_NUMBER: _ClassVar[int]
    STANCE_FIELD_NUMBER: _ClassVar[int]
    CONTACT_FORCE_IN_WORLD_N_FIELD_NUMBER: _ClassVar[int]
    FOOT_TARGET_IN_WORLD_M_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    robot: str
    success: bool
    status: str
    solve_time_s: float
    stance: _containers.RepeatedScalarFieldContainer[float]
    contact_force_in_world_n: _containers.RepeatedScalarFieldContainer[float]
    foot_target_in_world_m: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, time_s: _Optional[float] = ..., robot: _Optional[str] = ..., success: _Optional[bool] = ..., status: _Optional[str] = ..., solve_time_s: _Optional[float] = ..., stance: _Optional[_Iterable[float]] = ..., contact_force_in_world_n: _Optional[_Iterable[float]] = ..., foot_target_in_world_m: _Optional[_Iterable[float]] = ...) -> None: ...

class PayloadEstimate(_message.Message):
    __slots__ = ("time_s", "estimate", "has_ground_truth", "true_position_in_world_m", "true_quaternion_wxyz")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ESTIMATE_FIELD_NUMBER: _ClassVar[int]
    HAS_GROUND_TRUTH_FIELD_NUMBER: _ClassVar[int]
    TRUE_POSITION_IN_WORLD_M_FIELD_NUMBER: _ClassVar[int]
    TRUE_QUATERNION_WXYZ_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    estimate: _containers.RepeatedScalarFieldContainer[float]
    has_ground_truth: bool
    true_position_in_world_m: _containers.RepeatedScalarFieldContainer[float]
    true_quaternion_wxyz: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, time_s: _Optional[float] = ..., estimate: _Optional[_Iterable[float]] = ..., has_ground_truth: _Optional[bool] = ..., true_position_in_world_m: _Optional[_Iterable[float]] = ..., true_quaternion_wxyz: _Optional[_Iterable[float]] = ...) -> None: ...

class GroundTruth(_message.Message):
    __slots__ = ("time_s", "payload_position_in_world_m", "payload_yaw_rad", "desired_payload_position_in_world_m", "desired_payload_yaw_rad", "pair_names", "h_m", "robot_names", "coupling_error_m")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    PAYLOAD_POSITION_IN_WORLD_M_FIELD_NUMBER: _ClassVar[int]
    PAYLOAD_YAW_RAD_FIELD_NUMBER: _ClassVar[int]
    DESIRED_PAYLOAD_POSITION_IN_WORLD_M_FIELD_NUMBER: _ClassVar[int]
    DESIRED_PAYLOAD_YAW_RAD_FIELD_NUMBER: _ClassVar[int]
    PAIR_NAMES_FIELD_NUMBER: _ClassVar[int]
    H_M_FIELD_NUMBER: _ClassVar[int]
    ROBOT_NAMES_FIELD_NUMBER: _ClassVar[int]
    COUPLING_ERROR_M_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    payload_position_in_world_m: _containers.RepeatedScalarFieldContainer[float]
    payload_yaw_rad: float
    desired_payload_position_in_world_m: _containers.RepeatedScalarFieldContainer[float]
    desired_payload_yaw_rad: float
    pair_names: _containers.RepeatedScalarFieldContainer[str]
    h_m: _containers.RepeatedScalarFieldContainer[float]
    robot_names: _containers.RepeatedScalarFieldContainer[str]
    coupling_error_m: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, time_s: _Optional[float] = ..., payload_position_in_world_m: _Optional[_Iterable[float]] = ..., payload_yaw_rad: _Optional[float] = ..., desired_payload_position_in_world_m: _Optional[_Iterable[float]] = ..., desired_payload_yaw_rad: _Optional[float] = ..., pair_names: _Optional[_Iterable[str]] = ..., h_m: _Optional[_Iterable[float]] = ..., robot_names: _Optional[_Iterable[str]] = ..., coupling_error_m: _Optional[_Iterable[float]] = ...) -> None: ...

class NmpcInputs(_message.Message):
    __slots__ = ("update", "time_s", "robot_states", "payload_state", "robot_references", "payload_reference", "feet_positions", "contacts", "obstacles")
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ROBOT_STATES_FIELD_NUMBER: _ClassVar[int]
    PAYLOAD_STATE_FIELD_NUMBER: _ClassVar[int]
    ROBOT_REFERENCES_FIELD_NUMBER: _ClassVar[int]
    PAYLOAD_REFERENCE_FIELD_NUMBER: _ClassVar[int]
    FEET_POSITIONS_FIELD_NUMBER: _ClassVar[int]
    CONTACTS_FIELD_NUMBER: _ClassVar[int]
    OBSTACLES_FIELD_NUMBER: _ClassVar[int]
    update: int
    time_s: float
    robot_states: Array
    payload_state: Array
    robot_references: Array
    payload_reference: Array
    feet_positions: Array
    contacts: Array
    obstacles: Array
    def __init__(self, update: _Optional[int] = ..., time_s: _Optional[float] = ..., robot_states: _Optional[_Union[Array, _Mapping]] = ..., payload_state: _Optional[_Union[Array, _Mapping]] = ..., robot_references: _Optional[_Union[Array, _Mapping]] = ..., payload_reference: _Optional[_Union[Array, _Mapping]] = ..., feet_positions: _Optional[_Union[Array, _Mapping]] = ..., contacts: _Optional[_Union[Array, _Mapping]] = ..., obstacles: _Optional[_Union[Array, _Mapping]] = ...) -> None: ...

class AgentWarmStart(_message.Message):
    __slots__ = ("agent", "present", "decision", "constraint_multipliers", "bound_multipliers")
    AGENT_FIELD_NUMBER: _ClassVar[int]
    PRESENT_FIELD_NUMBER: _ClassVar[int]
    DECISION_FIELD_NUMBER: _ClassVar[int]
    CONSTRAINT_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    BOUND_MULTIPLIERS_FIELD_NUMBER: _ClassVar[int]
    agent: int
    present: bool
    decision: Array
    constraint_multipliers: Array
    bound_multipliers: Array
    def __init__(self, agent: _Optional[int] = ..., present: _Optional[bool] = ..., decision: _Optional[_Union[Array, _Mapping]] = ..., constraint_multipliers: _Optional[_Union[Array, _Mapping]] = ..., bound_multipliers: _Optional[_Union[Array, _Mapping]] = ...) -> None: ...

class WarmStart(_message.Message):
    __slots__ = ("update", "time_s", "agents", "has_consensus", "consensus", "duals")
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    AGENTS_FIELD_NUMBER: _ClassVar[int]
    HAS_CONSENSUS_FIELD_NUMBER: _ClassVar[int]
    CONSENSUS_FIELD_NUMBER: _ClassVar[int]
    DUALS_FIELD_NUMBER: _ClassVar[int]
    update: int
    time_s: float
    agents: _containers.RepeatedCompositeFieldContainer[AgentWarmStart]
    has_consensus: bool
    consensus: Array
    duals: Array
    def __init__(self, update: _Optional[int] = ..., time_s: _Optional[float] = ..., agents: _Optional[_Iterable[_Union[AgentWarmStart, _Mapping]]] = ..., has_consensus: _Optional[bool] = ..., consensus: _Optional[_Union[Array, _Mapping]] = ..., duals: _Optional[_Union[Array, _Mapping]] = ...) -> None: ...

class SolveStats(_message.Message):
    __slots__ = ("agent", "admm_iteration", "status", "success", "iterations", "wall_time_s", "objective", "constraint_violation")
    AGENT_FIELD_NUMBER: _ClassVar[int]
    ADMM_ITERATION_FIELD_NUMBER: _ClassVar[int]
    STATUS_FIELD_NUMBER: _ClassVar[int]
    SUCCESS_FIELD_NUMBER: _ClassVar[int]
    ITERATIONS_FIELD_NUMBER: _ClassVar[int]
    WALL_TIME_S_FIELD_NUMBER: _ClassVar[int]
    OBJECTIVE_FIELD_NUMBER: _ClassVar[int]
    CONSTRAINT_VIOLATION_FIELD_NUMBER: _ClassVar[int]
    agent: int
    admm_iteration: int
    status: str
    success: bool
    iterations: int
    wall_time_s: float
    objective: float
    constraint_violation: float
    def __init__(self, agent: _Optional[int] = ..., admm_iteration: _Optional[int] = ..., status: _Optional[str] = ..., success: _Optional[bool] = ..., iterations: _Optional[int] = ..., wall_time_s: _Optional[float] = ..., objective: _Optional[float] = ..., constraint_violation: _Optional[float] = ...) -> None: ...

class NmpcUpdate(_message.Message):
    __slots__ = ("update", "time_s", "success", "update_time_s", "deadline_missed", "solves", "warnings", "grf", "wrench", "robot_trajectories", "payload_trajectory", "grf_trajectories", "wrench_trajectories", "consensus_trajectory", "max_solve_time_s", "total_iterations")
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    SUCCESS_FIELD_NUMBER: _ClassVar[int]
    UPDATE_TIME_S_FIELD_NUMBER: _ClassVar[int]
    DEADLINE_MISSED_FIELD_NUMBER: _ClassVar[int]
    SOLVES_FIELD_NUMBER: _ClassVar[int]
    WARNINGS_FIELD_NUMBER: _ClassVar[int]
    GRF_FIELD_NUMBER: _ClassVar[int]
    WRENCH_FIELD_NUMBER: _ClassVar[int]
    ROBOT_TRAJECTORIES_FIELD_NUMBER: _ClassVar[int]
    PAYLOAD_TRAJECTORY_FIELD_NUMBER: _ClassVar[int]
    GRF_TRAJECTORIES_FIELD_NUMBER: _ClassVar[int]
    WRENCH_TRAJECTORIES_FIELD_NUMBER: _ClassVar[int]
    CONSENSUS_TRAJECTORY_FIELD_NUMBER: _ClassVar[int]
    MAX_SOLVE_TIME_S_FIELD_NUMBER: _ClassVar[int]
    TOTAL_ITERATIONS_FIELD_NUMBER: _ClassVar[int]
    update: int
    time_s: float
    success: bool
    update_time_s: float
    deadline_missed: bool
    solves: _containers.RepeatedCompositeFieldContainer[SolveStats]
    warnings: _containers.RepeatedScalarFieldContainer[str]
    grf: Array
    wrench: Array
    robot_trajectories: Array
    payload_trajectory: Array
    grf_trajectories: Array
    wrench_trajectories: Array
    consensus_trajectory: Array
    max_solve_time_s: float
    total_iterations: int
    def __init__(self, update: _Optional[int] = ..., time_s: _Optional[float] = ..., success: _Optional[bool] = ..., update_time_s: _Optional[float] = ..., deadline_missed: _Optional[bool] = ..., solves: _Optional[_Iterable[_Union[SolveStats, _Mapping]]] = ..., warnings: _Optional[_Iterable[str]] = ..., grf: _Optional[_Union[Array, _Mapping]] = ..., wrench: _Optional[_Union[Array, _Mapping]] = ..., robot_trajectories: _Optional[_Union[Array, _Mapping]] = ..., payload_trajectory: _Optional[_Union[Array, _Mapping]] = ..., grf_trajectories: _Optional[_Union[Array, _Mapping]] = ..., wrench_trajectories: _Optional[_Union[Array, _Mapping]] = ..., consensus_trajectory: _Optional[_Union[Array, _Mapping]] = ..., max_solve_time_s: _Optional[float] = ..., total_iterations: _Optional[int] = ...) -> None: ...

class AdmmIteration(_message.Message):
    __slots__ = ("update", "time_s", "iteration", "primal_payload_rms", "primal_wrench_rms", "dual_norm", "max_primal_payload_rms", "max_primal_wrench_rms", "primal_position_rms_m", "primal_force_rms_n")
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ITERATION_FIELD_NUMBER: _ClassVar[int]
    PRIMAL_PAYLOAD_RMS_FIELD_NUMBER: _ClassVar[int]
    PRIMAL_WRENCH_RMS_FIELD_NUMBER: _ClassVar[int]
    DUAL_NORM_FIELD_NUMBER: _ClassVar[int]
    MAX_PRIMAL_PAYLOAD_RMS_FIELD_NUMBER: _ClassVar[int]
    MAX_PRIMAL_WRENCH_RMS_FIELD_NUMBER: _ClassVar[int]
    PRIMAL_POSITION_RMS_M_FIELD_NUMBER: _ClassVar[int]
    PRIMAL_FORCE_RMS_N_FIELD_NUMBER: _ClassVar[int]
    update: int
    time_s: float
    iteration: int
    primal_payload_rms: _containers.RepeatedScalarFieldContainer[float]
    primal_wrench_rms: _containers.RepeatedScalarFieldContainer[float]
    dual_norm: float
    max_primal_payload_rms: float
    max_primal_wrench_rms: float
    primal_position_rms_m: _containers.RepeatedScalarFieldContainer[float]
    primal_force_rms_n: _containers.RepeatedScalarFieldContainer[float]
    def __init__(self, update: _Optional[int] = ..., time_s: _Optional[float] = ..., iteration: _Optional[int] = ..., primal_payload_rms: _Optional[_Iterable[float]] = ..., primal_wrench_rms: _Optional[_Iterable[float]] = ..., dual_norm: _Optional[float] = ..., max_primal_payload_rms: _Optional[float] = ..., max_primal_wrench_rms: _Optional[float] = ..., primal_position_rms_m: _Optional[_Iterable[float]] = ..., primal_force_rms_n: _Optional[_Iterable[float]] = ...) -> None: ...

class CbfValues(_message.Message):
    __slots__ = ("update", "time_s", "pair_names", "h_m", "predicted_min_h_m", "min_h_m")
    UPDATE_FIELD_NUMBER: _ClassVar[int]
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    PAIR_NAMES_FIELD_NUMBER: _ClassVar[int]
    H_M_FIELD_NUMBER: _ClassVar[int]
    PREDICTED_MIN_H_M_FIELD_NUMBER: _ClassVar[int]
    MIN_H_M_FIELD_NUMBER: _ClassVar[int]
    update: int
    time_s: float
    pair_names: _containers.RepeatedScalarFieldContainer[str]
    h_m: _containers.RepeatedScalarFieldContainer[float]
    predicted_min_h_m: _containers.RepeatedScalarFieldContainer[float]
    min_h_m: float
    def __init__(self, update: _Optional[int] = ..., time_s: _Optional[float] = ..., pair_names: _Optional[_Iterable[str]] = ..., h_m: _Optional[_Iterable[float]] = ..., predicted_min_h_m: _Optional[_Iterable[float]] = ..., min_h_m: _Optional[float] = ...) -> None: ...

class InteractionWrench(_message.Message):
    __slots__ = ("time_s", "robot", "measured_force_n", "predicted_force_n", "measured_torque_nm", "predicted_torque_nm", "force_error_n")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    ROBOT_FIELD_NUMBER: _ClassVar[int]
    MEASURED_FORCE_N_FIELD_NUMBER: _ClassVar[int]
    PREDICTED_FORCE_N_FIELD_NUMBER: _ClassVar[int]
    MEASURED_TORQUE_NM_FIELD_NUMBER: _ClassVar[int]
    PREDICTED_TORQUE_NM_FIELD_NUMBER: _ClassVar[int]
    FORCE_ERROR_N_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    robot: str
    measured_force_n: _containers.RepeatedScalarFieldContainer[float]
    predicted_force_n: _containers.RepeatedScalarFieldContainer[float]
    measured_torque_nm: _containers.RepeatedScalarFieldContainer[float]
    predicted_torque_nm: _containers.RepeatedScalarFieldContainer[float]
    force_error_n: float
    def __init__(self, time_s: _Optional[float] = ..., robot: _Optional[str] = ..., measured_force_n: _Optional[_Iterable[float]] = ..., predicted_force_n: _Optional[_Iterable[float]] = ..., measured_torque_nm: _Optional[_Iterable[float]] = ..., predicted_torque_nm: _Optional[_Iterable[float]] = ..., force_error_n: _Optional[float] = ...) -> None: ...

class LoopTiming(_message.Message):
    __slots__ = ("time_s", "nmpc_update_s", "nmpc_period_s", "deadline_missed", "deadline_misses", "wbc_tick_max_s", "wbc_tick_mean_s", "recorder_dropped")
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    NMPC_UPDATE_S_FIELD_NUMBER: _ClassVar[int]
    NMPC_PERIOD_S_FIELD_NUMBER: _ClassVar[int]
    DEADLINE_MISSED_FIELD_NUMBER: _ClassVar[int]
    DEADLINE_MISSES_FIELD_NUMBER: _ClassVar[int]
    WBC_TICK_MAX_S_FIELD_NUMBER: _ClassVar[int]
    WBC_TICK_MEAN_S_FIELD_NUMBER: _ClassVar[int]
    RECORDER_DROPPED_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    nmpc_update_s: float
    nmpc_period_s: float
    deadline_missed: bool
    deadline_misses: int
    wbc_tick_max_s: float
    wbc_tick_mean_s: float
    recorder_dropped: int
    def __init__(self, time_s: _Optional[float] = ..., nmpc_update_s: _Optional[float] = ..., nmpc_period_s: _Optional[float] = ..., deadline_missed: _Optional[bool] = ..., deadline_misses: _Optional[int] = ..., wbc_tick_max_s: _Optional[float] = ..., wbc_tick_mean_s: _Optional[float] = ..., recorder_dropped: _Optional[int] = ...) -> None: ...

class Event(_message.Message):
    __slots__ = ("time_s", "level", "source", "text")
    class Level(int, metaclass=_enum_type_wrapper.EnumTypeWrapper):
        __slots__ = ()
        INFO: _ClassVar[Event.Level]
        WARNING: _ClassVar[Event.Level]
        ERROR: _ClassVar[Event.Level]
    INFO: Event.Level
    WARNING: Event.Level
    ERROR: Event.Level
    TIME_S_FIELD_NUMBER: _ClassVar[int]
    LEVEL_FIELD_NUMBER: _ClassVar[int]
    SOURCE_FIELD_NUMBER: _ClassVar[int]
    TEXT_FIELD_NUMBER: _ClassVar[int]
    time_s: float
    level: Event.Level
    source: str
    text: str
    def __init__(self, time_s: _Optional[float] = ..., level: _Optional[_Union[Event.Level, str]] = ..., source: _Optional[str] = ..., text: _Optional[str] = ...) -> None: ...
