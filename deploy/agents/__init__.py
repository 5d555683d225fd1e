"""ADMM agents on the network: the wire schema, ``porter agent`` and the Zenoh executor.

``wire`` (protobuf messages, checked on receipt), ``zenoh_session`` (settings, keys, peer
sessions), ``agent`` (one robot's local solver served over Zenoh), ``zenoh_executor`` (the
coordinator's side: a ``LocalSolveExecutor`` whose agents are processes). Names load on first
use (``core.lazy_exports``): importing the package imports neither Zenoh nor CasADi.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "deploy.agents.agent": ["AdmmAgent", "AgentAddress"],
    "deploy.agents.wire": ["WireError", "ProblemSizes", "WIRE_VERSION", "problem_digest"],
    "deploy.agents.zenoh_executor": ["ZenohExecutor"],
    "deploy.agents.zenoh_session": ["AgentNetwork", "open_session"],
}
__all__ = ["WIRE_VERSION", "AdmmAgent", "AgentAddress", "AgentNetwork", "WireError",
           "ProblemSizes", "ZenohExecutor", "open_session", "problem_digest"]
__getattr__ = lazy_exports(__name__, _SOURCES)
