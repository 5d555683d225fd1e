"""Package namespaces that import a name's module only when the name is first used (PEP 562)."""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

__all__ = ["lazy_exports"]


def lazy_exports(package: str, sources: dict[str, list[str]]) -> Callable[[str], Any]:
    """A module ``__getattr__`` for ``package``: ``sources`` maps each module to the public
    names it defines; a name not listed raises ``AttributeError`` as usual. Type checkers see
    the names as ``Any``: porter's own modules import from the defining module."""
    where = {name: module for module, names in sources.items() for name in names}

    def attribute(name: str) -> Any:
        if name not in where:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        return getattr(importlib.import_module(where[name]), name)

    return attribute
