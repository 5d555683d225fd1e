"""Flight logs in Rerun: Rerun's MCAP converter accepts porter logs, ``porter replay --rrd``
and the live sink write recordings with the expected entities (read back with Rerun's own
chunk reader), and unusable logs give exit code 2 with a clear message."""

from __future__ import annotations

import subprocess
import sys
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest
import rerun.chunk as rrc

from deploy.cli.porter import main
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.recording import log_format as fmt
from deploy.recording.flight_recorder import FlightRecorder
from deploy.recording.log_reader import LogFile
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.recording.run_record import open_run_recorder
from deploy.runtime.sim_run import SimRun
from deploy.viewing.rerun_view import live_sink

RERUN = Path(sys.executable).with_name("rerun")
ROBOTS = ("go2_0", "go2_1")


@dataclass
class Entity:
    rows: int = 0  # temporal rows (static ones not counted)
    components: set[str] = field(default_factory=set)


def rrd_entities(path: Path) -> dict[str, Entity]:
    """Entity path -> temporal row count and component columns, from the recording store."""
    entities: dict[str, Entity] = {}
    for chunk in rrc.RrdReader(path).stream().to_chunks():
        entity = entities.setdefault(chunk.entity_path, Entity())
        if not chunk.is_static:
            entity.rows += chunk.num_rows
        entity.components |= {name for name in chunk.to_record_batch().schema.names
                              if ":" in name}
    return entities


