"""Transfer acceptance against libcanard's ``canardHandleRxFrame``, frame by frame.

The vectors (data/libcanard_acceptance.json, made by libcanard itself: see its ``note`` and
libcanard_streams.py) hold streams with stuck, repeated, skipped, wrapped and backward
transfer ids, flipped toggles, dropped, doubled and reordered frames, timeouts, interleaved
sessions and transfers, interface switches, and long faulted streams of four sessions;
for every frame, what libcanard returned and the transfer it delivered. The reassembler
(default rules) must deliver the same transfers on the same frames and refuse the frames
libcanard refuses, naming libcanard's reason; the strict rules differ where documented.
"""

from __future__ import annotations

import json
from typing import Any

import pytest
from libcanard_streams import VECTORS

from veronte4x import dronecan
from veronte4x.dronecan import Problem, Problems
from veronte4x.dronecan.can_id import TransferKind
from veronte4x.dronecan.codec import BY_ID
from veronte4x.errors import DecodeError

DOCUMENT = json.loads(VECTORS.read_text())
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


def outcomes(stream: dict[str, Any], **options: Any) -> list[Any]:
    """`Reassembler.push` on every frame, one reassembler per interface (a channel)."""
    reassemblers: dict[int, dronecan.Reassembler] = {}
    out = []
    for at, interface, can_id, data in stream["frames"]:
        r = reassemblers.setdefault(interface, dronecan.Reassembler(**options))
        out.append(r.push(can_id, bytes.fromhex(data), at / 1e6))
    return out


@pytest.mark.parametrize("name", sorted(STREAMS))
def test_the_reassembler_accepts_and_refuses_what_libcanard_does(name: str) -> None:
    stream = STREAMS[name]
    # A capture's channels are buses of their own: each interface is compared with
    # libcanard fed that interface alone (see the docs on redundant interfaces).
    results = stream.get("interfaces_apart", stream["libcanard"])
    for n, (outcome, result, (_, _, can_id, _)) in enumerate(
        zip(outcomes(stream), results, stream["frames"], strict=True)
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
    """Issue 35: StaticPressure-like frames, all tail 0xC0, 20 ms apart."""
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
        ("interrupted after one frame, same id", 1, 1),  # which of the two differs
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
