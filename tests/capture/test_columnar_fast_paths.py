"""The column-wise DroneCAN shortcuts against their exact references: the transfer CRC two
bytes at a time against `crc16`, whole-byte scalars read as one view against the bit runs,
and payload rows cut from one slice against rows gathered one by one."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x.capture.columnar import dronecan
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.scalar_code import bit_runs
from veronte4x.dronecan.schema import Scalar

KNOWN = dronecan.type_index_of()


def _transfers(payloads: list[bytes], types: list[int]) -> dronecan.Transfers:
    sizes = np.array([len(p) for p in payloads], np.int64)
    offsets = np.zeros(len(payloads) + 1, np.int64)
    np.cumsum(sizes, out=offsets[1:])
    payload = np.frombuffer(b"".join(payloads) + b"\0", np.uint8)[: int(offsets[-1])].copy()
    rows = np.arange(len(payloads), dtype=np.int64)
    crc = np.zeros(len(payloads), np.int64)
    return dronecan.Transfers(rows, rows, np.array(types, np.int16), payload, offsets, crc)


@settings(max_examples=200)
@given(
    st.lists(
        st.tuples(st.binary(max_size=300), st.integers(0, len(KNOWN.codecs) - 1)),
        min_size=1,
        max_size=20,
    ),
    st.data(),
)
def test_transfer_crc_two_bytes_at_a_time_is_crc16(
    drawn: list[tuple[bytes, int]], data: st.DataObject
) -> None:
    found = _transfers([p for p, _ in drawn], [t for _, t in drawn])
    which = np.array(data.draw(st.lists(st.integers(0, len(drawn) - 1), unique=True)), np.int64)
    computed = dronecan.crc_ok(found, which, KNOWN)
    for transfer, crc in zip(which.tolist(), computed.tolist(), strict=True):
        payload, index = drawn[transfer]
        assert crc == crc16(payload, int(KNOWN.seeds[index])), payload.hex()


def _by_runs(row: bytes, t: Scalar, offset: int) -> int:
    """A scalar's raw bits read bit run by bit run from the payload as one int."""
    whole = int.from_bytes(row, "little")
    raw = 0
    for source, width, dest in bit_runs(offset, t.bits):
        raw |= ((whole >> dest) & ((1 << width) - 1)) << source
    return raw


@pytest.mark.parametrize("bits", [8, 16, 32, 64])
@pytest.mark.parametrize("offset", [0, 8, 16, 24, 3, 13])
def test_whole_byte_scalars_read_as_the_bit_runs(bits: int, offset: int) -> None:
    rng = np.random.default_rng(bits * 100 + offset)
    size = (offset + bits + 7) // 8
    matrix = np.zeros((64, size + 8), np.uint8)
    matrix[:, :size] = rng.integers(0, 256, (64, size), dtype=np.uint8)
    matrix[0, :size] = 0xFF
    matrix[1, :size] = 0
    t = Scalar("uint", bits)
    got = dronecan.scalar(matrix, t, offset)
    for row in range(len(matrix)):
        assert int(got[row]) == _by_runs(matrix[row].tobytes(), t, offset)


@settings(max_examples=300)
@given(st.integers(1, 64), st.integers(0, 40), st.sampled_from(["uint", "int"]))
def test_scalars_of_any_width_at_any_offset_read_as_the_bit_runs(
    bits: int, offset: int, kind: str
) -> None:
    """Fields within one 8-byte window read from it, the others bit run by bit run;
    windows shared by the fields of one matrix."""
    rng = np.random.default_rng(bits * 100 + offset)
    size = (offset + bits + 7) // 8
    matrix = np.zeros((16, size + 8), np.uint8)
    matrix[:, :size] = rng.integers(0, 256, (16, size), dtype=np.uint8)
    matrix[0, :size] = 0xFF
    windows: dict[int, np.ndarray] = {}
    dronecan.scalar(matrix, Scalar("uint", 8), offset // 8 * 8, windows)
    got = dronecan.scalar(matrix, Scalar(kind, bits), offset, windows)
    for row in range(len(matrix)):
        raw = _by_runs(matrix[row].tobytes(), Scalar(kind, bits), offset)
        if kind == "int" and raw >> (bits - 1):
            raw -= 1 << bits
        assert int(got[row]) == raw


@settings(max_examples=100)
@given(
    st.integers(0, 40),
    st.lists(st.booleans(), min_size=1, max_size=30),
    st.integers(0, 3),
)
def test_payload_rows_from_one_slice_as_gathered(size: int, taken: list[bool], other: int) -> None:
    """Consecutive transfers of one size come from a slice; others, as of a type with
    transfers of another size or left out between them, row by row."""
    payloads, which = [], []
    rng = np.random.default_rng(size * 7 + len(taken))
    for index, take in enumerate(taken):
        length = size if take else other
        payloads.append(rng.integers(0, 256, length, dtype=np.uint8).tobytes())
        if take:
            which.append(index)
    if not which:
        return
    found = _transfers(payloads, [0] * len(payloads))
    matrix = dronecan.payload_matrix(found, np.array(which, np.int64), size)
    assert matrix.shape == (len(which), size + 8)
    for row, transfer in enumerate(which):
        assert matrix[row, :size].tobytes() == payloads[transfer]
        assert not matrix[row, size:].any()
