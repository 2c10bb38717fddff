"""Public names renamed so that each name has one meaning still import under their old names,
as aliases of the new ones (issue 23, "names with one meaning").

This file is the one place the old names are used: the rename script of that change skips it.
"""

from __future__ import annotations

import typing

from veronte4x import codec, dronecan, variables
from veronte4x.dronecan import codec as dronecan_codec
from veronte4x.dronecan import messages


def test_old_names_are_aliases_of_the_new_ones() -> None:
    from veronte4x.codec import Kind
    from veronte4x.dronecan import Frame, Message
    from veronte4x.dronecan.codec import Codec
    from veronte4x.dronecan.frame import Frame as FrameFromModule
    from veronte4x.dronecan.messages import Message as MessageFromModule

    assert Codec is dronecan_codec.TypeCodec
    assert Frame is FrameFromModule is dronecan.TransferFrame
    assert Message is MessageFromModule is messages.HandNamedMessage
    assert Kind is codec.FieldKind


def test_old_names_work_as_the_new_ones() -> None:
    frame = dronecan.Frame(0x10015501, b"\x00\xc0")
    assert frame == dronecan.TransferFrame(0x10015501, b"\x00\xc0")
    assert isinstance(
        dronecan.encode(dronecan.NodeStatus(), source_node_id=1, transfer_id=0)[0], dronecan.Frame
    )
    assert dronecan.NodeStatus in typing.get_args(dronecan.Message)
    assert repr(dronecan_codec.Codec(dronecan_codec.BY_CLASS[dronecan.NodeStatus].data_type))
    assert codec.Kind.UNSIGNED is codec.FieldKind.UNSIGNED


def test_old_names_stay_exported() -> None:
    for module, name in (
        (dronecan, "Frame"),
        (dronecan, "Message"),
        (messages, "Message"),
        (codec, "Kind"),
    ):
        assert name in module.__all__, (module.__name__, name)


def test_each_kept_name_keeps_its_one_meaning() -> None:
    assert codec.Codec is not dronecan_codec.TypeCodec
    assert codec.Message is not dronecan.HandNamedMessage
    assert variables.Kind is not codec.FieldKind
