"""A stage-wise ordered NLP: decision variables x0, u0, x1, u1, ..., xN and constraints grouped by
stage, as structure-exploiting solvers (fatrop) need, and as any general NLP solver accepts."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import casadi as ca
import numpy as np

from core.nmpc.layout import BlockLayout


@dataclass
class StageStructure:
    """Per stage k = 0..N: state size, input size (0 at N) and path-constraint count."""

    state_sizes: list[int]
    input_sizes: list[int]
    path_constraint_counts: list[int]


@dataclass
class NlpProblem:
    """min f(w, p) s.t. lbg <= g(w, p) <= ubg, lbx <= w <= ubx (bounds given at solve time)."""

    name: str
    decision: BlockLayout
    parameters: BlockLayout
    objective: ca.SX
    constraints: ca.SX
    lower_constraints: np.ndarray
    upper_constraints: np.ndarray
    equality: list[bool]
    structure: StageStructure
    # Constraint rows by block, ``<name>@<stage>`` -> (first row, rows): dynamics gaps are
    # ``gap_<state block>@k`` (leaving stage k), path constraints carry their own names.
    constraint_blocks: dict[str, tuple[int, int]] = field(default_factory=dict)

    @property
    def variable_count(self) -> int:
        return self.decision.size

    @cached_property
    def decision_shift(self) -> np.ndarray:
        """Index map moving every decision block one stage earlier (see ``stage_shift_index``)."""
        return stage_shift_index(self.decision.offsets, self.decision.size)

    @cached_property
    def constraint_shift(self) -> np.ndarray:
        """Index map moving every constraint block one stage earlier."""
        return stage_shift_index(self.constraint_blocks, self.lower_constraints.size)

    def casadi_dict(self) -> dict[str, ca.SX]:
        return {
            "x": self.decision.vector(),
            "p": self.parameters.vector(),
            "f": self.objective,
            "g": self.constraints,
        }


def stage_shift_index(blocks: dict[str, tuple[int, int]], size: int) -> np.ndarray:
    """Index map ``values[index]`` of ``size`` entries laid out in ``<block>@<stage>`` blocks:
    each block takes the next stage's values, a block's last stage is repeated, and a block
    that exists at one stage only (the initial condition) or entries outside every block keep
    their own."""
    last: dict[str, int] = {}
    for name in blocks:
        base, stage = name.rsplit("@", 1)
        last[base] = max(last.get(base, 0), int(stage))
    index = np.arange(size)
    for name, (start, rows) in blocks.items():
        base, stage = name.rsplit("@", 1)
        source_start, source_rows = blocks[f"{base}@{min(int(stage) + 1, last[base])}"]
        if source_rows == rows:
            index[start : start + rows] = np.arange(source_start, source_start + rows)
    return index


@dataclass
class _Stage:
    states: list[ca.SX] = field(default_factory=list)
    inputs: list[ca.SX] = field(default_factory=list)
    path: list[tuple[str, ca.SX, float, float]] = field(default_factory=list)
    dynamics: list[tuple[ca.SX, ca.SX]] = field(default_factory=list)  # (x_{k+1}, F(x_k, u_k))


class StagewiseBuilder:
    """Collects variables and constraints per stage, then assembles them in stage order.

    Declare all variables stage by stage (``state`` then ``input`` for k, then k + 1); add
    constraints in any order: they are grouped by their stage when assembled. Per stage the
    order is: the dynamics gap x_{k+1} - F(x_k, u_k) = 0, then the path constraints (the
    order fatrop's structure detection expects).
    """

    def __init__(self, name: str, horizon_steps: int) -> None:
        self.name = name
        self.horizon_steps = horizon_steps
        self.decision = BlockLayout("w")
        self.parameters = BlockLayout("p")
        self._stages = [_Stage() for _ in range(horizon_steps + 1)]
        self._objective: ca.SX = ca.SX(0)

    def state(self, stage: int, name: str, size: int) -> ca.SX:
        symbol = self.decision.add(f"{name}@{stage}", size)
        self._stages[stage].states.append(symbol)
        return symbol

    def input(self, stage: int, name: str, size: int) -> ca.SX:
        if stage >= self.horizon_steps:
            raise ValueError("no inputs at the terminal stage")
        symbol = self.decision.add(f"{name}@{stage}", size)
        self._stages[stage].inputs.append(symbol)
        return symbol

    def parameter(self, name: str, size: int) -> ca.SX:
        return self.parameters.add(name, size)

    def path(self, stage: int, name: str, expression: ca.SX, lower: float, upper: float
             ) -> None:
        """lower <= expression <= upper at ``stage`` (element-wise, same bounds for all rows);
        ``name`` (unique within the stage) names the block, e.g. for shifting multipliers."""
        if any(existing == name for existing, *_ in self._stages[stage].path):
            raise ValueError(f"{self.name}: stage {stage}: duplicate path block {name!r}")
        self._stages[stage].path.append((name, expression, lower, upper))

    def dynamics(self, stage: int, next_state: ca.SX, value: ca.SX) -> None:
        """next_state - F(x_k, u_k) = 0 for the transition leaving ``stage``; ``next_state`` must
        be one of the state blocks of stage + 1. Gaps are assembled in state-declaration order."""
        self._stages[stage].dynamics.append((next_state, value))

    def cost(self, term: ca.SX) -> None:
        self._objective = self._objective + term

    def build(self, objective_scale: float = 1.0) -> NlpProblem:
        rows: list[ca.SX] = []
        lower: list[np.ndarray] = []
        upper: list[np.ndarray] = []
        counts = []
        blocks: dict[str, tuple[int, int]] = {}
        row = 0

        def add_rows(name: str, expression: ca.SX, lo: float, up: float) -> int:
            nonlocal row
            n = expression.numel()
            rows.append(expression)
            lower.append(np.full(n, lo))
            upper.append(np.full(n, up))
            blocks[name] = (row, n)
            row += n
            return n

        state_names = {id(symbol): name.rsplit("@", 1)[0] for name, symbol in zip(
            self.decision.offsets, self.decision.symbols, strict=True)}
        for k, stage in enumerate(self._stages):
            count = 0
            gaps = {id(x): x - value for x, value in stage.dynamics}
            if k < self.horizon_steps:
                next_states = self._stages[k + 1].states
                if set(gaps) != {id(x) for x in next_states}:
                    raise ValueError(f"{self.name}: stage {k}: one dynamics gap per state block")
                for x in next_states:
                    add_rows(f"gap_{state_names[id(x)]}@{k}", gaps[id(x)], 0.0, 0.0)
            for name, expression, lo, up in stage.path:
                count += add_rows(f"{name}@{k}", expression, lo, up)
            counts.append(count)
        lbg = np.concatenate(lower)
        ubg = np.concatenate(upper)
        structure = StageStructure(
            state_sizes=[int(sum(s.numel() for s in st.states)) for st in self._stages],
            input_sizes=[int(sum(s.numel() for s in st.inputs)) for st in self._stages],
            path_constraint_counts=counts,
        )
        return NlpProblem(
            name=self.name,
            decision=self.decision,
            parameters=self.parameters,
            objective=objective_scale * self._objective,
            constraints=ca.vertcat(*rows),
            lower_constraints=lbg,
            upper_constraints=ubg,
            equality=[bool(lo == up) for lo, up in zip(lbg, ubg, strict=True)],
            structure=structure,
            constraint_blocks=blocks,
        )
