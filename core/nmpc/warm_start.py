"""Initial guesses for the NMPC: a cold guess from the measurement, and the shifted previous plan.

Decision blocks are named ``<block>@<stage>`` (see ``core.nmpc.stagewise_nlp``). Shifting moves every
block one stage earlier and repeats the last one. Ground reaction forces are then made
consistent with the new contact schedule: zero on swing feet, and the nominal weight share on a
stance foot that the old plan left unloaded (a gait switch); without this, the newly appended
stage costs the solver many extra iterations.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from core.model.team import TeamModel
from core.nmpc.layout import BlockLayout
from core.nmpc.mpc_inputs import MpcInputs
from core.nmpc.nlp_solver import NlpSolution
from core.nmpc.stagewise_nlp import stage_shift_index
from core.nmpc.transport_problem import TransportProblem


def shift_blocks(offsets: dict[str, tuple[int, int]], values: np.ndarray) -> np.ndarray:
    """``values`` laid out in ``<block>@<stage>`` blocks, each block moved one stage earlier;
    a block's last stage is repeated, and a block that exists at one stage only (the initial
    condition) keeps its value."""
    source = np.asarray(values, dtype=float)
    return source[stage_shift_index(offsets, source.size)]


def shifted_multipliers(problem: TransportProblem, previous: NlpSolution
                        ) -> tuple[np.ndarray, np.ndarray]:
    """(constraint, bound) multipliers of ``previous`` moved one stage earlier with the same
    stage map as the primal warm start (the problem's index maps, built once)."""
    return (np.asarray(previous.constraint_multipliers, float)[problem.nlp.constraint_shift],
            np.asarray(previous.bound_multipliers, float)[problem.nlp.decision_shift])


def nominal_foot_forces(contacts: np.ndarray, supported_mass_kg: float, gravity_m_s2: float
                        ) -> np.ndarray:
    """12-vector of GRFs [N] sharing ``supported_mass_kg``'s weight among the stance feet of
    ``contacts`` (4,) flags; (..., 4) flags give (..., 12), one per row."""
    flags = np.asarray(contacts, dtype=float)
    stance = np.maximum(flags.sum(axis=-1), 1.0)[..., None]
    forces = np.zeros((*flags.shape, 3))
    forces[..., 2] = flags * supported_mass_kg * gravity_m_s2 / stance
    return forces.reshape(*flags.shape[:-1], -1)


def conform_forces(
    guess: np.ndarray,
    layout: BlockLayout,
    grf_block: str,
    contacts: np.ndarray,
    supported_mass_kg: float,
    gravity_m_s2: float,
    minimum_stance_force_n: float = 1.0,
) -> None:
    """In place: zero GRFs on swing feet, nominal force (``nominal_foot_forces``) on unloaded
    stance feet, per stage; every stage at once (``contacts`` (N, 4) flags)."""
    flags = np.asarray(contacts, dtype=float)
    rows = layout.stage_rows(grf_block, len(flags))
    forces = guess[rows].reshape(-1, 4, 3)
    nominal_z = nominal_foot_forces(flags, supported_mass_kg, gravity_m_s2)[:, 2::3]
    swing = flags == 0.0
    unloaded = ~swing & (forces[:, :, 2] < minimum_stance_force_n)
    forces[swing | unloaded] = 0.0
    forces[:, :, 2] = np.where(unloaded, nominal_z, forces[:, :, 2])
    guess[rows] = forces.reshape(rows.shape)


def initial_guess(
    problem: TransportProblem,
    team: TeamModel,
    inputs: MpcInputs,
    previous: NlpSolution | None,
    agent: int | None,
) -> np.ndarray:
    """Shifted previous solution, or a cold guess holding the measured states with nominal
    forces; GRFs are conformed to the contact schedule either way."""
    layout = problem.nlp.decision
    n = problem.horizon_steps
    g = problem.settings.gravity_m_s2
    payload_share_kg = team.payload.mass_kg / team.agent_count
    if previous is not None:
        guess = np.asarray(previous.decision, float)[problem.nlp.decision_shift]
    else:
        guess = np.zeros(layout.size)
        for k in range(n + 1):
            for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
                layout.put(guess, f"robot_{key}@{k}", inputs.robot_states[r])
            layout.put(guess, f"payload@{k}", inputs.payload_state)
            if k < n:
                for j in range(team.agent_count):
                    layout.put(guess, f"wrench_{j}@{k}",
                               np.array([0, 0, payload_share_kg * g, 0, 0, 0]))
    for key, r in zip(problem.robot_keys(), problem.robot_indices(agent), strict=True):
        conform_forces(guess, layout, f"grf_{key}", inputs.contacts[r],
                       team.robots[r].mass_kg + payload_share_kg, g)
    return guess


@dataclass
class ControllerMemory:
    """What an NMPC carries from one update to the next (its warm start).

    ``previous``: the last NLP solution per local problem (one entry for the centralized NMPC,
    one per agent for ADMM; None before the first solve). ``consensus`` and ``duals``: the ADMM
    consensus trajectory s_bar and scaled duals w^i (None when centralized or before the first
    update). Together with an update's ``MpcInputs`` this determines the update exactly.
    """

    previous: list[NlpSolution | None]
    consensus: np.ndarray | None = None
    duals: np.ndarray | None = None
