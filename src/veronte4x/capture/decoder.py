"""Turn captured frames into records: the bus map routes, the codecs decode.

Sans-IO: frames come in with their timestamps; nothing here opens a file or reads a clock.
A bad frame becomes a record with its error and raw bytes; the stream never stops on one.
"""

from __future__ import annotations

import binascii
import itertools
import math
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from veronte4x.capture.busmap import BusMap, Role
from veronte4x.capture.frames import BadLine, Frame, Truncation, text_seconds
from veronte4x.capture.readers.candump import (
    CAN_ERR_FLAG,
    Identifiers,
    parse_candump,
    parse_line,
)
from veronte4x.capture.records import Record, error_record, transfer_record, veronte_record
from veronte4x.capture.source import Truncated
from veronte4x.codec import DecodeError, Sender, UnknownCommandError
from veronte4x.codec.compiler import FrameDecoder
from veronte4x.dronecan import ProblemReport, Reassembler
from veronte4x.dronecan.reassembler import Problem, Problems
from veronte4x.errors import BytesLike, argument_type_error

_SENDERS = {Role.ARBITER: Sender.ARBITER, Role.AUTOPILOT: Sender.AUTOPILOT}

IdRoute = tuple[Role, int | None, FrameDecoder]
"""Where the bus map sends a Veronte CAN ID: its role, autopilot index and decoder."""


