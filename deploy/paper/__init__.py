"""The paper's claims reproduced: one ``porter paper CLAIM`` per ablation, porter's figures
beside the paper's.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.paper.claims": ["CLAIMS", "Claim", "Variant"],
    "deploy.paper.reproduce": ["reproduce", "run_claim"],
}
__all__ = ["CLAIMS", "Claim", "Variant", "reproduce", "run_claim"]
__getattr__ = lazy_exports(__name__, _SOURCES)
