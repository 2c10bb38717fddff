"""SavvyCAN's GVRET CSV, its native log format (``.csv``, beside python-can's CSV).

The layout is SavvyCAN's own (collin80/SavvyCAN ``framefileio.cpp``: ``isNativeCSVFile``,
``loadNativeCSVFile``, ``saveNativeCSVFile``), a header line, then one frame a line::

    Time Stamp,ID,Extended,Dir,Bus,LEN,D1,D2,D3,D4,D5,D6,D7,D8
    39747828,000005EB,false,Rx,0,8,E8,45,85,4B,4A,28,36,69,

The time in microseconds (SavvyCAN's clock: since its capture started, or Unix time), the
CAN ID and data bytes in hexadecimal, ``Extended`` true or false, the direction (``Rx`` or
``Tx``; absent from the first version's header, ``Time Stamp,ID,Extended,Bus,LEN,...``), the
bus number, and the length: at most 8, and no more than the bytes on the line, as SavvyCAN
reads it. The bus is the channel, named as candump names interfaces: bus 0 is ``can0``.

Where SavvyCAN reads a cell that is no number as 0, here the line is a `BadLine`; a
timestamp of up to 3 digits, which SavvyCAN replaces by a time of its own, is kept as given.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import TYPE_CHECKING

from veronte4x.capture.frames import BadLine, Frame, micros_seconds

if TYPE_CHECKING:
    from veronte4x.capture.source import Source

_DIR_AT = 23
"""Where the header of the second version has ``Dir``: SavvyCAN tells the versions so."""
_MAX_LENGTH = 8
_ID_MASK = 0x1FFF_FFFF


def frames(source: Source) -> Iterator[Frame | BadLine]:
    """The frames of a GVRET CSV file (a `Truncation` last where gzip data ends early): the
    reader registry's ``frames``."""
    from veronte4x.capture.source import Truncated, open_lines

    with open_lines(source) as lines:
        try:
            yield from parse_gvret(lines)
        except Truncated as cut:
            yield cut.bad_line()


def sniff(head: bytes) -> bool:
    """Whether a file's first line is GVRET CSV's header, as SavvyCAN's ``isNativeCSVFile``
    asks: ``TIME STAMP``, ``EXTENDED`` and ``D1`` in it, in any case."""
    header = head.split(b"\n", 1)[0].upper()
    return b"TIME STAMP" in header and b"EXTENDED" in header and b"D1" in header


def parse_gvret(lines: Iterable[str]) -> Iterator[Frame | BadLine]:
    """Parse GVRET CSV lines, the header first, into frames and a `BadLine` for each line
    that is no frame."""
    numbered = enumerate(lines, 1)
    header = next(numbered, (0, ""))[1].upper()
    length_column = 5 if header[_DIR_AT : _DIR_AT + 1] == "D" else 4
    for number, line in numbered:
        text = " ".join(line.split())  # Qt's simplified(): whitespace trimmed and collapsed
        if len(text) > 2:
            yield parse_line(text, number, length_column)


def parse_line(text: str, number: int, length_column: int = 5) -> Frame | BadLine:
    """One GVRET CSV line's frame, or the `BadLine` that says why not.

    Args:
        text: The line, its whitespace collapsed.
        number: Its 1-based line number.
        length_column: The column of ``LEN``: 5 in the second version, 4 in the first.
    """
    cells = [cell.strip() for cell in text.split(",")]
    if len(cells) <= length_column:
        return BadLine(number, text, f"fewer than {length_column + 1} columns")
    try:
        micros = int(cells[0])
        can_id = int(cells[1], 16)
        bus = int(cells[length_column - 1])
        length = int(cells[length_column])
        if micros < 0 or bus < 0 or not 0 <= can_id <= _ID_MASK:
            raise ValueError("a negative time or bus, or a CAN ID past 29 bits")
        data = cells[length_column + 1 :]
        length = max(0, min(length, _MAX_LENGTH, len(data)))
        payload = bytes(int(cell, 16) for cell in data[:length])
    except ValueError as error:
        return BadLine(number, text, f"not a GVRET CSV frame: {error}")
    return Frame(micros_seconds(micros), f"can{bus}", can_id, payload, "TRUE" in cells[2].upper())
