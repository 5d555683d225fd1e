"""How messages between ADMM agents travel: a seeded lossy, delaying channel with hold-last.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {"core.communication.lossy_channel": ["LossyChannel"]}
__all__ = ["LossyChannel"]
__getattr__ = lazy_exports(__name__, _SOURCES)
