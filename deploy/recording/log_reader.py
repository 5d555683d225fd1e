"""Reading flight-recorder logs back: validation with clear errors, decoded messages, metadata,
attachments, and recovery of a file whose run was killed before it was closed.
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from mcap.reader import make_reader
from mcap.records import Attachment, Channel, Message, Metadata, Schema
from mcap.stream_reader import StreamReader
from mcap.writer import CompressionType, Writer
from mcap_protobuf.decoder import DecoderFactory

from deploy.recording.log_format import (
    CLOCK_METADATA,
    LOG_FORMAT_VERSION,
    PROFILE,
    READABLE_LOG_FORMAT_VERSIONS,
    RUN_METADATA,
    SUMMARY_METADATA,
)

MAGIC = b"\x89MCAP0\r\n"


class LogError(ValueError):
    """A log cannot be used: not MCAP, incomplete, corrupted, or from another format version."""


@dataclass(frozen=True)
class DecodedMessage:
    """A message of a log at its run time (the file's log time less the time origin)."""

    topic: str
    log_time_ns: int
    message: Any

    @property
    def time_s(self) -> float:
        return self.log_time_ns * 1e-9


class LogFile:
    """A complete porter log. Opening checks the magic, the index and the format version.
    Times given back are run times; ``time_origin_ns`` is the Unix time [ns] of run time 0
    (0 for version-1 logs, whose log times were run times)."""

    def __init__(self, path: Path | str) -> None:
        self.path = Path(path)
        try:
            data_size = self.path.stat().st_size
            with open(self.path, "rb") as stream:
                head = stream.read(len(MAGIC))
                stream.seek(max(data_size - len(MAGIC), 0))
                tail = stream.read(len(MAGIC))
        except OSError as error:
            raise LogError(f"{self.path}: cannot read ({error.strerror})") from None
        if head != MAGIC:
            raise LogError(f"{self.path}: not an MCAP file (bad magic bytes)")
        if tail != MAGIC or data_size < 2 * len(MAGIC):
            raise LogError(f"{self.path}: incomplete (no index; the run did not end cleanly, "
                           f"e.g. kill -9). `porter log recover {self.path}` rewrites the part "
                           "that was written into a readable file")
        header = self._reader_call(lambda reader: reader.get_header())
        if header.profile != PROFILE:
            raise LogError(f"{self.path}: not a porter log (MCAP profile {header.profile!r})")
        metadata = self.metadata()
        version = metadata.get(RUN_METADATA, {}).get("log_format_version")
        self.time_origin_ns = int(metadata.get(CLOCK_METADATA, {}).get("time_origin_ns", 0))
        if version not in READABLE_LOG_FORMAT_VERSIONS:
            raise LogError(f"{self.path}: written with log format version {version}, this "
                           f"porter reads versions {', '.join(READABLE_LOG_FORMAT_VERSIONS)} "
                           f"(writes {LOG_FORMAT_VERSION}); replay it with the porter "
                           "revision in its metadata (`porter log info`)")

    def _reader_call(self, action: Any) -> Any:
        try:
            with open(self.path, "rb") as stream:
                return action(make_reader(stream, decoder_factories=[DecoderFactory()]))
        except LogError:
            raise
        except Exception as error:  # mcap, zstd, protobuf decode: any damage reads the same
            raise LogError(f"{self.path}: corrupted ({type(error).__name__}: {error})") from None

    def metadata(self) -> dict[str, dict[str, str]]:
        return self._reader_call(
            lambda reader: {m.name: dict(m.metadata) for m in reader.iter_metadata()})

    def attachments(self) -> dict[str, bytes]:
        return self._reader_call(
            lambda reader: {a.name: bytes(a.data) for a in reader.iter_attachments()})

    def attachment_text(self, name: str) -> str:
        attachments = self.attachments()
        if name not in attachments:
            raise LogError(f"{self.path}: no attachment {name!r} "
                           f"(has {', '.join(sorted(attachments)) or 'none'})")
        return attachments[name].decode()

    def summary(self) -> dict | None:
        """The run's summary metrics, or None if the run recorded none."""
        record = self.metadata().get(SUMMARY_METADATA)
        return None if record is None else json.loads(record["json"])

    def message_counts(self) -> tuple[dict[str, int], int, int]:
        """Messages per topic and the first and last run time [ns], from the index."""
        def read(reader: Any) -> tuple[dict[str, int], int, int]:
            summary = reader.get_summary()
            if summary is None or summary.statistics is None:
                raise LogError(f"{self.path}: no statistics in the index")
            counts = {summary.channels[c].topic: n
                      for c, n in summary.statistics.channel_message_counts.items()}
            stats = summary.statistics
            return (counts, stats.message_start_time - self.time_origin_ns,
                    stats.message_end_time - self.time_origin_ns)
        return self._reader_call(read)

    def messages(self, topics: list[str] | None = None) -> Iterator[DecodedMessage]:
        """Decoded messages in log-time order (all topics, or those named)."""
        try:
            with open(self.path, "rb") as stream:
                reader = make_reader(stream, decoder_factories=[DecoderFactory()])
                for _, channel, message, decoded in reader.iter_decoded_messages(
                        topics=topics, log_time_order=True):
                    yield DecodedMessage(channel.topic, message.log_time - self.time_origin_ns,
                                         decoded)
        except LogError:
            raise
        except Exception as error:  # mcap, zstd, protobuf decode: any damage reads the same
            raise LogError(f"{self.path}: corrupted ({type(error).__name__}: {error})") from None

    def by_topic(self, topics: list[str]) -> dict[str, list[DecodedMessage]]:
        grouped: dict[str, list[DecodedMessage]] = {topic: [] for topic in topics}
        for item in self.messages(topics):
            grouped[item.topic].append(item)
        return grouped


@dataclass(frozen=True)
class Recovery:
    messages: int
    chunks_lost: bool  # the stream ended inside a record (the unfinished chunk is lost)
    error: str


def recover(source: Path | str, destination: Path | str) -> Recovery:
    """Copy every complete record of a (possibly truncated) MCAP file into a new, indexed one."""
    source, destination = Path(source), Path(destination)
    with open(source, "rb") as stream:
        if stream.read(len(MAGIC)) != MAGIC:
            raise LogError(f"{source}: not an MCAP file (bad magic bytes)")
    counts: Counter[str] = Counter()
    error = ""
    with open(source, "rb") as stream, open(destination, "wb") as out:
        writer = Writer(out, compression=CompressionType.ZSTD)
        schemas: dict[int, int] = {}
        channels: dict[int, int] = {}
        started = False
        try:
            for record in StreamReader(stream, validate_crcs=True).records:
                if not started:
                    profile = getattr(record, "profile", PROFILE)
                    writer.start(profile=profile, library="porter log recover")
                    started = True
                if isinstance(record, Schema):
                    schemas[record.id] = writer.register_schema(record.name, record.encoding,
                                                                record.data)
                elif isinstance(record, Channel):
                    channels[record.id] = writer.register_channel(
                        record.topic, record.message_encoding, schemas.get(record.schema_id, 0),
                        dict(record.metadata))
                elif isinstance(record, Message) and record.channel_id in channels:
                    writer.add_message(channels[record.channel_id], record.log_time,
                                       record.data, record.publish_time, record.sequence)
                    counts["messages"] += 1
                elif isinstance(record, Attachment):
                    writer.add_attachment(record.create_time, record.log_time, record.name,
                                          record.media_type, record.data)
                elif isinstance(record, Metadata):
                    writer.add_metadata(record.name, dict(record.metadata))
        except Exception as exc:  # truncation or damage: keep what came before
            error = f"{type(exc).__name__}: {exc}"
        if not started:
            writer.start(profile=PROFILE, library="porter log recover")
        writer.finish()
    return Recovery(counts["messages"], bool(error), error)
