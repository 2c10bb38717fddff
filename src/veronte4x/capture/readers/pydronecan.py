"""pydronecan's capture files: the frames its ``fileout:`` driver writes and its ``filein:``
driver plays back (``dronecan/driver/file.py``, pydronecan 1.0.27, github.com/dronecan/
pydronecan commit 9e65bcca48cb6d428d80e23ed5a0993eff3ed528).

The file is a run of records, little-endian, packed, with no file header::

    magic      uint16  0x2934
    timestamp  uint64  microseconds of the recording machine's monotonic clock
    crc        uint16  CRC-16-CCITT-FALSE (init 0xFFFF) of the data
    length     uint16  data bytes
    flags      uint16  bit 0: a CAN FD frame
    id         uint32  the identifier; bit 31: extended (29-bit) frame
    data       length bytes

- The timestamps are seconds of a monotonic clock (``time.monotonic()`` of the machine
  that recorded: since it booted, on Linux), not Unix time: text output shows them as
  seconds, as it shows a DataFlash log's.
- The file names no bus: the frames' channel is ``""``.
- pydronecan stops at the first record with a wrong magic or CRC (``DriverError``); this
  reader counts it as one `BadLine` and goes on from the next record it finds (a
  ``0x2934`` that starts a record whose CRC holds), as the other readers skip a bad line.
  A record that is no CAN frame (more than 8 bytes in a classic frame, a length no CAN FD
  data length code gives, a standard identifier past 11 bits) is a `BadLine` too, as
  `veronte4x.dronecan.mcast.decode` refuses it; pydronecan reads it as it is. A record
  cut by the end of the file ends the frames with a `Truncation`.

`write` writes the same records (`record` makes one), which pydronecan's ``filein:`` plays.
"""

from __future__ import annotations

import os
import struct
from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

from veronte4x.capture.frames import BadLine, Frame, Truncation, micros, micros_seconds
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.mcast import FD_LENGTHS, ID_EXTENDED
from veronte4x.errors import SourceError

if TYPE_CHECKING:
    from veronte4x.capture.source import Source

MAGIC = 0x2934
"""The first two bytes of every record (``FILE_MAGIC``)."""
RECORD = struct.Struct("<HQHHHI")
"""magic, timestamp, crc, length, flags, id: the 20 bytes before the data."""
FLAG_FD = 0x0001
"""``flags`` bit of a CAN FD frame (``FILE_FLAG_CANFD``)."""
_MAGIC_BYTES = MAGIC.to_bytes(2, "little")
_LONGEST = RECORD.size + 64
_CHUNK = 1 << 20


def sniff(head: bytes) -> bool:
    """Whether a file starts as a pydronecan capture: with a record whose CRC holds (or, in
    a file cut within its first record, the magic and a length of at most 64)."""
    if len(head) < RECORD.size:
        return False
    magic, _, crc, length, _, _ = RECORD.unpack_from(head)
    if magic != MAGIC or length > 64:
        return False
    end = RECORD.size + length
    return len(head) < end or bool(crc16(head[RECORD.size : end]) == crc)


def frames(source: Source) -> Iterator[Frame | BadLine]:
    """The frames of a pydronecan capture, gzipped or not: the reader registry's ``frames``."""
    from veronte4x.capture.source import Truncated, read_chunks

    try:
        yield from parse_pydronecan(read_chunks(source, _CHUNK), source.path)
    except Truncated as cut:
        yield Truncation(cut.line_number, "", f"{source.path}: the gzip data ends early: the "
                         "file is truncated; the frames before were read")  # fmt: skip


