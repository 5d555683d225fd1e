"""The flight recorder: every channel reads back equal, drops are counted and said, crash
safety (exceptions, SIGTERM, kill -9 + recover), clear errors on bad files."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from google.protobuf.json_format import MessageToDict
from mcap.reader import make_reader
from mcap_protobuf.decoder import DecoderFactory

from deploy.cli.porter import main
from deploy.compute.codegen_cache import CompiledCodeCache
from deploy.config.scenario import load_scenario
from deploy.recording import log_format as fmt
from deploy.recording.flight_recorder import FlightRecorder, RecorderSettings
from deploy.recording.log_reader import LogError, LogFile, recover
from deploy.recording.messages import porter_log_pb2 as pb
from deploy.recording.robot_scene import LINK_TF, ROBOT_SCENE
from deploy.recording.run_record import open_run_recorder
from deploy.runtime.sim_run import SimRun

REPOSITORY = Path(__file__).resolve().parents[3]
PORTER = [sys.executable, "-m", "deploy.cli"]


def test_every_channel_reads_back_equal(recorded_run: tuple[Path, list, dict]) -> None:
    """Read with the mcap library alone: every message the sinks saw (the loop's, the events
    again as foxglove.Log, the derived link transforms) is in the file, in order, at the wall
    clock's log time of its run time; Foxglove timestamps moved alike, porter's kept."""
    path, logged, summary = recorded_run
    with open(path, "rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        origin_ns = int({m.name: m.metadata for m in reader.iter_metadata()}
                        [fmt.CLOCK_METADATA]["time_origin_ns"])
        read_all = [(channel.topic, decoded, message.log_time - origin_ns, schema.name)
                    for schema, channel, message, decoded in reader.iter_decoded_messages(
                        log_time_order=False)]
    assert 0 < time.time_ns() - origin_ns < 3600e9  # the run started within the last hour
    # every event is written twice: porter's Event and a foxglove.Log for Foxglove's Log panel
    events = [(m, t) for topic, m, t in logged if topic == fmt.EVENTS]
    logs = [(m, t, schema) for topic, m, t, schema in read_all if topic == fmt.FOXGLOVE_LOG]
    assert len(logs) == len(events) > 0
    levels = {0: 2, 1: 3, 2: 4}  # porter INFO/WARNING/ERROR -> foxglove.Log INFO/WARNING/ERROR
    for (log_message, time_ns, schema), (event, event_time) in zip(logs, events, strict=True):
        assert schema == "foxglove.Log" and time_ns == event_time
        assert log_message.timestamp.ToNanoseconds() == origin_ns + event_time
        assert (log_message.message, log_message.name) == (event.text, event.source)
        assert log_message.level == levels[event.level]
    assert len(read_all) == len(logged)
    for (topic, decoded, time_ns, _), (topic_logged, message, time_logged) in zip(
            read_all, logged, strict=True):
        assert (topic, time_ns) == (topic_logged, time_logged)
        expected = fmt.on_log_clock(message, origin_ns)  # Foxglove's stamps on the log clock
        if expected is message:  # porter's own messages keep the run time
            assert getattr(message, "time_s", time_logged * 1e-9) == pytest.approx(
                time_logged * 1e-9, abs=0.01)
        message = expected
        # the decoder builds its classes from the file's own schema: compare field by field
        assert MessageToDict(decoded) == MessageToDict(message), topic
        assert decoded.SerializeToString() == message.SerializeToString(), topic
    topics = {topic for topic, _, _, _ in read_all}
    expected = {fmt.TF, LINK_TF, ROBOT_SCENE, fmt.FOXGLOVE_LOG, fmt.OBSTACLES, fmt.NMPC_INPUTS,
                fmt.NMPC_WARM_START, fmt.NMPC_UPDATE, fmt.ADMM, fmt.CBF, fmt.PAYLOAD_ESTIMATE,
                fmt.GROUND_TRUTH, fmt.LOOP_TIMING, fmt.EVENTS, "/mocap/payload"}
    for robot in ("go2_0", "go2_1"):
        expected |= {fmt.robot_topic(robot, kind) for kind in ("state", "command", "wbc",
                                                                "wrench")}
        expected.add(fmt.mocap_topic(robot))
    assert expected <= topics
    log = LogFile(path)
    assert log.summary() == json.loads(json.dumps(summary))
    counts, start_ns, end_ns = log.message_counts()
    assert start_ns == 0 and end_ns == pytest.approx(0.4e9, abs=0.01e9)  # run times again
    assert counts[fmt.NMPC_UPDATE] == summary["nmpc_updates"] == 24
    assert counts[fmt.robot_topic("go2_0", "state")] == 200  # 500 Hz for 0.4 s
    assert counts[fmt.NMPC_WARM_START] == 5  # every 5th of 24 updates
    metadata = log.metadata()[fmt.RUN_METADATA]
    assert metadata["log_format_version"] == str(fmt.LOG_FORMAT_VERSION)
    assert metadata["scenario"] == "two_go2" and metadata["git_revision"]
    assert {"scenario.yaml", "mpc_settings.yaml", "robots/go2.urdf"} <= set(log.attachments())


def test_logged_values_are_the_loop_values(recorded_run: tuple[Path, list, dict]) -> None:
    path, logged, _ = recorded_run
    log = LogFile(path)
    inputs = next(log.messages([fmt.NMPC_INPUTS])).message
    states = fmt.from_array(inputs.robot_states)
    assert states.shape == (2, 12) and inputs.update == 0
    state = next(m.message for m in log.messages([fmt.robot_topic("go2_0", "state")]))
    # the NMPC's first robot state and the first measurement share the robot's position
    # (SRB CoM vs trunk origin differ by the fixed CoM offset, < 5 cm)
    assert np.linalg.norm(states[0, 0:3] - np.array(state.position_in_world_m)) < 0.05
    update = next(log.messages([fmt.NMPC_UPDATE])).message
    grf = fmt.from_array(update.grf)
    assert grf.shape == (2, 12)
    # the team stands at t = 0: the planned GRFs carry the robots and the payload
    assert 0.8 < grf[:, 2::3].sum() / (9.81 * (2 * 15.0 + 5.0)) < 1.3
    events = [m.message.text for m in log.messages([fmt.EVENTS])]
    assert events[0].startswith("start: scenario two_go2") and events[-1].startswith("end:")


def test_queue_overflow_drops_counts_and_says_so(tmp_path: Path) -> None:
    path = tmp_path / "small.mcap"
    recorder = FlightRecorder(path, RecorderSettings(queue_size=2),
                              {fmt.RUN_METADATA: {"log_format_version": str(
                                  fmt.LOG_FORMAT_VERSION)}})
    accepted = sum(recorder.log("/x", pb.Event(text=str(i)), i * 1e-3) for i in range(5000))
    recorder.close()
    assert recorder.dropped == 5000 - accepted > 0
    log = LogFile(path)
    assert log.metadata()["recorder"]["messages_dropped"] == str(recorder.dropped)
    texts = [m.message.text for m in log.messages([fmt.EVENTS])]
    assert any("dropped" in text for text in texts)


def test_an_exception_still_leaves_a_complete_file(tmp_path: Path) -> None:
    path = tmp_path / "crash.mcap"
    with pytest.raises(RuntimeError), FlightRecorder(
            path, metadata={fmt.RUN_METADATA: {"log_format_version": str(
                fmt.LOG_FORMAT_VERSION)}}) as recorder:
        recorder.log("/x", pb.Event(text="before"), 0.1)
        raise RuntimeError("controller crashed")
    assert [m.message.text for m in LogFile(path).messages(["/x"])] == ["before"]


def _start_sim(log: Path) -> subprocess.Popen:
    return subprocess.Popen(
        [*PORTER, "sim", "two_go2", "--serial", "--quiet", "--duration", "16",
         "--record", str(log)], cwd=REPOSITORY, stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE, text=True)


def _wait_for_chunks(process: subprocess.Popen, log: Path, size_bytes: int) -> None:
    deadline = time.monotonic() + 120
    while not (log.exists() and log.stat().st_size > size_bytes):
        assert process.poll() is None, process.stderr.read() if process.stderr else ""
        assert time.monotonic() < deadline, "the run wrote no chunks"
        time.sleep(0.2)


@pytest.mark.slow
def test_sigterm_finishes_the_file(tmp_path: Path) -> None:
    log = tmp_path / "term.mcap"
    process = _start_sim(log)
    _wait_for_chunks(process, log, 200_000)
    process.send_signal(signal.SIGTERM)
    assert process.wait(60) == 130
    counts, _, _ = LogFile(log).message_counts()
    assert counts[fmt.NMPC_UPDATE] > 10


@pytest.mark.slow
def test_kill_9_leaves_a_file_that_recover_reads(tmp_path: Path) -> None:
    log = tmp_path / "killed.mcap"
    process = _start_sim(log)
    _wait_for_chunks(process, log, 200_000)
    os.kill(process.pid, signal.SIGKILL)
    process.wait(30)
    with pytest.raises(LogError, match="incomplete.*porter log recover"):
        LogFile(log)
    assert main(["log", "recover", str(log)]) == 0
    recovered = LogFile(log.with_suffix(".recovered.mcap"))
    counts, _, _ = recovered.message_counts()
    assert counts[fmt.NMPC_UPDATE] > 10
    assert "scenario.yaml" in recovered.attachments()


def test_bad_files_get_clear_errors(tmp_path: Path, recorded_run: tuple[Path, list, dict]
                                    ) -> None:
    source = recorded_run[0].read_bytes()
    garbage = tmp_path / "garbage.mcap"
    garbage.write_bytes(b"not a log at all" * 10)
    with pytest.raises(LogError, match="not an MCAP file"):
        LogFile(garbage)
    truncated = tmp_path / "truncated.mcap"
    truncated.write_bytes(source[: len(source) // 2])
    with pytest.raises(LogError, match="incomplete"):
        LogFile(truncated)
    corrupted = tmp_path / "corrupted.mcap"
    # zero 4 KiB inside the compressed records of a middle chunk (the middle of the file may
    # fall on an attachment, which message reading never touches)
    with recorded_run[0].open("rb") as stream:
        summary = make_reader(stream).get_summary()
    assert summary is not None
    chunks = sorted(summary.chunk_indexes, key=lambda c: c.chunk_start_offset)
    chunk = max(chunks[len(chunks) // 4 : 3 * len(chunks) // 4 + 1], key=lambda c: c.chunk_length)
    assert chunk.chunk_length > 3 * 4096
    middle = chunk.chunk_start_offset + chunk.chunk_length // 2
    corrupted.write_bytes(source[:middle] + bytes(4096) + source[middle + 4096:])
    with pytest.raises(LogError, match="corrupted"):
        for _ in LogFile(corrupted).messages():
            pass
    assert recover(corrupted, tmp_path / "salvaged.mcap").chunks_lost
    with pytest.raises(LogError, match="no such|cannot read"):
        LogFile(tmp_path / "missing.mcap")


def test_a_log_from_another_format_version_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "future.mcap"
    FlightRecorder(path, metadata={fmt.RUN_METADATA: {"log_format_version": "99"}}).close()
    with pytest.raises(LogError, match="format version 99.*reads versions"):
        LogFile(path)
    assert main(["log", "info", str(path)]) == 2


def test_log_info_prints_topics_and_summary(recorded_run: tuple[Path, list, dict],
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["log", "info", str(recorded_run[0])]) == 0
    out = capsys.readouterr().out
    assert "/nmpc/update" in out and "500.0" in out and "nmpc_updates: 24" in out
    # written for people: nested metrics named on one line, no Python reprs
    assert "nmpc_update_ms: median " in out and "{" not in out and "True" not in out


def test_chunks_carry_data_crcs_and_a_corrupted_one_is_caught(tmp_path: Path) -> None:
    from mcap.records import Chunk
    from mcap.stream_reader import CRCValidationError, StreamReader

    path = tmp_path / "crc.mcap"
    with FlightRecorder(path, metadata={fmt.RUN_METADATA: {"log_format_version": str(
            fmt.LOG_FORMAT_VERSION)}}) as recorder:
        for i in range(200):
            recorder.log("/x", pb.Event(text=f"event {i}"), i * 1e-3)
    with open(path, "rb") as stream:
        chunks = [r for r in StreamReader(stream, emit_chunks=True, validate_crcs=True).records
                  if isinstance(r, Chunk)]
    assert chunks and all(chunk.uncompressed_crc != 0 for chunk in chunks)
    data = bytearray(path.read_bytes())
    # flip one byte inside the first chunk's compressed records
    offset = bytes(data).find(chunks[0].data)
    assert offset > 0
    data[offset + len(chunks[0].data) // 2] ^= 0xFF
    broken = tmp_path / "broken.mcap"
    broken.write_bytes(bytes(data))
    with open(broken, "rb") as stream, pytest.raises(CRCValidationError, match="Chunk"):
        for _ in StreamReader(stream, validate_crcs=True).records:
            pass


def test_default_log_names_are_unique_and_stay_in_their_folder(tmp_path: Path) -> None:
    from deploy.recording.run_record import default_log_path, safe_file_stem

    scenario = load_scenario("two_go2")
    paths = [default_log_path(scenario, tmp_path) for _ in range(3)]
    assert len(set(paths)) == 3 and all(p.exists() and p.parent == tmp_path for p in paths)
    assert paths[0].name.startswith("two_go2-") and paths[1].stem.endswith("-2")
    escaping = scenario.model_copy(update={"name": "../../etc/passwd"})
    path = default_log_path(escaping, tmp_path / "runs", prefix="deploy-")
    assert path.parent == tmp_path / "runs" and path.name.startswith("deploy-_.._etc_passwd-")
    assert safe_file_stem("..") == "run" and safe_file_stem("a b/c") == "a_b_c"


class _DiskFull:
    """Wraps a recorder's ``_write``: after ``after`` messages every write fails (ENOSPC)."""

    def __init__(self, write, after: int) -> None:  # type: ignore[no-untyped-def]
        self.write, self.after, self.calls = write, after, 0

    def __call__(self, *args) -> None:  # type: ignore[no-untyped-def]
        self.calls += 1
        if self.calls > self.after:
            raise OSError(28, "No space left on device")
        self.write(*args)


