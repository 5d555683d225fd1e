"""The flight recorder: one MCAP file per run, written by its own thread from a bounded queue.

The control loop only builds a protobuf message and puts it in the queue (``log``, never
blocks). The writer thread serializes, writes zstd chunks and flushes the file at least every
``flush_interval_s``, so after a ``kill -9`` the file is readable up to its last completed chunk
(``porter log recover`` rewrites such a file with an index). When the queue is full the message
is dropped and counted; the count goes into the log as an event and into the ``recorder``
metadata at the end. ``close`` (also reached on Ctrl-C, exceptions and SIGTERM through the
callers' ``finally``) drains the queue, writes the summary metadata and the MCAP footer.

Sinks (e.g. the live Rerun view) see every message in the writer thread, off the loop.
"""

from __future__ import annotations

import json
import queue
import threading
import time
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

from mcap.writer import CompressionType, Writer
from mcap_protobuf.schema import register_schema
from pydantic import BaseModel, ConfigDict, Field

from deploy.log_format import EVENTS, PROFILE, SUMMARY_METADATA, to_nanoseconds
from deploy.messages import porter_log_pb2 as pb

Sink = Callable[[str, Any, int], None]  # (topic, protobuf message, log time [ns])
_CLOSE = object()


class RecorderSettings(BaseModel):
    """Flight-recorder options (``recorder:`` in YAML)."""

    model_config = ConfigDict(extra="forbid")
    queue_size: int = Field(50_000, ge=1, description="messages buffered before dropping")
    chunk_size_bytes: int = Field(1 << 20, ge=1024, description="uncompressed chunk size")
    flush_interval_s: float = Field(1.0, gt=0.0,
                                    description="a chunk is closed and flushed at least this often")
    warm_start_every: int = Field(
        60, ge=1, description="NMPC updates between controller warm-start keyframes")


class FlightRecorder:
    """Records protobuf messages to ``path``; build once per run, ``close`` at its end."""

    def __init__(self, path: Path | str, settings: RecorderSettings | None = None,
                 metadata: dict[str, dict[str, str]] | None = None,
                 attachments: dict[str, bytes] | None = None,
                 sinks: Iterable[Sink] = ()) -> None:
        self.path = Path(path)
        self.settings = settings or RecorderSettings()
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._stream = open(self.path, "wb")  # noqa: SIM115 -- closed in close()
        self._writer = Writer(self._stream, chunk_size=self.settings.chunk_size_bytes,
                              compression=CompressionType.ZSTD)
        self._writer.start(profile=PROFILE, library="porter flight recorder")
        for name, data in (metadata or {}).items():
            self._writer.add_metadata(name, data)
        for name, content in (attachments or {}).items():
            self._writer.add_attachment(0, 0, name, _media_type(name), content)
        self._writer.flush()
        self._stream.flush()
        self._queue: queue.Queue[Any] = queue.Queue(maxsize=self.settings.queue_size)
        self._sinks = list(sinks)
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
        try:
            self._queue.put_nowait((topic, message, to_nanoseconds(time_s)))
        except queue.Full:
            self.dropped += 1
            return False
        return True

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
        try:  # waits only while the writer drains a full queue
            self._queue.put(_CLOSE, timeout=timeout_s)
        except queue.Full:
            self.error = self.error or TimeoutError("writer thread did not drain the queue")
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
        finally:
            self._stream.close()

    def __enter__(self) -> FlightRecorder:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- the writer thread -----------------------------------------------------------------
    def _run(self) -> None:
        last_flush = time.monotonic()
        unflushed = False
        while True:
            try:
                item = self._queue.get(timeout=self.settings.flush_interval_s / 4)
            except queue.Empty:
                item = None
            if item is _CLOSE:
                return
            if item is not None and self.error is None:
                try:
                    self._write(*item)
                    unflushed = True
                except Exception as error:  # disk full, bad message: stop writing, keep the file
                    self.error = error
            if self.dropped > self._reported_dropped and self.error is None:
                self._report_drops()
            now = time.monotonic()
            if now - last_flush > self.settings.flush_interval_s:
                if unflushed and self.error is None:
                    self._writer.flush()  # closes the chunk: it survives a kill -9
                last_flush, unflushed = now, False

    def _write(self, topic: str, message: Any, log_time_ns: int) -> None:
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
        self._writer.add_message(channel_id=channel, log_time=log_time_ns,
                                 data=message.SerializeToString(), publish_time=log_time_ns,
                                 sequence=sequence)
        self.written += 1
        self._last_time_ns = max(self._last_time_ns, log_time_ns)
        for sink in list(self._sinks):
            try:
                sink(topic, message, log_time_ns)
            except Exception as error:  # a viewer going away must not stop the recording
                self._sinks.remove(sink)
                self._write(EVENTS, pb.Event(time_s=log_time_ns * 1e-9, level=pb.Event.WARNING,
                                             source="recorder", text=f"sink removed: {error}"),
                            log_time_ns)

    def _report_drops(self) -> None:
        dropped = self.dropped
        text = (f"recorder queue full: {dropped - self._reported_dropped} messages dropped "
                f"({dropped} in total)")
        self._reported_dropped = dropped
        self._write(EVENTS, pb.Event(time_s=self._last_time_ns * 1e-9, level=pb.Event.WARNING,
                                     source="recorder", text=text), self._last_time_ns)


def _media_type(name: str) -> str:
    if name.endswith((".yaml", ".yml")):
        return "application/yaml"
    if name.endswith((".urdf", ".xml")):
        return "application/xml"
    return "application/octet-stream"
