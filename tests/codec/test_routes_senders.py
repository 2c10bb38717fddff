"""The route table's sender rules: a sender's own route of a header shadows a route of
either sender with the same header (for that sender only), a header must be a byte, and
``veronte4x list`` names who sends each route."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest

from veronte4x import codec
from veronte4x.codec import layouts, routes
from veronte4x.codec.compiler import FrameLayout
from veronte4x.codec.routes import ROUTES, Route, RouteTable, sender_names

ARB, AP = codec.Sender.ARBITER, codec.Sender.AUTOPILOT


def _layout(name: str, fields: list[codec.Field]) -> FrameLayout:
    return codec.Layout(25, name, fields).frame


MINE = _layout("ArbiterHeaded", [codec.constant(0xFF, 8, name="header"), codec.unsigned("x", 8)])
EITHER = _layout("EitherHeaded", [codec.constant(0xFF, 8, name="header"), codec.signed("y", 8)])
OTHER = _layout("EitherOther", [codec.unsigned("z", 8)])
SHADOWED = (Route(25, MINE, ARB, 0xFF), Route(25, EITHER, None, 0xFF), Route(25, OTHER))


@pytest.fixture(scope="module")
def shadowed() -> Iterator[codec.Codec]:
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(routes, "ROUTES", (*ROUTES, *SHADOWED))
        yield codec.Codec()


def test_a_senders_own_header_route_shadows_the_one_of_either_sender() -> None:
    table = RouteTable(routes=(*ROUTES, *SHADOWED))
    assert table.for_sender(25, ARB) == [[SHADOWED[0]], [SHADOWED[2]]]
    assert table.for_sender(25, AP) == [[SHADOWED[1]], [SHADOWED[2]]]


@pytest.mark.parametrize("sender", [ARB, AP])
def test_every_decoder_follows_the_shadowing(shadowed: codec.Codec, sender: codec.Sender) -> None:
    expected = "ArbiterHeaded(x=254)" if sender is ARB else "EitherHeaded(y=-2)"
    decoders: list[Callable[[bytes], Any]] = [
        lambda d: shadowed.decode(d, sender=sender),
        lambda d: shadowed._checked(d, sender=sender),
        lambda d: shadowed.decoder(sender)(d, False),
    ]
    for decode in decoders:
        message: Any = decode(b"\x19\xff\xfe")
        assert repr(message) == expected
        other: Any = decode(b"\x19\x07")
        assert repr(other) == "EitherOther(z=7)"


@pytest.mark.parametrize("header", [256, -1])
def test_a_header_is_a_byte(header: int) -> None:
    with pytest.raises(codec.LayoutError) as raised:
        RouteTable(routes=(*ROUTES, Route(25, MINE, ARB, header)))
    assert str(raised.value) == f"ArbiterHeaded: header {header} is not a byte"


def test_who_sends_each_route() -> None:
    table = RouteTable()
    names = {route.frame.name: sender_names(route) for route in table.routes}
    assert names["Status"] == "arbiter"
    assert names["Score"] == "arbiter"
    assert names["Ready"] == "autopilots"
    assert names["ArbitrationVariable"] == "autopilots"
    assert names["VersionRequest"] == names["PwmSet"] == "any Veronte ID"
    assert {sender_names(Route(c, layout)) for c, layout in layouts.OPAQUE.items()} == {
        "any Veronte ID"
    }