def parse_pydronecan(chunks: Iterable[bytes], path: str) -> Iterator[Frame | BadLine]:
    """The frames of a pydronecan capture's bytes, given in chunks of any size.

    A `BadLine`'s number is that of the record it stands in place of (1-based).
    """
    buffer, at, number, skipped = b"", 0, 0, 0
    for chunk in chunks:
        buffer = buffer[at:] + chunk
        at = 0
        end = len(buffer)
        while end - at >= RECORD.size:
            magic, stamp, crc, length, flags, message_id = RECORD.unpack_from(buffer, at)
            if magic != MAGIC or length > 64:
                found = buffer.find(_MAGIC_BYTES, at + 1)
                step = (found if found >= 0 else end - 1) - at  # the last byte may start one
                skipped, at = skipped + step, at + step
                continue
            stop = at + RECORD.size + length
            if stop > end:
                break  # the rest of the record is in the next chunk
            data = buffer[at + RECORD.size : stop]
            if crc16(data) != crc:
                skipped, at = skipped + 1, at + 1
                continue
            if skipped:
                number += 1
                yield _skipped(number, skipped, buffer[at - min(skipped, 16) : at])
                skipped = 0
            number += 1
            yield _frame(number, stamp, flags, message_id, data, buffer[at:stop])
            at = stop
    if skipped or at < len(buffer):
        rest = len(buffer) - at
        if skipped:
            number += 1
            yield _skipped(number, skipped, buffer[at - min(skipped, 16) : at])
        if rest:
            yield Truncation(
                number + 1,
                buffer[at : at + 16].hex(" "),
                f"{path}: the last record ends early ({rest} of its bytes): the file is "
                "truncated; the frames before were read",
            )


def _frame(
    number: int, stamp: int, flags: int, message_id: int, data: bytes, raw: bytes
) -> Frame | BadLine:
    """The frame of a record whose CRC holds, or its `BadLine` if it is no CAN frame."""
    fd = bool(flags & FLAG_FD)
    if len(data) not in FD_LENGTHS if fd else len(data) > 8:
        kind = "a CAN FD frame" if fd else "a classic frame"
        return BadLine(number, raw[:16].hex(" "), f"{len(data)} data bytes: no length of {kind}")
    extended = bool(message_id & ID_EXTENDED)
    can_id = message_id & 0x1FFF_FFFF
    if not extended and can_id > 0x7FF:
        return BadLine(number, raw[:16].hex(" "), f"standard identifier {can_id:#x} past 11 bits")
    return Frame(micros_seconds(stamp), "", can_id, data, extended, fd=fd)


def _skipped(number: int, count: int, tail: bytes) -> BadLine:
    """The `BadLine` of ``count`` bytes that are no record, shown by their last 16."""
    return BadLine(number, tail[-16:].hex(" "), f"{count} bytes are no pydronecan record")


def record(frame: Frame) -> bytes:
    """The record of one frame (its timestamp taken as microseconds).

    Raises:
        SourceError: The frame has no timestamp or one before 0, is a remote or error
            frame (the file has no flag for them), or is no CAN frame.
    """
    stamp = None if frame.timestamp is None else micros(frame.timestamp)
    if stamp is None or not 0 <= stamp < 1 << 64:
        raise SourceError(
            f"a frame at {frame.timestamp} s: a pydronecan capture holds times of 0 s or later"
        )
    if frame.remote or frame.error:
        raise SourceError("a pydronecan capture holds data frames only, no remote or error frame")
    length = len(frame.data)
    if length not in FD_LENGTHS if frame.fd else length > 8:
        raise SourceError(f"a frame of {length} data bytes is no CAN frame")
    message_id = frame.can_id | (ID_EXTENDED if frame.extended else 0)
    header = RECORD.pack(
        MAGIC, stamp, crc16(frame.data), length, FLAG_FD if frame.fd else 0, message_id
    )
    return header + frame.data


def write(path: str | os.PathLike[str], frames: Iterable[Frame]) -> int:
    """Write ``frames`` as a pydronecan capture; returns how many.

    Raises:
        SourceError: A frame the file cannot hold (see `record`); the file is then removed.
    """
    count = 0
    try:
        with open(path, "wb") as file:
            for frame in frames:
                file.write(record(frame))
                count += 1
    except SourceError:
        os.remove(path)
        raise
    return count