class CaptureDecoder:
    """Decode the frames of a capture into `Record` objects.

    Args:
        bus_map: CAN IDs of the Veronte roles and the codec choices (among them
            ``strict_transfers``, the rules of every channel's reassembler); defaults to
            Embention's template IDs.
    """

    def __init__(self, bus_map: BusMap | None = None) -> None:
        self.bus_map = bus_map or BusMap()
        self.codec = self.bus_map.codec()
        self.reassemblers: dict[str, Reassembler] = {}
        """One DroneCAN reassembler per channel (bus), created on its first frame."""
        self._routes: dict[int, IdRoute] = {
            can_id: (role, index, self.codec.decoder(_SENDERS[role]))
            for can_id, (role, index) in self.bus_map.veronte_roles.items()
        }

    def decode(self, items: Iterable[Frame | BadLine]) -> Iterator[Record]:
        """Yield the records of a stream of frames and bad lines, in order."""
        routes = self._routes
        veronte_extended = self.bus_map.extended
        dronecan = self.bus_map.dronecan
        dbc_ids = self.bus_map.dbc_ids  # 29-bit IDs DroneCAN leaves to a DBC
        excess = self.bus_map.allow_excess
        decoded, delivered = veronte_record, transfer_record
        # The reassembler of the latest DroneCAN frame's channel (one lookup per change).
        last_channel, reassembler = None, None
        for item in items:
            if type(item) is Frame:
                timestamp, channel, can_id, data, extended, remote, fd, error, _, _, _ = item
                if not (remote or fd or error):
                    route = routes.get(can_id) if extended == veronte_extended else None
                    if route is not None:
                        role, index, decode = route
                        try:
                            message = decode(data, excess)
                        except DecodeError as failure:
                            yield _failed(timestamp, channel, can_id, role, index, data,
                                          extended, failure)  # fmt: skip
                        else:
                            yield decoded(timestamp, channel, can_id, role, index, message, data,
                                          extended)  # fmt: skip
                        continue
                    if extended and dronecan and can_id not in dbc_ids:
                        # _dronecan, inlined: no generator per frame.
                        if channel != last_channel or reassembler is None:
                            reassembler = self._reassembler(channel)
                            last_channel, push = channel, reassembler.push
                        transfer = push(can_id, data, 0.0 if timestamp is None else timestamp)
                        if isinstance(transfer, Problems):
                            yield from _problems(transfer, channel)
                            transfer = transfer.transfer
                        if transfer is not None:
                            yield delivered(timestamp, channel, can_id, transfer.source_node_id,
                                            transfer.message, data,
                                            transfer.destination_node_id)  # fmt: skip
                        continue
                yield self._odd_frame(item)
            else:
                yield self._bad_line(item)  # type: ignore[arg-type]

    def decode_candump(self, lines: Iterable[str], channel: str | None = None) -> Iterator[Record]:
        """Yield the records of candump text lines: ``decode(parse_candump(lines, channel))``.

        Each item of ``lines`` is one line, with or without its line break. For text as it
        comes from a file, a pipe or a socket, `decode_chunks` is faster.
        """
        return self.decode(parse_candump(lines, channel))

    def decode_chunks(
        self, chunks: Iterable[BytesLike], channel: str | None = None
    ) -> Iterator[Record]:
        """Yield the records of candump text that comes as bytes, in chunks cut anywhere.

        The text is read as `open` reads a text file: UTF-8 (bytes that are not are
        replaced) with ``\\n``, ``\\r\\n`` or ``\\r`` line breaks; each line gives the records
        of `decode_candump`. Plain log-form frames, the bulk of a capture, are parsed as
        bytes with no intermediate `Frame`: an 11-bit frame on a Veronte ID is decoded
        inline, a 29-bit one goes straight to its channel's DroneCAN reassembler. Other
        lines go through `parse_line`, and a block of lines with bytes that are not plain
        ASCII through `parse_candump`. If ``chunks`` raises `Truncated` (gzip data that ends
        early), the records end with a "truncated" record at the first line not read whole.

        Raises:
            TypeError: A chunk is not bytes-like (lines of text go to `decode_candump`), or
                ``channel`` is not a str.
        """
        if channel is not None and not isinstance(channel, str):
            raise argument_type_error("decode_chunks", "channel", "a str or None", channel)
        fast = _FastPath(
            veronte={} if self.bus_map.extended else _routes_by_text(self._routes),
            dronecan=self.bus_map.dronecan and not self.bus_map.extended,
            dbc_ids=self.bus_map.dbc_ids,
            excess=self.bus_map.allow_excess,
            channel=channel,
            identifiers=Identifiers(),
        )
        return self._chunk_records(chunks, fast)

    def _chunk_records(self, chunks: Iterable[BytesLike], fast: _FastPath) -> Iterator[Record]:
        """`decode_chunks`'s records. A plain block's log-form frame is parsed as bytes: on a
        Veronte ID it is decoded inline, on a 29-bit ID it goes straight to its channel's
        DroneCAN reassembler; any other line goes to `parse_line`, the exact parser. One
        generator for blocks and lines: a generator per block costs 2-3 % a line."""
        veronte, dronecan, dbc_ids = fast.veronte, fast.dronecan, fast.dbc_ids
        excess, channel, identifiers = fast.excess, fast.channel, fast.identifiers
        unhexlify, exact = binascii.unhexlify, self._parsed_line
        # The interface of the latest frame and its reassembler's push (None until its
        # first DroneCAN frame): looked up again only when the interface changes.
        name_before, interface, push = b"", "", None
        number = 0  # lines read
        try:
            for block in _blocks_of_lines(chunks):
                if not _is_plain(block):
                    text_lines = _text_lines(block)
                    yield from self.decode(parse_candump(text_lines, channel, number + 1))
                    number += len(text_lines)
                    continue
                lines = block.split(b"\n")
                lines.pop()  # the empty text after the block's last line feed
                for line in lines:
                    number += 1
                    try:
                        stamp, name, body = line.split()
                        ident, separator, text = body.partition(b"#")
                        if not separator or stamp[0] != 40 or stamp[-1] != 41:  # ( and )
                            raise ValueError  # no log-form frame: parse_line tells what
                        # _seconds, inlined for candump's own (%010lu.%06lu).
                        seconds = float(stamp[1:-1])
                        if not (len(stamp) == 19 and stamp[11] == 46
                                and seconds < 8_589_934_592.0
                                and stamp[12:18].isdigit()):  # fmt: skip
                            seconds = _seconds(stamp)
                        data = unhexlify(text)
                    except ValueError:  # not three tokens, or a bad time or data
                        seconds = math.nan
                    # seconds - seconds is 0.0 for a finite time only.
                    if seconds - seconds != 0.0:
                        if line.strip():
                            yield from exact(line.decode("ascii"), number, channel)
                        continue
                    if name != name_before:
                        name_before, interface, push = name, name.decode("ascii"), None
                    route = veronte.get(ident)
                    if route is not None:
                        if channel is None or interface == channel:
                            can_id, role, index, decode = route
                            try:
                                message = decode(data, excess)
                            except DecodeError as failure:
                                yield _failed(seconds, interface, can_id, role, index, data,
                                              False, failure)  # fmt: skip
                            else:
                                yield veronte_record(seconds, interface, can_id, role, index,
                                                     message, data, False)  # fmt: skip
                        continue
                    try:  # a DroneCAN frame's ID; CAN_ERR_FLAG stands for any other
                        can_id = (
                            identifiers[ident] if dronecan and len(ident) == 8 else CAN_ERR_FLAG
                        )
                    except ValueError:
                        can_id = CAN_ERR_FLAG
                    if can_id & CAN_ERR_FLAG or can_id in dbc_ids:
                        yield from exact(line.decode("ascii"), number, channel)
                    elif channel is None or interface == channel:
                        # _dronecan, inlined: no Frame, no generator per frame.
                        if push is None:
                            push = self._reassembler(interface).push
                        transfer = push(can_id, data, seconds)
                        if isinstance(transfer, Problems):
                            yield from _problems(transfer, interface)
                            transfer = transfer.transfer
                        if transfer is not None:
                            yield transfer_record(seconds, interface, can_id,
                                                  transfer.source_node_id, transfer.message, data,
                                                  transfer.destination_node_id)  # fmt: skip
        except Truncated as cut:  # raised by ``chunks``, so between two blocks
            yield self._bad_line(Truncated(cut.path, number + 1).bad_line())

    def _parsed_line(self, line: str, number: int, channel: str | None) -> Iterator[Record]:
        """The records of a line that only `parse_line`, the exact parser, reads."""
        item = parse_line(line, number)
        if isinstance(item, BadLine):
            yield self._bad_line(item)
        elif channel is None or item.channel == channel:
            yield from self.decode((item,))

    def _odd_frame(self, frame: Frame) -> Record:
        """The record of a frame that is neither a plain Veronte nor a plain DroneCAN frame:
        an error or remote frame, CAN FD, or a foreign ID."""
        role, index = self.bus_map.role(frame.can_id, frame.extended)
        base = (frame.timestamp, frame.channel, frame.can_id, role, index, None)
        data, extended = frame.data, frame.extended
        if frame.error:
            return error_record(*base, "error frame", "error frame", data, extended)
        if frame.remote:
            return error_record(*base, "remote frame", "remote frame", data, extended)
        if role is Role.ARBITER or role is Role.AUTOPILOT:
            detail = "a CAN FD frame on a Veronte ID"
            return error_record(*base, "decode error", detail, data, extended)
        return error_record(*base, None, foreign_id(frame.can_id, extended), data, extended)

    def _reassembler(self, channel: str) -> Reassembler:
        """The reassembler of a channel, made on its first DroneCAN frame."""
        reassembler = self.reassemblers.get(channel)
        if reassembler is None:
            reassembler = self.reassemblers[channel] = Reassembler(
                types=self.bus_map.dronecan_types, strict=self.bus_map.strict_transfers
            )
        return reassembler

    @staticmethod
    def _bad_line(item: BadLine) -> Record:
        if isinstance(item, Truncation):
            return error_record(None, "", 0, Role.UNKNOWN, None, None, "truncated", item.reason,
                                b"", False)  # fmt: skip
        detail = f"line {item.line_number}: {item.reason}: {item.text!r}"
        return error_record(None, "", 0, Role.UNKNOWN, None, None, "bad line", detail, b"", False)


