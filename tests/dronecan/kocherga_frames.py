"""Dynamic node ID allocation frames from kocherga's unit tests.

Source: github.com/Zubax/kocherga, ``tests/unit/can/test_node.cpp``, test case
``can::detail::V0NodeIDAllocationActivity`` (commit 1094eec7c3575cd408da2066ecee2547be97203c;
MIT licence, Copyright (c) 2021 Zubax Robotics). The allocatee's requests are anonymous
single frames of ``uavcan.protocol.dynamic_node_id.Allocation`` (type id 1) at priority 30,
their CAN IDs computed as that test does: ``0x1E000100 | (CRC-16-CCITT-FALSE of the frame's
data & 0x3FFF) << 10``. The allocator's answers are multi-frame transfers from node 127,
in the order the test feeds them (duplicates, a wrong transfer id, a bad CRC and a bad
node id included, as the test has them).
"""

from __future__ import annotations

REQUESTS: tuple[tuple[int, bytes], ...] = (
    (0x1E64B500, bytes.fromhex("0135ffd5055059c0")),  # stage 1, transfer id 0
    (0x1E243100, bytes.fromhex("0135ffd5055059c1")),  # stage 1 again, transfer id 1
    (0x1EB17500, bytes.fromhex("00313461412343c2")),  # stage 2
    (0x1EA53900, bytes.fromhex("0135ffd5055059c3")),  # stage 1
    (0x1E5F6100, bytes.fromhex("0000000000c4")),  # stage 3
)
"""The allocatee's five requests, in the order it sends them."""

ANSWERS: tuple[tuple[int, bytes], ...] = (
    (0x1400017F, bytes.fromhex("9e3d0035ffd50581")),
    (0x1400017F, bytes.fromhex("5059313461412321")),
    (0x1400017F, bytes.fromhex("5059313461412321")),  # duplicate
    (0x1400027F, bytes.fromhex("5059313461412321")),  # another type
    (0x14000177, bytes.fromhex("5059313461412321")),  # another sender
    (0x1400017F, bytes.fromhex("5059313461412322")),  # wrong transfer id
    (0x1400017F, bytes.fromhex("4341")),
    (0x1400017F, bytes.fromhex("4341")),  # duplicate
    (0x1400017F, bytes.fromhex("ffffea35ffd50582")),  # bad CRC
    (0x1400017F, bytes.fromhex("5059313461412322")),
    (0x1400017F, bytes.fromhex("430000000042")),
    (0x1400017F, bytes.fromhex("57760035ffd50583")),  # node id 0: the test's "bad node-ID value"
    (0x1400017F, bytes.fromhex("5059313461412323")),
    (0x1400017F, bytes.fromhex("430000000043")),
    (0x1400017F, bytes.fromhex("8c7afa35ffd50584")),  # correct CRC
    (0x1400017F, bytes.fromhex("5059313461412324")),
    (0x1400017F, bytes.fromhex("430000000044")),
)
"""The allocator's frames, in the order the test feeds them."""
