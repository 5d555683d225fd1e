"""A CasADi function of one parameter vector, evaluated in place: inputs are NumPy views into
that vector, outputs land in preallocated arrays (no allocation per call), as compiled C from
the code cache when one is given.

CasADi's ``Function.buffer()`` evaluates with ~0.1 µs of call overhead against ~15 µs for a
normal call from Python (measured), which is what makes a function per robot and tick cheap.
"""

from __future__ import annotations

import casadi as ca
import numpy as np

from core.nmpc.nlp_solver import NlpCompiler, function_key

__all__ = ["BufferedFunction", "ParameterVector"]


class ParameterVector:
    """Named blocks of one parameter vector: ``views[name]`` (NumPy, to fill) and
    ``symbols[name]`` (CasADi SX, to build expressions from), each (rows, cols) column-major as
    CasADi reads a dense matrix (1-D views for vectors)."""

    def __init__(self, sizes: list[tuple[str, int, int]]) -> None:
        total = sum(rows * cols for _, rows, cols in sizes)
        self.values = np.zeros(total)
        self.vector = ca.SX.sym("p", total)
        self.views: dict[str, np.ndarray] = {}
        self.symbols: dict[str, ca.SX] = {}
        start = 0
        for name, rows, cols in sizes:
            block = self.values[start:start + rows * cols]
            self.views[name] = block if cols == 1 else block.reshape((rows, cols), order="F")
            self.symbols[name] = ca.reshape(self.vector[start:start + rows * cols], rows, cols)
            start += rows * cols


class BufferedFunction:
    """``outputs`` of ``parameters``' symbols as one function named ``name``; ``evaluate()``
    writes them (dense, column-major) into ``results`` from ``parameters.values`` as filled now.

    ``compiler``: the function as compiled C from this cache (built once per expression and
    CasADi version); None: CasADi's SX virtual machine, the same numbers bit for bit."""

    def __init__(self, name: str, parameters: ParameterVector, outputs: list[ca.SX],
                 results: list[np.ndarray], compiler: NlpCompiler | None = None) -> None:
        # dense outputs: the buffer interface writes nonzeros, the callers read full arrays
        self.function = ca.Function(name, [parameters.vector], [ca.densify(x) for x in outputs])
        self.compiled = compiler is not None
        evaluated = self.function
        if compiler is not None:
            function = self.function

            def generate_c(path: str) -> None:
                function.generate(path)

            library = compiler.library_for(name, function_key(function), generate_c)
            evaluated = ca.external(name, library)
        self.results = results
        self._buffer, self.evaluate = evaluated.buffer()
        # CasADi's Python binding takes (index, memoryview) and reads the size from the view;
        # its type stubs list the C++ signature with the size
        self._buffer.set_arg(0, memoryview(parameters.values))  # type: ignore[call-arg, arg-type]
        for index, array in enumerate(results):
            if array.size != self.function.nnz_out(index) or not array.flags.c_contiguous:
                raise ValueError(f"{name}: result {index} needs {self.function.nnz_out(index)} "
                                 f"contiguous values, got {array.shape}")
            self._buffer.set_res(index, memoryview(array.reshape(-1)))  # type: ignore[call-arg, arg-type]
