"""Shared memory between the process executor and one ADMM worker: each agent the worker
solves has a slot holding its request's arrays and its solution's arrays (float64), so a round
crosses the pipe as a few numbers (the request's flags, the solve's stats), not as pickled
arrays (~20 kB a request and ~11 kB a solution for a two-agent team: pickling, the pipe's
copies and unpickling cost ~0.18 ms of each ADMM round on the caller's side, measured).

The executor creates the block (``SolveSlots.create``, tracked by multiprocessing's resource
tracker: removed if the executor's process dies) and unlinks it on ``close``; the worker maps
the same block by name (``SolveSlots.attach``, untracked: the block is the executor's). The
pipe orders every access: the executor writes a slot's request before it sends the round's
message and reads a slot's solution after the worker's answer came; the worker reads the
requests after the message came and writes the solutions before it answers. A request is
copied out of its slot before the solve (an executor that timed out on a round writes the
next one's requests while the worker may still be solving).
"""

from __future__ import annotations

import contextlib
import mmap
from dataclasses import dataclass
from multiprocessing import shared_memory
from pathlib import Path

import numpy as np

from core.admm.admm_executor import LocalSolveRequest
from core.nmpc.nlp_solver import NlpSolution, SolveStats

__all__ = ["RequestHeader", "SlotLayout", "SolveSlots"]

SHM_DIRECTORY = Path("/dev/shm")  # where Linux keeps POSIX shared memory by name


@dataclass(frozen=True)
class SlotLayout:
    """``slots`` agent slots of a problem with ``variables`` decision variables, ``parameters``
    parameters and ``constraints`` constraints, in block ``name``."""

    name: str
    slots: int
    variables: int
    parameters: int
    constraints: int

    def fields(self) -> list[tuple[str, int]]:
        """(field, size) in slot order: the request's six arrays, then the solution's three."""
        n, m = self.variables, self.constraints
        return [("initial_guess", n), ("parameters", self.parameters), ("lower_bounds", n),
                ("upper_bounds", n), ("constraint_multipliers", m), ("bound_multipliers", n),
                ("decision", n), ("solution_constraint_multipliers", m),
                ("solution_bound_multipliers", n)]

    @property
    def slot_size(self) -> int:
        return sum(size for _, size in self.fields())

    def fits(self, request: LocalSolveRequest) -> bool:
        return (request.initial_guess.size == self.variables
                and request.parameters.size == self.parameters
                and (request.constraint_multipliers is None
                     or request.constraint_multipliers.size == self.constraints))


@dataclass(frozen=True)
class RequestHeader:
    """What of a request is not in its slot."""

    agent: int
    has_constraint_multipliers: bool
    has_bound_multipliers: bool
    warm_start: bool
    update: int
    iteration: int


class SolveSlots:
    """The arrays of ``layout``'s slots over one shared block: ``arrays[slot][field]``."""

    def __init__(self, layout: SlotLayout, buffer: memoryview | mmap.mmap,
                 owner: shared_memory.SharedMemory | None) -> None:
        self.layout = layout
        self._buffer, self._owner = buffer, owner
        whole = np.frombuffer(buffer, dtype=np.float64, count=layout.slots * layout.slot_size)
        self.arrays: list[dict[str, np.ndarray]] = []
        for slot in range(layout.slots):
            offset, views = slot * layout.slot_size, {}
            for field, size in layout.fields():
                views[field] = whole[offset:offset + size]
                offset += size
            self.arrays.append(views)

    @classmethod
    def create(cls, slots: int, variables: int, parameters: int, constraints: int
               ) -> SolveSlots:
        """A new block of ``slots`` slots for a problem of these sizes (the executor's)."""
        size = SlotLayout("", slots, variables, parameters, constraints).slot_size
        block = shared_memory.SharedMemory(create=True, size=8 * slots * size)
        assert block.buf is not None
        return cls(SlotLayout(block.name, slots, variables, parameters, constraints),
                   block.buf, block)

    @classmethod
    def attach(cls, layout: SlotLayout) -> SolveSlots:
        """The executor's block, mapped by name (the worker's side; not tracked)."""
        with open(SHM_DIRECTORY / layout.name, "r+b") as file:
            buffer = mmap.mmap(file.fileno(), 8 * layout.slots * layout.slot_size)
        return cls(layout, buffer, None)

    # --- the executor's side -------------------------------------------------------------
    def put_request(self, slot: int, request: LocalSolveRequest) -> RequestHeader:
        views = self.arrays[slot]
        for field in ("initial_guess", "parameters", "lower_bounds", "upper_bounds"):
            np.copyto(views[field], getattr(request, field))
        for field in ("constraint_multipliers", "bound_multipliers"):
            value = getattr(request, field)
            if value is not None:
                np.copyto(views[field], value)
        return RequestHeader(request.agent, request.constraint_multipliers is not None,
                             request.bound_multipliers is not None, request.warm_start,
                             request.update, request.iteration)

    def take_solution(self, slot: int, stats: SolveStats) -> NlpSolution:
        views = self.arrays[slot]
        return NlpSolution(views["decision"].copy(),
                           views["solution_constraint_multipliers"].copy(),
                           views["solution_bound_multipliers"].copy(), stats)

    # --- the worker's side ---------------------------------------------------------------
    def take_request(self, slot: int, header: RequestHeader) -> LocalSolveRequest:
        views = self.arrays[slot]
        return LocalSolveRequest(
            agent=header.agent, initial_guess=views["initial_guess"].copy(),
            parameters=views["parameters"].copy(), lower_bounds=views["lower_bounds"].copy(),
            upper_bounds=views["upper_bounds"].copy(),
            constraint_multipliers=(views["constraint_multipliers"].copy()
                                    if header.has_constraint_multipliers else None),
            bound_multipliers=(views["bound_multipliers"].copy()
                               if header.has_bound_multipliers else None),
            warm_start=header.warm_start, update=header.update, iteration=header.iteration)

    def put_solution(self, slot: int, solution: NlpSolution) -> SolveStats:
        views = self.arrays[slot]
        np.copyto(views["decision"], solution.decision)
        np.copyto(views["solution_constraint_multipliers"], solution.constraint_multipliers)
        np.copyto(views["solution_bound_multipliers"], solution.bound_multipliers)
        return solution.stats

    def close(self) -> None:
        """Unmap (and, on the executor's side, remove) the block; idempotent."""
        self.arrays = []
        with contextlib.suppress(BufferError):  # a view still held elsewhere: unmapped at exit
            if self._owner is not None:
                self._owner.close()
            elif isinstance(self._buffer, mmap.mmap):
                self._buffer.close()
        if self._owner is not None:
            with contextlib.suppress(FileNotFoundError):
                self._owner.unlink()
            self._owner = None
