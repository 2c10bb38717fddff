"""The route table: every generated decoder follows it, for the built-in routes and for
routes of shapes the built-in table does not have (a second command told apart by sender and
byte 1, forms of several lengths from either sender)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.codec.test_declared_properties import layouts as declared_layouts
from tests.codec.test_declared_properties import valid_frames
from veronte4x import codec
from veronte4x.capture.columnar import veronte
from veronte4x.codec import layouts, routes
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.routes import ROUTES, Route, RouteTable

ARB, AP = codec.Sender.ARBITER, codec.Sender.AUTOPILOT


def _layout(command: int, name: str, fields: list[codec.Field]) -> FrameLayout:
    return codec.Layout(command, name, fields).frame


HEADED = _layout(21, "Headed", [codec.constant(0xFF, 8, name="header"), codec.unsigned("x", 8)])
SCORED = _layout(21, "Scored", [codec.unsigned("who", 8), codec.signed("y", 8)])
SHORT = _layout(22, "Short", [codec.unsigned("a", 8)])
LONG = _layout(22, "Long", [codec.unsigned("a", 8), codec.unsigned("b", 8), codec.skip(8)])
WIDE = _layout(23, "Wide", [codec.unsigned("a", 16)])  # no struct plan: no optimistic body
EXTRA = (
    Route(21, HEADED, ARB, 0xFF),
    Route(21, SCORED, ARB),
    Route(21, SCORED, AP),
    Route(22, SHORT, form="short form"),
    Route(22, LONG, form="long form"),
    Route(23, WIDE),
)


@pytest.fixture(scope="module")
def extended() -> Iterator[codec.Codec]:
    """A codec of the built-in routes and `EXTRA`."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(routes, "ROUTES", (*ROUTES, *EXTRA))
        yield codec.Codec()


def _outcome(function: Callable[..., Any], data: bytes, **kwargs: Any) -> tuple[str, Any]:
    try:
        message = function(data, **kwargs)
    except Exception as error:  # the comparison needs the exception itself
        return type(error).__name__, str(error)
    return "ok", repr(message)


_HEADS = [b"\x00", b"\x00\xff", b"\x01", b"\x02", b"\x09", b"\x15", b"\x15\xff", b"\x16", b"\x17"]
_FRAMES = st.binary(max_size=10) | st.tuples(st.sampled_from(_HEADS), st.binary(max_size=8)).map(
    b"".join
)


@settings(max_examples=600)
@given(data=_FRAMES, sender=st.sampled_from(codec.Sender), excess=st.booleans())
def test_fast_checked_sender_and_columnar_decoders_agree(
    extended: codec.Codec, data: bytes, sender: codec.Sender, excess: bool
) -> None:
    checked = _outcome(extended._checked, data, sender=sender, allow_excess=excess)
    assert _outcome(extended.decode, data, sender=sender, allow_excess=excess) == checked
    decoder = extended.decoder(sender)
    assert _outcome(lambda d: decoder(d, excess), data) == checked
    # The column-wise router picks the layout of the message decoded, or leaves the frame
    # to the per-frame decoder. CAN frames have 8 bytes at most.
    if len(data) > 8:
        return
    word = np.array([int.from_bytes(data[:8].ljust(8, b"\0"), "little")], np.uint64)
    length = np.array([len(data)], np.int64)
    target = int(veronte.targets(extended, sender, word, length, excess)[0])
    if checked[0] == "ok":
        assert target >= 0, data
        layout = veronte.layout_list(extended)[target]
        assert checked[1].startswith(layout.name + "("), (checked, layout.name)
        good, _ = veronte.decode(layout, word, length, excess)
        assert good.tolist() == [True]
    elif target >= 0:
        layout = veronte.layout_list(extended)[target]
        good, _ = veronte.decode(layout, word, length, excess)
        assert good.tolist() == [False], data


