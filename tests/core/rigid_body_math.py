"""Independent NumPy rigid-body math shared by the core tests (not the code under test)."""

from __future__ import annotations

import casadi as ca
import numpy as np

from core.model.srb_model import rotation_body_to_world

GRAVITY_M_S2 = 9.81


def as_array(value) -> np.ndarray:
    """A CasADi DM (or anything DM accepts) as a squeezed NumPy array."""
    return np.array(ca.DM(value)).squeeze()


def rotation(euler) -> np.ndarray:
    """The code under test's R(Theta), evaluated numerically."""
    return as_array(rotation_body_to_world(ca.DM(euler)))


def rot_x(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def rot_y(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rot_z(a: float) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def skew(w: np.ndarray) -> np.ndarray:
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def expm_so3(w: np.ndarray) -> np.ndarray:
    """exp(skew(w)) by Rodrigues' formula."""
    angle = np.linalg.norm(w)
    if angle < 1e-14:
        return np.eye(3) + skew(w)
    k = skew(w / angle)
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def euler_from_rotation(r: np.ndarray) -> np.ndarray:
    """(roll, pitch, yaw) with R = Rz(yaw) Ry(pitch) Rx(roll), pitch in (-pi/2, pi/2)."""
    return np.array([
        np.arctan2(r[2, 1], r[2, 2]),
        -np.arcsin(np.clip(r[2, 0], -1.0, 1.0)),
        np.arctan2(r[1, 0], r[0, 0]),
    ])


def random_euler(rng: np.random.Generator, tilt: float = 1.3) -> np.ndarray:
    """Yaw anywhere; roll and pitch in [-tilt, tilt] (away from the pitch singularity)."""
    return np.array([rng.uniform(-tilt, tilt), rng.uniform(-tilt, tilt), rng.uniform(-np.pi, np.pi)])


def random_inertia(rng: np.random.Generator, scale: float = 1.0) -> np.ndarray:
    """A random symmetric positive definite 3x3 matrix."""
    a = rng.normal(size=(3, 3))
    return scale * (a @ a.T + np.eye(3))


def random_state(rng: np.random.Generator, tilt: float = 1.3) -> np.ndarray:
    """A random SRB state (p, v, Theta, omega)."""
    return np.concatenate([rng.normal(size=3), rng.normal(size=3), random_euler(rng, tilt),
                           rng.normal(size=3)])
