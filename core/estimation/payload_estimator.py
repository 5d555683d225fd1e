"""Kinematic payload estimator: the payload SRB state from the robots' states and the coupling.

The payload carries no sensors. Each robot i is rigidly coupled at the point whose coordinates are
r_i in the robot frame and s_i in the payload frame, with the robot's z-axis kept parallel to the
payload's and the relative yaw free (core/model/coupling.py). The estimator inverts that geometry
(core/nmpc/reference.py ``robot_state_from_payload`` is a forward map of the level case):

* Coupling points in world: c_i = p_i + R_i r_i, with velocities u_i = v_i + omega_i x (R_i r_i).
* Tilt: the payload z-axis n is the normalised mean of the robots' z-axes R_i e_z. Any rotation
  with R e_z = n is R = Q Rz(alpha), with Q the minimal rotation taking e_z to n.
* Yaw (robot yaws carry no information, the coupling is yaw-free): alpha is the best-fit planar
  rotation (2-D Procrustes/Kabsch, centred) taking the payload-frame points s_i to the un-tilted
  world points Q^T c_i; the payload rotation is R_L = Q Rz(alpha), from which the XYZ Euler angles
  (R = Rz(yaw) Ry(pitch) Rx(roll)) follow, so R_L e_z = n exactly. Needs 2+ agents whose
  payload-frame coupling points differ in x-y.
* Position: p_L = mean_i (c_i - R_L s_i).
* Angular velocity: the coupling shares every component of omega orthogonal to n (it keeps the
  z-axes parallel, so omega_i x n = omega_L x n) and leaves the component along n free. The
  orthogonal part is the mean of the robots' orthogonal parts; the component w along n is the
  least-squares rigid-body fit u_i - omega_perp x d_i = v_L + w n x d_i with d_i = R_L s_i.
* Linear velocity: v_L from the same fit (the mean of u_i - omega_L x d_i).

With a ``previous`` payload state the yaw is unwrapped to stay continuous with it (the output yaw
may then leave (-pi, pi]); roll and pitch are always in their principal ranges.
"""

from __future__ import annotations

import numpy as np

from core.model.rotations import cross_rows, euler_from_rotation, rotation_from_euler
from core.model.srb_model import STATE_SIZE
from core.model.team import TeamModel

# Smallest x-y spread [m] of the payload-frame coupling points for the yaw to be observable.
MIN_COUPLING_SPREAD_M = 1e-6


def _tilt_rotation(n: np.ndarray) -> np.ndarray:
    """Minimal rotation taking e_z to the unit vector n (Rodrigues; needs n_z > -1)."""
    k = np.array([[0.0, 0.0, n[0]], [0.0, 0.0, n[1]], [-n[0], -n[1], 0.0]])
    return np.eye(3) + k + k @ k / (1.0 + n[2])


def _wrap(angle: float) -> float:
    return float((angle + np.pi) % (2 * np.pi) - np.pi)


class PayloadEstimator:
    """Payload SRB state (p, v, Theta, omega), world frame, from the team's robot SRB states."""

    def __init__(self, team: TeamModel) -> None:
        self.team = team
        self._in_robot = np.asarray(team.coupling_points_in_robot_m, dtype=float)
        self._in_payload = np.asarray(team.coupling_points_in_payload_m, dtype=float)
        count = team.agent_count
        if self._in_robot.shape != (count, 3) or self._in_payload.shape != (count, 3):
            raise ValueError(f"team: coupling points must be ({count}, 3) arrays")
        planar = self._in_payload[:, 0:2] - self._in_payload[:, 0:2].mean(axis=0)
        if count < 2 or np.max(np.linalg.norm(planar, axis=1)) < MIN_COUPLING_SPREAD_M:
            raise ValueError("team: payload yaw is unobservable; need 2+ agents whose payload "
                             "coupling points differ in x-y")
        self._planar_in_payload = planar

    def estimate(self, robot_states: np.ndarray, previous: np.ndarray | None = None) -> np.ndarray:
        """Payload state (12,) from robot states (n_A, 12) in team order; ``previous`` (12,), if
        given, makes the yaw continuous with its yaw (no 2 pi jumps)."""
        count = self.team.agent_count
        states = np.asarray(robot_states, dtype=float)
        if states.shape != (count, STATE_SIZE):
            raise ValueError(f"robot_states: expected shape ({count}, {STATE_SIZE}), "
                             f"got {states.shape}")
        if not np.all(np.isfinite(states)):
            raise ValueError("robot_states: contains NaN or inf")
        if previous is not None:
            previous = np.asarray(previous, dtype=float)
            if previous.shape != (STATE_SIZE,) or not np.all(np.isfinite(previous)):
                raise ValueError(f"previous: expected a finite ({STATE_SIZE},) state")

        rotations = np.array([rotation_from_euler(x[6:9]) for x in states])
        arms = np.einsum("ijk,ik->ij", rotations, self._in_robot)  # R_i r_i
        points = states[:, 0:3] + arms
        point_velocities = states[:, 3:6] + cross_rows(states[:, 9:12], arms)

        n = rotations[:, :, 2].mean(axis=0)
        norm = np.linalg.norm(n)
        if norm < 1e-9 or n[2] <= -1.0 + 1e-9:
            raise ValueError("robot_states: robots' z-axes do not define a payload z-axis")
        n = n / norm

        tilt = _tilt_rotation(n)
        untilted = points @ tilt  # rows Q^T c_i
        planar = untilted[:, 0:2] - untilted[:, 0:2].mean(axis=0)
        a, b = self._planar_in_payload, planar
        alpha = np.arctan2(np.sum(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]), np.sum(a * b))
        ca, sa = np.cos(alpha), np.sin(alpha)
        rotation = tilt @ np.array([[ca, -sa, 0.0], [sa, ca, 0.0], [0.0, 0.0, 1.0]])
        euler = euler_from_rotation(rotation)
        if previous is not None:
            euler[2] = previous[8] + _wrap(euler[2] - previous[8])

        offsets = self._in_payload @ rotation.T  # d_i = R_L s_i
        position = (points - offsets).mean(axis=0)

        omega_perp = (states[:, 9:12] - np.outer(states[:, 9:12] @ n, n)).mean(axis=0)
        residual = point_velocities - cross_rows(omega_perp, offsets)
        spin = cross_rows(n, offsets - offsets.mean(axis=0))  # n x (d_i - mean d)
        centred = residual - residual.mean(axis=0)
        spin_rate = np.sum(spin * centred) / np.sum(spin * spin)
        omega = omega_perp + spin_rate * n
        velocity = (point_velocities - cross_rows(omega, offsets)).mean(axis=0)

        return np.concatenate([position, velocity, euler, omega])
