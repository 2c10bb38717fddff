"""Generated code is readable where it runs: tracebacks show its lines, getsource its text."""

from __future__ import annotations

import inspect
import traceback

import pytest

from veronte4x import codec, dronecan
from veronte4x.codec import layouts
from veronte4x.dronecan.codec import BY_CLASS
from veronte4x.errors import DecodeError


def test_decode_error_in_generated_code_shows_its_line() -> None:
    decode = layouts.SCORE.functions[0]
    with pytest.raises(DecodeError) as caught:
        decode(b"\x00", False)
    text = "".join(traceback.format_exception(caught.value))
    assert "<veronte4x generated decode Score #" in text
    assert "raise _derr(" in text


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
