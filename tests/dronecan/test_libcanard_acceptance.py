"""Transfer acceptance against libcanard's ``canardHandleRxFrame``, frame by frame, in the
per-frame reassembler and in the column-wise path of `capture.read_tables`.

The vectors (data/libcanard_acceptance.json, made by libcanard itself: see its ``note`` and
libcanard_streams.py) hold streams with stuck, repeated, skipped, wrapped and backward
transfer ids, flipped toggles, dropped, doubled and reordered frames, timeouts, interleaved
sessions and transfers, interface switches, and long faulted streams of four sessions;
for every frame, what libcanard returned and the transfer it delivered. The reassembler
(default rules) must deliver the same transfers on the same frames and refuse the frames
libcanard refuses, naming libcanard's reason; the strict rules differ where documented.
`capture.read` and `capture.read_tables` (column-wise where a session is regular, the
reassembler elsewhere) must give those same transfers, and the same tables.
"""

from __future__ import annotations

import importlib.util
import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from libcanard_streams import VECTORS
from tests.capture.columnar_support import assert_same_tables, read_piped, write

from veronte4x import capture, dronecan
from veronte4x.dronecan import Problem, Problems, TypeSet
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_ID
from veronte4x.errors import DecodeError

DOCUMENT = json.loads(VECTORS.read_text())
STANDARD = TypeSet.standard()
"""The types libcanard was told to accept when it made the vectors (the standard set)."""
STREAMS: dict[str, Any] = DOCUMENT["streams"]

# libcanard's return codes (canard.h) and the problems that name them.
REFUSED = {
    -10: {Problem.MALFORMED_FRAME},  # RX_INCOMPATIBLE_PACKET
    -12: {Problem.UNKNOWN_TYPE, Problem.MALFORMED_FRAME},  # RX_NOT_WANTED (also anonymous)
    -13: {Problem.MISSED_START},
    -14: {Problem.TOGGLE_ERROR, Problem.DUPLICATE_FRAME},  # RX_WRONG_TOGGLE
    -15: {Problem.UNEXPECTED_TRANSFER_ID},  # RX_UNEXPECTED_TID
    -16: {Problem.MALFORMED_FRAME},  # RX_SHORT_FRAME
    -17: {Problem.CRC_MISMATCH},  # RX_BAD_CRC
}
# Reports a frame libcanard takes may bring: the transfer its restart drops, as veronte4x
# counts lost transfers, and a payload past its type's largest (libcanard stores it).
LOST_ON_THE_WAY = {Problem.INTERRUPTED, Problem.TIMEOUT, Problem.PAYLOAD_TOO_LONG}


def test_the_vectors_come_from_one_recorded_libcanard_commit() -> None:
    assert DOCUMENT["libcanard_commit"] == "601ed35467e0ac38819df17cd7c918de19f62d58"
    assert DOCUMENT["payload_head_size"] == 5
    assert len(STREAMS) >= 40


def _codec(can_id: int) -> Any:
    if not can_id & 0x80:
        return BY_ID[TransferKind.MESSAGE, (can_id >> 8) & 0xFFFF]
    kind = TransferKind.REQUEST if can_id & 0x8000 else TransferKind.RESPONSE
    return BY_ID[kind, (can_id >> 16) & 0xFF]


def expected(can_id: int, result: list[Any]) -> tuple[int, Any] | str | None:
    """What libcanard delivered on a frame: (transfer id, message), "undecodable" for a
    payload that is not of its type (the reassembler reports `Problem.BAD_PAYLOAD`), or None."""
    if len(result) == 1:
        return None
    try:
        return result[1], _codec(can_id).decode(bytes.fromhex(result[2]))
    except DecodeError:
        return "undecodable"


def delivered(outcome: Any) -> tuple[int, Any] | str | None:
    """What the reassembler delivered on a frame, in the form of `expected`."""
    transfer = outcome.transfer if isinstance(outcome, Problems) else outcome
    if transfer is not None:
        return transfer.transfer_id, transfer.message
    reports = outcome.reports if isinstance(outcome, Problems) else ()
    return "undecodable" if any(r.problem is Problem.BAD_PAYLOAD for r in reports) else None


