"""``porter regress``'s second check: run the logged scenario again and recompute its metrics.

The decision replay re-runs the NMPC on logged inputs, so it cannot see a change anywhere
else (the whole-body controller, the gait, the estimator, the loop, the metrics). The
re-simulation runs the log's own scenario (its attached file: team, obstacles, seed, duration)
with the log's effective NMPC and WBC settings on the MuJoCo backend in lockstep (serial ADMM:
deterministic on the same BLAS kernels) and returns the summary the expectations are then
checked against, instead of the summary stored in the log, which nothing recomputes.
"""

from __future__ import annotations

import yaml

from core.locomotion.settings import WbcSettings
from core.nmpc.settings import MpcSettings
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.files import validate_settings
from deploy.config.scenario import Scenario
from deploy.recording import log_format as fmt
from deploy.recording.log_reader import LogError, LogFile
from deploy.runtime.sim_run import SimRun


def logged_run(log: LogFile, mpc_settings: MpcSettings | None = None,
               wbc_settings: WbcSettings | None = None
               ) -> tuple[Scenario, MpcSettings, WbcSettings]:
    """The scenario (serial ADMM) and settings of the logged run; ``mpc_settings`` /
    ``wbc_settings`` replace the logged ones (a changed controller)."""
    source = str(log.path)
    data = yaml.safe_load(log.attachment_text(fmt.SCENARIO_ATTACHMENT))
    if not isinstance(data, dict) or not isinstance(data.get("duration_s"), int | float):
        raise LogError(f"{source}: the attached scenario has no duration_s")
    # A logged run may be shorter than its reference needs (``porter sim --duration``), which
    # a scenario file may not be: validate the file's content, then shorten it again.
    duration_s = float(data["duration_s"])
    scenario = validate_settings({**data, "duration_s": 1e6}, Scenario,
                                 source=f"{source}: scenario")
    scenario = scenario.model_copy(update={
        "duration_s": duration_s,
        "controller": scenario.controller.model_copy(update={"executor": "serial"})})
    mpc = mpc_settings or validate_settings(yaml.safe_load(log.attachment_text(
        fmt.MPC_SETTINGS_ATTACHMENT)), MpcSettings, source=f"{source}: mpc_settings")
    wbc = wbc_settings or validate_settings(yaml.safe_load(log.attachment_text(
        fmt.WBC_SETTINGS_ATTACHMENT)), WbcSettings, source=f"{source}: wbc_settings")
    return scenario, mpc, wbc


def resimulate(log: LogFile, cache: CompiledCodeCache,
               mpc_settings: MpcSettings | None = None,
               wbc_settings: WbcSettings | None = None) -> dict:
    """The summary of the logged run, simulated again from its attachments."""
    scenario, mpc, wbc = logged_run(log, mpc_settings, wbc_settings)
    run = SimRun(scenario, cache, mpc, wbc)
    try:
        return run.run()
    finally:
        run.close()
