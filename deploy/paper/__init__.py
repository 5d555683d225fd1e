"""The paper's claims reproduced: one ``porter paper CLAIM`` per ablation, porter's figures
beside the paper's.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.paper.claims": ["CLAIMS", "Claim", "Variant"],
    "deploy.paper.experiments": ["EXPERIMENTS", "reproduce_experiments"],
    "deploy.paper.reproduce": ["reproduce", "run_claim"],
    "deploy.paper.table1": ["PAPER_TABLE1", "reproduce_table1"],
}
__all__ = ["CLAIMS", "EXPERIMENTS", "PAPER_TABLE1", "Claim", "Variant", "reproduce",
           "reproduce_experiments", "reproduce_table1", "run_claim"]
__getattr__ = lazy_exports(__name__, _SOURCES)
