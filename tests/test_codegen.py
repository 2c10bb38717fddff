"""Generated code is readable where it runs: tracebacks show its lines, getsource its text;
slot builders build slotted objects, or are refused where slot stores would fail."""

from __future__ import annotations

import inspect
import subprocess
import sys
import traceback
from dataclasses import dataclass
from typing import Any

import pytest

from veronte4x import codec, dronecan
from veronte4x.codec import layouts
from veronte4x.codegen import slot_builder
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.dronecan.fast_base import SlowPath
from veronte4x.errors import DecodeError


def test_decode_error_in_generated_code_shows_its_line() -> None:
    decode = layouts.SCORE.functions[0]
    with pytest.raises(DecodeError) as caught:
        decode(b"\x00", False)
    text = "".join(traceback.format_exception(caught.value))
    assert "<veronte4x generated decode Score #" in text
    assert "raise _derr(" in text


def test_dronecan_error_in_generated_code_shows_its_line() -> None:
    fast = BY_CLASS[dronecan.standard.LightsCommand].fast
    with pytest.raises(SlowPath) as caught:
        fast.decode(bytes(4))  # a struct item cut short: the generated code hands over
    text = "".join(traceback.format_exception(caught.value))
    assert "dronecan/fast/uavcan_equipment_indication_LightsCommand.py" in text
    assert "raise SlowPath" in text
    assert "def decode(buf):" in inspect.getsource(fast.decode)


def test_shipped_types_compile_nothing_and_import_their_fast_paths_on_first_use() -> None:
    code = (
        "import linecache, sys, veronte4x.dronecan as d\n"
        "def state():\n"
        "    fast = [m for m in sys.modules if m.startswith('veronte4x.dronecan.fast.')]\n"
        "    compiled = sum('generated fast paths' in name for name in linecache.cache)\n"
        "    return f'{sorted(fast)}/{compiled}'\n"
        "before = state()\n"
        "d.decode_frames([(0x1015505, bytes(7) + b'\\xc0')])\n"
        "print(before, state())\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    # Nothing at import, then NodeStatus's checked-in module alone; nothing compiled.
    assert done.stdout.split() == [
        "[]/0",
        "['veronte4x.dronecan.fast.uavcan_protocol_NodeStatus']/0",
    ]


def test_getsource_of_generated_functions() -> None:
    assert inspect.getsource(codec.decode).startswith("def decode(data")
    assert "def decode(data" in inspect.getsource(layouts.SCORE.functions[0])
    fast = BY_CLASS[dronecan.NodeStatus].fast
    assert fast is not None
    assert inspect.getsource(fast.decode).startswith("def decode(buf):")


def test_file_names_are_unique() -> None:
    names = {
        layouts.SCORE.functions[0].__code__.co_filename,
        layouts.READY.functions[0].__code__.co_filename,
        codec.decode.__code__.co_filename,
    }
    assert len(names) == 3


@dataclass(frozen=True, slots=True)
class _Base:
    a: int


@dataclass(frozen=True, slots=True)
class _Derived(_Base):
    b: int


def test_slot_builder_of_plain_slotted_classes_builds_them() -> None:
    made: Any = object.__new__(slot_builder(_Base))  # type: ignore[arg-type]
    made.a = 3
    made.__class__ = _Base
    assert made == _Base(3) and type(made) is _Base


def test_no_slot_builder_where_a_base_guards_its_attributes() -> None:
    """A mutation survivor: a builder made under a frozen base, whose slot stores raise.

    `_Derived` declares slot ``b`` over the frozen `_Base`: a builder for it would inherit
    `_Base`'s ``__setattr__`` and could not store ``a``; callers build it another way.
    """
    assert slot_builder(_Derived) is None
    assert slot_builder(object) is None
