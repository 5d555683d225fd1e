"""The flight recorder: one MCAP file per run, written by its own thread from a bounded queue.

The control loop only builds a protobuf message and puts it in the queue (``log``, never
blocks). The writer thread serializes, writes zstd chunks and flushes the file at least every
``flush_interval_s``, so after a ``kill -9`` the file is readable up to its last completed chunk
(``porter log recover`` rewrites such a file with an index). When the queue is full the message
is dropped and counted; the count goes into the log as an event and into the ``recorder``
metadata at the end. ``close`` (also reached on Ctrl-C, exceptions and SIGTERM through the
callers' ``finally``) drains the queue, writes the summary metadata and the MCAP footer.

Derivers (e.g. ``deploy.recording.robot_scene.LinkTransforms``) turn logged messages into
more messages, and sinks (e.g. the live Rerun view) see every message, both in the writer
thread, off the loop; a deriver or sink that raises is removed with a WARNING event.

Log times are on the wall clock: the file's log time of a message is ``time_origin_ns`` (the
Unix time of the run's time 0, in the ``clock`` metadata) plus the run time it was logged at,
so viewers show the day of the run; porter's messages keep the run time in their ``time_s``,
Foxglove messages' ``timestamp`` fields are shifted like the log time (``fmt.on_log_clock``),
and ``LogFile`` gives run times back. Sinks and derivers see run times.
"""

from __future__ import annotations

import json
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, Literal

from mcap.writer import CompressionType, Writer
from mcap_protobuf.schema import register_schema
from pydantic import Field

from core.model.strict_model import StrictModel
from deploy.recording.log_format import (
    CLOCK_METADATA,
    EVENTS,
    FOXGLOVE_LOG,
    PROFILE,
    SUMMARY_METADATA,
    foxglove_log,
    on_log_clock,
    to_nanoseconds,
)
from deploy.recording.messages import porter_log_pb2 as pb

Sink = Callable[[str, Any, int], None]  # (topic, protobuf message, run time [ns])
# (topic, message, run time [ns]) -> further (topic, message) to log at the same time
Deriver = Callable[[str, Any, int], Iterable[tuple[str, Any]]]


class RecorderSettings(StrictModel):
    """Flight-recorder options (``recorder:`` in YAML)."""

    queue_size: int = Field(50_000, ge=1, description="messages buffered before dropping")
    chunk_size_bytes: int = Field(1 << 20, ge=1024, description="uncompressed chunk size")
    flush_interval_s: float = Field(1.0, gt=0.0,
                                    description="a chunk is closed and flushed at least this often")
    warm_start_every: int = Field(
        60, ge=1, description="NMPC updates between controller warm-start keyframes")
    poll_interval_s: float = Field(0.01, gt=0.0, description="the writer drains the queue this "
                                   "often (batches: one wake-up per interval, not per message)")
    on_failure: Literal["safe_stop", "warn"] = Field(
        "safe_stop", description="when the writer fails (disk full, write error, its thread "
        "gone): stop the team (a run that cannot be recorded cannot be audited) or go on "
        "unrecorded with a warning")


