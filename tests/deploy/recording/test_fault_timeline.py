"""``porter log timeline --around-fault`` on a recorded run: a robot whose state stalls 18 ms
and then turns NaN (a safe stop), read back from the MCAP file."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from deploy.cli.porter import main
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.recording.fault_timeline import fault_timelines, format_timelines
from deploy.recording.flight_recorder import RecorderSettings
from deploy.recording.log_reader import LogFile
from deploy.recording.run_record import open_run_recorder
from deploy.runtime.sim_run import SimRun
from drivers.interfaces import JointCommand, RobotDriver, RobotMeasurement

STALL = (0.40, 0.418)  # simulated seconds in which go2_0's state does not advance
NAN_AT_S = 0.43


class StallThenNan:
    """A driver whose state repeats during ``STALL`` and has a NaN joint from ``NAN_AT_S``."""

    def __init__(self, driver: RobotDriver) -> None:
        self.driver, self.name = driver, driver.name
        self.last: RobotMeasurement | None = None

    def read(self) -> RobotMeasurement:
        measurement = self.driver.read()
        if self.last is None or not STALL[0] <= measurement.time_s < STALL[1]:
            self.last = measurement
        if measurement.time_s >= NAN_AT_S:
            q = measurement.position_rad.copy()
            q[2] = np.nan
            return replace(measurement, position_rad=q)
        return self.last

    def send(self, command: JointCommand) -> None:
        self.driver.send(command)

    def send_damping(self, kd: float) -> None:
        self.driver.send_damping(kd)

    def close(self) -> None:
        self.driver.close()


@pytest.fixture(scope="module")
def stopped_log(tmp_path_factory: pytest.TempPathFactory) -> Path:
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={"duration_s": 0.6, "controller": (
        scenario.controller.model_copy(update={"executor": "serial"}))})
    path = tmp_path_factory.mktemp("timeline") / "stopped.mcap"
    run = SimRun(scenario, CompiledCodeCache())
    run.links.drivers["go2_0"] = StallThenNan(run.links.drivers["go2_0"])
    recorder = open_run_recorder(path, scenario, run.settings, run.wbc_settings, "mujoco",
                                 RecorderSettings(),
                                 blas_kernels=run.control.cache.blas_kernels().target)
    run.attach_recorder(recorder)
    try:
        summary = run.run(verbose=False)
    finally:
        run.close()
        recorder.close(summary)
    assert "non-finite measurement: go2_0" in summary["safety"]["safe_stop"]
    return path


def test_the_timeline_finds_the_stall_before_the_stop(stopped_log: Path) -> None:
    timelines = fault_timelines(LogFile(stopped_log))
    assert len(timelines) == 1
    timeline = timelines[0]
    assert NAN_AT_S <= timeline.time_s < NAN_AT_S + 0.004
    assert "non-finite measurement: go2_0" in timeline.cause
    assert timeline.tick_period_s == pytest.approx(0.002, rel=0.01)
    go2_0, go2_1 = timeline.robots
    assert (go2_0.robot, go2_1.robot) == ("go2_0", "go2_1")
    # the 18 ms stall: one run of held states, from the last state before 0.40 s
    assert len(go2_0.held_states) == 1
    start_s, held_s, ticks = go2_0.held_states[0]
    assert STALL[0] - 0.0025 < start_s < STALL[0]
    assert held_s == pytest.approx(STALL[1] - STALL[0] + 0.002, abs=0.0021)
    assert ticks == 9
    assert go2_1.held_states == []
    # lockstep: no tick is late; the gait is trotting, feet in stance at the stop listed
    assert go2_0.late_ticks == [] == go2_1.late_ticks
    assert go2_0.stance and all(len(p) == 4 and set(p) <= {"0", "1"} for _, p in go2_0.stance)
    assert go2_0.fastest_joint is not None and 0 <= go2_0.fastest_joint[0] < 12
    assert timeline.plans_in_window >= 2  # 60 Hz over 50 ms
    text = format_timelines(timelines)
    assert "go2_0: held states: -" in text and "(9 ticks)" in text
    assert "go2_1: held states: none" in text


def test_porter_log_timeline_prints_and_writes_json(stopped_log: Path, tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "timeline.json"
    assert main(["log", "timeline", str(stopped_log), "--around-fault", "--json",
                 str(out)]) == 0
    printed = capsys.readouterr().out
    assert printed.startswith("safe stop at 0.43")
    data = json.loads(out.read_text())
    assert data[0]["robots"][0]["held_states"][0][2] == 9
    # a narrower window misses the stall, which ended 12 ms before the stop
    assert main(["log", "timeline", str(stopped_log), "--around-fault", "--window-ms",
                 "5"]) == 0
    assert "go2_0: held states: none" in capsys.readouterr().out


def test_porter_log_timeline_rejects_bad_input(tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "missing.mcap"
    assert main(["log", "timeline", str(missing), "--around-fault"]) == 2
    assert "missing.mcap" in capsys.readouterr().err
    for bad in ("nan", "0", "10001"):
        with pytest.raises(SystemExit) as usage:
            main(["log", "timeline", str(missing), "--around-fault", "--window-ms", bad])
        assert usage.value.code == 2
        assert "--window-ms: must be a finite number in (0, 10000]" in capsys.readouterr().err


def test_a_log_without_a_safe_stop_says_so() -> None:
    log = Path(__file__).resolve().parents[3] / "logs" / "two_go2.mcap"
    assert fault_timelines(LogFile(log)) == []
    assert format_timelines([]) == "no safe stop in this log"
