"""Porter log messages as Rerun time series (``Scalars``), for ``deploy.viewing.rerun_view``.

Per-agent and per-pair quantities are one entity with one series per agent / pair (their
names as static ``SeriesLines``, re-sent when the names become known), so an entity has one
row per message: ``admm/primal_payload_rms`` has exactly one row per logged ADMM iteration.
The caller has set the ``sim_time`` of the message; ADMM iterations are also placed on the
``admm_iteration`` sequence timeline (one step each), to plot them one after the other.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import rerun as rr

from deploy.recording.messages import porter_log_pb2 as pb
from deploy.viewing import layout as paths


class SeriesLogger:
    """Time series of one recording; ``agent_names(n)`` names the first n agents."""

    def __init__(self, recording: rr.RecordingStream,
                 agent_names: Callable[[int], list[str]]) -> None:
        self.recording = recording
        self.agent_names = agent_names
        self.admm_iterations = 0
        self._series_names: dict[str, list[str]] = {}

    def scalar(self, entity: str, value: float | Sequence[float] | np.ndarray,
               names: Sequence[str] | None = None) -> None:
        """One sample (or one per named series) on ``entity``."""
        values = np.atleast_1d(np.asarray(value, dtype=float))
        if values.size == 0:
            return
        if names is not None and self._series_names.get(entity) != list(names):
            self._series_names[entity] = list(names)
            self.recording.log(entity, rr.SeriesLines(names=list(names)), static=True)
        self.recording.log(entity, rr.Scalars(values))

    def admm(self, message: pb.AdmmIteration) -> None:
        self.recording.set_time(paths.ADMM_ITERATION, sequence=self.admm_iterations)
        self.admm_iterations += 1
        names = self.agent_names(len(message.primal_payload_rms))
        self.scalar(f"{paths.ADMM}/primal_payload_rms", message.primal_payload_rms, names)
        self.scalar(f"{paths.ADMM}/primal_wrench_rms", message.primal_wrench_rms, names)
        self.scalar(f"{paths.ADMM}/dual_norm", message.dual_norm)
        if len(message.primal_position_rms_m):  # logs before the paper's residuals lack them
            self.scalar(f"{paths.ADMM}/primal_position_rms_m", message.primal_position_rms_m,
                        names)
            self.scalar(f"{paths.ADMM}/primal_force_rms_n", message.primal_force_rms_n, names)
        self.recording.disable_timeline(paths.ADMM_ITERATION)

    def nmpc_update(self, message: pb.NmpcUpdate, grf_n: np.ndarray | None) -> None:
        """Update and solve times, NLP iterations, deadline, planned first-stage GRF sums."""
        self.scalar(f"{paths.NMPC_TIMES}/update", message.update_time_s)
        self.scalar(f"{paths.NMPC_TIMES}/max_solve", message.max_solve_time_s)
        self.scalar(f"{paths.NMPC_ITERATIONS}/total", message.total_iterations)
        self.scalar(f"{paths.LOOP_COUNTS}/deadline_missed", float(message.deadline_missed))
        if message.solves:
            agents = max(s.agent for s in message.solves) + 1
            solve_time_s, iterations = np.zeros(agents), np.zeros(agents)
            for solve in message.solves:  # per agent: slowest solve, iterations summed
                solve_time_s[solve.agent] = max(solve_time_s[solve.agent], solve.wall_time_s)
                iterations[solve.agent] += solve.iterations
            names = self.agent_names(agents) if agents > 1 else ["team"]  # centralized: one
            self.scalar(f"{paths.NMPC_TIMES}/agent_solve", solve_time_s, names)
            self.scalar(f"{paths.NMPC_ITERATIONS}/per_agent", iterations, names)
        if grf_n is not None and grf_n.ndim == 2:
            for name, forces in zip(self.agent_names(grf_n.shape[0]), grf_n, strict=True):
                total = float(np.linalg.norm(forces.reshape(-1, 3).sum(axis=0)))
                self.scalar(f"{paths.FORCES}/{name}/planned_grf_sum_n", total)

    def wbc(self, robot: str, message: pb.WbcTick, stance_force_sum_n: float) -> None:
        self.scalar(f"{paths.FORCES}/{robot}/wbc_grf_sum_n", stance_force_sum_n)
        self.scalar(f"{paths.LOOP_TIMES}/wbc/{robot}", message.solve_time_s)

    def wrench(self, robot: str, message: pb.InteractionWrench) -> None:
        self.scalar(f"{paths.FORCES}/{robot}/coupling_force_n",
                    [float(np.linalg.norm(message.measured_force_n)),
                     float(np.linalg.norm(message.predicted_force_n))], ["measured", "predicted"])

    def cbf(self, message: pb.CbfValues) -> None:
        if not message.pair_names:
            return
        self.scalar(f"{paths.SAFETY}/h_m", message.h_m, list(message.pair_names))
        self.scalar(f"{paths.SAFETY}/min_h_m", message.min_h_m)
        if message.predicted_min_h_m:
            self.scalar(f"{paths.SAFETY}/predicted_min_h_m", min(message.predicted_min_h_m))

    def ground_truth(self, message: pb.GroundTruth) -> None:
        position = np.asarray(message.payload_position_in_world_m, dtype=float)
        desired = np.asarray(message.desired_payload_position_in_world_m, dtype=float)
        if position.size == 3 and desired.size == 3:
            self.scalar(f"{paths.TRACKING}/payload_position_error_m",
                        float(np.linalg.norm(position - desired)))
        yaw_error = message.payload_yaw_rad - message.desired_payload_yaw_rad
        self.scalar(f"{paths.TRACKING}/payload_yaw_error_rad",
                    abs((yaw_error + np.pi) % (2 * np.pi) - np.pi))
        if message.coupling_error_m:
            self.scalar(f"{paths.TRACKING}/coupling_error_m", message.coupling_error_m,
                        list(message.robot_names) or None)
        if message.h_m:
            self.scalar(f"{paths.SAFETY}/true_min_h_m", min(message.h_m))

    def payload_estimate(self, message: pb.PayloadEstimate) -> None:
        if message.has_ground_truth and len(message.estimate) >= 3:
            error = np.subtract(message.estimate[0:3], message.true_position_in_world_m)
            self.scalar(f"{paths.TRACKING}/payload_estimate_error_m", float(np.linalg.norm(error)))

    def loop_timing(self, message: pb.LoopTiming) -> None:
        self.scalar(f"{paths.NMPC_TIMES}/deadline", message.nmpc_period_s)
        self.scalar(f"{paths.LOOP_TIMES}/wbc_tick_max", message.wbc_tick_max_s)
        self.scalar(f"{paths.LOOP_TIMES}/wbc_tick_mean", message.wbc_tick_mean_s)
        self.scalar(f"{paths.LOOP_COUNTS}/deadline_misses_total", message.deadline_misses)
        self.scalar(f"{paths.LOOP_COUNTS}/recorder_dropped", message.recorder_dropped)
