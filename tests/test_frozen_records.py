"""The records the arbiter, the client, the DroneCAN node and the simulator return or take
are frozen dataclasses with slots (the design card): a caller cannot change a result it
was given, nor add an attribute to one by a typo."""

from __future__ import annotations

import dataclasses
import importlib

import pytest

RECORDS = [
    "veronte4x.arbiter.config.VariableConfig",
    "veronte4x.arbiter.config.ArbiterConfig",
    "veronte4x.arbiter.replay.Disagreement",
    "veronte4x.arbiter.replay.FrameError",
    "veronte4x.arbiter.replay.Restart",
    "veronte4x.arbiter.replay.ReplayResult",
    "veronte4x.arbiter.scores.Contribution",
    "veronte4x.arbiter.selection.Choice",
    "veronte4x.arbiter.state.SystemChecks",
    "veronte4x.arbiter.state.Decision",
    "veronte4x.arbiter.state.ArbiterState",
    "veronte4x.client.files.FileRead",
    "veronte4x.client.firmware.FirmwareOptions",
    "veronte4x.client.firmware.UpdateProgress",
    "veronte4x.client.nodes.NodeEntry",
    "veronte4x.client.operations.Call",
    "veronte4x.client.operations.Listen",
    "veronte4x.client.operations.Now",
    "veronte4x.client.paramfile.NodeParameters",
    "veronte4x.client.paramfile.Change",
    "veronte4x.client.params.ParameterInfo",
    "veronte4x.client.parmfile.ParmLine",
    "veronte4x.client.protocol.Received",
    "veronte4x.client.protocol.StatusSeen",
    "veronte4x.client.protocol.FileServed",
    "veronte4x.node.requests.Pending",
    "veronte4x.node.requests.Answered",
    "veronte4x.node.requests.TimedOut",
    "veronte4x.simulator.esc.EscState",
    "veronte4x.simulator.motor.MotorModel",
    "veronte4x.simulator.motor.MotorState",
    "veronte4x.simulator.parameters.ParameterRange",
]


@pytest.mark.parametrize("path", RECORDS)
def test_a_record_is_frozen_and_slotted(path: str) -> None:
    module, name = path.rsplit(".", 1)
    cls: type = getattr(importlib.import_module(module), name)
    assert dataclasses.is_dataclass(cls)
    assert getattr(cls, "__dataclass_params__").frozen  # noqa: B009 (not in the stubs)
    assert "__slots__" in cls.__dict__
