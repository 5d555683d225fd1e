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

    @property
    def size(self) -> int:
        return sum(s.numel() for s in self.symbols)

    def add(self, name: str, size: int) -> ca.SX:
        if name in self.offsets:
            raise LayoutError(f"{self.prefix}: duplicate block {name!r}")
        symbol = ca.SX.sym(f"{self.prefix}_{name}", size)
        self.offsets[name] = (self.size, size)
        self.symbols.append(symbol)
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

    def put(self, values: np.ndarray, name: str, block: np.ndarray) -> None:
        target = self.slice(name)
        flat = np.asarray(block, dtype=float).reshape(-1)
        if flat.size != target.stop - target.start:
            raise LayoutError(
                f"{self.prefix}: block {name!r} expects {target.stop - target.start} values, "
                f"got {flat.size} (shape {np.shape(block)})"
            )
        values[target] = flat