TextRoute = tuple[int, Role, int | None, FrameDecoder]
"""A Veronte route by identifier text: the CAN ID and its `IdRoute`."""


@dataclass(frozen=True, slots=True)
class _FastPath:
    """What `CaptureDecoder._plain_lines` needs of one `decode_chunks` call.

    Attributes:
        veronte: The 11-bit Veronte routes by identifier text, in every case spelling: one
            dict lookup replaces int() and the error-flag check (3 hex digits cannot hold
            the flag). Empty when the bus map puts the Veronte IDs on 29 bits.
        dronecan: Whether 29-bit frames go to DroneCAN.
        dbc_ids: The 29-bit IDs DroneCAN leaves to a DBC.
        excess: The bus map's ``allow_excess``.
        channel: The interface whose frames are kept, or None for all.
        identifiers: The CAN IDs of identifier texts, parsed once each.
    """

    veronte: dict[bytes, TextRoute]
    dronecan: bool
    dbc_ids: frozenset[int]
    excess: bool
    channel: str | None
    identifiers: Identifiers


def _problems(problems: Problems, channel: str) -> Iterator[Record]:
    """The records of the problems one frame caused on ``channel``."""
    for report in problems.reports:
        yield problem_record(report, channel)


def _routes_by_text(routes: dict[int, IdRoute]) -> dict[bytes, TextRoute]:
    """The 11-bit Veronte routes keyed by identifier text, each in every case spelling."""
    by_text = {}
    for can_id, (role, index, decode) in routes.items():
        if can_id <= 0xFFF:  # what 3 hex digits hold
            for spelling in itertools.product(*({c.lower(), c.upper()} for c in f"{can_id:03x}")):
                by_text["".join(spelling).encode()] = (can_id, role, index, decode)
    return by_text


