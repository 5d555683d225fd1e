"""The safety settings of deploy configs (``safety:``, ``watchdog:``): typed, bounded, and free of
driver imports, so that loading a configuration loads no driver."""

from __future__ import annotations

from pydantic import Field

from core.model.strict_model import StrictModel

__all__ = ["SupervisorSettings", "WatchdogSettings"]


class SupervisorSettings(StrictModel):
    """Fault thresholds of the safety supervisor (``safety:`` in deploy configs)."""

    # Every bound keeps the check meaningful: a timeout longer than ~1 s, a tilt past ~70
    # degrees, zero damping in a safe stop or a budget that can never be used up would switch
    # the safety off without saying so.
    mocap_timeout_s: float = Field(0.1, gt=0.0, le=1.0, description="oldest MoCap frame "
                                   "tolerated [s]")
    heartbeat_timeout_s: float = Field(
        0.1, gt=0.0, le=1.0,
        description="informational: the EstopMonitor applies its own timeout [s]")
    max_consecutive_solver_failures: int = Field(
        3, ge=0, le=30, description="more consecutive failed NMPC updates than this trip")
    deadline_overrun_budget: int = Field(
        30, ge=0, le=600, description="more NMPC deadline overruns than this within the "
                                      "window trip (at most nmpc_hz x window in a deploy config)")
    deadline_window_s: float = Field(1.0, gt=0.0, le=10.0,
                                     description="window of the overrun budget [s]")
    max_tilt_rad: float = Field(0.7, gt=0.0, le=1.2,
                                description="largest trunk tilt from upright [rad]")
    min_base_height_fraction: float = Field(
        0.5, ge=0.1, le=1.0, description="lowest base height, fraction of the nominal standing "
                                         "height (checked while ARMED and RUNNING)")
    max_joint_velocity_rad_s: float = Field(30.0, gt=0.0, le=60.0)
    # A leg pressed against its end stop reads a little past the URDF limit (MuJoCo's soft
    # limits; encoder offsets on robots): with no margin, a stretched leg in a tight spot was a
    # safe stop, and the damping that followed made the loaded team fall.
    joint_limit_margin_rad: float = Field(
        0.1, ge=0.0, le=0.2,
        description="joint positions within [lower - margin, upper + margin] are fine [rad]")
    torque_limit_fraction: float = Field(
        1.0, gt=0.0, le=1.0, description="commanded |tau| beyond fraction * limit trips")
    damping_kd: float = Field(2.0, gt=0.0, le=20.0,
                              description="joint damping [N m s/rad] in a safe stop")
    max_consecutive_wbc_failures: int = Field(
        2, ge=0, le=25, description="more consecutive failed WBC QPs of one robot than this "
                                    "trip (a failed tick repeats the robot's last torques)")
    stale_state_hold_ticks: int = Field(
        2, ge=1, le=50, description="from this many loop ticks in a row without a new state of "
                                    "a robot on, it gets its last fresh command again "
                                    "(deploy.runtime.team_commands)")
    stale_state_budget_s: float = Field(
        0.05, ge=0.004, le=1.0, description="a RUNNING robot whose state has not advanced for "
                                            "longer than this [s] trips: up to it the motors "
                                            "hold its last fresh command (stalls of 40-55 ms "
                                            "rode through), past it the hold may no longer "
                                            "carry a leg (a 60 ms stall whipped a calf to 36 "
                                            "rad/s once)")
    loop_overrun_budget: int = Field(
        50, ge=0, le=500, description="more control-loop ticks starting over a period late "
                                      "than this within deadline_window_s trip")


class WatchdogSettings(StrictModel):
    """``watchdog:`` in deploy configs."""

    enabled: bool = True
    timeout_s: float = Field(0.025, gt=0.0, le=0.5,
                             description="heartbeat older than this: take over [s]")
    period_s: float = Field(0.002, gt=0.0, le=0.02,
                            description="damping command period after taking over [s]")
    damping_s: float = Field(5.0, gt=0.0, le=60.0,
                             description="send damping this long, then exit [s]")
