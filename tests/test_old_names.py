"""Public names renamed so that each name has one meaning exist once, under their new names
(issue 23, "names with one meaning"; issue 37, item 4: no aliases).

This file is the one place the old names are written: the rename script of that change skips it.
"""

from __future__ import annotations

import importlib

import pytest

from veronte4x import client, dronecan

OLD_NAMES = [
    ("veronte4x.codec", "Kind", "FieldKind"),
    ("veronte4x.codec.fields", "Kind", "FieldKind"),
    ("veronte4x.codec.compiler", "builder", "slot_builder"),
    ("veronte4x.dronecan", "Frame", "TransferFrame"),
    ("veronte4x.dronecan.frame", "Frame", "TransferFrame"),
    ("veronte4x.dronecan", "Message", "HandNamedMessage"),
    ("veronte4x.dronecan.messages", "Message", "HandNamedMessage"),
    ("veronte4x.dronecan.codec", "Codec", "TypeCodec"),
    ("veronte4x.dronecan.typeset", "resolve", "types_or_default"),
    ("veronte4x.client", "FirmwareUpdateError", "FirmwareUpdateFailedError"),
    ("veronte4x.client.errors", "FirmwareUpdateError", "FirmwareUpdateFailedError"),
    ("veronte4x.client.operations", "Batch", "OperationBatch"),
    ("veronte4x.capture.columnar.dbc", "decode_frames", "decode_dbc_frames"),
    ("veronte4x.arbiter", "Mode", "ArbiterMode"),
    ("veronte4x.arbiter.state", "Mode", "ArbiterMode"),
    ("veronte4x.arbiter", "Phase", "ArbiterPhase"),
    ("veronte4x.arbiter.machine", "Phase", "ArbiterPhase"),
    ("veronte4x.arbiter", "Event", "ArbiterEvent"),
    ("veronte4x.arbiter.machine", "Event", "ArbiterEvent"),
    ("veronte4x.simulator.can_node", "wanted", "is_dronecan_frame"),
    ("veronte4x.simulator.can_node", "to_message", "frame_to_message"),
]


@pytest.mark.parametrize(("module", "old", "new"), OLD_NAMES)
def test_an_old_name_is_gone_and_the_new_one_stays(module: str, old: str, new: str) -> None:
    loaded = importlib.import_module(module)
    assert not hasattr(loaded, old)
    assert old not in getattr(loaded, "__all__", ())
    assert hasattr(loaded, new)


def test_firmware_update_error_has_one_meaning_after_star_imports_in_either_order() -> None:
    """``client.FirmwareUpdateError`` was an alias of the exception while
    ``dronecan.FirmwareUpdateError`` is the DSDL enum: after ``from ... import *`` of both,
    the later won, and ``except FirmwareUpdateError:`` raised TypeError."""
    for order in (("client", "dronecan"), ("dronecan", "client")):
        names: dict[str, object] = {}
        for package in order:
            exec(f"from veronte4x.{package} import *", names)
        assert names["FirmwareUpdateError"] is dronecan.FirmwareUpdateError
        assert names["FirmwareUpdateFailedError"] is client.FirmwareUpdateFailedError
        error = client.FirmwareUpdateFailedError("node 21 refused the update: INVALID_MODE")
        with pytest.raises(client.FirmwareUpdateFailedError) as caught:
            exec(
                "try:\n raise error\nexcept FirmwareUpdateFailedError:\n raise",
                names | {"error": error},
            )
        assert caught.value is error


def test_each_kept_name_keeps_its_one_meaning() -> None:
    from veronte4x import arbiter, codec, variables
    from veronte4x.capture.columnar import batches
    from veronte4x.dronecan import codec as dronecan_codec

    assert codec.Codec is not dronecan_codec.TypeCodec
    assert codec.Message is not dronecan.HandNamedMessage
    assert variables.Kind is not codec.FieldKind
    assert issubclass(dronecan.FirmwareUpdateError, int)  # the DSDL enum keeps its name
    assert not issubclass(client.FirmwareUpdateFailedError, int)
    assert dronecan.Mode is not arbiter.ArbiterMode
    assert client.Phase is not arbiter.ArbiterPhase
    assert client.Event is not arbiter.ArbiterEvent
    assert batches.Batch is not client.operations.OperationBatch
    assert dronecan.decode_frames.__module__ == "veronte4x.dronecan.transfer"