class FlightRecorder:
    """Records protobuf messages to ``path``; build once per run, ``close`` at its end."""

    def __init__(self, path: Path | str, settings: RecorderSettings | None = None,
                 metadata: dict[str, dict[str, str]] | None = None,
                 attachments: dict[str, bytes] | None = None,
                 sinks: Iterable[Sink] = (), derivers: Iterable[Deriver] = (),
                 time_origin_ns: int | None = None) -> None:
        self.path = Path(path)
        # the Unix time [ns] of the run's time 0: now, unless given (tests, re-recordings)
        self.time_origin_ns = time.time_ns() if time_origin_ns is None else time_origin_ns
        self.settings = settings or RecorderSettings()
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._stream = open(self.path, "wb")  # noqa: SIM115 -- closed in close()
        # Data CRCs on: a reader can tell a torn or corrupted chunk from a good one.
        self._writer = Writer(self._stream, chunk_size=self.settings.chunk_size_bytes,
                              compression=CompressionType.ZSTD, enable_data_crcs=True)
        self._writer.start(profile=PROFILE, library="porter flight recorder")
        for name, data in (metadata or {}).items():
            self._writer.add_metadata(name, data)
        self._writer.add_metadata(CLOCK_METADATA, {"time_origin_ns": str(self.time_origin_ns)})
        for name, content in (attachments or {}).items():
            self._writer.add_attachment(self.time_origin_ns, self.time_origin_ns, name,
                                        _media_type(name), content)
        self._writer.flush()
        self._stream.flush()
        # A deque: append/popleft are atomic under the GIL, so the loop's side takes no lock
        # and never wakes the writer (measured: per-message wake-ups cost the writer ~80 us
        # each and the loop a GIL hand-off).
        self._queue: deque[tuple[str, Any, int]] = deque()
        self._closing = threading.Event()
        self._sinks = list(sinks)
        self._derivers = list(derivers)
        self._channels: dict[str, int] = {}
        self._schemas: dict[str, int] = {}
        self._sequence: dict[str, int] = {}
        self.dropped = 0
        self.written = 0
        self._reported_dropped = 0
        self._last_time_ns = 0
        self.error: BaseException | None = None
        self._closed = False
        self._thread = threading.Thread(target=self._run, name="flight-recorder", daemon=True)
        self._thread.start()

    # --- the loop's side -------------------------------------------------------------------
    def log(self, topic: str, message: Any, time_s: float) -> bool:
        """Queue ``message`` on ``topic`` at the run's time ``time_s``; False if dropped."""
        if self._closed:
            return False
        if len(self._queue) >= self.settings.queue_size:
            self.dropped += 1
            return False
        self._queue.append((topic, message, to_nanoseconds(time_s)))
        return True

    @property
    def failure(self) -> str | None:
        """Why the writer stopped writing (its exception, or its thread gone), else None."""
        if self.error is not None:
            return repr(self.error)
        if not self._closed and not self._thread.is_alive():
            return "the writer thread died"
        return None

    @property
    def pending(self) -> int:
        """Messages queued and not yet written."""
        return len(self._queue)

    def event(self, time_s: float, text: str, source: str = "loop",
              level: int = pb.Event.INFO) -> None:
        """A state change, fault or warning on ``/events`` (level: ``pb.Event.INFO`` etc.)."""
        message = pb.Event(time_s=time_s, source=source, text=text)
        message.level = level  # type: ignore[assignment]
        self.log(EVENTS, message, time_s)

    def close(self, summary: dict | None = None, timeout_s: float = 30.0) -> None:
        """Drain the queue, write the summary metadata and the index; idempotent."""
        if self._closed:
            return
        self._closed = True
        self._closing.set()
        self._thread.join(timeout_s)
        if self._thread.is_alive():  # stuck writer: finish the file without it
            self.error = self.error or TimeoutError("writer thread did not finish")
        try:
            if summary is not None:
                self._writer.add_metadata(SUMMARY_METADATA, {"json": json.dumps(summary)})
            self._writer.add_metadata("recorder", {
                "messages_written": str(self.written), "messages_dropped": str(self.dropped),
                "writer_error": repr(self.error) if self.error else ""})
            self._writer.finish()
        except OSError as error:  # disk full at the end: the file ends at its last good chunk
            self.error = self.error or error
        finally:
            try:
                self._stream.close()
            except OSError as error:  # the close's own flush failed the same way
                self.error = self.error or error

    def __enter__(self) -> FlightRecorder:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- the writer thread -----------------------------------------------------------------
    def _run(self) -> None:
        last_flush = time.monotonic()
        unflushed = False
        while True:
            closing = self._closing.is_set()  # read first: drain everything logged before it
            written = 0
            while self._queue and self.error is None:
                try:
                    self._write(*self._queue.popleft())
                    unflushed = True
                except Exception as error:  # disk full, bad message: stop writing, keep the file
                    self.error = error
                written += 1
                if written % 32 == 0:
                    # Hand the GIL back: a thread waiting for it (the loop, back from a pipe or
                    # a solver) would otherwise wait up to the 5 ms switch interval.
                    time.sleep(0)
            if self.dropped > self._reported_dropped and self.error is None:
                self._report_drops()
            now = time.monotonic()
            if closing:
                return
            if now - last_flush > self.settings.flush_interval_s:
                if unflushed and self.error is None:
                    self._writer.flush()  # closes the chunk: it survives a kill -9
                last_flush, unflushed = now, False
            self._closing.wait(self.settings.poll_interval_s)

    def _write(self, topic: str, message: Any, log_time_ns: int) -> None:
        messages = [(topic, message)]
        if topic == EVENTS:
            messages.append((FOXGLOVE_LOG, foxglove_log(message)))
        for deriver in list(self._derivers):
            try:
                derived = list(deriver(topic, message, log_time_ns))
                if derived:
                    messages.extend(derived)
                    time.sleep(0)  # hand the GIL back to the loop after a deriver's work
            except Exception as error:  # a derived view must not stop the recording
                self._derivers.remove(deriver)
                self._warn(f"deriver removed: {error!r}", log_time_ns)
        for item_topic, item in messages:
            for sink in list(self._sinks):
                try:
                    sink(item_topic, item, log_time_ns)
                except Exception as error:  # a viewer going away must not stop the recording
                    self._sinks.remove(sink)
                    self._warn(f"sink removed: {error}", log_time_ns)
            self._add(item_topic, item, log_time_ns)

    def _warn(self, text: str, log_time_ns: int) -> None:
        self._write(EVENTS, pb.Event(time_s=log_time_ns * 1e-9, level=pb.Event.WARNING,
                                     source="recorder", text=text), log_time_ns)

    def _add(self, topic: str, message: Any, log_time_ns: int) -> None:
        """One message into the file at run time ``log_time_ns`` (its channel and schema
        registered on first use; a Foxglove message's timestamps moved to the log's clock)."""
        channel = self._channels.get(topic)
        if channel is None:
            name = type(message).DESCRIPTOR.full_name
            if name not in self._schemas:
                self._schemas[name] = register_schema(self._writer, type(message))
            channel = self._writer.register_channel(topic=topic, message_encoding="protobuf",
                                                    schema_id=self._schemas[name])
            self._channels[topic] = channel
        sequence = self._sequence.get(topic, 0)
        self._sequence[topic] = sequence + 1
        file_time_ns = self.time_origin_ns + log_time_ns
        self._writer.add_message(channel_id=channel, log_time=file_time_ns,
                                 data=on_log_clock(message, self.time_origin_ns)
                                 .SerializeToString(),
                                 publish_time=file_time_ns, sequence=sequence)
        self.written += 1
        self._last_time_ns = max(self._last_time_ns, log_time_ns)

    def _report_drops(self) -> None:
        dropped = self.dropped
        text = (f"recorder queue full: {dropped - self._reported_dropped} messages dropped "
                f"({dropped} in total)")
        self._reported_dropped = dropped
        self._warn(text, self._last_time_ns)


def _media_type(name: str) -> str:
    if name.endswith((".yaml", ".yml")):
        return "application/yaml"
    if name.endswith((".urdf", ".xml")):
        return "application/xml"
    return "application/octet-stream"
