"""Named blocks of a flat vector: build CasADi symbols and pack/unpack NumPy values by name."""

from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca
import numpy as np


class LayoutError(ValueError):
    """A value does not fit the block it is written into."""


@dataclass
class BlockLayout:
    """Ordered named blocks; ``add`` returns the block's symbol (a column of ``size`` SX)."""

    prefix: str
    offsets: dict[str, tuple[int, int]] = field(default_factory=dict)
    symbols: list[ca.SX] = field(default_factory=list)
    size: int = 0  # total length (kept with ``add``: summing the symbols cost ~0.1 ms a read)
    _stage_rows: dict[tuple[str, int], np.ndarray] = field(
        default_factory=dict, repr=False, compare=False)

    def add(self, name: str, size: int) -> ca.SX:
        if name in self.offsets:
            raise LayoutError(f"{self.prefix}: duplicate block {name!r}")
        symbol = ca.SX.sym(f"{self.prefix}_{name}", size)
        self.offsets[name] = (self.size, size)
        self._stage_rows.clear()
        self.symbols.append(symbol)
        self.size += size
        return symbol

    def vector(self) -> ca.SX:
        return ca.vertcat(*self.symbols)

    def slice(self, name: str) -> slice:
        try:
            start, size = self.offsets[name]
        except KeyError:
            raise LayoutError(
                f"{self.prefix}: no block {name!r}; available: {', '.join(self.offsets)}"
            ) from None
        return slice(start, start + size)

    def get(self, values: np.ndarray, name: str) -> np.ndarray:
        return np.asarray(values)[self.slice(name)]

    def stage_rows(self, block: str, stages: int) -> np.ndarray:
        """(stages, size) row indices of blocks ``block@0`` ... ``block@{stages - 1}`` (of one
        size): ``values[rows]`` reads them all in one indexing instead of a ``get`` per stage.
        Built once per (block, stages)."""
        rows = self._stage_rows.get((block, stages))
        if rows is None:
            rows = np.array([np.arange(*self.slice(f"{block}@{k}").indices(self.size))
                             for k in range(stages)])
            rows.flags.writeable = False  # shared by every caller (and ``DecisionRows``' views)
            self._stage_rows[(block, stages)] = rows
        return rows

    def put(self, values: np.ndarray, name: str, block: np.ndarray) -> None:
        target = self.slice(name)
        flat = np.asarray(block, dtype=float).reshape(-1)
        if flat.size != target.stop - target.start:
            raise LayoutError(
                f"{self.prefix}: block {name!r} expects {target.stop - target.start} values, "
                f"got {flat.size} (shape {np.shape(block)})"
            )
        values[target] = flat


@dataclass(frozen=True)
class DecisionRows:
    """Where the per-stage blocks of a transport problem's decision start, as index arrays,
    so bounds and guesses are read and written without a Python loop over stages:
    ``robot_state[key][k]`` and ``payload_state[k]`` (k = 0..N) the first row of that state,
    ``grf_z[key]`` (N, 4) the rows of each foot's normal force, ``slack`` every barrier-slack row
    (none without soft barriers)."""

    robot_state: dict[str, np.ndarray]
    payload_state: np.ndarray
    grf_z: dict[str, np.ndarray]
    slack: np.ndarray

    @staticmethod
    def of(decision: BlockLayout, horizon_steps: int, robot_keys: list[str],
           slack_block: str) -> DecisionRows:
        n = horizon_steps
        soft = f"{slack_block}@0" in decision.offsets
        return DecisionRows(
            robot_state={key: decision.stage_rows(f"robot_{key}", n + 1)[:, 0]
                         for key in robot_keys},
            payload_state=decision.stage_rows("payload", n + 1)[:, 0],
            # (x, y, z) per foot: every third row from the third
            grf_z={key: decision.stage_rows(f"grf_{key}", n)[:, 2::3] for key in robot_keys},
            slack=(decision.stage_rows(slack_block, n).reshape(-1) if soft
                   else np.zeros(0, dtype=int)),
        )

def shared_indices(decision: BlockLayout, horizon_steps: int, agent_count: int
                   ) -> np.ndarray:
    """Where the shared trajectory s (``TransportProblem.shared_trajectory``) sits in a local
    or centralized decision vector laid out by ``decision``: ``solution[indices]`` is s
    (payload states k = 1..N, then wrench j = 1..n_A over k = 0..N-1)."""
    n = horizon_steps
    return np.concatenate([decision.stage_rows("payload", n + 1)[1:].reshape(-1)]
                          + [decision.stage_rows(f"wrench_{j}", n).reshape(-1)
                             for j in range(agent_count)])