@pytest.fixture(scope="module")
def porter_log(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """0.5 s of ``narrow_passage`` (two Go2, two obstacles), recorded."""
    scenario = load_scenario("narrow_passage")
    scenario = scenario.model_copy(update={
        "duration_s": 0.5,
        "controller": scenario.controller.model_copy(update={"executor": "serial"})})
    path = tmp_path_factory.mktemp("replay") / "narrow_passage.mcap"
    loop = SimRun(scenario, CompiledCodeCache())
    recorder = open_run_recorder(path, scenario, loop.settings, loop.wbc_settings, "mujoco",
                                 blas_kernels=loop.control.cache.blas_kernels().target)
    loop.attach_recorder(recorder)
    summary = None
    try:
        summary = loop.run()
    finally:
        loop.close()
        recorder.close(summary)
    return path


def test_rerun_mcap_converter_accepts_a_porter_log(porter_log: Path, tmp_path: Path) -> None:
    out = tmp_path / "converted.rrd"
    result = subprocess.run([str(RERUN), "mcap", "convert", str(porter_log), "-o", str(out)],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert out.stat().st_size > 0


def test_replay_writes_the_scene_and_the_time_series(porter_log: Path, tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "replay.rrd"
    assert main(["replay", str(porter_log), "--rrd", str(out)]) == 0
    assert f"-> {out}" in capsys.readouterr().out
    counts, _, _ = LogFile(porter_log).message_counts()
    entities = rrd_entities(out)
    for robot in ROBOTS:
        body = entities[f"/world/robots/{robot}/body"]
        assert "Transform3D:translation" in body.components
        assert "Boxes3D:half_sizes" not in body.components  # drawn as its URDF model instead
        # the URDF's meshes, under the robot's model entity, each in its link's frame
        meshes = [e for path, e in entities.items() if path.startswith(f"/model_{robot}/")
                  and "Asset3D:blob" in e.components]
        assert len(meshes) >= 13  # Go2: base and 3 visual meshes per leg, plus collisions
        # the root placed in the world and the 12 leg joints moved at 50 Hz per robot
        states = counts[fmt.robot_topic(robot, "state")]
        pose = entities[f"/model_{robot}_pose"]
        assert {"Transform3D:parent_frame", "Transform3D:child_frame"} <= pose.components
        assert pose.rows == pytest.approx(states / 10, abs=1)
        joints = [e for path, e in entities.items()
                  if path.startswith(f"/model_{robot}_joints/")]
        assert len(joints) == 12 and all(e.rows == pose.rows for e in joints)
        assert entities[f"/world/robots/{robot}/foot_targets"].rows == counts[
            fmt.robot_topic(robot, "wbc")]
        assert "Arrows3D:vectors" in entities[f"/world/robots/{robot}/contact_forces"].components
        assert entities[f"/world/robots/{robot}/coupling_force"].rows > 0
        assert entities[f"/forces/{robot}/wbc_grf_sum_n"].rows > 0
        assert entities[f"/forces/{robot}/coupling_force_n"].rows > 0
    assert "Transform3D:translation" in entities["/world/payload"].components
    assert "Boxes3D:half_sizes" in entities["/world/payload/box"].components
    assert entities["/world/couplings"].rows == counts[fmt.TF]
    for j in (0, 1):
        assert "Cylinders3D:radii" in entities[f"/world/obstacles/obstacle_{j}"].components
        assert "LineStrips3D:strips" in entities[
            f"/world/obstacles/obstacle_{j}/safety_circle"].components
    for plan in ("payload_plan", "robot_plans", "consensus_payload_plan"):
        assert entities[f"/world/nmpc/{plan}"].rows == counts[fmt.NMPC_UPDATE]
    # one row per message: every ADMM iteration, every CBF evaluation
    for residual in ("primal_payload_rms", "primal_wrench_rms", "dual_norm"):
        assert entities[f"/admm/{residual}"].rows == counts[fmt.ADMM]
    assert entities["/safety/h_m"].rows == counts[fmt.CBF]
    assert entities["/safety/predicted_min_h_m"].rows == counts[fmt.CBF]
    assert entities["/tracking/payload_position_error_m"].rows == counts[fmt.GROUND_TRUTH]
    assert entities["/nmpc/time_s/update"].rows == counts[fmt.NMPC_UPDATE]
    assert entities["/events"].rows == counts[fmt.EVENTS]
    assert "TextDocument:text" in entities["/run"].components
    verify = subprocess.run([str(RERUN), "rrd", "verify", str(out)], capture_output=True,
                            text=True, timeout=120)
    assert verify.returncode == 0, verify.stderr


def test_live_sink_streams_recorded_messages(tmp_path: Path) -> None:
    rrd = tmp_path / "live.rrd"
    sink = live_sink(str(rrd), "test")
    metadata = {fmt.RUN_METADATA: {"log_format_version": str(fmt.LOG_FORMAT_VERSION)}}
    recorder = FlightRecorder(tmp_path / "live.mcap", metadata=metadata, sinks=[sink])
    for tick in range(3):
        time_s = 0.002 * tick
        recorder.log(fmt.robot_topic("r0", "state"), pb.RobotState(
            time_s=time_s, robot="r0", position_in_world_m=[0.1 * tick, 0.0, 0.3],
            quaternion_wxyz=[1.0, 0.0, 0.0, 0.0]), time_s)
        recorder.log(fmt.ADMM, pb.AdmmIteration(time_s=time_s, iteration=tick,
                                                primal_payload_rms=[0.1, 0.2],
                                                primal_wrench_rms=[1.0, 2.0], dual_norm=0.5),
                     time_s)
    plan = np.zeros((2, 9, 12))
    recorder.log(fmt.NMPC_UPDATE, pb.NmpcUpdate(
        robot_trajectories=fmt.array(plan), payload_trajectory=fmt.array(plan[0])), 0.004)
    recorder.event(0.004, "done")
    recorder.close()
    sink.close()
    entities = rrd_entities(rrd)
    assert entities["/world/robots/r0/body"].rows == 3
    assert entities["/admm/primal_payload_rms"].rows == 3
    assert entities["/world/nmpc/robot_plans"].rows == 1
    assert entities["/events"].rows == 1
    messages = Counter(m.topic for m in LogFile(tmp_path / "live.mcap").messages())
    assert messages[fmt.EVENTS] == 1  # no "sink removed" warning


@pytest.mark.parametrize("content, reason", [
    (b"this is not a flight log\n" * 10, "not an MCAP file"),
    (b"\x89MCAP0\r\n" + b"\x00" * 64, "incomplete"),
])
def test_unusable_log_exits_2_with_a_clear_message(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], content: bytes, reason: str) -> None:
    log = tmp_path / "broken.mcap"
    log.write_bytes(content)
    assert main(["replay", str(log), "--rrd", str(tmp_path / "out.rrd")]) == 2
    error = capsys.readouterr().err
    assert error.startswith("porter: ") and reason in error
    assert not (tmp_path / "out.rrd").exists()


def test_replay_rejects_a_connect_target_that_is_no_url(
        porter_log: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["replay", str(porter_log), "--connect", "localhost"]) == 2
    assert "expected a URL" in capsys.readouterr().err