def outcomes(stream: dict[str, Any], kind: type = bytes, **options: Any) -> list[Any]:
    """`Reassembler.push` on every frame, one reassembler per interface (a channel); data
    of another ``kind`` than bytes takes the checked path, not the fast one."""
    reassemblers: dict[int, dronecan.Reassembler] = {}
    out = []
    for at, interface, can_id, data in stream["frames"]:
        r = reassemblers.setdefault(interface, dronecan.Reassembler(types=STANDARD, **options))
        out.append(r.push(can_id, kind(bytes.fromhex(data)), at / 1e6))
    return out


@pytest.mark.parametrize("kind", [bytes, bytearray], ids=["fast", "checked"])
@pytest.mark.parametrize("name", sorted(STREAMS))
def test_the_reassembler_accepts_and_refuses_what_libcanard_does(name: str, kind: type) -> None:
    stream = STREAMS[name]
    # A capture's channels are buses of their own: each interface is compared with
    # libcanard fed that interface alone (see the docs on redundant interfaces).
    results = stream.get("interfaces_apart", stream["libcanard"])
    for n, (outcome, result, (_, _, can_id, _)) in enumerate(
        zip(outcomes(stream, kind), results, stream["frames"], strict=True)
    ):
        if can_id & 0x80 and not (can_id & 0x7F and can_id & 0x7F00):
            # A service to or from node 0 is not DroneCAN (spec 4.1, "Anonymous message
            # broadcasting"); libcanard does not check the source (its session apart).
            assert outcome.reports[-1].problem is Problem.MALFORMED_FRAME
            continue
        assert delivered(outcome) == expected(can_id, result), (n, result, outcome)
        reports = [r.problem for r in outcome.reports] if isinstance(outcome, Problems) else []
        if result[0] < 0:
            assert reports and reports[-1] in REFUSED[result[0]], (n, result, outcome)
            assert set(reports[:-1]) <= LOST_ON_THE_WAY, (n, result, outcome)
        else:
            assert set(reports) <= LOST_ON_THE_WAY | {Problem.BAD_PAYLOAD}, (n, result, outcome)


def _count(stream: dict[str, Any], **options: Any) -> int:
    return sum(delivered(o) is not None for o in outcomes(stream, **options))


def test_a_node_whose_transfer_id_never_advances_is_heard_at_every_frame() -> None:
    """Issue 35: StaticPressure frames, all with tail 0xC0, 20 ms apart."""
    stream = STREAMS["stuck single frames"]
    assert {data[-2:] for _, _, _, data in stream["frames"]} == {"c0"}
    assert _count(stream) == 17
    assert _count(stream, strict=True) == 1


@pytest.mark.parametrize(
    ("name", "default", "strict"),
    [
        ("the same single frame again", 4, 2),  # a repeat of the id delivered last
        ("toggle set on a single frame", 2, 1),  # libcanard does not check it
        ("stuck single and multi-frame", 4, 2),  # strict: single frames refused
        ("frame out of order then resent", 1, 0),  # strict: lost at the first toggle error
    ],
)
def test_where_the_strict_rules_differ(name: str, default: int, strict: int) -> None:
    assert _count(STREAMS[name]) == default
    assert _count(STREAMS[name], strict=True) == strict


def test_redundant_interfaces_are_not_merged() -> None:
    """libcanard takes two interfaces of one node as redundant and delivers each transfer
    once; a capture's channels are separate buses, so each channel delivers its own."""
    stream = STREAMS["redundant interfaces"]
    assert sum(len(r) > 1 for r in stream["libcanard"]) == 4
    assert sum(len(r) > 1 for r in stream["interfaces_apart"]) == 8
    assert _count(stream) == 8


