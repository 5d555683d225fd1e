"""A short recorded run shared by the recording tests (one simulation for the package)."""

from __future__ import annotations

from pathlib import Path

import pytest

from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.recording.flight_recorder import RecorderSettings
from deploy.recording.run_record import open_run_recorder
from deploy.runtime.sim_run import SimRun


@pytest.fixture(scope="package")
def recorded_run(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, list, dict]:
    """A 0.4 s two-Go2 run recorded to MCAP; also every (topic, message, time) as logged."""
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={
        "duration_s": 0.4, "controller": scenario.controller.model_copy(
            update={"executor": "serial"})})
    path = tmp_path_factory.mktemp("log") / "run.mcap"
    loop = SimRun(scenario, CompiledCodeCache())
    logged: list = []
    recorder = open_run_recorder(path, scenario, loop.settings, loop.wbc_settings, "mujoco",
                                 RecorderSettings(warm_start_every=5),
                                 sinks=[lambda topic, message, t: logged.append((topic, message, t))],
                                 blas_kernels=loop.control.cache.blas_kernels().target)
    loop.attach_recorder(recorder)
    try:
        summary = loop.run()
    finally:
        loop.close()
        recorder.close(summary)
    return path, logged, summary