def test_new_routes_decode_and_encode(extended: codec.Codec) -> None:
    headed: Any = extended.decode(b"\x15\xff\x07", sender=ARB)
    assert type(headed).__name__ == "Headed" and headed.x == 7
    scored: Any = extended.decode(b"\x15\x01\xfe", sender=ARB)
    assert (type(scored).__name__, scored.who, scored.y) == ("Scored", 1, -2)
    as_ap: Any = extended.decode(b"\x15\xff\xfe", sender=AP)
    assert as_ap.who == 0xFF  # no header route for the autopilots
    assert extended.encode(headed) == b"\x15\xff\x07"
    assert type(extended.decode(b"\x16\x01", sender=AP)).__name__ == "Short"
    assert type(extended.decode(b"\x16\x01\x02\x00", sender=AP)).__name__ == "Long"
    with pytest.raises(codec.DecodeError, match=r"Long: 3 bytes; 2 \(short form\) or 4"):
        extended.decode(b"\x16\x01\x02", sender=AP)
    with pytest.raises(codec.DecodeError, match=r"^Long: 1 byte; 2 \(short form\) or 4"):
        extended.decode(b"\x16", sender=AP)
    assert type(extended.decode(b"\x16\x01\x02", sender=AP, allow_excess=True)).__name__ == (
        "Short"
    )
    with pytest.raises(codec.DecodeError, match="a command-21 frame has at least 2 bytes"):
        extended.decode(b"\x15", sender=ARB)
    wide: Any = extended.decode(b"\x17\x01\x02", sender=ARB)
    assert wide.a == 0x201


def test_the_built_in_table() -> None:
    table = RouteTable()
    assert table.commands()[:2] == [0, 1]
    assert [len(g) for g in table.for_sender(0, ARB)] == [2, 1]  # Status forms, then Score
    assert table.for_sender(0, AP) == [[table.routes[3]], [table.routes[4]]]
    assert routes.length_error(table.for_sender(0, ARB)[0]) == "4 (CEX form) or 6 (4x form)"
    assert routes.family(0, table) == "arbitration"
    assert table.layouts()[: len(layouts.ARBITRATION_AND_VERSION)] == list(
        layouts.ARBITRATION_AND_VERSION
    )


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (Route(24, SHORT), "a route of command 24 needs a layout whose first field"),
        (Route(22, LONG), "each needs a form name and a length of its own"),
    ],
)
def test_bad_routes(extra: Route, message: str) -> None:
    with pytest.raises(codec.LayoutError, match=message):
        RouteTable(routes=(*ROUTES, Route(22, SHORT), extra))


def test_declared_layouts_take_opaque_routes_or_free_commands() -> None:
    mine = codec.Layout(9, "Mine", [codec.unsigned("a", 8)])
    free = codec.Layout(40, "Free", [codec.unsigned("a", 8)])
    table = RouteTable(declared=[mine, free])
    assert table.of(9) == [Route(9, mine.frame)]
    assert table.routes[-1] == Route(40, free.frame)
    with pytest.raises(codec.LayoutError, match=r"only commands 5-10, 16-19 \(layout not"):
        RouteTable(declared=[codec.Layout(1, "Bad", [])])


@settings(max_examples=300)
@given(data=st.data(), sender=st.sampled_from(codec.Sender), excess=st.booleans())
def test_declared_routes_fast_and_checked_agree(
    data: st.DataObject, sender: codec.Sender, excess: bool
) -> None:
    """A declared layout's route gets an optimistic body in the fast decoder: the same
    outcome as the checked decoder, on its frames and on any bytes after its command."""
    layout = data.draw(declared_layouts())
    c = codec.Codec(layouts=[layout])
    frame = data.draw(
        valid_frames(layout) | st.binary(max_size=9).map(bytes((layout.command,)).__add__)
    )
    checked = _outcome(c._checked, frame, sender=sender, allow_excess=excess)
    assert _outcome(c.decode, frame, sender=sender, allow_excess=excess) == checked
    decoder = c.decoder(sender)
    assert _outcome(lambda d: decoder(d, excess), frame) == checked