@pytest.mark.parametrize("name", sorted(STREAMS))
def test_read_tables_accepts_what_libcanard_does(name: str, tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    stream = STREAMS[name]
    lines = [f"({t / 1e6:.6f}) can{i} {c:08X}#{d.upper()}" for t, i, c, d in stream["frames"]]
    path = write(tmp_path / "capture.log", lines)
    records = list(capture.read(path, types=STANDARD))
    results = stream.get("interfaces_apart", stream["libcanard"])
    want = [
        (f"can{i}", c & 0x7F, found[1])
        for (_, i, c, _), result in zip(stream["frames"], results, strict=True)
        if isinstance(found := expected(c, result), tuple)
    ]
    assert [(r.channel, r.node_id, r.message) for r in records if r.message is not None] == want
    tables = capture.tables_from_records(records, types=STANDARD)
    assert_same_tables(capture.read_tables(path, types=STANDARD), tables)
    assert_same_tables(read_piped(path, types=STANDARD), tables)


def _pydronecan(stream: dict[str, Any]) -> int:
    """The transfers pydronecan's receiving code (`dronecan.transport`) makes of a stream."""
    transport = pytest.importorskip("dronecan.transport")
    managers: dict[int, Any] = {}
    count = 0
    for at, interface, can_id, data in stream["frames"]:
        manager = managers.setdefault(interface, transport.TransferManager())
        frame = transport.Frame(can_id, bytearray.fromhex(data), at / 1e6, at / 1e6)
        frames = manager.receive_frame(frame)
        if frames:
            try:
                transport.Transfer().from_frames(frames)
            except transport.TransferError:
                continue
            count += 1
    return count


@pytest.mark.parametrize(
    ("name", "pydronecan", "libcanard"),
    [
        ("stuck single frames", 17, 17),  # the one that matters: all three agree
        ("stuck multi-frame", 5, 1),  # pydronecan keeps no transfer id state
        ("the same transfer again", 3, 2),
        ("interleaved transfers of one session", 2, 1),
        ("timeout within a transfer", 2, 1),  # no transfer-ID timeout in pydronecan
        ("toggle set on a single frame", 1, 2),  # pydronecan checks every toggle bit
        ("a frame twice", 1, 2),  # pydronecan loses a transfer with a frame doubled
        ("frame out of order then resent", 0, 1),
    ],
)
def test_where_pydronecan_differs_veronte4x_follows_libcanard(
    name: str, pydronecan: int, libcanard: int
) -> None:
    stream = STREAMS[name]
    assert _pydronecan(stream) == pydronecan
    assert sum(len(r) > 1 for r in stream["libcanard"]) == libcanard
    assert _count(stream) == libcanard


@pytest.mark.parametrize(("strict", "want"), [(False, 17), (True, 1)])
def test_strict_transfers_reach_every_way_of_decoding(
    strict: bool, want: int, tmp_path: Path
) -> None:
    """Issue 35's stuck StaticPressure node through `capture.read`, `read_tables` and
    ``veronte4x decode``: 17 transfers by libcanard's rules, 1 with ``strict_transfers``."""
    stream = STREAMS["stuck single frames"]
    lines = [f"({t / 1e6:.6f}) can{i} {c:08X}#{d.upper()}" for t, i, c, d in stream["frames"]]
    path = write(tmp_path / "capture.log", lines)
    records = list(capture.read(path, strict_transfers=strict))
    assert [r.kind for r in records if r.message is not None] == ["StaticPressure"] * want
    if importlib.util.find_spec("pyarrow") is not None:
        tables = capture.read_tables(path, strict_transfers=strict)
        assert tables["StaticPressure"].num_rows == want
        assert_same_tables(tables, capture.tables_from_records(records))
    flag = ["--strict-transfers"] if strict else []
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "decode", str(path), *flag],
        capture_output=True,
        text=True,
        check=False,
    )
    # The strict rules refuse the 16 repeats: each is a bad record, which decode skips.
    summary = f"veronte4x: 17 records, 0 undecoded, {17 - want} bad (skip)\n"
    assert (result.returncode, result.stderr) == (0, summary)
    assert sum("StaticPressure(" in line for line in result.stdout.splitlines()) == want


@pytest.mark.parametrize("name", sorted(STREAMS))
def test_read_tables_follows_the_strict_rules_too(name: str, tmp_path: Path) -> None:
    """Column-wise, regular sessions come out the same under both rules; the others go to
    the reassembler with the rule chosen, so the tables are those of the strict records."""
    pytest.importorskip("pyarrow")
    stream = STREAMS[name]
    lines = [f"({t / 1e6:.6f}) can{i} {c:08X}#{d.upper()}" for t, i, c, d in stream["frames"]]
    path = write(tmp_path / "capture.log", lines)
    records = list(capture.read(path, types=STANDARD, strict_transfers=True))
    taken = [delivered(o) for o in outcomes(stream, strict=True)]
    assert [r.message for r in records if r.message is not None] == [
        t[1] for t in taken if isinstance(t, tuple)
    ]
    tables = capture.tables_from_records(records, types=STANDARD)
    assert_same_tables(capture.read_tables(path, types=STANDARD, strict_transfers=True), tables)