@pytest.mark.parametrize("policy", ["safe_stop", "warn"])
def test_a_failing_writer_reaches_the_loop_and_the_log_keeps_its_flushed_part(
        tmp_path: Path, policy: str) -> None:
    scenario = load_scenario("two_go2")
    scenario = scenario.model_copy(update={"duration_s": 1.0, "controller": (
        scenario.controller.model_copy(update={"executor": "serial"}))})
    path = tmp_path / "run.mcap"
    loop = SimRun(scenario, CompiledCodeCache())
    recorder = open_run_recorder(path, scenario, loop.settings, loop.wbc_settings, "mujoco",
                                 RecorderSettings(flush_interval_s=0.05, on_failure=policy),
                                 blas_kernels=loop.control.cache.blas_kernels().target)
    recorder._write = _DiskFull(recorder._write, after=3000)  # type: ignore[method-assign]
    loop.attach_recorder(recorder)
    try:
        summary = loop.run(verbose=False)
    finally:
        loop.close()
        recorder.close(summary)
    safety = summary["safety"]
    assert "No space left on device" in safety["recorder_failure"]
    if policy == "safe_stop":
        assert safety["safe_stop"].startswith("flight recorder failed: OSError(28")
        trip_s = float(safety["transitions"][1].split(" s ")[0])
        assert trip_s < 1.0  # before the run's end
    else:
        assert safety["safe_stop"] is None and safety["result"] == "ran 1 s"
    assert "No space left on device" in (recorder.failure or "")
    # what was flushed before the failure reads back, CRCs checked
    recovered = recover(path, tmp_path / "recovered.mcap")
    assert recovered.messages > 1000
    log = LogFile(tmp_path / "recovered.mcap")
    counts, _, _ = log.message_counts()
    assert counts.get("/robot/go2_0/state", 0) > 100
