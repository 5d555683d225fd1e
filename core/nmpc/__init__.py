"""The NMPC: stage-wise NLPs, CBFs, solvers, warm start, ADMM and centralized controllers.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "core.nmpc.admm_executor": ["LocalSolveRequest", "LocalSolverSpec", "solve_request",
        "LocalSolveExecutor", "SerialExecutor"],
    "core.nmpc.admm_mpc": ["DistributedMpc"],
    "core.nmpc.cbf": ["obstacle_position", "safety_function", "hocbf_condition",
        "stage_safety_values", "stagewise_hocbf", "first_order_condition", "stagewise_first_order"],
    "core.nmpc.centralized_mpc": ["CentralizedMpc"],
    "core.nmpc.delay_compensation": ["interpolate_trajectory", "predict_states"],
    "core.nmpc.inputs_builder": ["FootHorizon", "build_mpc_inputs"],
    "core.nmpc.layout": ["LayoutError", "BlockLayout"],
    "core.nmpc.mpc_inputs": ["InvalidMpcInputError", "MpcInputs"],
    "core.nmpc.mpc_plan": ["AdmmIteration", "MpcPlan", "decode_plan"],
    "core.nmpc.nlp_solver": ["NlpCompiler", "SolveStats", "NlpSolution", "problem_key",
                             "function_key", "NlpSolver"],
    "core.nmpc.obstacle_selection": ["ObstacleSelection", "predicted_min_safety_values",
        "select_obstacles"],
    "core.nmpc.reference": ["BrakingReference", "WaypointReference", "robot_state_from_payload",
        "horizon_references"],
    "core.nmpc.settings": ["SrbWeights", "CostSettings", "CouplingSettings", "SafetySettings",
        "ContactSettings", "AdmmSettings", "ChannelSettings", "BrakingSettings",
        "CapabilitySettings", "SolverSettings", "MpcSettings"],
    "core.nmpc.stagewise_nlp": ["StageStructure", "NlpProblem", "StagewiseBuilder"],
    "core.nmpc.transport_problem": ["TransportProblem", "build_transport_problem",
        "consensus_weights"],
    "core.nmpc.warm_start": ["shift_blocks", "shift_solution", "shifted_multipliers",
        "nominal_foot_forces", "conform_forces", "initial_guess", "ControllerMemory"],
}
__all__ = ["AdmmIteration", "AdmmSettings", "ChannelSettings", "BlockLayout", "BrakingReference",
           "BrakingSettings", "CapabilitySettings", "CentralizedMpc", "ContactSettings",
           "ControllerMemory", "CostSettings", "CouplingSettings", "DistributedMpc", "FootHorizon",
           "InvalidMpcInputError", "LayoutError", "LocalSolveExecutor", "LocalSolveRequest",
           "LocalSolverSpec", "MpcInputs", "MpcPlan", "MpcSettings", "NlpCompiler", "NlpProblem",
           "NlpSolution", "NlpSolver", "ObstacleSelection", "SafetySettings", "SerialExecutor",
           "SolveStats", "SolverSettings", "SrbWeights", "StageStructure", "StagewiseBuilder",
           "TransportProblem", "WaypointReference", "build_mpc_inputs", "build_transport_problem",
           "conform_forces", "consensus_weights", "decode_plan", "first_order_condition",
           "hocbf_condition", "horizon_references", "initial_guess", "interpolate_trajectory",
           "nominal_foot_forces", "obstacle_position", "predict_states",
           "predicted_min_safety_values", "problem_key", "function_key",
           "robot_state_from_payload",
           "safety_function", "select_obstacles", "shift_blocks", "shift_solution",
           "shifted_multipliers", "solve_request", "stage_safety_values", "stagewise_first_order",
           "stagewise_hocbf"]
__getattr__ = lazy_exports(__name__, _SOURCES)
