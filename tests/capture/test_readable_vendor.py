"""Values of vendor types: exact for machines, their half-precision floats in 16-bit shortest
form for people."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from tests.dsdl_support import write_namespace
from veronte4x.capture.readable import format_message, readable_fields
from veronte4x.dronecan import TypeSet, decode_frames, encode, from_builtin


def test_a_vendor_float16_shows_as_its_shortest_half_precision_form(tmp_path: Path) -> None:
    """0.1 as float16 is 0.0999755859375: '0.1' in 16 bits; its 32-bit shortest form,
    '0.099975586', was shown for every float16 outside the standard set."""
    root = write_namespace(
        tmp_path,
        "half",
        {
            "Inner": "float16 h\n",
            "Choice": "@union\nfloat16 half\nfloat32 single\n",
            "20900.Half": "float16 x\nfloat16[<=2] xs\nfloat32 y\nInner inner\nChoice choice\n",
        },
    )
    types = TypeSet.standard().with_dsdl(root)
    fields = {
        "x": 0.1,
        "xs": [0.1, 65504.0],
        "y": 0.1,
        "inner": {"h": 0.3},
        "choice": {"half": 0.1},
    }
    sent: Any = from_builtin(types["half.Half"], fields, types=types)
    sent_frames = encode(sent, source_node_id=9, transfer_id=0, types=types)
    frames = [(f.can_id, f.data) for f in sent_frames]
    message = decode_frames(frames, types=types).message
    assert message.x == 0.0999755859375  # what the wire holds
    assert readable_fields(message) == {  # machine formats: the exact values
        "x": 0.0999755859375,
        "xs_0": 0.0999755859375,
        "xs_1": 65504.0,
        "y": 0.10000000149011612,
        "inner.h": 0.300048828125,
        "choice.value": 0.0999755859375,  # the union's member ``half``
    }
    # For people: the shortest form at each field's declared width (65504, the largest
    # float16, reads back from 65500).
    assert format_message(message) == (
        "Half(x=0.1, xs=(0.1, 65500.0), y=0.1, inner=Inner(h=0.3), choice=ChoiceHalf(value=0.1))"
    )
