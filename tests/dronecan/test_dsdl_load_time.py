"""DSDL loads in time linear in the files: the nested-type checks, the signatures and the
bit lengths visit each type once, not each path to it (a diamond chain of 20 files took
6 s of CPU, of 26 files more than a minute; one of depth 60 has 2**60 paths)."""

from __future__ import annotations

import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from types import FrameType
from typing import Any

import dronecan.dsdl
import pytest

from veronte4x.dronecan import DsdlError, TypeSet, parser
from veronte4x.dronecan.crc import crc64we


def _diamonds(root: Path, depth: int) -> Path:
    """``chain.Top`` (message 20000) and ``N1`` .. ``N<depth>``: each holds the next twice,
    the last one byte."""
    root.mkdir(parents=True)
    (root / f"N{depth}.uavcan").write_text("uint8 x\n")
    for i in range(1, depth):
        (root / f"N{i}.uavcan").write_text(f"N{i + 1} a\nN{i + 1} b\n")
    (root / "20000.Top.uavcan").write_text("N1 a\nN1 b\n")
    return root


def _chain(root: Path, depth: int) -> Path:
    """``chain.Top`` holding ``N1``, which holds ``N2`` ... down to ``N<depth>``."""
    root.mkdir(parents=True)
    (root / f"N{depth}.uavcan").write_text("uint8 x\n")
    for i in range(1, depth):
        (root / f"N{i}.uavcan").write_text(f"N{i + 1} a\n")
    (root / "20000.Top.uavcan").write_text("N1 a\n")
    return root


@contextmanager
def _counting_signature_crcs() -> Iterator[list[int]]:
    """Count the CRC-64 runs of `parser.signature` (one per type, one per nested field)."""
    count = [0]

    def profile(frame: FrameType, event: str, arg: Any) -> None:
        back = frame.f_back
        if event == "call" and frame.f_code is crc64we.__code__ and back is not None:
            count[0] += back.f_code is parser.signature.__code__

    sys.setprofile(profile)
    try:
        yield count
    finally:
        sys.setprofile(None)


def test_a_diamond_chain_60_deep_loads_visiting_each_type_once(tmp_path: Path) -> None:
    root = _diamonds(tmp_path / "chain", 60)
    with _counting_signature_crcs() as count:
        types = TypeSet.standard().with_dsdl(root)
    assert count[0] == 60 * 3 + 1  # Top and N1..N59: itself and two fields; N60: itself
    codec = types.by_class[types["chain.Top"]]
    assert codec.max_payload == 2**60  # 2**60 leaves of one byte
    signatures: dict[str, int] = {}
    value = parser.signature("chain.Top", types.definitions, signatures)
    assert value == codec.data_type.signature
    assert sorted(signatures) == sorted(["chain.Top", *(f"chain.N{i}" for i in range(1, 61))])


def test_the_signature_of_a_diamond_chain_is_the_dronecan_packages(tmp_path: Path) -> None:
    root = _diamonds(tmp_path / "chain", 5)
    types = TypeSet.standard().with_dsdl(root)
    [reference] = [t for t in dronecan.dsdl.parse_namespaces([str(root)]) if t.default_dtid]
    assert types.by_class[types["chain.Top"]].data_type.signature == (
        reference.get_data_type_signature()
    )


def test_nesting_100_levels_deep_loads_and_101_is_refused(tmp_path: Path) -> None:
    types = TypeSet.standard().with_dsdl(_chain(tmp_path / "a" / "chain", 100))
    assert types.by_class[types["chain.Top"]].max_payload == 1
    root = _chain(tmp_path / "b" / "chain", 101)
    with pytest.raises(DsdlError) as error:
        TypeSet.standard().with_dsdl(root)
    assert str(error.value) == (
        f"{root.resolve() / '20000.Top.uavcan'}: chain.Top nests types more than 100 levels deep"
    )


def test_a_chain_deeper_than_the_stack_is_refused_not_a_recursion_error(tmp_path: Path) -> None:
    root = _chain(tmp_path / "chain", 3 * sys.getrecursionlimit())
    with pytest.raises(DsdlError, match="nests types more than 100 levels deep"):
        TypeSet.standard().with_dsdl(root)


def test_a_cycle_under_a_diamond_chain_is_found(tmp_path: Path) -> None:
    root = _diamonds(tmp_path / "chain", 40)
    (root / "N40.uavcan").write_text("N1 back\n")
    with pytest.raises(DsdlError, match=r"N\d+.uavcan: chain.N\d+ contains itself"):
        TypeSet.standard().with_dsdl(root)
