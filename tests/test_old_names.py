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


def test_second_round_old_names_are_aliases_of_the_new_ones() -> None:
    from veronte4x import arbiter, client
    from veronte4x.arbiter import machine, state
    from veronte4x.capture.columnar import dbc
    from veronte4x.client import errors, operations
    from veronte4x.dronecan import typeset

    assert client.FirmwareUpdateError is errors.FirmwareUpdateError
    assert errors.FirmwareUpdateError is client.FirmwareUpdateFailedError
    assert arbiter.Mode is state.Mode is arbiter.ArbiterMode
    assert arbiter.Phase is machine.Phase is arbiter.ArbiterPhase
    assert arbiter.Event is machine.Event is arbiter.ArbiterEvent
    assert operations.Batch is operations.OperationBatch
    assert dbc.decode_frames is dbc.decode_dbc_frames
    assert typeset.resolve is typeset.types_or_default
    for module, name in (
        (client, "FirmwareUpdateError"),
        (arbiter, "Mode"),
        (arbiter, "Phase"),
        (arbiter, "Event"),
    ):
        assert name in module.__all__, (module.__name__, name)


def test_second_round_old_names_work_as_the_new_ones() -> None:
    from veronte4x import arbiter, client

    error = client.FirmwareUpdateFailedError("node 21 refused the update: INVALID_MODE")
    try:
        raise error
    except client.FirmwareUpdateError as caught:  # what users wrote before
        assert caught is error and not caught.timed_out
    assert arbiter.Mode.IDLE is arbiter.ArbiterMode.IDLE
    assert arbiter.TRANSITIONS[(arbiter.Phase.IDLE, arbiter.Event.CHECKS_PASS)] is (
        arbiter.ArbiterPhase.NORMAL
    )


def test_second_round_each_kept_name_keeps_its_one_meaning() -> None:
    from veronte4x import arbiter, client
    from veronte4x.capture.columnar import batches
    from veronte4x.client import operations

    # the DSDL enum keeps its generated name; the client's exception has its own
    assert issubclass(dronecan.FirmwareUpdateError, int)
    assert not issubclass(client.FirmwareUpdateFailedError, int)
    assert dronecan.Mode is not arbiter.ArbiterMode
    assert client.Phase is not arbiter.ArbiterPhase
    assert client.Event is not arbiter.ArbiterEvent
    assert batches.Batch is not operations.OperationBatch
    assert dronecan.decode_frames.__module__ == "veronte4x.dronecan.transfer"