def _blocks_of_lines(chunks: Iterable[BytesLike]) -> Iterator[bytes]:
    """``chunks`` cut into blocks of whole lines: each block ends in a line feed, or in a
    carriage return that no line feed follows; the last line gets a line feed if it has
    none. Cutting at line breaks, which are ASCII, never splits a UTF-8 character; the
    pieces of a long line are joined once, when its end arrives."""
    pending: list[bytes] = []  # the start of a line, cut by the chunks
    for chunk in chunks:
        if chunk.__class__ is not bytes:
            chunk = _as_bytes(chunk)
        cut = chunk.rfind(b"\n") + 1 or chunk.rfind(b"\r", 0, len(chunk) - 1) + 1
        if not cut:
            pending.append(chunk)
            continue
        if pending:
            pending.append(chunk[:cut])
            yield b"".join(pending)
            pending.clear()
        else:
            yield chunk[:cut]
        if cut < len(chunk):
            pending.append(chunk[cut:])
    if any(pending):
        yield b"".join(pending) + b"\n"


def _as_bytes(chunk: object) -> bytes:
    """A bytes-like chunk as bytes, else the `TypeError` of the library's policy."""
    if isinstance(chunk, (bytes, bytearray, memoryview)):
        return bytes(chunk)
    raise argument_type_error("decode_chunks", "each chunk", "bytes-like", chunk)


_NOT_SPACE_TO_BYTES = (b"\x1c", b"\x1d", b"\x1e", b"\x1f")
"""White space to `str.split` that `bytes.split` keeps in a token."""


def _is_plain(block: bytes) -> bool:
    """Whether bytes parsing reads ``block`` exactly as text parsing would: ASCII, no byte
    that `str.split` alone takes for white space, and every carriage return in a CRLF."""
    return (
        block.isascii()
        and not any(byte in block for byte in _NOT_SPACE_TO_BYTES)
        and (b"\r" not in block or block.count(b"\r") == block.count(b"\r\n"))
    )


def _text_lines(block: bytes) -> list[str]:
    """The lines of a block as `open` gives them in text mode: UTF-8 with replacement,
    universal line breaks."""
    text = block.decode("utf-8", "replace").replace("\r\n", "\n").replace("\r", "\n")
    return text.split("\n")[:-1]


def _failed(
    timestamp: float | None,
    channel: str,
    can_id: int,
    role: Role,
    index: int | None,
    data: bytes,
    extended: bool,
    failure: DecodeError,
) -> Record:
    """The record of a Veronte frame its codec refused."""
    kind = "unknown command" if isinstance(failure, UnknownCommandError) else "decode error"
    return error_record(timestamp, channel, can_id, role, index, None, kind, str(failure), data,
                        extended)  # fmt: skip


def problem_record(report: ProblemReport, channel: str) -> Record:
    """The record of a DroneCAN reassembly problem on a channel; a frame of a data type
    with no codec is undecoded traffic (error None, `foreign_data_type` as its detail)."""
    if report.problem is Problem.UNKNOWN_TYPE:
        return error_record(report.timestamp, channel, report.can_id, Role.DRONECAN, None,
                            report.can_id & 0x7F or None, None, foreign_data_type(report.can_id),
                            report.data, True)  # fmt: skip
    kind = report.problem.name.lower().replace("_", " ")
    detail = f"{report.problem.value} {report.detail}"
    return error_record(report.timestamp, channel, report.can_id, Role.DRONECAN, None,
                        report.can_id & 0x7F or None, kind, detail, report.data, True)  # fmt: skip


def foreign_id(can_id: int, extended: bool) -> str:
    """The `Record.detail` of a frame on a CAN ID outside the bus map: ``11-bit CAN ID 0x123``."""
    return f"{'29' if extended else '11'}-bit CAN ID {can_id:#x}"


def foreign_data_type(can_id: int) -> str:
    """The `Record.detail` of a DroneCAN frame of a type with no codec, from its CAN ID:
    ``DroneCAN data type 1234``, ``DroneCAN service type 48`` or
    ``DroneCAN anonymous data type 2`` (only the type id's low 2 bits are on the wire)."""
    if can_id & 0x80:
        return f"DroneCAN service type {(can_id >> 16) & 0xFF}"
    if can_id & 0x7F:
        return f"DroneCAN data type {(can_id >> 8) & 0xFFFF}"
    return f"DroneCAN anonymous data type {(can_id >> 8) & 0x3}"


def _seconds(stamp: bytes) -> float:
    """The time of a log line's ``(seconds)``: a float, exact as `text_seconds` gives it
    unless it is candump's own ``%010lu.%06lu`` before 2242 (the float holds those)."""
    seconds = float(stamp[1:-1])
    if (
        len(stamp) == 19
        and stamp[11] == 46
        and seconds < 8_589_934_592.0
        and stamp[12:18].isdigit()
    ):
        return seconds
    return text_seconds(stamp[1:-1].decode("ascii"), seconds)
