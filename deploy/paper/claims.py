"""The paper's ablation claims as runnable variants, with the paper's own figures beside them.

Each claim is a set of variants of one scenario (two_go2 by default: the 2-agent transport)
that differ only in the controller settings the claim is about, and the metrics the paper
reports for it (Table II and the ablation figure of the paper).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from core.nmpc.settings import ChannelSettings

# The paper's Table II: "time-averaged RMS", the RMS over agents, stages and components of
# each update's last-iteration primal residual (eq. 18), averaged over the updates. Porter's
# summary also keeps the RMS over updates (``admm_residual_rms``), shown beside it.
RESIDUALS = ("admm_residual_mean.payload_position_m", "admm_residual_mean.force_n")
RMS_RESIDUALS = ("admm_residual_rms.payload_position_m", "admm_residual_rms.force_n")


@dataclass(frozen=True)
class Variant:
    """One run: ``controller`` fields of the scenario and ``coupling_enabled`` replaced."""

    label: str
    controller: dict = field(default_factory=dict)
    coupling_enabled: bool = True
    paper: dict[str, float] = field(default_factory=dict)  # metric -> the paper's figure
    executor: str | None = None  # where the local solves run, when not the command's choice


@dataclass(frozen=True)
class Claim:
    name: str
    statement: str
    metrics: tuple[str, ...]  # dotted summary keys
    series: tuple[str, ...]  # RunMetrics lists plotted over time
    variants: tuple[Variant, ...]


_DELAYED = ChannelSettings(max_delay_rounds=20, drop_probability=0.5)

CLAIMS = {claim.name: claim for claim in (
    Claim("delay", "communication delays (up to 20 rounds, p = 0.5 dropouts, hold-last) "
          "increase the consensus residuals, but transport stays stable",
          (*RESIDUALS, *RMS_RESIDUALS), ("position_residual_m", "force_residual_n"), (
              Variant("nominal", paper={RESIDUALS[0]: 6.97e-5, RESIDUALS[1]: 7.40e-2}),
              Variant("delayed, hold-last (paper)",
                      {"channel": _DELAYED.model_copy(update={"max_age_rounds": None})},
                      paper={RESIDUALS[0]: 1.87e-2, RESIDUALS[1]: 5.93}),
              Variant("delayed, fresh <= 2 rounds (porter)", {"channel": _DELAYED}),
              # the same over real Zenoh: every s^i crosses it, the delays and drops are
              # applied to what arrives (the emulated channel, seeded as above)
              Variant("delayed, fresh <= 2, over Zenoh agents", {"channel": _DELAYED},
                      executor="zenoh"))),
    Claim("iterations", "more ADMM iterations per update reduce the force residual; two "
          "balance consensus and computation", (RESIDUALS[1], RMS_RESIDUALS[1]),
          ("force_residual_n",), tuple(
              Variant(f"{n} iteration{'s' if n > 1 else ''}", {"admm_iterations": n},
                      paper={RESIDUALS[1]: figure})
              for n, figure in ((1, 9.93e-2), (2, 7.70e-2), (3, 4.92e-2), (6, 2.62e-2)))),
    Claim("consensus", "payload-state consensus with holonomic constraints cuts the payload "
          "yaw error about 4x against wrench-only consensus",
          ("rms_payload_yaw_error_rad",), ("yaw_error_rad",), (
              Variant("rho_x 1e4, holonomic", paper={"rms_payload_yaw_error_rad": 0.116}),
              Variant("rho_x 10, no holonomic", {"rho_state": 10.0}, coupling_enabled=False,
                      paper={"rms_payload_yaw_error_rad": 0.481}),
              Variant("rho_x 0, no holonomic", {"rho_state": 0.0}, coupling_enabled=False,
                      paper={"rms_payload_yaw_error_rad": 0.482}))),
)}
