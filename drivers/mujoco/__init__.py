"""The MuJoCo team: the scene built from the URDFs, the simulation and its driver ends.

Names load on first use (``core.lazy_exports``), so importing the package imports nothing
else.
"""

from __future__ import annotations

from core.lazy_exports import lazy_exports

_SOURCES = {
    "drivers.mujoco.scene": ["robot_urdf_text", "urdf_effort_limits_nm", "robot_spec",
        "RobotIndices", "TeamScene", "build_team_scene"],
    "drivers.mujoco.simulation": ["TeamSimulation"],
    "drivers.mujoco.sim_links": ["SimRobotDriver", "SimMocap", "SimWrenchSensors",
        "SimulatedEstop"],
}
__all__ = ["RobotIndices", "SimMocap", "SimRobotDriver", "SimWrenchSensors", "SimulatedEstop",
           "TeamScene", "TeamSimulation", "build_team_scene", "robot_spec", "robot_urdf_text",
           "urdf_effort_limits_nm"]
__getattr__ = lazy_exports(__name__, _SOURCES)
