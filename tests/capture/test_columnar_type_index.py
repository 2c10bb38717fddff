"""`type_index` refuses the frames the reassembler refuses whatever their session."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from veronte4x import dronecan
from veronte4x.capture.columnar.dronecan import type_index, type_index_of
from veronte4x.dronecan import Problem
from veronte4x.dronecan.compiled import can_id_base

_STATUS = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)


def _can_id(message: object, source: int, destination: int | None = None) -> int:
    (frame, *_) = dronecan.encode(
        message, source_node_id=source, transfer_id=0, destination_node_id=destination
    )
    return frame.can_id


def _refused_by_the_reassembler(can_id: int) -> bool:
    """Whether a valid-looking single frame on ``can_id`` is refused by its CAN ID alone."""
    r = dronecan.Reassembler()
    r.feed(can_id, b"\x00" * 7 + b"\xc0", 0.0)
    return r.counts[Problem.MALFORMED_FRAME] + r.counts[Problem.UNKNOWN_TYPE] > 0


def test_anonymous_node_0_and_over_29_bits_are_refused() -> None:
    status = _can_id(_STATUS, 21)
    request = _can_id(dronecan.GetNodeInfoRequest(), 21, 22)
    ids = [
        status,
        status & ~0x7F,  # anonymous message
        request,
        request & ~0x7F00,  # a request to node 0
        request & ~0x7F,  # a request from node 0
        status | 1 << 29,  # beyond 29 bits
        request | 1 << 31,
    ]
    found = type_index(np.array(ids, dtype=np.uint32)).tolist()
    assert found[0] >= 0 and found[2] >= 0
    assert found[1:2] + found[3:] == [-1] * 5


_KNOWN = st.builds(
    lambda base, source, destination: (
        base & ~0x7F7F | destination << 8 | source if base & 0x80 else base & ~0x7F | source
    ),
    st.sampled_from([_can_id(_STATUS, 21), _can_id(dronecan.GetNodeInfoRequest(), 21, 22)]),
    st.integers(0, 127),
    st.integers(0, 127),
)
"""Known types from any node, node 0 included, to any node."""


@given(st.integers(0, 2**32 - 1) | _KNOWN)
def test_type_index_refuses_what_the_reassembler_refuses(can_id: int) -> None:
    refused = type_index(np.array([can_id], dtype=np.uint32))[0] == -1
    if can_id >> 29 or not can_id & 0xFF:  # anonymous messages go to the per-frame path
        assert refused
    else:
        assert refused == _refused_by_the_reassembler(can_id)


@pytest.mark.parametrize(("source", "destination"), [(21, 22), (127, 1), (1, 127)])
def test_every_type_is_found_by_its_can_id(source: int, destination: int) -> None:
    """Each type of the default set, a message from ``source`` or a request or response from
    ``source`` to ``destination``, at its own index (a request and its response apart)."""
    known = type_index_of()
    ids = []
    for codec in known.codecs:
        service = codec.data_type.kind is not dronecan.TransferKind.MESSAGE
        to = destination << 8 if service else 0
        ids.append(16 << 24 | can_id_base(codec.data_type) | source | to)
    found = type_index(np.array(ids, dtype=np.uint32), known).tolist()
    assert found == list(range(len(known.codecs)))
